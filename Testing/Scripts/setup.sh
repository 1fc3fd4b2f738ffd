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
# (test: skip the sanitizer build, for a quick local run; CI never sets it),
# TYNDALL_SANITIZE_ALL=1 (test: run every test under the sanitizers, not only
# the selection of Documentation/testing.md, "Sanitizers").
#
# Every mode ends with the time of each stage (packages, builds, suites) and,
# after a test run, the 20 slowest tests of each suite: the figures of
# Documentation/testing.md, "What CI costs".
set -euo pipefail

mode="${1:-render}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${TYNDALL_BUILD_DIR:-$root/build}"
sanitizer_build="${TYNDALL_SANITIZER_BUILD_DIR:-$root/build-asan}"
jobs="${TYNDALL_JOBS:-$(nproc)}"

# The time of each stage, printed when the script ends (also on failure).
stage_lines=()
stage_name=""
stage_start=0
suites_run=()
begin_stage() {
  stage_name="$1"
  stage_start=$SECONDS
  echo "setup: stage '$stage_name'" >&2
}
end_stage() {
  stage_lines+=("$(printf '%7d s  %s' $((SECONDS - stage_start)) "$stage_name")")
  stage_name=""
}
# Runs "$@" as the stage $1 (a failure still ends the script: set -e).
timed() {
  begin_stage "$1"
  shift
  "$@"
  end_stage
}
print_profile() {
  local status=$?
  if [ -n "$stage_name" ]; then
    stage_lines+=("$(printf '%7d s  %s (failed)' $((SECONDS - stage_start)) "$stage_name")")
  fi
  if [ "${#stage_lines[@]}" -gt 0 ]; then
    echo "setup: time per stage (wall clock, $jobs jobs):" >&2
    printf '%s\n' "${stage_lines[@]}" >&2
    printf '%7d s  in all\n' "$SECONDS" >&2
  fi
  local dir
  for dir in "${suites_run[@]}"; do
    echo "setup: the slowest tests of $dir:" >&2
    bash "$root/Testing/Scripts/slowest-tests.sh" "$dir" 20 >&2 || true
  done
  return "$status"
}
trap print_profile EXIT

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

# Both builds compile the libraries in batches (TYNDALL_UNITY_BUILD: a
# fresh build's libraries in about half the time; CMakeLists.txt).
build_tyndall() {
  local paraview
  paraview="$(paraview_dir)"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTYNDALL_UNITY_BUILD=ON \
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
      -DTYNDALL_SANITIZE=ON -DTYNDALL_ENABLE_FUZZING=OFF -DTYNDALL_UNITY_BUILD=ON \
      -DPython3_EXECUTABLE=/usr/bin/python3 >&2
  fi
  # The NoSanitizer tests are built only when the suite runs them.
  if [ "${TYNDALL_SANITIZE_ALL:-0}" = 1 ]; then
    cmake -DTYNDALL_SANITIZE_ALL_TESTS=ON "$sanitizer_build" >&2
  fi
  cmake --build "$sanitizer_build" -j "$jobs" >&2
}

# Rendering needs an X display: Debian's VTK renders through GLX only. One
# server for the whole command, which never resets and picks its display
# number without a race (with-display.sh says why).
with_display() {
  bash "$root/Testing/Scripts/with-display.sh" "$@"
}

# Runs the suite of build directory $1 (further arguments go to ctest) under
# one virtual display. No retries: with one server that never resets there is
# no "bad X server connection" to retry (Documentation/testing.md, "One X
# display"); any failure fails the run.
run_suite() {
  local dir="$1"
  shift
  suites_run+=("$dir")
  (cd "$dir" && with_display ctest --output-on-failure -j "$jobs" "$@")
}

# What the sanitizer suite runs: every test but those labelled
# NoSanitizer (rendering tests whose code under test is the GPU's and whose
# CPU side other tests cover; Documentation/testing.md, "Sanitizers"), or
# every test with TYNDALL_SANITIZE_ALL=1.
sanitizer_selection() {
  if [ "${TYNDALL_SANITIZE_ALL:-0}" = 1 ]; then
    return
  fi
  echo -LE NoSanitizer
}

case "$mode" in
  render)
    timed packages install_packages
    timed "build ($build)" build_tyndall
    timed "render the default scene" with_display "$build/bin/tyndall-render" -o "$build/tyndall-cloud.png"
    ;;
  test)
    timed packages install_packages
    timed "build ($build)" build_tyndall
    timed "test suite ($build)" run_suite "$build"
    if [ "${TYNDALL_SKIP_SANITIZERS:-0}" = 1 ]; then
      echo "setup: TYNDALL_SKIP_SANITIZERS=1: the sanitizer build is skipped" >&2
      exit 0
    fi
    timed "sanitizer build ($sanitizer_build)" build_sanitized
    # shellcheck disable=SC2046 # the selection is zero or two words
    timed "test suite under AddressSanitizer and UBSan ($sanitizer_build)" \
      run_suite "$sanitizer_build" $(sanitizer_selection)
    ;;
  build)
    timed packages install_packages
    timed "build ($build)" build_tyndall
    ;;
  *)
    echo "usage: $0 [render|test|build]" >&2
    exit 2
    ;;
esac
