"""Checks BenchTransmittanceMapper's --export output, which
Documentation/scripts/paraview_volumetric_shadows.py and benchmark_report.py
read: one scene per medium (volume, CPU reference, Tyndall's images, scene
JSON), figures consistent with the images, data volumes shifted, keyed and
framed as asked, and clear failures for bad arguments. Timings are not
checked. Needs an X display (run ctest under xvfb-run).

    TestBenchmarkExport.py BENCH_EXECUTABLE WORK_DIR
"""

import json
import math
import os
import shutil
import subprocess
import sys

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLImageDataWriter

FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print("FAIL:", message)


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    return pixels[:, :, :3].astype(numpy.float64)


def psnr(a, b):
    mse = numpy.mean((a - b) ** 2)
    return float("inf") if mse == 0 else 10.0 * math.log10(255.0 ** 2 / mse)


def read_vti(path):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def write_blob(path):
    """A Gaussian blob on an anisotropic 20 x 24 x 16 grid (spacing 1, 1, 2)."""
    dims = (20, 24, 16)
    z, y, x = numpy.meshgrid(numpy.arange(dims[2]) * 2.0, numpy.arange(dims[1]) * 1.0,
                             numpy.arange(dims[0]) * 1.0, indexing="ij")
    r2 = (x - 9.5) ** 2 + (y - 11.5) ** 2 + (z - 15.0) ** 2
    values = (100.0 * numpy.exp(-r2 / 40.0)).astype(numpy.float32).ravel()
    image = vtkImageData()
    image.SetDimensions(*dims)
    image.SetSpacing(1.0, 1.0, 2.0)
    array = numpy_to_vtk(values, deep=True)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()
    return dims, (float(values.min()), float(values.max()))


def main():
    bench, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    export = os.path.join(work, "scenes")
    os.makedirs(export)
    blob = os.path.join(work, "blob.vti")
    dims, blob_range = write_blob(blob)

    # Tiny sizes; the transmittance cache's lattice too (its default 256^3 texels
    # would be most of the run's time at these sizes).
    small = ["--size", "48", "--resolution", "24", "--map-size", "32", "--frames", "1",
             "--reference-size", "32", "--light-samples", "32", "--cache-size", "32"]
    result = subprocess.run(
        [bench] + small + ["--export", export, "--volume", blob, "--preset", "Cloud", "--y-up",
                           "--volume", blob, "--shift", "5", "--preset", "MR"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
    check(result.returncode == 0, "benchmark exit code %d: %s" % (result.returncode,
                                                                  result.stderr[-1000:]))
    exported = [line.split(":", 1)[1].strip() for line in result.stdout.splitlines()
                if line.startswith("exported:")]
    keys = [os.path.basename(path)[:-len("-scene.json")] for path in exported]
    check(keys == ["cloud", "dense", "sparse", "blob", "blob-2"], "exported scenes %s" % keys)

    for path in exported:
        with open(path) as f:
            scene = json.load(f)
        key = os.path.basename(path)[:-len("-scene.json")]
        check(scene["volume"] == key + ".vti", "%s: volume file %s" % (key, scene["volume"]))
        check(scene["size"] == 48 and scene["reference_size"] == 32 and scene["frames"] == 1,
              "%s: sizes %s %s %s" % (key, scene["size"], scene["reference_size"],
                                      scene["frames"]))
        volume = read_vti(os.path.join(export, scene["volume"]))
        spacing = volume.GetSpacing()
        check(abs(scene["sample_distance"] - 0.5 * min(spacing)) < 1e-12,
              "%s: sample distance %g for spacing %s" % (key, scene["sample_distance"], spacing))
        check(len(scene["opacity"]) >= 2 and all(len(node) == 4 for node in scene["opacity"]),
              "%s: opacity nodes %s" % (key, scene["opacity"]))
        check(len(scene["color"]) >= 2 and all(len(node) == 6 for node in scene["color"]),
              "%s: colour nodes %s" % (key, scene["color"]))
        check(scene["scalar_opacity_unit_distance"] > 0, "%s: unit distance" % key)
        check(abs(scene["light_scale"] - 4.0 * math.pi) < 1e-9, "%s: light scale" % key)
        check(scene["ambient"] == 0.1 and scene["light"]["positional"] is False,
              "%s: ambient / light %s %s" % (key, scene["ambient"], scene["light"]))
        camera = scene["camera"]
        check(all(math.isfinite(v) for v in camera["position"] + camera["focal_point"]),
              "%s: camera %s" % (key, camera))

        reference = read_png(os.path.join(export, scene["reference"]))
        check(reference.shape == (32, 32, 3), "%s: reference shape %s" % (key, reference.shape))
        for method, suffix in (("AdaptiveETM", "adaptive-etm"), ("BruteForce", "brute-force")):
            image = read_png(os.path.join(export, "%s-%s.png" % (key, suffix)))
            measured = psnr(image, reference)
            recorded = scene["tyndall"][method]["psnr"]
            check(abs(measured - recorded) < 1e-6,
                  "%s: %s PSNR recorded %g, images give %g" % (key, method, recorded, measured))
        # The reference shows the medium: not the bare background everywhere.
        background = numpy.round(numpy.array(scene["background"]) * 255.0)
        check(numpy.abs(reference - background).max() > 20, "%s: the reference is empty" % key)
        check(set(scene["tyndall"]) == {"None", "BruteForce", "TFM", "AdaptiveTFM", "ETM",
                                        "AdaptiveETM"}, "%s: methods %s" % (key, scene["tyndall"]))

        if key.startswith("blob"):
            check(volume.GetDimensions() == dims, "%s: dimensions %s" % (key, volume.GetDimensions()))
            low, high = volume.GetScalarRange()
            shift = 5.0 if key == "blob-2" else 0.0
            check(abs(low - blob_range[0] - shift) < 1e-3 and
                  abs(high - blob_range[1] - shift) < 1e-3,
                  "%s: scalar range %s (shift %g)" % (key, (low, high), shift))
            # --y-up: seen from +z with y up; otherwise from -y with z up.
            up = [0, 1, 0] if key == "blob" else [0, 0, 1]
            check(numpy.allclose(camera["view_up"], up, atol=1e-9),
                  "%s: view-up %s, expected %s" % (key, camera["view_up"], up))

    # Bad arguments: a per-volume option without --volume, a missing file.
    bad = subprocess.run([bench, "--shift", "3"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, timeout=60)
    check(bad.returncode == 2 and "usage" in bad.stderr,
          "--shift without --volume: exit %d, %r" % (bad.returncode, bad.stderr))
    missing = subprocess.run([bench] + small + ["--volume", os.path.join(work, "absent.vti")],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             timeout=60)
    check(missing.returncode == 1 and "absent.vti" in missing.stderr,
          "missing volume: exit %d, %r" % (missing.returncode, missing.stderr))

    if FAILURES:
        print("%d failure(s)" % len(FAILURES))
        return 1
    print("benchmark export: %d scenes checked" % len(exported))
    return 0


sys.exit(main())
