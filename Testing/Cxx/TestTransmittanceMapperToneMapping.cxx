// The mapper's display transform (Exposure, ToneCurve, EncodeSRGB) on the GPU
// against its CPU twin, vtkTyndallToneMapping, pixel by pixel, in a float
// frame buffer (vtkFramebufferPass, RGBA32F). Each case renders the medium
// linear over black with a transparent clear (its radiance L and opacity
// a), the background alone (B, as VTK draws it), then the transformed
// picture over B; every pixel must be Map(L + (1 - a) Unmap(B)) (float
// arithmetic: within 1e-5 of display values; measured 2.5e-7). Checked:
// - the map-based frame drawn straight into the window (one pass, full
//   size), over black with +1.5 stops and the linear curve (values above 1
//   kept), over grey with Reinhard at -1 stop, over the sky's gradient with
//   ACES and sRGB;
// - the accumulated image's composite (a coloured extinction: the
//   background seen through each channel's transmittance, measured linear
//   over grey), ACES + sRGB;
// - the projection blend mode (maximum intensity), ACES + sRGB;
// - the path-traced picture with ACES and sRGB from its start (the history
//   stays linear), then a new exposure keeps its samples and maps the same
//   mean;
// - back to the defaults: the linear picture again, bit for bit.
#include "vtkFramebufferPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallToneMapping.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"
#include "TyndallTestFloatFrame.h"
#include "TyndallTestPathScene.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;
using tyndall_test::RenderFloat;
using Mapper = vtkTransmittanceVolumeMapper;

struct Transform
{
  double Exposure;
  int Curve;
  bool SRGB;
};

const Transform Identity{ 0.0, Mapper::TONE_CURVE_LINEAR, false };

void SetTransform(Mapper* mapper, const Transform& t)
{
  mapper->SetExposure(t.Exposure);
  mapper->SetToneCurve(t.Curve);
  mapper->SetEncodeSRGB(t.SRGB);
}

// The largest difference between `shown` and the twin's pixel for the
// medium `medium` (L, a over black) over `background`; counts the colour
// channels the medium lit (L above 0.01).
double Worst(const std::vector<float>& medium, const std::vector<float>& background,
  const std::vector<float>& shown, const Transform& t, int& lit)
{
  const size_t n = medium.size();
  double worst = shown.size() == n && background.size() == n ? 0.0 : 1e30;
  lit = 0;
  for (size_t i = 0; i + 3 < n && worst < 1e30; i += 4)
  {
    const double rgba[4] = { medium[i], medium[i + 1], medium[i + 2], medium[i + 3] };
    const double under[3] = { background[i], background[i + 1], background[i + 2] };
    double out[4], pixel[3];
    vtkTyndallToneMapping::MapOver(rgba, under, t.Exposure, t.Curve, t.SRGB, out, pixel);
    for (int k = 0; k < 3; ++k)
    {
      worst = std::max(worst, std::abs(shown[i + k] - pixel[k]));
      lit += medium[i + k] > 0.01f ? 1 : 0;
    }
  }
  return worst;
}

struct Bench
{
  tyndall_test::PathScene& Scene;
  vtkFramebufferPass* Pass;

  // The medium alone, linear: L and a (black, transparent clear).
  std::vector<float> Medium()
  {
    SetTransform(this->Scene.Mapper, Identity);
    this->Background(0.0, 0.0, 0.0, nullptr);
    this->Scene.Renderer->SetBackgroundAlpha(0.0);
    std::vector<float> medium = RenderFloat(this->Scene.Window, this->Pass);
    this->Scene.Renderer->SetBackgroundAlpha(1.0);
    return medium;
  }

  void Background(double r, double g, double b, const double* top)
  {
    this->Scene.Renderer->SetBackground(r, g, b);
    this->Scene.Renderer->SetGradientBackground(top != nullptr);
    if (top)
    {
      this->Scene.Renderer->SetBackground2(top[0], top[1], top[2]);
    }
  }

  // The background as VTK draws it (the volume hidden).
  std::vector<float> Under()
  {
    this->Scene.Volume->VisibilityOff();
    std::vector<float> under = RenderFloat(this->Scene.Window, this->Pass);
    this->Scene.Volume->VisibilityOn();
    return under;
  }

  // Linear over black, the background alone, then the transform over it.
  double Check(
    const Transform& t, const double bottom[3], const double* top, const std::string& what)
  {
    const std::vector<float> medium = this->Medium();
    this->Background(bottom[0], bottom[1], bottom[2], top);
    const std::vector<float> under = this->Under();
    SetTransform(this->Scene.Mapper, t);
    const std::vector<float> shown = RenderFloat(this->Scene.Window, this->Pass);
    int lit = 0;
    const double worst = Worst(medium, under, shown, t, lit);
    std::cout << what << ": largest difference from the CPU twin " << worst << " (" << lit
              << " lit channels; " << this->Scene.Mapper->GetLastRayCastPassCount()
              << " pass(es), reduction " << this->Scene.Mapper->GetLastImageReduction() << ")\n";
    tyndall_test::Check(lit > 1000, what + ": the medium is in the picture");
    tyndall_test::Check(worst < 1e-5, what + ": the GPU's transform is the CPU twin's");
    SetTransform(this->Scene.Mapper, Identity);
    return worst;
  }
};
}

int TestTransmittanceMapperToneMapping(int, char*[])
{
  using tyndall_test::MakeCloud;
  const Transform brighter{ 1.5, Mapper::TONE_CURVE_LINEAR, false };
  const Transform reinhard{ -1.0, Mapper::TONE_CURVE_REINHARD, false };
  const Transform aces{ 0.5, Mapper::TONE_CURVE_ACES, true };
  const double black[3] = { 0.0, 0.0, 0.0 };
  const double grey[3] = { 0.35, 0.4, 0.45 };
  const double skyBottom[3] = { 0.55, 0.68, 0.82 };
  const double skyTop[3] = { 0.16, 0.32, 0.58 };

  tyndall_test::PathScene scene(MakeCloud(32), 0.8, 96);
  scene.Mapper->PathTracingOff();
  vtkNew<vtkFramebufferPass> pass;
  vtkNew<vtkRenderStepsPass> steps;
  pass->SetColorFormat(vtkTextureObject::Float32);
  pass->SetDelegatePass(steps);
  scene.Renderer->SetPass(pass);
  vtkRenderWindow* window = scene.Window;
  Mapper* mapper = scene.Mapper;
  Bench bench{ scene, pass };

  // The map-based frame, drawn straight into the window.
  bench.Check(brighter, black, nullptr, "map frame over black, +1.5 stops, linear");
  Check(mapper->GetLastRayCastPassCount() == 1 && mapper->GetLastImageReduction() == 1,
    "the map frame was drawn straight into the window");
  bench.Check(reinhard, grey, nullptr, "map frame over grey, -1 stop, Reinhard");
  bench.Check(aces, skyBottom, skyTop, "map frame over the sky's gradient, +0.5 stops, ACES, sRGB");

  // Back to the defaults: the linear picture, bit for bit.
  bench.Background(grey[0], grey[1], grey[2], nullptr);
  const std::vector<float> linear = RenderFloat(window, pass);
  SetTransform(mapper, aces);
  RenderFloat(window, pass);
  SetTransform(mapper, Identity);
  Check(RenderFloat(window, pass) == linear, "the defaults give the linear picture again");

  // The accumulation's composite (a coloured extinction): the background is
  // seen through the transmittance T of each channel, measured linear over
  // grey: the pixel is Map(L + T Unmap(B)).
  {
    scene.Property->SetExtinctionColor(1.0, 0.7, 0.4);
    const std::vector<float> medium = bench.Medium();
    bench.Background(grey[0], grey[1], grey[2], nullptr);
    const std::vector<float> linearGrey = RenderFloat(window, pass);
    SetTransform(mapper, aces);
    const std::vector<float> shown = RenderFloat(window, pass);
    SetTransform(mapper, Identity);
    double worst = shown.size() == medium.size() && linearGrey.size() == medium.size() ? 0.0 : 1e30;
    double spread = 0.0; // how far the channels' transmittances part
    for (size_t i = 0; i + 3 < medium.size() && worst < 1e30; i += 4)
    {
      double T[3];
      for (int k = 0; k < 3; ++k)
      {
        T[k] = (linearGrey[i + k] - medium[i + k]) / grey[k];
        const double pixel = vtkTyndallToneMapping::Map(medium[i + k] +
            T[k] * vtkTyndallToneMapping::Unmap(grey[k], aces.Exposure, aces.Curve, aces.SRGB),
          aces.Exposure, aces.Curve, aces.SRGB);
        worst = std::max(worst, std::abs(shown[i + k] - pixel));
      }
      spread = std::max(spread, std::abs(T[0] - T[2]));
    }
    std::cout << "coloured extinction over grey, ACES, sRGB: largest difference from the CPU twin "
              << worst << " (transmittances part by up to " << spread << ")\n";
    Check(spread > 0.1, "the channels' transmittances differ");
    Check(worst < 1e-5,
      "a coloured extinction: the background through each channel's "
      "transmittance, transformed");
    scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
  }

  // The projection blend mode (a plain property, maximum intensity).
  {
    vtkNew<vtkVolumeProperty> plain;
    plain->SetColor(scene.Property->GetRGBTransferFunction());
    plain->SetScalarOpacity(scene.Property->GetScalarOpacity());
    mapper->SetBlendModeToMaximumIntensity();
    scene.Volume->SetProperty(plain);
    bench.Check(aces, grey, nullptr, "maximum intensity over grey, ACES, sRGB");
    mapper->SetBlendModeToComposite();
    scene.Volume->SetProperty(scene.Property);
  }

  // The path-traced picture, transformed from its start: its history is the
  // linear mean (the same frames as a linear run of the same seed).
  bench.Background(grey[0], grey[1], grey[2], nullptr);
  const std::vector<float> under = bench.Under();
  SetTransform(mapper, Identity);
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Renderer->SetBackgroundAlpha(0.0);
  Check(scene.Trace(8) == 8, "the linear paths reach 8 samples per pixel");
  const std::vector<float> paths = RenderFloat(window, pass); // redrawn: the same mean
  scene.Renderer->SetBackground(grey[0], grey[1], grey[2]);
  scene.Renderer->SetBackgroundAlpha(1.0);
  SetTransform(mapper, aces);
  Check(scene.Trace(8) == 8, "the transformed paths reach 8 samples per pixel");
  int lit = 0;
  double worst = Worst(paths, under, RenderFloat(window, pass), aces, lit);
  std::cout << "path-traced over grey, ACES, sRGB from the start: largest difference from the "
               "CPU twin "
            << worst << " (" << lit << " lit channels)\n";
  Check(lit > 1000 && worst < 1e-5, "the path-traced mean goes through the same transform");
  const Transform darker{ -1.0, Mapper::TONE_CURVE_ACES, true };
  SetTransform(mapper, darker);
  const std::vector<float> shownDarker = RenderFloat(window, pass);
  std::cout << "path-traced samples after a new exposure: " << mapper->GetLastPathTraceSamples()
            << "\n";
  Check(mapper->GetLastPathTraceSamples() == 8,
    "changing the transform keeps the path-traced picture's samples");
  worst = Worst(paths, under, shownDarker, darker, lit);
  Check(worst < 1e-5, "the kept mean goes through the new transform");
  mapper->PathTracingOff();

  scene.Renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
