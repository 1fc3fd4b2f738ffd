"""Renders the documentation's coloured-extinction picture: the built-in
cloud with vtkParticipatingMediumProperty.SetExtinctionColor 1 1 1 (grey),
0.25 0.6 1 (blue the densest channel: blue edges, red depths, the sky seen
through it reddened) and 1 0.5 0.15 (red the densest), side by side.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/chromatic_picture.py Documentation/images
"""

import sys

from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkVolume

from doc_scene import cloud_medium, cloud_source, grab, window_around

from tyndall import vtkTransmittanceVolumeMapper

SIZE = 256
source = cloud_source()
medium = cloud_medium(0.6, 0.9, 0.1)

mapper = vtkTransmittanceVolumeMapper()
mapper.SetInputConnection(source.GetOutputPort())
mapper.JitterOff()
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(medium)
window, renderer = window_around(volume, SIZE, (0.45, 0.6, 0.85), (1.0, 0.6, 0.4), 0.8)

row = vtkImageAppend()
row.SetAppendAxis(0)
for color in ((1, 1, 1), (0.25, 0.6, 1), (1, 0.5, 0.15)):
    medium.SetExtinctionColor(*color)
    row.AddInputData(grab(window))
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/chromatic.png")
writer.Write()
