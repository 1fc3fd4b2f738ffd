// A particle cloud's extinction maps: splatting (vtkTransmittanceParticleMapper's
// closed-form coefficients, no grid) against voxelising the particles and
// marching the grid (the same mapper with Splatting off, the grid at several
// resolutions, twice as many light samples as grid samples).
//
// For each way: the time to voxelise (the grid's re-sampling, when the
// particles change: the maps' grid when voxelised, the camera rays' grid
// when splatted), the map build (median over frames whose light moves a
// little, so the maps are rebuilt every frame), their sum (what a frame whose
// particles moved costs for its grid and maps), the frame, and the accuracy
// of the map: the PSNR of the transmittance it reconstructs (at s = 0.05 ..
// 0.95 of every 4th texel each way) against the exact ETM map of the same
// particles (vtkParticleKernel's closed form summed on the CPU, the twin the
// tests check the splats against).
//
// Two scenes:
// - "cloud": the particles seen from the front, lit from the side. The
//   camera rays sample the particles' grid in every way, so the picture's
//   error is mostly theirs; only the map's accuracy is compared.
// - "shadow": the particles above a white ground that receives their shadow
//   (vtkVolumeShadowReceiverPass), seen from under them, so that no camera
//   ray crosses the medium: the picture's error is the maps' alone. Its
//   "picture PSNR" compares the 8-bit ground as drawn with the ground
//   unshadowed (the volume hidden) times the CPU reference's transmittance
//   to the light (vtkSingleScatteringReference::ComputeLightTransmittance,
//   a light step of 0.002), at every 2nd pixel of the lit ground: the
//   issue's "equal PSNR against the reference". The verdict names the
//   cheapest grid within 0.5 dB of the splatted maps' picture.
//
// Run under xvfb-run.
//
// Usage: BenchParticles [--particles N] [--map-size N] [--frames N]
//                       [--scene cloud|shadow|both] [--grids N,N,...]
//                       [--pictures DIR] [--quick]
// --grids: the voxelised ways' grid resolutions, 8 .. 1024; default 64,128,256.
// --pictures: writes the shadow scene's pictures, each way's and the
// reference's, as DIR/particle-shadow-<way>.png (the reference, and the
// picture PSNR, then at every pixel).
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeShadowReceiverPass.h"

#include "TyndallTestImage.h"
#include "TyndallTestParticles.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
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
  bool Cloud = true;
  bool Shadow = true;
  std::vector<int> Grids = { 64, 128, 256 }; // the voxelised ways' grid resolutions
  std::string Pictures;     // where the shadow scene's pictures go (none: not written)
  double LightStep = 0.002; // the CPU reference's light step (the particles' radii: 0.02 .. 0.05)
};

enum class Scene
{
  Cloud,
  Shadow
};

// The shadow scene's ground: a 6 x 6 square at y = -3.4, facing up (the
// particles end above y = -0.85).
const tyndall_test::Ground kGround{ -3.4, -3.0, 3.0 };

struct Row
{
  std::string Name;
  std::string Slug; // in picture file names
  double Voxelise = 0.0;
  double Build = 0.0;
  double Frame = 0.0;
  double Psnr = 0.0;
  double Error = 0.0;
  double PicturePsnr = 0.0; // the shadow scene's ground against the CPU reference
  double Received = 0.0;    // the largest |received fraction - T| there
  bool Culled = false;      // the volume was never ray cast (out of view)
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// The CPU reference's transmittance at the ground points the shadow scene
// compares: computed once, for the first way, and shared by the others (the
// same particles, camera and last light position).
struct GroundReference
{
  std::vector<vtkIdType> Pixels;
  std::vector<double> T; // 3 per pixel
  int Shadowed = 0;      // points with T < 0.9
  double Seconds = 0.0;
  double StepError = 0.0; // the largest change at half the light step (every 32nd point)
};

// The white, purely diffuse ground that receives the particles' shadow, and
// a camera under the particles looking down at it.
void AddGround(vtkRenderer* renderer)
{
  renderer->AddActor(kGround.MakeActor());
  renderer->SetBackground(0.1, 0.1, 0.1);
  vtkNew<vtkVolumeShadowReceiverPass> shadows;
  shadows->Install(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  // Nearly straight down at the shadow of the ball's centre, from low
  // enough that the renderer culls the particles (what --quick checks).
  camera->SetPosition(-1.4, -1.3, -0.4);
  camera->SetFocalPoint(-1.7, kGround.Height, -1.0);
  camera->SetViewUp(0.0, 0.0, -1.0);
  camera->SetViewAngle(60.0);
  camera->SetClippingRange(0.02, 20.0);
}

// The CPU reference's transmittance at every 2nd pixel of the lit ground
// (every pixel when the pictures are written).
void ComputeGroundReference(const Options& options, vtkRenderer* renderer, vtkVolume* volume,
  vtkImageData* lit, GroundReference& ground)
{
  vtkDataArray* b = lit->GetPointData()->GetScalars();
  vtkNew<vtkSingleScatteringReference> reference, finer;
  reference->SetLightStepSize(options.LightStep);
  finer->SetLightStepSize(0.5 * options.LightStep);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const int stride = options.Pictures.empty() ? 2 : 1;
  for (int j = stride - 1; j < options.Size; j += stride)
  {
    for (int i = stride - 1; i < options.Size; i += stride)
    {
      double x[3], T[3], U[3];
      const vtkIdType pixel = static_cast<vtkIdType>(j) * options.Size + i;
      if (!kGround.PixelPoint(renderer, options.Size, i, j, x) ||
        b->GetComponent(pixel, 0) < 100.0 ||
        !reference->ComputeLightTransmittance(renderer, volume, 0, x, T))
      {
        continue;
      }
      ground.Pixels.push_back(pixel);
      ground.T.insert(ground.T.end(), T, T + 3);
      ground.Shadowed += T[0] < 0.9 ? 1 : 0;
      if (ground.Pixels.size() % 32 == 1 &&
        finer->ComputeLightTransmittance(renderer, volume, 0, x, U))
      {
        ground.StepError = std::max(ground.StepError, std::abs(U[0] - T[0]));
      }
    }
  }
  timer->StopTimer();
  ground.Seconds = timer->GetElapsedTime();
}

// The reference picture: the ground unshadowed times the reference's T.
vtkSmartPointer<vtkImageData> ReferencePicture(vtkImageData* lit, const GroundReference& ground)
{
  auto picture = vtkSmartPointer<vtkImageData>::New();
  picture->DeepCopy(lit);
  vtkDataArray* values = picture->GetPointData()->GetScalars();
  for (size_t p = 0; p < ground.Pixels.size(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = values->GetComponent(ground.Pixels[p], c) * ground.T[3 * p + c];
      values->SetComponent(ground.Pixels[p], c, std::round(v));
    }
  }
  return picture;
}

// Writes `picture` as <Pictures>/particle-shadow-<name>.png (nothing without --pictures).
void WritePicture(const Options& options, const std::string& name, vtkImageData* picture)
{
  if (options.Pictures.empty())
  {
    return;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(picture);
  writer->SetFileName((options.Pictures + "/particle-shadow-" + name + ".png").c_str());
  writer->Write();
}

// The shadow scene's picture against the reference: the ground as drawn
// against the ground unshadowed (the volume hidden) times the reference's T.
void ComparePicture(const Options& options, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkVolume* volume, GroundReference& ground, Row& row)
{
  volume->SetVisibility(false);
  window->Render();
  const vtkSmartPointer<vtkImageData> lit = tyndall_test::Grab(window);
  volume->SetVisibility(true);
  window->Render();
  const vtkSmartPointer<vtkImageData> received = tyndall_test::Grab(window);

  if (ground.Pixels.empty())
  {
    ComputeGroundReference(options, renderer, volume, lit, ground);
    WritePicture(options, "reference", ReferencePicture(lit, ground));
  }
  WritePicture(options, row.Slug, received);
  vtkDataArray* a = received->GetPointData()->GetScalars();
  vtkDataArray* b = lit->GetPointData()->GetScalars();
  double sum = 0.0;
  for (size_t p = 0; p < ground.Pixels.size(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double drawn = a->GetComponent(ground.Pixels[p], c);
      const double unshadowed = b->GetComponent(ground.Pixels[p], c);
      const double expected = unshadowed * ground.T[3 * p + c];
      sum += (drawn - expected) * (drawn - expected);
      row.Received = std::max(row.Received, std::abs(drawn / unshadowed - ground.T[3 * p + c]));
    }
  }
  const double mse = sum / std::max<double>(1.0, 3.0 * ground.Pixels.size());
  row.PicturePsnr = 10.0 * std::log10(255.0 * 255.0 / std::max(mse, 1e-12));
}

// A scene: its renderer, ground, camera and sun, in the program's one window
// (one X connection throughout: Xvfb resets when its last client leaves, and
// a window opened during the reset fails, "bad X server connection").
struct Stage
{
  vtkNew<vtkRenderer> Renderer;
  vtkRenderWindow* Window;
  vtkSmartPointer<vtkLight> Sun;
  Scene Kind;
  double Base[3]; // the sun's position before it moves

  Stage(vtkRenderWindow* window, Scene kind)
    : Window(window)
    , Kind(kind)
  {
    // From the side for the cloud, from above for the shadow.
    const double cloud[3] = { 1.0, 0.5, 0.3 }, shadow[3] = { 0.5, 1.0, 0.3 };
    std::copy_n(kind == Scene::Shadow ? shadow : cloud, 3, this->Base);
    this->Sun = tyndall_test::MakeSun(this->Base[0], this->Base[1], this->Base[2]);
    this->Renderer->AddLight(this->Sun);
    if (kind == Scene::Shadow)
    {
      AddGround(this->Renderer);
    }
    else
    {
      tyndall_test::SetTestCamera(this->Renderer);
    }
    this->Window->AddRenderer(this->Renderer);
  }

  ~Stage()
  {
    this->Renderer->ReleaseGraphicsResources(this->Window);
    this->Window->RemoveRenderer(this->Renderer);
  }

  Stage(const Stage&) = delete;
  void operator=(const Stage&) = delete;

  // The sun after `frame` steps (0: where it starts).
  void MoveSun(int frame)
  {
    const double a = 0.005 * frame;
    this->Sun->SetPosition(
      this->Base[0] * std::cos(a), this->Base[1], this->Base[2] + this->Base[0] * std::sin(a));
  }
};

Row Measure(const Options& options, vtkPolyData* particles, bool splat, int grid, Stage& stage,
  GroundReference& ground)
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
  vtkRenderer* renderer = stage.Renderer;
  vtkRenderWindow* window = stage.Window;
  renderer->AddVolume(volume);
  stage.MoveSun(0);

  Row row;
  row.Slug = splat ? "splat" : "grid" + std::to_string(grid);
  row.Name = splat
    ? "splatted, camera grid " + std::to_string(grid) + "^3"
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
  // The grid is re-sampled whenever the particles change: the maps' grid
  // when voxelised, the camera rays' grid when splatted.
  row.Voxelise = mapper->GetLastGridTime();
  std::vector<double> builds, frames;
  vtkNew<vtkTimerLog> timer;
  for (int f = 0; f < options.Frames; ++f)
  {
    stage.MoveSun(f + 1); // the maps are rebuilt
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
  if (stage.Kind == Scene::Shadow)
  {
    row.Culled = mapper->GetLastRayCastPassCount() == 0;
    ComparePicture(options, window, renderer, volume, ground, row);
  }
  renderer->RemoveVolume(volume);
  volume->ReleaseGraphicsResources(window);
  return row;
}

void PrintTable(const std::vector<Row>& rows, bool picture)
{
  std::cout << std::left << std::setw(40) << "maps" << std::right << std::setw(12) << "voxelise"
            << std::setw(12) << "map build" << std::setw(12) << "sum" << std::setw(12) << "frame"
            << std::setw(14) << "map T PSNR" << std::setw(14) << "coef. error"
            << (picture ? "  picture PSNR  largest |dT|" : "") << "\n";
  for (const Row& r : rows)
  {
    std::cout << std::left << std::setw(40) << r.Name << std::right << std::fixed
              << std::setprecision(4) << std::setw(11) << r.Voxelise << "s" << std::setw(11)
              << r.Build << "s" << std::setw(11) << r.Voxelise + r.Build << "s" << std::setw(11)
              << r.Frame << "s" << std::setprecision(1) << std::setw(11) << r.Psnr << " dB"
              << std::scientific << std::setprecision(1) << std::setw(14) << r.Error;
    if (picture)
    {
      std::cout << std::fixed << std::setprecision(1) << std::setw(11) << r.PicturePsnr << " dB"
                << std::setprecision(4) << std::setw(15) << r.Received;
    }
    std::cout << std::defaultfloat << "\n";
  }
  const Row& splat = rows.front();
  for (size_t i = 1; i < rows.size(); ++i)
  {
    const Row& r = rows[i];
    std::cout << std::setprecision(3) << r.Name << ": voxelise + march / (grid + splat) = "
              << (r.Voxelise + r.Build) / std::max(splat.Voxelise + splat.Build, 1e-9)
              << "x (march / splat alone " << r.Build / std::max(splat.Build, 1e-9) << "x), map "
              << r.Psnr << " dB vs " << splat.Psnr << " dB";
    if (picture)
    {
      std::cout << ", picture " << r.PicturePsnr << " dB vs " << splat.PicturePsnr << " dB";
    }
    std::cout << "\n";
  }
}

// The shadow scene's verdict: the cheapest grid whose picture is as close to
// the reference as the splatted maps' (within 0.5 dB).
void PrintVerdict(const std::vector<Row>& rows)
{
  const Row& splat = rows.front();
  const Row* match = nullptr;
  for (size_t i = 1; i < rows.size(); ++i)
  {
    if (rows[i].PicturePsnr >= splat.PicturePsnr - 0.5 &&
      (!match || rows[i].Voxelise + rows[i].Build < match->Voxelise + match->Build))
    {
      match = &rows[i];
    }
  }
  std::cout << std::setprecision(3) << "At the splat's picture PSNR (" << splat.PicturePsnr
            << " dB, within 0.5 dB): ";
  if (match)
  {
    std::cout << match->Name << ", voxelise + march = "
              << (match->Voxelise + match->Build) / std::max(splat.Voxelise + splat.Build, 1e-9)
              << "x the splat's camera grid + map build (march alone "
              << match->Build / std::max(splat.Build, 1e-9) << "x the splat)\n";
  }
  else
  {
    std::cout << "no grid measured reaches it\n";
  }
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--particles" && value)
    {
      options.Particles = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--map-size" && value)
    {
      options.MapSize = std::max(16, std::atoi(argv[++i]));
    }
    else if (a == "--frames" && value)
    {
      options.Frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--scene" && value)
    {
      const std::string scene = argv[++i];
      options.Cloud = scene == "cloud" || scene == "both";
      options.Shadow = scene == "shadow" || scene == "both";
      if (!options.Cloud && !options.Shadow)
      {
        return false;
      }
    }
    else if (a == "--grids" && value)
    {
      options.Grids.clear();
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');)
      {
        const int grid = std::atoi(item.c_str());
        if (grid < 8 || grid > 1024)
        {
          return false;
        }
        options.Grids.push_back(grid);
      }
    }
    else if (a == "--pictures" && value)
    {
      options.Pictures = argv[++i];
    }
    else if (a == "--quick")
    {
      options.Particles = 2000;
      options.MapSize = 256;
      options.Frames = 1;
      options.Size = 64;
      options.Grids = { 64 };
    }
    else
    {
      return false;
    }
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseArguments(argc, argv, options))
  {
    std::cerr << "usage: BenchParticles [--particles N] [--map-size N] [--frames N] "
                 "[--scene cloud|shadow|both] [--grids N,N,...] [--pictures DIR] [--quick]\n";
    return EXIT_FAILURE;
  }
  // Radii 0.02 .. 0.05 in a ball of radius 0.8, densities for an optical
  // depth of about 3 across the ball.
  vtkSmartPointer<vtkPolyData> particles =
    tyndall_test::MakeParticles(options.Particles, 5, 0.8, 0.02, 0.05, 0.4, 1.3);
  std::cout << options.Particles << " particles, ETM with 8 coefficients, " << options.MapSize
            << "^2 map, one directional light, frame " << options.Size << "^2; median of "
            << options.Frames << " frames with the light moving\n\n";
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(options.Size, options.Size);
  bool ok = true;
  for (const Scene scene : { Scene::Cloud, Scene::Shadow })
  {
    const bool shadow = scene == Scene::Shadow;
    if (!(shadow ? options.Shadow : options.Cloud))
    {
      continue;
    }
    std::cout << (shadow ? "Scene \"shadow\": the particles' shadow on the ground, no camera ray "
                           "in the medium\n"
                         : "Scene \"cloud\": the particles seen from the front\n");
    GroundReference ground;
    Stage stage(window, scene);
    std::vector<Row> rows;
    // The splatted maps need no grid; the camera rays sample one (at 128^3
    // for the cloud; the shadow scene's camera never sees the particles, so
    // a 64^3 grid does).
    rows.push_back(Measure(options, particles, true, shadow ? 64 : 128, stage, ground));
    for (int grid : options.Grids)
    {
      rows.push_back(Measure(options, particles, false, grid, stage, ground));
    }
    if (shadow)
    {
      std::cout << "CPU reference: " << ground.Pixels.size() << " ground points ("
                << ground.Shadowed << " with T < 0.9) in " << std::setprecision(3) << ground.Seconds
                << " s; light step " << options.LightStep << ", largest change at half the step "
                << ground.StepError << "\n";
    }
    PrintTable(rows, shadow);
    const Row& splat = rows.front();
    // The splatted map is the closed form (float rounding); in the shadow
    // scene the particles are out of view (culled: their maps built by the
    // receiver pass alone, and still reported) and the ground, partly in
    // shadow, receives within 0.02 of the reference (the bar for
    // surfaces). What --quick checks.
    const bool exact = splat.Psnr > 0.0 && splat.Error < 1e-4;
    std::cout << (exact ? "" : "FAILED: the splatted map is not the closed form\n");
    ok = ok && exact;
    if (shadow)
    {
      PrintVerdict(rows);
      const bool received = ground.Shadowed >= 10 && splat.Received <= 0.02;
      std::cout << (received ? "" : "FAILED: the ground does not receive the splatted shadow\n");
      std::cout << (splat.Culled ? "" : "FAILED: the camera sees the particles\n");
      ok = ok && received && splat.Culled;
    }
    std::cout << "\n";
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
