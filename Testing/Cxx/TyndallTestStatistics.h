// Statistics of the Monte Carlo tests (vtkVolumetricPathTracer against the
// single-scattering reference or against itself): per pixel and channel
// z = (a - b) / standard error, their mean square, the largest |z|, and the
// global z of the image sums per channel. Header only; not part of the
// library.
#ifndef TyndallTestStatistics_h
#define TyndallTestStatistics_h

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include "TyndallTestCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

namespace tyndall_test
{
struct Stats
{
  double Global = 0.0; // z of the image sums, the largest |z| of the three channels
  double MeanZ2 = 0.0;
  double MaxZ = 0.0;
  double Sum[2] = { 0.0, 0.0 };
  int Count = 0;
  int Infinite = 0; // values that differ with no variance
};

// z statistics of a - b, each with its standard error (b's may be null: an
// exact reference). The per-pixel z (MeanZ2, MaxZ, Count) leaves out the
// pixels whose view transmittance in b exceeds `clear` (mean over its
// channels): there a path meets the medium rarely, and among a few hundred
// paths the few that do (or none) give a skewed estimate whose sample
// standard error says little; the global z of the sums keeps every pixel.
// So does a value below `faint` in both images (a pixel in deep shadow,
// whose shadow rays rarely reach the light). The defaults keep every pixel.
inline Stats Compare(
  vtkImageData* a, vtkImageData* b, bool bHasError, double clear = 2.0, double faint = 0.0)
{
  Stats s;
  vtkDataArray* la = a->GetPointData()->GetArray("Radiance");
  vtkDataArray* ea = a->GetPointData()->GetArray("RadianceStandardError");
  vtkDataArray* lb = b->GetPointData()->GetArray("Radiance");
  vtkDataArray* eb = bHasError ? b->GetPointData()->GetArray("RadianceStandardError") : nullptr;
  vtkDataArray* tb = b->GetPointData()->GetArray("Transmittance");
  // Per channel: a path's channels are strongly correlated, so the sum over
  // channels does not have the variance sum(SE^2).
  double difference[3] = { 0.0, 0.0, 0.0 }, variance[3] = { 0.0, 0.0, 0.0 }, z2 = 0.0;
  for (vtkIdType p = 0; p < la->GetNumberOfTuples(); ++p)
  {
    double transmittance = 0.0;
    for (int c = 0; tb && c < tb->GetNumberOfComponents(); ++c)
    {
      transmittance += tb->GetComponent(p, c) / tb->GetNumberOfComponents();
    }
    const bool clearPixel = tb && transmittance > clear;
    for (int c = 0; c < 3; ++c)
    {
      const double d = la->GetComponent(p, c) - lb->GetComponent(p, c);
      const double e2 =
        std::pow(ea->GetComponent(p, c), 2) + (eb ? std::pow(eb->GetComponent(p, c), 2) : 0.0);
      s.Sum[0] += la->GetComponent(p, c);
      s.Sum[1] += lb->GetComponent(p, c);
      difference[c] += d;
      variance[c] += e2;
      if (clearPixel ||
        (std::abs(la->GetComponent(p, c)) < faint && std::abs(lb->GetComponent(p, c)) < faint))
      {
        continue;
      }
      if (e2 > 0.0)
      {
        const double z = d / std::sqrt(e2);
        z2 += z * z;
        s.MaxZ = std::max(s.MaxZ, std::abs(z));
        ++s.Count;
      }
      else if (std::abs(d) > 1e-12)
      {
        s.MaxZ = std::numeric_limits<double>::infinity();
        if (s.Infinite++ == 0)
        {
          std::cout << "  pixel " << p << " channel " << c << ": " << la->GetComponent(p, c)
                    << " against " << lb->GetComponent(p, c) << " with no variance"
                    << (tb ? ", transmittance " + std::to_string(transmittance) : std::string())
                    << std::endl;
        }
      }
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    const double z = variance[c] > 0.0 ? difference[c] / std::sqrt(variance[c]) : 0.0;
    s.Global = std::abs(z) > std::abs(s.Global) ? z : s.Global;
  }
  s.MeanZ2 = s.Count ? z2 / s.Count : 0.0;
  return s;
}

inline void Report(const Stats& s, const std::string& what)
{
  std::cout << what << ": image sums " << s.Sum[0] << " vs " << s.Sum[1] << ", global z "
            << s.Global << ", mean z^2 " << s.MeanZ2 << " over " << s.Count << ", max |z| "
            << s.MaxZ << std::endl;
}

// The bounds of an unbiased comparison: |global z| < 4.5 (each channel), mean z^2 within
// [0.75, 1.3] (its standard deviation is about sqrt(2 / Count), 0.03 over
// the ~1700 values of a 24 x 24 image), and max |z| < 6.5 (heavy-tailed
// estimates allowed for); at least `count` values.
inline void CheckUnbiased(const Stats& s, const std::string& what, int count = 500)
{
  Report(s, what);
  tyndall_test::Check(s.Count > count, what + ": enough non-empty pixels");
  tyndall_test::Check(std::abs(s.Global) < 4.5, what + ": global z");
  tyndall_test::Check(s.MeanZ2 > 0.75 && s.MeanZ2 < 1.3, what + ": mean z^2");
  tyndall_test::Check(s.MaxZ < 6.5, what + ": max |z|");
}

// TYNDALL_PATH_TRACER_QUICK set and not "0" (the sanitizer suite, set in
// Testing/Cxx/CMakeLists.txt for the CPU path tracer's tests): every render
// with a sixteenth of its samples, and what is a statistic reported, not
// checked (with so few samples per pixel the standard errors are too rough
// for the bounds: false alarms). The same code runs; the Release suite
// checks every statistic.
inline bool PathTracerQuick()
{
  const char* quick = std::getenv("TYNDALL_PATH_TRACER_QUICK");
  return quick && std::string(quick) != "0";
}

// `samples`, or in the quick mode a sixteenth of them (at least 4).
inline int PathTracerSamples(int samples)
{
  return PathTracerQuick() ? std::max(4, samples / 16) : samples;
}

// A statistical check: Check(), or in the quick mode a line that says so.
inline void CheckStatistic(bool ok, const std::string& what)
{
  if (PathTracerQuick())
  {
    std::cout << "  (quick: not checked) " << what << (ok ? "" : " would fail") << std::endl;
    return;
  }
  tyndall_test::Check(ok, what);
}

// CheckUnbiased(); in the quick mode its z bounds reported, not checked, and
// what is not a statistic checked: at least `count` values with a z, finite
// sums and z.
inline void CheckPictureUnbiased(const Stats& s, const std::string& what, int count = 500)
{
  if (!PathTracerQuick())
  {
    CheckUnbiased(s, what, count);
    return;
  }
  Report(s, what + " (quick: z bounds not checked)");
  tyndall_test::Check(s.Count > count, what + ": enough non-empty pixels");
  tyndall_test::Check(std::isfinite(s.Sum[0]) && std::isfinite(s.Sum[1]) && std::isfinite(s.Global),
    what + ": finite radiance");
}
}

#endif
