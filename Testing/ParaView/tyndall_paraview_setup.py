"""The scene of tyndall_paraview_scene.py set up in a ParaView session
(paraview.simple): shared by the pvbatch test (TestParaViewPlugin.py) and
the GUI test (TestParaViewGUI.py)."""

from paraview import simple

import tyndall_paraview_scene as scene


def prepare_view(view):
    """A plain black view lit by one directional scene light of the light
    inspector (the light kit off)."""
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.BackgroundColorMode = "Single Color"
    view.Background = list(scene.BACKGROUND)
    view.UseFXAA = 0
    view.UseToneMapping = 0
    view.UseLight = 0
    light = simple.AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.Position = list(scene.LIGHT_DIRECTION)
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.Intensity = scene.LIGHT_INTENSITY
    return view


def place_camera(view, position=scene.CAMERA_POSITION, focal_point=scene.FOCAL_POINT):
    """The scene's camera. After a first render: paraview.simple resets the
    camera of a view on its first render."""
    simple.Render(view)
    view.CameraPosition = list(position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(scene.VIEW_UP)
    view.CameraViewAngle = scene.VIEW_ANGLE
    view.CameraParallelProjection = 0


def transfer_functions(array):
    """The scene's colour map and opacity function for `array`, kept as set
    (no automatic rescaling to the data's range)."""
    lut = simple.GetColorTransferFunction(array)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.RGBPoints = [v for point in scene.COLOR for v in point]
    pwf = simple.GetOpacityTransferFunction(array)
    pwf.AllowDuplicateScalars = 1
    pwf.Points = [v for x, a in scene.OPACITY for v in (x, a, 0.5, 0.0)]
    return lut, pwf


def show_smoke(source, view, method=None):
    """`source` (smoke.vdb) shown as a Tyndall Volume with the scene's
    transfer functions and medium settings, under the scene's camera; with
    `method`, that transmittance method from the first render on."""
    display = simple.Show(source, view)
    display.SetRepresentationType("Tyndall Volume")
    simple.ColorBy(display, ("POINTS", "density"))
    transfer_functions("density")
    display.ScalarOpacityUnitDistance = scene.UNIT_DISTANCE
    display.InterpolationType = "Linear"
    display.TyndallAmbient = scene.AMBIENT
    display.TyndallAnisotropy = scene.ANISOTROPY
    if method is not None:
        display.TyndallTransmittanceMethod = method
    place_camera(view)
    return display


def show_noise_cloud(view, size, distance, method=None):
    """The plugin's Cosine Noise Cloud source (size^3 points over [-1, 1]^3,
    four octaves) shown as a Tyndall Volume, seen from `distance` along +z;
    with `method`, that transmittance method from the first render on."""
    noise = simple.CosineNoiseCloud(WholeExtent=[0, size - 1] * 3,
                                    Spacing=[2.0 / (size - 1)] * 3)
    noise.NumberOfOctaves = 4
    display = simple.Show(noise, view)
    display.SetRepresentationType("Tyndall Volume")
    simple.ColorBy(display, ("POINTS", "density"))
    _, pwf = transfer_functions("density")
    pwf.Points = [0.0, 0.0, 0.5, 0.0, 1.0, 0.5, 0.5, 0.0, 3.0, 0.9, 0.5, 0.0]
    display.TyndallDensityScale = 4.0
    if method is not None:
        display.TyndallTransmittanceMethod = method
    place_camera(view, (0.0, 0.0, distance), (0.0, 0.0, 0.0))
    return display


def screenshot(view, path):
    """The view's picture at the scene's size, written to `path`."""
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=[scene.WIDTH, scene.HEIGHT],
                          TransparentBackground=0)
