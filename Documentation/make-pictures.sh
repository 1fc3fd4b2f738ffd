#!/usr/bin/env bash
# Regenerates the pictures under Documentation/images from a build of
# Tyndall (default: ./build). Every picture in the documentation comes from
# here; run it after a change that alters them, look at them, commit them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TYNDALL_BUILD_DIR:-$root/build}"
images="$root/Documentation/images"
mkdir -p "$images"
run() { xvfb-run -a -s "-screen 0 1280x1024x24" "$@"; }

# The README's picture: the built-in default scene.
run "$build/bin/tyndall-render" -o "$images/tyndall-cloud.png" -s 384 384

# The method gallery: every method beside the CPU reference, cloud and dense.
PYTHONPATH="$build/lib/python3/dist-packages" run /usr/bin/python3 \
  "$root/Documentation/scripts/method_gallery.py" "$images"
