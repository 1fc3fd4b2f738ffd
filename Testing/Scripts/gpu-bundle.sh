#!/bin/bash
# Packs Tyndall programs for a bare GPU machine (no VTK, no X server, no
# Mesa: only the NVIDIA driver), as Documentation/benchmarks-gpu.md
# describes. Debian's VTK renders through GLX only, so the programs run on a
# carried Xvfb whose GLX extension is Mesa's (it needs Mesa's swrast_dri.so to
# offer any visual), while the client side asks for the NVIDIA GLX vendor
# (__GLX_VENDOR_LIBRARY_NAME=nvidia): the rendering then runs on the GPU.
#
#   Testing/Scripts/gpu-bundle.sh OUTDIR PROGRAM...
#
# writes OUTDIR/base.tar.xz (the loader, Xvfb, xkbcomp and their keyboard
# data, Mesa's swrast driver, the GL client libraries and every library these
# load) and OUTDIR/app.tar.xz (the programs and the libraries they need beyond
# base), and copies OUTDIR/gpu-run.sh beside them. The two archives are apart
# because one carry to the machine holds at most 64 MiB: carry base first
# (`gpu-run.sh --unpack base`), then app in the next call while the machine
# is still warm (`gpu-run.sh --unpack app -- PROGRAM ARGS...`).
set -euo pipefail

if [ $# -lt 2 ]; then
  echo "usage: $0 OUTDIR PROGRAM..." >&2
  exit 2
fi
out=$1
shift
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
libdir=/usr/lib/$multiarch
# What base holds: the X server, the keyboard compiler, Mesa's software driver
# (Xvfb's GLX loads it by its absolute path), and libglvnd's and Mesa's GLX
# client libraries, which open libxcb-glx and friends with dlopen (ldd of a
# program does not list them).
base_files=(/usr/bin/Xvfb /usr/bin/xkbcomp "$libdir/dri/swrast_dri.so"
  "$libdir/libGLX_mesa.so.0" "$libdir/libGLX.so.0" "$libdir/libGL.so.1"
  "$libdir/libGLdispatch.so.0" "$libdir/libOpenGL.so.0")

# The libraries a file needs (ldd's resolved paths).
needs() {
  ldd "$1" 2>/dev/null | awk '/=> \// { print $3 }'
}

mkdir -p "$work/base/lib" "$work/base/bin" "$work/base/dri" "$work/app/lib" "$work/app/bin"
cp -L "$(ldd /usr/bin/Xvfb | awk '/ld-linux/ { print $1 }')" "$work/base/lib/"
cp /usr/bin/Xvfb /usr/bin/xkbcomp "$work/base/bin/"
cp "$libdir/dri/swrast_dri.so" "$work/base/dri/"
cp -r /usr/share/X11/xkb "$work/base/xkb"
for f in "${base_files[@]}"; do
  [ -e "$f" ] || { echo "missing $f" >&2; exit 1; }
  case "$f" in *.so*) cp -L "$f" "$work/base/lib/" ;; esac
  for l in $(needs "$f"); do cp -nL "$l" "$work/base/lib/"; done
done
for program in "$@"; do
  [ -x "$program" ] || { echo "not a program: $program" >&2; exit 1; }
  cp -L "$program" "$work/app/bin/"
  for l in $(needs "$program"); do
    [ -e "$work/base/lib/$(basename "$l")" ] || cp -nL "$l" "$work/app/lib/"
  done
done
strip --strip-unneeded "$work"/app/bin/* "$work"/app/lib/libTyndall* 2>/dev/null || true
tar -C "$work" -cJf "$out/base.tar.xz" base
tar -C "$work" -cJf "$out/app.tar.xz" app
cp "$(dirname "$0")/gpu-run.sh" "$out/"
du -h "$out"/*.tar.xz
