"""Renders the documentation's fire picture: the built-in cloud as the smoke
(extinction) and a "temperature" array (Kelvin) as black-body emission per
unit length (vtkParticipatingMediumProperty.SetEmissionArrayName,
BlackbodyOn), beside the same smoke without emission.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/fire_picture.py Documentation/images
"""

import math
import sys

from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume

from doc_scene import grab, window_around

from tyndall import (vtkCosineNoiseSource, vtkParticipatingMediumProperty,
                     vtkTransmittanceVolumeMapper)

SIZE = 256
source = vtkCosineNoiseSource()
source.SetWholeExtent(0, 95, 0, 95, 0, 95)
source.SetSpacing(2 / 95, 2 / 95, 2 / 95)
source.Update()
image = source.GetOutput()
temperature = vtkFloatArray()
temperature.SetName("temperature")
temperature.SetNumberOfTuples(image.GetNumberOfPoints())
for i in range(image.GetNumberOfPoints()):
    x, y, z = image.GetPoint(i)
    r2 = x * x + (y + 0.35) ** 2 + z * z
    temperature.SetValue(i, 400.0 + 1900.0 * math.exp(-r2 / (2 * 0.3 ** 2)))
image.GetPointData().AddArray(temperature)

opacity = vtkPiecewiseFunction()
opacity.AddPoint(0.0, 0.0)
opacity.AddPoint(8.0, 0.5)
albedo = vtkColorTransferFunction()
albedo.AddRGBPoint(0.0, 0.5, 0.5, 0.5)
albedo.AddRGBPoint(8.0, 0.5, 0.5, 0.5)
medium = vtkParticipatingMediumProperty()
medium.SetScalarOpacity(opacity)
medium.SetColor(albedo)
medium.SetScalarOpacityUnitDistance(0.05)
medium.SetAmbientIntensity(0.05)
medium.SetEmissionArrayName("temperature")
medium.BlackbodyOn()

mapper = vtkTransmittanceVolumeMapper()
mapper.SetInputData(image)
mapper.JitterOff()
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(medium)
window, renderer = window_around(volume, SIZE, (0.02, 0.02, 0.04), (1.0, 0.5, 0.3), 0.4)

row = vtkImageAppend()
row.SetAppendAxis(0)
for scale in (0.0, 3.0):
    medium.SetEmissionScale(scale)
    row.AddInputData(grab(window))
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/fire.png")
writer.Write()
