"""Python wrapping of Tyndall: the classes import from the 'tyndall'
package, the closed form matches a fine Simpson rule, the source produces
the documented image, errors arrive through VTK's error mechanism, and the
denoiser's CPU twin filters arrays."""

import math
import sys

from vtkmodules.vtkCommonCore import reference, vtkCommand

from tyndall import vtkCosineNoise, vtkCosineNoiseSource

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAILED:", what, file=sys.stderr)


noise = vtkCosineNoise()
check(noise.GetNumberOfWaves() == 24 * 4, "24 directions x 4 octaves by default")
noise.SetNumberOfOctaves(2)
noise.SetOffset(0.0)
noise.SetOffset(-noise.GetMinimumValue())

# Closed form vs composite Simpson (fine, pure Python).
o, w, t0, t1 = (0.1, -0.3, 0.2), (0.3, 0.5, -0.8), 0.0, 1.7
norm = math.sqrt(sum(c * c for c in w))
wn = [c / norm for c in w]
n = 4000
h = (t1 - t0) / n
acc = 0.0
for i in range(n + 1):
    t = t0 + i * h
    x = [o[c] + t * wn[c] for c in range(3)]
    weight = 1 if i in (0, n) else (4 if i % 2 else 2)
    acc += weight * noise.EvaluateFunction(x)
simpson = acc * h / 3.0
closed = noise.ComputeIntegral(o, w, t0, t1)
check(abs(closed - simpson) < 1e-7 * abs(simpson), "closed form = Simpson (%r vs %r)" % (closed, simpson))
check(abs(noise.ComputeTransmittance(o, w, t0, t1) - math.exp(-closed)) < 1e-14, "T = exp(-depth)")

# The output-argument method is wrapped with a mutable reference.
tref = reference(0.0)
status = noise.SampleDistance(o, w, t0, t1, 0.5 * closed, tref)
check(status == 1, "SampleDistance reaches half the depth")
check(abs(noise.ComputeOpticalDepth(o, w, t0, float(tref)) - 0.5 * closed) < 1e-9, "depth at the sample")

# The source.
source = vtkCosineNoiseSource()
source.SetWholeExtent(0, 31, 0, 15, 0, 7)
source.SetOrigin(-0.5, -0.25, -0.125)
source.SetSpacing(1.0 / 31, 1.0 / 31, 1.0 / 31)
source.Update()
image = source.GetOutput()
check(image.GetDimensions() == (32, 16, 8), "dimensions")
scalars = image.GetPointData().GetScalars()
check(scalars.GetName() == "density" and scalars.GetDataTypeAsString() == "float", "float density")
lo, hi = scalars.GetRange()
check(lo >= 0.0 and hi > 0.0, "non-negative, non-empty density")

# Errors go through VTK's error mechanism, observable from Python.
errors = []
noise.AddObserver(vtkCommand.ErrorEvent, lambda obj, ev: errors.append(ev))
noise.SetNumberOfOctaves(0)
check(len(errors) == 1 and noise.GetNumberOfOctaves() == 1, "zero octaves reported and clamped")

# The particle kernel from Python: a chord's depth by Simpson, and the
# coefficients written into a list.
from tyndall import vtkParticleKernel  # noqa: E402

R, rho, b = 0.8, 3.0, 0.3
half = math.sqrt(R * R - b * b)
m = 2000
acc = 0.0
for i in range(m + 1):
    v = -half + 2 * half * i / m
    weight = 1 if i in (0, m) else (4 if i % 2 else 2)
    acc += weight * vtkParticleKernel.Extinction(math.sqrt(b * b + v * v), R, rho)
chord = acc * (2 * half / m) / 3.0
check(abs(chord - vtkParticleKernel.ChordDepth(b, R, rho)) < 1e-10, "a particle's chord depth")
coefficients = [0.0] * 4
check(vtkParticleKernel.AddExtinctionCoefficients(b, 2.0, 4.0, R, rho, 4, coefficients)
      and abs(coefficients[0] - 2 * chord) < 1e-9, "a particle's map coefficients from Python")

# A particle file from Python.
import os  # noqa: E402
import tempfile  # noqa: E402

from tyndall import vtkParticleFileReader  # noqa: E402

with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "particles.csv")
    with open(path, "w") as f:
        f.write("x,y,z,radius,density\n0,0,0,0.5,2\n1,2,3,0.25,1\n")
    particles = vtkParticleFileReader()
    particles.SetFileName(path)
    particles.Update()
    cloud = particles.GetOutput()
    check(cloud.GetNumberOfPoints() == 2
          and cloud.GetPointData().GetArray("radius").GetValue(1) == 0.25,
          "a particle file read from Python")

# The path-traced picture's denoiser's CPU twin, on arrays: a residual
# impulse on a uniform guide spreads as the B3 kernel (its centre keeps
# (6/16)^2 of it after one pass).
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402

from tyndall import vtkTyndallDenoiser  # noqa: E402

mean, guide, out = vtkFloatArray(), vtkFloatArray(), vtkFloatArray()
for array in (mean, guide):
    array.SetNumberOfComponents(4)
    array.SetNumberOfTuples(9 * 9)
    array.Fill(0.5)
mean.SetComponent(4 * 9 + 4, 0, 1.5)
check(vtkTyndallDenoiser.Filter(mean, guide, 9, 9, 1, 0.3, out)
      and abs(out.GetComponent(4 * 9 + 4, 0) - (0.5 + (6.0 / 16.0) ** 2)) < 1e-6
      and abs(out.GetComponent(4 * 9 + 5, 0) - (0.5 + 6.0 * 4.0 / 256.0)) < 1e-6,
      "the denoiser's twin from Python")
check(not vtkTyndallDenoiser.Filter(mean, guide, 9, 8, 1, 0.3, out),
      "the denoiser's twin refuses a wrong size")

if failures:
    sys.exit(1)
print("ok")
