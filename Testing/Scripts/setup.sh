#!/usr/bin/env bash
# Tyndall's set-up script for a fresh Debian 12 machine. Idempotent: it
# installs only missing packages and rebuilds only what changed.
#
#   bash Testing/Scripts/setup.sh render   install, build, render the default scene
#   bash Testing/Scripts/setup.sh test     install, build, run every test under Xvfb
#   bash Testing/Scripts/setup.sh build    install and build only
#
# Environment: TYNDALL_BUILD_DIR (default: build), TYNDALL_JOBS (default: nproc).
set -euo pipefail

mode="${1:-render}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${TYNDALL_BUILD_DIR:-$root/build}"
jobs="${TYNDALL_JOBS:-$(nproc)}"

# Every Debian package Tyndall needs to build, test and render.
packages=(
  cmake g++ make pkg-config           # toolchain
  libvtk9-dev vtk9                    # VTK 9.1 (C++ headers, CMake package, wrapping tools)
  python3 python3-dev python3-vtk9    # Python wrapping and tests (/usr/bin/python3)
  xvfb xauth                          # a virtual X display for rendering
  libgl1-mesa-dri libglx-mesa0        # Mesa llvmpipe OpenGL
  libopenvdb-dev libopenvdb-tools     # Tyndall::IO (OpenVDB reader/writer; vdb_print)
  clang libclang-rt-14-dev            # libFuzzer for the reader's fuzz test (Testing/Fuzz)
  libopenexr-dev                      # tyndall-render --exr (linear float OpenEXR output)
  libglfw3-dev libglew-dev            # tyndall-viewer (GLFW window, GLEW)
)

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]; then
      missing+=("$p")
    fi
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return
  fi
  echo "setup: installing ${missing[*]}" >&2
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo); fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
}

build_tyndall() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DPython3_EXECUTABLE=/usr/bin/python3 >&2
  fi
  cmake --build "$build" -j "$jobs" >&2
}

# Rendering needs an X display: Debian's VTK renders through GLX only.
with_display() {
  xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
}

case "$mode" in
  render)
    install_packages
    build_tyndall
    with_display "$build/bin/tyndall-render" -o "$build/tyndall-cloud.png"
    ;;
  test)
    install_packages
    build_tyndall
    cd "$build"
    with_display ctest --output-on-failure -j "$jobs"
    ;;
  build)
    install_packages
    build_tyndall
    ;;
  *)
    echo "usage: $0 [render|test|build]" >&2
    exit 2
    ;;
esac
