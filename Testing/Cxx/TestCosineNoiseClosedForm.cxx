// Closed-form optical depth of vtkCosineNoise against adaptive numerical
// quadrature on thousands of random rays (near-perpendicular ones included),
// the exact gradient against finite differences, the paper's definition,
// determinism under a seed, and what the closed form does with negative
// noise values.
#include "vtkCosineNoise.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include "TyndallTestCheck.h"
#include "TyndallTestQuadrature.h"

#include <cmath>
#include <iostream>
#include <random>

namespace
{
using tyndall_test::Check;

void RandomUnit(std::mt19937& rng, double w[3])
{
  std::normal_distribution<double> n(0.0, 1.0);
  do
  {
    w[0] = n(rng);
    w[1] = n(rng);
    w[2] = n(rng);
  } while (vtkMath::Normalize(w) < 1e-6);
}

// Integral of noise (or of |noise| when absolute) along o + t w by quadrature.
double Quadrature(vtkCosineNoise* noise, const double o[3], const double w[3], double t0, double t1,
  double tolerance, bool absolute = false)
{
  auto f = [&](double t)
  {
    double x[3] = { o[0] + t * w[0], o[1] + t * w[1], o[2] + t * w[2] };
    const double v = noise->EvaluateFunction(x);
    return absolute ? std::abs(v) : v;
  };
  return tyndall_test::AdaptiveIntegrate(f, t0, t1, tolerance);
}

// Relative error of the closed form over nRays random rays; every fourth ray
// is perpendicular to one wave up to a tiny tilt (1e-2 .. 1e-15, or exactly).
double MaxRelativeError(vtkCosineNoise* noise, int nRays, std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> wave(0, noise->GetNumberOfWaves() - 1);
  const double tilts[] = { 1e-2, 1e-5, 1e-8, 1e-11, 1e-15, 0.0 };
  double worst = 0.0;
  for (int r = 0; r < nRays; ++r)
  {
    double o[3] = { u(rng), u(rng), u(rng) };
    double w[3];
    RandomUnit(rng, w);
    if (r % 4 == 0)
    {
      double k[3], phase, amplitude;
      noise->GetWave(wave(rng), k, phase, amplitude);
      vtkMath::Normalize(k);
      // Remove w's component along k, then tilt by a tiny angle.
      const double along = vtkMath::Dot(w, k);
      for (int c = 0; c < 3; ++c)
      {
        w[c] -= along * k[c];
      }
      vtkMath::Normalize(w);
      const double tilt = tilts[(r / 4) % 6];
      for (int c = 0; c < 3; ++c)
      {
        w[c] += tilt * k[c];
      }
    }
    const double t0 = 0.5 * u(rng);
    const double t1 = t0 + 0.01 + 1.5 * (u(rng) + 1.0);
    double wn[3] = { w[0], w[1], w[2] };
    vtkMath::Normalize(wn);
    const double scaleOfIntegrand = Quadrature(noise, o, wn, t0, t1, 1e-6, true);
    const double reference = Quadrature(noise, o, wn, t0, t1, 1e-14 * scaleOfIntegrand);
    const double closed = noise->ComputeIntegral(o, w, t0, t1);
    if (!std::isfinite(closed))
    {
      std::cerr << "non-finite closed form on ray " << r << std::endl;
      return 1.0;
    }
    worst = std::max(worst, std::abs(closed - reference) / scaleOfIntegrand);
  }
  return worst;
}
}

int TestCosineNoiseClosedForm(int, char*[])
{
  std::mt19937 rng(12345);

  // 1. Closed form vs quadrature, non-negative noise (relative to the
  // integral itself, which is then the integral of |noise|).
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(3);
    noise->SetFrequency(0.8);
    noise->SetOffset(0.0);
    noise->SetOffset(-noise->GetMinimumValue()); // exactly non-negative
    Check(std::abs(noise->GetMinimumValue()) < 1e-12, "offset makes the minimum zero");
    const double err = MaxRelativeError(noise, 2000, rng);
    std::cout << "non-negative noise: max relative error " << err << " over 2000 rays\n";
    Check(err < 1e-9, "closed form matches quadrature (non-negative noise) to 1e-9");
  }

  // 1b. GetStandardDeviation() is the noise's spread over space: against
  // the sample standard deviation at 20 000 random points (1 % sampling
  // error; the bound sum |a| would be 5x off).
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetFrequency(3.0);
    noise->SetOffset(0.7);
    std::uniform_real_distribution<double> u(-4.0, 4.0);
    double sum = 0.0, squares = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i)
    {
      double p[3] = { u(rng), u(rng), u(rng) };
      const double v = noise->EvaluateFunction(p);
      sum += v;
      squares += v * v;
    }
    const double mean = sum / n;
    const double sampled = std::sqrt(squares / n - mean * mean);
    const double exact = noise->GetStandardDeviation();
    std::cout << "standard deviation: " << exact << ", sampled " << sampled << ", mean " << mean
              << "\n";
    Check(std::abs(sampled / exact - 1.0) < 0.03 && std::abs(mean - 0.7) < 0.1 * exact,
      "GetStandardDeviation() matches the sampled spread, the offset the mean");
  }

  // 2. Signed noise (offset 0): error relative to the integral of |noise|.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(2);
    noise->SetFrequency(1.3);
    noise->SetSeed(7);
    const double err = MaxRelativeError(noise, 1000, rng);
    std::cout << "signed noise: max relative error " << err << " over 1000 rays\n";
    Check(err < 1e-9, "closed form matches quadrature (signed noise) to 1e-9");
  }

  // 3. Exactly perpendicular rays: the limit, never NaN or Inf.
  {
    vtkNew<vtkDoubleArray> dirs;
    dirs->SetNumberOfComponents(3);
    dirs->InsertNextTuple3(0.0, 0.0, 1.0);
    dirs->InsertNextTuple3(0.0, 1.0, 0.0);
    vtkNew<vtkCosineNoise> noise;
    noise->SetCustomDirections(dirs);
    noise->SetNumberOfOctaves(1);
    noise->SetOffset(2.0);
    noise->RandomPhasesOff();
    const double o[3] = { 0.3, 0.2, 0.1 };
    const double w[3] = { 5.0, 0.0, 0.0 }; // not normalised on purpose
    const double k = 2.0 * vtkMath::Pi();
    const double expected = 1.5 * (2.0 + std::cos(k * 0.1) + std::cos(k * 0.2));
    const double got = noise->ComputeIntegral(o, w, 0.25, 1.75);
    Check(std::isfinite(got) && std::abs(got - expected) < 1e-14 * std::abs(expected),
      "perpendicular ray integral is the exact limit");
    Check(noise->ComputeIntegral(o, w, 1.0, 1.0) == 0.0, "empty segment integrates to 0");
    Check(std::abs(noise->ComputeIntegral(o, w, 1.75, 0.25) + got) < 1e-14,
      "reversed bounds negate the integral");
  }

  // 4. The paper's definition: one octave, no phases, 2 pi f = 1.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(1);
    noise->RandomPhasesOff();
    noise->SetFrequency(1.0 / (2.0 * vtkMath::Pi()));
    noise->SetOffset(0.25);
    Check(noise->GetNumberOfWaves() == 24, "24 directions by default");
    double origin[3] = { 0.0, 0.0, 0.0 };
    Check(std::abs(noise->EvaluateFunction(origin) - 24.25) < 1e-12, "phi(0) = offset + N");
    double x[3] = { 0.7, -1.1, 2.3 };
    double sum = 0.25;
    bool scalesOk = true;
    for (int i = 0; i < 24; ++i)
    {
      double S[3], phase, amplitude;
      noise->GetWave(i, S, phase, amplitude);
      const double len = vtkMath::Norm(S);
      scalesOk = scalesOk && len >= 0.8 && len <= 1.2 && phase == 0.0 && amplitude == 1.0;
      sum += std::cos(vtkMath::Dot(x, S));
    }
    Check(scalesOk, "|S_i| in [0.8, 1.2], zero phases, unit amplitudes");
    Check(std::abs(noise->EvaluateFunction(x) - sum) < 1e-12, "phi(x) = offset + sum cos(x.S_i)");
    // Sobol point 0 is (0, 0): direction +z.
    double S0[3], p, a;
    noise->GetWave(0, S0, p, a);
    Check(std::abs(S0[0]) < 1e-12 && std::abs(S0[1]) < 1e-12 && S0[2] > 0.0,
      "first Sobol direction is +z");
  }

  // 5. Gradient vs central finite differences.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double worst = 0.0;
    for (int r = 0; r < 500; ++r)
    {
      double x[3] = { u(rng), u(rng), u(rng) };
      double g[3];
      noise->EvaluateGradient(x, g);
      const double h = 1e-6;
      for (int c = 0; c < 3; ++c)
      {
        double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
        xp[c] += h;
        xm[c] -= h;
        const double fd = (noise->EvaluateFunction(xp) - noise->EvaluateFunction(xm)) / (2.0 * h);
        worst = std::max(worst, std::abs(fd - g[c]) / std::max(1.0, vtkMath::Norm(g)));
      }
    }
    std::cout << "gradient: max relative finite-difference error " << worst << "\n";
    Check(worst < 1e-6, "gradient matches finite differences");
  }

  // 6. Determinism: the same seed gives the same waves, another seed others.
  {
    vtkNew<vtkCosineNoise> a, b, c;
    c->SetSeed(2);
    double x[3] = { 0.1, 0.2, 0.3 };
    Check(a->EvaluateFunction(x) == b->EvaluateFunction(x), "same seed, same value");
    Check(a->EvaluateFunction(x) != c->EvaluateFunction(x), "other seed, other value");
    const double before = a->EvaluateFunction(x);
    a->SetSeed(2);
    Check(a->EvaluateFunction(x) == c->EvaluateFunction(x), "changing the seed rebuilds the waves");
    a->SetSeed(1);
    Check(a->EvaluateFunction(x) == before, "restoring the seed restores the noise");
  }

  // 7. Optical depth and transmittance; negative noise values.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(2);
    noise->SetOffset(0.5); // strongly signed noise
    noise->SetExtinctionScale(3.0);
    Check(noise->GetMinimumValue() < 0.0, "this noise has negative values");
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int clampedRays = 0;
    bool ok = true;
    for (int r = 0; r < 300; ++r)
    {
      double o[3] = { u(rng), u(rng), u(rng) };
      double w[3];
      RandomUnit(rng, w);
      const double t1 = 0.05 + u(rng) + 1.0;
      const double signedIntegral = Quadrature(noise, o, w, 0.0, t1, 1e-12);
      const double depth = noise->ComputeOpticalDepth(o, w, 0.0, t1);
      const double expected = 3.0 * std::max(0.0, signedIntegral);
      ok = ok && std::abs(depth - expected) < 1e-8 * std::max(1.0, expected);
      ok = ok && std::abs(noise->ComputeTransmittance(o, w, 0.0, t1) - std::exp(-depth)) < 1e-15;
      ok = ok && depth >= 0.0;
      // The clamped extinction that a ray marcher sees integrates to more.
      auto clampedNoise = [&](double t)
      {
        double x[3] = { o[0] + t * w[0], o[1] + t * w[1], o[2] + t * w[2] };
        return std::max(0.0, noise->EvaluateFunction(x));
      };
      const double clampedDepth =
        3.0 * tyndall_test::AdaptiveIntegrate(clampedNoise, 0.0, t1, 1e-10);
      ok = ok && depth <= clampedDepth + 1e-8;
      clampedRays += signedIntegral < 0.0 ? 1 : 0;
    }
    Check(ok, "depth = scale * max(0, signed integral) <= depth of the clamped extinction");
    std::cout << "negative noise: " << clampedRays << " of 300 rays had a negative integral\n";
    Check(clampedRays > 0, "the negative-integral case was exercised");
  }

  // 8. Parameters change the wave table.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfDirections(10);
    noise->SetNumberOfOctaves(3);
    Check(noise->GetNumberOfWaves() == 30, "waves = directions x octaves");
    double k0[3], k10[3], p, a0, a10;
    noise->GetWave(0, k0, p, a0);
    noise->GetWave(10, k10, p, a10);
    Check(std::abs(vtkMath::Norm(k10) / vtkMath::Norm(k0) - 2.0) < 1e-12,
      "lacunarity scales the second octave's wave number");
    Check(std::abs(a10 / a0 - 0.5) < 1e-15, "gain scales the second octave's amplitude");
  }

  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
