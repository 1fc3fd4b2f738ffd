#!/usr/bin/python3
"""Render a tomography or simulation volume with Tyndall, from Python.

A thin front-end over Tyndall's kit, like tyndall-render: vtkTyndallOptions
parses the same options (--preset, --transfer-function, --method, --size,
--output, ...; see tyndall-render --help) and vtkTyndallSceneBuilder builds
the same scene: the volume read by vtkVolumeFileReader (DICOM directory,
NIfTI, MetaImage, NRRD, VTK XML or legacy image data, SLC, OpenVDB), the
preset guessed from the data unless one is given, a camera fitted to the
data and a key light, rendered by vtkTransmittanceVolumeMapper. Without
--output it opens an interactive window.

    /usr/bin/python3 render_tomography.py HeadMRVolume.mhd --output head.png

Two options of its own: --check (with --output: fail when the picture shows
nothing) and --skip-missing (exit 125 when the input does not exist, for
tests). Run it with /usr/bin/python3 (Debian's VTK bindings import only
there) and Tyndall's package on PYTHONPATH (build/lib/python3/dist-packages
in a build tree). Debian's VTK renders through GLX: without a display, run
it under xvfb-run. Exit status: 0 on success, 1 when reading or rendering
fails (or --check finds an empty picture), 2 for bad arguments, 125 with
--skip-missing and a missing input.
"""

import os
import sys

# Import VTK module by module: `import vtk` replaces vtkNrrdReader.
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkStringArray
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkRenderer, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401  (interactor style factory)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window factory)

from tyndall import vtkTyndallOptions, vtkTyndallSceneBuilder


class Errors:
    """Collects the error messages of VTK objects (the kit reports through them)."""

    def __init__(self):
        self.messages = []

    def watch(self, obj):
        @calldata_type(VTK_STRING)
        def on_error(_caller, _event, message):
            lines = [line for line in str(message).splitlines() if line.strip()]
            text = lines[-1] if lines else "unknown error"
            self.messages.append(text.split("): ", 1)[-1])
        obj.AddObserver(vtkCommand.ErrorEvent, on_error)


def count_lit_pixels(image):
    """Pixels that are not black."""
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    return sum(1 for i in range(scalars.GetNumberOfTuples())
               if any(scalars.GetComponent(i, c) > 0 for c in range(min(components, 3))))


def main(argv):
    check = "--check" in argv
    skip_missing = "--skip-missing" in argv
    arguments = vtkStringArray()
    for arg in argv:
        if arg not in ("--check", "--skip-missing"):
            arguments.InsertNextValue(arg)
    options = vtkTyndallOptions()
    if not options.ParseArguments(arguments):
        print("render_tomography: %s" % options.GetErrorMessage(), file=sys.stderr)
        return 2
    if options.GetHelpRequested():
        print(options.GetHelp(__doc__))
        return 0
    # tyndall-render's outputs beyond one PNG are not this example's.
    for name in ("exr", "sequence", "orbit", "video"):
        if options.IsSet(name):
            print("render_tomography: --%s is tyndall-render's; this example writes one PNG"
                  % name, file=sys.stderr)
            return 2
    path = options.GetInput()
    if skip_missing and path and not os.path.exists(path):
        print("render_tomography: skipped: %s does not exist" % path, file=sys.stderr)
        return 125

    builder = vtkTyndallSceneBuilder()
    builder.SetOptions(options)
    errors = Errors()
    errors.watch(builder)
    renderer = vtkRenderer()
    if not builder.Build(renderer):
        for message in errors.messages or ["cannot build the scene"]:
            print("render_tomography: %s" % message, file=sys.stderr)
        return 1
    print("render_tomography: %s, %s" % (path or "the default cloud",
                                         builder.GetTransferFunctionDescription()),
          file=sys.stderr)

    window = vtkRenderWindow()
    window.SetSize(int(options.GetNumber("size", 0)), int(options.GetNumber("size", 1)))
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    errors.watch(builder.GetMapper())
    output = options.GetText("output")
    if not output:
        interactor = vtkRenderWindowInteractor()
        interactor.SetRenderWindow(window)
        window.Render()
        interactor.Start()
        return 0

    window.SetOffScreenRendering(1)
    window.Render()
    if errors.messages:
        for message in errors.messages:
            print("render_tomography: rendering failed: %s" % message, file=sys.stderr)
        return 1
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(output)
    writer.Write()
    if writer.GetErrorCode():
        print("render_tomography: cannot write %s" % output, file=sys.stderr)
        return 1
    print(os.path.abspath(output))
    if check:
        lit = count_lit_pixels(grab.GetOutput())
        total = grab.GetOutput().GetNumberOfPoints()
        print("render_tomography: %d of %d pixels lit" % (lit, total), file=sys.stderr)
        if lit < 0.01 * total:
            print("render_tomography: the picture shows nothing", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
