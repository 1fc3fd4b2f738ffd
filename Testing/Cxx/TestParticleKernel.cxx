// vtkParticleKernel, the smooth-sphere particle, against numerical
// integration (adaptive Gauss-Kronrod, TyndallTestQuadrature.h) and against
// vtkTransmittanceMapMath's ETM projection of the same extinction:
// 1. the mass (the radial integral) and the chord's optical depth;
// 2. the optical depth of random segments of random rays (misses, partial
//    chords, segments beyond the particle);
// 3. the extinction map coefficients of one particle on random light rays
//    (the closed form across its series / closed-form switch), and their sum
//    over several particles against the ETM march of the summed extinction;
// 4. bad input: zeros, false, never NaN.
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParticleKernel.h"
#include "vtkTransmittanceMapMath.h"

#include "TyndallTestCheck.h"
#include "TyndallTestQuadrature.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
using tyndall_test::Check;
using K = vtkParticleKernel;

// Adaptive Gauss-Kronrod to 1e-14 of `scale`, the size of the integral (a
// tolerance that rounding lets it reach).
double Integrate(const std::function<double(double)>& f, double a, double b, double scale)
{
  return tyndall_test::AdaptiveIntegrate(f, a, b, 1e-14 * std::max(scale, 1e-300));
}

// The particle's extinction at distance t along the ray o + t d.
double AlongRay(
  const double o[3], const double d[3], double t, const double c[3], double radius, double density)
{
  const double x[3] = { o[0] + t * d[0] - c[0], o[1] + t * d[1] - c[1], o[2] + t * d[2] - c[2] };
  return K::Extinction(vtkMath::Norm(x), radius, density);
}

void MassAndChord()
{
  double worst = 0.0;
  for (double radius : { 0.01, 0.3, 1.0, 7.5 })
  {
    const double density = 2.5;
    const double radial = Integrate([&](double r)
      { return 4.0 * vtkMath::Pi() * r * r * K::Extinction(r, radius, density); },
      0.0, radius, density * radius * radius * radius);
    worst = std::max(worst, std::abs(radial - K::Mass(radius, density)) / radial);
    for (double f : { 0.0, 0.2, 0.7, 0.999 })
    {
      const double b = f * radius, h = std::sqrt(radius * radius - b * b);
      const double chord = Integrate([&](double v)
        { return K::Extinction(std::sqrt(b * b + v * v), radius, density); },
        -h, h, density * h);
      worst = std::max(worst, std::abs(chord - K::ChordDepth(b, radius, density)) / chord);
      const double part = Integrate([&](double v)
        { return K::Extinction(std::sqrt(b * b + v * v), radius, density); },
        -h, 0.3 * h, density * h);
      worst =
        std::max(worst, std::abs(part - K::PartialDepth(b, 0.3 * h, radius, density)) / chord);
    }
  }
  std::cout << "mass and chords against quadrature: largest relative difference " << worst << "\n";
  Check(worst < 1e-12, "mass, chord and partial chord depths are exact");
  Check(K::ChordDepth(1.0, 1.0, 1.0) == 0.0 && K::ChordDepth(2.0, 1.0, 1.0) == 0.0,
    "a ray that misses or grazes the particle sees nothing");
}

void Segments(vtkMinimalStandardRandomSequence* random)
{
  double worst = 0.0;
  int hits = 0;
  for (int i = 0; i < 2000; ++i)
  {
    // Rays from a random origin towards a random point near the particle.
    double o[3], d[3], c[3];
    for (int a = 0; a < 3; ++a)
    {
      o[a] = random->GetNextRangeValue(-3.0, 3.0);
      c[a] = random->GetNextRangeValue(-1.0, 1.0);
      d[a] = c[a] + random->GetNextRangeValue(-1.0, 1.0) - o[a];
    }
    if (vtkMath::Normalize(d) < 1e-3)
    {
      continue;
    }
    const double radius = random->GetNextRangeValue(0.05, 1.5);
    const double density = random->GetNextRangeValue(0.0, 10.0);
    double t0 = random->GetNextRangeValue(0.0, 6.0), t1 = random->GetNextRangeValue(0.0, 6.0);
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    const double exact = K::SegmentDepth(o, d, t0, t1, c, radius, density);
    // The quadrature over the chord's part in [t0, t1] (the integrand is a
    // polynomial there; outside it is 0, a kink Gauss-Kronrod would not see).
    const double e[3] = { c[0] - o[0], c[1] - o[1], c[2] - o[2] };
    const double tc = vtkMath::Dot(e, d);
    const double b2 = std::max(0.0, vtkMath::Dot(e, e) - tc * tc);
    double numeric = 0.0;
    if (b2 < radius * radius)
    {
      const double h = std::sqrt(radius * radius - b2);
      const double a = std::max(t0, tc - h), z = std::min(t1, tc + h);
      if (a < z)
      {
        numeric = Integrate(
          [&](double t) { return AlongRay(o, d, t, c, radius, density); }, a, z, density * radius);
        ++hits;
      }
    }
    worst = std::max(worst, std::abs(exact - numeric) / std::max(1.0, density * radius));
  }
  std::cout << "2000 random segments (" << hits << " cross a particle): largest difference "
            << worst << " (relative to rho R)\n";
  Check(worst < 1e-12 && hits > 500, "segment depths are exact");
}

// c_j = 2 integral of sigma(t) cos(j pi t / D) over [0, D], by quadrature.
double NumericCoefficient(int j, double b, double tc, double length, double radius, double density)
{
  const double h = std::sqrt(std::max(0.0, radius * radius - b * b));
  return 2.0 *
    Integrate(
      [&](double t)
      {
        const double v = t - tc;
        return K::Extinction(std::sqrt(b * b + v * v), radius, density) *
          std::cos(j * vtkMath::Pi() * t / length);
      },
      tc - h, tc + h, density * radius);
}

void Coefficients(vtkMinimalStandardRandomSequence* random)
{
  const int count = vtkTransmittanceMapMath::GetMaximumNumberOfCoefficients();
  double worst = 0.0;
  for (int i = 0; i < 300; ++i)
  {
    const double length = random->GetNextRangeValue(0.5, 20.0);
    // Tiny particles (the series) to ones a map ray's length wide (the closed form).
    const double radius = std::min(
      0.49 * length, std::exp(random->GetNextRangeValue(std::log(1e-3), std::log(0.5 * length))));
    const double b = random->GetNextRangeValue(0.0, radius);
    const double tc = random->GetNextRangeValue(radius, length - radius);
    const double density = random->GetNextRangeValue(0.1, 5.0);
    std::vector<double> c(count, 0.0);
    Check(K::AddExtinctionCoefficients(b, tc, length, radius, density, count, c.data()),
      "AddExtinctionCoefficients accepts a particle inside the ray");
    const double scale = std::max(K::ChordDepth(0.0, radius, density), 1e-300);
    for (int j = 0; j < count; ++j)
    {
      const double numeric = NumericCoefficient(j, b, tc, length, radius, density);
      worst = std::max(worst, std::abs(c[j] - numeric) / scale);
    }
  }
  std::cout << "extinction coefficients of 300 random particles (16 each) against quadrature: "
            << "largest difference " << worst << " (relative to the centre chord's depth)\n";
  Check(worst < 1e-10, "a particle's extinction coefficients are exact");
  for (double x : { 1e-8, 0.1, 0.4999, 0.5, 0.5001, 3.0, 40.0 })
  {
    const double numeric = Integrate(
      [&](double s) { return (1 - s * s) * (1 - s * s) * std::cos(x * s); }, -1.0, 1.0, 1.0);
    std::cout << "g(" << x << ") = " << K::ProfileCosineIntegral(x) << ", quadrature " << numeric
              << "\n";
    Check(std::abs(K::ProfileCosineIntegral(x) - numeric) < 1e-13,
      "g(x) on both sides of the series' switch");
  }

  // Several particles on one light ray: their summed coefficients against
  // vtkTransmittanceMapMath's ETM march of the summed extinction.
  const double length = 4.0;
  const double particles[4][4] = { { 0.0, 0.8, 0.3, 3.0 }, { 0.1, 1.5, 0.5, 1.0 },
    { 0.25, 2.9, 0.4, 6.0 }, { 0.0, 1.7, 0.2, 2.0 } }; // b, tc, R, rho
  std::vector<double> splat(count, 0.0), marched(count, 0.0);
  for (const auto& p : particles)
  {
    K::AddExtinctionCoefficients(p[0], p[1], length, p[2], p[3], count, splat.data());
  }
  auto extinction = [&](double s)
  {
    double sum = 0.0;
    for (const auto& p : particles)
    {
      const double v = s * length - p[1];
      sum += K::Extinction(std::sqrt(p[0] * p[0] + v * v), p[2], p[3]);
    }
    return sum;
  };
  double bounds[3];
  vtkTransmittanceMapMath::Project(
    vtkTransmittanceMapMath::ETM, extinction, length, 200000, count, 0.0, marched.data(), bounds);
  double largest = 0.0;
  for (int j = 0; j < count; ++j)
  {
    largest = std::max(largest, std::abs(splat[j] - marched[j]));
  }
  std::cout << "four particles on one ray, splatted against the ETM march (200000 samples): "
            << "largest coefficient difference " << largest << " (c_0 = " << splat[0] << ")\n";
  Check(largest < 1e-10 * splat[0], "splatted coefficients equal the march's");
  const double T = vtkTransmittanceMapMath::Reconstruct(
    vtkTransmittanceMapMath::ETM, splat.data(), count, nullptr, 1.0);
  double depth = 0.0;
  for (const auto& p : particles)
  {
    depth += K::ChordDepth(p[0], p[2], p[3]);
  }
  Check(std::abs(T - std::exp(-depth)) < 1e-12 * std::max(T, 1e-300) + 1e-15,
    "the map's transmittance past all particles is exp(-the chords' depths)");
}

void BadInput()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double o[3] = { 0, 0, -2 }, d[3] = { 0, 0, 1 }, c[3] = { 0, 0, 0 };
  double coefficients[16] = {};
  Check(K::Extinction(0.0, 0.0, 1.0) == 0.0 && K::Extinction(0.0, -1.0, 1.0) == 0.0 &&
      K::Extinction(0.0, 1.0, -1.0) == 0.0 && K::Extinction(nan, 1.0, 1.0) == 0.0 &&
      K::Extinction(0.0, nan, 1.0) == 0.0 && K::Mass(nan, 1.0) == 0.0 &&
      K::ChordDepth(nan, 1.0, 1.0) == 0.0 && K::PartialDepth(0.0, nan, 1.0, 1.0) == 0.0 &&
      K::SegmentDepth(nullptr, d, 0, 1, c, 1, 1) == 0.0 &&
      K::SegmentDepth(o, d, 3.0, 1.0, c, 1, 1) == 0.0 &&
      K::SegmentDepth(o, d, 0.0, nan, c, 1, 1) == 0.0 && K::ProfileCosineIntegral(nan) == 0.0,
    "invalid particles and rays give 0");
  // Radii whose square under- or overflows a double: the kernel still of
  // the distance's ratio to the radius (never 0 inside, never NaN).
  const double inf = std::numeric_limits<double>::infinity();
  auto near = [](double v, double expected) { return std::abs(v - expected) < 1e-15; };
  Check(K::Extinction(0.0, 1e-170, 2.0) == 2.0 &&
      near(K::Extinction(0.5e-160, 1e-160, 1.0), 0.5625) &&
      near(K::Extinction(0.5e200, 1e200, 1.0), 0.5625) && K::Extinction(1e200, 1e200, 1.0) == 0.0 &&
      K::Extinction(inf, 1e200, 1.0) == 0.0 && K::Extinction(-0.5, 1.0, 1.0) == 0.5625 &&
      K::Extinction(1.0, 1.0, 1.0) == 0.0,
    "tiny and huge radii, on and off the sphere");
  Check(!K::AddExtinctionCoefficients(0, 1, 2, 0.5, 1, 0, coefficients) &&
      !K::AddExtinctionCoefficients(0, 1, 2, 0.5, 1, 17, coefficients) &&
      !K::AddExtinctionCoefficients(0, 1, 2, 0.5, 1, 4, nullptr) &&
      !K::AddExtinctionCoefficients(0, 1, 0.0, 0.5, 1, 4, coefficients) &&
      !K::AddExtinctionCoefficients(nan, 1, 2, 0.5, 1, 4, coefficients) &&
      !K::AddExtinctionCoefficients(0, 1, 2, 0.5, nan, 4, coefficients) &&
      std::all_of(coefficients, coefficients + 16, [](double v) { return v == 0.0; }),
    "invalid coefficient requests are refused and add nothing");
  Check(K::AddExtinctionCoefficients(2.0, 1, 2, 0.5, 1, 4, coefficients) &&
      std::all_of(coefficients, coefficients + 16, [](double v) { return v == 0.0; }),
    "a ray that misses adds nothing");
  Check(
    std::abs(K::SegmentDepth(o, d, 0.0, 4.0, c, 1.0, 1.0) - K::ChordDepth(0.0, 1.0, 1.0)) < 1e-15,
    "a segment over the whole chord is the chord");
  vtkNew<vtkParticleKernel> kernel;
  std::ostringstream os;
  kernel->Print(os);
  Check(os.str().find("vtkParticleKernel") != std::string::npos, "PrintSelf");
}
}

int TestParticleKernel(int, char*[])
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(20261124);
  MassAndChord();
  Segments(random);
  Coefficients(random);
  BadInput();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
