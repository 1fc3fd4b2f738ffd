"""Renders the documentation's picture of a path-traced shaded CT:
VTK's CT head (../shared/data/volumes/headsq), bone through a plain
vtkVolumeProperty with Shade on, one scene light from the upper left (the
view of shaded_ct_picture.py), side by side: the mapper's map-based frame
(VTK's shading, shadowed by the maps), its paths on the GPU and
vtkVolumetricPathTracer's (128 samples per pixel each, 8 bounces, tracked
shadows). shaded-ct-paths.png. And the same head lit by a gradient sky
alone (the light off; dim brown straight down to blue straight up): the
map-based frame with the sky's mean as diffuse light | with the sky's 4
lights (the default) | the GPU's paths. shaded-ct-sky.png.

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



def paths(samples):
    """The GPU's paths from a new start until they have `samples` per pixel."""
    mapper.PathTracingOn()
    mapper.SetPathTraceSamplesPerPixel(samples)
    mapper.SetPathTraceSamplesPerFrame(16)
    mapper.SetPathTraceMaximumBounces(BOUNCES)
    mapper.SetPathTraceShadowsToTracked()
    window.Render()  # the map-based frame; the paths start with the next
    for _ in range(4 * samples):
        window.Render()
        if mapper.GetLastPathTraceSamples() >= samples:
            break
    picture = grab(window)
    mapper.PathTracingOff()
    return picture


def write(row, name):
    writer = vtkPNGWriter()
    writer.SetInputConnection(row.GetOutputPort())
    writer.SetFileName(sys.argv[1] + "/" + name)
    writer.Write()


row = vtkImageAppend()
row.SetAppendAxis(0)
mapper.PathTracingOff()
row.AddInputData(grab(window))
row.AddInputData(paths(SAMPLES))
tracer = vtkVolumetricPathTracer()
tracer.SetSamplesPerPixel(SAMPLES)
tracer.SetMaximumBounces(BOUNCES)
tracer.SetDistanceSamplingToDeltaTracking()
tracer.Render(renderer, volume, SIZE, SIZE)
row.AddInputData(tracer.Composite())
write(row, "shaded-ct-paths.png")
print("GPU %d spp, CPU %.1f s" % (mapper.GetLastPathTraceSamples(), tracer.GetLastRenderTime()))

# The sky alone: a gradient from dim brown straight down to blue straight up.
renderer.GetLights().GetItemAsObject(0).SwitchOff()
renderer.GradientEnvironmentalBGOn()
renderer.SetEnvironmentalBG(0.05, 0.04, 0.03)
renderer.SetEnvironmentalBG2(0.15, 0.22, 0.4)
sky = vtkImageAppend()
sky.SetAppendAxis(0)
mapper.SetSkyLightDirections(0)
sky.AddInputData(grab(window))
mapper.SetSkyLightDirections(4)
sky.AddInputData(grab(window))
sky.AddInputData(paths(SAMPLES))
write(sky, "shaded-ct-sky.png")
