#!/bin/bash
# Runs a program packed by gpu-bundle.sh on a bare GPU machine (see
# Documentation/benchmarks-gpu.md), from the folder that holds the archives:
#
#   gpu-run.sh --unpack base                      # first call: unpack base
#   gpu-run.sh --unpack app -- BenchParticles     # next call: app, then run
#   gpu-run.sh -- BenchParticles --quick          # later calls
#
# Unpacks into /tmp/tyndall-gpu, puts the keyboard data and Mesa's driver
# where Xvfb looks for them (/usr/share/X11/xkb and the Debian driver
# folder: this writes outside /tmp, so run it on a throw-away machine only),
# starts Xvfb, and runs the program with the NVIDIA GLX vendor through the
# carried loader (TYNDALL_GPU_VENDOR=mesa: on the CPU, for a check).
set -euo pipefail

root=/tmp/tyndall-gpu
here=$(cd "$(dirname "$0")" && pwd)
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    --unpack) mkdir -p "$root" && tar -C "$root" -xJf "$here/$2.tar.xz"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] && shift # the --
[ $# -gt 0 ] || exit 0
[ -d "$root/base" ] && [ -d "$root/app" ] || { echo "unpack base and app first" >&2; exit 3; }

nvidia=$(dirname "$(find / -xdev -name 'libGLX_nvidia.so.0' 2>/dev/null | head -1)")
loader="$root/base/lib/$(ls "$root/base/lib" | grep '^ld-linux' | head -1)"
path="$root/app/lib:$root/base/lib:$nvidia"
run() { "$loader" --library-path "$path" "$@"; }

# Xvfb finds the keyboard compiler on PATH (or at /usr/bin) and its data and Mesa's driver at
# the paths Debian built it with.
mkdir -p "$root/path" /usr/share/X11 /usr/lib/x86_64-linux-gnu/dri
printf '#!/bin/sh\nexec "%s" --library-path "%s" "%s" "$@"\n' "$loader" "$path" \
  "$root/base/bin/xkbcomp" > "$root/path/xkbcomp"
chmod +x "$root/path/xkbcomp"
# Xvfb may also call it by the absolute path it was built with.
[ -e /usr/bin/xkbcomp ] || cp "$root/path/xkbcomp" /usr/bin/xkbcomp
[ -e /usr/share/X11/xkb ] || cp -r "$root/base/xkb" /usr/share/X11/xkb
cp -n "$root/base/dri/swrast_dri.so" /usr/lib/x86_64-linux-gnu/dri/
display=:${TYNDALL_GPU_DISPLAY:-9}
PATH="$root/path:$PATH" run "$root/base/bin/Xvfb" "$display" -screen 0 1280x1024x24 \
  -nolisten tcp > /tmp/tyndall-gpu-xvfb.log 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 3
program=$1
shift
[ -x "$program" ] || program="$root/app/bin/$program"
DISPLAY=$display __GLX_VENDOR_LIBRARY_NAME=${TYNDALL_GPU_VENDOR:-nvidia} run "$program" "$@"
