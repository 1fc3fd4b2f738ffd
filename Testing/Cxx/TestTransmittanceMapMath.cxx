// vtkTransmittanceMapMath against exact math: the projection and
// reconstruction of TFM, ETM and their adaptive variants on 1-D extinction
// profiles (a "1-D experiment": RMS and maximum errors against the exact
// transmittance, printed as a table), the specification's sample positions
// and adaptive bounds, exact special cases, the Henyey-Greenstein phase
// function, the opacity-to-extinction conversion and bad input.
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkTransmittanceMapMath.h"

#include "TyndallTestCheck.h"
#include "TyndallTestQuadrature.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Math = vtkTransmittanceMapMath;

using tyndall_test::Check;

constexpr int kProfileSize = 1001; // profile points, s_i = i / 1000
constexpr double kLength = 2.0;    // world length D of the light ray
constexpr int kSamples = 256;      // N
constexpr double kThreshold = 0.01;
constexpr int kGrid = 4001; // error grid over s in [0, 1]

struct Profile
{
  std::string Name;
  std::vector<double> Sigma;
};

// Optical depth D * integral_0^1 sigma of a piecewise-linear profile.
double TotalDepth(const std::vector<double>& sigma)
{
  return -std::log(
    Math::ExactTransmittance(sigma.data(), static_cast<int>(sigma.size()), kLength, 1.0));
}

// Profile from a function of s, scaled to a total optical depth.
template <typename F>
Profile MakeProfile(const std::string& name, F f, double depth)
{
  Profile p{ name, std::vector<double>(kProfileSize) };
  for (int i = 0; i < kProfileSize; ++i)
  {
    p.Sigma[i] = f(static_cast<double>(i) / (kProfileSize - 1));
  }
  const double scale = depth / TotalDepth(p.Sigma);
  for (double& v : p.Sigma)
  {
    v *= scale;
  }
  return p;
}

// A raised-cosine bump of the given centre and half width (compact support).
double Bump(double s, double centre, double halfWidth)
{
  const double x = (s - centre) / halfWidth;
  return std::abs(x) < 1.0 ? 0.5 * (1.0 + std::cos(vtkMath::Pi() * x)) : 0.0;
}

// The profile at s, linearly interpolated (written independently of the
// class).
double SigmaAt(const std::vector<double>& sigma, double s)
{
  const double x = s * (sigma.size() - 1);
  const size_t i = std::min(static_cast<size_t>(x), sigma.size() - 2);
  return sigma[i] + (x - i) * (sigma[i + 1] - sigma[i]);
}

struct Errors
{
  double Rms = 0.0;
  double Max = 0.0;
  double MinT = 1.0; // smallest reconstructed value, to check [0, 1]
  double MaxT = 0.0;
};

// Projects the profile and compares Reconstruct with ExactTransmittance on
// a grid of s (and a few points outside [0, 1] for the range check).
Errors Measure(const Profile& p, int method, int coefficientCount, double bounds[3])
{
  double coefficients[16];
  Errors e;
  if (!Math::Project(method, p.Sigma.data(), kProfileSize, kLength, kSamples, coefficientCount,
        kThreshold, coefficients, bounds))
  {
    Check(false, "Project succeeds on " + p.Name);
    e.Rms = e.Max = 1.0;
    return e;
  }
  double sum = 0.0;
  for (int k = 0; k < kGrid; ++k)
  {
    const double s = static_cast<double>(k) / (kGrid - 1);
    const double t = Math::Reconstruct(method, coefficients, coefficientCount, bounds, s);
    const double exact = Math::ExactTransmittance(p.Sigma.data(), kProfileSize, kLength, s);
    const double err = std::abs(t - exact);
    sum += err * err;
    e.Max = std::max(e.Max, err);
    e.MinT = std::min(e.MinT, t);
    e.MaxT = std::max(e.MaxT, t);
  }
  for (double s : { -1.0, -1e-9, 1.0 + 1e-9, 2.0 })
  {
    const double t = Math::Reconstruct(method, coefficients, coefficientCount, bounds, s);
    e.MinT = std::min(e.MinT, t);
    e.MaxT = std::max(e.MaxT, t);
  }
  e.Rms = std::sqrt(sum / kGrid);
  return e;
}

std::string Format(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%9.2e", v);
  return buffer;
}

const int kMethods[] = { Math::TFM, Math::ADAPTIVE_TFM, Math::ETM, Math::ADAPTIVE_ETM };
const int kCounts[] = { 4, 8, 16 };
}

int TestTransmittanceMapMath(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // Basics.
  {
    vtkNew<vtkTransmittanceMapMath> math;
    std::ostringstream os;
    math->Print(os);
    Check(os.str().find("vtkTransmittanceMapMath") != std::string::npos, "PrintSelf");
    const char* names[] = { "None", "BruteForce", "TFM", "AdaptiveTFM", "ETM", "AdaptiveETM" };
    for (int m = 0; m <= 5; ++m)
    {
      Check(std::string(Math::GetMethodName(m)) == names[m], std::string("name of ") + names[m]);
    }
    Check(std::string(Math::GetMethodName(6)) == "Unknown", "name of an unknown method");
    Check(Math::GetMaximumNumberOfCoefficients() == 16, "16 coefficients at most");
  }

  // 1. The 1-D experiment.
  const Profile profiles[] = {
    // Smooth, low density, optical depth 1, non-zero at both ends.
    MakeProfile(
      "wispy",
      [](double s)
      {
        return 1.0 + 0.5 * std::sin(2.0 * vtkMath::Pi() * 2.5 * s + 0.3) +
          0.2 * std::cos(2.0 * vtkMath::Pi() * 7.0 * s);
      },
      1.0),
    // Empty, a constant block over [0.3, 0.6] of optical depth 30, empty.
    MakeProfile(
      "dense step", [](double s) { return s >= 0.3 - 1e-12 && s <= 0.6 + 1e-12 ? 1.0 : 0.0; },
      30.0),
    // Two raised-cosine bumps of depths 2 and 3 with a gap: the threshold is
    // crossed in the second one.
    MakeProfile(
      "two blobs",
      [](double s) { return 2.0 * Bump(s, 0.25, 0.1) / 0.1 + 3.0 * Bump(s, 0.7, 0.12) / 0.12; },
      5.0),
  };

  // errors[profile][method][count]
  Errors errors[3][4][3];
  double allBounds[3][4][3][3];
  std::cout << "1-D experiment: N = " << kSamples << " samples, D = " << kLength
            << ", threshold = " << kThreshold << ", error of Reconstruct vs the exact T over "
            << kGrid << " points of s in [0, 1]\n";
  std::cout << "profile      method        RMS(M=4)  RMS(M=8) RMS(M=16)  max(M=4)  max(M=8) "
               "max(M=16)  s_min  s_max  T_beyond\n";
  for (int p = 0; p < 3; ++p)
  {
    for (int m = 0; m < 4; ++m)
    {
      for (int c = 0; c < 3; ++c)
      {
        errors[p][m][c] = Measure(profiles[p], kMethods[m], kCounts[c], allBounds[p][m][c]);
      }
      char line[256];
      std::snprintf(line, sizeof(line), "%-12s %-12s", profiles[p].Name.c_str(),
        Math::GetMethodName(kMethods[m]));
      std::cout << line;
      for (int c = 0; c < 3; ++c)
      {
        std::cout << " " << Format(errors[p][m][c].Rms);
      }
      for (int c = 0; c < 3; ++c)
      {
        std::cout << " " << Format(errors[p][m][c].Max);
      }
      const double* b = allBounds[p][m][1];
      std::snprintf(line, sizeof(line), "  %.4f %.4f %9.2e\n", b[0], b[1], b[2]);
      std::cout << line;
    }
  }
  const int wispy = 0, dense = 1, blobs = 2;
  const int tfm = 0, adaptiveTfm = 1, etm = 2, adaptiveEtm = 3;

  // Adaptive beats plain on the dense profile (RMS), for every count.
  for (int c = 0; c < 3; ++c)
  {
    const std::string count = " (M=" + std::to_string(kCounts[c]) + ")";
    Check(errors[dense][adaptiveTfm][c].Rms < 0.5 * errors[dense][tfm][c].Rms,
      "adaptive TFM halves the RMS error of TFM on the dense step" + count);
    Check(errors[dense][adaptiveEtm][c].Rms < 0.5 * errors[dense][etm][c].Rms,
      "adaptive ETM halves the RMS error of ETM on the dense step" + count);
  }
  // Adaptive beats plain on the two blobs too (RMS), for every count.
  for (int c = 0; c < 3; ++c)
  {
    const std::string count = " (M=" + std::to_string(kCounts[c]) + ")";
    Check(errors[blobs][adaptiveTfm][c].Rms < errors[blobs][tfm][c].Rms,
      "adaptive TFM beats TFM on the two blobs" + count);
    Check(errors[blobs][adaptiveEtm][c].Rms < errors[blobs][etm][c].Rms,
      "adaptive ETM beats ETM on the two blobs" + count);
  }
  // Every method is accurate on the wispy profile. (TFM's maximum error is
  // at s = 0, where the cosine series of T, whose slope is not zero there,
  // converges only as 1/M; the adaptive TFM returns exactly 1 at s_min = 0.)
  for (int m = 0; m < 4; ++m)
  {
    const std::string name = Math::GetMethodName(kMethods[m]);
    Check(errors[wispy][m][1].Rms < 1e-2, name + " RMS error < 1e-2 on the wispy profile (M=8)");
    Check(errors[wispy][m][1].Max < 5e-2, name + " max error < 5e-2 on the wispy profile (M=8)");
    Check(errors[wispy][m][2].Rms < 4e-3, name + " RMS error < 4e-3 on the wispy profile (M=16)");
    Check(errors[wispy][m][2].Max < 3e-2, name + " max error < 3e-2 on the wispy profile (M=16)");
  }
  // ETM is more accurate than TFM there, and converges fast with M.
  for (int m : { etm, adaptiveEtm })
  {
    const std::string name = Math::GetMethodName(kMethods[m]);
    Check(errors[wispy][m][1].Max < 1e-2, name + " max error < 1e-2 on the wispy profile (M=8)");
    Check(errors[wispy][m][2].Max < 2e-3, name + " max error < 2e-3 on the wispy profile (M=16)");
    Check(errors[wispy][m][0].Rms > 3.0 * errors[wispy][m][1].Rms &&
        errors[wispy][m][1].Rms > 3.0 * errors[wispy][m][2].Rms,
      name + " RMS error falls at least 3-fold from M=4 to 8 to 16 on the wispy profile");
  }
  // Reconstruction within [0, 1]; bounds ordered.
  for (int p = 0; p < 3; ++p)
  {
    for (int m = 0; m < 4; ++m)
    {
      for (int c = 0; c < 3; ++c)
      {
        const Errors& e = errors[p][m][c];
        const double* b = allBounds[p][m][c];
        const std::string what = profiles[p].Name + " " + Math::GetMethodName(kMethods[m]) +
          " M=" + std::to_string(kCounts[c]);
        Check(e.MinT >= 0.0 && e.MaxT <= 1.0, what + ": reconstruction within [0, 1]");
        Check(0.0 <= b[0] && b[0] <= b[1] && b[1] <= 1.0 && b[2] >= 0.0 && b[2] <= 1.0,
          what + ": 0 <= s_min <= s_max <= 1, T_beyond in [0, 1]");
      }
    }
  }

  // 2. The bounds follow the specification.
  {
    const double du = 1.0 / kSamples;
    // Plain methods: (0, 1, T at the end as the midpoint march sees it).
    for (int p = 0; p < 3; ++p)
    {
      double depth = 0.0;
      for (int n = 0; n < kSamples; ++n)
      {
        depth += SigmaAt(profiles[p].Sigma, (n + 0.5) * du) * kLength * du;
      }
      for (int m : { tfm, etm })
      {
        const double* b = allBounds[p][m][1];
        Check(b[0] == 0.0 && b[1] == 1.0 && std::abs(b[2] / std::exp(-depth) - 1.0) < 1e-12,
          profiles[p].Name + ": plain bounds are (0, 1, T(1) of the march)");
      }
    }
    const double wispyEnd =
      Math::ExactTransmittance(profiles[wispy].Sigma.data(), kProfileSize, kLength, 1.0);
    Check(std::abs(allBounds[wispy][tfm][1][2] - wispyEnd) < 1e-5,
      "wispy: the march's T(1) is close to the exact one");
    // Wispy: no empty start, never below the threshold: the whole segment.
    const double* w = allBounds[wispy][adaptiveTfm][1];
    Check(w[0] == 0.0 && w[1] == 1.0 && w[2] == allBounds[wispy][tfm][1][2],
      "wispy adaptive bounds are (0, 1, T(1))");
    // Adaptive: an independent first march (the specification, literally).
    for (int p : { dense, blobs })
    {
      const std::vector<double>& sigma = profiles[p].Sigma;
      int first = -1, below = -1;
      double depth = 0.0;
      for (int n = 0; n < kSamples; ++n)
      {
        const double sig = SigmaAt(sigma, (n + 0.5) * du);
        if (first < 0 && sig > 0.0)
        {
          first = n;
        }
        depth += sig * kLength * du;
        if (std::exp(-(depth - 0.5 * sig * kLength * du)) < kThreshold)
        {
          below = n + 1; // the range ends after the sample that crossed
          break;
        }
      }
      for (int m : { adaptiveTfm, adaptiveEtm })
      {
        const double* b = allBounds[p][m][1];
        const std::string what = profiles[p].Name + " " + Math::GetMethodName(kMethods[m]);
        Check(below > first && b[0] == first * du && b[1] == below * du,
          what +
            ": s_min is the start of the first non-empty sample, s_max the end of the "
            "first dense one");
        Check(std::abs(b[2] - std::exp(-depth)) < 1e-14, what + ": T_beyond is T at s_max");
        Check(b[2] < kThreshold && b[2] > 0.01 * kThreshold,
          what + ": T_beyond just below the threshold");
      }
    }
    // Two thin layers, as isosurfaces are for the light: one transmitting
    // 0.7, then an opaque one (depth 13.8), each within one sample. T_beyond
    // must be the second's, not the first's.
    {
      std::vector<double> layers(kProfileSize, 0.0);
      const double width = kLength / (kProfileSize - 1); // one profile interval, world units
      layers[300] = layers[301] = -std::log(0.7) / width;
      layers[600] = layers[601] = 13.8 / width;
      for (int m : { adaptiveTfm, adaptiveEtm })
      {
        double coefficients[8], b[3];
        Math::Project(kMethods[m], layers.data(), kProfileSize, kLength, kSamples, 8, kThreshold,
          coefficients, b);
        Check(b[2] < 1e-5 && b[1] > 0.6,
          std::string(Math::GetMethodName(kMethods[m])) +
            ": an opaque layer behind a translucent one: T_beyond past both");
      }
    }
    // Reconstruction at the bounds themselves: 1 at s_min, T_beyond at s_max.
    for (int m : { adaptiveTfm, adaptiveEtm })
    {
      double coefficients[8], b[3];
      Math::Project(kMethods[m], profiles[dense].Sigma.data(), kProfileSize, kLength, kSamples, 8,
        kThreshold, coefficients, b);
      Check(Math::Reconstruct(kMethods[m], coefficients, 8, b, b[0]) == 1.0 &&
          Math::Reconstruct(kMethods[m], coefficients, 8, b, b[1]) == b[2],
        std::string(Math::GetMethodName(kMethods[m])) + ": T(s_min) = 1, T(s_max) = T_beyond");
    }
    // Plain methods clamp s to [0, 1].
    for (int m : { tfm, etm })
    {
      double coefficients[8], b[3];
      Math::Project(kMethods[m], profiles[blobs].Sigma.data(), kProfileSize, kLength, kSamples, 8,
        kThreshold, coefficients, b);
      const double t0 = Math::Reconstruct(kMethods[m], coefficients, 8, b, 0.0);
      const double t1 = Math::Reconstruct(kMethods[m], coefficients, 8, b, 1.0);
      Check(Math::Reconstruct(kMethods[m], coefficients, 8, b, -0.3) == t0 &&
          Math::Reconstruct(kMethods[m], coefficients, 8, b, 1.3) == t1,
        std::string(Math::GetMethodName(kMethods[m])) + ": s is clamped to [0, 1]");
    }
    // The step starts at s = 0.299 (the linear ramp of the profile): the
    // first sample with extinction is the one whose midpoint passes it.
    Check(allBounds[dense][adaptiveTfm][1][0] == 77.0 / 256.0, "dense step: s_min = 77/256");

    // An opaque sample: the threshold is crossed within the first sample
    // with extinction; the range keeps that sample (s_max = s_min + 1/N).
    std::vector<double> wall(kProfileSize, 0.0);
    for (int i = 500; i < kProfileSize; ++i)
    {
      wall[i] = 1e4;
    }
    for (int method : { Math::ADAPTIVE_TFM, Math::ADAPTIVE_ETM })
    {
      double coefficients[8], b[3];
      const bool ok = Math::Project(
        method, wall.data(), kProfileSize, kLength, kSamples, 8, kThreshold, coefficients, b);
      const int n0 = 128; // midpoint 128.5/256 > 0.5
      const double stepDepth = 1e4 * kLength * du;
      const std::string what = std::string(Math::GetMethodName(method)) + " opaque wall";
      Check(ok && b[0] == n0 * du && b[1] == (n0 + 1) * du && b[2] == std::exp(-stepDepth),
        what + ": s_max = s_min + 1/N, T_beyond at its end");
      Check(Math::Reconstruct(method, coefficients, 8, b, 0.4) == 1.0 &&
          Math::Reconstruct(method, coefficients, 8, b, 0.9) == b[2],
        what + ": lit before, dark behind");
    }
  }

  // 3. The sample positions and the midpoint T_n of the specification, on
  // profiles where the sums have independent closed forms.
  {
    const int n = 64;
    const double du = 1.0 / n;
    // Linear profile sigma(s) = b s: tau_n = D b du^2 (n^2/2 + n/2 + 1/4)
    // (not the exact integral D b u_n^2 / 2, which differs by D b du^2/8).
    const double slope = 3.0;
    const double linear[2] = { 0.0, slope };
    double a[16], bounds[3];
    Check(Math::Project(Math::TFM, linear, 2, kLength, n, 16, kThreshold, a, bounds),
      "TFM of a linear profile");
    double worst = 0.0;
    for (int j = 0; j < 16; ++j)
    {
      double expected = 0.0;
      for (int k = 0; k < n; ++k)
      {
        const double tau = kLength * slope * du * du * (0.5 * k * k + 0.5 * k + 0.25);
        expected += 2.0 * std::exp(-tau) * std::cos(j * vtkMath::Pi() * (k + 0.5) * du) * du;
      }
      worst = std::max(worst, std::abs(a[j] - expected));
    }
    std::cout << "TFM coefficients of a linear profile vs the specification: " << worst << "\n";
    Check(worst < 1e-14, "TFM a_j = 2 sum T_n cos(j pi u_n) du with the midpoint T_n");
    Check(std::abs(bounds[2] - std::exp(-kLength * slope * 0.5)) < 1e-14,
      "plain T_beyond: the march's T at the end (exact for a linear profile)");
    // ETM of the same profile: c_j = 2 D b sum u_n cos(j pi u_n) du.
    double c[16];
    Check(Math::Project(Math::ETM, linear, 2, kLength, n, 16, kThreshold, c, bounds),
      "ETM of a linear profile");
    worst = 0.0;
    for (int j = 0; j < 16; ++j)
    {
      double expected = 0.0;
      for (int k = 0; k < n; ++k)
      {
        const double u = (k + 0.5) * du;
        expected += 2.0 * kLength * slope * u * std::cos(j * vtkMath::Pi() * u) * du;
      }
      worst = std::max(worst, std::abs(c[j] - expected));
    }
    Check(worst < 1e-13, "ETM c_j = 2 sum D' sigma_n cos(j pi u_n) du");
    Check(
      std::abs(c[0] - kLength * slope) < 1e-13, "ETM c_0 = 2 D integral sigma (midpoint exact)");
  }

  // 4. Exact special cases.
  {
    // ETM with one coefficient is exact for a constant profile:
    // tau(u) = c_0 u / 2 = D' sigma u. Adaptive too (T_beyond is exact).
    const double sigma = 1.7;
    std::vector<double> constant(11, sigma);
    for (int method : { Math::ETM, Math::ADAPTIVE_ETM })
    {
      double c[1], b[3];
      Check(Math::Project(method, constant.data(), 11, kLength, kSamples, 1, kThreshold, c, b),
        "ETM of a constant profile");
      double worst = 0.0;
      for (int k = 0; k <= 1000; ++k)
      {
        const double s = k / 1000.0;
        const double exact = std::exp(-sigma * kLength * s);
        worst = std::max(worst, std::abs(Math::Reconstruct(method, c, 1, b, s) - exact) / exact);
        worst = std::max(worst,
          std::abs(Math::ExactTransmittance(constant.data(), 11, kLength, s) - exact) / exact);
      }
      std::cout << Math::GetMethodName(method) << " with M=1, constant profile: max relative error "
                << worst << "\n";
      Check(worst < 1e-13,
        std::string(Math::GetMethodName(method)) +
          " with one coefficient is exact for a constant profile");
    }
    // A zero profile reconstructs T = 1: exactly for ETM (all c_j are 0);
    // for TFM a_0 = 2 exactly, but the a_j, j >= 1, are the rounding
    // residues (~1e-16) of sum_n cos(j pi u_n), which is 0 only in exact
    // arithmetic, so T = 1 to a few ulps.
    std::vector<double> zero(5, 0.0);
    for (int method : { Math::TFM, Math::ADAPTIVE_TFM, Math::ETM, Math::ADAPTIVE_ETM })
    {
      double c[16], b[3];
      const std::string name = Math::GetMethodName(method);
      Check(Math::Project(method, zero.data(), 5, kLength, kSamples, 16, kThreshold, c, b) &&
          b[0] == 0.0 && b[1] == 1.0 && b[2] == 1.0,
        name + " of a zero profile: bounds (0, 1, 1)");
      Check(c[0] == (method == Math::TFM || method == Math::ADAPTIVE_TFM ? 2.0 : 0.0),
        name + " of a zero profile: c_0 = 2 (TFM), 0 (ETM)");
      double worst = 0.0;
      for (int k = 0; k <= 1000; ++k)
      {
        worst = std::max(worst, std::abs(Math::Reconstruct(method, c, 16, b, k / 1000.0) - 1.0));
      }
      const bool etmMethod = method == Math::ETM || method == Math::ADAPTIVE_ETM;
      std::cout << name << " of a zero profile: max |T - 1| = " << worst << "\n";
      Check(etmMethod ? worst == 0.0 : worst < 1e-14, name + " of a zero profile gives T = 1");
    }
  }

  // 5. Exact math.
  {
    // ExactTransmittance of sigma(s) = a + b s: exp(-D (a s + b s^2 / 2)).
    const double a = 0.4, b = 2.5;
    std::vector<double> linear(7);
    for (int i = 0; i < 7; ++i)
    {
      linear[i] = a + b * i / 6.0;
    }
    double worst = 0.0;
    for (int k = 0; k <= 1000; ++k)
    {
      const double s = k / 1000.0;
      const double exact = std::exp(-kLength * (a * s + 0.5 * b * s * s));
      worst =
        std::max(worst, std::abs(Math::ExactTransmittance(linear.data(), 7, kLength, s) - exact));
    }
    Check(worst < 1e-14, "ExactTransmittance of a linear profile is the closed form");
    Check(Math::ExactTransmittance(linear.data(), 7, kLength, -1.0) == 1.0 &&
        Math::ExactTransmittance(linear.data(), 7, kLength, 3.0) ==
          Math::ExactTransmittance(linear.data(), 7, kLength, 1.0),
      "ExactTransmittance clamps s to [0, 1]");

    // Henyey-Greenstein: normalised, isotropic at g = 0, forward peaked.
    for (double g : { -0.99, -0.7, -0.3, 0.0, 0.2, 0.5, 0.8, 0.95, 0.99 })
    {
      auto p = [g](double mu) { return Math::HenyeyGreenstein(g, mu); };
      const double integral =
        2.0 * vtkMath::Pi() * tyndall_test::AdaptiveIntegrate(p, -1.0, 1.0, 1e-12);
      Check(std::abs(integral - 1.0) < 1e-9,
        "HG integrates to 1 over the sphere, g = " + std::to_string(g));
      if (g > 0.0)
      {
        bool peak = true;
        for (int k = 0; k < 200; ++k)
        {
          const double mu = -1.0 + k / 100.0;
          peak = peak && p(mu) < p(1.0) && p(mu) <= p(mu + 0.01);
        }
        Check(peak, "HG peaks forward (mu = 1) and increases with mu, g = " + std::to_string(g));
      }
    }
    const double isotropic = 1.0 / (4.0 * vtkMath::Pi());
    Check(std::abs(Math::HenyeyGreenstein(0.0, 0.3) - isotropic) < 1e-16 &&
        std::abs(Math::HenyeyGreenstein(0.0, -1.0) - isotropic) < 1e-16,
      "HG(g = 0) = 1 / (4 pi)");
    Check(Math::HenyeyGreenstein(2.0, 0.5) == Math::HenyeyGreenstein(0.99, 0.5) &&
        Math::HenyeyGreenstein(-5.0, 0.5) == Math::HenyeyGreenstein(-0.99, 0.5),
      "HG clamps g to [-0.99, 0.99]");
    Check(std::abs(Math::HenyeyGreenstein(0.5, 1.0) - 0.75 / (4.0 * vtkMath::Pi() * 0.125)) < 1e-14,
      "HG(0.5, 1) = (1 - g^2) / (4 pi (1 - g)^3)");

    // Multiple-scattering octaves: one octave is p T; three octaves against
    // the sum written out, without and with the build-up; T = 0 and NaN
    // give 0; clamps.
    {
      const double albedo[3] = { 0.9, 0.5, 0.0 };
      double w[3];
      const double quarter[4] = { 0.5, 0.25, 0.5, 0.0 };
      Math::OctaveScattering(1, quarter, 0.3, 0.2, 0.4, albedo, w);
      const double single = Math::HenyeyGreenstein(0.3, 0.2) * 0.4;
      Check(w[0] == single && w[1] == single && w[2] == single, "one octave is p(g, mu) T");
      for (double s : { 0.0, 5.0 })
      {
        const double factors[4] = { 1.6, 0.3, 0.5, s };
        Math::OctaveScattering(3, factors, 0.4, -0.3, 0.2, albedo, w);
        const double buildUp = s > 0.0 ? 1.0 - std::pow(0.2, s) : 1.0;
        bool agree = true;
        for (int k = 0; k < 3; ++k)
        {
          const double r = 1.6 * albedo[k];
          const double expected = Math::HenyeyGreenstein(0.4, -0.3) * 0.2 +
            buildUp *
              (r * Math::HenyeyGreenstein(0.2, -0.3) * std::pow(0.2, 0.3) +
                r * r * Math::HenyeyGreenstein(0.1, -0.3) * std::pow(0.2, 0.09));
          agree = agree && std::abs(w[k] - expected) < 1e-14 * expected;
        }
        Check(agree,
          s > 0.0 ? "three octaves with build-up: p T + (1 - T^s) sum_i (a rho)^i p(c^i g) T^(b^i)"
                  : "three octaves: sum_i (a rho)^i p(c^i g, mu) T^(b^i)");
        Check(w[2] == Math::HenyeyGreenstein(0.4, -0.3) * 0.2, "albedo 0: the first octave alone");
      }
      const double full[4] = { 1.3, 0.45, 0.0, 6.0 };
      Math::OctaveScattering(2, full, 0.4, 0.2, 1.0, albedo, w);
      Check(w[0] == Math::HenyeyGreenstein(0.4, 0.2),
        "build-up: no multiply scattered light where the light crossed no medium (T = 1)");
      Math::OctaveScattering(4, quarter, 0.3, 0.2, 0.0, albedo, w);
      Check(w[0] == 0.0 && w[1] == 0.0 && w[2] == 0.0, "T = 0: no light in any octave");
      Math::OctaveScattering(4, quarter, 0.3, 0.2, std::nan(""), albedo, w);
      Check(w[0] == 0.0, "T = NaN: no light");
      double clamped[3];
      const double wild[4] = { 9.0, -1.0, 2.0, 100.0 };
      const double limits[4] = { 4.0, 0.0, 1.0, 64.0 };
      // T near 1, where 1 - T^64 and 1 - T^100 differ.
      Math::OctaveScattering(20, wild, 0.3, 0.2, 0.999, albedo, w);
      Math::OctaveScattering(8, limits, 0.3, 0.2, 0.999, albedo, clamped);
      Check(w[0] == clamped[0] && w[1] == clamped[1],
        "n clamps to 8, a to [0, 4], b, c to [0, 1], k to [0, 64]");
      const double nans[4] = { 1.3, std::nan(""), std::nan(""), std::nan("") };
      const double zeros[4] = { 1.3, 0.0, 0.0, 0.0 };
      Math::OctaveScattering(3, nans, 0.3, 0.2, 0.5, albedo, w);
      Math::OctaveScattering(3, zeros, 0.3, 0.2, 0.5, albedo, clamped);
      Check(w[0] == clamped[0] && w[0] > 1.5 * Math::HenyeyGreenstein(0.3, 0.2) * 0.5,
        "NaN b, c, k count as 0 (the further octaves still there)");
      const double nanA[4] = { std::nan(""), 0.3, 0.0, 0.0 };
      Math::OctaveScattering(3, nanA, 0.3, 0.2, 0.5, albedo, w);
      Check(std::abs(w[0] - Math::HenyeyGreenstein(0.3, 0.2) * 0.5) < 1e-15 * w[0],
        "NaN a counts as 0 (the first octave alone)");
      Math::OctaveScattering(4, quarter, 0.3, 0.2, 1.0, albedo, w);
      Math::OctaveScattering(4, quarter, 0.3, 0.2, 0.9, albedo, clamped);
      Check(w[0] > clamped[0] && clamped[0] > single, "the octaves add light and fall with T");
    }

    // Opacity correction: 1 - exp(-sigma d) = 1 - (1 - alpha)^(d / u).
    worst = 0.0;
    for (double alpha : { 0.0, 1e-6, 0.01, 0.3, 0.5, 0.9, 0.999 })
    {
      for (double unit : { 0.1, 1.0, 3.5 })
      {
        for (double d : { 0.01, 0.5, 1.0, 7.0 })
        {
          const double sigma = Math::ExtinctionFromOpacity(alpha, unit, 1.0);
          worst = std::max(worst,
            std::abs((1.0 - std::exp(-sigma * d)) - (1.0 - std::pow(1.0 - alpha, d / unit))));
        }
      }
    }
    Check(worst < 1e-14, "ExtinctionFromOpacity reproduces VTK's opacity correction");
    Check(std::abs(Math::ExtinctionFromOpacity(0.5, 2.0, 3.0) - 3.0 * std::log(2.0) / 2.0) < 1e-15,
      "ExtinctionFromOpacity scales with DensityScale and 1 / unit distance");
    const double opaque = -std::log(1e-6);
    Check(std::abs(Math::ExtinctionFromOpacity(1.0, 1.0, 1.0) - opaque) < 1e-9 &&
        Math::ExtinctionFromOpacity(7.0, 1.0, 1.0) == Math::ExtinctionFromOpacity(1.0, 1.0, 1.0),
      "ExtinctionFromOpacity clamps alpha to 1 - 1e-6");
    Check(Math::ExtinctionFromOpacity(-0.5, 1.0, 1.0) == 0.0, "negative alpha gives 0");
  }

  // 6. Bad input: false, nothing written; defined values, never NaN.
  {
    const std::vector<double>& good = profiles[wispy].Sigma;
    double c[17], b[3];
    auto fails = [&](int method, const double* profile, int size, double length, int samples,
                   int count, double threshold, bool nullOutputs = false)
    {
      std::fill(c, c + 17, 42.0);
      std::fill(b, b + 3, 42.0);
      const bool ok = Math::Project(method, profile, size, length, samples, count, threshold,
        nullOutputs ? nullptr : c, nullOutputs ? nullptr : b);
      bool untouched = true;
      for (double v : c)
      {
        untouched = untouched && v == 42.0;
      }
      return !ok && untouched && b[0] == 42.0 && b[1] == 42.0 && b[2] == 42.0;
    };
    const int size = kProfileSize;
    const double* g = good.data();
    std::vector<double> withNaN(good), negative(good), infinite(good);
    withNaN[17] = nan;
    negative[500] = -1e-9;
    infinite[3] = inf;
    Check(fails(Math::TFM, nullptr, size, 1.0, 64, 8, 0.01), "null profile");
    Check(fails(Math::TFM, g, 1, 1.0, 64, 8, 0.01), "profile size 1");
    Check(fails(Math::ETM, withNaN.data(), size, 1.0, 64, 8, 0.01), "NaN in the profile");
    Check(
      fails(Math::ADAPTIVE_ETM, negative.data(), size, 1.0, 64, 8, 0.01), "negative extinction");
    Check(fails(Math::TFM, infinite.data(), size, 1.0, 64, 8, 0.01), "infinite extinction");
    Check(fails(Math::TFM, g, size, 0.0, 64, 8, 0.01), "zero length");
    Check(fails(Math::TFM, g, size, -1.0, 64, 8, 0.01), "negative length");
    Check(fails(Math::TFM, g, size, nan, 64, 8, 0.01), "NaN length");
    Check(fails(Math::TFM, g, size, inf, 64, 8, 0.01), "infinite length");
    Check(fails(Math::TFM, g, size, 1.0, 0, 8, 0.01), "zero samples");
    Check(fails(Math::TFM, g, size, 1.0, 64, 0, 0.01), "zero coefficients");
    Check(fails(Math::TFM, g, size, 1.0, 64, 17, 0.01), "17 coefficients");
    Check(fails(Math::NONE, g, size, 1.0, 64, 8, 0.01), "NONE is not a map method");
    Check(fails(Math::BRUTE_FORCE, g, size, 1.0, 64, 8, 0.01), "BRUTE_FORCE is not a map method");
    Check(fails(6, g, size, 1.0, 64, 8, 0.01) && fails(-1, g, size, 1.0, 64, 8, 0.01),
      "unknown methods");
    Check(fails(Math::ADAPTIVE_TFM, g, size, 1.0, 64, 8, nan), "NaN threshold");
    Check(fails(Math::ADAPTIVE_TFM, g, size, 1.0, 64, 8, -0.1), "negative threshold");
    Check(fails(Math::ADAPTIVE_ETM, g, size, 1.0, 64, 8, 1.0), "threshold 1");
    Check(fails(Math::TFM, g, size, 1.0, 64, 8, 0.01, true), "null outputs");
    Check(Math::Project(Math::TFM, g, size, 1.0, 64, 8, nan, c, b),
      "the threshold does not matter to plain methods");

    // Reconstruct: 1 for invalid input.
    double coefficients[16], bounds[3];
    Math::Project(Math::ADAPTIVE_ETM, profiles[dense].Sigma.data(), size, kLength, 64, 16,
      kThreshold, coefficients, bounds);
    Check(Math::Reconstruct(Math::NONE, coefficients, 16, bounds, 0.5) == 1.0, "NONE gives 1");
    Check(Math::Reconstruct(Math::BRUTE_FORCE, coefficients, 16, bounds, 0.5) == 1.0 &&
        Math::Reconstruct(9, coefficients, 16, bounds, 0.5) == 1.0,
      "non-map methods give 1");
    Check(
      Math::Reconstruct(Math::ETM, nullptr, 16, bounds, 0.5) == 1.0, "null coefficients give 1");
    Check(Math::Reconstruct(Math::ETM, coefficients, 0, bounds, 0.5) == 1.0 &&
        Math::Reconstruct(Math::ETM, coefficients, 17, bounds, 0.5) == 1.0,
      "counts outside [1, 16] give 1");
    Check(Math::Reconstruct(Math::ADAPTIVE_ETM, coefficients, 16, nullptr, 0.5) == 1.0,
      "adaptive without bounds gives 1");
    Check(Math::Reconstruct(Math::ETM, coefficients, 16, nullptr, 0.5) < 1.0,
      "plain methods need no bounds");
    Check(Math::Reconstruct(Math::ADAPTIVE_ETM, coefficients, 16, bounds, nan) == 1.0 &&
        Math::Reconstruct(Math::TFM, coefficients, 16, bounds, nan) == 1.0,
      "NaN s gives 1");
    const double badBounds[][3] = { { 0.6, 0.5, 0.1 }, { -0.1, 0.5, 0.1 }, { 0.1, 1.5, 0.1 },
      { 0.1, 0.5, 1.5 }, { 0.1, 0.5, -0.1 }, { nan, 0.5, 0.1 }, { 0.1, nan, 0.1 },
      { 0.1, 0.5, nan } };
    bool allOne = true;
    for (const auto& bad : badBounds)
    {
      for (int method : { Math::ADAPTIVE_TFM, Math::ADAPTIVE_ETM })
      {
        for (double s : { 0.3, 0.7, 0.95 })
        {
          allOne = allOne && Math::Reconstruct(method, coefficients, 16, bad, s) == 1.0;
        }
      }
    }
    Check(allOne, "invalid bounds give 1");
    double nanCoefficients[4] = { 1.0, nan, 0.0, 0.0 };
    const double fine[3] = { 0.0, 1.0, 0.5 };
    bool finite = true;
    for (int method : { Math::TFM, Math::ADAPTIVE_TFM, Math::ETM, Math::ADAPTIVE_ETM })
    {
      for (double s : { -inf, -1.0, 0.0, 0.25, 1.0, 2.0, inf })
      {
        for (const double* coeffs :
          { static_cast<const double*>(coefficients), static_cast<const double*>(nanCoefficients) })
        {
          const double t = Math::Reconstruct(method, coeffs, coeffs == coefficients ? 16 : 4,
            coeffs == coefficients ? bounds : fine, s);
          finite = finite && t >= 0.0 && t <= 1.0;
        }
      }
    }
    Check(finite, "Reconstruct is in [0, 1] for infinite s and NaN coefficients");

    Check(Math::ExactTransmittance(nullptr, 5, 1.0, 0.5) == 1.0 &&
        Math::ExactTransmittance(withNaN.data(), size, 1.0, 0.5) == 1.0 &&
        Math::ExactTransmittance(g, size, 1.0, nan) == 1.0 &&
        Math::ExactTransmittance(g, size, -2.0, 0.5) == 1.0,
      "ExactTransmittance gives 1 for invalid input");
    Check(Math::HenyeyGreenstein(nan, 0.5) == Math::HenyeyGreenstein(0.0, 0.5) &&
        Math::HenyeyGreenstein(0.5, nan) == Math::HenyeyGreenstein(0.5, 0.0) &&
        Math::HenyeyGreenstein(0.5, inf) == Math::HenyeyGreenstein(0.5, 1.0),
      "HG: NaN counts as 0, mu is clamped");
    Check(Math::ExtinctionFromOpacity(0.5, 0.0, 1.0) == 0.0 &&
        Math::ExtinctionFromOpacity(0.5, -1.0, 1.0) == 0.0 &&
        Math::ExtinctionFromOpacity(0.5, nan, 1.0) == 0.0 &&
        Math::ExtinctionFromOpacity(0.5, 1.0, nan) == 0.0 &&
        Math::ExtinctionFromOpacity(0.5, 1.0, -1.0) == 0.0 &&
        Math::ExtinctionFromOpacity(nan, 1.0, 1.0) == 0.0,
      "ExtinctionFromOpacity gives 0 for invalid input");
  }

  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
