// The footprint filter of procedural detail (issue 39) on the CPU, the
// oracle the GPU's camera rays are compared with:
//
// 1. vtkTyndallFootprint: the world width of a pixel at a point equals the
//    distance between the unprojections of two neighbouring pixel centres
//    at that point's depth (the camera's composite projection matrix),
//    perspective (vertical and horizontal view angle) and parallel;
// 2. the waves are sorted by world wave number, their world |k|^2 is the
//    squared gradient of their phase in world coordinates (finite
//    differences through the rotated, anisotropically spaced, translated
//    image), and each group of four is filtered at its level, the largest
//    K0 x 1.5^n at or below its coarsest wave's |k|^2 (no wave more than its
//    own Gaussian asks; also with one direction, where a group spans four
//    octaves);
// 3. a single wave filtered by the Gaussian of sigma = width x pixel equals
//    the noise convolved with that Gaussian in world space (a trapezoid rule
//    in three dimensions, spectrally accurate for it), to 1e-9;
// 4. the cutoff: GetLiveWaves() is the count of waves whose factor is at
//    least FilterCutoff, and FilteredNoise() is the sum over them;
// 5. GetCameraStep(): the midpoint rule's bound at the returned step is
//    within StepTolerance, and 5% longer it is not (unless capped at half
//    the spacing or half the finest wavelength).
// 6. Steps that span waves: StepMeanNoise() equals Simpson's rule of
//    FilteredNoise() along the step (spans of 0.05 to 8 index units in any
//    direction), to 1e-7 of the noise's range; GetClampShare() agrees with
//    the share measured at random points (from 15 % below to 30 % above:
//    measured 0.4 % to 22 % above far out, where the bounded waves' tail is
//    lighter than the Gaussian's; 0 for a noise that cannot dip below 0); GetCameraStep() spans the
//    waves (half the lighting width) only with the filter on, a negligible clamp and maps, and
//    where that is longer than the waves' own step.
//
// Costs about 1.1 s.
#include "vtkCamera.h"
#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallFootprint.h"
#include "vtkTyndallGridMedium.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestDetailScene.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

using Scene = tyndall_test::DetailScene;

// The world point of normalised device coordinates (x, y, z).
void Unproject(const double inverse[16], double x, double y, double z, double world[3])
{
  const double in[4] = { x, y, z, 1.0 };
  double out[4];
  vtkMatrix4x4::MultiplyPoint(inverse, in, out);
  for (int c = 0; c < 3; ++c)
  {
    world[c] = out[c] / out[3];
  }
}

void TestFootprint()
{
  const int width = 160, height = 100;
  for (int kind = 0; kind < 3; ++kind)
  {
    vtkNew<vtkCamera> camera;
    camera->SetPosition(1.0, 2.0, 6.0);
    camera->SetFocalPoint(0.2, -0.1, 0.3);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(35.0);
    camera->SetUseHorizontalViewAngle(kind == 1);
    camera->SetParallelProjection(kind == 2);
    camera->SetParallelScale(1.7);
    camera->SetClippingRange(0.5, 20.0);
    vtkTyndallFootprint footprint;
    Check(footprint.SetCamera(camera, width, height), "the footprint reads the camera");
    double inverse[16];
    vtkMatrix4x4::Invert(
      camera->GetCompositeProjectionTransformMatrix(double(width) / height, -1.0, 1.0)->GetData(),
      inverse);
    double worst = 0.0;
    for (const double z : { -0.9, 0.0, 0.7 })
    {
      // The centre pixel and its right-hand neighbour at one depth.
      double a[3], b[3];
      Unproject(inverse, 1.0 / width, 1.0 / height, z, a);
      Unproject(inverse, 3.0 / width, 1.0 / height, z, b);
      const double measured = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      worst = std::max(worst, std::abs(footprint.At(a) / measured - 1.0));
    }
    const char* names[3] = { "perspective", "horizontal view angle", "parallel" };
    std::cout << names[kind] << ": pixel width against unprojected pixel centres, worst " << worst
              << " relative\n";
    Check(
      worst < 1e-3, std::string("the footprint is a pixel's world width (") + names[kind] + ")");
  }
  vtkTyndallFootprint none;
  Check(!none.SetCamera(nullptr, 10, 10) && none.At(std::array<double, 3>{ 1, 2, 3 }.data()) == 0.0,
    "no camera: no footprint");
}

// The levels of the filter: group g of four is filtered with |k|^2 = K0
// 1.5^n, n the largest level at or below its first (coarsest) wave's |k|^2,
// K0 the coarsest wave's (`ok` false where a wave is not). Returns the number
// of levels the groups use.
int CountLevels(const std::vector<vtkTyndallDetailMedium::Wave>& waves, bool& ok)
{
  double k0 = 0.0; // the coarsest positive |k|^2
  for (const auto& w : waves)
  {
    if (w.WorldK2 > 0.0)
    {
      k0 = w.WorldK2;
      break;
    }
  }
  if (!(k0 > 0.0))
  {
    ok = false;
    return 0;
  }
  const double ratio = vtkTyndallDetailMedium::FilterLevelRatio;
  int levels = 0, last = -1;
  for (size_t i = 0; i < waves.size(); ++i)
  {
    const double first = waves[i / 4 * 4].WorldK2;
    int n = 0;
    while (k0 * std::pow(ratio, n + 1) <= first)
    {
      ++n;
    }
    const double k2 = k0 * std::pow(ratio, n);
    ok = ok && waves[i].FilterLevel == n && std::abs(waves[i].FilterK2 / k2 - 1.0) < 1e-12 &&
      waves[i].FilterK2 <= waves[i].WorldK2;
    if (n != last)
    {
      ++levels;
      last = n;
    }
  }
  return levels;
}

void TestWaves()
{
  Scene scene(24, 3, 0.5);
  const auto& waves = scene.Detail.GetWaves();
  bool sorted = true, groups = true;
  double worstK2 = 0.0;
  const int skewedLevels = CountLevels(waves, groups);
  // vtkCosineNoise's directions are 0.8 to 1.2 long: 3 octaves' |k|^2 span
  // up to 16 x 2.25 = 1.5^8.8, at most 9 levels (without the actor's
  // anisotropic scale: the image's rotation and spacing do not change the
  // noise, which lives in data coordinates; 18 groups of four).
  Scene isotropic(24, 3, 0.5);
  isotropic.Volume->SetScale(1.0);
  isotropic.Update(0.5);
  const int isotropicLevels = CountLevels(isotropic.Detail.GetWaves(), groups);
  std::cout << "24 directions x 3 octaves: " << isotropicLevels << " levels of the filter ("
            << skewedLevels << " under the anisotropic scale)\n";
  for (size_t i = 0; i < waves.size(); ++i)
  {
    sorted = sorted && (i == 0 || waves[i - 1].WorldK2 <= waves[i].WorldK2);
    // Filtered at its group's level: never more than its own Gaussian asks
    // (or 0 below the cutoff), the group's first wave within a level of it.
    const double coarsest = waves[i].FilterK2;
    groups =
      groups && waves[i / 4 * 4].WorldK2 < vtkTyndallDetailMedium::FilterLevelRatio * coarsest;
    const double sigma = 0.1;
    const double factor = std::exp(-0.5 * coarsest * sigma * sigma);
    const double f = scene.Detail.FilterFactor(static_cast<int>(i), sigma);
    groups = groups &&
      std::abs(f - (factor >= vtkTyndallDetailMedium::FilterCutoff ? factor : 0.0)) <= 1e-12 &&
      (f == 0.0 || f >= std::exp(-0.5 * waves[i].WorldK2 * sigma * sigma));
    // |grad_x (k . p(x))|^2 by central differences in world space.
    const double x[3] = { 0.1, -0.2, 0.3 };
    double k2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] }, pp[3], pm[3];
      xp[a] += 1e-4;
      xm[a] -= 1e-4;
      scene.ToIndex(xp, pp);
      scene.ToIndex(xm, pm);
      const double phaseDifference = waves[i].K[0] * (pp[0] - pm[0]) +
        waves[i].K[1] * (pp[1] - pm[1]) + waves[i].K[2] * (pp[2] - pm[2]);
      k2 += std::pow(phaseDifference / 2e-4, 2);
    }
    worstK2 = std::max(worstK2, std::abs(k2 / waves[i].WorldK2 - 1.0));
  }
  // One direction x 4 octaves: one group spanning the octaves, filtered
  // by its coarsest wave.
  Scene spanning(1, 4, 0.5);
  const auto& few = spanning.Detail.GetWaves();
  for (size_t i = 0; i < few.size(); ++i)
  {
    for (const double sigma : { 0.05, 0.2, 1.0 })
    {
      const double f = spanning.Detail.FilterFactor(static_cast<int>(i), sigma);
      groups = groups &&
        (f == 0.0 ? std::exp(-0.5 * few[0].WorldK2 * sigma * sigma) < 0.01
                  : f >= std::exp(-0.5 * few[i].WorldK2 * sigma * sigma));
    }
  }
  std::cout << "world |k|^2 against the phase's gradient: worst " << worstK2 << " relative\n";
  Check(waves.size() == 72 && sorted, "the waves are sorted by world wave number");
  Check(isotropicLevels >= 6 && isotropicLevels <= 9,
    "24 directions x 3 octaves use six to nine levels of the filter");
  Check(skewedLevels < 18, "the groups share levels under an anisotropic scale too");
  Check(groups, "each group is filtered at the level of its coarsest wave's |k|^2");
  Check(worstK2 < 1e-6, "world |k|^2 is the squared gradient of the phase in world space");
}

void TestGaussian()
{
  Scene scene(1, 1, 0.8);
  const double pixel = 0.45;
  const double sigma = 0.8 * pixel;
  const auto& wave = scene.Detail.GetWaves().at(0);
  std::cout << "one wave, |k| sigma = " << std::sqrt(wave.WorldK2) * sigma << "\n";
  double worst = 0.0;
  const double points[2][3] = { { 0.1, -0.2, 0.3 }, { -0.4, 0.5, 0.05 } };
  for (const double* x : points)
  {
    // The Gaussian convolution in world space: a trapezoid rule over
    // [-8 sigma, 8 sigma]^3 (spectrally accurate for a Gaussian times a wave).
    const int n = 64;
    const double h = 16.0 * sigma / n;
    double sum = 0.0, weights = 0.0;
    for (int i = 0; i <= n; ++i)
    {
      for (int j = 0; j <= n; ++j)
      {
        for (int k = 0; k <= n; ++k)
        {
          const double u[3] = { -8 * sigma + i * h, -8 * sigma + j * h, -8 * sigma + k * h };
          const double g =
            std::exp(-(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) / (2 * sigma * sigma));
          const double y[3] = { x[0] + u[0], x[1] + u[1], x[2] + u[2] };
          double p[3];
          scene.ToIndex(y, p);
          sum += g * scene.Detail.Noise(p);
          weights += g;
        }
      }
    }
    double p[3];
    scene.ToIndex(x, p);
    worst = std::max(worst, std::abs(sum / weights - scene.Detail.FilteredNoise(p, pixel)));
  }
  std::cout << "filtered wave against its Gaussian convolution: worst " << worst << "\n";
  Check(worst < 1e-9, "a filtered wave is the wave convolved with the Gaussian of the footprint");
}

void TestCutoff()
{
  Scene scene(24, 4, 0.5);
  const vtkTyndallDetailMedium& detail = scene.Detail;
  const int n = static_cast<int>(detail.GetWaves().size());
  const double x[3] = { 0.2, 0.1, -0.1 };
  double p[3];
  scene.ToIndex(x, p);
  int cut = 0;
  double worst = 0.0;
  for (double pixel = 0.0; pixel < 2.0; pixel += 0.01)
  {
    const int live = detail.GetLiveWaves(pixel);
    const double sigma = 0.5 * pixel;
    bool consistent = live == n || detail.FilterFactor(live, sigma) == 0.0;
    consistent = consistent && (live == 0 || detail.FilterFactor(live - 1, sigma) >= 0.01);
    double sum = detail.GetOffset();
    for (int i = 0; i < live; ++i)
    {
      const auto& w = detail.GetWaves()[i];
      sum += detail.FilterFactor(i, sigma) * w.Amplitude *
        std::cos(w.K[0] * p[0] + w.K[1] * p[1] + w.K[2] * p[2] + w.Phase);
    }
    worst = std::max(worst, std::abs(sum - detail.FilteredNoise(p, pixel)));
    cut += live < n ? 1 : 0;
    if (!consistent)
    {
      Check(false, "GetLiveWaves() keeps exactly the waves above the cutoff");
      break;
    }
  }
  std::cout << "cutoff: " << cut << " of 200 footprints leave waves out; filtered noise against "
            << "the sum over the live waves: worst " << worst << "\n";
  Check(cut > 100 && worst < 1e-12, "the filtered noise is the sum over the live waves");
  Check(detail.GetLiveWaves(0.0) == n &&
      std::abs(detail.FilteredNoise(p, 0.0) - detail.Noise(p)) == 0.0,
    "an empty footprint filters nothing");
}

void TestCameraStep()
{
  for (const double gain : { 0.5, 0.9 })
  {
    Scene scene(24, 4, 0.5);
    scene.Noise->SetGain(gain);
    scene.Update(0.5);
    const vtkTyndallDetailMedium& detail = scene.Detail;
    double sum = 0.0;
    for (const auto& w : detail.GetWaves())
    {
      sum += std::abs(w.Amplitude);
    }
    for (const double pixel : { 0.0, 0.02, 0.2 })
    {
      const int live = detail.GetLiveWaves(pixel);
      auto bound = [&](double h)
      {
        double e = 0.0;
        for (int i = 0; i < live; ++i)
        {
          const auto& w = detail.GetWaves()[i];
          const double a = 0.5 * std::sqrt(w.WorldK2) * h;
          e += std::abs(w.Amplitude) * (1.0 - std::sin(a) / a);
        }
        return e / sum;
      };
      const double cap = std::min(1.0, 0.5 * detail.GetFinestWavelength(live));
      const double h = detail.GetCameraStep(pixel, 1.0);
      const bool capped = h >= cap * (1 - 1e-12);
      std::cout << "gain " << gain << ", pixel " << pixel << ": step " << h << " ("
                << detail.GetFinestWavelength(live) / h << " per finest wavelength), bound "
                << bound(h) << (capped ? ", capped" : "") << "\n";
      Check(h > 0.0 && h <= cap * (1 + 1e-12) &&
          bound(h) <= vtkTyndallDetailMedium::StepTolerance * (1 + 1e-9) &&
          (capped || bound(1.05 * h) > vtkTyndallDetailMedium::StepTolerance),
        "the camera step is the longest within the midpoint rule's tolerance");
    }
  }
}

void TestStepMeans()
{
  Scene scene(24, 4, 0.5);
  scene.Noise->SetAmplitude(0.5);
  scene.Noise->SetOffset(1.0);
  scene.Update(0.5);
  const vtkTyndallDetailMedium& detail = scene.Detail;
  double range = std::abs(detail.GetOffset());
  for (const auto& w : detail.GetWaves())
  {
    range += std::abs(w.Amplitude);
  }
  std::mt19937 random(39);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 24; ++trial)
  {
    const double p[3] = { 4.0 + 3.0 * unit(random), 4.0 + 3.0 * unit(random),
      4.0 + 3.0 * unit(random) };
    double d[3] = { unit(random), unit(random), unit(random) };
    vtkMath::Normalize(d);
    const double length = 0.05 * std::pow(160.0, (trial % 8) / 7.0); // 0.05 .. 8
    const double span[3] = { length * d[0], length * d[1], length * d[2] };
    const double pixel = trial < 12 ? 0.0 : 0.02;
    const int n = 20000; // Simpson's rule, even
    double integral = 0.0;
    for (int i = 0; i <= n; ++i)
    {
      const double u = static_cast<double>(i) / n - 0.5;
      const double q[3] = { p[0] + u * span[0], p[1] + u * span[1], p[2] + u * span[2] };
      const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      integral += weight * detail.FilteredNoise(q, pixel);
    }
    const double mean = integral / (3.0 * n);
    worst = std::max(worst, std::abs(detail.StepMeanNoise(p, pixel, span) - mean) / range);
  }
  std::cout << "step means against Simpson's rule: worst " << worst << " of the noise's range\n";
  Check(worst < 1e-7, "a step's mean of the waves is their integral over it");

  // The clamp's share: estimated against measured at random points, for
  // offsets of 2.6, 2 and 1.4 standard deviations of the noise.
  double variance = 0.0;
  for (const auto& w : detail.GetWaves())
  {
    variance += 0.5 * w.Amplitude * w.Amplitude;
  }
  const double deviation = std::sqrt(variance);
  for (const double offset : { 2.6 * deviation, 2.0 * deviation, 1.4 * deviation })
  {
    scene.Noise->SetOffset(offset);
    scene.Update(0.5);
    double negative = 0.0, positive = 0.0;
    const int samples = 100000;
    for (int i = 0; i < samples; ++i)
    {
      const double q[3] = { 50.0 * unit(random), 50.0 * unit(random), 50.0 * unit(random) };
      const double value = detail.Noise(q);
      (value < 0.0 ? negative : positive) += std::abs(value);
    }
    const double measured = negative / positive;
    const double estimated = detail.GetClampShare();
    std::cout << "clamp share, offset " << offset << ": estimated " << estimated << ", measured "
              << measured << "\n";
    // A sum of bounded waves has lighter tails than the Gaussian: far out
    // the estimate is the larger (the safe side).
    Check(estimated >= 0.85 * measured && estimated <= 1.3 * measured,
      "the clamp's share is the Gaussian estimate of the noise's");
  }
  scene.Noise->SetOffset(0.0);
  scene.Noise->SetOffset(-scene.Noise->GetMinimumValue());
  scene.Update(0.5);
  Check(detail.GetClampShare() == 0.0, "a noise that cannot dip below 0 has no clamp");

  // The step's choice.
  const double pixel = 0.001, spacing = 1.0;
  const double waves = detail.GetWaveStep(pixel, spacing);
  const double light = 40.0 * waves; // a map texel 40 wave steps wide
  const double spanning = detail.GetCameraStep(pixel, spacing, light);
  std::cout << "camera step: the waves' " << waves << ", with maps " << spanning << "\n";
  Check(detail.UsesStepMeans(pixel, spacing, light) && spanning == std::min(spacing, 20.0 * waves),
    "with maps the step follows the maps and the shape");
  Check(!detail.UsesStepMeans(pixel, spacing, 0.0) &&
      detail.GetCameraStep(pixel, spacing, 0.0) == waves,
    "a brute-force light's step resolves the waves");
  Check(!detail.UsesStepMeans(pixel, spacing, waves) &&
      detail.GetCameraStep(pixel, spacing, waves) == waves,
    "maps finer than the waves' step leave it");
  scene.Noise->SetOffset(1.4 * deviation);
  scene.Update(0.5);
  Check(detail.GetClampShare() > vtkTyndallDetailMedium::ClampTolerance &&
      detail.GetCameraStep(pixel, spacing, light) == detail.GetWaveStep(pixel, spacing),
    "a noise that often dips below 0 keeps the waves' step");
  scene.Noise->SetOffset(0.0);
  scene.Noise->SetOffset(-scene.Noise->GetMinimumValue());
  scene.Update(0.0);
  Check(detail.GetCameraStep(pixel, spacing, light) == detail.GetWaveStep(pixel, spacing),
    "the unfiltered march resolves the waves");
}
}

int TestTyndallFootprintFilter(int, char*[])
{
  TestFootprint();
  TestWaves();
  TestGaussian();
  TestCutoff();
  TestCameraStep();
  TestStepMeans();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
