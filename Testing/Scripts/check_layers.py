#!/usr/bin/env python3
"""Checks the layers of Module/ (Documentation/architecture.md, "Layers"):

  python3 Testing/Scripts/check_layers.py [--library-dir DIR]

1. The medium model (Module/Medium) and the CPU integrators (Module/Reference)
   include no OpenGL header: none of GL/gl*.h, vtk_glew.h, vtkOpenGL*.h,
   vtkShader*.h, vtkTextureObject.h, and no GLSL.
2. No medium, and nothing in those two modules, includes a mapper of
   Module/Rendering (vtkTransmittanceVolumeMapper.h,
   vtkTransmittanceParticleMapper.h) or anything else of Module/Rendering.
3. The modules depend on each other in one direction only:
   Core <- Medium <- Reference, Core <- Medium <- Rendering (and IO, Application,
   ParaView above them): a header or source of a module includes no header of a
   module above it.
4. No circle of includes among Tyndall's classes (a class is its header and its
   source): the classes on a circle are printed.
5. With --library-dir, the built libraries of Medium and Reference link no
   OpenGL library (their ELF NEEDED entries: no libvtkRenderingOpenGL2, no
   libGL, libGLX, libOpenGL, libGLEW).

Exits 1 with a line per violation, 0 when every check holds.
"""

import argparse
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODULE = os.path.join(ROOT, "Module")
# Each module and the modules it may include (directly).
ALLOWED = {
    "Core": set(),
    "Medium": {"Core"},
    "Reference": {"Core", "Medium"},
    "Rendering": {"Core", "Medium"},
    "IO": {"Core"},
    "Application": {"Core", "Medium", "Reference", "Rendering", "IO"},
}
GL_HEADER = re.compile(r"^(GL/|vtk_glew\.h|vtkOpenGL|vtkShader|vtkTextureObject|vtkglew|glad)")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def sources(module):
    files = []
    for pattern in ("*.h", "*.cxx", "*.glsl"):
        files += glob.glob(os.path.join(MODULE, module, pattern))
    return sorted(files)


def includes(path):
    with open(path, encoding="utf-8") as f:
        return INCLUDE.findall(f.read())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--library-dir", help="the build's library folder (build/lib)")
    args = parser.parse_args()
    problems = []

    # Which module owns each Tyndall header.
    owner = {}
    for module in ALLOWED:
        for path in sources(module):
            if path.endswith(".h"):
                owner[os.path.basename(path)] = module
    # The generated shader headers belong to Rendering.
    for path in glob.glob(os.path.join(MODULE, "Rendering", "glsl", "*.glsl")):
        owner[os.path.splitext(os.path.basename(path))[0] + ".h"] = "Rendering"

    edges = {}
    for module, allowed in ALLOWED.items():
        for path in sources(module):
            name = os.path.relpath(path, ROOT)
            if module in ("Medium", "Reference") and path.endswith(".glsl"):
                problems.append("%s: GLSL in the %s module" % (name, module))
            cls = os.path.splitext(os.path.basename(path))[0]
            for header in includes(path):
                if module in ("Medium", "Reference") and GL_HEADER.match(header):
                    problems.append("%s includes the OpenGL header %s" % (name, header))
                target = owner.get(header)
                if target and target != module and target not in allowed:
                    problems.append("%s (%s) includes %s of the %s module above it"
                                    % (name, module, header, target))
                included = os.path.splitext(header)[0]
                if target and included != cls:
                    edges.setdefault(cls, set()).add(included)

    # Circles of includes, class by class (a header and its source are one node).
    def reach(start):
        seen, todo = set(), [start]
        while todo:
            for nxt in edges.get(todo.pop(), ()):
                if nxt not in seen:
                    seen.add(nxt)
                    todo.append(nxt)
        return seen

    circle = sorted(c for c in edges if c in reach(c))
    if circle:
        problems.append("includes go round in a circle among: " + ", ".join(circle))

    if args.library_dir:
        for module in ("Medium", "Reference"):
            found = glob.glob(os.path.join(args.library_dir, "libTyndall%s.so*" % module))
            libraries = [f for f in found if not os.path.islink(f)] or found
            if not libraries:
                problems.append("libTyndall%s.so is not in %s" % (module, args.library_dir))
                continue
            dynamic = subprocess.run(["readelf", "-d", libraries[0]], stdout=subprocess.PIPE,
                                     universal_newlines=True, check=False).stdout
            for needed in re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", dynamic):
                if re.match(r"lib(vtkRenderingOpenGL2|GL|GLX|OpenGL|GLEW|vtkglew)", needed):
                    problems.append("%s links the OpenGL library %s"
                                    % (os.path.basename(libraries[0]), needed))

    for problem in problems:
        print("FAIL:", problem)
    if not problems:
        print("layers: the medium model and the CPU integrators include and link no OpenGL and "
              "no mapper; modules include downwards only; no circle of includes among %d classes"
              % len(edges))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
