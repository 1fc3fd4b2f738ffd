"""What the documentation's picture scripts share: a renderer with one sun
and the tests' camera around a volume, a window, and grabbing its picture."""

from vtkmodules.vtkRenderingCore import (vtkLight, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)


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
