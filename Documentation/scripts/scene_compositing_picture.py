"""Renders the documentation's overlapping-volumes picture: two copies of the
built-in cloud through the same space, the second turned a quarter turn,
red and moved a little, under a low sun from the left. Left: drawn as layers
(SceneCompositing off: VTK composites one whole volume over the other);
right: drawn as one medium (the default: the first volume's mapper casts the
camera rays through both).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/scene_compositing_picture.py Documentation/images
"""

import sys

from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume

from doc_scene import cloud_medium, cloud_source, grab, window_around

from tyndall import vtkTransmittanceVolumeMapper

SIZE = 300
source = cloud_source()
volumes = []
for turn in (0.0, 90.0):
    mapper = vtkTransmittanceVolumeMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.JitterOff()
    volume = vtkVolume()
    volume.SetMapper(mapper)
    medium = cloud_medium(0.9, 0.9, 0.05)
    medium.SetDensityScale(0.5)
    volume.SetProperty(medium)
    volume.SetScale(0.8)
    volume.SetOrientation(0, turn, 0)
    volumes.append(volume)
red = vtkColorTransferFunction()
red.AddRGBPoint(0.0, 0.95, 0.45, 0.3)
red.AddRGBPoint(8.0, 0.95, 0.45, 0.3)
volumes[1].GetProperty().SetColor(red)
volumes[1].SetPosition(0.05, 0.05, 0)
window, renderer = window_around(volumes[0], SIZE, (0.32, 0.42, 0.6), (-1.0, 0.3, 0.2), 1.0)
renderer.AddVolume(volumes[1])
renderer.GetActiveCamera().SetPosition(0, -0.3, 2.8)
renderer.ResetCameraClippingRange()
renderer.GetCullers().GetItemAsObject(0).SetSortingStyleToBackToFront()

row = vtkImageAppend()
row.SetAppendAxis(0)  # left to right
for together in (False, True):
    for volume in volumes:
        volume.GetProperty().SetSceneCompositing(together)
    row.AddInputData(grab(window))
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/scene-compositing.png")
writer.Write()
