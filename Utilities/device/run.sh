#!/usr/bin/env bash
# Utilities/device/run.sh: on a GPU machine without our Debian packages, unpacks .gk/gk.tar.xz
# (Utilities/device/bundle.sh) into /opt/gk, starts Xvfb, and runs the benchmarks on the GPU
# through the NVIDIA GLX vendor library (glvnd). Run from the source tree's root, as root (it
# links /work/main to the tree, where the build looks for Data/, and adds /usr/bin/xkbcomp if
# missing). Every program runs on the carried glibc (its ld.so with --library-path), so the
# host's own libraries do not matter. Results go to $OUT (default /tmp/gk-out).
#
#   FULL=1        the whole accuracy-vs-time benchmark (full.json, full.txt)
#   WINDOWS="..." otherwise, --grid-only in these windows (default 800x600 1600x1200 400x300)
#   COST=1        also GlobeCostBenchmark (cost.json)
#   BENCH_ARGS    more arguments for GlobeBenchmark; TLIM: seconds per benchmark (default 150)
#   AB="DIR..."   instead: GlobeBenchmark $BENCH_ARGS with the packed libraries (a1), with the
#                 libraries in each DIR (relative to the tree, e.g. a rebuilt
#                 libvtkGlobeRendering.so.1) ahead of them (b-DIRNAME), and packed again (a2):
#                 before and after in one run
#   BENCH_BIN=F   run this GlobeBenchmark (relative to the tree) instead of the packed one
#   FORCE_MESA=1  render with the carried Mesa (softpipe) instead: a dry run on any machine
set -u
R="$PWD"
OUT="${OUT:-/tmp/gk-out}"
mkdir -p "$OUT"
T0=$(date +%s)
# A second run in the same machine reuses the unpacked bundle and the X server.
if ! [ -e /opt/gk/.unpacked ]; then
  python3 -c "import tarfile; tarfile.open('.gk/gk.tar.xz').extractall('/opt')" || exit 3
  touch /opt/gk/.unpacked
  echo "unpacked in $(($(date +%s) - T0)) s"
fi
G=/opt/gk
LD=$G/lib/ld-linux-x86-64.so.2
NV=$(for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu /usr/lib64; do
  [ -e "$d/libGLX_nvidia.so.0" ] && echo "$d"; done | head -1)
if [ -z "$NV" ]; then
  NV=$(dirname "$(timeout 30 find / -xdev -name libGLX_nvidia.so.0 2>/dev/null | head -1)")
  [ "$NV" = . ] && NV=
fi
echo "NVIDIA GLX in: ${NV:-none}"
LP=$G/lib${NV:+:$NV}
mkdir -p /work /var/lib/xkb
[ -e /work/main ] || ln -s "$R" /work/main
if ! [ -x /usr/bin/xkbcomp ]; then
  printf '#!/bin/sh\nexec %s --library-path %s %s/bin/xkbcomp "$@"\n' "$LD" "$G/lib" "$G" > /usr/bin/xkbcomp
  chmod +x /usr/bin/xkbcomp
fi
if ! [ -e /tmp/.X11-unix/X97 ]; then
  GALLIUM_DRIVER=softpipe DRAW_USE_LLVM=0 LIBGL_DRIVERS_PATH=$G/dri "$LD" --library-path "$G/lib" \
    "$G/bin/Xvfb" :97 -screen 0 2048x1536x24 -nolisten tcp -xkbdir "$G/xkb" > /tmp/xvfb.log 2>&1 &
  sleep 3
fi
export DISPLAY=:97 LIBGL_DRIVERS_PATH=$G/dri
if [ -n "${FORCE_MESA:-}" ]; then
  export GALLIUM_DRIVER=softpipe DRAW_USE_LLVM=0
elif [ -n "$NV" ]; then
  export __GLX_VENDOR_LIBRARY_NAME=nvidia
fi
"$LD" --library-path "$LP" "$G/bin/glxinfo" -B > /tmp/glx.txt 2>&1
grep -E "renderer string|core profile version" /tmp/glx.txt
if [ -z "${FORCE_MESA:-}" ] && ! grep -q NVIDIA /tmp/glx.txt; then
  echo "no NVIDIA OpenGL:"; head -20 /tmp/glx.txt; tail -20 /tmp/xvfb.log; exit 4
fi
export GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=536870912
bench() { timeout "${TLIM:-150}" "$LD" --library-path "$LP" "$@"; }
B="$G/bin/GlobeBenchmark"
[ -n "${BENCH_BIN:-}" ] && B="$R/$BENCH_BIN"
renderer=$(sed -n 's/.*renderer string: //p' /tmp/glx.txt)
conditions="$renderer (Utilities/device/run.sh: Xvfb, glvnd's NVIDIA GLX; the Debian 12 runtime carried; glibc malloc tuned)"
if [ -n "${AB:-}" ]; then
  # Each run as NAME:LIBRARY-PATH-PREFIX.
  set -- "a1:"
  for dir in $AB; do set -- "$@" "b-$(basename "$dir"):$R/$dir:"; done
  for item in "$@" "a2:"; do
    run=${item%%:*}
    lp=${item#*:}$LP
    echo "== $run"
    timeout "${TLIM:-150}" "$LD" --library-path "$lp" "$B" \
      --conditions "$conditions; $run" --json "$OUT/$run.json" ${BENCH_ARGS:-} > "$OUT/$run.txt" 2>&1
    echo "rc $?"
    grep -E '^(== |baseline|refinement|grid |naive)' "$OUT/$run.txt"
  done
elif [ -n "${FULL:-}" ]; then
  echo "== full"
  bench "$B" --conditions "$conditions" --json "$OUT/full.json" \
    ${BENCH_ARGS:-} > "$OUT/full.txt" 2>&1
  echo "rc $?"
  grep -v '^ \|^\[' "$OUT/full.txt" | tail -150
else
  for w in ${WINDOWS:-800x600 1600x1200 400x300}; do
    echo "== grid-only $w"
    bench "$B" --grid-only --window "$w" --scene rainier --scene everest \
      --scene earth --conditions "$conditions" --json "$OUT/grid-$w.json" ${BENCH_ARGS:-} \
      > "$OUT/grid-$w.txt" 2>&1
    echo "rc $?"
    grep -E '^(== |baseline|grid |naive)' "$OUT/grid-$w.txt"
  done
fi
if [ -n "${COST:-}" ]; then
  echo "== cost"
  bench "$G/bin/GlobeCostBenchmark" --json "$OUT/cost.json" > "$OUT/cost.txt" 2>&1
  echo "rc $?"
  tail -40 "$OUT/cost.txt"
fi
echo "total $(($(date +%s) - T0)) s"
