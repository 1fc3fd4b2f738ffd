"""Renders the benchmark's scenes with VTK 9.2's volumetric shadow rays, the
renderer users would otherwise pick, for the side-by-side in
Documentation/benchmarks.md. Runs under ParaView 5.11's pvbatch (which bundles
VTK 9.2), never under Tyndall's VTK 9.1 and never in CI:

    PYTHONPATH=<folder>/usr/lib/python3/dist-packages \\
        xvfb-run -a -s "-screen 0 1280x1024x24" \\
        pvbatch Documentation/scripts/paraview_volumetric_shadows.py SCENE.json OUTDIR

Getting pvbatch without disturbing Debian's VTK 9.1 packages (python3-paraview
conflicts with python3-vtk9, so it is unpacked, not installed):

    apt-get install --no-install-recommends paraview
    apt-get download python3-paraview
    dpkg -x python3-paraview_*.deb <folder>

SCENE.json comes from `BenchTransmittanceMapper --export DIR` (camera, light,
transfer functions, sample distance, image sizes); the volume is the .vti
beside it. The scene is drawn by vtkGPUVolumeRayCastMapper with
VolumetricScatteringBlending 2 (volumetric shading only) and
GlobalIlluminationReach 1 (shadow rays cross the whole volume), with the
lighting matched to Tyndall's single-scattering model as far as VTK 9.2's
model allows (see Documentation/benchmarks.md for what differs).

Writes OUTDIR/<key>-vtk92.png (the reference size, for PSNR against the CPU
reference) and prints one JSON object: frame times at the benchmark size for
the unshadowed frame (VolumetricScatteringBlending 0, gradient shading) and
the shadowed one, the first-frame times, and the VTK version.
"""

import json
import math
import os
import sys

from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkCommonSystem import vtkTimerLog
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def transfer_functions(scene):
    """The scene's scalar opacity and colour transfer functions."""
    opacity = vtkPiecewiseFunction()
    for x, y, midpoint, sharpness in scene["opacity"]:
        opacity.AddPoint(x, y, midpoint, sharpness)
    color = vtkColorTransferFunction()
    for x, r, g, b, midpoint, sharpness in scene["color"]:
        color.AddRGBPoint(x, r, g, b, midpoint, sharpness)
    return opacity, color


def make_scene(scene, folder, size):
    reader = vtkXMLImageDataReader()
    path = os.path.join(folder, scene["volume"])
    if not reader.CanReadFile(path):
        sys.exit("paraview_volumetric_shadows.py: cannot read the volume %s" % path)
    reader.SetFileName(path)
    reader.Update()
    if reader.GetOutput().GetNumberOfPoints() == 0:
        sys.exit("paraview_volumetric_shadows.py: the volume %s is empty" % path)

    opacity, color = transfer_functions(scene)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(scene["scalar_opacity_unit_distance"])
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()

    mapper = vtkOpenGLGPUVolumeRayCastMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(scene["sample_distance"])
    mapper.SetUseJittering(False)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(*scene["background"])
    renderer.SetAutomaticLightCreation(False)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(scene["light"]["positional"])
    light.SetPosition(*scene["light"]["position"])
    light.SetFocalPoint(*scene["light"]["focal_point"])
    light.SetColor(*scene["light"]["color"])
    light.SetIntensity(scene["light"]["intensity"])
    match_lighting(scene, prop, light)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*scene["camera"]["position"])
    camera.SetFocalPoint(*scene["camera"]["focal_point"])
    camera.SetViewUp(*scene["camera"]["view_up"])
    camera.SetViewAngle(scene["camera"]["view_angle"])
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(size, size)
    return window, mapper


def mean_albedo(scene):
    """The opacity-weighted mean of the colour transfer function (grey)."""
    opacity, color = transfer_functions(scene)
    lo, hi = scene["opacity"][0][0], scene["opacity"][-1][0]
    total = weight = 0.0
    for i in range(1024):
        x = lo + (hi - lo) * i / 1023.0
        w = opacity.GetValue(x)
        total += w * sum(color.GetColor(x)) / 3.0
        weight += w
    return total / weight if weight > 0 else 1.0


def match_lighting(scene, prop, light):
    """VTK 9.2's volumetric model (vtkVolumeShaderComposer.h, ShadingSingleInput,
    VolumetricScatteringBlending 2 = volumetric term only) gives a sample

        S = sum_l shadow_l * phase4pi(mu) * c(s) * Diffuse * Intensity_l * DiffuseColor_l
            + Ambient * Intensity_l * AmbientColor_l

    with phase4pi the Henyey-Greenstein phase normalised to 4 pi (1 when
    isotropic) and shadow_l the product of (1 - opacity) along a shadow ray.
    Tyndall's is S = c(s) * (LightScale * Intensity * Color * p(mu) * T + A)
    with p normalised to 1: so Diffuse = LightScale / (4 pi), Specular 0, and
    the ambient term, which VTK 9.2 does not multiply by the albedo c(s),
    gets A times the medium's mean albedo (exact for a grey medium of one
    albedo, approximate for coloured ones such as the CT preset)."""
    prop.SetDiffuse(scene["light_scale"] / (4.0 * math.pi))
    prop.SetSpecular(0.0)
    prop.SetScatteringAnisotropy(scene["anisotropy"])
    # VTK 9.2 scales a light's ambient colour by its intensity.
    intensity = scene["light"]["intensity"]
    prop.SetAmbient(scene["ambient"] * mean_albedo(scene) / intensity if intensity > 0 else 0.0)
    light.SetAmbientColor(1.0, 1.0, 1.0)


def time_frame(window):
    timer = vtkTimerLog()
    timer.StartTimer()
    window.Render()
    window.WaitForCompletion()
    timer.StopTimer()
    return timer.GetElapsedTime()


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: pvbatch paraview_volumetric_shadows.py SCENE.json OUTDIR")
    scene_file, out_dir = sys.argv[1], sys.argv[2]
    try:
        with open(scene_file) as f:
            scene = json.load(f)
    except (OSError, ValueError) as error:
        sys.exit("paraview_volumetric_shadows.py: cannot read the scene %s: %s"
                 % (scene_file, error))
    folder = os.path.dirname(os.path.abspath(scene_file))
    key = scene["volume"][:-len(".vti")]
    result = {"vtk_version": vtkVersion.GetVTKVersion(), "key": key}

    # The image for PSNR, at the reference size.
    window, mapper = make_scene(scene, folder, scene["reference_size"])
    mapper.SetVolumetricScatteringBlending(2.0)
    mapper.SetGlobalIlluminationReach(1.0)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    result["image"] = os.path.join(out_dir, key + "-vtk92.png")
    writer.SetFileName(result["image"])
    writer.Write()
    if writer.GetErrorCode() != 0:
        sys.exit("paraview_volumetric_shadows.py: cannot write %s" % result["image"])
    renderer_string = window.ReportCapabilities().splitlines()
    result["opengl"] = [line for line in renderer_string if line.startswith("OpenGL renderer")]
    del window

    # Frame times at the benchmark size: unshadowed, then with shadow rays.
    window, mapper = make_scene(scene, folder, scene["size"])
    for label, blending, reach in (("unshadowed", 0.0, 0.0), ("shadow_rays", 2.0, 1.0)):
        mapper.SetVolumetricScatteringBlending(blending)
        mapper.SetGlobalIlluminationReach(reach)
        first = time_frame(window)
        best = min(time_frame(window) for _ in range(max(1, scene["frames"])))
        result[label] = {"first_frame": first, "frame": best}
    print(json.dumps(result))


main()
