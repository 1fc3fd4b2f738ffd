// A particle cloud's extinction maps: splatting (vtkTransmittanceParticleMapper's
// closed-form coefficients, no grid) against voxelising the particles and
// marching the grid (the same mapper with Splatting off, the grid at several
// resolutions, twice as many light samples as grid samples).
//
// For each way: the time to voxelise (the grid's re-sampling, when the
// particles change), the map build (median over frames whose light moves a
// little, so the maps are rebuilt every frame), their sum, the frame, and the
// accuracy of the map: the PSNR of the transmittance it reconstructs (at s =
// 0.05 .. 0.95 of every 4th texel each way) against the exact ETM map of the
// same particles (vtkParticleKernel's closed form summed on the CPU, the
// twin the tests check the splats against). Run under xvfb-run.
//
// Usage: BenchParticles [--particles N] [--map-size N] [--frames N] [--quick]
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkVolume.h"

#include "TyndallTestParticles.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  int Particles = 100000;
  int MapSize = 256;
  int Frames = 5;
  int Size = 256;
};

struct Row
{
  std::string Name;
  double Voxelise = 0.0;
  double Build = 0.0;
  double Frame = 0.0;
  double Psnr = 0.0;
  double Error = 0.0;
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

Row Measure(const Options& options, vtkPolyData* particles, bool splat, int grid)
{
  vtkNew<vtkTransmittanceParticleMapper> mapper;
  mapper->SetInputData(particles);
  mapper->SetTransmittanceMethodToETM();
  mapper->SetNumberOfCoefficients(8);
  mapper->SetTransmittanceMapSize(options.MapSize);
  mapper->SetSplatting(splat);
  mapper->SetGridResolution(grid);
  mapper->SetLightSampleCount(2 * grid);
  mapper->JitterOff();
  auto property = tyndall_test::MakeCloudProperty();
  property->SetAmbientIntensity(0.1);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkSmartPointer<vtkLight> sun = tyndall_test::MakeSun(1.0, 0.5, 0.3);
  renderer->AddLight(sun);
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(options.Size, options.Size);
  window->AddRenderer(renderer);

  Row row;
  row.Name = splat
    ? "splatted (no grid for the maps)"
    : "grid " + std::to_string(grid) + "^3, " + std::to_string(2 * grid) + " light samples";
  window->Render(); // the grid, the upload, the shaders
  static bool reported = false;
  if (!reported)
  {
    // Which OpenGL: llvmpipe (the CPU) or a GPU.
    const std::string caps = window->ReportCapabilities();
    const size_t at = caps.find("OpenGL renderer string:");
    std::cout << caps.substr(at, caps.find('\n', at) - at) << "\n\n";
    reported = true;
  }
  row.Voxelise = splat ? 0.0 : mapper->GetLastGridTime();
  std::vector<double> builds, frames;
  vtkNew<vtkTimerLog> timer;
  for (int f = 0; f < options.Frames; ++f)
  {
    const double a = 0.005 * (f + 1);
    sun->SetPosition(std::cos(a), 0.5, 0.3 + std::sin(a)); // the maps are rebuilt
    timer->StartTimer();
    window->Render();
    window->WaitForCompletion();
    timer->StopTimer();
    frames.push_back(timer->GetElapsedTime());
    builds.push_back(mapper->GetLastMapBuildTime());
  }
  row.Build = Median(builds);
  row.Frame = Median(frames);
  vtkNew<vtkImageData> map;
  if (mapper->GetTransmittanceMap(0, map))
  {
    const tyndall_test::ExactMap exact =
      tyndall_test::ExactEtmMap(mapper, renderer, volume, particles, map, 4);
    row.Psnr = exact.TransmittancePSNR(map);
    row.Error = exact.LargestError(map);
  }
  return row;
}
}

int main(int argc, char* argv[])
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--particles" && i + 1 < argc)
    {
      options.Particles = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--map-size" && i + 1 < argc)
    {
      options.MapSize = std::max(16, std::atoi(argv[++i]));
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      options.Frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--quick")
    {
      options.Particles = 2000;
      options.MapSize = 64;
      options.Frames = 1;
      options.Size = 64;
    }
    else
    {
      std::cerr << "usage: BenchParticles [--particles N] [--map-size N] [--frames N] [--quick]\n";
      return EXIT_FAILURE;
    }
  }
  // Radii 0.02 .. 0.05 in a ball of radius 0.8, densities for an optical
  // depth of about 3 across the ball.
  vtkSmartPointer<vtkPolyData> particles =
    tyndall_test::MakeParticles(options.Particles, 5, 0.8, 0.02, 0.05, 0.4, 1.3);
  std::cout << options.Particles << " particles, ETM with 8 coefficients, " << options.MapSize
            << "^2 map, one directional light, frame " << options.Size << "^2; median of "
            << options.Frames << " frames with the light moving\n\n";
  std::vector<Row> rows;
  rows.push_back(Measure(options, particles, true, 128));
  for (int grid : { 64, 128, 256 })
  {
    rows.push_back(Measure(options, particles, false, grid));
  }
  std::cout << std::left << std::setw(40) << "maps" << std::right << std::setw(12) << "voxelise"
            << std::setw(12) << "map build" << std::setw(12) << "sum" << std::setw(12) << "frame"
            << std::setw(14) << "map T PSNR" << std::setw(14) << "coef. error"
            << "\n";
  for (const Row& r : rows)
  {
    std::cout << std::left << std::setw(40) << r.Name << std::right << std::fixed
              << std::setprecision(4) << std::setw(11) << r.Voxelise << "s" << std::setw(11)
              << r.Build << "s" << std::setw(11) << r.Voxelise + r.Build << "s" << std::setw(11)
              << r.Frame << "s" << std::setprecision(1) << std::setw(11) << r.Psnr << " dB"
              << std::scientific << std::setprecision(1) << std::setw(14) << r.Error
              << std::defaultfloat << "\n";
  }
  const Row& splat = rows.front();
  for (size_t i = 1; i < rows.size(); ++i)
  {
    std::cout << std::setprecision(3) << rows[i].Name << ": voxelise + march / splat = "
              << (rows[i].Voxelise + rows[i].Build) / std::max(splat.Build, 1e-9)
              << "x (march alone " << rows[i].Build / std::max(splat.Build, 1e-9) << "x), "
              << rows[i].Psnr << " dB vs " << splat.Psnr << " dB\n";
  }
  // The splatted map is the closed form (float rounding): what --quick checks.
  const bool exact = splat.Psnr > 0.0 && splat.Error < 1e-4;
  std::cout << (exact ? "" : "FAILED: the splatted map is not the closed form\n");
  return exact ? EXIT_SUCCESS : EXIT_FAILURE;
}
