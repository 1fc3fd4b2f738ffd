"""Renders the documentation's picture of a path-traced shaded CT:
VTK's CT head (../shared/data/volumes/headsq), bone through a plain
vtkVolumeProperty with Shade on, one scene light from the upper left (the
view of shaded_ct_picture.py), side by side: the mapper's map-based frame
(VTK's shading, shadowed by the maps), its paths on the GPU and
vtkVolumetricPathTracer's (128 samples per pixel each, 8 bounces, tracked
shadows). shaded-ct-paths.png.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/shaded_ct_paths_picture.py Documentation/images
"""

import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume, vtkVolumeProperty
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (its OpenGL implementation)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from tyndall import vtkTransmittanceVolumeMapper, vtkVolumetricPathTracer
from doc_scene import ct_head_reader, ct_head_window, grab

SIZE = 240
SAMPLES = 128
BOUNCES = 8
reader = ct_head_reader()
if reader is None:
    sys.exit(0)
color = vtkColorTransferFunction()
color.AddRGBPoint(1150.0, 0.85, 0.6, 0.45)
color.AddRGBPoint(1400.0, 0.95, 0.9, 0.8)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(1150.0, 0.0)
opacity.AddPoint(1400.0, 0.9)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(2.0)
prop.SetInterpolationTypeToLinear()
prop.ShadeOn()
prop.SetAmbient(0.1)
prop.SetDiffuse(0.6)
prop.SetSpecular(0.3)
prop.SetSpecularPower(15.0)

mapper = vtkTransmittanceVolumeMapper()
mapper.SetInputConnection(reader.GetOutputPort())
mapper.JitterOff()
mapper.InteractiveAdjustmentOff()
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
window, renderer = ct_head_window(volume, SIZE)

row = vtkImageAppend()
row.SetAppendAxis(0)
mapper.PathTracingOff()
row.AddInputData(grab(window))
mapper.PathTracingOn()
mapper.SetPathTraceSamplesPerPixel(SAMPLES)
mapper.SetPathTraceSamplesPerFrame(16)
mapper.SetPathTraceMaximumBounces(BOUNCES)
mapper.SetPathTraceShadowsToTracked()
window.Render()  # the map-based frame; the paths start with the next
for _ in range(4 * SAMPLES):
    window.Render()
    if mapper.GetLastPathTraceSamples() >= SAMPLES:
        break
row.AddInputData(grab(window))
tracer = vtkVolumetricPathTracer()
tracer.SetSamplesPerPixel(SAMPLES)
tracer.SetMaximumBounces(BOUNCES)
tracer.SetDistanceSamplingToDeltaTracking()
tracer.Render(renderer, volume, SIZE, SIZE)
row.AddInputData(tracer.Composite())
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/shaded-ct-paths.png")
writer.Write()
print("GPU %d spp, CPU %.1f s" % (mapper.GetLastPathTraceSamples(), tracer.GetLastRenderTime()))
