#!/usr/bin/env bash
# Utilities/device/bundle.sh: packs the benchmarks (GlobeBenchmark, GlobeCostBenchmark) with the
# Debian 12 runtime they need, glibc included, and an X server (Xvfb, xkbcomp, Mesa's swrast for
# its GLX), into .gk/gk.tar.xz (about 36 MB), for a machine that has a GPU but none of our
# Debian packages, such as the GPU machines lent to development sessions. There,
# Utilities/device/run.sh unpacks it and runs the benchmarks on the GPU through the NVIDIA GLX
# vendor library. A measuring tool for developers: nothing in the build or the tests uses it.
#
# To stay small, libraries that must load but never run are replaced by stand-ins
# (make_stub.py): OpenImageIO's plugins for formats the globe does not read and what they pull
# in, and Mesa's LLVM (the X server's GLX uses softpipe; the programs render on the GPU). Before
# packing, the benchmark runs here on the packed libraries alone to prove that.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${VTKGLOBE_BUILD_DIR:-$root/build}"
bash "$root/Utilities/globe.sh" build
# Beyond globe.sh's packages (binutils comes with g++, glxinfo with mesa-utils): xz.
if ! command -v xz > /dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends xz-utils
fi
out="$root/.gk/gk.tar.xz"
mkdir -p "$root/.gk"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
g="$work/gk"
mkdir -p "$g/lib" "$g/bin" "$g/dri" "$work/stub"
arch=/usr/lib/x86_64-linux-gnu
programs=("$build/bin/GlobeBenchmark" "$build/bin/GlobeCostBenchmark")
xprograms=(/usr/bin/Xvfb /usr/bin/xkbcomp /usr/bin/glxinfo)
stubbed=(libopenvdb.so.10.0 libgdal.so.32 libopencv_core.so.406 libopencv_imgproc.so.406
  libopencv_videoio.so.406 libdcmimage.so.17 libdcmimgle.so.17 libdcmdata.so.17 liboflog.so.17
  libofstd.so.17 libavcodec.so.59 libavformat.so.59 libavutil.so.57 libswscale.so.6
  libheif.so.1 libraw_r.so.20 libopenjp2.so.7 libgif.so.7 libLLVM-15.so.1)
glibc='/(libc|libm|libpthread|libdl|librt|libresolv|ld-linux-x86-64)\.so'
closure() { LD_LIBRARY_PATH="$1:$build/lib" ldd "${@:2}" | awk '{print $3}' | grep '^/' | sort -u; }

cp "${programs[@]}" "${xprograms[@]}" "$g/bin/"
cp -L "$arch/dri/swrast_dri.so" "$g/dri/"
cp -r /usr/share/X11/xkb "$g/xkb"
# What the real closure imports: the stand-ins export exactly those names.
{ closure /nonexistent "${programs[@]}" "${xprograms[@]}" "$g/dri/swrast_dri.so" \
    "$arch/libGLX_mesa.so.0"
  printf '%s\n' "${programs[@]}" "${xprograms[@]}" "$g/dri/swrast_dri.so"; } |
  xargs nm -D --undefined-only 2>/dev/null | awk '{print $NF}' | sed 's/@.*//' | sort -u \
  > "$work/wanted"
for s in "${stubbed[@]}"; do
  python3 "$root/Utilities/device/make_stub.py" "$arch/$s" "$work/wanted" "$work/stub" > /dev/null
done
cp "$work/stub/"* "$g/lib/"
closure "$work/stub" "${programs[@]}" "${xprograms[@]}" "$g/dri/swrast_dri.so" \
  "$arch/libGLX_mesa.so.0" | grep -v -E "$glibc|^$work|^$build" | xargs -I{} cp -nL {} "$g/lib/"
cp -L "$arch/libGLX_mesa.so.0" "$build/lib/libvtkGlobeCore.so.1" \
  "$build/lib/libvtkGlobeRendering.so.1" "$g/lib/"
for l in ld-linux-x86-64.so.2 libc.so.6 libm.so.6 libpthread.so.0 libdl.so.2 librt.so.1 \
  libresolv.so.2; do
  cp -L "/lib/x86_64-linux-gnu/$l" "$g/lib/"
done

echo "== checking the packed libraries alone (softpipe, a 64x48 window)"
check="$work/check.json"
GALLIUM_DRIVER=softpipe DRAW_USE_LLVM=0 LIBGL_DRIVERS_PATH="$g/dri" \
  xvfb-run -a -s "-screen 0 640x480x24" \
  "$g/lib/ld-linux-x86-64.so.2" --library-path "$g/lib" "$g/bin/GlobeBenchmark" \
  --grid-only --scene earth --frames 1 --window 64x48 --json "$check" > "$work/check.log" 2>&1 ||
  { tail -20 "$work/check.log"; echo "the packed benchmark failed here" >&2; exit 1; }
echo "== packing $(du -sh "$g" | cut -f1)"
tar -C "$work" -cf - gk | xz -9 -T2 > "$out"
ls -la "$out"
