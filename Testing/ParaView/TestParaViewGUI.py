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
    import tyndall_paraview_setup as setup

    if not os.path.exists(scene.SMOKE):
        return "skipped"
    simple.LoadPlugin(plugin, remote=False)
    reader = simple.TyndallVolumeReader(FileName=scene.SMOKE)
    view = setup.prepare_view(simple.GetActiveViewOrCreate("RenderView"))
    setup.show_smoke(reader, view)
    path = os.path.join(output, "gui-smoke.png")
    setup.screenshot(view, path)
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
