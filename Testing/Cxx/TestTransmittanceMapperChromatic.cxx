// Coloured extinction (vtkParticipatingMediumProperty::ExtinctionColor): a
// cloud whose red extinction is 0.25 and green 0.6 of its blue, so that the
// light it lets through (and the background behind it) turns red, with the
// default two multiple-scattering octaves and a per-extinction emission.
// 1. Exact math on the CPU: each channel of the chromatic picture equals that
//    channel of the grey medium rendered with DensityScale = its component
//    (radiance and view transmittance, no early termination): the channels
//    are independent media, and a channel's light transmittance is the
//    densest channel's raised to its component;
// 2. the same identity on the GPU, brute force (the three grey pictures are
//    drawn direct, the chromatic one through the accumulation images);
// 3. every method against the CPU reference: >= 40 dB (the target);
// 4. the colour is there: the grey medium is far from the chromatic one;
// 5. the property clamps its components, equal components are a density
//    scale; the path tracer renders a chromatic medium (a transmittance per
//    channel; TestVolumetricPathTracerScenes holds it to the reference).
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestCloudScene.h"
#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;
using M = vtkTransmittanceVolumeMapper;

const double kColor[3] = { 0.25, 0.6, 1.0 };

struct Scene : tyndall_test::CloudScene
{
  explicit Scene(int size)
    : CloudScene(size, 0.7)
  {
    this->Mapper->SetNumberOfCoefficients(16);
    this->Property->SetScatteringOctaves(2);
    this->Property->SetAmbientIntensity(0.05);
    vtkNew<vtkColorTransferFunction> emission;
    emission->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
    emission->AddRGBPoint(8.0, 0.3, 0.2, 0.1);
    this->Property->SetEmissionColor(emission);
    this->Property->SetEmissionScale(0.5);
    // A bright background: the view transmittance's colour shows on it.
    this->Renderer->SetBackground(0.55, 0.6, 0.7);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.8, 0.6, 1.0));
  }

  /// The CPU reference's picture, or with `raw` its radiance and transmittance.
  vtkSmartPointer<vtkImageData> Cpu(bool raw = false, double threshold = 1.0e-6)
  {
    vtkNew<vtkSingleScatteringReference> reference;
    reference->SetEarlyTerminationThreshold(threshold);
    return this->CloudScene::Cpu(reference, raw);
  }
};

// The largest |a - b| over channel c of the named arrays (b's channel 0 when
// it has one component); infinity when an array is missing or sizes differ.
double ChannelDifference(vtkImageData* a, vtkImageData* b, const char* name, int c, int cb)
{
  vtkDataArray* x = a->GetPointData()->GetArray(name);
  vtkDataArray* y = b->GetPointData()->GetArray(name);
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() || x->GetNumberOfTuples() == 0)
  {
    return HUGE_VAL;
  }
  double largest = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    largest = std::max(largest, std::abs(x->GetComponent(i, c) - y->GetComponent(i, cb)));
  }
  return largest;
}

// The mean (or with `smallest`, the smallest) red minus blue of a picture, in levels.
double RedMinusBlue(vtkImageData* image, bool smallest = false)
{
  vtkDataArray* x = image->GetPointData()->GetScalars();
  double sum = 0.0, least = HUGE_VAL;
  const vtkIdType n = x ? x->GetNumberOfTuples() : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double d = x->GetComponent(i, 0) - x->GetComponent(i, 2);
    sum += d;
    least = std::min(least, d);
  }
  return n == 0 ? -HUGE_VAL : (smallest ? least : sum / static_cast<double>(n));
}

// PSNR of channel c of two 8-bit pictures.
double ChannelPSNR(vtkImageData* a, vtkImageData* b, int c)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() || x->GetNumberOfTuples() == 0)
  {
    return 0.0;
  }
  double sum = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    const double d = x->GetComponent(i, c) - y->GetComponent(i, c);
    sum += d * d;
  }
  const double mse = sum / static_cast<double>(x->GetNumberOfTuples());
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : 100.0;
}
}

int TestTransmittanceMapperChromatic(int, char*[])
{
  Scene scene(128);
  scene.Property->SetExtinctionColor(kColor);
  scene.Mapper->SetTransmittanceMethodToBruteForce();
  const vtkSmartPointer<vtkImageData> chromaticCpu = scene.Cpu(true, 0.0);
  const vtkSmartPointer<vtkImageData> chromaticGpu = scene.Gpu();
  const vtkSmartPointer<vtkImageData> chromatic = scene.Cpu();
  vtkDataArray* T = chromaticCpu->GetPointData()->GetArray("Transmittance");
  Check(T && T->GetNumberOfComponents() == 3, "the CPU reference's transmittance is per channel");

  // 1. and 2.: each channel is the grey medium at that density.
  for (int c = 0; c < 3; ++c)
  {
    scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
    scene.Property->SetDensityScale(kColor[c]);
    const vtkSmartPointer<vtkImageData> grey = scene.Cpu(true, 0.0);
    const double dL = ChannelDifference(chromaticCpu, grey, "Radiance", c, c);
    const double dT = ChannelDifference(chromaticCpu, grey, "Transmittance", c, 0);
    const double gpu = ChannelPSNR(chromaticGpu, scene.Gpu(), c);
    std::cout << "channel " << c << " against the grey medium at density " << kColor[c]
              << ": CPU radiance " << dL << ", transmittance " << dT << "; GPU brute force " << gpu
              << " dB\n";
    Check(dL < 1e-12 && dT < 1e-12, "CPU: channel " + std::to_string(c) + " is its grey medium");
    // Measured 61-66 dB (the float light march's rounding against the
    // power of one march).
    Check(gpu >= 55.0, "GPU: channel " + std::to_string(c) + " is its grey medium");
  }
  scene.Property->SetDensityScale(1.0);
  scene.Property->SetExtinctionColor(kColor);

  // 3. Every method against the CPU reference.
  const int methods[5] = { M::BRUTE_FORCE, M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM };
  // Measured on llvmpipe (16 coefficients, the default octaves: a 1.3, b
  // 0.45, build-up 6), dB: BruteForce 53.3, TFM 45.7, AdaptiveTFM 50.2, ETM
  // 50.0, AdaptiveETM 50.8 (with the earlier a 0.9, b 0.3 and no build-up:
  // 53.3, 44.6, 47.7, 50.8, 52.3); the grey medium's 53.4, 42.8, 48.5, 48.3,
  // 50.5 (printed). TFM with one map raised to the
  // channels' powers was 31.7 dB at 12 coefficients (its error near T = 0,
  // magnified by T^0.25): hence its per-channel maps. The bar is 40.
  const double floors[5] = { 52.0, 43.5, 46.0, 49.5, 50.5 };
  scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
  const vtkSmartPointer<vtkImageData> greyCpu = scene.Cpu();
  for (int i = 0; i < 5; ++i)
  {
    scene.Mapper->SetTransmittanceMethod(methods[i]);
    std::cout << "  (grey: " << tyndall_test::PSNR(scene.Gpu(), greyCpu) << " dB)\n";
  }
  scene.Property->SetExtinctionColor(kColor);
  for (int i = 0; i < 5; ++i)
  {
    scene.Mapper->SetTransmittanceMethod(methods[i]);
    const double psnr = tyndall_test::PSNR(scene.Gpu(), chromatic);
    std::cout << scene.Mapper->GetTransmittanceMethodAsString() << ": " << psnr
              << " dB against the CPU reference (largest difference "
              << tyndall_test::MaxDifference(scene.Gpu(), chromatic) << "/255)\n";
    Check(psnr >= floors[i],
      std::string(scene.Mapper->GetTransmittanceMethodAsString()) + " against the CPU reference");
  }
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();

  // Without the transmittance cache (the camera rays read the maps: per
  // channel for TFM, a power of the extinction map's for ETM).
  scene.Mapper->TransmittanceCacheOff();
  const double uncachedFloors[2] = { 43.5, 49.5 };
  const int uncached[2] = { M::TFM, M::ADAPTIVE_ETM };
  for (int i = 0; i < 2; ++i)
  {
    scene.Mapper->SetTransmittanceMethod(uncached[i]);
    const double psnr = tyndall_test::PSNR(scene.Gpu(), chromatic);
    std::cout << scene.Mapper->GetTransmittanceMethodAsString() << " without the cache: " << psnr
              << " dB against the CPU reference\n";
    Check(psnr >= uncachedFloors[i],
      std::string(scene.Mapper->GetTransmittanceMethodAsString()) + " without the cache");
  }
  scene.Mapper->TransmittanceCacheOn();

  // A new colour of the same densest channel: ETM's maps stay (they hold the
  // densest channel's extinction), the cache and TFM's per-channel maps are
  // rebuilt, and both draw the new colour.
  const double otherColor[3] = { 0.5, 1.0, 0.3 };
  for (int method : { M::ETM, M::TFM })
  {
    scene.Mapper->SetTransmittanceMethod(method);
    scene.Gpu();
    const int maps = scene.Mapper->GetMapBuildCount();
    const int caches = scene.Mapper->GetTransmittanceCacheBuildCount();
    scene.Property->SetExtinctionColor(otherColor);
    const double psnr = tyndall_test::PSNR(scene.Gpu(), scene.Cpu());
    const int mapBuilds = scene.Mapper->GetMapBuildCount() - maps;
    const int cacheBuilds = scene.Mapper->GetTransmittanceCacheBuildCount() - caches;
    std::cout << scene.Mapper->GetTransmittanceMethodAsString() << ", another colour: " << psnr
              << " dB against the CPU reference, " << mapBuilds << " map and " << cacheBuilds
              << " cache builds\n";
    const std::string what = scene.Mapper->GetTransmittanceMethodAsString();
    Check(psnr >= 43.5, what + ": another colour drawn right");
    Check(mapBuilds == (method == M::TFM ? 1 : 0), what + ": maps rebuilt only when per channel");
    Check(cacheBuilds == 1, what + ": the cache is rebuilt for another colour");
    scene.Property->SetExtinctionColor(kColor);
  }

  // 4. The colour is there.
  scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
  const double grey = tyndall_test::PSNR(scene.Gpu(), chromatic);
  std::cout << "the grey medium: " << grey << " dB against the chromatic one\n";
  Check(grey < 30.0, "the coloured extinction changes the picture");
  // Without light or emission, over a white background, the picture is the
  // view transmittance: blue, the densest channel, lets the least through.
  scene.Property->SetExtinctionColor(kColor);
  scene.Property->SetLightScale(0.0);
  scene.Property->SetAmbientIntensity(0.0);
  scene.Property->SetEmissionScale(0.0);
  scene.Renderer->SetBackground(1.0, 1.0, 1.0);
  const double redMinusBlue = RedMinusBlue(scene.Gpu());
  std::cout << "the view transmittance over white: red - blue " << redMinusBlue
            << " levels on average, at least " << RedMinusBlue(scene.Gpu(), true) << "\n";
  Check(redMinusBlue > 10.0 && RedMinusBlue(scene.Gpu(), true) >= -1.0,
    "the view transmittance is redder where blue is the densest channel");
  scene.Renderer->SetBackground(0.55, 0.6, 0.7);
  scene.Property->SetLightScale(4.0 * 3.141592653589793);
  scene.Property->SetAmbientIntensity(0.05);
  scene.Property->SetEmissionScale(0.5);

  // 5. The property, equal components, the path tracer.
  scene.Property->SetExtinctionColor(2.0, -1.0, std::nan(""));
  const double* e = scene.Property->GetExtinctionColor();
  Check(e[0] == 1.0 && e[1] == 0.0 && e[2] == 1.0, "ExtinctionColor is clamped to [0, 1]");
  scene.Property->SetExtinctionColor(0.5, 0.5, 0.5);
  const vtkSmartPointer<vtkImageData> equal = scene.Gpu();
  scene.Property->SetExtinctionColor(1.0, 1.0, 1.0);
  scene.Property->SetDensityScale(0.5);
  const double asDensity = tyndall_test::PSNR(equal, scene.Gpu());
  std::cout << "equal components 0.5 against DensityScale 0.5: " << asDensity << " dB\n";
  Check(asDensity >= 60.0, "equal components are a density scale");
  scene.Property->SetDensityScale(1.0);
  scene.Property->SetExtinctionColor(kColor);
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkVolumetricPathTracer> tracer;
  tracer->AddObserver(vtkCommand::ErrorEvent, errors);
  tracer->SetSamplesPerPixel(1);
  vtkImageData* traced = tracer->Render(scene.Renderer, scene.Volume, 8, 8);
  Check(traced && !errors->GetError() &&
      traced->GetPointData()->GetArray("Transmittance")->GetNumberOfComponents() == 3,
    "the path tracer renders a coloured extinction, a transmittance per channel");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
