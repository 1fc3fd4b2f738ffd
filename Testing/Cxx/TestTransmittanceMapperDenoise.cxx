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

// The largest difference of two pictures' values over `peak` (1e30: not the same size).
double Largest(const std::vector<float>& a, const std::vector<float>& b, double peak)
{
  double worst = a.size() == b.size() ? 0.0 : 1e30;
  for (size_t i = 0; i < a.size() && worst < 1e30; ++i)
  {
    worst = std::max(worst, std::abs(double(a[i]) - b[i]) / peak);
  }
  return worst;
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
    const double worst = Largest(shown, twin, peak);
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

  // The denoiser on from the paths' start: the map-based frame drawn when
  // they start (full size, marched) is drawn as the guide, the same
  // picture as without the denoiser (there drawn direct: one pass), and the
  // paths draw no guide again. Grey, then with the display transform over a
  // grey background, then a coloured extinction (composited per channel:
  // over black the channels' opacities would not show).
  mapper->PathTracingOn();
  const int guides = mapper->GetPathTraceGuideRenderCount();
  int direct = 0;
  auto startDifference = [&]()
  {
    mapper->PathTraceDenoiseOn();
    mapper->ResetAccumulation();
    const std::vector<float> asGuide = frame.Render();
    mapper->PathTraceDenoiseOff();
    mapper->ResetAccumulation();
    const std::vector<float> drawn = frame.Render();
    direct += mapper->GetLastRayCastPassCount() == 1 ? 1 : 0;
    return Largest(asGuide, drawn, peak);
  };
  const double greyWorst = startDifference();
  scene.Renderer->SetBackground(0.4, 0.4, 0.4); // (102 / 255: a whole 8-bit level)
  scene.Renderer->SetBackgroundAlpha(1.0);
  mapper->SetExposure(0.5);
  mapper->SetToneCurveToACES();
  mapper->EncodeSRGBOn();
  const double displayWorst = startDifference();
  mapper->SetExposure(0.0);
  mapper->SetToneCurveToLinear();
  mapper->EncodeSRGBOff();
  scene.Property->SetExtinctionColor(0.25, 0.6, 1.0);
  const double chromaticWorst = startDifference();
  scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Renderer->SetBackgroundAlpha(0.0);
  const int startGuides = mapper->GetPathTraceGuideRenderCount() - guides;
  mapper->PathTraceDenoiseOn();
  Check(scene.Trace(16) == 16, "denoised from the start: 16 samples per pixel");
  const int traceGuides = mapper->GetPathTraceGuideRenderCount() - guides - startGuides;
  std::cout << "the paths' start, denoised: the map-based frame drawn as the guide against "
               "drawn without the denoiser, largest difference "
            << greyWorst << " (with exposure, ACES and sRGB over grey " << displayWorst
            << ", a coloured extinction " << chromaticWorst << "; " << direct
            << " of 3 drawn in one pass, the grey ones direct); guides drawn: at 3 starts "
            << startGuides << ", by a new start and 16 spp of paths " << traceGuides << "\n";
  Check(startGuides == 3 && direct == 3 && greyWorst < 1e-6 && displayWorst < 1e-6 &&
      chromaticWorst < 1e-6,
    "the map-based frame at the paths' start is drawn as the guide, the same picture");
  Check(traceGuides == 1, "the paths take the guide drawn at their start");

  // Then the camera turned: the paths and the guide start again for the new
  // view (the twin filters the new mean with the new map-based frame).
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
  const double worst = Largest(turnedShown, turnedTwin, peak);
  std::cout << "the turned view, denoised from the start: GPU against the twin " << worst
            << " (the two views' guides differ by " << Decibels(RMS(guide, turnedGuide), peak)
            << " dB)\n";
  Check(worst < 1e-4, "a moved view: the denoiser's guide is the new view's");
  mapper->PathTracingOff();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
