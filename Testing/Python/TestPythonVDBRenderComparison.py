"""Tyndall against an independent renderer: smoke.vdb rendered by OpenVDB's
vdb_render and by vtkTransmittanceVolumeMapper (brute force) under matched
camera, light and units; asserts the PSNR reached.

Matching the units (see ../shared/data/README.md and OpenVDB's
tools/RayTracer.h, VolumeRender):
- vdb_render's extinction is (scatter + absorb) * density per voxel length,
  so Tyndall's sigma_t = k * density with k = (scatter + absorb) / voxel
  size; the opacity transfer function alpha(rho) = 1 - exp(-k rho u) is
  tabulated finely so that -ln(1 - alpha) / u is linear in rho.
- vdb_render's phase function is 1 and its light colour is the irradiance:
  Tyndall's default LightScale (4 pi) with an isotropic phase (1 / 4 pi)
  and the same light colour gives the same in-scattering.
- The albedo is scatter / (scatter + absorb).
- -gain 0 and a tiny -cutoff turn off vdb_render's multiple-scattering
  heuristic and its density skipping; -fov is horizontal.
- Values stay below 1, so vdb_render's PNG (which wraps values above 1)
  holds the radiance exactly as an 8-bit frame buffer would.

Skips (exit 125) when ../shared/data/vdb/smoke.vdb or vdb_render is absent.
"""

import math
import os
import shutil
import subprocess
import sys
import tempfile

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import tyndall

SMOKE = os.path.join(os.environ.get("TYNDALL_SHARED_DATA", ""), "vdb", "smoke.vdb")
if not os.path.exists(SMOKE):
    print("skip: %s is absent" % SMOKE)
    sys.exit(125)
VDB_RENDER = shutil.which("vdb_render")
if not VDB_RENDER:
    print("skip: vdb_render (Debian libopenvdb-tools) is not installed")
    sys.exit(125)
if not hasattr(tyndall, "vtkOpenVDBImageReader"):
    print("skip: Tyndall was built without Tyndall::IO")
    sys.exit(125)

SIZE = 160
SCATTER, ABSORB = 0.05, 0.01
LIGHT = (0.4, 1.0, 0.3)            # towards the light
LIGHT_COLOR = (0.55, 0.55, 0.55)
FOV = 40.0                          # horizontal, degrees

reader = tyndall.vtkOpenVDBImageReader()
reader.SetFileName(SMOKE)
reader.SetGridName("density")
reader.Update()
image = reader.GetOutput()
bounds = image.GetBounds()
spacing = image.GetSpacing()[0]
center = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
extent = max(bounds[2 * k + 1] - bounds[2 * k] for k in range(3))
eye = (center[0], center[1], center[2] + 1.6 * extent)

# vdb_render's image.
workdir = tempfile.mkdtemp()
vdb_png = os.path.join(workdir, "vdb.png")
command = [VDB_RENDER, SMOKE, vdb_png, "-name", "density", "-res", "%dx%d" % (SIZE, SIZE),
           "-translate", "%g,%g,%g" % eye, "-lookat", "%g,%g,%g" % tuple(center), "-up", "0,1,0",
           "-fov", str(FOV), "-scatter", "%g,%g,%g" % ((SCATTER,) * 3),
           "-absorb", "%g,%g,%g" % ((ABSORB,) * 3), "-gain", "0", "-cutoff", "1e-9",
           "-light", "%g,%g,%g,%g,%g,%g" % (LIGHT + LIGHT_COLOR), "-step", "0.25",
           "-shadowstep", "0.5"]
subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
png = vtkPNGReader()
png.SetFileName(vdb_png)
png.Update()
reference = png.GetOutput()

# Tyndall's image.
k = (SCATTER + ABSORB) / spacing
unit = 1.0
lo, hi = image.GetScalarRange()
opacity = vtkPiecewiseFunction()
for i in range(513):
    rho = lo + (hi - lo) * i / 512
    opacity.AddPoint(rho, 1.0 - math.exp(-k * max(rho, 0.0) * unit))
albedo = vtkColorTransferFunction()
a = SCATTER / (SCATTER + ABSORB)
albedo.AddRGBPoint(lo, a, a, a)
albedo.AddRGBPoint(hi, a, a, a)
# vdb_render scatters once: Tyndall's multiple-scattering octaves (on by
# default) are turned off to compare the same model.
prop = tyndall.vtkParticipatingMediumProperty()
prop.SetScatteringOctaves(1)
prop.SetScalarOpacity(opacity)
prop.SetColor(albedo)
prop.SetScalarOpacityUnitDistance(unit)
prop.SetInterpolationTypeToLinear()

mapper = tyndall.vtkTransmittanceVolumeMapper()
mapper.SetInputData(image)
mapper.SetTransmittanceMethodToBruteForce()
mapper.SetLightSampleCount(256)
mapper.SetSampleDistance(0.5 * spacing)  # within llvmpipe's loop limit
mapper.JitterOff()
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
renderer = vtkRenderer()
renderer.AddVolume(volume)
renderer.SetBackground(0, 0, 0)
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPositional(False)
light.SetPosition(*LIGHT)
light.SetFocalPoint(0, 0, 0)
light.SetColor(*LIGHT_COLOR)
light.SetIntensity(1.0)
renderer.AddLight(light)
camera = renderer.GetActiveCamera()
camera.SetPosition(*eye)
camera.SetFocalPoint(*center)
camera.SetViewUp(0, 1, 0)
camera.UseHorizontalViewAngleOn()
camera.SetViewAngle(FOV)
camera.SetClippingRange(0.01 * extent, 10 * extent)
window = vtkRenderWindow()
window.SetMultiSamples(0)
window.SetOffScreenRendering(1)
window.SetSize(SIZE, SIZE)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
ours = grab.GetOutput()

# PSNR over RGB; vdb_render's rows run top to bottom in the PNG as VTK's do.
sa, sb = ours.GetPointData().GetScalars(), reference.GetPointData().GetScalars()
n = sa.GetNumberOfTuples()
assert n == sb.GetNumberOfTuples(), "image sizes differ"
squared, peak = 0.0, 0.0
for i in range(n):
    for c in range(3):
        d = sa.GetComponent(i, c) - sb.GetComponent(i, c)
        squared += d * d
        peak = max(peak, sb.GetComponent(i, c))
mse = squared / (3 * n)
psnr = float("inf") if mse == 0 else 10 * math.log10(255 ** 2 / mse)
print("vdb_render peak value %d of 255; PSNR of Tyndall against vdb_render: %.2f dB" % (peak, psnr))
shutil.rmtree(workdir)
if peak >= 250:
    print("FAILED: vdb_render's image saturates; the comparison would be meaningless")
    sys.exit(1)
FLOOR = 36.0  # measured 38.1 dB here (Mesa llvmpipe, 160 x 160)
if not psnr >= FLOOR:
    print("FAILED: PSNR %.2f dB below %.1f dB" % (psnr, FLOOR))
    sys.exit(1)
print("ok")
