// BenchMultipleScattering: the multiple-scattering octaves
// (vtkParticipatingMediumProperty::ScatteringOctaves) against the Monte Carlo
// reference with many bounces (vtkVolumetricPathTracer), and their cost on the
// GPU.
//
// Scenes (one sun of intensity 0.5 from the upper right, the tests' camera, no ambient light,
// HG g = 0.5, albedo 0.9, Tyndall's default light scale):
// - dense: the benchmarks' dense medium (optical depths of several tens);
// - thick: the built-in cloud at 4x its density;
// - cloud: the built-in cloud as the other benchmarks draw it (thinner).
//
// For each scene:
// 1. the reference: the path tracer, delta tracking, up to --bounces
//    scattering events (default 128), --spp paths per pixel, W x W pixels;
// 2. the CPU single-scattering reference (vtkSingleScatteringReference) with
//    one octave (single scattering alone) and with the octaves (N, a, b, c,
//    build-up s);
//    the error of each against the path tracer: RMS of the linear radiance
//    over the pixels and channels, the PSNR of that against the path
//    tracer's peak, and the ratio of the two errors (the target: the
//    octaves at least 3x lower on the dense medium and the thick cloud);
//    the path tracer's own noise (RMS standard error) beside them;
// 3. the GPU mapper (AdaptiveETM, 256^2 maps, 8 coefficients) at G x G
//    pixels: frame time without and with the octaves (median of --frames
//    frames after a warm-up, maps built once), their ratio (target <= 1.3),
//    and the PSNR of its picture against the CPU reference's (octaves on).
//
// --fit searches the octaves' parameters (N in {2, 3}, a, b and s on a grid,
// c = 0: earlier searches over N up to 8 and c in {0, 0.5} never did better
// with them) on the CPU for the highest worst-case error ratio over the
// dense medium and the thick cloud, and prints the ten best; the defaults
// of vtkParticipatingMediumProperty were chosen with it (--size 48 --spp
// 512, then the best checked at 96^2 and 1024 spp).
//
// Usage: BenchMultipleScattering [--quick] [--size W] [--spp S] [--bounces B]
//   [--gpu-size G] [--frames F] [--octaves N a b c s] [--fit] [--no-gpu]
//   [--pictures DIR] [--help]
// --quick (what ctest runs): 24 x 24 pixels, 16 spp, 32^3 media, no GPU; checks
// that every render works and that the octaves are brighter than single
// scattering, never a timing or an error ratio.
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDisplay.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
struct Octaves
{
  int N = 0; // 0: the property's defaults
  double A = 0.0, B = 0.0, C = 0.0, S = 0.0;
};

struct Options
{
  bool Quick = false;
  bool Fit = false;
  bool Gpu = true;
  int Size = 64;
  int Samples = 256;
  int Bounces = 128;
  int Resolution = 96;
  int GpuSize = 256;
  int Frames = 5;
  Octaves Setting;
  std::string Pictures;
};

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto integer = [&](int& value)
    {
      value = std::max(1, std::atoi(argv[++i]));
      return true;
    };
    if (a == "--quick")
    {
      o.Quick = true;
      o.Gpu = false;
      o.Size = 24;
      o.Samples = 16;
      o.Resolution = 32;
    }
    else if (a == "--fit")
    {
      o.Fit = true;
    }
    else if (a == "--no-gpu")
    {
      o.Gpu = false;
    }
    else if (a == "--size" && i + 1 < argc)
    {
      integer(o.Size);
    }
    else if (a == "--spp" && i + 1 < argc)
    {
      integer(o.Samples);
    }
    else if (a == "--bounces" && i + 1 < argc)
    {
      integer(o.Bounces);
    }
    else if (a == "--resolution" && i + 1 < argc)
    {
      integer(o.Resolution);
    }
    else if (a == "--gpu-size" && i + 1 < argc)
    {
      integer(o.GpuSize);
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      integer(o.Frames);
    }
    else if (a == "--pictures" && i + 1 < argc)
    {
      o.Pictures = argv[++i];
    }
    else if (a == "--octaves" && i + 5 < argc)
    {
      o.Setting.N = std::atoi(argv[++i]);
      o.Setting.A = std::atof(argv[++i]);
      o.Setting.B = std::atof(argv[++i]);
      o.Setting.C = std::atof(argv[++i]);
      o.Setting.S = std::atof(argv[++i]);
    }
    else
    {
      std::printf("Usage: BenchMultipleScattering [--quick] [--size W] [--spp S] [--bounces B] "
                  "[--resolution R] [--gpu-size G] [--frames F] [--octaves N a b c s] [--fit] "
                  "[--no-gpu] [--pictures DIR] [--help]\n");
      return false;
    }
  }
  return true;
}

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One scene: the medium, its property, a renderer with the sun and camera.
struct Scene
{
  std::string Key;
  vtkSmartPointer<vtkImageData> Data;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;

  Scene(const std::string& key, vtkImageData* data, double peakOpacity, double density)
    : Key(key)
    , Data(data)
    , Property(tyndall_test::MakeCloudProperty(peakOpacity))
  {
    this->Property->SetDensityScale(density);
    this->Property->SetScatteringAnisotropy(0.5);
    this->Mapper->SetInputData(data);
    this->Mapper->JitterOff();
    this->Mapper->SetTransmittanceMethodToAdaptiveETM();
    this->Mapper->SetTransmittanceMapSize(256);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 1.5, 0.8, 0.5));
    tyndall_test::SetTestCamera(this->Renderer);
  }

  void SetOctaves(const Octaves& o)
  {
    this->Property->SetScatteringOctaves(o.N);
    this->Property->SetOctaveScattering(o.A);
    this->Property->SetOctaveExtinction(o.B);
    this->Property->SetOctaveAnisotropy(o.C);
    this->Property->SetOctaveBuildUp(o.S);
  }
};

double Mean(const std::vector<double>& a)
{
  double sum = 0.0;
  for (double v : a)
  {
    sum += v;
  }
  return sum / static_cast<double>(a.size());
}

// The path tracer's reference: radiance, its peak and its RMS standard error.
struct Reference
{
  std::vector<double> Radiance;
  double Peak = 0.0;
  double Noise = 0.0;
  double Seconds = 0.0;
  vtkSmartPointer<vtkImageData> Picture;
};

bool TracePaths(Scene& scene, const Options& o, Reference& reference)
{
  vtkNew<vtkVolumetricPathTracer> tracer;
  tracer->SetDistanceSampling(vtkVolumetricPathTracer::DELTA_TRACKING);
  tracer->SetSamplesPerPixel(o.Samples);
  tracer->SetMaximumBounces(o.Bounces);
  vtkImageData* image = tracer->Render(scene.Renderer, scene.Volume, o.Size, o.Size);
  if (!image)
  {
    return false;
  }
  reference.Radiance = tyndall_test::RadianceValues(image);
  reference.Peak = *std::max_element(reference.Radiance.begin(), reference.Radiance.end());
  vtkDataArray* error = image->GetPointData()->GetArray("RadianceStandardError");
  double sum = 0.0;
  for (vtkIdType i = 0; i < error->GetNumberOfValues(); ++i)
  {
    const double e = error->GetVariantValue(i).ToDouble();
    sum += e * e;
  }
  reference.Noise = std::sqrt(sum / static_cast<double>(error->GetNumberOfValues()));
  reference.Seconds = tracer->GetLastRenderTime();
  reference.Picture = vtkSmartPointer<vtkImageData>::New();
  reference.Picture->DeepCopy(tracer->Composite());
  return true;
}

// The CPU single-scattering reference with the octaves `octaves`.
struct Approximation
{
  std::vector<double> Radiance;
  vtkSmartPointer<vtkImageData> Picture;
};

bool RenderReference(Scene& scene, const Octaves& octaves, int size, Approximation& result)
{
  scene.SetOctaves(octaves);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkImageData* image = reference->Render(scene.Renderer, scene.Volume, size, size);
  if (!image)
  {
    return false;
  }
  result.Radiance = tyndall_test::RadianceValues(image);
  result.Picture = vtkSmartPointer<vtkImageData>::New();
  result.Picture->DeepCopy(reference->Composite());
  return true;
}

double PSNR(double rms, double peak)
{
  return 20.0 * std::log10(peak / std::max(rms, 1e-300));
}

// The worst error ratio (single / octaves) over the scenes for `octaves`.
double WorstRatio(std::vector<Scene*>& scenes, const std::vector<Reference>& references,
  const std::vector<double>& single, const Octaves& octaves, int size)
{
  double worst = 1e300;
  for (size_t s = 0; s < scenes.size(); ++s)
  {
    Approximation approximation;
    if (!RenderReference(*scenes[s], octaves, size, approximation))
    {
      return 0.0;
    }
    worst = std::min(
      worst, single[s] / tyndall_test::RMS(approximation.Radiance, references[s].Radiance));
  }
  return worst;
}

void Fit(std::vector<Scene*>& scenes, const std::vector<Reference>& references, int size)
{
  std::vector<double> single;
  for (size_t s = 0; s < scenes.size(); ++s)
  {
    Approximation one;
    RenderReference(*scenes[s], Octaves{ 1, 0.5, 0.5, 0.5, 0.0 }, size, one);
    single.push_back(tyndall_test::RMS(one.Radiance, references[s].Radiance));
  }
  struct Trial
  {
    Octaves Setting;
    double Ratio;
  };
  std::vector<Trial> trials;
  for (int n : { 2, 3 })
  {
    for (double a : { 0.9, 1.1, 1.3, 1.5, 1.7, 2.0 })
    {
      for (double b : { 0.3, 0.4, 0.45, 0.5, 0.55, 0.6 })
      {
        for (double s : { 0.0, 2.0, 4.0, 6.0, 8.0 })
        {
          const Octaves o{ n, a, b, 0.0, s };
          trials.push_back({ o, WorstRatio(scenes, references, single, o, size) });
        }
      }
    }
  }
  std::sort(
    trials.begin(), trials.end(), [](const Trial& x, const Trial& y) { return x.Ratio > y.Ratio; });
  std::printf("\n--fit over %zu scenes (%zu settings): the ten best worst-case error ratios\n",
    scenes.size(), trials.size());
  for (size_t i = 0; i < std::min<size_t>(10, trials.size()); ++i)
  {
    const Octaves& o = trials[i].Setting;
    std::printf("  N %d  a %.2f  b %.2f  c %.2f  s %.1f   single / octaves >= %.2fx\n", o.N, o.A,
      o.B, o.C, o.S, trials[i].Ratio);
  }
}

// GPU frames: the median time of `frames` frames after two warm-ups, and the
// picture.
double GpuFrames(vtkRenderWindow* window, int frames, vtkSmartPointer<vtkImageData>& picture)
{
  window->Render();
  window->Render();
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    times.push_back(Seconds(start));
  }
  std::sort(times.begin(), times.end());
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  picture = vtkSmartPointer<vtkImageData>::New();
  picture->DeepCopy(grab->GetOutput());
  return times[times.size() / 2];
}

bool Gpu(Scene& scene, const Octaves& octaves, const Options& o, vtkTyndallDisplay* display)
{
  vtkNew<vtkRenderWindow> window;
  display->Attach(window);
  window->SetMultiSamples(0);
  window->SetSize(o.GpuSize, o.GpuSize);
  window->AddRenderer(scene.Renderer);
  vtkSmartPointer<vtkImageData> single, multiple;
  scene.SetOctaves(Octaves{ 1, octaves.A, octaves.B, octaves.C, octaves.S });
  const double t1 = GpuFrames(window, o.Frames, single);
  scene.SetOctaves(octaves);
  const double tN = GpuFrames(window, o.Frames, multiple);
  Approximation cpu;
  if (!RenderReference(scene, octaves, o.GpuSize, cpu))
  {
    return false;
  }
  std::printf("  GPU (AdaptiveETM, %d^2): frame %.4f s single, %.4f s octaves: %.2fx (target <= "
              "1.3x); PSNR against the CPU reference with the octaves %.1f dB\n",
    o.GpuSize, t1, tN, tN / t1, tyndall_test::PSNR(multiple, cpu.Picture));
  window->RemoveRenderer(scene.Renderer);
  return true;
}

void SavePictures(
  const std::string& directory, const std::string& key, const std::vector<vtkImageData*>& pictures)
{
  // Side by side, left to right (8-bit RGB images of one size).
  int dims[3];
  pictures[0]->GetDimensions(dims);
  vtkNew<vtkImageData> row;
  row->SetDimensions(dims[0] * static_cast<int>(pictures.size()), dims[1], 1);
  row->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (size_t p = 0; p < pictures.size(); ++p)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        auto* in = static_cast<unsigned char*>(pictures[p]->GetScalarPointer(i, j, 0));
        auto* out = static_cast<unsigned char*>(
          row->GetScalarPointer(static_cast<int>(p) * dims[0] + i, j, 0));
        std::copy(in, in + 3, out);
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(row);
  const std::string name = directory + "/multiple-scattering-" + key + ".png";
  writer->SetFileName(name.c_str());
  writer->Write();
  std::printf("  pictures (path tracer | single scattering | octaves): %s\n", name.c_str());
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkParticipatingMediumProperty> defaults;
  Octaves octaves = o.Setting;
  if (octaves.N <= 0)
  {
    octaves = Octaves{ defaults->GetScatteringOctaves(), defaults->GetOctaveScattering(),
      defaults->GetOctaveExtinction(), defaults->GetOctaveAnisotropy(),
      defaults->GetOctaveBuildUp() };
  }
  if (octaves.N < 2)
  {
    octaves.N = 4; // the defaults are off: measure the octaves anyway
  }
  std::printf("BenchMultipleScattering: %d x %d pixels, path tracer %d spp, up to %d bounces; "
              "media %d^3; octaves N %d, a %.2f, b %.2f, c %.2f, build-up %.1f; %d threads\n",
    o.Size, o.Size, o.Samples, o.Bounces, o.Resolution, octaves.N, octaves.A, octaves.B, octaves.C,
    octaves.S, vtkSMPTools::GetEstimatedNumberOfThreads());
  Scene dense("dense", tyndall_test::MakeDenseMedium(o.Resolution), 0.9, 1.0);
  Scene thick("thick", tyndall_test::MakeCloud(o.Resolution), 0.5, 4.0);
  Scene cloud("cloud", tyndall_test::MakeCloud(o.Resolution), 0.5, 1.0);
  std::vector<Scene*> scenes = { &dense, &thick, &cloud };
  const char* names[] = { "Dense medium", "Thick cloud (built-in cloud, density x4)",
    "Built-in cloud" };
  vtkNew<vtkTyndallDisplay> display;
  if (o.Gpu && !display->Open())
  {
    std::printf("no display (%s): GPU figures skipped\n", display->GetErrorMessage());
    o.Gpu = false;
  }
  std::vector<Reference> references(scenes.size());
  bool ok = true;
  for (size_t s = 0; s < scenes.size(); ++s)
  {
    Scene& scene = *scenes[s];
    Reference& reference = references[s];
    Approximation one, many;
    if (!TracePaths(scene, o, reference) ||
      !RenderReference(
        scene, Octaves{ 1, octaves.A, octaves.B, octaves.C, octaves.S }, o.Size, one) ||
      !RenderReference(scene, octaves, o.Size, many))
    {
      std::printf("FAILED: a render of %s failed\n", scene.Key.c_str());
      return EXIT_FAILURE;
    }
    const double e1 = tyndall_test::RMS(one.Radiance, reference.Radiance);
    const double eN = tyndall_test::RMS(many.Radiance, reference.Radiance);
    std::printf("\n%s: path tracer %.1f s, mean radiance %.4f (single scattering %.4f, octaves "
                "%.4f), its noise (RMS standard error) %.2e\n",
      names[s], reference.Seconds, Mean(reference.Radiance), Mean(one.Radiance),
      Mean(many.Radiance), reference.Noise);
    std::printf("  error against the path tracer: single scattering RMS %.4e (%.1f dB), octaves "
                "RMS %.4e (%.1f dB): %.2fx lower%s\n",
      e1, PSNR(e1, reference.Peak), eN, PSNR(eN, reference.Peak), e1 / eN,
      s < 2 ? (e1 / eN >= 3.0 ? " (target >= 3x: MET)" : " (target >= 3x: MISSED)") : "");
    std::printf("  8-bit pictures against the path tracer's: single %.1f dB, octaves %.1f dB\n",
      tyndall_test::PSNR(one.Picture, reference.Picture),
      tyndall_test::PSNR(many.Picture, reference.Picture));
    if (!o.Pictures.empty())
    {
      SavePictures(o.Pictures, scene.Key, { reference.Picture, one.Picture, many.Picture });
    }
    if (o.Gpu && !Gpu(scene, octaves, o, display))
    {
      std::printf("FAILED: the GPU render of %s failed\n", scene.Key.c_str());
      ok = false;
    }
    // Not a measurement: the octaves add light and never take it away.
    if (!(Mean(many.Radiance) > Mean(one.Radiance)) || !(Mean(reference.Radiance) > 0.0))
    {
      std::printf("FAILED: the octaves are not brighter than single scattering\n");
      ok = false;
    }
  }
  if (o.Fit)
  {
    std::vector<Scene*> fitted = { &dense, &thick };
    std::vector<Reference> fittedReferences = { references[0], references[1] };
    Fit(fitted, fittedReferences, o.Size);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
