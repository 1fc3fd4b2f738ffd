// BenchCinematic: the mapper's path-traced mode (vtkTransmittanceVolumeMapper::
// PathTracing) beside its CPU twin, vtkVolumetricPathTracer (DELTA_TRACKING,
// the same estimator and bounce limit), on the built-in cloud, the dense
// medium (the tests' scenes: a sun of intensity 1.5, ambient 0.05, g 0.4)
// and a shaded CT (the dense medium's ball through a plain property with
// Shade on: its collisions scatter as VTK's shaded surfaces; the map-based
// frame's octaves do not apply to it).
//
// For each scene, at W x W pixels:
// 1. the converged picture: the GPU's, ratio-tracked shadows, at --reference
//    samples per pixel (default 1024), another seed; and its PSNR against the
//    CPU tracer's at --cpu-spp (default 256);
// 2. the map-based frame (AdaptiveETM, single scattering: what the mapper
//    draws while anything moves): its time (best of 3) and its PSNR against the
//    converged picture (under a sky, the sky's two models, each also with
//    the property's default two octaves); its time with the display transform (ACES, sRGB)
//    against linear, alternated, the best of five each; and at the paths'
//    start drawn as the denoiser's guide (PathTraceDenoise) against
//    directly, alternated likewise;
// 3. for each light transmittance (the maps, ratio tracked), then the maps'
//    with the denoiser (PathTraceDenoise): frames of paths from a new start,
//    the time and samples per pixel at which the picture first reaches 30 dB
//    against the converged one (the "time to 30 dB"), the GPU's
//    paths per second, and how much sooner the denoised picture gets there;
// 4. the CPU tracer's paths per second (one thread count: the machine's),
//    and the ratio GPU / CPU measured in this run. Paths per second count
//    every pixel's samples (the rays that miss the box too, on both).
// Times are the frames of paths alone, each finished on the GPU
// (WaitForCompletion), without the readbacks and PSNRs between them.
//
// With --sky both scenes are lit by a gradient sky too (the renderer's
// EnvironmentalBG 0.02 straight down to EnvironmentalBG2 (0.3, 0.45, 0.8)
// straight up, vtkTyndallEnvironment): the paths sample it; the map-based
// frame is measured with the sky's mean radiance as ambient light
// (SkyLightDirections 0) and with --sky-lights N sky lights (default 4, the
// mapper's; 0 measures the mean twice), each in single scattering and with
// the property's default two octaves; run with and without it for the sky's
// cost and how alike the two modes light it. --sun lights them by an image
// sky instead: the gradient with a small bright sun, 40 degrees up
// (MakeSunSky()).
//
// --detail measures instead the closed form against delta tracking on
// procedural detail (BenchPathTracer's scenes: its cloud, a 32^3 ellipsoid
// shape, and the paper's Table 1 setting, the noise in its bounding box at a
// mean optical depth of 8; under 6 octaves x 24 directions of noise, offset
// to stay non-negative: one medium both ways; g 0.6, the scene's sun), with
// tracked shadows: the converged
// picture (the GPU's closed form at 4 x --reference spp, seed 1), then for
// each mode the GPU's paths per second over --reference spp from a new
// start and its PSNR against the converged picture there (the same samples:
// the closed form's exact shadows are less noisy), and the CPU tracer's
// paths per second at --cpu-spp (its tracking's share of the time).
//
// Usage: BenchCinematic [--quick] [--size W] [--reference S] [--cpu-spp S]
//   [--bounces B] [--frame-spp K] [--sky] [--sun] [--sky-lights N] [--detail]
//   [--scene 0|1|2] [--chromatic] [--fog] [--hot-fog] [--fire] [--help]
// --scene N measures one scene: 0 the cloud, 1 the dense medium, 2 the shaded CT.
// --fog puts each scene in a fog lit its own way (the path tracing test's):
// another volume around and behind the medium, a guest whose collisions the
// scattered paths draw and light by its own parameters (g -0.6, LightScale
// 3, ambient 0.3); the window's picture is then both layers, and the CPU
// tracer's picture the medium's layer alone (its PSNR not comparable).
// --hot-fog is --fog glowing from an emission array (a "temperature" that
// rises from 1000 to 2000 across it, through a colour function,
// EmissionScale 1.5): its light along the medium's scattered paths'
// segments, four stratified points each, tracked from point to point.
// --fire makes the media glow from such an array (the same colours, over
// each grid's x; not the shaded CT's plain property): their own emission
// along every segment of their paths.
// --chromatic gives the media a coloured extinction (red 0.25, green 0.6 of
// blue's, the tests'): spectral tracking (not the shaded CT's plain property).
// --quick (what ctest runs): 24 x 24, reference 64 spp, CPU 16 spp, a light
// cache of 32 texels a side: every render works, never a timing or a PSNR.
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkCullerCollection.h"
#include "vtkFloatArray.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDisplay.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestPathScene.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

namespace
{
struct Options
{
  bool Quick = false;
  int Size = 128;
  int Reference = 1024;
  int CpuSamples = 256;
  int Bounces = 8;
  int FrameSamples = 16;
  bool Sky = false;
  int SkyLights = 4;
  bool Sun = false;
  bool Detail = false;
  int Scene = -1; // --scene: 0 the cloud, 1 the dense medium, 2 the shaded CT; -1 every one
  bool Chromatic = false;
  bool Fog = false;
  bool HotFog = false; // the fog glows from an emission array
  bool Fire = false;   // the media glow from an emission array
};

// The --sun sky: an equirectangular 128 x 64 image, the --sky gradient with a
// sun of 4 texels (radiance 2000, about 1.4 degrees across) 40 degrees up.
vtkSmartPointer<vtkTexture> MakeSunSky()
{
  const int W = 128, H = 64;
  vtkNew<vtkImageData> image;
  image->SetDimensions(W, H, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(W * H);
  const double down[3] = { 0.02, 0.02, 0.02 }, up[3] = { 0.3, 0.45, 0.8 };
  const int sunRow = static_cast<int>(H * (0.5 + 40.0 / 180.0)), sunColumn = W / 3;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const bool sun = (j == sunRow || j == sunRow + 1) && (i == sunColumn || i == sunColumn + 1);
      for (int c = 0; c < 3; ++c)
      {
        const double t = (j + 0.5) / H;
        values->SetComponent(j * W + i, c, sun ? 2000.0 : down[c] + t * (up[c] - down[c]));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  return texture;
}

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&](int& value, int low, int high)
    {
      if (i + 1 >= argc)
      {
        return false;
      }
      value = std::atoi(argv[++i]);
      return value >= low && value <= high;
    };
    bool ok = true;
    if (a == "--quick")
    {
      o.Quick = true;
      o.Size = 24;
      o.Reference = 64;
      o.CpuSamples = 16;
    }
    else if (a == "--size")
    {
      ok = next(o.Size, 8, 2048);
    }
    else if (a == "--reference")
    {
      ok = next(o.Reference, 1, 1000000);
    }
    else if (a == "--cpu-spp")
    {
      ok = next(o.CpuSamples, 1, 1000000);
    }
    else if (a == "--bounces")
    {
      ok = next(o.Bounces, 1, 1000);
    }
    else if (a == "--frame-spp")
    {
      ok = next(o.FrameSamples, 1, 64);
    }
    else if (a == "--sky")
    {
      o.Sky = true;
    }
    else if (a == "--sun")
    {
      o.Sky = o.Sun = true;
    }
    else if (a == "--sky-lights")
    {
      ok = next(o.SkyLights, 0, 8);
    }
    else if (a == "--detail")
    {
      o.Detail = true;
    }
    else if (a == "--scene")
    {
      ok = next(o.Scene, 0, 2);
    }
    else if (a == "--chromatic")
    {
      o.Chromatic = true;
    }
    else if (a == "--fog")
    {
      o.Fog = true;
    }
    else if (a == "--hot-fog")
    {
      o.Fog = o.HotFog = true;
    }
    else if (a == "--fire")
    {
      o.Fire = true;
    }
    else
    {
      ok = false;
    }
    if (!ok)
    {
      std::printf("Usage: BenchCinematic [--quick] [--size W] [--reference S] [--cpu-spp S] "
                  "[--bounces B] [--frame-spp K] [--sky] [--sun] [--sky-lights N] [--detail] "
                  "[--scene 0|1|2] [--chromatic] [--fog] [--hot-fog] [--fire] [--help]\n");
      return false;
    }
  }
  return true;
}

// The tests' scene (TyndallTestPathScene.h), named, in the display's window.
struct Scene : tyndall_test::PathScene
{
  std::string Name;
  // --fog: a 4^3 grid of the cloud's transfer functions at their peak value
  // (extinction about 1), scaled 1.3 about a point 0.3 behind the origin.
  vtkNew<vtkTransmittanceVolumeMapper> FogMapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> FogProperty =
    tyndall_test::MakeCloudProperty(0.05);
  vtkNew<vtkVolume> Fog;

  void AddFog(bool hot)
  {
    vtkSmartPointer<vtkImageData> fog = tyndall_test::MakeFog(-1.0, -1.0, -1.0, 2.0, 2.0, 2.0);
    if (hot)
    {
      tyndall_test::AddTemperature(fog);
      tyndall_test::GlowFromTemperature(this->FogProperty, 1.5);
    }
    this->FogMapper->SetInputData(fog);
    this->FogMapper->JitterOff();
    this->FogProperty->SetScatteringAnisotropy(-0.6);
    this->FogProperty->SetLightScale(3.0);
    this->FogProperty->SetAmbientIntensity(0.3);
    this->Fog->SetMapper(this->FogMapper);
    this->Fog->SetProperty(this->FogProperty);
    this->Fog->SetPosition(0.0, 0.0, -0.3);
    this->Fog->SetScale(1.3);
    this->Renderer->AddVolume(this->Fog);
    vtkFrustumCoverageCuller::SafeDownCast(this->Renderer->GetCullers()->GetLastItem())
      ->SetSortingStyleToBackToFront();
  }

  Scene(const char* name, vtkImageData* data, double peakOpacity, const Options& o,
    vtkTyndallDisplay* display)
    : tyndall_test::PathScene(data, peakOpacity, o.Size)
    , Name(name)
  {
    this->Mapper->SetPathTraceMaximumBounces(o.Bounces);
    this->Mapper->SetPathTraceSamplesPerFrame(o.FrameSamples);
    if (o.Chromatic)
    {
      this->Property->SetExtinctionColor(0.25, 0.6, 1.0);
    }
    if (o.Fire)
    {
      tyndall_test::AddTemperature(data);
      tyndall_test::GlowFromTemperature(this->Property, 1.5);
    }
    if (o.Quick)
    {
      // No figure: the sky's 4 lights' caches kept small (1.1 s each on
      // llvmpipe at the default 256, built again at each of the map-based
      // frame's sky settings).
      this->Mapper->SetTransmittanceCacheSize(32);
    }
    if (o.Sun)
    {
      this->Renderer->SetEnvironmentTexture(MakeSunSky());
      this->Renderer->UseImageBasedLightingOn();
    }
    else if (o.Sky)
    {
      this->Renderer->GradientEnvironmentalBGOn();
      this->Renderer->SetEnvironmentalBG(0.02, 0.02, 0.02);
      this->Renderer->SetEnvironmentalBG2(0.3, 0.45, 0.8);
    }
    if (o.Fog)
    {
      this->AddFog(o.HotFog);
    }
    display->Attach(this->Window);
  }

  // Trace() with `frame(samples, seconds)` after each frame of paths
  // (true: stop): the seconds the frames of paths took so far, each
  // finished on the GPU, without the time `frame` itself takes.
  template <typename F>
  void Timed(int samples, int shadows, F frame)
  {
    this->Mapper->SetPathTraceShadows(shadows);
    double excluded = 0.0;
    this->Trace(samples,
      [&](int n)
      {
        this->Finish();
        const double seconds = Seconds(this->PathsStart) - excluded;
        const auto start = std::chrono::steady_clock::now();
        const bool stop = frame(n, seconds);
        excluded += Seconds(start);
        return stop;
      });
  }

  void Finish() { vtkOpenGLRenderWindow::SafeDownCast(this->Window)->WaitForCompletion(); }
};

bool Run(Scene& s, const Options& o)
{
  std::printf("%s, %d x %d, up to %d bounces%s%s%s:\n", s.Name.c_str(), o.Size, o.Size, o.Bounces,
    o.Sun ? ", under the sun sky" : (o.Sky ? ", under the gradient sky" : ""),
    o.HotFog ? ", in a fog lit its own way that glows from an array"
             : (o.Fog ? ", in a fog lit its own way" : ""),
    o.Fire && vtkParticipatingMediumProperty::SafeDownCast(s.Volume->GetProperty())
      ? ", glowing from an array"
      : "");
  // 1. the converged picture (its own random numbers).
  s.Mapper->SetPathTraceSeed(1);
  double seconds = 0.0;
  int samples = 0;
  s.Timed(o.Reference, vtkTransmittanceVolumeMapper::PATH_SHADOWS_TRACKED,
    [&](int n, double t)
    {
      samples = n;
      seconds = t;
      return false;
    });
  if (samples < o.Reference)
  {
    std::printf("FAILED: the GPU traced %d of %d samples per pixel\n", samples, o.Reference);
    return false;
  }
  vtkSmartPointer<vtkImageData> converged = s.Picture();
  s.Mapper->SetPathTraceSeed(0);
  vtkNew<vtkVolumetricPathTracer> cpu;
  cpu->SetDistanceSampling(vtkVolumetricPathTracer::DELTA_TRACKING);
  cpu->SetSamplesPerPixel(o.CpuSamples);
  cpu->SetMaximumBounces(o.Bounces);
  const auto cpuStart = std::chrono::steady_clock::now();
  if (!cpu->Render(s.Renderer, s.Volume, o.Size, o.Size))
  {
    std::printf("FAILED: the CPU tracer did not render\n");
    return false;
  }
  const double cpuSeconds = Seconds(cpuStart);
  const double pixels = double(o.Size) * o.Size;
  const double cpuRate = pixels * o.CpuSamples / cpuSeconds;
  std::printf(
    "  converged: GPU %d spp (tracked shadows, seed 1) in %.1f s; against the CPU tracer at %d "
    "spp %.1f dB%s\n",
    samples, seconds, o.CpuSamples, tyndall_test::PSNR(converged, cpu->Composite()),
    o.Fog ? " (not comparable: the fog's layer is the GPU's only)" : "");
  // 2. the map-based frame; under the sky with its mean as ambient light and
  // with its lights, each in single scattering and with the property's two
  // octaves (its default; the paths ignore the octaves).
  s.Mapper->PathTracingOff();
  const int skyModels[2] = { 0, o.SkyLights };
  for (int octaves = 1; octaves <= (o.Sky ? 2 : 1); ++octaves)
  {
    s.Property->SetScatteringOctaves(octaves);
    for (int m = o.Sky ? 0 : 1; m < 2; ++m)
    {
      s.Mapper->SetSkyLightDirections(skyModels[m]);
      s.Window->Render(); // the maps
      s.Finish();
      double mapSeconds = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k)
      {
        const auto mapStart = std::chrono::steady_clock::now();
        s.Window->Render();
        s.Finish();
        mapSeconds = std::min(mapSeconds, Seconds(mapStart));
      }
      std::printf("  map-based frame (AdaptiveETM, %s%s): %.3f s (best of 3), %.1f dB against the "
                  "converged picture\n",
        octaves == 1 ? "single scattering" : "2 octaves",
        !o.Sky ? ""
               : (skyModels[m] == 0 ? ", the sky's mean as ambient light" : ", the sky's lights"),
        mapSeconds, tyndall_test::PSNR(s.Picture(), converged));
    }
  }
  s.Property->SetScatteringOctaves(1);
  s.Mapper->SetSkyLightDirections(0); // the paths as before (the sky lights are the frame's)
  // The display transform's cost: the frame linear and with ACES and sRGB,
  // alternated, the best of five each.
  double best[2] = { 1e30, 1e30 };
  for (int i = 0; i < 10; ++i)
  {
    const bool mapped = i % 2 == 1;
    s.Mapper->SetToneCurve(mapped ? vtkTransmittanceVolumeMapper::TONE_CURVE_ACES
                                  : vtkTransmittanceVolumeMapper::TONE_CURVE_LINEAR);
    s.Mapper->SetEncodeSRGB(mapped);
    const auto start = std::chrono::steady_clock::now();
    s.Window->Render();
    s.Finish();
    best[mapped ? 1 : 0] = std::min(best[mapped ? 1 : 0], Seconds(start));
  }
  s.Mapper->SetToneCurve(vtkTransmittanceVolumeMapper::TONE_CURVE_LINEAR);
  s.Mapper->SetEncodeSRGB(false);
  std::printf("  the map-based frame with ACES and sRGB: %.4f s, linear %.4f s (best of 5 each): "
              "%.3fx\n",
    best[1], best[0], best[1] / best[0]);
  // The map-based frame at the paths' start drawn as the denoiser's guide
  // (into an image, then composited) against drawn directly, alternated.
  s.Mapper->PathTracingOn();
  double start[2] = { 1e30, 1e30 };
  for (int i = 0; i < 10; ++i)
  {
    const bool guide = i % 2 == 1;
    s.Mapper->SetPathTraceDenoise(guide);
    s.Mapper->ResetAccumulation();
    const auto begin = std::chrono::steady_clock::now();
    s.Window->Render();
    s.Finish();
    start[guide ? 1 : 0] = std::min(start[guide ? 1 : 0], Seconds(begin));
  }
  s.Mapper->SetPathTraceDenoise(false);
  std::printf("  the paths' start (the map-based frame) drawn as the denoiser's guide: %.4f s, "
              "directly %.4f s (best of 5 each): %.3fx\n",
    start[1], start[0], start[1] / start[0]);
  // 3. time to 30 dB, each light transmittance (seed 0), then the maps' denoised.
  double gpuRate = 0.0, mapsReached = -1.0;
  struct Run
  {
    int Shadows;
    bool Denoise;
    const char* Name;
  };
  for (const Run& run :
    { Run{ vtkTransmittanceVolumeMapper::PATH_SHADOWS_FROM_MAPS, false, "shadows from the maps" },
      Run{ vtkTransmittanceVolumeMapper::PATH_SHADOWS_TRACKED, false, "tracked shadows" },
      Run{ vtkTransmittanceVolumeMapper::PATH_SHADOWS_FROM_MAPS, true,
        "shadows from the maps, denoised" } })
  {
    double reached = -1.0, last = 0.0, psnr = 0.0;
    const bool tracked = run.Shadows == vtkTransmittanceVolumeMapper::PATH_SHADOWS_TRACKED;
    int at = 0, traced = 0;
    s.Mapper->SetPathTraceDenoise(run.Denoise);
    s.Timed(o.Reference, run.Shadows,
      [&](int n, double t)
      {
        traced = n;
        last = t;
        psnr = tyndall_test::PSNR(s.Picture(), converged);
        if (psnr >= 30.0 && reached < 0.0)
        {
          reached = t;
          at = n;
        }
        return reached >= 0.0 && n >= 4 * at; // a little past it: the rate
      });
    s.Mapper->SetPathTraceDenoise(false);
    if (tracked && traced > 0)
    {
      gpuRate = pixels * traced / last;
    }
    if (reached >= 0.0)
    {
      std::printf("  %s: 30 dB after %.2f s (%d spp); %d spp in %.2f s (%.1f dB): %.3g paths/s\n",
        run.Name, reached, at, traced, last, psnr, pixels * traced / last);
    }
    else
    {
      std::printf("  %s: below 30 dB at %d spp (%.1f dB, %.2f s): %.3g paths/s\n", run.Name, traced,
        psnr, last, traced > 0 ? pixels * traced / last : 0.0);
    }
    if (!run.Denoise && !tracked)
    {
      mapsReached = reached;
    }
    else if (run.Denoise && reached > 0.0 && mapsReached > 0.0)
    {
      std::printf("  the denoiser: 30 dB %.1fx sooner than the mean (the same paths)\n",
        mapsReached / reached);
    }
  }
  // 4. the rates.
  std::printf("  paths per second: GPU %.3g (tracked shadows), CPU %.3g (%d "
              "threads): GPU / CPU %.2fx\n",
    gpuRate, cpuRate, vtkSMPTools::GetEstimatedNumberOfThreads(), gpuRate / cpuRate);
  return true;
}
}

// --detail's shapes: BenchPathTracer's procedural cloud (an ellipsoid of n^3
// samples) or its box (2^3 samples of 8: the noise in its bounding box, one
// cell per ray), over [-1, 1]^3.
vtkSmartPointer<vtkImageData> MakeDetailShape(int n, bool box)
{
  vtkNew<vtkCosineNoiseSource> source;
  n = box ? 2 : n;
  source->SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1);
  source->SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1));
  source->SetEnvelopeTypeToEllipsoid();
  source->GetNoise()->SetNumberOfOctaves(2);
  if (box)
  {
    source->SetEnvelopeTypeToNone();
    source->GetNoise()->SetAmplitude(0.0);
    source->GetNoise()->SetOffset(8.0);
  }
  source->Update();
  return source->GetOutput();
}

// One GPU picture of `samples` per pixel with tracked shadows in `mode`
// (from a new start): its paths per second (0: not traced).
double TraceDetail(Scene& s, int mode, int samples, vtkSmartPointer<vtkImageData>& picture)
{
  s.Mapper->SetPathTraceDistanceSampling(mode);
  double seconds = 0.0;
  int traced = 0;
  s.Timed(samples, vtkTransmittanceVolumeMapper::PATH_SHADOWS_TRACKED,
    [&](int n, double t)
    {
      traced = n;
      seconds = t;
      return false;
    });
  picture = s.Picture();
  const int* size = s.Window->GetSize();
  return traced >= samples && seconds > 0.0 ? double(size[0]) * size[1] * traced / seconds : 0.0;
}

bool RunDetail(const Options& o, vtkTyndallDisplay* display, bool box)
{
  // The box's shape: opacity 0.3 per 0.05 (extinction 7.13 per unit).
  Scene s(box ? "Procedural box (the paper's Table 1 setting)" : "Procedural cloud",
    MakeDetailShape(o.Quick ? 16 : 32, box), box ? 0.3 : 0.5, o, display);
  vtkNew<vtkCosineNoise> noise;
  noise->SetNumberOfOctaves(o.Quick ? 2 : 6); // --quick: fewer waves to compile and evaluate
  noise->SetNumberOfDirections(o.Quick ? 4 : 24);
  noise->SetFrequency(2.0);
  noise->SetOffset(-noise->GetMinimumValue() + 0.05);
  // The same mean extinction at every contrast; the box: a mean optical depth of 8 across it.
  noise->SetExtinctionScale(
    box ? 8.0 / (2.0 * -std::log(0.7) / 0.05 * noise->GetOffset()) : 1.0 / noise->GetOffset());
  s.Property->SetDetailNoise(noise);
  s.Property->SetScatteringAnisotropy(0.6);
  const int samples = o.Quick ? 4 : o.Reference;
  std::printf("%s (%d waves), %d x %d, up to %d bounces, %d spp, tracked shadows:\n",
    s.Name.c_str(), noise->GetNumberOfOctaves() * noise->GetNumberOfDirections(), o.Size, o.Size,
    o.Bounces, samples);
  using M = vtkTransmittanceVolumeMapper;
  const int modes[2] = { M::PATH_DISTANCE_CLOSED_FORM, M::PATH_DISTANCE_DELTA_TRACKING };
  vtkSmartPointer<vtkImageData> converged;
  s.Mapper->SetPathTraceSeed(1);
  if (TraceDetail(s, modes[0], 4 * samples, converged) <= 0.0)
  {
    std::printf("FAILED: the converged picture was not traced\n");
    return false;
  }
  s.Mapper->SetPathTraceSeed(0);
  const char* names[2] = { "closed form", "delta tracking" };
  double gpu[2], cpu[2];
  vtkSmartPointer<vtkImageData> pictures[2];
  for (int m = 0; m < 2; ++m)
  {
    gpu[m] = TraceDetail(s, modes[m], samples, pictures[m]);
    vtkNew<vtkVolumetricPathTracer> tracer;
    tracer->SetDistanceSampling(
      m == 0 ? vtkVolumetricPathTracer::CLOSED_FORM : vtkVolumetricPathTracer::DELTA_TRACKING);
    tracer->SetSamplesPerPixel(o.Quick ? 2 : o.CpuSamples);
    tracer->SetMaximumBounces(o.Bounces);
    const auto start = std::chrono::steady_clock::now();
    if (gpu[m] <= 0.0 || !tracer->Render(s.Renderer, s.Volume, o.Size, o.Size))
    {
      std::printf("FAILED: %s: the %s did not render\n", names[m], gpu[m] <= 0.0 ? "GPU" : "CPU");
      return false;
    }
    cpu[m] = double(o.Size) * o.Size * tracer->GetSamplesPerPixel() / Seconds(start);
    std::printf("  %s: GPU %.3g paths/s, %.1f dB against the converged picture; CPU %.3g "
                "paths/s (%d threads, %d spp; tracking %.0f %% of the paths' time)\n",
      names[m], gpu[m], tyndall_test::PSNR(pictures[m], converged), cpu[m],
      vtkSMPTools::GetEstimatedNumberOfThreads(), tracer->GetSamplesPerPixel(),
      100.0 * tracer->GetLastTrackingTimePerSample() / tracer->GetLastTotalTimePerSample());
  }
  std::printf("  closed form / delta tracking, paths per second: GPU %.2fx, CPU %.2fx\n",
    gpu[0] / gpu[1], cpu[0] / cpu[1]);
  return true;
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkTyndallDisplay> display;
  if (!display->Open())
  {
    std::printf("FAILED: no display (%s)\n", display->GetErrorMessage());
    return EXIT_FAILURE;
  }
  if (o.Detail)
  {
    return RunDetail(o, display, false) && RunDetail(o, display, true) ? EXIT_SUCCESS
                                                                       : EXIT_FAILURE;
  }
  const int resolution = o.Quick ? 24 : 64;
  Scene cloud("Built-in cloud", tyndall_test::MakeCloud(resolution), 0.5, o, display);
  Scene dense("Dense medium", tyndall_test::MakeDenseMedium(resolution), 0.9, o, display);
  // A shaded CT: the dense medium's ball through a plain property with
  // Shade on (vtkTyndallSurfaceLobe), the tests' (TestTransmittanceMapperPathTrace).
  Scene shaded("Shaded CT (the dense medium's ball, a plain property with Shade on)",
    tyndall_test::MakeDenseMedium(resolution), 0.9, o, display);
  shaded.Volume->SetProperty(tyndall_test::MakeShadedProperty(4.0, 12.0, 0.9));
  Scene* scenes[3] = { &cloud, &dense, &shaded };
  for (int k = 0; k < 3; ++k)
  {
    if ((o.Scene < 0 || o.Scene == k) && !Run(*scenes[k], o))
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
