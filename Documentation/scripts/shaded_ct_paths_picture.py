"""Renders the documentation's picture of a path-traced shaded CT:
VTK's CT head (../shared/data/volumes/headsq), bone through a plain
vtkVolumeProperty with Shade on, one sun from the upper left, side by side:
the mapper's map-based frame (VTK's shading, shadowed by the maps), its
paths on the GPU and vtkVolumetricPathTracer's (128 samples per pixel each,
8 bounces, tracked shadows). shaded-ct-paths.png.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/shaded_ct_paths_picture.py Documentation/images
"""

import os
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkNrrdReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (its OpenGL implementation)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from tyndall import vtkTransmittanceVolumeMapper, vtkVolumetricPathTracer

SIZE = 240
SAMPLES = 128
BOUNCES = 8
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HEAD = os.path.join(ROOT, "..", "shared", "data", "volumes", "headsq", "quarter.nhdr")
if not os.path.exists(HEAD):
    print("skip: %s is absent" % HEAD)
    sys.exit(0)

reader = vtkNrrdReader()
reader.SetFileName(HEAD)
reader.Update()
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
renderer = vtkRenderer()
renderer.SetBackground(0.2, 0.3, 0.4)
renderer.AddVolume(volume)
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPosition(-1.0, 1.0, 0.6)
light.SetFocalPoint(0.0, 0.0, 0.0)
renderer.AddLight(light)
window = vtkRenderWindow()
window.SetMultiSamples(0)
window.SetOffScreenRendering(1)
window.SetSize(SIZE, SIZE)
window.AddRenderer(renderer)
renderer.ResetCamera()
camera = renderer.GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(20.0)
renderer.ResetCamera()
camera.Zoom(1.3)


def grab():
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.Update()
    return image.GetOutput()


row = vtkImageAppend()
row.SetAppendAxis(0)
mapper.PathTracingOff()
window.Render()
row.AddInputData(grab())
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
row.AddInputData(grab())
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
