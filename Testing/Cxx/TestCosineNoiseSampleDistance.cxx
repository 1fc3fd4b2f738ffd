// vtkCosineNoise::SampleDistance inverts the closed-form optical depth:
// for random rays and targets the depth to the returned distance equals the
// target; unreachable targets report an escape; signed noise finds the first
// crossing on its scan grid.
#include "TyndallTestCheck.h"
#include "vtkCosineNoise.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>
#include <iostream>
#include <random>

namespace
{
using tyndall_test::Check;
}

int TestCosineNoiseSampleDistance(int, char*[])
{
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> u01(0.0, 1.0);

  // Non-negative noise: the cumulative depth is monotone.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(5);
    noise->SetOffset(0.0);
    noise->SetOffset(-noise->GetMinimumValue() + 0.5);
    noise->SetExtinctionScale(0.7);
    double worst = 0.0;
    int reached = 0, escaped = 0;
    bool ok = true;
    for (int r = 0; r < 3000; ++r)
    {
      double o[3] = { u(rng), u(rng), u(rng) };
      double w[3] = { u(rng), u(rng), u(rng) };
      if (vtkMath::Norm(w) < 1e-3)
      {
        continue;
      }
      const double t0 = u(rng), t1 = t0 + 2.0 * u01(rng) + 1e-3;
      const double total = noise->ComputeOpticalDepth(o, w, t0, t1);
      // Targets mostly inside the segment, some beyond it.
      const double target = total * 1.1 * u01(rng);
      double t = -1.0;
      const int status = noise->SampleDistance(o, w, t0, t1, target, t);
      if (target <= total)
      {
        ok = ok && status == 1 && t >= t0 && t <= t1;
        const double depth = noise->ComputeOpticalDepth(o, w, t0, t);
        worst = std::max(worst, std::abs(depth - target) / std::max(1.0, target));
        ++reached;
      }
      else
      {
        ok = ok && status == 0 && t == t1;
        ++escaped;
      }
    }
    std::cout << "monotone: " << reached << " reached, " << escaped << " escaped, max depth error "
              << worst << "\n";
    Check(ok, "status and range of SampleDistance");
    Check(worst < 1e-9, "SampleDistance inverts ComputeOpticalDepth to 1e-9");
    Check(reached > 2000 && escaped > 50, "both outcomes exercised");

    double o[3] = { 0.0, 0.0, 0.0 }, w[3] = { 0.0, 0.0, 1.0 }, t = -1.0;
    Check(noise->SampleDistance(o, w, 0.5, 1.0, 0.0, t) == 1 && t == 0.5, "target 0 gives t0");
    // Exponential sampling as in the paper's Algorithm 2.
    const double zeta = 0.3;
    const double target = -std::log(1.0 - zeta);
    Check(noise->SampleDistance(o, w, 0.0, 100.0, target, t) == 1, "free-flight sample found");
    Check(std::abs(noise->ComputeTransmittance(o, w, 0.0, t) - (1.0 - zeta)) < 1e-12,
      "transmittance at the sample is 1 - zeta");
  }

  // Signed noise: the first crossing on the quarter-wavelength scan grid.
  {
    vtkNew<vtkCosineNoise> noise;
    noise->SetNumberOfOctaves(2);
    noise->SetOffset(3.0); // mostly positive, with negative pockets
    Check(noise->GetMinimumValue() < 0.0, "the signed case has negative values");
    double worst = 0.0;
    bool ok = true;
    int reached = 0;
    for (int r = 0; r < 500; ++r)
    {
      double o[3] = { u(rng), u(rng), u(rng) };
      double w[3] = { u(rng), u(rng), u(rng) };
      if (vtkMath::Norm(w) < 1e-3)
      {
        continue;
      }
      vtkMath::Normalize(w);
      const double t1 = 3.0;
      const double target = 2.0 * u01(rng);
      double t = -1.0;
      const int status = noise->SampleDistance(o, w, 0.0, t1, target, t);
      if (status == 1)
      {
        ++reached;
        const double depth = noise->ComputeIntegral(o, w, 0.0, t);
        worst = std::max(worst, std::abs(depth - target) / std::max(1.0, target));
        // No earlier point of a fine grid reaches the target by a margin.
        for (double s = 0.0; s < t - 1e-9; s += 1e-3)
        {
          ok = ok && noise->ComputeIntegral(o, w, 0.0, s) < target + 1e-6;
        }
      }
      else
      {
        ok = ok && status == 0 && t == t1;
      }
    }
    std::cout << "signed: " << reached << " reached, max depth error " << worst << "\n";
    Check(ok, "signed noise: first crossing, escapes reported");
    Check(worst < 1e-9, "signed noise: depth at the sample equals the target");
    Check(reached > 100, "signed noise: crossings exercised");
  }

  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
