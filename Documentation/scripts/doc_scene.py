"""What the documentation's picture scripts share: the built-in cloud and a
white cloud medium, a renderer with one sun and the tests' camera around a
volume, a window, and grabbing its picture; VTK's CT head and its view."""

import os

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkNrrdReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from tyndall import vtkCosineNoiseSource, vtkParticipatingMediumProperty


def cloud_source(n=96):
    """The built-in cloud (vtkCosineNoiseSource's defaults) at n^3 over [-1, 1]^3."""
    source = vtkCosineNoiseSource()
    source.SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1)
    source.SetSpacing(2 / (n - 1), 2 / (n - 1), 2 / (n - 1))
    source.Update()
    return source


def cloud_medium(peak_opacity, albedo, ambient):
    """A grey medium for the cloud: opacity up to `peak_opacity` per 0.05
    world units at the density 8, the albedo `albedo`, ambient `ambient`."""
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(8.0, peak_opacity)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0.0, albedo, albedo, albedo)
    color.AddRGBPoint(8.0, albedo, albedo, albedo)
    medium = vtkParticipatingMediumProperty()
    medium.SetScalarOpacity(opacity)
    medium.SetColor(color)
    medium.SetScalarOpacityUnitDistance(0.05)
    medium.SetAmbientIntensity(ambient)
    return medium


def window_around(volume, size, background, sun_from, sun_intensity):
    """A size x size window whose renderer shows `volume` lit by a sun
    travelling from `sun_from` towards the origin, seen from (0, -0.6, 4.2)."""
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(*background)
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPositional(False)
    sun.SetPosition(*sun_from)
    sun.SetFocalPoint(0, 0, 0)
    sun.SetIntensity(sun_intensity)
    renderer.AddLight(sun)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -0.6, 4.2)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewAngle(30)
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    return window, renderer


def grab(window):
    """Renders `window` and returns a copy of its picture."""
    window.Render()
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.Update()
    copy = grabber.GetOutput().NewInstance()
    copy.DeepCopy(grabber.GetOutput())
    return copy


def ct_head_reader():
    """A reader of VTK's CT head (../shared/data/volumes/headsq), updated;
    None (after saying so) when the data is absent."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    head = os.path.join(root, "..", "shared", "data", "volumes", "headsq", "quarter.nhdr")
    if not os.path.exists(head):
        print("skip: %s is absent" % head)
        return None
    reader = vtkNrrdReader()
    reader.SetFileName(head)
    reader.Update()
    return reader


def ct_head_window(volume, size):
    """A size x size off-screen window whose renderer shows `volume` (its
    mapper set) lit by one scene light from the upper left, the camera
    turned 30 degrees round and 20 up, as the CT head's pictures are."""
    renderer = vtkRenderer()
    renderer.SetBackground(0.2, 0.3, 0.4)
    renderer.AddVolume(volume)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(-1.0, 1.0, 0.6)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.AddLight(light)
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetOffScreenRendering(1)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30.0)
    camera.Elevation(20.0)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    return window, renderer
