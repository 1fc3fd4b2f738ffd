// The footprint filter's factors as the GPU computes them (CPU, no
// OpenGL): vtkTransmittanceDetailFS.glsl's TYNDALL_DETAIL_FILTERED_GROUP
// re-done in float from the adapter's constants (detailLevelSteps:
// vtkTransmittanceDetailAdapter::LevelSteps(); detailDecay as
// WaveConstants() writes it): an exp2 where a group takes its own, e sqrt(e)
// per level climbed, 0 below the cutoff. Against the CPU twin's
// vtkTyndallDetailMedium::FilterFactor() (double) for every group and
// several pixel widths:
//
// 1. the default noise (6 octaves x 24 directions, 144 waves): every factor
//    within 1e-4 of the CPU's, relative, and 0 exactly where the CPU's is;
// 2. ten octaves x 24 directions (240 waves, 33 levels): the same,
//    which needs the chain restarted (MaximumChainedLevels: a factor that
//    rounds to 1 in float stays 1 up the chain, and the error grows 1.5x a
//    level);
// 3. the steps: the first group takes an exponential, no climb is larger
//    than MaximumLevelSteps, no chain longer than MaximumChainedLevels.
#include "vtkTransmittanceDetailAdapter.h"
#include "vtkTyndallDetailMedium.h"

#include "TyndallTestCheck.h"
#include "TyndallTestDetailScene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

// The worst relative difference between the GPU's chain (float) and the
// CPU's factors over the groups, for a pixel `pixel` wide; `zeros` false
// where one is 0 and the other not (beyond rounding at the cutoff).
double Compare(const vtkTyndallDetailMedium& detail, double pixel, bool& zeros)
{
  const auto& waves = detail.GetWaves();
  const std::vector<int> steps = vtkTransmittanceDetailAdapter::LevelSteps(detail);
  const double width = detail.GetFilterWidth();
  const float pixel2 = static_cast<float>(pixel) * static_cast<float>(pixel);
  const float cutoff = static_cast<float>(vtkTyndallDetailMedium::FilterCutoff);
  float e = 1.0f;
  double worst = 0.0;
  for (size_t g = 0; g < steps.size(); ++g)
  {
    const size_t i = 4 * g;
    const float decay = vtkTransmittanceDetailAdapter::FilterDecay(detail, static_cast<int>(g));
    if (steps[g] > vtkTransmittanceDetailAdapter::MaximumLevelSteps)
    {
      e = std::exp2(decay * pixel2);
    }
    else
    {
      for (int s = 0; s < steps[g]; ++s)
      {
        e *= std::sqrt(e);
      }
    }
    const float f = e >= cutoff ? e : 0.0f;
    const double cpu = detail.FilterFactor(static_cast<int>(i), width * pixel);
    if ((f == 0.0f) != (cpu == 0.0))
    {
      // Only at the cutoff, within rounding.
      const double exact = std::exp(-0.5 * waves[i].FilterK2 * width * width * pixel * pixel);
      zeros = zeros && std::abs(exact / vtkTyndallDetailMedium::FilterCutoff - 1.0) < 1e-4;
      continue;
    }
    if (cpu > 0.0)
    {
      worst = std::max(worst, std::abs(f / cpu - 1.0));
    }
  }
  return worst;
}

void CheckNoise(int octaves)
{
  tyndall_test::DetailScene scene(24, octaves, 0.5);
  const vtkTyndallDetailMedium& detail = scene.Detail;
  const std::vector<int> steps = vtkTransmittanceDetailAdapter::LevelSteps(detail);
  bool valid = !steps.empty() && steps[0] > vtkTransmittanceDetailAdapter::MaximumLevelSteps;
  int chained = 0, exponentials = 0;
  for (const int s : steps)
  {
    if (s > vtkTransmittanceDetailAdapter::MaximumLevelSteps)
    {
      chained = 0;
      ++exponentials;
    }
    else
    {
      chained += s;
      valid = valid && s >= 0 && chained <= vtkTransmittanceDetailAdapter::MaximumChainedLevels;
    }
  }
  const auto& waves = detail.GetWaves();
  const int levels = waves.back().FilterLevel - waves.front().FilterLevel;
  // Pixels from where the finest wave keeps nearly all of its amplitude to
  // where only the coarsest octave is left.
  double worst = 0.0;
  bool zeros = true;
  const double finest = std::sqrt(waves.back().WorldK2);
  for (double kSigma = 0.001; kSigma < 100.0; kSigma *= 1.37)
  {
    worst = std::max(worst, Compare(detail, kSigma / (finest * 0.5), zeros));
  }
  const std::string name = std::to_string(octaves) + " octaves";
  std::cout << name << ": " << steps.size() << " groups, levels " << levels << ", " << exponentials
            << " exponentials per sample; GPU chain against the CPU's factors: " << worst
            << " relative\n";
  Check(valid, name + ": the steps start with an exponential and stay within their bounds");
  Check(worst < 1e-4, name + ": the GPU's factors are the CPU's");
  Check(zeros, name + ": the GPU drops the groups the CPU drops");
}
}

int TestTransmittanceDetailFilterChain(int, char*[])
{
  CheckNoise(6);
  CheckNoise(10);
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
