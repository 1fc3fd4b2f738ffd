"""Renders the documentation's several-volumes picture: two clouds side by
side under a low sun from the left, so the left cloud's shadow falls into the
right one. Top to bottom: each volume lit alone (SceneShadows off, Tyndall
before the scene maps), the scene's shared maps (AdaptiveETM, the default),
and the CPU reference (vtkSingleScatteringReference, each cloud rendered lit
through the other and composited; their pictures do not overlap).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/scene_shadows_picture.py Documentation/images
"""

import sys

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkVolume

from doc_scene import cloud_medium, cloud_source, grab, window_around

from tyndall import vtkSingleScatteringReference, vtkTransmittanceVolumeMapper

W, H = 440, 220
source = cloud_source()
volumes = []
for x, opacity in ((-1.0, 0.9), (1.0, 0.5)):
    mapper = vtkTransmittanceVolumeMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.JitterOff()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(cloud_medium(opacity, 0.9, 0.05))
    volume.SetScale(0.8)
    volume.SetPosition(x, 0, 0)
    volumes.append(volume)
window, renderer = window_around(volumes[0], H, (0.32, 0.42, 0.6), (-1.0, 0.3, 0.2), 1.0)
renderer.AddVolume(volumes[1])
window.SetSize(W, H)
renderer.GetActiveCamera().SetViewAngle(24)
renderer.GetActiveCamera().SetPosition(0, -0.5, 4.6)
renderer.ResetCameraClippingRange()
renderer.GetCullers().GetItemAsObject(0).SetSortingStyleToBackToFront()


def reference():
    """The CPU reference's picture of the two clouds."""
    outputs = []
    for volume in volumes:
        cpu = vtkSingleScatteringReference()
        cpu.Render(renderer, volume, W, H)
        out = vtkImageData()
        out.DeepCopy(cpu.GetOutput())
        outputs.append(out)
    la, ta = (outputs[0].GetPointData().GetArray(n) for n in ("Radiance", "Transmittance"))
    lb, tb = (outputs[1].GetPointData().GetArray(n) for n in ("Radiance", "Transmittance"))
    rgb = vtkUnsignedCharArray()
    rgb.SetNumberOfComponents(3)
    rgb.SetNumberOfTuples(W * H)
    background = renderer.GetBackground()
    for i in range(W * H):
        t = ta.GetValue(i) * tb.GetValue(i)
        for c in range(3):
            value = la.GetComponent(i, c) + ta.GetValue(i) * lb.GetComponent(i, c)
            value = min(1.0, max(0.0, value + t * background[c]))
            rgb.SetComponent(i, c, int(value * 255.0 + 0.5))
    picture = vtkImageData()
    picture.SetDimensions(W, H, 1)
    picture.GetPointData().SetScalars(rgb)
    return picture


row = vtkImageAppend()
row.SetAppendAxis(1)  # the first input at the bottom
row.AddInputData(reference())
for shadows in (True, False):
    for volume in volumes:
        volume.GetProperty().SetSceneShadows(shadows)
    row.AddInputData(grab(window))
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/scene-shadows.png")
writer.Write()
