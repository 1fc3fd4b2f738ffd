#!/usr/bin/env bash
# Tyndall's set-up script for a fresh Debian 12 machine. Idempotent: it
# installs only missing packages and rebuilds only what changed.
#
#   bash Testing/Scripts/setup.sh render   install, build, render the default scene
#   bash Testing/Scripts/setup.sh test     install, build, run every test under Xvfb;
#                                          then the same suite built with AddressSanitizer
#                                          and UndefinedBehaviorSanitizer (build-asan/)
#   bash Testing/Scripts/setup.sh build    install and build only
#
# Environment: TYNDALL_BUILD_DIR (default: build), TYNDALL_SANITIZER_BUILD_DIR
# (default: build-asan), TYNDALL_JOBS (default: nproc), TYNDALL_SKIP_SANITIZERS=1
# (test: skip the sanitizer build, for a quick local run; CI never sets it).
set -euo pipefail

mode="${1:-render}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${TYNDALL_BUILD_DIR:-$root/build}"
sanitizer_build="${TYNDALL_SANITIZER_BUILD_DIR:-$root/build-asan}"
jobs="${TYNDALL_JOBS:-$(nproc)}"

# Every Debian package Tyndall needs to build, test and render.
packages=(
  cmake g++ make pkg-config           # toolchain
  libvtk9-dev vtk9                    # VTK 9.1 (C++ headers, CMake package, wrapping tools)
  python3 python3-dev python3-vtk9    # Python wrapping and tests (/usr/bin/python3)
  python3-numpy                       # the benchmark export's test, the report scripts
  xvfb xauth                          # a virtual X display for rendering
  libgl1-mesa-dri libglx-mesa0        # Mesa llvmpipe OpenGL
  libopenvdb-dev libopenvdb-tools     # Tyndall::IO (OpenVDB reader/writer; vdb_print)
  clang libclang-rt-14-dev            # libFuzzer for the reader's fuzz test (Testing/Fuzz)
  libopenexr-dev                      # tyndall-render --exr (linear float OpenEXR output)
  libglfw3-dev libglew-dev            # tyndall-viewer (GLFW window, GLEW)
  libgdcm-tools dcmtk                 # a DICOM test series made by Debian's tools
  paraview-dev                        # the ParaView 5.11 plugin (Module/ParaView); its
                                      # pvbatch comes with it (package paraview)
  openmpi-bin                         # mpirun, for the plugin's distributed-rendering test
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

# ParaView 5.11 for the plugin: Debian's paraview-dev needs files of
# python3-paraview, which conflicts with python3-vtk9; paraview-prefix.sh
# downloads and unpacks it into a prefix in the build tree (nothing is
# installed or removed) and prints the ParaView_DIR to configure with.
# A failure here (no network for the download, say) is not fatal: the
# build goes on without the plugin, and the configure log says why.
paraview_dir() {
  local dir
  if dir="$(bash "$root/Testing/Scripts/paraview-prefix.sh" "$build/paraview-prefix" | tail -n 1)" &&
    [ -n "$dir" ]; then
    echo "$dir"
  else
    echo "setup: WARNING: the ParaView prefix could not be made; the ParaView plugin is skipped" >&2
  fi
}

build_tyndall() {
  local paraview
  paraview="$(paraview_dir)"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
    -DPython3_EXECUTABLE=/usr/bin/python3 "-DParaView_DIR=$paraview" >&2
  cmake --build "$build" -j "$jobs" >&2
}

# The sanitizer build: every Tyndall target with -fsanitize=address,undefined
# (Testing/Sanitizers/TyndallSanitizers.cmake), -O1 with line tables for
# readable reports. The fuzz target has its own sanitizers and is left out.
build_sanitized() {
  if [ ! -f "$sanitizer_build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$sanitizer_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1" \
      -DTYNDALL_SANITIZE=ON -DTYNDALL_ENABLE_FUZZING=OFF \
      -DPython3_EXECUTABLE=/usr/bin/python3 >&2
  fi
  cmake --build "$sanitizer_build" -j "$jobs" >&2
}

# Rendering needs an X display: Debian's VTK renders through GLX only.
with_display() {
  xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
}

# Runs the suite of build directory $1 under a virtual display. Xvfb sometimes
# refuses a client under load ("bad X server connection", a known race of
# xvfb-run): tests that failed with nothing but that are run once more, named
# on stderr; any other failure fails the run.
run_suite() {
  local dir="$1"
  if (cd "$dir" && with_display ctest --output-on-failure -j "$jobs"); then
    return 0
  fi
  local failed="$dir/Testing/Temporary/LastTestsFailed.log"
  local log="$dir/Testing/Temporary/LastTest.log"
  [ -f "$failed" ] && [ -f "$log" ] || return 1
  local names=() name
  while IFS=: read -r _ name; do
    # The test's output in LastTest.log, from its header to the next one.
    if ! awk -v t="$name" '$0 ~ "^[0-9]+/[0-9]+ Testing: "t"$" {on=1; next}
        on && /^[0-9]+\/[0-9]+ Testing: / {exit} on' "$log" |
      grep -qE 'bad X server connection|cannot open display|Could not open display'; then
      echo "setup: $name failed for a reason other than the X server; no retry" >&2
      return 1
    fi
    names+=("$name")
  done <"$failed"
  [ "${#names[@]}" -gt 0 ] || return 1
  # Test names hold letters, digits, ':', '_' and '-' only: no escaping.
  local pattern
  pattern="^($(IFS='|'; echo "${names[*]}"))\$"
  echo "setup: retrying once after an X server connection failure: ${names[*]}" >&2
  (cd "$dir" && with_display ctest --output-on-failure -R "$pattern")
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
    echo "setup: the test suite ($build)" >&2
    run_suite "$build"
    if [ "${TYNDALL_SKIP_SANITIZERS:-0}" = 1 ]; then
      echo "setup: TYNDALL_SKIP_SANITIZERS=1: the sanitizer build is skipped" >&2
      exit 0
    fi
    build_sanitized
    echo "setup: the test suite under AddressSanitizer and UBSan ($sanitizer_build)" >&2
    run_suite "$sanitizer_build"
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
