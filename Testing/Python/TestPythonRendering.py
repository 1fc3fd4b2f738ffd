"""Python wrapping of Tyndall::Rendering: the mapper renders a cloud in a
VTK pipeline from Python, its parameters clamp, the map cache works, and the
CPU reference agrees with the in-shader brute force."""

import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from tyndall import (vtkCosineNoiseSource, vtkSingleScatteringReference,
                     vtkTransmittanceVolumeMapper)

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED:", what, file=sys.stderr)


source = vtkCosineNoiseSource()
source.SetWholeExtent(0, 31, 0, 31, 0, 31)
source.SetSpacing(2 / 31, 2 / 31, 2 / 31)

mapper = vtkTransmittanceVolumeMapper()
mapper.SetInputConnection(source.GetOutputPort())
mapper.SetNumberOfCoefficients(99)
check(mapper.GetNumberOfCoefficients() == 16, "coefficients clamp to 16")
mapper.SetNumberOfCoefficients(8)
mapper.SetTransmittanceMethodToBruteForce()
check(mapper.GetTransmittanceMethodAsString() == "BruteForce", "method name")
mapper.JitterOff()
mapper.SetLightSampleCount(64)

opacity = vtkPiecewiseFunction()
opacity.AddPoint(0, 0)
opacity.AddPoint(8, 0.5)
albedo = vtkColorTransferFunction()
albedo.AddRGBPoint(0, 0.9, 0.9, 0.9)
prop = vtkVolumeProperty()
# Tyndall interpolates trilinearly; VTK's default (nearest) would be named in a warning.
prop.SetInterpolationTypeToLinear()
# A plain property keeps VTK's meaning: unlit with Shade off; lit (and
# shadowed by the maps) with Shade on.
prop.ShadeOn()
prop.SetScalarOpacity(opacity)
prop.SetColor(albedo)
prop.SetScalarOpacityUnitDistance(0.05)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

renderer = vtkRenderer()
renderer.AddVolume(volume)
renderer.SetBackground(0.2, 0.3, 0.45)
sun = vtkLight()
sun.SetLightTypeToSceneLight()
sun.SetPositional(False)
sun.SetPosition(1, 0.5, 0.3)
sun.SetFocalPoint(0, 0, 0)
renderer.AddLight(sun)
camera = renderer.GetActiveCamera()
camera.SetPosition(0, -0.6, 4.2)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewAngle(30)
renderer.ResetCameraClippingRange()
window = vtkRenderWindow()
window.SetMultiSamples(0)
window.SetOffScreenRendering(1)
window.SetSize(96, 96)
window.AddRenderer(renderer)
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ReadFrontBufferOff()
grab.Update()
gpu = grab.GetOutput().GetPointData().GetScalars()

reference = vtkSingleScatteringReference()
check(reference.Render(renderer, volume, 96, 96) is not None, "the CPU reference renders")
cpu = reference.Composite().GetPointData().GetScalars()

# PSNR without numpy.
n = gpu.GetNumberOfTuples()
squared = 0.0
for i in range(n):
    for c in range(3):
        d = gpu.GetComponent(i, c) - cpu.GetComponent(i, c)
        squared += d * d
mse = squared / (3 * n)
import math  # noqa: E402
psnr = float("inf") if mse == 0 else 10 * math.log10(255 ** 2 / mse)
print("brute force vs CPU reference: %.2f dB" % psnr)
check(psnr >= 45.0, "GPU brute force matches the CPU reference from Python (%.2f dB)" % psnr)

mapper.SetTransmittanceMethodToAdaptiveETM()
window.Render()
builds = mapper.GetMapBuildCount()
camera.Azimuth(30)
window.Render()
check(builds == 1 and mapper.GetMapBuildCount() == 1, "orbiting reuses the map")

# A clipping plane from Python: the maps are rebuilt and the picture changes.
from vtkmodules.vtkCommonDataModel import vtkPlane  # noqa: E402
plane = vtkPlane()
plane.SetOrigin(0, 0, 0)
plane.SetNormal(-1, 0, 0)
mapper.AddClippingPlane(plane)
window.Render()
check(mapper.GetMapBuildCount() == 2, "a clipping plane rebuilds the maps")
mapper.RemoveAllClippingPlanes()

# The medium's newer settings are wrapped: octaves, the emission array,
# black bodies.
from tyndall import vtkBlackbody, vtkParticipatingMediumProperty  # noqa: E402
medium = vtkParticipatingMediumProperty()
medium.SetScatteringOctaves(20)
check(medium.GetScatteringOctaves() == 8, "octaves clamp to 8")
medium.SetEmissionArrayName("temperature")
medium.BlackbodyOn()
check(medium.GetEmissionArrayName() == "temperature" and medium.GetBlackbody(),
      "emission array and black body")
rgb = [0.0, 0.0, 0.0]
vtkBlackbody.LinearSRGB(1500.0, 1500.0, rgb)
check(rgb[0] > rgb[1] > rgb[2] >= 0.0, "1500 K is orange from Python: %s" % rgb)

medium.SetExtinctionColor(0.25, 2.0, -1.0)
check(medium.GetExtinctionColor() == (0.25, 1.0, 0.0),
      "the extinction colour clamps to [0, 1]: %s" % (medium.GetExtinctionColor(),))

# A coloured extinction from Python: the CPU reference's transmittance is
# per channel, and the GPU draws it.
colored_prop = vtkParticipatingMediumProperty()
colored_prop.DeepCopy(prop)
colored_prop.SetExtinctionColor(0.3, 0.6, 1.0)
volume.SetProperty(colored_prop)
mapper.SetTransmittanceMethodToBruteForce()
window.Render()
grab.Modified()
grab.Update()
colored = grab.GetOutput().GetPointData().GetScalars()
reference.Render(renderer, volume, 96, 96)
T = reference.GetOutput().GetPointData().GetArray("Transmittance")
check(T.GetNumberOfComponents() == 3, "per-channel view transmittance")
changed = sum(abs(colored.GetComponent(i, 0) - gpu.GetComponent(i, 0)) for i in range(n))
check(changed > 0, "the coloured extinction changes the GPU picture")
volume.SetProperty(prop)

# Surfaces in the medium's shadow from Python: a ground below the cloud.
from tyndall import vtkVolumeShadowReceiverPass  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402
plane = vtkPlaneSource()
plane.SetOrigin(-3, -1.5, -3)
plane.SetPoint1(-3, -1.5, 3)
plane.SetPoint2(3, -1.5, -3)
ground_mapper = vtkPolyDataMapper()
ground_mapper.SetInputConnection(plane.GetOutputPort())
ground = vtkActor()
ground.SetMapper(ground_mapper)
renderer.AddActor(ground)
mapper.SetTransmittanceMethodToAdaptiveETM()
shadows = vtkVolumeShadowReceiverPass()
check(shadows.Install(renderer), "the shadow pass installs")
window.Render()
check(shadows.GetLastCaster() is volume, "the cloud casts its shadow on the ground")
renderer.SetPass(None)
renderer.RemoveActor(ground)

# Several volumes from Python: a second cloud beside the first shadows it,
# and the second reads the first's maps (one set for both).
check(medium.GetSceneShadows(), "scene shadows are on by default")
second_mapper = vtkTransmittanceVolumeMapper()
second_mapper.SetInputConnection(mapper.GetInputConnection(0, 0))
second = vtkVolume()
second.SetMapper(second_mapper)
scene_prop = vtkParticipatingMediumProperty()
scene_prop.DeepCopy(prop)
# (prop's Shade would add a medium's surface term, drawn as its own layer.)
scene_prop.ShadeOff()
volume.SetProperty(scene_prop)
second.SetProperty(scene_prop)
second.SetPosition(-2.2, 0, 0)
renderer.AddVolume(second)
renderer.GetCullers().GetItemAsObject(0).SetSortingStyleToBackToFront()
window.Render()
builds = mapper.GetMapBuildCount() + second_mapper.GetMapBuildCount()
scene_prop.SetSceneShadows(False)
window.Render()
check(mapper.GetMapBuildCount() + second_mapper.GetMapBuildCount() == builds + 2,
      "switching scene shadows off: each volume builds its own maps")
# The two in the same place: one medium, drawn by the first volume's mapper.
check(scene_prop.GetSceneCompositing(), "scene compositing is on by default")
scene_prop.SetSceneShadows(True)
second.SetPosition(volume.GetPosition())


def pixels():
    window.Render()
    grab.Modified()
    grab.Update()
    a = grab.GetOutput().GetPointData().GetScalars()
    return [a.GetComponent(i, c) for i in range(a.GetNumberOfTuples()) for c in range(3)]


together = pixels()
scene_prop.SetSceneCompositing(False)
layers = pixels()
scene_prop.SetSceneCompositing(True)
check(together != layers, "overlapping volumes drawn as one medium differ from layers")
renderer.RemoveVolume(second)
volume.SetProperty(prop)

# A particle cloud from Python (vtkTransmittanceParticleMapper): a ring of
# puffs around the cloud, splatted into the cloud's shadow maps; it shadows
# the cloud, and its own picture matches the CPU reference.
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
from tyndall import vtkParticipatingMediumProperty, vtkTransmittanceParticleMapper  # noqa: E402

points = vtkPoints()
radius = vtkDoubleArray()
radius.SetName("radius")
density = vtkDoubleArray()
density.SetName("density")
for i in range(60):
    a = 2 * math.pi * i / 60
    points.InsertNextPoint(1.3 * math.cos(a), 0.4 * math.sin(3 * a), 1.3 * math.sin(a))
    radius.InsertNextValue(0.2)
    density.InsertNextValue(4.0)
ring = vtkPolyData()
ring.SetPoints(points)
ring.GetPointData().AddArray(radius)
ring.GetPointData().AddArray(density)
particle_mapper = vtkTransmittanceParticleMapper()
particle_mapper.SetInputData(ring)
check(particle_mapper.GetTransmittanceMethodAsString() == "ETM", "particles default to ETM")
particle_mapper.SetGridResolution(2)
check(particle_mapper.GetGridResolution() == 8, "the particles' grid clamps to 8")
particle_mapper.SetGridResolution(64)
particle_mapper.JitterOff()
particle_prop = vtkParticipatingMediumProperty()
particle_prop.SetColor(albedo)
particle_prop.SetScatteringOctaves(1)
particles = vtkVolume()
particles.SetMapper(particle_mapper)
particles.SetProperty(particle_prop)
mapper.SetTransmittanceMethodToETM()
alone = pixels()
renderer.AddVolume(particles)
with_ring = pixels()
check(particle_mapper.GetNumberOfParticles() == 60, "60 particles read")
check(with_ring != alone, "the particle ring is drawn and shadows the cloud")
volume.VisibilityOff()
ring_gpu = pixels()
ring_cpu = vtkSingleScatteringReference()
ring_cpu.Render(renderer, particles, 96, 96)
cpu = ring_cpu.Composite().GetPointData().GetScalars()
squared = sum((ring_gpu[3 * i + c] - cpu.GetComponent(i, c)) ** 2
              for i in range(cpu.GetNumberOfTuples()) for c in range(3))
mse = squared / (3 * cpu.GetNumberOfTuples())
psnr = float("inf") if mse == 0 else 10 * math.log10(255 ** 2 / mse)
print("particle ring vs CPU reference: %.2f dB" % psnr)
check(psnr >= 39.5, "the particle ring matches the CPU reference from Python (%.2f dB)" % psnr)
volume.VisibilityOn()
renderer.RemoveVolume(particles)

if failures:
    sys.exit(1)
print("ok")
