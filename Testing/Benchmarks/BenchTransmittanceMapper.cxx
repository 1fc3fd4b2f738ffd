// Benchmark of vtkTransmittanceVolumeMapper: frame time of every
// transmittance method with cached maps, map build time, PSNR against the
// CPU reference (vtkSingleScatteringReference), and the ratios the project
// sets bars on. Prints figures; it is not a test.
//
//   BenchTransmittanceMapper [--quick] [--size N] [--resolution N]
//     [--coefficients N] [--map-size N] [--frames N] [--reference-size N]
//     [--light-samples N]
//
// Defaults follow the setting: a 512 x 512 image of the built-in
// cloud at 256^3, 8 coefficients, 512^2 maps, brute force with 256 light
// samples. PSNR is measured at --reference-size (default 128) because the
// CPU reference is slow; the same scene at the same size for both.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
struct Options
{
  int Size = 512;
  int Resolution = 256;
  int Coefficients = 8;
  int MapSize = 512;
  int Frames = 3;
  int ReferenceSize = 128;
  int LightSamples = 256;
};

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
};

Scene MakeScene(vtkImageData* data, double peakOpacity, const Options& options)
{
  Scene scene;
  scene.Mapper = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
  scene.Mapper->SetInputData(data);
  scene.Mapper->SetNumberOfCoefficients(options.Coefficients);
  scene.Mapper->SetTransmittanceMapSize(options.MapSize);
  scene.Mapper->SetLightSampleCount(options.LightSamples);
  scene.Mapper->SetAmbientIntensity(0.1);
  scene.Mapper->JitterOff();
  scene.Volume = vtkSmartPointer<vtkVolume>::New();
  scene.Volume->SetMapper(scene.Mapper);
  scene.Volume->SetProperty(tyndall_test::MakeCloudProperty(peakOpacity));
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Renderer->AddVolume(scene.Volume);
  scene.Renderer->SetBackground(0.2, 0.3, 0.45);
  scene.Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  tyndall_test::SetTestCamera(scene.Renderer);
  scene.Window = vtkSmartPointer<vtkRenderWindow>::New();
  scene.Window->SetMultiSamples(0);
  scene.Window->SetOffScreenRendering(1);
  scene.Window->AddRenderer(scene.Renderer);
  return scene;
}

// Seconds of one finished frame.
double TimeFrame(vtkRenderWindow* window)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  vtkOpenGLRenderWindow::SafeDownCast(window)->WaitForCompletion();
  timer->StopTimer();
  return timer->GetElapsedTime();
}

vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

bool ParseArguments(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&](int& value)
    {
      if (i + 1 >= argc)
      {
        return false;
      }
      value = std::atoi(argv[++i]);
      return value > 0;
    };
    bool ok = true;
    if (arg == "--quick")
    {
      o.Size = 128;
      o.Resolution = 64;
      o.MapSize = 128;
      o.Frames = 1;
      o.ReferenceSize = 64;
      o.LightSamples = 64;
    }
    else if (arg == "--size")
      ok = next(o.Size);
    else if (arg == "--resolution")
      ok = next(o.Resolution);
    else if (arg == "--coefficients")
      ok = next(o.Coefficients);
    else if (arg == "--map-size")
      ok = next(o.MapSize);
    else if (arg == "--frames")
      ok = next(o.Frames);
    else if (arg == "--reference-size")
      ok = next(o.ReferenceSize);
    else if (arg == "--light-samples")
      ok = next(o.LightSamples);
    else
      ok = false;
    if (!ok)
    {
      std::cerr << "usage: BenchTransmittanceMapper [--quick] [--size N] [--resolution N] "
                   "[--coefficients N] [--map-size N] [--frames N] [--reference-size N] "
                   "[--light-samples N]\n";
      return false;
    }
  }
  return true;
}

const int kMethods[] = { vtkTransmittanceVolumeMapper::NONE,
  vtkTransmittanceVolumeMapper::BRUTE_FORCE, vtkTransmittanceVolumeMapper::TFM,
  vtkTransmittanceVolumeMapper::ADAPTIVE_TFM, vtkTransmittanceVolumeMapper::ETM,
  vtkTransmittanceVolumeMapper::ADAPTIVE_ETM };

// Runs every method on one medium and prints a table; returns the frame
// times and PSNRs by method.
void RunMedium(const char* name, vtkImageData* data, double peakOpacity, const Options& o,
  std::vector<double>& frame, std::vector<double>& psnr)
{
  std::cout << "\n## " << name << "\n\n";
  // The CPU reference at the reference size.
  Scene reference = MakeScene(data, peakOpacity, o);
  reference.Window->SetSize(o.ReferenceSize, o.ReferenceSize);
  reference.Window->Render();
  vtkNew<vtkSingleScatteringReference> cpu;
  cpu->SetAmbientIntensity(0.1);
  // Camera steps as fine as the mapper's (half a voxel); light steps of two
  // voxels keep the reference affordable at 256^3 (its light integral
  // converges as the square of the step: see TestSingleScatteringReference).
  cpu->SetLightStepSize(4.0 / (o.Resolution - 1));
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  cpu->Render(reference.Renderer, reference.Volume, o.ReferenceSize, o.ReferenceSize);
  timer->StopTimer();
  vtkImageData* cpuImage = cpu->Composite(reference.Renderer->GetBackground());
  std::cout << "CPU reference: " << o.ReferenceSize << " x " << o.ReferenceSize << " in "
            << timer->GetElapsedTime() << " s\n\n";

  Scene timing = MakeScene(data, peakOpacity, o);
  timing.Window->SetSize(o.Size, o.Size);
  std::cout << "| method | frame (s) | map build (s) | frame / None | PSNR vs CPU (dB) |\n"
            << "|---|---|---|---|---|\n";
  frame.assign(6, 0.0);
  psnr.assign(6, 0.0);
  for (int m : kMethods)
  {
    timing.Mapper->SetTransmittanceMethod(m);
    TimeFrame(timing.Window); // builds maps, compiles shaders
    const double build =
      vtkTransmittanceMapMath::GetMethodName(m) && m >= vtkTransmittanceVolumeMapper::TFM
      ? timing.Mapper->GetLastMapBuildTime()
      : 0.0;
    double best = 1e30;
    for (int f = 0; f < o.Frames; ++f)
    {
      timing.Mapper->Modified(); // a new frame, same maps
      best = std::min(best, TimeFrame(timing.Window));
    }
    frame[m] = best;
    reference.Mapper->SetTransmittanceMethod(m);
    reference.Window->Render();
    psnr[m] = tyndall_test::PSNR(Grab(reference.Window), cpuImage);
    std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | " << std::setprecision(4)
              << best << " | " << build << " | " << best / frame[0] << " | " << psnr[m] << " |\n";
  }
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!ParseArguments(argc, argv, o))
  {
    return 2;
  }
  std::cout << "# vtkTransmittanceVolumeMapper benchmark\n\n"
            << "image " << o.Size << "^2, volume " << o.Resolution << "^3, " << o.Coefficients
            << " coefficients, maps " << o.MapSize << "^2, brute force " << o.LightSamples
            << " light samples, best of " << o.Frames << " frames; PSNR at " << o.ReferenceSize
            << "^2 against vtkSingleScatteringReference; " << std::thread::hardware_concurrency()
            << " CPU threads\n";
  {
    Scene probe = MakeScene(tyndall_test::MakeCloud(8), 0.5, o);
    probe.Window->SetSize(16, 16);
    probe.Window->Render();
    // The renderer and version lines of VTK's capability report.
    std::istringstream report(
      vtkOpenGLRenderWindow::SafeDownCast(probe.Window)->ReportCapabilities());
    std::string line;
    while (std::getline(report, line))
    {
      if (line.rfind("OpenGL renderer", 0) == 0 || line.rfind("OpenGL version", 0) == 0)
      {
        std::cout << line << "\n";
      }
    }
  }

  std::vector<double> cloudFrame, cloudPSNR, denseFrame, densePSNR;
  RunMedium("Built-in cloud", tyndall_test::MakeCloud(o.Resolution), 0.5, o, cloudFrame, cloudPSNR);
  RunMedium(
    "Dense medium", tyndall_test::MakeDenseMedium(o.Resolution), 0.9, o, denseFrame, densePSNR);

  using M = vtkTransmittanceVolumeMapper;
  std::cout << "\n## Bars\n\n";
  for (int m : { M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
  {
    const double ratio = cloudFrame[m] / cloudFrame[M::NONE];
    std::cout << "- " << vtkTransmittanceMapMath::GetMethodName(m)
              << " frame <= 1.5x None: " << (ratio <= 1.5 ? "PASS" : "MISS") << " (" << ratio
              << "x)\n";
  }
  const double bruteOverETM = cloudFrame[M::BRUTE_FORCE] / cloudFrame[M::ETM];
  std::cout << "- BruteForce (" << o.LightSamples
            << " samples) >= 10x ETM: " << (bruteOverETM >= 10.0 ? "PASS" : "MISS") << " ("
            << bruteOverETM << "x)\n";
  std::cout << "- AdaptiveETM PSNR >= 40 dB on the cloud: "
            << (cloudPSNR[M::ADAPTIVE_ETM] >= 40.0 ? "PASS" : "MISS") << " ("
            << cloudPSNR[M::ADAPTIVE_ETM] << " dB)\n";
  std::cout << "- AdaptiveETM PSNR >= 40 dB on the dense medium: "
            << (densePSNR[M::ADAPTIVE_ETM] >= 40.0 ? "PASS" : "MISS") << " ("
            << densePSNR[M::ADAPTIVE_ETM] << " dB)\n";
  return EXIT_SUCCESS;
}
