// Benchmark of vtkTransmittanceVolumeMapper: frame time of every
// transmittance method with cached maps, map build time, PSNR against the
// CPU reference (vtkSingleScatteringReference), and the ratios the project
// sets bars on. Prints figures; it is not a test.
//
//   BenchTransmittanceMapper [--quick] [--size N] [--resolution N]
//     [--coefficients N] [--map-size N] [--frames N] [--reference-size N]
//     [--light-samples N] [--volume FILE [--shift S] [--preset NAME] [--y-up]]...
//     [--export DIR]
//
// Defaults follow the setting: a 512 x 512 image of the built-in
// cloud at 256^3, 8 coefficients, 512^2 maps, brute force with 256 light
// samples. PSNR is measured at --reference-size (default 128) because the
// CPU reference is slow; the same scene at the same size for both.
//
// Per medium, a second table measures empty-space skipping off against on
// in the same run (frame, map build, the grid's cost, picture difference),
// a third the transmittance cache off against on (frame, the cache's build,
// PSNR against the CPU reference, picture difference; the method tables
// above are drawn with the cache, the mapper's default, and their map
// build column is the maps alone), a fourth a coloured extinction against
// the grey medium (frame, map build, PSNR against the CPU reference of the
// coloured medium); on the cloud, a table of the frame rate while dragging the
// camera (interactive level of detail, shadows on); last, several volumes: two
// clouds side by side lit alone against the scene's shared maps (builds,
// frame, PSNR against the CPU reference of the scene).
//
// Media: the built-in cloud, a dense medium, sparse blobs (six Gaussian
// blobs, most of the box empty), and one more per --volume: a
// data file (any input tyndall-render reads; the report adds a CT volume and
// a smoke simulation), its scalars shifted by S (e.g. -1024 to turn raw CT
// numbers into Hounsfield units; default 0), coloured by a transfer-function
// preset (default CT) with opacities per mean voxel spacing, and seen by a
// camera fitted to its bounds: from the front (-y) with z up (the tomography
// convention), or with --y-up from +z with y up (simulations, OpenVDB).
// --shift, --preset and --y-up apply to the --volume before them.
//
// --export DIR writes, per medium, what another renderer needs to draw the
// same scene and be compared with the same reference: the volume
// (<key>.vti), the CPU reference (<key>-reference.png), Tyndall's
// AdaptiveETM and BruteForce images at the reference size, and the scene
// (<key>-scene.json: camera, light, transfer functions, sample distance,
// image sizes, Tyndall's figures). Documentation/scripts/
// paraview_volumetric_shadows.py reads it.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkImageShiftScale.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTransferFunctionPresets.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDisplay.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkVolume.h"
#include "vtkVolumeFileReader.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLImageDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"
#include "TyndallTestTwoClouds.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
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
  int CacheSize = 256; // the mapper's TransmittanceCacheSize (its default)
  struct Volume
  {
    std::string Path;
    double Shift = 0.0;
    std::string Preset = "CT";
    bool YUp = false;
  };
  std::vector<Volume> Volumes;
  std::string Export;
};

const double kAmbient = 0.1;
const double kBackground[3] = { 0.2, 0.3, 0.45 };
const double kSunFrom[3] = { 1.0, 0.5, 0.3 };

// One medium of the benchmark.
struct Medium
{
  std::string Key;  // file names of --export
  std::string Name; // table heading
  vtkSmartPointer<vtkImageData> Data;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;
  bool FitCamera = false; // data volumes: a camera fitted to the bounds
  bool YUp = false;       // with FitCamera: seen from +z, y up
};

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
};

// The X connection every window uses, opened patiently (vtkTyndallDisplay).
vtkTyndallDisplay* TheDisplay = nullptr;

double MinimumSpacing(vtkImageData* data)
{
  double spacing[3];
  data->GetSpacing(spacing);
  return std::min({ std::fabs(spacing[0]), std::fabs(spacing[1]), std::fabs(spacing[2]) });
}

Scene MakeScene(const Medium& medium, const Options& options)
{
  Scene scene;
  scene.Mapper = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
  scene.Mapper->SetInputData(medium.Data);
  scene.Mapper->SetNumberOfCoefficients(options.Coefficients);
  scene.Mapper->SetTransmittanceMapSize(options.MapSize);
  scene.Mapper->SetLightSampleCount(options.LightSamples);
  scene.Mapper->SetTransmittanceCacheSize(options.CacheSize);
  scene.Mapper->JitterOff();
  scene.Volume = vtkSmartPointer<vtkVolume>::New();
  scene.Volume->SetMapper(scene.Mapper);
  scene.Volume->SetProperty(medium.Property);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Renderer->AddVolume(scene.Volume);
  scene.Renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
  scene.Renderer->AddLight(tyndall_test::MakeSun(kSunFrom[0], kSunFrom[1], kSunFrom[2]));
  if (medium.FitCamera)
  {
    // A view from the front (-y) with z up, or from +z with y up, fitted to
    // the data.
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    if (medium.YUp)
    {
      camera->SetPosition(0.0, 0.0, 1.0);
      camera->SetViewUp(0.0, 1.0, 0.0);
    }
    else
    {
      camera->SetPosition(0.0, -1.0, 0.0);
      camera->SetViewUp(0.0, 0.0, 1.0);
    }
    scene.Renderer->ResetCamera(medium.Data->GetBounds());
  }
  else
  {
    tyndall_test::SetTestCamera(scene.Renderer);
  }
  scene.Window = vtkSmartPointer<vtkRenderWindow>::New();
  TheDisplay->Attach(scene.Window);
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

bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
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
    auto text = [&](std::string& value)
    {
      if (i + 1 >= argc)
      {
        return false;
      }
      value = argv[++i];
      return !value.empty();
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
    else if (arg == "--cache-size")
      ok = next(o.CacheSize) && o.CacheSize >= 16 && o.CacheSize <= 1024;
    else if (arg == "--volume")
    {
      o.Volumes.emplace_back();
      ok = text(o.Volumes.back().Path);
    }
    else if (arg == "--preset")
      ok = !o.Volumes.empty() && text(o.Volumes.back().Preset);
    else if (arg == "--y-up")
      ok = !o.Volumes.empty() && (o.Volumes.back().YUp = true);
    else if (arg == "--export")
      ok = text(o.Export);
    else if (arg == "--shift")
    {
      std::string value;
      char* end = nullptr;
      ok = !o.Volumes.empty() && text(value);
      if (ok)
      {
        double& shift = o.Volumes.back().Shift;
        shift = std::strtod(value.c_str(), &end);
        ok = end && *end == '\0' && std::isfinite(shift);
      }
    }
    else
      ok = false;
    if (!ok)
    {
      std::cerr << "usage: BenchTransmittanceMapper [--quick] [--size N] [--resolution N] "
                   "[--coefficients N] [--map-size N] [--frames N] [--reference-size N] "
                   "[--light-samples N] [--cache-size N (16..1024)] "
                   "[--volume FILE [--shift S] [--preset NAME] "
                   "[--y-up]]... [--export DIR]\n"
                   "(--shift, --preset and --y-up follow the --volume they apply to)\n";
      return false;
    }
  }
  return true;
}

const int kMethods[] = { vtkTransmittanceVolumeMapper::NONE,
  vtkTransmittanceVolumeMapper::BRUTE_FORCE, vtkTransmittanceVolumeMapper::TFM,
  vtkTransmittanceVolumeMapper::ADAPTIVE_TFM, vtkTransmittanceVolumeMapper::ETM,
  vtkTransmittanceVolumeMapper::ADAPTIVE_ETM };

// JSON helpers for --export.
std::string JsonArray(const double* v, int n)
{
  std::ostringstream s;
  s << std::setprecision(17) << "[";
  for (int i = 0; i < n; ++i)
  {
    s << (i ? ", " : "") << v[i];
  }
  s << "]";
  return s.str();
}

std::string JsonNodes(vtkPiecewiseFunction* f)
{
  std::ostringstream s;
  s << "[";
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double node[4]; // x, y, midpoint, sharpness
    f->GetNodeValue(i, node);
    s << (i ? ", " : "") << JsonArray(node, 4);
  }
  s << "]";
  return s.str();
}

std::string JsonNodes(vtkColorTransferFunction* f)
{
  std::ostringstream s;
  s << "[";
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double node[6]; // x, r, g, b, midpoint, sharpness
    f->GetNodeValue(i, node);
    s << (i ? ", " : "") << JsonArray(node, 6);
  }
  s << "]";
  return s.str();
}

struct Figures
{
  std::vector<double> Frame, Build, PSNR;
};

// Writes the scene of `medium` for another renderer (see the header).
bool ExportScene(const Medium& medium, const Scene& scene, const Options& o, vtkImageData* cpuImage,
  const Figures& figures, double referenceSeconds)
{
  const std::string base = o.Export + "/" + medium.Key;
  vtkNew<vtkXMLImageDataWriter> volumeWriter;
  volumeWriter->SetInputData(medium.Data);
  volumeWriter->SetFileName((base + ".vti").c_str());
  volumeWriter->SetDataModeToAppended();
  volumeWriter->EncodeAppendedDataOff();
  if (!volumeWriter->Write() || !WritePNG(cpuImage, base + "-reference.png"))
  {
    return false;
  }
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  vtkVolumeProperty* property = medium.Property;
  vtkSmartPointer<vtkLight> sun = tyndall_test::MakeSun(kSunFrom[0], kSunFrom[1], kSunFrom[2]);
  std::ofstream json(base + "-scene.json");
  json << std::setprecision(17) << "{\n"
       << "  \"name\": \"" << medium.Name << "\",\n"
       << "  \"volume\": \"" << medium.Key << ".vti\",\n"
       << "  \"reference\": \"" << medium.Key << "-reference.png\",\n"
       << "  \"reference_seconds\": " << referenceSeconds << ",\n"
       << "  \"size\": " << o.Size << ",\n"
       << "  \"reference_size\": " << o.ReferenceSize << ",\n"
       << "  \"frames\": " << o.Frames << ",\n"
       << "  \"background\": " << JsonArray(kBackground, 3) << ",\n"
       << "  \"camera\": {\"position\": " << JsonArray(camera->GetPosition(), 3)
       << ", \"focal_point\": " << JsonArray(camera->GetFocalPoint(), 3)
       << ", \"view_up\": " << JsonArray(camera->GetViewUp(), 3)
       << ", \"view_angle\": " << camera->GetViewAngle() << "},\n"
       << "  \"light\": {\"position\": " << JsonArray(sun->GetPosition(), 3)
       << ", \"focal_point\": " << JsonArray(sun->GetFocalPoint(), 3)
       << ", \"color\": " << JsonArray(sun->GetDiffuseColor(), 3)
       << ", \"intensity\": " << sun->GetIntensity() << ", \"positional\": false},\n"
       << "  \"light_scale\": " << medium.Property->GetLightScale() << ",\n"
       << "  \"ambient\": " << kAmbient << ",\n"
       << "  \"anisotropy\": " << medium.Property->GetScatteringAnisotropy() << ",\n"
       << "  \"sample_distance\": " << 0.5 * MinimumSpacing(medium.Data) << ",\n"
       << "  \"scalar_opacity_unit_distance\": " << property->GetScalarOpacityUnitDistance()
       << ",\n"
       << "  \"opacity\": " << JsonNodes(property->GetScalarOpacity()) << ",\n"
       << "  \"color\": " << JsonNodes(property->GetRGBTransferFunction()) << ",\n"
       << "  \"tyndall\": {";
  for (int m : kMethods)
  {
    json << (m ? ", " : "") << "\"" << vtkTransmittanceMapMath::GetMethodName(m)
         << "\": {\"frame\": " << figures.Frame[m] << ", \"map_build\": " << figures.Build[m]
         << ", \"psnr\": " << figures.PSNR[m] << "}";
  }
  json << "}\n}\n";
  return static_cast<bool>(json);
}

// Empty-space skipping off against on, in one run: frame and map-build
// times of None and AdaptiveETM, the grid's cost, and how far apart the
// pictures are.
void MeasureSkipping(Scene& timing, const Options& o)
{
  using M = vtkTransmittanceVolumeMapper;
  std::cout << "\nEmpty-space skipping (off -> on, same run; blocks of 8^3 voxels):\n\n"
            << "| method | frame off (s) | frame on (s) | speed-up | map build off (s) | "
               "map build on (s) | largest pixel difference |\n"
            << "|---|---|---|---|---|---|---|\n";
  for (int m : { M::NONE, M::ADAPTIVE_ETM })
  {
    timing.Mapper->SetTransmittanceMethod(m);
    double frame[2], build[2];
    vtkSmartPointer<vtkImageData> image[2];
    for (int skip = 0; skip < 2; ++skip)
    {
      timing.Mapper->SetEmptySpaceSkipping(skip != 0);
      TimeFrame(timing.Window); // compiles the variant, builds the maps
      build[skip] = m == M::NONE ? 0.0 : timing.Mapper->GetLastMapBuildTime();
      image[skip] = tyndall_test::Grab(timing.Window);
      frame[skip] = std::numeric_limits<double>::infinity();
      for (int f = 0; f < o.Frames; ++f)
      {
        timing.Mapper->Modified();
        frame[skip] = std::min(frame[skip], TimeFrame(timing.Window));
      }
    }
    std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | " << std::setprecision(4)
              << frame[0] << " | " << frame[1] << " | " << frame[0] / frame[1] << "x | " << build[0]
              << " | " << build[1] << " | " << tyndall_test::MaxDifference(image[0], image[1])
              << "/255 |\n";
  }
  std::cout << "\nThe grid: " << std::setprecision(3)
            << 100.0 * timing.Mapper->GetEmptyBlockFraction() << " % of blocks empty, built in "
            << 1000.0 * timing.Mapper->GetLastEmptySpaceGridTime()
            << " ms (block ranges when the scalars change, majorants when the transfer "
               "functions do).\n";
}

// The transmittance cache off against on, in one run: frame time, the
// cache's build time, PSNR against the CPU reference and the largest pixel
// difference, for the map methods the report compares.
void MeasureCache(Scene& timing, Scene& reference, vtkImageData* cpuImage, const Options& o)
{
  using M = vtkTransmittanceVolumeMapper;
  std::cout << "\nTransmittance cache (off -> on, same run; lattice of "
            << timing.Mapper->GetTransmittanceCacheSize() << " texels on the longest side):\n\n"
            << "| method | frame off (s) | frame on (s) | speed-up | cache build (s) | "
               "PSNR vs CPU off (dB) | PSNR vs CPU on (dB) | largest pixel difference |\n"
            << "|---|---|---|---|---|---|---|---|\n";
  for (int m : { M::TFM, M::ADAPTIVE_ETM })
  {
    timing.Mapper->SetTransmittanceMethod(m);
    reference.Mapper->SetTransmittanceMethod(m);
    double frame[2], psnr[2], build = 0.0;
    vtkSmartPointer<vtkImageData> image[2];
    for (int cache = 0; cache < 2; ++cache)
    {
      timing.Mapper->SetTransmittanceCache(cache != 0);
      reference.Mapper->SetTransmittanceCache(cache != 0);
      TimeFrame(timing.Window); // compiles the variant, builds the cache
      if (cache)
      {
        build = timing.Mapper->GetLastTransmittanceCacheBuildTime();
      }
      image[cache] = tyndall_test::Grab(timing.Window);
      frame[cache] = std::numeric_limits<double>::infinity();
      for (int f = 0; f < o.Frames; ++f)
      {
        timing.Mapper->Modified();
        frame[cache] = std::min(frame[cache], TimeFrame(timing.Window));
      }
      reference.Window->Render();
      psnr[cache] = tyndall_test::PSNR(tyndall_test::Grab(reference.Window), cpuImage);
    }
    std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | " << std::setprecision(4)
              << frame[0] << " | " << frame[1] << " | " << frame[0] / frame[1] << "x | " << build
              << " | " << psnr[0] << " | " << psnr[1] << " | "
              << tyndall_test::MaxDifference(image[0], image[1]) << "/255 |\n";
  }
  timing.Mapper->TransmittanceCacheOn();
  reference.Mapper->TransmittanceCacheOn();
}

// A coloured extinction (ExtinctionColor 0.25 0.6 1: blue the densest
// channel) against the grey medium of the method table, same run: frame,
// map build (TFM's maps per channel, ETM's one set), PSNR against the CPU
// reference of the chromatic medium.
void MeasureChromatic(
  const Medium& medium, Scene& timing, Scene& reference, const Figures& grey, const Options& o)
{
  using M = vtkTransmittanceVolumeMapper;
  const double color[3] = { 0.25, 0.6, 1.0 };
  medium.Property->SetExtinctionColor(color);
  vtkNew<vtkSingleScatteringReference> cpu;
  cpu->SetLightStepSize(2.0 * MinimumSpacing(medium.Data));
  cpu->Render(reference.Renderer, reference.Volume, o.ReferenceSize, o.ReferenceSize);
  vtkImageData* cpuImage = cpu->Composite(reference.Renderer->GetBackground());
  std::cout << "\nColoured extinction (" << color[0] << " " << color[1] << " " << color[2]
            << ") against the grey medium above, same run:\n\n"
            << "| method | frame grey (s) | frame coloured (s) | ratio | map build grey (s) | map "
               "build coloured (s) | PSNR vs CPU coloured (dB) |\n"
            << "|---|---|---|---|---|---|---|\n";
  for (int m : { M::BRUTE_FORCE, M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
  {
    timing.Mapper->SetTransmittanceMethod(m);
    reference.Mapper->SetTransmittanceMethod(m);
    TimeFrame(timing.Window); // compiles the variant, builds the maps
    const double build = m >= M::TFM ? timing.Mapper->GetLastMapBuildTime() : 0.0;
    double frame = std::numeric_limits<double>::infinity();
    for (int f = 0; f < o.Frames; ++f)
    {
      timing.Mapper->Modified();
      frame = std::min(frame, TimeFrame(timing.Window));
    }
    reference.Window->Render();
    const double psnr = tyndall_test::PSNR(tyndall_test::Grab(reference.Window), cpuImage);
    std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | " << std::setprecision(4)
              << grey.Frame[m] << " | " << frame << " | " << frame / grey.Frame[m] << "x | "
              << grey.Build[m] << " | " << build << " | " << psnr << " |\n";
  }
  medium.Property->SetExtinctionColor(1.0, 1.0, 1.0);
}

// Dragging the camera as VTK's interactor does (desired update rate 10
// frames per second, then the still rate): frames per second while
// dragging, with AdaptiveETM shadows, and whether the still frame after it
// is the picture from before.
void MeasureInteraction(const Medium& medium, const Options& o)
{
  Scene scene = MakeScene(medium, o);
  scene.Window->SetSize(o.Size, o.Size);
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
  TimeFrame(scene.Window); // builds the maps
  const double still = TimeFrame(scene.Window);
  vtkSmartPointer<vtkImageData> before = tyndall_test::Grab(scene.Window);
  const int builds = scene.Mapper->GetMapBuildCount();
  const double rate = 10.0;
  scene.Window->SetDesiredUpdateRate(rate);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const int frames = 20;
  double total = 0.0;
  for (int f = 0; f < frames; ++f)
  {
    camera->Azimuth(f < frames / 2 ? 2.0 : -2.0);
    total += TimeFrame(scene.Window);
  }
  const int reduction = scene.Mapper->GetLastImageReduction();
  const double stepScale = scene.Mapper->GetLastStepScale();
  scene.Window->SetDesiredUpdateRate(0.0001);
  TimeFrame(scene.Window);
  std::cout << "\n## Interaction (" << medium.Name << ", " << o.Size << "^2, AdaptiveETM)\n\n"
            << "| still frame (s) | frames per second while dragging (asked: " << rate
            << ") | image reduction | step scale | map builds while dragging | still frame "
               "after the drag vs before |\n"
            << "|---|---|---|---|---|---|\n"
            << "| " << std::setprecision(4) << still << " | " << frames / total << " | 1/"
            << reduction << " | " << stepScale << " | " << scene.Mapper->GetMapBuildCount() - builds
            << " | largest difference "
            << tyndall_test::MaxDifference(tyndall_test::Grab(scene.Window), before) << "/255 |\n";
}

// The two-cloud scene off screen on the benchmark's display, both mappers
// with the benchmark's coefficients, map size, light samples and cache size.
void SetUpTwoClouds(tyndall_test::TwoClouds& scene, const Options& o)
{
  TheDisplay->Attach(scene.Window);
  scene.Window->SetOffScreenRendering(1);
  for (vtkTransmittanceVolumeMapper* mapper : { scene.Left.Mapper.Get(), scene.Right.Mapper.Get() })
  {
    mapper->SetNumberOfCoefficients(o.Coefficients);
    mapper->SetTransmittanceMapSize(o.MapSize);
    mapper->SetLightSampleCount(o.LightSamples);
    mapper->SetTransmittanceCacheSize(o.CacheSize);
  }
}

// Several volumes (tyndall_test::TwoClouds: two clouds side by side, the
// left one shadowing the right), per method: the volumes lit alone
// (SceneShadows off: each builds maps over its own box) against the scene
// (one set of maps over both, built once and shared): map builds and their
// seconds, frame, PSNR against the CPU reference of the scene.
void MeasureSeveralVolumes(const Options& o)
{
  using M = vtkTransmittanceVolumeMapper;
  tyndall_test::TwoClouds timing(o.Size, o.Size / 2, o.Resolution);
  tyndall_test::TwoClouds reference(o.ReferenceSize, o.ReferenceSize / 2, o.Resolution);
  SetUpTwoClouds(timing, o);
  SetUpTwoClouds(reference, o);
  const vtkSmartPointer<vtkImageData> cpu = reference.Cpu();
  std::cout << "\n## Several volumes (two clouds side by side, " << o.Size << " x " << o.Size / 2
            << ", the left one in front of the sun)\n\n"
            << "| method | lit | map builds | build (s) | frame (s) | PSNR vs CPU of the scene "
               "(dB) |\n"
            << "|---|---|---|---|---|---|\n";
  for (int m : { M::BRUTE_FORCE, M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
  {
    for (bool shadows : { false, true })
    {
      for (tyndall_test::TwoClouds* scene : { &timing, &reference })
      {
        scene->SetMethod(m);
        scene->SetSceneShadows(shadows);
      }
      const int left = timing.Left.Mapper->GetMapBuildCount();
      const int right = timing.Right.Mapper->GetMapBuildCount();
      TimeFrame(timing.Window); // compiles the variant, builds the maps
      const int leftBuilds = timing.Left.Mapper->GetMapBuildCount() - left;
      const int rightBuilds = timing.Right.Mapper->GetMapBuildCount() - right;
      const double build = (leftBuilds ? timing.Left.Mapper->GetLastMapBuildTime() : 0.0) +
        (rightBuilds ? timing.Right.Mapper->GetLastMapBuildTime() : 0.0);
      double frame = std::numeric_limits<double>::infinity();
      for (int f = 0; f < o.Frames; ++f)
      {
        timing.Left.Mapper->Modified();
        frame = std::min(frame, TimeFrame(timing.Window));
      }
      std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | "
                << (shadows ? "the scene (shared maps)" : "each alone") << " | "
                << leftBuilds + rightBuilds << " | " << std::setprecision(4) << build << " | "
                << frame << " | " << tyndall_test::PSNR(reference.Gpu(), cpu) << " |\n";
    }
  }
}

// Overlapping volumes (tyndall_test::TwoClouds::Interpenetrate(): two clouds
// through the same space), per method: drawn as layers (SceneCompositing
// off: each volume by its own mapper) against one medium (the first
// volume's mapper casts the camera rays through both): frame and PSNR
// against the CPU reference of the one medium.
void MeasureOverlapping(const Options& o)
{
  using M = vtkTransmittanceVolumeMapper;
  tyndall_test::TwoClouds timing(o.Size, o.Size / 2, o.Resolution);
  tyndall_test::TwoClouds reference(o.ReferenceSize, o.ReferenceSize / 2, o.Resolution);
  SetUpTwoClouds(timing, o);
  SetUpTwoClouds(reference, o);
  timing.Interpenetrate();
  reference.Interpenetrate();
  const vtkSmartPointer<vtkImageData> cpu = reference.Cpu();
  std::cout << "\n## Overlapping volumes (two clouds through the same space, " << o.Size << " x "
            << o.Size / 2 << ")\n\n"
            << "| method | drawn | frame (s) | PSNR vs CPU of the one medium (dB) |\n"
            << "|---|---|---|---|\n";
  for (int m : { M::BRUTE_FORCE, M::ADAPTIVE_TFM, M::ADAPTIVE_ETM })
  {
    for (bool together : { false, true })
    {
      for (tyndall_test::TwoClouds* scene : { &timing, &reference })
      {
        scene->SetMethod(m);
        scene->SetSceneCompositing(together);
      }
      TimeFrame(timing.Window); // compiles the variant, builds the maps and the cache
      double frame = std::numeric_limits<double>::infinity();
      for (int f = 0; f < o.Frames; ++f)
      {
        timing.Left.Mapper->Modified();
        frame = std::min(frame, TimeFrame(timing.Window));
      }
      std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | "
                << (together ? "one medium" : "as layers") << " | " << std::setprecision(4) << frame
                << " | " << tyndall_test::PSNR(reference.Gpu(), cpu) << " |\n";
    }
  }
}

// Runs every method on one medium and prints a table; returns the frame
// times and PSNRs by method.
Figures RunMedium(const Medium& medium, const Options& o)
{
  std::cout << "\n## " << medium.Name << "\n\n";
  // The CPU reference at the reference size.
  Scene reference = MakeScene(medium, o);
  reference.Window->SetSize(o.ReferenceSize, o.ReferenceSize);
  reference.Window->Render();
  vtkNew<vtkSingleScatteringReference> cpu;
  // Camera steps as fine as the mapper's (half a voxel); light steps of two
  // voxels keep the reference affordable at 256^3 (its light integral
  // converges as the square of the step: see TestSingleScatteringReference).
  cpu->SetLightStepSize(2.0 * MinimumSpacing(medium.Data));
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  cpu->Render(reference.Renderer, reference.Volume, o.ReferenceSize, o.ReferenceSize);
  timer->StopTimer();
  vtkImageData* cpuImage = cpu->Composite(reference.Renderer->GetBackground());
  std::cout << "CPU reference: " << o.ReferenceSize << " x " << o.ReferenceSize << " in "
            << timer->GetElapsedTime() << " s\n\n";

  Scene timing = MakeScene(medium, o);
  timing.Window->SetSize(o.Size, o.Size);
  Figures figures;
  figures.Frame.assign(6, 0.0);
  figures.Build.assign(6, 0.0);
  figures.PSNR.assign(6, 0.0);
  std::vector<vtkSmartPointer<vtkImageData>> images(6);
  for (int m : kMethods)
  {
    timing.Mapper->SetTransmittanceMethod(m);
    TimeFrame(timing.Window); // builds maps, compiles shaders
    figures.Build[m] =
      m >= vtkTransmittanceVolumeMapper::TFM ? timing.Mapper->GetLastMapBuildTime() : 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (int f = 0; f < o.Frames; ++f)
    {
      timing.Mapper->Modified(); // a new frame, same maps
      best = std::min(best, TimeFrame(timing.Window));
    }
    figures.Frame[m] = best;
    reference.Mapper->SetTransmittanceMethod(m);
    reference.Window->Render();
    images[m] = tyndall_test::Grab(reference.Window);
    figures.PSNR[m] = tyndall_test::PSNR(images[m], cpuImage);
  }
  using M = vtkTransmittanceVolumeMapper;
  std::cout << "| method | frame (s) | map build (s) | frame / None | frame / BruteForce | "
               "PSNR vs CPU (dB) |\n"
            << "|---|---|---|---|---|---|\n";
  for (int m : kMethods)
  {
    std::cout << "| " << vtkTransmittanceMapMath::GetMethodName(m) << " | " << std::setprecision(4)
              << figures.Frame[m] << " | " << figures.Build[m] << " | "
              << figures.Frame[m] / figures.Frame[M::NONE] << " | "
              << figures.Frame[m] / figures.Frame[M::BRUTE_FORCE] << " | " << figures.PSNR[m]
              << " |\n";
  }
  MeasureSkipping(timing, o);
  MeasureCache(timing, reference, cpuImage, o);
  MeasureChromatic(medium, timing, reference, figures, o);
  if (!o.Export.empty())
  {
    const std::string base = o.Export + "/" + medium.Key;
    if (!ExportScene(medium, reference, o, cpuImage, figures, timer->GetElapsedTime()) ||
      !WritePNG(images[M::ADAPTIVE_ETM], base + "-adaptive-etm.png") ||
      !WritePNG(images[M::BRUTE_FORCE], base + "-brute-force.png"))
    {
      std::cerr << "BenchTransmittanceMapper: cannot write the scene to " << o.Export << "\n";
      std::exit(EXIT_FAILURE);
    }
    std::cout << "\nexported: " << base << "-scene.json\n";
  }
  return figures;
}

// The data medium of one --volume; false (with a message) on failure.
bool MakeDataMedium(const Options::Volume& volume, Medium& medium)
{
  vtkNew<vtkVolumeFileReader> reader;
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(reader);
  reader->SetFileName(volume.Path.c_str());
  reader->Update();
  if (errors->HasErrors())
  {
    std::cerr << "BenchTransmittanceMapper: " << errors->GetMessages().front() << "\n";
    return false;
  }
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  if (volume.Shift != 0.0)
  {
    vtkNew<vtkImageShiftScale> shift;
    shift->SetInputData(image);
    shift->SetShift(volume.Shift);
    shift->SetOutputScalarTypeToFloat();
    shift->Update();
    image = shift->GetOutput();
  }
  medium.Property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  medium.Property->SetInterpolationTypeToLinear();
  medium.Property->SetAmbientIntensity(kAmbient);
  // As tyndall-render: over the data's range, opacities per mean voxel spacing.
  if (!vtkTransferFunctionPresets::ApplyToImage(volume.Preset.c_str(), medium.Property, image))
  {
    std::cerr << "BenchTransmittanceMapper: cannot apply the preset '" << volume.Preset << "'\n";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  const std::string file = vtksys::SystemTools::GetFilenameName(volume.Path);
  std::ostringstream name;
  name << "Data volume: " << file << " (" << dims[0] << " x " << dims[1] << " x " << dims[2]
       << ", scalars shifted by " << volume.Shift << ", preset " << volume.Preset << ")";
  medium.Key = vtksys::SystemTools::GetFilenameWithoutLastExtension(file);
  medium.Name = name.str();
  medium.Data = image;
  medium.FitCamera = true;
  medium.YUp = volume.YUp;
  return true;
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!ParseArguments(argc, argv, o))
  {
    return 2;
  }
  vtkNew<vtkTyndallDisplay> display;
  if (!display->Open())
  {
    std::cerr << "BenchTransmittanceMapper: " << display->GetErrorMessage() << "\n";
    return EXIT_FAILURE;
  }
  TheDisplay = display;
  std::cout << "# vtkTransmittanceVolumeMapper benchmark\n\n"
            << "image " << o.Size << "^2, volume " << o.Resolution << "^3, " << o.Coefficients
            << " coefficients, maps " << o.MapSize << "^2, brute force " << o.LightSamples
            << " light samples, transmittance cache " << o.CacheSize
            << " texels on the longest side, best of " << o.Frames << " frames; PSNR at "
            << o.ReferenceSize << "^2 against vtkSingleScatteringReference; "
            << std::thread::hardware_concurrency() << " CPU threads\n";
  std::vector<Medium> media(3);
  media[0].Key = "cloud";
  media[0].Name = "Built-in cloud";
  media[0].Data = tyndall_test::MakeCloud(o.Resolution);
  media[0].Property = tyndall_test::MakeCloudProperty(0.5);
  media[0].Property->SetAmbientIntensity(kAmbient);
  media[1].Key = "dense";
  media[1].Name = "Dense medium";
  media[1].Data = tyndall_test::MakeDenseMedium(o.Resolution);
  media[1].Property = tyndall_test::MakeCloudProperty(0.9);
  media[1].Property->SetAmbientIntensity(kAmbient);
  media[2].Key = "sparse";
  media[2].Name = "Sparse blobs (six Gaussian blobs in a mostly empty box)";
  media[2].Data = tyndall_test::MakeSparseBlobs(o.Resolution);
  media[2].Property = tyndall_test::MakeCloudProperty(0.8);
  media[2].Property->SetAmbientIntensity(kAmbient);
  for (const Options::Volume& volume : o.Volumes)
  {
    Medium medium;
    if (!MakeDataMedium(volume, medium))
    {
      return EXIT_FAILURE;
    }
    // Unique file keys for --export.
    const std::string key = medium.Key;
    for (int n = 2; std::any_of(
           media.begin(), media.end(), [&](const Medium& m) { return m.Key == medium.Key; });
         ++n)
    {
      medium.Key = key + "-" + std::to_string(n);
    }
    media.push_back(medium);
  }
  {
    Scene probe = MakeScene(media[0], o);
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

  std::vector<Figures> figures;
  for (const Medium& medium : media)
  {
    figures.push_back(RunMedium(medium, o));
  }
  const Figures& cloud = figures[0];
  const Figures& dense = figures[1];
  MeasureInteraction(media[0], o);
  MeasureSeveralVolumes(o);
  MeasureOverlapping(o);

  using M = vtkTransmittanceVolumeMapper;
  std::cout << "\n## Bars\n\n";
  for (int m : { M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
  {
    const double ratio = cloud.Frame[m] / cloud.Frame[M::NONE];
    std::cout << "- " << vtkTransmittanceMapMath::GetMethodName(m)
              << " frame <= 1.5x None: " << (ratio <= 1.5 ? "PASS" : "MISS") << " (" << ratio
              << "x)\n";
  }
  const double bruteOverETM = cloud.Frame[M::BRUTE_FORCE] / cloud.Frame[M::ETM];
  std::cout << "- BruteForce (" << o.LightSamples
            << " samples) >= 10x ETM: " << (bruteOverETM >= 10.0 ? "PASS" : "MISS") << " ("
            << bruteOverETM << "x)\n";
  std::cout << "- AdaptiveETM PSNR >= 40 dB on the cloud: "
            << (cloud.PSNR[M::ADAPTIVE_ETM] >= 40.0 ? "PASS" : "MISS") << " ("
            << cloud.PSNR[M::ADAPTIVE_ETM] << " dB)\n";
  std::cout << "- AdaptiveETM PSNR >= 40 dB on the dense medium: "
            << (dense.PSNR[M::ADAPTIVE_ETM] >= 40.0 ? "PASS" : "MISS") << " ("
            << dense.PSNR[M::ADAPTIVE_ETM] << " dB)\n";
  return EXIT_SUCCESS;
}
