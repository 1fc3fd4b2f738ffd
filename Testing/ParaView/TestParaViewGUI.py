"""Tyndall's plugin in ParaView's GUI (run by `paraview --script=THIS --exit`
under Xvfb): loads the plugin into the GUI's session, shows smoke.vdb as a
Tyndall Volume in the GUI's own render view with the scene of
tyndall_paraview_scene.py, and compares the view's picture with the
baseline that pvbatch and the plain VTK pipeline are held to.

The GUI's exit code does not say whether a script failed, so the verdict is
written to the file named by TYNDALL_PARAVIEW_GUI_RESULT ("passed" or
"failed: ..."), which the test reads. Skips without smoke.vdb (writes
"skipped").
"""

import os
import sys
import traceback

# The GUI runs this file without __file__: the wrapper names the folder.
sys.path.insert(0, os.environ["TYNDALL_PARAVIEW_TEST_DIR"])

result_file = os.environ["TYNDALL_PARAVIEW_GUI_RESULT"]
plugin = os.environ["TYNDALL_PARAVIEW_PLUGIN"]
output = os.path.dirname(result_file)


def verdict(text):
    with open(result_file, "w") as f:
        f.write(text + "\n")
    print("TestParaViewGUI: " + text)


def run():
    from paraview import simple

    import tyndall_paraview_images as images
    import tyndall_paraview_scene as scene

    if not os.path.exists(scene.SMOKE):
        return "skipped"
    simple.LoadPlugin(plugin, remote=False)
    reader = simple.TyndallVolumeReader(FileName=scene.SMOKE)
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.BackgroundColorMode = "Single Color"
    view.Background = list(scene.BACKGROUND)
    view.UseLight = 0
    light = simple.AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.Position = list(scene.LIGHT_DIRECTION)
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.Intensity = scene.LIGHT_INTENSITY
    display = simple.Show(reader, view)
    display.SetRepresentationType("Tyndall Volume")
    simple.ColorBy(display, ("POINTS", "density"))
    lut = simple.GetColorTransferFunction("density")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.RGBPoints = [v for point in scene.COLOR for v in point]
    pwf = simple.GetOpacityTransferFunction("density")
    pwf.Points = [v for x, a in scene.OPACITY for v in (x, a, 0.5, 0.0)]
    display.ScalarOpacityUnitDistance = scene.UNIT_DISTANCE
    display.InterpolationType = "Linear"
    display.TyndallAmbient = scene.AMBIENT
    display.TyndallAnisotropy = scene.ANISOTROPY
    simple.Render(view)
    view.CameraPosition = list(scene.CAMERA_POSITION)
    view.CameraFocalPoint = list(scene.FOCAL_POINT)
    view.CameraViewUp = list(scene.VIEW_UP)
    view.CameraViewAngle = scene.VIEW_ANGLE
    path = os.path.join(output, "gui-smoke.png")
    simple.SaveScreenshot(path, view, ImageResolution=[scene.WIDTH, scene.HEIGHT],
                          TransparentBackground=0)
    picture, size = images.rgb(path)
    baseline, baseline_size = images.rgb(scene.BASELINE)
    if size != baseline_size:
        return "failed: picture %s, baseline %s" % (size, baseline_size)
    value = scene.psnr(picture, baseline)
    if value < scene.PSNR_FLOOR:
        return "failed: %.1f dB against the baseline (floor %.0f)" % (value, scene.PSNR_FLOOR)
    return "passed: %.1f dB against the baseline" % value


try:
    verdict(run())
except Exception:  # noqa: BLE001 -- any failure is the test's verdict
    verdict("failed: " + traceback.format_exc().replace("\n", " | "))
