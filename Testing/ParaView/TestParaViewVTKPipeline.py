"""The ParaView plugin's scene (tyndall_paraview_scene.py) through a plain
VTK pipeline: the system VTK, Tyndall's Python package, smoke.vdb read by
vtkVolumeFileReader into vtkTransmittanceVolumeMapper. Writes the picture
to the path given as the first argument and compares it with the baseline
that the plugin's picture is compared with (TestParaViewPlugin.py).

Skips (exit 125) without ../shared/data/vdb/smoke.vdb.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight,  # noqa: E402
                                         vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

import tyndall  # noqa: E402
import tyndall_paraview_images as images  # noqa: E402
import tyndall_paraview_scene as scene  # noqa: E402

if not os.path.exists(scene.SMOKE):
    print("skip: %s is absent" % scene.SMOKE)
    sys.exit(125)
output = sys.argv[1]

reader = tyndall.vtkVolumeFileReader()
reader.SetFileName(scene.SMOKE)

color = vtkColorTransferFunction()
for x, r, g, b in scene.COLOR:
    color.AddRGBPoint(x, r, g, b)
opacity = vtkPiecewiseFunction()
for x, a in scene.OPACITY:
    opacity.AddPoint(x, a)
medium = tyndall.vtkParticipatingMediumProperty()
medium.SetColor(color)
medium.SetScalarOpacity(opacity)
medium.SetScalarOpacityUnitDistance(scene.UNIT_DISTANCE)
medium.SetInterpolationTypeToLinear()
medium.SetAmbientIntensity(scene.AMBIENT)
medium.SetScatteringAnisotropy(scene.ANISOTROPY)

mapper = tyndall.vtkTransmittanceVolumeMapper()
mapper.SetInputConnection(reader.GetOutputPort())
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(medium)

renderer = vtkRenderer()
renderer.AddVolume(volume)
renderer.SetBackground(*scene.BACKGROUND)
renderer.AutomaticLightCreationOff()
light = vtkLight()
light.SetLightTypeToSceneLight()
light.PositionalOff()
light.SetPosition(*scene.LIGHT_DIRECTION)
light.SetFocalPoint(0.0, 0.0, 0.0)
light.SetIntensity(scene.LIGHT_INTENSITY)
renderer.AddLight(light)
camera = renderer.GetActiveCamera()
camera.SetPosition(*scene.CAMERA_POSITION)
camera.SetFocalPoint(*scene.FOCAL_POINT)
camera.SetViewUp(*scene.VIEW_UP)
camera.SetViewAngle(scene.VIEW_ANGLE)
renderer.ResetCameraClippingRange()

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(scene.WIDTH, scene.HEIGHT)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()

picture, size = images.rgb(output)
if os.environ.get("TYNDALL_PARAVIEW_REBASELINE"):
    print("wrote %s; not compared" % output)
    sys.exit(0)
baseline, baseline_size = images.rgb(scene.BASELINE)
if size != baseline_size:
    print("FAIL: picture %s, baseline %s" % (size, baseline_size))
    sys.exit(1)
value = scene.psnr(picture, baseline)
print("VTK pipeline against the baseline: %.1f dB (floor %.0f)" % (value, scene.PSNR_FLOOR))
sys.exit(0 if value >= scene.PSNR_FLOOR else 1)
