"""The scene that Tyndall's ParaView tests render twice: in pvbatch through
the plugin (TestParaViewPlugin.py) and through a plain VTK pipeline with the
system VTK (TestParaViewVTKPipeline.py). Both compare with one baseline,
Testing/Data/Baseline/TyndallParaViewSmoke.png, so the plugin's picture
equals the VTK pipeline's within the baseline threshold.

Plain numbers only: this module imports neither VTK (two different VTKs
read it).
"""

import math
import os

SMOKE = os.path.join(os.environ.get("TYNDALL_SHARED_DATA", ""), "vdb", "smoke.vdb")
BASELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "Baseline",
                        "TyndallParaViewSmoke.png")
# The floor of every picture comparison, as the command-line tests' (dB).
PSNR_FLOOR = 45.0

WIDTH, HEIGHT = 200, 280
BACKGROUND = (0.0, 0.0, 0.0)
# smoke.vdb's bounds are about x [-33.6, 18.8], y [-12.1, 93.1], z [-26.0, 26.9].
FOCAL_POINT = (-7.4, 40.5, 0.5)
CAMERA_POSITION = (70.0, 75.0, 250.0)
VIEW_UP = (0.0, 1.0, 0.0)
VIEW_ANGLE = 30.0
# One directional scene light, from this direction (towards the light).
LIGHT_DIRECTION = (0.6, 1.0, 0.2)
LIGHT_INTENSITY = 1.0

# The transfer functions of Testing/CLI/Data/smoke.tf (density 0 .. 5.7).
OPACITY = [(0.0, 0.0), (0.05, 0.0), (2.0, 0.35), (6.0, 0.8)]
COLOR = [(0.0, 0.85, 0.85, 0.88), (6.0, 0.70, 0.70, 0.72)]
UNIT_DISTANCE = 0.5
AMBIENT = 0.1
ANISOTROPY = 0.3


def psnr(a, b):
    """PSNR in dB of two equally shaped sequences of 8-bit values."""
    if len(a) != len(b) or not a:
        return -math.inf
    mse = sum((float(x) - float(y)) ** 2 for x, y in zip(a, b)) / len(a)
    return math.inf if mse == 0 else 10.0 * math.log10(255.0 ** 2 / mse)
