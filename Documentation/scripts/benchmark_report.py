"""Runs Tyndall's benchmark programs and writes Documentation/benchmarks.md
with tables and plots, from measured data only, with the machine and date.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24" \
        /usr/bin/python3 Documentation/scripts/benchmark_report.py [--build build] [--quick]

What it runs:
- build/bin/BenchCosineNoise: closed-form optical depth vs ray marching, and the
  source's throughput;
- build/bin/BenchTransmittanceMapper: frame and map-build time per method and PSNR
  against the CPU reference, on the built-in cloud and a dense medium;
- build/bin/tyndall-render on a CT volume (../shared/data/volumes/headsq, when
  present) for every method, and on the cloud at several image sizes;
- vtkTransmittanceMapMath (through the Python wrapping) for the error of each
  method against the coefficient count and the transmittance along one light ray.

Plots are drawn with VTK's charts into Documentation/images/bench-*.png.

The side-by-side with VTK 9.2's volumetric shadows (ParaView 5.11's pvbatch)
is not implemented yet; the report says so. Never run this script in CI.
"""

import argparse
import datetime
import math
import os
import platform
import re
import subprocess
import sys

from vtkmodules.vtkChartsCore import vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from tyndall import vtkCosineNoise, vtkTransmittanceMapMath

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
IMAGES = os.path.join(ROOT, "Documentation", "images")
METHODS = ["none", "brute-force", "tfm", "adaptive-tfm", "etm", "adaptive-etm"]
MAP_METHODS = [(2, "TFM"), (3, "AdaptiveTFM"), (4, "ETM"), (5, "AdaptiveETM")]
COLORS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189)]


def load_average():
    try:
        return " ".join(open("/proc/loadavg").read().split()[:3])
    except OSError:
        return "unknown"


def run(command, timeout=3600):
    print("running:", " ".join(command), file=sys.stderr)
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            timeout=timeout)
    if result.returncode != 0:
        raise RuntimeError("%s failed:\n%s" % (command[0], result.stderr[-2000:]))
    return result.stdout, result.stderr


def plot(name, title, xlabel, ylabel, x, series, logy=False):
    """A line chart of series [(label, ys)] over x, written to images/name."""
    table = vtkTable()
    xs = vtkFloatArray()
    xs.SetName(xlabel)
    table.AddColumn(xs)
    for label, _ in series:
        column = vtkFloatArray()
        column.SetName(label)
        table.AddColumn(column)
    table.SetNumberOfRows(len(x))
    for i, value in enumerate(x):
        table.SetValue(i, 0, value)
        for j, (_, ys) in enumerate(series):
            y = ys[i]
            table.SetValue(i, j + 1, math.log10(max(y, 1e-12)) if logy else y)
    view = vtkContextView()
    view.GetRenderWindow().SetSize(640, 400)
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderer().SetBackground(1, 1, 1)
    chart = vtkChartXY()
    chart.SetTitle(title)
    chart.SetShowLegend(True)
    chart.GetAxis(1).SetTitle(xlabel)
    chart.GetAxis(0).SetTitle(("log10 " if logy else "") + ylabel)
    view.GetScene().AddItem(chart)
    for j in range(len(series)):
        line = chart.AddPlot(vtkChart.LINE)
        line.SetInputData(table, 0, j + 1)
        line.SetColor(*COLORS[j % len(COLORS)], 255)
        line.SetWidth(2.0)
    view.GetRenderWindow().Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(os.path.join(IMAGES, name))
    writer.Write()
    return "![%s](images/%s)" % (title, name)


def profiles():
    """1-D extinction profiles: a dense step and a ray through the built-in cloud."""
    n = 1025
    dense = [30.0 / 0.3 / 2.0 if 0.3 <= i / (n - 1) <= 0.6 else 0.0 for i in range(n)]
    noise = vtkCosineNoise()
    noise.SetNumberOfOctaves(6)
    noise.SetGain(0.55)
    noise.SetOffset(1.5)
    cloud = []
    for i in range(n):
        s = i / (n - 1)
        x = (-1.0 + 2.0 * s, 0.1, 0.05)
        envelope = max(0.0, 1.0 - (x[0] / 0.95) ** 2 - (x[1] / 0.6) ** 2 - (x[2] / 0.7) ** 2)
        cloud.append(max(0.0, noise.EvaluateFunction(x)) * min(1.0, 2.0 * envelope) * 0.3)
    return {"dense step": dense, "cloud ray": cloud}


def rms_error(method, profile, count, length=2.0, samples=256):
    coefficients = [0.0] * count
    bounds = [0.0, 0.0, 0.0]
    vtkTransmittanceMapMath.Project(method, profile, len(profile), length, samples, count, 0.01,
                                    coefficients, bounds)
    total = 0.0
    points = 1001
    for i in range(points):
        s = i / (points - 1)
        exact = vtkTransmittanceMapMath.ExactTransmittance(profile, len(profile), length, s)
        approx = vtkTransmittanceMapMath.Reconstruct(method, coefficients, count, bounds, s)
        total += (approx - exact) ** 2
    return math.sqrt(total / points)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true", help="small sizes, for trying the script")
    args = parser.parse_args()
    bin_dir = os.path.join(args.build, "bin")
    quick = ["--quick"] if args.quick else []
    os.makedirs(IMAGES, exist_ok=True)

    out = ["# Benchmarks", "",
           "Generated by `Documentation/scripts/benchmark_report.py` from measured data only.", "",
           "- Date: %s" % datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
           "- Machine: %s, %d CPU threads, %s" % (platform.machine(), os.cpu_count(),
                                                 platform.platform()),
           "- Load average at start: %s (other work on the machine makes the timings noisy; "
           "compare figures within one table, not across runs)" % load_average(),
           ""]

    # 1. Cosine noise.
    stdout, _ = run([os.path.join(bin_dir, "BenchCosineNoise")] + quick)
    out += ["## Cosine noise: closed form vs ray marching", "", "```", stdout.strip(), "```", ""]

    # 2. The mapper on the cloud and a dense medium.
    stdout, _ = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                     os.path.join(bin_dir, "BenchTransmittanceMapper")] + quick)
    renderer = [line for line in stdout.splitlines() if line.startswith("OpenGL")]
    out += ["## The mapper: frame time, map build and PSNR per method", ""] + \
        ["- " + line for line in renderer] + [""]
    body = stdout.split("## ", 1)[-1]
    out += ["## " + body.strip(), ""]

    # 3. Frame time against image size (cloud), None vs AdaptiveETM vs BruteForce.
    sizes = [128, 256] if args.quick else [128, 256, 384, 512]
    timing = {}
    for method in ("none", "adaptive-etm", "brute-force"):
        timing[method] = []
        for size in sizes:
            _, stderr = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                             os.path.join(bin_dir, "tyndall-render"), "--size", str(size),
                             str(size), "--method", method, "--frames", "3", "-o",
                             os.path.join(args.build, "bench-size.png")])
            match = re.search(r"([0-9.e+-]+) s per frame", stderr)
            timing[method].append(float(match.group(1)) if match else float("nan"))
    out += ["## Frame time against image size (built-in cloud, 128^3, cached maps)", "",
            "| size | " + " | ".join(timing) + " |",
            "|---|" + "---|" * len(timing)]
    for i, size in enumerate(sizes):
        out.append("| %d^2 | " % size + " | ".join("%.3f s" % timing[m][i] for m in timing) + " |")
    out += ["", plot("bench-frame-vs-size.png", "Frame time vs image size", "image width (px)",
                     "seconds per frame", sizes, [(m, timing[m]) for m in timing]), ""]

    # 4. A CT volume, every method.
    ct = os.path.join(ROOT, "..", "shared", "data", "volumes", "headsq", "quarter.nhdr")
    if os.path.exists(ct):
        out += ["## A CT volume (headsq quarter, 64 x 64 x 93, preset CT), 512^2", "",
                "| method | first frame (s) | map build (s) | cached frame (s) |",
                "|---|---|---|---|"]
        size = "256" if args.quick else "512"
        for method in METHODS:
            _, stderr = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                             os.path.join(bin_dir, "tyndall-render"), ct, "--size", size, size,
                             "--method", method, "--frames", "3", "-o",
                             os.path.join(args.build, "bench-ct.png")])
            first = re.search(r"first frame: ([0-9.e+-]+) s", stderr)
            maps = re.search(r"transmittance maps: ([0-9.e+-]+) s", stderr)
            cached = re.search(r"([0-9.e+-]+) s per frame", stderr)
            out.append("| %s | %s | %s | %s |" % (method, first.group(1) if first else "-",
                                                  maps.group(1) if maps else "-",
                                                  cached.group(1) if cached else "-"))
        out += ["", "PSNR against the CPU reference is not measured for the CT volume.", ""]
    else:
        out += ["## A CT volume", "", "Not measured: %s is absent." % ct, ""]

    # 5. Error against the coefficient count, and transmittance along one ray.
    shapes = profiles()
    counts = list(range(1, 17))
    for name, profile in shapes.items():
        series = [(label, [rms_error(method, profile, m) for m in counts])
                  for method, label in MAP_METHODS]
        out += ["## RMS error of the reconstructed transmittance vs coefficients: %s" % name, "",
                plot("bench-error-%s.png" % name.replace(" ", "-"),
                     "RMS transmittance error, %s" % name, "coefficients", "RMS error", counts,
                     series, logy=True), ""]
    profile = shapes["dense step"]
    s_values = [i / 200 for i in range(201)]
    curves = [("exact", [vtkTransmittanceMapMath.ExactTransmittance(profile, len(profile), 2.0, s)
                         for s in s_values])]
    for method, label in MAP_METHODS:
        coefficients, bounds = [0.0] * 8, [0.0, 0.0, 0.0]
        vtkTransmittanceMapMath.Project(method, profile, len(profile), 2.0, 256, 8, 0.01,
                                        coefficients, bounds)
        curves.append((label, [vtkTransmittanceMapMath.Reconstruct(method, coefficients, 8,
                                                                    bounds, s)
                               for s in s_values]))
    out += ["## Transmittance along one light ray (dense step, 8 coefficients)", "",
            plot("bench-transmittance-ray.png", "Transmittance along a light ray",
                 "s (position along the ray)", "T", s_values, curves), ""]

    # 6. VTK 9.2's volumetric shadows: not implemented (needs ParaView's pvbatch).
    out += ["## VTK 9.2's volumetric shadows (ParaView 5.11)", "",
            "Not measured: running the same scene through ParaView 5.11's pvbatch "
            "(vtkGPUVolumeRayCastMapper, VolumetricScatteringBlending 2, "
            "GlobalIlluminationReach 1) is not implemented in this script yet. For scale, the "
            "project's brief measured VTK 9.2's shadow rays at 6x the cost of its unshadowed "
            "frame on smoke.vdb, 256 x 256.", ""]

    with open(os.path.join(ROOT, "Documentation", "benchmarks.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    print(os.path.join(ROOT, "Documentation", "benchmarks.md"))


main()
