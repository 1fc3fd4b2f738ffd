"""Renders the documentation's clipping picture: the built-in cloud clipped in
half by a plane and lit from the clipped side, drawn by
vtkTransmittanceVolumeMapper (the light respects the clipping), by the CPU
reference (the same) and by the CPU reference with LightIgnoresClipping (what
a renderer whose shadow rays ignore clipping draws: the half that remains sits
in the removed half's shadow).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/clipping_pictures.py Documentation/images
"""

import sys

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkVolume

from doc_scene import cloud_medium, cloud_source, grab, window_around

from tyndall import vtkSingleScatteringReference, vtkTransmittanceVolumeMapper

SIZE = 256

source = cloud_source()
medium = cloud_medium(0.6, 0.9, 0.05)

plane = vtkPlane()  # keeps x <= 0.05: the half away from the sun
plane.SetOrigin(0.05, 0, 0)
plane.SetNormal(-1, 0, 0)
mapper = vtkTransmittanceVolumeMapper()
mapper.SetInputConnection(source.GetOutputPort())
mapper.JitterOff()
mapper.AddClippingPlane(plane)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(medium)

# The sun comes from +x: across the clipped half.
window, renderer = window_around(volume, SIZE, (0.2, 0.3, 0.45), (1.0, 0.25, 0.15), 0.8)

row = vtkImageAppend()
row.SetAppendAxis(0)
row.AddInputData(grab(window))
for ignores in (False, True):
    reference = vtkSingleScatteringReference()
    reference.SetLightIgnoresClipping(ignores)
    reference.Render(renderer, volume, SIZE, SIZE)
    picture = reference.Composite()
    copy = picture.NewInstance()
    copy.DeepCopy(picture)
    row.AddInputData(copy)
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/clipping.png")
writer.Write()
