"""Renders the documentation's particle picture: a plume of 6000 particles
(vtkTransmittanceParticleMapper) rising over the built-in cloud, a sun from
the upper left, both drawn with ETM maps. Left: each lit as if alone
(SceneShadows off); middle: the default, one set of maps per light for both,
the particles splatted into it, so the plume's shadow falls on the cloud
and the cloud's on the foot of the plume; right: the same with a colour per
particle (a "color" array: its albedo), rust at the foot to grey at the top.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Documentation/scripts/particles_picture.py Documentation/images
"""

import math
import random
import sys

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolume

from doc_scene import cloud_medium, cloud_source, grab, window_around

from tyndall import (vtkParticipatingMediumProperty, vtkTransmittanceParticleMapper,
                     vtkTransmittanceVolumeMapper)

SIZE = 300
random.seed(4)
points = vtkPoints()
radius = vtkDoubleArray()
radius.SetName("radius")
density = vtkDoubleArray()
density.SetName("density")
heights = []
for i in range(6000):
    t = random.random()
    heights.append(t)
    spread = 0.05 + 0.16 * t
    centre = (0.3 * math.sin(4.0 * t) - 0.15, 0.1 + 0.9 * t, 0.2 * math.cos(3.0 * t))
    points.InsertNextPoint(*(c + random.gauss(0.0, spread) for c in centre))
    radius.InsertNextValue(0.04 + 0.05 * random.random())
    density.InsertNextValue(3.0 + 4.0 * random.random())
plume = vtkPolyData()
plume.SetPoints(points)
plume.GetPointData().AddArray(radius)
plume.GetPointData().AddArray(density)

particle_mapper = vtkTransmittanceParticleMapper()
particle_mapper.SetInputData(plume)
particle_mapper.SetGridResolution(160)
particle_mapper.JitterOff()
smoke = vtkColorTransferFunction()
smoke.AddRGBPoint(0.0, 0.7, 0.7, 0.75)
particle_prop = vtkParticipatingMediumProperty()
particle_prop.SetColor(smoke)
particle_prop.SetAmbientIntensity(0.05)
particles = vtkVolume()
particles.SetMapper(particle_mapper)
particles.SetProperty(particle_prop)

cloud_mapper = vtkTransmittanceVolumeMapper()
source = cloud_source()
cloud_mapper.SetInputConnection(source.GetOutputPort())
cloud_mapper.SetTransmittanceMethodToETM()  # the maps the particles are splatted into
cloud_mapper.JitterOff()
cloud = vtkVolume()
cloud.SetMapper(cloud_mapper)
cloud.SetProperty(cloud_medium(0.6, 0.9, 0.05))
cloud.SetScale(0.75)
cloud.SetPosition(0.1, -0.55, 0)

window, renderer = window_around(cloud, SIZE, (0.32, 0.42, 0.6), (-0.7, 1.0, 0.35), 0.8)
renderer.AddVolume(particles)
renderer.GetActiveCamera().SetPosition(0, 0.2, 5.4)
renderer.GetActiveCamera().SetFocalPoint(0, 0.2, 0)
renderer.ResetCameraClippingRange()
renderer.GetCullers().GetItemAsObject(0).SetSortingStyleToBackToFront()

row = vtkImageAppend()
row.SetAppendAxis(0)  # left to right
for shared in (False, True):
    for volume in (cloud, particles):
        volume.GetProperty().SetSceneShadows(shared)
    row.AddInputData(grab(window))
# Per-particle colours: rust at the foot of the plume to grey at its top.
colors = vtkDoubleArray()
colors.SetName("color")
colors.SetNumberOfComponents(3)
for t in heights:
    colors.InsertNextTuple3(0.95 - 0.3 * t, 0.45 + 0.2 * t, 0.2 + 0.45 * t)
plume.GetPointData().AddArray(colors)
plume.Modified()
row.AddInputData(grab(window))
writer = vtkPNGWriter()
writer.SetInputConnection(row.GetOutputPort())
writer.SetFileName(sys.argv[1] + "/particles.png")
writer.Write()
