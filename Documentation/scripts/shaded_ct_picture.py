"""Renders the documentation's gradient-shading and isosurface pictures:
VTK's CT head (../shared/data/volumes/headsq) with a plain vtkVolumeProperty,
Shade on, lit by one scene light from the upper left, side by side: VTK
9.1's vtkGPUVolumeRayCastMapper, Tyndall's mapper with the method None
(VTK's picture), Tyndall with the maps' shadows (AdaptiveETM, the default)
and with brute-force shadows. shaded-ct.png: the composite blend mode;
isosurface-ct.png: the isosurface blend mode, skin (translucent) and bone.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/shaded_ct_picture.py Documentation/images
"""

import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume, vtkVolumeProperty
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (its OpenGL implementation)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from tyndall import vtkTransmittanceVolumeMapper
from doc_scene import ct_head_reader, ct_head_window, grab

SIZE = 320
reader = ct_head_reader()
if reader is None:
    sys.exit(0)
lo, hi = reader.GetOutput().GetPointData().GetScalars().GetRange()
span = hi - lo
color = vtkColorTransferFunction()
color.AddRGBPoint(lo, 0.1, 0.2, 0.8)
color.AddRGBPoint(lo + 0.5 * span, 0.9, 0.8, 0.3)
color.AddRGBPoint(hi, 1.0, 0.3, 0.1)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(lo, 0.0)
opacity.AddPoint(lo + 0.4 * span, 0.0)
opacity.AddPoint(hi, 0.3)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(0.5)
prop.SetInterpolationTypeToLinear()
prop.ShadeOn()
prop.SetAmbient(0.0)  # VTK's ambient with a scene light: its ambient colour, black

volume = vtkVolume()
volume.SetProperty(prop)
vtk_mapper = vtkGPUVolumeRayCastMapper()
vtk_mapper.SetInputConnection(reader.GetOutputPort())
tyndall = vtkTransmittanceVolumeMapper()
tyndall.SetInputConnection(reader.GetOutputPort())
tyndall.SetLightSampleCount(256)
volume.SetMapper(vtk_mapper)
window, renderer = ct_head_window(volume, SIZE)


def picture(name):
    """Writes the row of the four renderings to <output>/<name>."""
    row = vtkImageAppend()
    row.SetAppendAxis(0)
    volume.SetMapper(vtk_mapper)
    row.AddInputData(grab(window))
    volume.SetMapper(tyndall)
    for method in ("None", "AdaptiveETM", "BruteForce"):
        getattr(tyndall, "SetTransmittanceMethodTo" + method)()
        row.AddInputData(grab(window))
    writer = vtkPNGWriter()
    writer.SetInputConnection(row.GetOutputPort())
    writer.SetFileName(sys.argv[1] + "/" + name)
    writer.Write()


picture("shaded-ct.png")

# The isosurface blend mode: skin at 600 (opacity 0.4), bone at 1400 (opaque).
for mapper in (vtk_mapper, tyndall):
    mapper.SetBlendModeToIsoSurface()
prop.GetIsoSurfaceValues().SetValue(0, 600.0)
prop.GetIsoSurfaceValues().SetValue(1, 1400.0)
color.RemoveAllPoints()
color.AddRGBPoint(600.0, 0.9, 0.6, 0.5)
color.AddRGBPoint(1400.0, 1.0, 1.0, 0.9)
opacity.RemoveAllPoints()
opacity.AddPoint(600.0, 0.4)
opacity.AddPoint(1400.0, 1.0)
picture("isosurface-ct.png")
