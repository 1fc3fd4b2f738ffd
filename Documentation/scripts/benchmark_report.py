"""Runs Tyndall's benchmark programs and writes Documentation/benchmarks.md
with tables and plots, from measured data only, with the machine and date.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a -s "-screen 0 1280x1024x24" \
        /usr/bin/python3 Documentation/scripts/benchmark_report.py [--build build] [--quick] \
        [--paraview-python FOLDER]

What it runs:
- build/bin/BenchCosineNoise: closed-form optical depth vs ray marching, and the
  source's throughput;
- build/bin/BenchTransmittanceMapper: frame and map-build time per method,
  ratios to None and BruteForce, and PSNR against the CPU reference, on the
  built-in cloud, a dense medium, a CT volume (../shared/data/volumes/headsq)
  and a dense smoke (../shared/data/vdb/smoke.vdb, white: preset Cloud), the
  last two when present;
  it exports the scenes for the side-by-side below;
- build/bin/tyndall-render on the cloud at several image sizes;
- build/bin/tyndall-viewer on its default scene without detail (the 128^3
  cloud, --no-detail: the scene these figures were first measured on) at 512^2:
  frames per second while a script drags the camera (interactive level of
  detail, shadows on);
- vtkTransmittanceMapMath (through the Python wrapping) for the error of each
  method against the coefficient count and the transmittance along one light ray;
- with --paraview-python FOLDER (ParaView 5.11's Python modules, unpacked as
  paraview_section() says; or TYNDALL_PARAVIEW_PYTHON), paraview_volumetric_shadows.py
  under pvbatch on the exported scenes: the same scenes through VTK 9.2's
  volumetric shadow rays, frame time and PSNR against the same reference.
  Without it the report says how to get it.

Plots are drawn with VTK's charts into Documentation/images/bench-*.png.

Never run this script in CI.
"""

import argparse
import datetime
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkChartsCore import vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
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


def run(command, timeout=3600, env=None):
    print("running:", " ".join(command), file=sys.stderr)
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            timeout=timeout, env=env)
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


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    return pixels[:, :, :3].astype(numpy.float64)


def psnr(path_a, path_b):
    """PSNR in dB of two 8-bit images over RGB, as tyndall_test::PSNR."""
    a, b = read_png(path_a), read_png(path_b)
    if a.shape != b.shape:
        return float("nan")
    mse = numpy.mean((a - b) ** 2)
    return float("inf") if mse == 0 else 10.0 * math.log10(255.0 ** 2 / mse)


def paraview_section(args, exported):
    """The exported scenes through VTK 9.2's volumetric shadow rays."""
    title = ["## Side by side: VTK 9.2's volumetric shadow rays (ParaView 5.11)", ""]
    pvbatch = shutil.which("pvbatch")
    folder = args.paraview_python
    if not pvbatch or not folder or not os.path.isdir(folder):
        return title + [
            "Not measured on this run: it needs ParaView 5.11's `pvbatch` and its Python "
            "modules. Get them without disturbing Debian's VTK 9.1 packages "
            "(`python3-paraview` conflicts with `python3-vtk9`, so it is unpacked, not "
            "installed):", "", "```",
            "apt-get install --no-install-recommends paraview",
            "apt-get download python3-paraview",
            "dpkg -x python3-paraview_*.deb <folder>",
            "benchmark_report.py --paraview-python <folder>/usr/lib/python3/dist-packages",
            "```", ""]
    script = os.path.join(ROOT, "Documentation", "scripts", "paraview_volumetric_shadows.py")
    env = dict(os.environ, PYTHONPATH=folder)
    rows, pictures, version, opengl = [], [], "9.2", "unknown (no scene rendered)"
    for scene_file in exported:
        scenes = os.path.dirname(scene_file)
        with open(scene_file) as f:
            scene = json.load(f)
        key = scene["volume"][:-len(".vti")]
        try:
            stdout, _ = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", pvbatch, script,
                             scene_file, scenes], env=env)
            result = json.loads(stdout.strip().splitlines()[-1])
        except (RuntimeError, ValueError, IndexError, subprocess.TimeoutExpired) as error:
            # One failed scene does not lose the rest of the report.
            rows.append("| %s | not measured: pvbatch failed (%s) ||||||||||" % (
                scene["name"].split(" (")[0], str(error).strip().splitlines()[-1][:200]))
            continue
        version = result["vtk_version"]
        opengl = "; ".join(line.split(":", 1)[-1].strip() for line in result["opengl"])
        reference = os.path.join(scenes, scene["reference"])
        tyndall = scene["tyndall"]
        unshadowed = result["unshadowed"]["frame"]
        shadowed = result["shadow_rays"]["frame"]
        rows.append("| %s | %.3f | %.3f (%.2fx) | %.3f (%.2fx) | %.3f | %.3f (%.2fx) | "
                    "%.2fx | %.2fx | %.1f | %.1f | %.1f |" % (
                        scene["name"].split(" (")[0], tyndall["None"]["frame"],
                        tyndall["AdaptiveETM"]["frame"],
                        tyndall["AdaptiveETM"]["frame"] / tyndall["None"]["frame"],
                        tyndall["BruteForce"]["frame"],
                        tyndall["BruteForce"]["frame"] / tyndall["None"]["frame"],
                        unshadowed, shadowed, shadowed / unshadowed,
                        tyndall["AdaptiveETM"]["frame"] / unshadowed,
                        shadowed / tyndall["AdaptiveETM"]["frame"],
                        tyndall["AdaptiveETM"]["psnr"], tyndall["BruteForce"]["psnr"],
                        psnr(result["image"], reference)))
        names = []
        for suffix, source in (("reference", reference),
                               ("adaptive-etm", os.path.join(scenes, key + "-adaptive-etm.png")),
                               ("vtk92", result["image"])):
            name = "bench-side-%s-%s.png" % (key, suffix)
            shutil.copyfile(source, os.path.join(IMAGES, name))
            names.append("![%s %s](images/%s)" % (key, suffix, name))
        pictures.append("| " + " | ".join(names) + " | %s |" % scene["name"].split(" (")[0])
    if not rows:
        return title + ["Not measured: BenchTransmittanceMapper exported no scenes.", ""]
    size = scene["size"]
    return title + [
        "The same scenes (volume, transfer functions, camera, sun, sample distance) exported by "
        "`BenchTransmittanceMapper --export` and drawn by `vtkGPUVolumeRayCastMapper` of VTK %s "
        "(ParaView 5.11's pvbatch, `Documentation/scripts/paraview_volumetric_shadows.py`) with "
        "`VolumetricScatteringBlending` 2 and `GlobalIlluminationReach` 1, its lighting matched "
        "to Tyndall's model as far as VTK 9.2's model allows (see below). Renderer: %s." % (
            version, opengl), "",
        "Frame times at %d^2 (best of %d frames; Tyndall's from the tables above: maps and "
        "transmittance cache built before the timed frames, their build times in those tables); "
        "PSNR at %d^2 against the same CPU reference." % (size, scene["frames"],
                                                         scene["reference_size"]), "",
        "| medium | Tyndall None (s) | Tyndall AdaptiveETM (s) | Tyndall BruteForce (s) | "
        "VTK 9.2 unshadowed (s) | VTK 9.2 shadow rays (s) | AdaptiveETM / VTK 9.2 unshadowed | "
        "VTK 9.2 shadows / AdaptiveETM | "
        "PSNR AdaptiveETM (dB) | PSNR BruteForce (dB) | PSNR VTK 9.2 (dB) |",
        "|---|---|---|---|---|---|---|---|---|---|---|"] + rows + [
        "", "Ratios in parentheses are to the same renderer's unshadowed frame (VTK 9.2's is its "
        "gradient-shaded frame, `VolumetricScatteringBlending` 0). "
        "Pictures at the reference size:", "",
        "| CPU reference | Tyndall AdaptiveETM | VTK 9.2 shadow rays | medium |",
        "|---|---|---|---|"] + pictures + [
        "", "How the lighting is matched, and what cannot be "
        "(`paraview_volumetric_shadows.py`, `match_lighting()`; read from VTK 9.2.6's "
        "`vtkVolumeShaderComposer.h` and `vtkOpenGLGPUVolumeRayCastMapper.cxx`):", "",
        "- Same extinction: both composite `1 - (1 - alpha)^(dt / u)` per step, and VTK's "
        "shadow rays multiply `1 - alpha` of the same opacity table.",
        "- Same source for grey media: VTK 9.2 lights a sample with `c(s) * Diffuse * "
        "Intensity * phase * shadow`, its Henyey-Greenstein phase normalised to 4 pi (1 when "
        "isotropic); `Diffuse = LightScale / 4 pi` (1 by default) gives Tyndall's "
        "`c(s) * E * p(mu) * T`. Specular is 0.",
        "- Ambient: VTK 9.2 adds `Ambient * Intensity * AmbientColor` of each light, not "
        "multiplied by the albedo `c(s)` (and a vtkLight's ambient colour is black by default). "
        "The script sets the light's ambient colour white and `Ambient` to Tyndall's ambient "
        "times the opacity-weighted mean albedo: exact for the grey cloud and dense medium, "
        "an approximation for the coloured CT preset.",
        "- Shadow rays are marched in texture coordinates with the camera ray's texture-space "
        "step and the camera's opacity correction. For volumes that are not cubes in texture "
        "space (headsq: 201.6 x 201.6 x 138 world units) the world length of a shadow step "
        "depends on its direction, so the optical depth towards the light is off by up to "
        "the aspect ratio; the phase angle is measured in texture space too (it matters only "
        "for anisotropic phase functions).",
        "- VTK 9.2 stores no transmittance (no maps, no cache): every camera sample marches to the light "
        "(brute force, at the camera's step), so its cost grows with the light ray's length "
        "in samples, as Tyndall's BruteForce does.", ""]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true", help="small sizes, for trying the script")
    parser.add_argument("--paraview-python", default=os.environ.get("TYNDALL_PARAVIEW_PYTHON"),
                        help="dist-packages folder of an unpacked python3-paraview, for the "
                        "side-by-side with VTK 9.2 (see paraview_section())")
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

    # 2. The mapper on the cloud, a dense medium, a CT volume (raw headsq
    # numbers shifted to Hounsfield units) and a dense smoke (smoke.vdb); the
    # scenes are exported for the ParaView comparison below.
    scenes = os.path.join(args.build, "bench-scenes")
    shutil.rmtree(scenes, ignore_errors=True)
    os.makedirs(scenes)
    data = os.path.join(ROOT, "..", "shared", "data")
    volumes, missing = [], []
    for path, options in ((os.path.join(data, "volumes", "headsq", "quarter.nhdr"),
                           ["--shift", "-1024", "--preset", "CT"]),
                          (os.path.join(data, "vdb", "smoke.vdb"),
                           ["--preset", "Cloud", "--y-up"])):
        if os.path.exists(path):
            volumes += ["--volume", path] + options
        else:
            missing.append(path)
    stdout, _ = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                     os.path.join(bin_dir, "BenchTransmittanceMapper"), "--export", scenes] +
                    volumes + quick)
    settings = [line for line in stdout.splitlines()
                if line.startswith("OpenGL") or line.startswith("image ")]
    out += ["## The mapper: frame time, map build and PSNR per method", ""] + \
        ["- " + line for line in settings] + [""]
    out += ["Not measured (absent): %s" % path for path in missing]
    out += [""] if missing else []
    exported = [line.split(":", 1)[1].strip() for line in stdout.splitlines()
                if line.startswith("exported:")]
    body = stdout.split("## ", 1)[-1]
    # The program's sections become subsections of this one.
    body = "\n".join("#" + line if line.startswith("## ") else line
                     for line in ("## " + body).splitlines()
                     if not line.startswith("exported:"))
    out += [body.strip(), ""]

    # 3. Frame time against image size (cloud), None vs AdaptiveETM vs BruteForce.
    sizes = [128, 256] if args.quick else [128, 256, 384, 512]
    timing = {}
    for method in ("none", "adaptive-etm", "brute-force"):
        timing[method] = []
        for size in sizes:
            _, stderr = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                             os.path.join(bin_dir, "tyndall-render"), "--no-detail", "--size",
                             str(size), str(size), "--method", method, "--frames", "3", "-o",
                             os.path.join(args.build, "bench-size.png")])
            match = re.search(r"([0-9.e+-]+) s per frame", stderr)
            timing[method].append(float(match.group(1)) if match else float("nan"))
    out += ["## Frame time against image size (built-in cloud, 128^3, --no-detail, cached maps)",
            "",
            "| size | " + " | ".join(timing) + " |",
            "|---|" + "---|" * len(timing)]
    for i, size in enumerate(sizes):
        out.append("| %d^2 | " % size + " | ".join("%.3f s" % timing[m][i] for m in timing) + " |")
    out += ["", plot("bench-frame-vs-size.png", "Frame time vs image size", "image width (px)",
                     "seconds per frame", sizes, [(m, timing[m]) for m in timing]), ""]

    # 4. Dragging the camera in the viewer (the default scene's 128^3 cloud without detail),
    # shadows on: VTK's interactive/still protocol and the mapper's level of
    # detail.
    script = os.path.join(args.build, "bench-drag.txt")
    with open(script, "w") as f:
        f.write("frames 2\n" + "drag left 6 0\n" * 20 + "frames 1\n")
    stdout, _ = run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                     os.path.join(bin_dir, "tyndall-viewer"), "--no-detail", "--size", "512", "512",
                     "--script", script, "--events", "quit"])
    drag = re.search(r"summary drag-frames (\d+) mean-ms ([0-9.]+) fps ([0-9.]+)", stdout)
    frames = [line.split() for line in stdout.splitlines() if line.startswith("frame ")]
    still = [float(w[3]) for w in frames if w[-2:] == ["frames", "1"]]
    reductions = sorted({w[w.index("reduction") + 1] for w in frames
                         if "reduction" in w and w[-4] == "drag"})
    out += ["## Dragging the camera in tyndall-viewer (built-in cloud, 128^3, --no-detail, "
            "512^2, AdaptiveETM)", ""]
    if drag:
        out += ["| frames per second while dragging (asked: 10) | mean drag frame | image "
                "reduction | still frame after the drag |", "|---|---|---|---|",
                "| %s | %s ms | 1/%s | %s |" % (
                    drag.group(3), drag.group(2), ", 1/".join(reductions),
                    "%.0f ms" % still[-1] if still else "?"), "",
                "20 scripted drags (`drag left 6 0`), the viewer's default `--interactive-rate 10`"
                ": each drag frame is rendered with the render window's desired update rate at "
                "10 per second and the mapper reduces its image to meet it, shadows on; the "
                "frame after the drag is full size.", ""]
    else:
        out += ["Not measured: the viewer printed no drag summary.", ""]

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

    # 6. VTK 9.2's volumetric shadows through ParaView 5.11's pvbatch.
    out += paraview_section(args, exported)

    with open(os.path.join(ROOT, "Documentation", "benchmarks.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    print(os.path.join(ROOT, "Documentation", "benchmarks.md"))


main()
