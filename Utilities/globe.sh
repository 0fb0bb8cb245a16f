#!/usr/bin/env bash
# Sets up, builds and runs VTKGlobe on Debian 12. Idempotent: installs only missing packages,
# configures once, rebuilds only what changed.
#
#   Utilities/globe.sh demo [args]    build, then render the Earth (PNGs, or a window)
#   Utilities/globe.sh test [args]    build, then run the whole test suite (ctest args pass on)
#   Utilities/globe.sh bench [args]   build, then run the benchmark (table + build/benchmark.json)
#                                     and plot it (Documentation/accuracy-vs-time.md, images/)
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
#
# Environment: VTKGLOBE_BUILD_DIR (default: build/ in the source tree).
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

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
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
    cd "$build"
    with_display ctest --output-on-failure --timeout 900 "$@"
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
    echo "== running the benchmark (a program, not a test)"
    with_display "$build/bin/GlobeBenchmark" --json "$build/benchmark.json" "$@"
    echo "== plotting"
    with_display env PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
      /usr/bin/python3 "$root/Utilities/plot_benchmark.py" "$build/benchmark.json" \
      --images "$images" "${report[@]}"
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
  python)
    install_packages >&2
    build_project >&2
    # Debian's interpreter: the one VTK's Python modules are built for.
    with_display env PYTHONPATH="$build/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
      /usr/bin/python3 "$@"
    ;;
  *)
    echo "usage: $0 demo|test|bench|bench-streaming|build|prepare|python [args]" >&2
    exit 2
    ;;
esac
