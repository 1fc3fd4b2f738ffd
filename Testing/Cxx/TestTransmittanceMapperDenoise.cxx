// The path-traced picture's denoiser (vtkTransmittanceVolumeMapper::
// PathTraceDenoise) on the GPU against its CPU twin, vtkTyndallDenoiser,
// and against the converged picture, in a float frame buffer (linear, over
// black with a transparent clear: the pixels are the mapper's premultiplied
// radiance and opacity).
// - the guide: the map-based frame (PathTracing off);
// - the converged picture: 1024 samples per pixel, another seed;
// - at 4, 16 and 64 samples per pixel: the mean M (denoiser off), then the
//   denoiser turned on keeps the samples and shows D; D must be the twin's
//   Filter(M, guide) (float arithmetic: within 1e-4 of the guide's largest
//   value; measured 3.6e-7) and nearer the converged picture than M by 3 dB
//   at least (measured: 4 spp 13.99 -> 26.32 dB, 16 spp 20.33 -> 27.99, 64
//   spp 25.84 -> 29.94); turned off again, M bit for bit;
// - the denoiser on from the paths' start, then the camera turned: the
//   denoised picture is the twin's with the new view's guide.
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDenoiser.h"

#include "TyndallTestCheck.h"
#include "TyndallTestFloatFrame.h"
#include "TyndallTestPathScene.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;
// The root mean square difference of the colour channels.
double RMS(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return 1e30;
  }
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (i % 4 != 3)
    {
      sum += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    }
  }
  return std::sqrt(sum / (a.size() * 3 / 4));
}

double Decibels(double rms, double peak)
{
  return 20.0 * std::log10(peak / std::max(rms, 1e-30));
}
}

int TestTransmittanceMapperDenoise(int, char*[])
{
  const int size = 64;
  tyndall_test::PathScene scene(tyndall_test::MakeCloud(32), 0.8, size);
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Renderer->SetBackgroundAlpha(0.0);
  tyndall_test::FloatFrame frame(scene.Renderer, scene.Window);
  vtkTransmittanceVolumeMapper* mapper = scene.Mapper;
  Check(!mapper->GetPathTraceDenoise(), "the denoiser is off by default");

  mapper->PathTracingOff();
  const std::vector<float> guide = frame.Render();
  double peak = 0.0;
  for (size_t i = 0; i < guide.size(); ++i)
  {
    peak = std::max(peak, double(guide[i]));
  }

  mapper->SetPathTraceSeed(1);
  Check(scene.Trace(1024) == 1024, "the converged picture has 1024 samples per pixel");
  const std::vector<float> converged = frame.Render();
  mapper->SetPathTraceSeed(0);
  std::cout << "the map-based frame against the converged picture: "
            << Decibels(RMS(guide, converged), peak) << " dB (peak " << peak << ")\n";

  for (int samples : { 4, 16, 64 })
  {
    std::ostringstream what;
    what << samples << " samples per pixel";
    Check(scene.Trace(samples) == samples, what.str() + ": the paths reach them");
    const std::vector<float> mean = frame.Render();
    mapper->PathTraceDenoiseOn();
    const std::vector<float> shown = frame.Render();
    Check(mapper->GetLastPathTraceSamples() == samples,
      what.str() + ": turning the denoiser on keeps the samples");
    std::vector<float> twin(mean.size());
    Check(vtkTyndallDenoiser::Filter(mean.data(), guide.data(), size, size,
            vtkTyndallDenoiser::DefaultIterations, vtkTyndallDenoiser::EdgeStopFor(samples),
            twin.data()),
      what.str() + ": the twin filters");
    double worst = shown.size() == twin.size() ? 0.0 : 1e30;
    for (size_t i = 0; i < twin.size() && worst < 1e30; ++i)
    {
      worst = std::max(worst, std::abs(double(shown[i]) - twin[i]) / peak);
    }
    const double raw = Decibels(RMS(mean, converged), peak);
    const double denoised = Decibels(RMS(shown, converged), peak);
    const double twinDb = Decibels(RMS(twin, converged), peak);
    std::cout << what.str() << ": the mean " << raw << " dB, denoised " << denoised
              << " dB (the twin " << twinDb << " dB); GPU against the twin " << worst << "\n";
    Check(worst < 1e-4, what.str() + ": the GPU's denoiser is the twin's");
    Check(denoised > raw + 3.0,
      what.str() + ": the denoised picture is nearer the converged one (by 3 dB at least)");
    mapper->PathTraceDenoiseOff();
    Check(frame.Render() == mean, what.str() + ": turned off, the mean again");
  }

  // The denoiser on from the paths' start, then the camera turned: the
  // paths and the guide start again for the new view (the twin filters the
  // new mean with the new map-based frame).
  mapper->PathTraceDenoiseOn();
  Check(scene.Trace(16) == 16, "denoised from the start: 16 samples per pixel");
  scene.Renderer->GetActiveCamera()->Azimuth(40.0);
  mapper->PathTracingOff();
  const std::vector<float> turnedGuide = frame.Render();
  Check(scene.Trace(16) == 16, "the turned view: 16 samples per pixel");
  const std::vector<float> turnedShown = frame.Render();
  mapper->PathTraceDenoiseOff();
  const std::vector<float> turnedMean = frame.Render();
  std::vector<float> turnedTwin(turnedMean.size());
  vtkTyndallDenoiser::Filter(turnedMean.data(), turnedGuide.data(), size, size,
    vtkTyndallDenoiser::DefaultIterations, vtkTyndallDenoiser::EdgeStopFor(16), turnedTwin.data());
  double worst = turnedShown.size() == turnedTwin.size() ? 0.0 : 1e30;
  for (size_t i = 0; i < turnedTwin.size() && worst < 1e30; ++i)
  {
    worst = std::max(worst, std::abs(double(turnedShown[i]) - turnedTwin[i]) / peak);
  }
  std::cout << "the turned view, denoised from the start: GPU against the twin " << worst
            << " (the two views' guides differ by " << Decibels(RMS(guide, turnedGuide), peak)
            << " dB)\n";
  Check(worst < 1e-4, "a moved view: the denoiser's guide is the new view's");
  mapper->PathTracingOff();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
