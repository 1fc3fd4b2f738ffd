"""Tyndall's ParaView plugin over time, in pvbatch: a series of OpenVDB
files (a blob moving along x, written by the CLI tests' data fixture) opened
as one Tyndall Volume Reader is a source with one time step per file; shown
as "Tyndall Volume" and stepped through by the animation scene, the picture
at each time step must be the one of that file opened alone (45 dB), the
steps must differ from each other, and going back to the first step must
give its picture again (nothing kept from a later step).

Arguments: the plugin (Tyndall.so), the folder of the series
(seq/blob_0000.vdb ...) and an output folder.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from paraview import simple  # noqa: E402

import tyndall_paraview_images as images  # noqa: E402
import tyndall_paraview_scene as scene  # noqa: E402
import tyndall_paraview_setup as setup  # noqa: E402

plugin, series, output = sys.argv[1], sys.argv[2], sys.argv[3]
files = [os.path.join(series, "blob_%04d.vdb" % i) for i in range(3)]
if not all(os.path.exists(f) for f in files):
    print("FAIL: the series is missing (the CLI tests' make-data writes it): %s" % files)
    sys.exit(1)
os.makedirs(output, exist_ok=True)
failures = []
FLOOR = 45.0
# The blob's box is [0, 23] x [0, 19] x [0, 15]: seen from +z, lit from above.
FOCAL_POINT = (11.5, 9.5, 7.5)
CAMERA_POSITION = (11.5, 25.0, 75.0)


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        failures.append(message)


def show(source):
    """`source` as a Tyndall Volume in a view of its own, the transfer
    functions fixed over the blob's values [0, 100]."""
    view = setup.prepare_view(simple.CreateView("RenderView"))
    view.ViewSize = [scene.WIDTH, scene.HEIGHT]
    display = simple.Show(source, view)
    display.SetRepresentationType("Tyndall Volume")
    simple.ColorBy(display, ("POINTS", "density"))
    lut, pwf = setup.transfer_functions("density")
    lut.RGBPoints = [0.0, 0.9, 0.8, 0.7, 100.0, 1.0, 1.0, 1.0]
    pwf.Points = [0.0, 0.0, 0.5, 0.0, 100.0, 0.9, 0.5, 0.0]
    display.ScalarOpacityUnitDistance = 1.0
    setup.place_camera(view, CAMERA_POSITION, FOCAL_POINT)
    return view


def picture(view, name):
    path = os.path.join(output, name)
    setup.screenshot(view, path)
    return images.rgb(path)[0]


simple.LoadPlugin(plugin, remote=False)
reader = simple.TyndallVolumeReader(FileName=files)
steps = list(reader.TimestepValues)
check(len(steps) == len(files), "one time step per file: %s" % steps)
view = show(reader)
animation = simple.GetAnimationScene()
animation.UpdateAnimationUsingDataTimeSteps()
played = []
for i, t in enumerate(steps):
    animation.AnimationTime = t
    check(view.ViewTime == t, "the view is at time %s (%s)" % (t, view.ViewTime))
    played.append(picture(view, "time-step-%d.png" % i))
animation.AnimationTime = steps[0] if steps else 0.0
again = picture(view, "time-step-0-again.png")

for i, f in enumerate(files):
    alone = picture(show(simple.TyndallVolumeReader(FileName=[f])), "file-%d.png" % i)
    if i < len(played):
        value = scene.psnr(played[i], alone)
        check(value >= FLOOR, "time step %d against %s alone: %.1f dB (floor %.0f)"
              % (i, os.path.basename(f), value, FLOOR))
for i in range(1, len(played)):
    value = scene.psnr(played[i], played[i - 1])
    check(value < 30.0, "time step %d differs from step %d: %.1f dB (below 30)" % (i, i - 1, value))
if played:
    value = scene.psnr(again, played[0])
    check(value >= FLOOR, "back at the first step, its picture again: %.1f dB" % value)

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("PASS")
