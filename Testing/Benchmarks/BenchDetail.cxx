// BenchDetail: procedural detail (a coarse shape times cosine noise in the
// shader, never voxelised) against the same medium voxelised, issue 12's
// memory and sharpness target.
//
// The shape is a 64^3 vtkCosineNoiseSource cloud over [-1, 1]^3 (the tests'
// cloud property); the detail 6 octaves x 24 directions (144 waves), one
// cycle of the first octave per 2 shape samples (the last octave: 16 cycles
// per shape sample, 2 per voxel of 512^3), contrast 0.5 (offset 1, standard
// deviation 0.5; clamped where it dips below 0). The voxelised medium samples exactly that
// extinction (vtkTyndallDetailMedium::Extinction) at N^3 points (default
// 512^3) into a float image whose opacity function maps the value back to
// the same extinction (alpha = 1 - exp(-value * unit distance), 1024 points).
// Both are drawn by vtkTransmittanceVolumeMapper (AdaptiveETM, maps 256,
// no jitter) from a far camera, two close-ups (the second 4x nearer: a
// 512^3 voxel spans about 4 pixels at 256^2) and a macro view (0.1 from the
// focus: a voxel spans about 18 pixels), W x W pixels;
// the plain 64^3 shape (no detail) is drawn too.
//
// Printed: the GPU memory of the medium's textures (scalars, shape, and for
// the voxelised medium its N^3 floats), the time to voxelise, first-frame
// and later-frame times, and the PSNR of the procedural picture against the
// voxelised one and against the plain shape. The procedural medium is drawn
// twice: filtered by the pixel's footprint (the default,
// vtkParticipatingMediumProperty::DetailFilterWidth 0.5; the camera waves it
// kept are printed) and unfiltered (width 0), with the time ratio and the
// PSNR between the two (issue 39). With an output directory the
// close-ups are written as PNGs (Documentation/images/detail-*.png).
//
// Camera rays sampled in closed form (the paper's section 7,
// vtkTransmittanceVolumeMapper::DetailSamplesPerPixel): for each view, the
// procedural medium with 4 and 16 free-flight samples per pixel per frame,
// averaged over still frames: the time per frame and the PSNR after 1, 4,
// 16 and 64 frames against the marched picture (same maps: the difference
// is the camera estimator's noise), and the time to reach 40 dB against
// the march's frame. --sampling-only skips the voxelised medium,
// --no-sampling this study.
//
// First, on the CPU, a map texel's projection through the detail in closed
// form (vtkTyndallDetailMedium::ProjectExtinction) against the march the
// map passes do: time per ray and transmittance error (--projection-only:
// only that).
//
// A fifth view, "surface", looks at the cloud's lit surface from just in
// front of it: the point where the optical depth along a ray from the lit
// side (from (1.7, 1.45, 2) towards the close-up's focus) reaches 0.5, seen
// from 0.08 (world) before it (a 512^3 voxel
// some 20 pixels wide at 256^2): where a dense medium's first mean free path
// shows the finest octaves.
//
// Usage: BenchDetail [--voxels N] [--size W[xH]] [--frames N] [--output DIR] [--quick]
//                    [--sampling-only] [--projection-only] [--no-sampling] [--density S]
//                    [--gain G] [--view NAME]
// (--size: the window, W x W or W x H; --frames N: the later frame's time is
// the mean of N, each finished with WaitForCompletion())
// (--density S multiplies the medium's density: a denser cloud shows its
// first mean free path, where the finest octaves are not averaged away;
// --gain G the noise's gain, default 0.65: each octave's amplitude over the
// one before; --view NAME compares the voxelised medium in that view only:
// far, close-up, closer, macro or surface)
#include "vtkCamera.h"
#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallGridMedium.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
struct Options
{
  int Voxels = 512;
  int Size = 256; // width
  int Height = 0; // 0: square
  int Frames = 1; // later frames timed (their mean)
  std::string Output;
  bool SamplingOnly = false;
  bool ProjectionOnly = false;
  bool NoSampling = false;
  double Density = 1.0; // multiplies the cloud property's density scale
  double Gain = 0.65;
  std::string ViewName;
};

double Seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One medium in a window of its own: the mapper, the frames, the picture.
struct View
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  int Frames = 1; // later frames timed: their mean

  View(vtkImageData* data, vtkParticipatingMediumProperty* property, int width, int height)
  {
    this->Mapper->SetInputData(data);
    this->Mapper->JitterOff();
    this->Mapper->SetTransmittanceMapSize(256);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
  }

  // One frame, finished (a GPU's commands done): its time.
  double Frame()
  {
    const auto start = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    return Seconds(start);
  }

  // Renders from (x, y, z): first and later frame times, and the picture.
  vtkSmartPointer<vtkImageData> Render(const double eye[3], const double focus[3], double times[2])
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(eye[0], eye[1], eye[2]);
    camera->SetFocalPoint(focus[0], focus[1], focus[2]);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
    times[0] = this->Frame();
    times[1] = 0.0;
    for (int i = 0; i < this->Frames; ++i)
    {
      times[1] += this->Frame() / this->Frames;
    }
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->Update();
    auto copy = vtkSmartPointer<vtkImageData>::New();
    copy->DeepCopy(grab->GetOutput());
    return copy;
  }
};

// A map texel's projection through the detail on the CPU, in closed form
// (vtkTyndallDetailMedium::ProjectExtinction) against the map passes' march
// (vtkTransmittanceMapMath::Project, the shaders' CPU twin, 128 samples):
// time per light ray, and the ETM transmittance of each (8 coefficients)
// against the exact one (closed-form optical depth) at 16 points per ray.
void ProjectionStudy(const vtkTyndallGridMedium& grid, const vtkTyndallDetailMedium& detail)
{
  const int rays = 400, count = 8, samples = 128, points = 16;
  const double* m = grid.GetWorldToIndex();
  const double light[3] = { -0.8, -0.3, -0.52 }; // roughly the tests' sun, travelling
  const double norm = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  double d[3];
  for (int r = 0; r < 3; ++r)
  {
    // index units per world unit
    d[r] = (m[4 * r] * light[0] + m[4 * r + 1] * light[1] + m[4 * r + 2] * light[2]) / norm;
  }
  const double* lo = grid.GetBoxLow();
  const double* hi = grid.GetBoxHigh();
  unsigned int seed = 12345;
  auto uniform = [&seed]()
  {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / 16777216.0;
  };
  double closedTime = 0.0, marchTime = 0.0, closedError = 0.0, marchError = 0.0;
  int measured = 0;
  for (int ray = 0; ray < rays; ++ray)
  {
    double o[3], t0 = -1e30, t1 = 1e30;
    for (int a = 0; a < 3; ++a)
    {
      o[a] = lo[a] + uniform() * (hi[a] - lo[a]);
    }
    for (int a = 0; a < 3; ++a)
    {
      if (d[a] != 0.0)
      {
        const double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
      }
    }
    const double length = t1 - t0;
    double closed[count], march[count], bounds[3];
    auto start = std::chrono::steady_clock::now();
    detail.ProjectExtinction(o, d, t0, t1, count, closed);
    closedTime += Seconds(start);
    start = std::chrono::steady_clock::now();
    vtkTransmittanceMapMath::Project(
      vtkTransmittanceMapMath::ETM,
      [&](double u)
      {
        const double t = t0 + u * length;
        const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
        return detail.Extinction(p);
      },
      length, samples, count, 0.01, march, bounds);
    marchTime += Seconds(start);
    for (int k = 1; k <= points; ++k)
    {
      const double u = static_cast<double>(k) / points;
      const double exact = std::exp(-detail.ClosedFormDepth(o, d, t0, t0 + u * length));
      const double a = vtkTransmittanceMapMath::Reconstruct(
        vtkTransmittanceMapMath::ETM, closed, count, bounds, u);
      const double b =
        vtkTransmittanceMapMath::Reconstruct(vtkTransmittanceMapMath::ETM, march, count, bounds, u);
      closedError += (a - exact) * (a - exact);
      marchError += (b - exact) * (b - exact);
      ++measured;
    }
  }
  std::printf("map texel projection through the detail (CPU, %d light rays, ETM, %d "
              "coefficients): closed form %.1f us per ray, march of %d samples %.1f us per ray "
              "(the closed form takes %.1fx the march's time); RMS transmittance error against "
              "the exact one: closed form %.4f, march %.4f\n",
    rays, count, 1e6 * closedTime / rays, samples, 1e6 * marchTime / rays, closedTime / marchTime,
    std::sqrt(closedError / measured), std::sqrt(marchError / measured));
}

// The sampled camera rays against the marched picture from one view.
void SamplingStudy(View& view, const char* name, const double eye[3], const double focus[3])
{
  vtkTransmittanceVolumeMapper* mapper = view.Mapper;
  mapper->SetDetailSamplesPerPixel(0);
  double marchTimes[2];
  vtkSmartPointer<vtkImageData> marched = view.Render(eye, focus, marchTimes);
  std::printf("%-9s marched: %.2f s per frame (%d camera waves)\n", name, marchTimes[1],
    mapper->GetLastDetailCameraWaves());
  for (const int samples : { 4, 16 })
  {
    mapper->SetDetailSamplesPerPixel(samples);
    double times[2];
    view.Render(eye, focus, times); // compiles the variant; starts the average
    mapper->ResetAccumulation();
    std::string line;
    double total = 0.0, reached = -1.0;
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view.Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    for (int frame = 1; frame <= 64; ++frame)
    {
      total += view.Frame();
      const bool report = frame == 1 || frame == 4 || frame == 16 || frame == 64;
      if (!report && reached >= 0.0)
      {
        continue;
      }
      grab->Modified();
      grab->Update();
      const double psnr = tyndall_test::PSNR(grab->GetOutput(), marched);
      if (reached < 0.0 && psnr >= 40.0)
      {
        reached = total;
      }
      if (report)
      {
        line += " " + std::to_string(frame) + ": " + std::to_string(psnr).substr(0, 4) + " dB;";
      }
    }
    std::printf("%-9s sampled %2d per pixel: %.3f s per frame (%.1fx faster than a march), "
                "%d frames averaged; PSNR against the march after%s 40 dB after %.2f s "
                "(%.2fx the march's frame)\n",
      name, samples, total / 64.0, marchTimes[1] / (total / 64.0), mapper->GetAccumulatedFrames(),
      line.c_str(), reached, reached / marchTimes[1]);
  }
  mapper->SetDetailSamplesPerPixel(0);
}

// The detailed extinction sampled at n^3 points over the shape's bounds.
vtkSmartPointer<vtkImageData> Voxelise(
  const vtkTyndallDetailMedium& detail, vtkImageData* shape, int n, double& maximum)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetOrigin(shape->GetOrigin());
  const double* s = shape->GetSpacing();
  const int* dims = shape->GetDimensions();
  const double scale = (dims[0] - 1.0) / (n - 1.0); // shape samples per voxel
  image->SetSpacing(s[0] * scale, s[1] * scale, s[2] * scale);
  vtkNew<vtkFloatArray> values;
  values->SetName("extinction");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  float* out = values->GetPointer(0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType k0, vtkIdType k1)
    {
      for (vtkIdType k = k0; k < k1; ++k)
      {
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            const double p[3] = { i * scale, j * scale, k * scale };
            out[(k * n + j) * n + i] = static_cast<float>(detail.Extinction(p));
          }
        }
      }
    });
  image->GetPointData()->SetScalars(values);
  maximum = values->GetRange()[1];
  return image;
}

// A property whose table gives back the extinction stored in the scalars.
vtkSmartPointer<vtkParticipatingMediumProperty> ExtinctionProperty(
  vtkParticipatingMediumProperty* like, double maximum)
{
  auto property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  property->DeepCopy(like);
  property->SetDetailNoise(nullptr);
  // The scalars are the extinction, density scale included
  // (vtkTyndallDetailMedium::Extinction): the table must not scale it again.
  property->SetDensityScale(1.0);
  // A unit distance 16x shorter than the cloud's keeps alpha below the
  // table's 1 - 1e-6 clamp (sigma u < 13.8) for dense media (--density).
  const double unit = like->GetScalarOpacityUnitDistance() / 16.0;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (int i = 0; i <= 1024; ++i)
  {
    const double value = maximum * i / 1024.0;
    opacity->AddPoint(value, 1.0 - std::exp(-value * unit));
  }
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
  return property;
}

void Write(const Options& options, const char* name, vtkImageData* image)
{
  if (options.Output.empty())
  {
    return;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((options.Output + "/" + name).c_str());
  writer->SetInputData(image);
  writer->Write();
}

// The "surface" view: the point where the optical depth from `eye` towards
// `focus` reaches 0.5 (world steps of 1e-3 through the detailed extinction),
// and an eye 0.08 before it on that ray. False if the ray never gets there.
bool SurfaceView(const vtkTyndallGridMedium& grid, const vtkTyndallDetailMedium& detail,
  const double eye[3], const double focus[3], double surfaceEye[3], double surface[3])
{
  const double* m = grid.GetWorldToIndex();
  double d[3] = { focus[0] - eye[0], focus[1] - eye[1], focus[2] - eye[2] };
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& c : d)
  {
    c /= length;
  }
  const double step = 1e-3;
  double tau = 0.0;
  for (double t = 0.0; t < 4.0; t += step)
  {
    const double x[3] = { eye[0] + t * d[0], eye[1] + t * d[1], eye[2] + t * d[2] };
    double p[3];
    for (int r = 0; r < 3; ++r)
    {
      p[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
    }
    tau += detail.Extinction(p) * step;
    if (tau >= 0.5)
    {
      for (int r = 0; r < 3; ++r)
      {
        surface[r] = x[r];
        surfaceEye[r] = x[r] - 0.08 * d[r];
      }
      return true;
    }
  }
  return false;
}

// "W" (height 0: square) or "WxH", each a whole number of 16 or more.
bool ParseSize(const char* text, int& width, int& height)
{
  char* end = nullptr;
  const long w = std::strtol(text, &end, 10);
  long h = 0;
  if (*end == 'x')
  {
    const char* rest = end + 1;
    h = std::strtol(rest, &end, 10);
    if (end == rest || h < 16 || h > 16384)
    {
      return false;
    }
  }
  if (*end != '\0' || w < 16 || w > 16384)
  {
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

bool Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--quick")
    {
      options.Voxels = 96;
      options.Size = 64;
      options.Height = 0;
    }
    else if (a == "--density" && i + 1 < argc)
    {
      options.Density = std::max(1e-3, std::atof(argv[++i]));
    }
    else if (a == "--gain" && i + 1 < argc)
    {
      options.Gain = std::min(1.0, std::max(0.05, std::atof(argv[++i])));
    }
    else if (a == "--view" && i + 1 < argc)
    {
      options.ViewName = argv[++i];
    }
    else if (a == "--no-sampling")
    {
      options.NoSampling = true;
    }
    else if (a == "--projection-only")
    {
      options.ProjectionOnly = true;
    }
    else if (a == "--sampling-only")
    {
      options.SamplingOnly = true;
    }
    else if (a == "--voxels" && i + 1 < argc)
    {
      options.Voxels = std::max(16, std::atoi(argv[++i]));
    }
    else if (a == "--size" && i + 1 < argc)
    {
      // W or WxH, each 16 or more
      if (!ParseSize(argv[++i], options.Size, options.Height))
      {
        std::printf("BenchDetail: --size wants W or WxH (16 or more each), not %s\n", argv[i]);
        return false;
      }
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      options.Frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--output" && i + 1 < argc)
    {
      options.Output = argv[++i];
    }
    else
    {
      std::printf(
        "Usage: BenchDetail [--voxels N] [--size W[xH]] [--frames N] [--output DIR] [--quick] "
        "[--sampling-only] [--projection-only] [--no-sampling] [--density S] "
        "[--gain G] [--view NAME]\n");
      return false;
    }
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkImageData> shape = tyndall_test::MakeCloud(64);
  auto property = tyndall_test::MakeCloudProperty(0.5);
  property->SetDensityScale(property->GetDensityScale() * options.Density);
  property->SetAmbientIntensity(0.1);
  vtkNew<vtkCosineNoise> noise;
  noise->SetNumberOfOctaves(6);
  noise->SetNumberOfDirections(24);
  noise->SetFrequency(64.0 / (2.0 * 2.0));
  noise->SetGain(options.Gain); // 0.65: the finer octaves stronger than the default 0.5
  double power = 0.0;
  for (int i = 0; i < noise->GetNumberOfWaves(); ++i)
  {
    double k[3], phase, amplitude;
    noise->GetWave(i, k, phase, amplitude);
    power += 0.5 * amplitude * amplitude;
  }
  noise->SetAmplitude(0.5 / std::sqrt(power));
  noise->SetOffset(1.0);
  property->SetDetailNoise(noise);

  const int height = options.Height > 0 ? options.Height : options.Size;
  View procedural(shape, property, options.Size, height);
  procedural.Frames = options.Frames;
  vtkTyndallGridMedium grid;
  vtkTyndallDetailMedium detail;
  if (!grid.Update(procedural.Volume, procedural.Mapper) ||
    !detail.Update(grid, noise, procedural.Mapper))
  {
    return EXIT_FAILURE;
  }
  ProjectionStudy(grid, detail);
  if (options.ProjectionOnly)
  {
    return EXIT_SUCCESS;
  }
  // The macro view: 0.1 from the focus, about 0.054 across (14 voxels of
  // 512^3, each some 18 pixels at 256^2).
  double eyes[5][3] = { { 0.0, -0.6, 4.2 }, { 0.2, 0.5, 1.7 }, { 0.125, 0.3125, 0.425 },
    { 0.1, 0.25, 0.1 }, { 0.0, 0.0, 0.0 } };
  double focus[5][3] = { { 0.0, 0.0, 0.0 }, { 0.1, 0.25, 0.0 }, { 0.1, 0.25, 0.0 },
    { 0.1, 0.25, 0.0 }, { 0.0, 0.0, 0.0 } };
  const char* names[5] = { "far", "close-up", "closer", "macro", "surface" };
  // The surface view approaches the lit side (the sun comes from +x), the
  // light half-way between the camera's direction and the surface normal.
  const double approach[3] = { 0.1 + 1.6, 0.25 + 1.2, 0.0 + 2.0 };
  const int views = SurfaceView(grid, detail, approach, focus[1], eyes[4], focus[4]) ? 5 : 4;
  std::printf("BenchDetail: 64^3 shape x %d waves, %d x %d, AdaptiveETM; camera rays sampled in "
              "closed form against marched\n",
    noise->GetNumberOfWaves(), options.Size, height);
  for (int e = 0; e < 3 && !options.NoSampling; ++e)
  {
    SamplingStudy(procedural, names[e], eyes[e], focus[e]);
  }
  if (options.SamplingOnly)
  {
    return EXIT_SUCCESS;
  }
  auto start = std::chrono::steady_clock::now();
  double maximum = 0.0;
  vtkSmartPointer<vtkImageData> voxels = Voxelise(detail, shape, options.Voxels, maximum);
  const double voxeliseTime = Seconds(start);
  auto voxelProperty = ExtinctionProperty(property, maximum);
  View voxelised(voxels, voxelProperty, options.Size, height);
  voxelised.Frames = options.Frames;
  auto plainProperty = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  plainProperty->DeepCopy(property);
  plainProperty->SetDetailNoise(nullptr);
  View plain(shape, plainProperty, options.Size, height);
  plain.Frames = options.Frames;
  // The same procedural medium without the footprint filter.
  auto unfilteredProperty = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  unfilteredProperty->DeepCopy(property);
  unfilteredProperty->SetDetailFilterWidth(0.0);
  View unfiltered(shape, unfilteredProperty, options.Size, height);
  unfiltered.Frames = options.Frames;

  const double n = options.Voxels;
  const double shapeBytes = 64.0 * 64 * 64 * 4;
  std::printf("BenchDetail: 64^3 shape x %d waves against the same medium voxelised at %d^3, "
              "%d x %d, AdaptiveETM (later frames: the mean of %d)\n",
    noise->GetNumberOfWaves(), options.Voxels, options.Size, height, options.Frames);
  std::printf("GPU memory of the medium: procedural %.2f MiB (scalars + shape, 64^3 floats "
              "each), voxelised %.1f MiB (%d^3 floats): %.0fx\n",
    2 * shapeBytes / 1048576.0, n * n * n * 4 / 1048576.0, options.Voxels,
    n * n * n * 4 / (2 * shapeBytes));
  std::printf(
    "voxelising (%d threads): %.1f s\n", vtkSMPTools::GetEstimatedNumberOfThreads(), voxeliseTime);
  for (int e = 0; e < views; ++e)
  {
    if (!options.ViewName.empty() && options.ViewName != names[e])
    {
      continue;
    }
    double tp[2], tv[2], tc[2], tu[2];
    auto a = procedural.Render(eyes[e], focus[e], tp);
    const int cameraWaves = procedural.Mapper->GetLastDetailCameraWaves();
    auto u = unfiltered.Render(eyes[e], focus[e], tu);
    auto b = voxelised.Render(eyes[e], focus[e], tv);
    auto c = plain.Render(eyes[e], focus[e], tc);
    std::printf("%-9s frame (first / next): procedural %.2f / %.2f s (%d of %d waves; unfiltered "
                "%.2f / %.2f s: %.2fx), voxelised %.2f / %.2f s (procedural %.2fx), plain shape "
                "%.2f / %.2f s\n",
      names[e], tp[0], tp[1], cameraWaves, noise->GetNumberOfWaves(), tu[0], tu[1], tp[1] / tu[1],
      tv[0], tv[1], tp[1] / tv[1], tc[0], tc[1]);
    std::printf("%-9s frames per second: procedural %.1f, unfiltered %.1f, voxelised %.1f, plain "
                "shape %.1f\n",
      names[e], 1.0 / tp[1], 1.0 / tu[1], 1.0 / tv[1], 1.0 / tc[1]);
    std::printf("%-9s PSNR of the procedural picture: %.1f dB against the unfiltered one, %.1f dB "
                "against the voxelised one, %.1f dB against the plain shape; unfiltered against "
                "voxelised %.1f dB\n",
      names[e], tyndall_test::PSNR(a, u), tyndall_test::PSNR(a, b), tyndall_test::PSNR(a, c),
      tyndall_test::PSNR(u, b));
    if (e > 0)
    {
      const std::string view = e == 1 ? "closeup"
        : e == 2                      ? "closer"
        : e == 3                      ? "macro"
                                      : "surface";
      Write(options, ("detail-" + view + "-procedural.png").c_str(), a);
      Write(options, ("detail-" + view + "-voxelised.png").c_str(), b);
      Write(options, ("detail-" + view + "-shape.png").c_str(), c);
    }
  }
  return EXIT_SUCCESS;
}
