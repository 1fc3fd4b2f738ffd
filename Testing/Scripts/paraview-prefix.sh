#!/usr/bin/env bash
# Prepares a private ParaView 5.11 prefix for building and testing Tyndall's
# ParaView plugin on Debian 12, without installing python3-paraview.
#
#   bash Testing/Scripts/paraview-prefix.sh PREFIX
#
# Why: Debian's paraview-dev CMake package names 162 files (ParaView's and its
# VTK's Python modules, pvpython, the wrapping hierarchy files) that only the
# python3-paraview package ships, and python3-paraview conflicts with
# python3-vtk9, which Tyndall's own Python package needs. This script
# downloads python3-paraview (apt-get download: nothing is installed),
# unpacks it under PREFIX, and builds PREFIX/usr as a mirror of /usr made of
# symbolic links, except for:
#   usr/lib/x86_64-linux-gnu/cmake/paraview-5.11   a copy of ParaView's CMake
#       package, so that its imported targets resolve under PREFIX/usr;
#   usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView  the unpacked hierarchy files;
#   usr/lib/python3/dist-packages                 the unpacked Python modules
#       (paraview, ParaView's own vtkmodules): put PREFIX/usr/lib/python3/dist-packages
#       first on PYTHONPATH for pvbatch and pvpython;
#   usr/bin                                       /usr/bin's programs and pvpython.
# The system stays as it was: python3-vtk9 is untouched.
#
# Prints the ParaView_DIR to pass to CMake on its last line. Idempotent:
# a prefix that is already complete is left as it is.
set -euo pipefail

prefix="${1:?usage: $0 PREFIX}"
mkdir -p "$prefix"
prefix="$(cd "$prefix" && pwd)"
arch_lib=lib/x86_64-linux-gnu
pv_cmake=/usr/$arch_lib/cmake/paraview-5.11
stamp="$prefix/.complete"
paraview_dir="$prefix/usr/$arch_lib/cmake/paraview-5.11"

if [ -f "$stamp" ]; then
  echo "$paraview_dir"
  exit 0
fi
# The script replaces PREFIX/usr: it works only in a folder of its own.
marker="$prefix/.tyndall-paraview-prefix"
if [ "$prefix" = / ] || [ "$prefix" = /usr ]; then
  echo "paraview-prefix: refusing to use $prefix as the prefix" >&2
  exit 1
fi
if [ ! -f "$marker" ] && [ -n "$(ls -A "$prefix")" ]; then
  echo "paraview-prefix: $prefix is not empty and was not made by this script: choose another folder" >&2
  exit 1
fi
touch "$marker"
if [ ! -f "$pv_cmake/paraview-config.cmake" ]; then
  echo "paraview-prefix: $pv_cmake/paraview-config.cmake is missing: install paraview-dev" >&2
  exit 1
fi

# 1. python3-paraview of the installed paraview-dev's version, downloaded
# and unpacked (never installed).
version="$(dpkg-query -W -f='${Version}' paraview-dev 2>/dev/null || true)"
if [ -z "$version" ]; then
  echo "paraview-prefix: paraview-dev is not installed" >&2
  exit 1
fi
deb_dir="$prefix/deb"
unpacked="$prefix/unpacked"
mkdir -p "$deb_dir"
deb="$(ls "$deb_dir"/python3-paraview_"${version#*:}"_*.deb 2>/dev/null | head -n 1 || true)"
if [ -z "$deb" ]; then
  rm -f "$deb_dir"/*.deb
  (cd "$deb_dir" && apt-get download "python3-paraview=$version" >&2)
  deb="$(ls "$deb_dir"/python3-paraview_*.deb | head -n 1)"
fi
rm -rf "$unpacked"
dpkg-deb -x "$deb" "$unpacked"

# 2. PREFIX/usr: links to /usr's entries, with real folders where the
# unpacked package or the CMake copy must go.
# mirror DIR SOURCE: DIR holds a link to every entry of SOURCE that it lacks
# (one ln for them all: /usr/lib's thousands of entries, a fork each, took
# half a minute).
mirror() {
  mkdir -p "$1"
  local entry links=()
  for entry in "$2"/* "$2"/.[!.]*; do
    [ -e "$entry" ] || [ -L "$entry" ] || continue
    [ -e "$1/${entry##*/}" ] || [ -L "$1/${entry##*/}" ] || links+=("$entry")
  done
  if [ "${#links[@]}" -gt 0 ]; then
    ln -s -t "$1" "${links[@]}"
  fi
}
usr="$prefix/usr"
rm -rf "$usr"
mkdir -p "$usr/$arch_lib/cmake" "$usr/$arch_lib/vtk/hierarchy" "$usr/lib/python3"
cp -r "$pv_cmake" "$usr/$arch_lib/cmake/"
mv "$unpacked/usr/$arch_lib/vtk/hierarchy/ParaView" "$usr/$arch_lib/vtk/hierarchy/"
mirror "$usr/$arch_lib/vtk/hierarchy" "/usr/$arch_lib/vtk/hierarchy"
mirror "$usr/$arch_lib/vtk" "/usr/$arch_lib/vtk"
mirror "$usr/$arch_lib/cmake" "/usr/$arch_lib/cmake"
mirror "$usr/$arch_lib" "/usr/$arch_lib"
mv "$unpacked/usr/lib/python3/dist-packages" "$usr/lib/python3/"
mirror "$usr/lib/python3" /usr/lib/python3
mirror "$usr/lib" /usr/lib
mkdir -p "$usr/bin"
cp -a "$unpacked/usr/bin/." "$usr/bin/"
mirror "$usr/bin" /usr/bin
mirror "$usr" /usr
rm -rf "$unpacked"

# 3. Check: every file ParaView's imported targets name exists.
missing=0
while IFS= read -r file; do
  if [ ! -e "$file" ]; then
    echo "paraview-prefix: still missing: $file" >&2
    missing=$((missing + 1))
  fi
done < <(grep -ho '"${_IMPORT_PREFIX}/[^"]*"' "$paraview_dir"/*-targets-debug.cmake \
  "$paraview_dir"/vtk/*-targets-debug.cmake 2>/dev/null |
  sed -e 's/^"//' -e 's/"$//' -e "s|\${_IMPORT_PREFIX}|$usr|" | sort -u)
if [ "$missing" -ne 0 ]; then
  echo "paraview-prefix: $missing files named by ParaView's CMake package are missing" >&2
  exit 1
fi
touch "$stamp"
echo "$paraview_dir"
