#!/usr/bin/env bash
# Sets up, builds and runs VTKGlobe on Debian 12. Idempotent: installs only missing packages,
# configures once, rebuilds only what changed.
#
#   Utilities/globe.sh demo [args]    build, then render the Earth (PNGs, or a window)
#   Utilities/globe.sh test [args]    build, then run the whole test suite (ctest args pass on)
#   Utilities/globe.sh bench [args]   build, then run the benchmark (table + build/benchmark.json)
#                                     and plot it (Documentation/accuracy-vs-time.md, images/)
#   Utilities/globe.sh bench-cost [args]   build, then measure out-of-view layers, the data's
#                                     size and the automatic grid (build/cost.json)
#   Utilities/globe.sh bench-streaming [args]   build, make the global rasters of the
#                                     streaming flight (GlobeMakePlanet, widths from
#                                     VTKGLOBE_PLANET_WIDTHS, kept in VTKGLOBE_PLANET_DIR), fly them
#                                     (build/streaming.json) and plot (Documentation/images)
#   Utilities/globe.sh build          install packages and build only
#   Utilities/globe.sh prepare IN OUT [--tile N] [--no-compression]
#                                     build, then rewrite a georeferenced raster as a tiled
#                                     GeoTIFF with reduced-resolution levels (GlobePrepare)
#   Utilities/globe.sh python script.py [args]   build, then run a Python script with the
#                                     build's vtkglobe package, under Xvfb when there is no display
#   Utilities/globe.sh check [args]   the whole C++ suite under AddressSanitizer and UBSan, in
#                                     its own build (build-check/; ctest args pass on)
#   Utilities/globe.sh check-core     only the CI's sanitizer subset (run by `test` as well)
#   Utilities/globe.sh fuzz [TARGET|all] [SECONDS] [libFuzzer args]
#                                     build the libFuzzer targets with clang (build-fuzz/) and run
#                                     each for SECONDS (default 60); findings in build-fuzz/crashes
#   Utilities/globe.sh paraview [args]  unpack Debian's ParaView 5.11 into a private prefix
#                                     (build-paraview/prefix), build the ParaView plugin
#                                     (Plugins/ParaView, in build-paraview/obj) and run its tests
#                                     (ctest args pass on)
#   Utilities/globe.sh pvpython script.py [args]   the same set-up, then run a script with that
#                                     ParaView's pvpython (VTKGLOBE_PARAVIEW_PLUGIN names the plugin)
#   Utilities/globe.sh pvbatch RANKS script.py [args]   the same with RANKS processes of
#                                     pvbatch --symmetric under Open MPI's mpiexec
#
# `test` also runs the CI's sanitizer subset (Core and the fuzz corpus replays, build-check-core/;
# VTKGLOBE_SANITIZER_TESTS=0 skips it). Documentation/reliability.md, "Fuzzing and sanitizers".
# Then `paraview`'s set-up, build and tests (VTKGLOBE_PARAVIEW_TESTS=0 skips them).
#
# Environment: VTKGLOBE_BUILD_DIR (default: build/ in the source tree), VTKGLOBE_CHECK_DIR
# (build-check/), VTKGLOBE_CHECK_CORE_DIR (build-check-core/), VTKGLOBE_FUZZ_DIR (build-fuzz/),
# VTKGLOBE_PARAVIEW_DIR (build-paraview/).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VTKGLOBE_BUILD_DIR:-$root/build}"
command="${1:-}"
shift || true

# Debian packages: compiler and CMake, VTK 9.1 with Python, GLM, GeographicLib, OpenImageIO,
# libgeotiff with PROJ (its database, the EGM96 geoid grid), and Xvfb + Mesa (llvmpipe) for
# rendering without a display.
packages=(
  cmake g++ make pkg-config
  libvtk9-dev python3-vtk9
  libglm-dev libgeographiclib-dev libopenimageio-dev libgeotiff-dev libtiff-dev
  libproj-dev proj-data
  xvfb xauth x11-utils libgl1-mesa-dri libglx-mesa0 mesa-utils
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Only for `fuzz`: clang and its sanitizer runtimes with libFuzzer.
fuzz_packages=(clang-14 libclang-rt-14-dev)

# Installs the missing ones of `packages` and of the packages named as arguments.
install_packages() {
  local missing=()
  for p in "${packages[@]}" "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "== installing Debian packages: ${missing[*]}"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}

build_project() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    echo "== configuring in $build"
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
  fi
  echo "== building"
  cmake --build "$build" --parallel "$(nproc)"
}

# The sanitizer builds: AddressSanitizer (with LeakSanitizer) and UBSan, -O1 with frame
# pointers for readable stacks; no Python wrapping (the Python tests do not run under them).
sanitize_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -g -O1"
configure_sanitized() {
  local dir="$1"
  shift
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    echo "== configuring the sanitizer build in $dir"
    cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Sanitize \
      -DCMAKE_C_FLAGS_SANITIZE="$sanitize_flags" -DCMAKE_CXX_FLAGS_SANITIZE="$sanitize_flags" \
      -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
      -DCMAKE_SHARED_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
      -DCMAKE_MODULE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
      -DVTKGLOBE_WRAP_PYTHON=OFF -DPython3_EXECUTABLE=/usr/bin/python3 "$@"
  fi
}

# How the sanitized programs run: any report fails the test (UBSan halts on its first);
# LeakSanitizer skips only the leaks of Mesa, X11 and libraries' singletons listed, each with
# its reason, in Testing/Sanitizers/lsan.supp.
asan_options="detect_leaks=1:halt_on_error=1:abort_on_error=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
sanitizer_env=(
  ASAN_OPTIONS="$asan_options"
  LSAN_OPTIONS="suppressions=$root/Testing/Sanitizers/lsan.supp:print_suppressions=0"
  UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
)
# The programs without OpenGL (Core.*, Fuzz.Replay.*) record full stacks for every allocation:
# the system libraries have no frame pointers, so a frame-pointer stack stops at the first of
# them, and a suppression must see the library frame that owns a leak (OpenImageIO's, under
# libstdc++). Not for the rendering tests: LLVM (llvmpipe's shader compiler) allocates while it
# registers unwind tables, and the slow unwinder deadlocks on libgcc's lock there.
full_stacks_env=(ASAN_OPTIONS="$asan_options:fast_unwind_on_malloc=0")

# The CI's part of the sanitizer suite: the Core module alone (no rendering), its
# reader/layer/page-source tests and the fuzz corpus replays (Documentation/reliability.md).
sanitizer_ci_tests='^(Fuzz\.Replay\..*|Core\.TestGlobe(RasterReader|RasterReaderHardening|RasterReaderSeries|LayerBadInput|LayerRead|LayerLevels|PageSource))$'
run_sanitizer_ci() {
  local dir="${VTKGLOBE_CHECK_CORE_DIR:-$root/build-check-core}"
  configure_sanitized "$dir" -DVTKGLOBE_BUILD_RENDERING=OFF
  echo "== building the Core module and its tests under the sanitizers ($dir)"
  cmake --build "$dir" --parallel "$(nproc)" --target GlobeCoreCxxTests \
    GlobeFuzzReplayRasterReader GlobeFuzzReplayWorldFile GlobeFuzzReplayLayer \
    GlobeFuzzReplayPageSource
  echo "== running the sanitizer subset"
  (cd "$dir" && env "${sanitizer_env[@]}" "${full_stacks_env[@]}" ctest --output-on-failure \
    --timeout 900 -R "$sanitizer_ci_tests")
}

# ParaView (Plugins/ParaView; Documentation/user-guide.md, "ParaView"). Debian's python3-paraview
# conflicts with python3-vtk9 (both own dist-packages/vtkmodules): installing it would remove
# python3-vtk9 and libvtk9-dev, which the main build needs. So the three ParaView packages are
# only downloaded and unpacked into a private prefix (their CMake files and pvpython are
# relocatable as they are), and apt installs only their dependencies, none of which conflicts:
# what they declare, the Qt development packages paraview-config.cmake looks for, and Open MPI's
# mpirun. Nothing is installed when the simulation says apt would remove a package.
paraview_dir="${VTKGLOBE_PARAVIEW_DIR:-$root/build-paraview}"
paraview_prefix="$paraview_dir/prefix"
paraview_debs=(paraview paraview-dev python3-paraview)
paraview_packages=(qtbase5-dev libqt5svg5-dev qttools5-dev libqt5opengl5-dev openmpi-bin)

setup_paraview() {
  local debs="$paraview_dir/debs"
  if [ ! -f "$paraview_prefix/.unpacked" ] || [ "$(ls "$debs"/*.deb 2>/dev/null | wc -l)" != 3 ]; then
    rm -f "$paraview_prefix/.unpacked"
    if ! apt-cache show paraview-dev >/dev/null 2>&1; then
      as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    fi
    echo "== downloading ${paraview_debs[*]} into $debs (not installed)"
    rm -rf "$debs"
    mkdir -p "$debs"
    (cd "$debs" && apt-get download "${paraview_debs[@]}")
  fi
  # Their dependencies, first alternatives, without versions, less the three themselves.
  local deps=()
  mapfile -t deps < <(for deb in "$debs"/*.deb; do dpkg-deb -f "$deb" Depends | tr ',' '\n'; done |
    sed 's/|.*//; s/(.*)//; s/:any//; s/ //g' | grep -vxE 'paraview|paraview-dev|python3-paraview|' |
    sort -u)
  local simulation
  simulation="$(apt-get install -s --no-install-recommends "${deps[@]}" "${paraview_packages[@]}")"
  if grep -q '^Remv' <<<"$simulation"; then
    echo "== refusing to install ParaView's dependencies: apt would remove" \
      "$(grep '^Remv' <<<"$simulation" | cut -d' ' -f2 | tr '\n' ' ')" >&2
    exit 1
  fi
  if grep -q '^Inst' <<<"$simulation"; then
    echo "== installing ParaView's dependencies ($(grep -c '^Inst' <<<"$simulation") packages)"
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      "${deps[@]}" "${paraview_packages[@]}"
  fi
  if [ ! -f "$paraview_prefix/.unpacked" ]; then
    echo "== unpacking them into $paraview_prefix"
    rm -rf "$paraview_prefix"
    for deb in "$debs"/*.deb; do
      dpkg-deb -x "$deb" "$paraview_prefix"
    done
    touch "$paraview_prefix/.unpacked"
  fi
}

# The plugin's build, against the private ParaView.
paraview_obj="$paraview_dir/obj"
build_paraview_plugin() {
  if [ ! -f "$paraview_obj/CMakeCache.txt" ]; then
    echo "== configuring the ParaView plugin in $paraview_obj"
    cmake -S "$root/Plugins/ParaView" -B "$paraview_obj" -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 \
      -DParaView_DIR="$paraview_prefix/usr/lib/$(gcc -print-multiarch)/cmake/paraview-5.11"
  fi
  echo "== building the ParaView plugin"
  cmake --build "$paraview_obj" --parallel "$(nproc)"
}

# Set-up, build and tests of the plugin, each timed (ctest args pass on).
run_paraview() {
  local start status=0
  start=$(date +%s)
  setup_paraview
  echo "== ParaView set up in $(( $(date +%s) - start )) s"
  start=$(date +%s)
  build_paraview_plugin
  echo "== plugin built in $(( $(date +%s) - start )) s"
  start=$(date +%s)
  echo "== running the ParaView tests"
  (cd "$paraview_obj" && with_display ctest --output-on-failure --timeout 900 "$@") || status=$?
  echo "== ParaView tests ran in $(( $(date +%s) - start )) s"
  return "$status"
}

# pvpython or pvbatch (under mpiexec) of the private ParaView, with the plugin, under a display.
run_paraview_program() {
  local program="$1"
  shift
  setup_paraview >&2
  build_paraview_plugin >&2
  local pv="$paraview_prefix/usr"
  local lib="$pv/lib/$(gcc -print-multiarch)"
  local pv_env=(LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    PYTHONPATH="$pv/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
    VTKGLOBE_PARAVIEW_PLUGIN="$paraview_obj/lib/paraview-5.11/plugins/VTKGlobe/VTKGlobe.so"
    VTKGLOBE_DATA_DIR="$root/Data")
  if [ "$program" = pvpython ]; then
    with_display env "${pv_env[@]}" "$pv/bin/pvpython" --force-offscreen-rendering "$@"
  else
    # RANKS processes of pvbatch --symmetric (every rank runs the script) under Open MPI.
    local ranks="${1:?usage: globe.sh pvbatch RANKS script.py [args]}"
    shift
    local mpi_flags=(--oversubscribe)
    if [ "$(id -u)" -eq 0 ]; then mpi_flags+=(--allow-run-as-root); fi
    with_display env "${pv_env[@]}" mpiexec "${mpi_flags[@]}" -n "$ranks" \
      "$pv/bin/pvbatch" --symmetric --force-offscreen-rendering "$@"
  fi
}

# Runs a command with a display: the user's, or a private Xvfb server (Mesa's llvmpipe gives
# OpenGL 4.5 core there).
with_display() {
  if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    "$@"
  else
    # -noreset: Xvfb resets when its last client leaves, and a test that closes one window
    # and opens the next could reach it mid-reset ("bad X server connection").
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
  fi
}

case "$command" in
  demo)
    install_packages
    build_project
    echo "== running the demo"
    if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1 && [ -z "${CI:-}" ]; then
      # A real display: an interactive window (keys 1, 2, 3 switch viewpoints).
      "$build/bin/GlobeEarth" --interactive "$@"
    else
      mkdir -p "$build/demo"
      with_display "$build/bin/GlobeEarth" --out "$build/demo" "$@"
      echo "== the pictures are in $build/demo"
    fi
    ;;
  test)
    install_packages
    build_project
    echo "== running the tests"
    (cd "$build" && with_display ctest --output-on-failure --timeout 900 "$@")
    if [ "${VTKGLOBE_SANITIZER_TESTS:-1}" != 0 ]; then
      run_sanitizer_ci
    fi
    if [ "${VTKGLOBE_PARAVIEW_TESTS:-1}" != 0 ]; then
      run_paraview
    fi
    ;;
  check-core)
    install_packages
    start=$(date +%s)
    run_sanitizer_ci
    echo "== the sanitizer subset took $(( $(date +%s) - start )) s"
    ;;
  check)
    install_packages
    check="${VTKGLOBE_CHECK_DIR:-$root/build-check}"
    configure_sanitized "$check"
    echo "== building under AddressSanitizer and UBSan"
    start=$(date +%s)
    cmake --build "$check" --parallel "$(nproc)"
    echo "== built in $(( $(date +%s) - start )) s"
    # Not Install.Downstream: it links an uninstrumented program against the instrumented
    # libraries. Core and the replays with full stacks, the rest without (see above).
    start=$(date +%s)
    cd "$check"
    status=0
    echo "== running the Core tests and the fuzz replays under the sanitizers"
    env "${sanitizer_env[@]}" "${full_stacks_env[@]}" ctest --output-on-failure --timeout 1800 \
      -R '^(Core|Fuzz)\.' "$@" || status=$?
    # Mesa unloads its driver (swrast_dri.so, llvmpipe) when the last context goes; the blocks
    # its static data still pointed to then look leaked to LeakSanitizer at exit (a few
    # "indirect leaks" of 56 bytes from unmapped code, in every rendering test). Preloaded, the
    # driver stays mapped and LeakSanitizer sees those references: nothing is suppressed for it.
    # (libasan must come first in LD_PRELOAD.)
    preload=()
    asan_lib="$(ldd "$check/bin/GlobeRenderingCxxTests" 2>/dev/null | awk '/libasan/ {print $3}')"
    dri="/usr/lib/$(gcc -print-multiarch)/dri/swrast_dri.so"
    if [ -n "$asan_lib" ] && [ -f "$dri" ]; then
      preload=(LD_PRELOAD="$asan_lib $dri")
    fi
    echo "== running the other C++ tests under the sanitizers"
    with_display env "${sanitizer_env[@]}" "${preload[@]}" ctest --output-on-failure \
      --timeout 1800 -E '^(Core\.|Fuzz\.|Install\.)' "$@" || status=$?
    echo "== tests ran in $(( $(date +%s) - start )) s"
    exit "$status"
    ;;
  fuzz)
    install_packages "${fuzz_packages[@]}"
    fuzz="${VTKGLOBE_FUZZ_DIR:-$root/build-fuzz}"
    if [ ! -f "$fuzz/CMakeCache.txt" ]; then
      # Core only, every library of ours instrumented for coverage and the sanitizers; the
      # fuzz programs add libFuzzer (Testing/Fuzz/CMakeLists.txt).
      fuzz_flags="-g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
      echo "== configuring the fuzz build in $fuzz"
      cmake -S "$root" -B "$fuzz" -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
        -DCMAKE_BUILD_TYPE=Fuzz -DCMAKE_C_FLAGS_FUZZ="$fuzz_flags" -DCMAKE_CXX_FLAGS_FUZZ="$fuzz_flags" \
        -DCMAKE_EXE_LINKER_FLAGS_FUZZ="-fsanitize=address,undefined" \
        -DCMAKE_SHARED_LINKER_FLAGS_FUZZ="-fsanitize=address,undefined" \
        -DBUILD_TESTING=OFF -DVTKGLOBE_BUILD_RENDERING=OFF -DVTKGLOBE_WRAP_PYTHON=OFF \
        -DVTKGLOBE_BUILD_FUZZERS=ON -DPython3_EXECUTABLE=/usr/bin/python3
    fi
    targets=(RasterReader WorldFile Layer PageSource)
    target="${1:-all}"
    seconds="${2:-60}"
    shift 2 || shift $#
    if [ "$target" != all ]; then
      targets=("$target")
    fi
    echo "== building the fuzz targets"
    cmake --build "$fuzz" --parallel "$(nproc)" --target "${targets[@]/#/GlobeFuzz}"
    for t in "${targets[@]}"; do
      # New inputs go to build-fuzz/corpus/T; the committed seeds and crashers are only read.
      # A finding is written to build-fuzz/crashes/T/ (copy it to Testing/Fuzz/crashers/T/).
      mkdir -p "$fuzz/corpus/$t" "$fuzz/crashes/$t"
      seeds=("$root/Testing/Fuzz/corpus/$t")
      if [ -d "$root/Testing/Fuzz/crashers/$t" ]; then
        seeds+=("$root/Testing/Fuzz/crashers/$t")
      fi
      # Fuzzing with frame-pointer stacks and no leak check (4 times faster: the full stacks
      # the suppressions need cost a DWARF unwind per allocation); then every input of the
      # grown corpus once more with the leak check and full stacks.
      echo "== fuzzing $t for $seconds s"
      env "${sanitizer_env[@]}" ASAN_OPTIONS="$asan_options:detect_leaks=0" "$fuzz/bin/GlobeFuzz$t" \
        -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=60 -detect_leaks=0 \
        -print_final_stats=1 -artifact_prefix="$fuzz/crashes/$t/" "$@" "$fuzz/corpus/$t" \
        "${seeds[@]}"
      echo "== leak check of $t's corpus"
      env "${sanitizer_env[@]}" "${full_stacks_env[@]}" "$fuzz/bin/GlobeFuzz$t" -runs=0 -detect_leaks=1 \
        -rss_limit_mb=2048 -timeout=60 -artifact_prefix="$fuzz/crashes/$t/" \
        "$fuzz/corpus/$t" "${seeds[@]}"
    done
    ;;
  bench)
    install_packages
    build_project
    # From scratch: the JSON, then the plots, the Pareto fronts and the report's tables from it.
    # A --quick (smoke) run leaves the report alone and puts its plots in the build tree.
    images="$root/Documentation/images"
    report=(--markdown "$root/Documentation/accuracy-vs-time.md")
    for arg in "$@"; do
      if [ "$arg" = "--quick" ]; then
        images="$build/benchmark-images"
        report=()
      fi
    done
    rm -f "$build/benchmark.json" "$images"/accuracy-vs-time-*.png
    echo "== running the benchmark (a program, not a test; glibc malloc tuned)"
    with_display env \
      GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=536870912 \
      "$build/bin/GlobeBenchmark" --json "$build/benchmark.json" "$@"
    echo "== plotting"
    with_display env PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
      /usr/bin/python3 "$root/Utilities/plot_benchmark.py" "$build/benchmark.json" \
      --images "$images" "${report[@]}"
    ;;
  bench-cost)
    install_packages
    build_project
    echo "== what the frame costs against what it shows (GlobeCostBenchmark; glibc malloc tuned)"
    with_display env \
      GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=536870912 \
      "$build/bin/GlobeCostBenchmark" --json "$build/cost.json" "$@"
    ;;
  bench-streaming)
    install_packages
    build_project
    planet="${VTKGLOBE_PLANET_DIR:-$build/planet}"
    planets=()
    for w in ${VTKGLOBE_PLANET_WIDTHS:-2048 8192 21600 43200}; do
      # Both files, each renamed into place only when complete (GlobeMakePlanet).
      if [ ! -f "$planet/planet_heights_$w.tif" ] || [ ! -f "$planet/planet_imagery_$w.tif" ]; then
        echo "== making the ${w}-wide global rasters (GlobeMakePlanet)"
        "$build/bin/GlobeMakePlanet" "$root/Data" "$planet" --width "$w"
      fi
      planets+=(--planet "$w:$planet/planet_heights_$w.tif:$planet/planet_imagery_$w.tif")
    done
    echo "== flying (GlobeStreamingBenchmark; glibc malloc tuned: see the developers' notes)"
    with_display env \
      GLIBC_TUNABLES=glibc.malloc.mmap_threshold=268435456:glibc.malloc.trim_threshold=536870912 \
      "$build/bin/GlobeStreamingBenchmark" --data "$root/Data" "${planets[@]}" \
      --json "$build/streaming.json" "$@"
    with_display env PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
      /usr/bin/python3 "$root/Utilities/plot_streaming.py" "$build/streaming.json"
    ;;
  build)
    install_packages
    build_project
    ;;
  prepare)
    install_packages
    build_project
    echo "== preparing (GlobePrepare $*)"
    "$build/bin/GlobePrepare" "$@"
    ;;
  paraview)
    install_packages
    run_paraview "$@"
    ;;
  pvpython)
    install_packages >&2
    run_paraview_program pvpython "$@"
    ;;
  pvbatch)
    install_packages >&2
    run_paraview_program pvbatch "$@"
    ;;
  python)
    install_packages >&2
    build_project >&2
    # Debian's interpreter: the one VTK's Python modules are built for.
    with_display env PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
      /usr/bin/python3 "$@"
    ;;
  *)
    echo "usage: $0 demo|test|check|check-core|fuzz|bench|bench-cost|bench-streaming|build|prepare|python|paraview|pvpython|pvbatch [args]" >&2
    exit 2
    ;;
esac
