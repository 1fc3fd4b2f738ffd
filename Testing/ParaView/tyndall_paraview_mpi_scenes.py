"""Renders the MPI test's two scenes (TestParaViewMPI.py) in pvbatch, in one
process or under mpirun: the smoke of tyndall_paraview_scene.py and a
cosine-noise cloud, each a Tyndall Volume with plain ETM (the method whose
maps add exactly over the ranks), lit by one directional scene light.

    pvbatch [--mpi] tyndall_paraview_mpi_scenes.py PLUGIN OUTPUT_PREFIX

Writes OUTPUT_PREFIX-smoke.png and OUTPUT_PREFIX-cloud.png and prints, per
scene, "reduction SCENE SECONDS FLOATS": the last map reduction on rank 0
(0 0 in one process).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from paraview import simple  # noqa: E402

import tyndall_paraview_scene as scene  # noqa: E402
import tyndall_paraview_setup as setup  # noqa: E402

ETM = 4


def make_view():
    view = simple.CreateView("RenderView")
    view.ViewSize = [scene.WIDTH, scene.HEIGHT]
    return setup.prepare_view(view)


def report(name, display):
    display.UpdatePropertyInformation()
    seconds = display.GetPropertyValue("TyndallMapReductionTime")
    floats = display.GetPropertyValue("TyndallMapReductionSize")
    print("reduction %s %.6f %d" % (name, seconds, int(floats)), flush=True)


def smoke(prefix):
    reader = simple.TyndallVolumeReader(FileName=scene.SMOKE)
    view = make_view()
    display = setup.show_smoke(reader, view, ETM)
    setup.screenshot(view, prefix + "-smoke.png")
    report("smoke", display)


def cloud(prefix):
    view = make_view()
    display = setup.show_noise_cloud(view, 64, 4.0, ETM)
    setup.screenshot(view, prefix + "-cloud.png")
    report("cloud", display)


simple.LoadPlugin(sys.argv[1], remote=False)
smoke(sys.argv[2])
simple.ResetSession()
cloud(sys.argv[2])
