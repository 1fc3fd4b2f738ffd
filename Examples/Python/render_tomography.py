#!/usr/bin/python3
"""Render a tomography (or simulation) volume with a Tyndall transfer-function preset.

Loads any volume format VTK reads -- a DICOM directory (or a .dcm file),
NIfTI (.nii, .nii.gz), MetaImage (.mhd, .mha), NRRD (.nrrd, .nhdr), VTK XML
image data (.vti), legacy structured points (.vtk), SLC (.slc) -- or an
OpenVDB file (.vdb, through Tyndall's vtkOpenVDBImageReader), and renders it
with VTK's GPU ray caster and a vtkTransferFunctionPresets preset, on screen
or into a PNG.

    /usr/bin/python3 render_tomography.py HeadMRVolume.mhd --output head.png

Run it with /usr/bin/python3 (Debian's VTK bindings import only there) and
Tyndall's package on PYTHONPATH (build/lib/python3/dist-packages in a build
tree).  Debian's VTK renders through GLX: without a display, run it under
xvfb-run.  Exit status: 0 on success, 1 when reading or rendering fails (or
--check finds an empty picture), 2 for bad arguments, 125 with
--skip-missing and a missing input.
"""

import argparse
import os
import sys

# Import VTK module by module: `import vtk` replaces vtkNrrdReader.
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkIOImage import (
    vtkDICOMImageReader,
    vtkMetaImageReader,
    vtkNIFTIImageReader,
    vtkNrrdReader,
    vtkPNGWriter,
    vtkSLCReader,
)
from vtkmodules.vtkIOLegacy import vtkStructuredPointsReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkRenderingCore import (
    vtkRenderer,
    vtkRenderWindow,
    vtkRenderWindowInteractor,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkInteractionStyle  # noqa: F401  (interactor style factory)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL render window factory)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (GPU ray caster factory)

from tyndall import vtkOpenVDBImageReader, vtkTransferFunctionPresets

BACKGROUND = (0.1, 0.1, 0.14)


def preset_names():
    return [vtkTransferFunctionPresets.GetPresetName(i)
            for i in range(vtkTransferFunctionPresets.GetNumberOfPresets())]


def make_reader(path, grid=None):
    """The VTK reader for `path`, or None for an unknown kind of file."""
    lower = path.lower()
    if os.path.isdir(path):
        reader = vtkDICOMImageReader()
        reader.SetDirectoryName(path)
        return reader
    for suffixes, cls in (((".dcm",), vtkDICOMImageReader),
                          ((".nii", ".nii.gz"), vtkNIFTIImageReader),
                          ((".mhd", ".mha"), vtkMetaImageReader),
                          ((".nrrd", ".nhdr"), vtkNrrdReader),
                          ((".vti",), vtkXMLImageDataReader),
                          ((".vtk",), vtkStructuredPointsReader),
                          ((".slc",), vtkSLCReader),
                          ((".vdb",), vtkOpenVDBImageReader)):
        if lower.endswith(suffixes):
            reader = cls()
            reader.SetFileName(path)
            if cls is vtkOpenVDBImageReader and grid:
                reader.SetGridName(grid)
            return reader
    return None


def default_preset(path, scalar_range):
    """Cloud for OpenVDB fog, CT for data in Hounsfield units, else MR."""
    if path.lower().endswith(".vdb"):
        return "Cloud"
    return "CT" if scalar_range[0] < -500.0 else "MR"


def count_lit_pixels(image):
    """Pixels that differ from the background by more than 8 levels."""
    scalars = image.GetPointData().GetScalars()
    background = [round(255 * c) for c in BACKGROUND]
    lit = 0
    for p in range(scalars.GetNumberOfTuples()):
        if max(abs(int(scalars.GetComponent(p, c)) - background[c]) for c in range(3)) > 8:
            lit += 1
    return lit, scalars.GetNumberOfTuples()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="DICOM directory or a .dcm, .nii(.gz), .mhd, .mha, "
                        ".nrrd, .nhdr, .vti, .vtk, .slc or .vdb file")
    parser.add_argument("--preset", help="one of: " + ", ".join(preset_names()) +
                        " (default: Cloud for .vdb, CT below -500, else MR)")
    parser.add_argument("--grid", help="the OpenVDB grid to read")
    parser.add_argument("--output", help="render once off screen into this PNG")
    parser.add_argument("--size", type=int, nargs=2, default=(512, 512), metavar=("W", "H"))
    parser.add_argument("--check", action="store_true",
                        help="with --output: fail when the picture shows only background")
    parser.add_argument("--skip-missing", action="store_true",
                        help="exit with 125 (CTest's skip code) when the input is absent")
    args = parser.parse_args(argv)

    if args.preset and vtkTransferFunctionPresets.GetPresetIndex(args.preset) < 0:
        print("unknown preset %r; the presets: %s" % (args.preset, ", ".join(preset_names())),
              file=sys.stderr)
        return 2
    if not os.path.exists(args.input):
        print("%s: no such file or directory" % args.input, file=sys.stderr)
        return 125 if args.skip_missing else 1
    reader = make_reader(args.input, args.grid)
    if reader is None:
        print("%s: unknown kind of file" % args.input, file=sys.stderr)
        return 2
    reader.Update()
    image = reader.GetOutputDataObject(0)
    if image is None or image.GetNumberOfPoints() == 0 or image.GetPointData().GetScalars() is None:
        print("%s: could not be read (see the errors above)" % args.input, file=sys.stderr)
        return 1
    scalar_range = list(image.GetPointData().GetScalars().GetRange(0))
    if not scalar_range[0] < scalar_range[1]:
        scalar_range[1] = scalar_range[0] + 1.0
    preset = args.preset or default_preset(args.input, scalar_range)
    spacing = image.GetSpacing()
    print("%s: %d x %d x %d, spacing %g %g %g, values %g .. %g, preset %s"
          % ((args.input,) + image.GetDimensions() + spacing + tuple(scalar_range) + (preset,)))

    prop = vtkVolumeProperty()
    if not vtkTransferFunctionPresets.Apply(preset, prop, scalar_range):
        return 1
    prop.SetScalarOpacityUnitDistance(sum(spacing) / 3.0)
    mapper = vtkGPUVolumeRayCastMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(*BACKGROUND)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30.0)
    camera.Elevation(20.0)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    window.SetWindowName("Tyndall tomography")
    if not args.output:
        interactor = vtkRenderWindowInteractor()
        interactor.SetRenderWindow(window)
        window.Render()
        interactor.Start()
        return 0

    window.SetOffScreenRendering(1)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(args.output)
    writer.Write()
    print("wrote " + args.output)
    if args.check:
        lit, total = count_lit_pixels(grab.GetOutput())
        print("%d of %d pixels show the volume" % (lit, total))
        if total == 0 or lit < total // 200:
            print("the picture shows (almost) nothing but the background", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    vtkObject.GlobalWarningDisplayOn()
    sys.exit(main())
