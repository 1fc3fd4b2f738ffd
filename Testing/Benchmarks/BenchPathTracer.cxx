// BenchPathTracer: closed-form distance sampling against delta tracking in
// vtkVolumetricPathTracer, beside the paper's Table 1 (Balint and Mantiuk,
// RTX 2080 Ti: transmittance evaluations and distance sampling 65 ms vs
// 1136 ms, total 179 ms vs 1250 ms per sample per pixel: 17x and 7x).
//
// Scene: a procedural cloud. The shape is a 32^3 vtkCosineNoiseSource over
// [-1, 1]^3 (ellipsoid envelope, 2 octaves: a coarse, smooth shape); the
// detail is vtkCosineNoise with 6 octaves x 24 directions (144 waves),
// frequency 2, at several offsets in the noise's standard deviations
// (--offsets; 0: -minimum + 0.05, the smallest that keeps it non-negative),
// extinction scale 1 / offset (the same mean extinction at every contrast).
// The offset sets how loose delta tracking's majorant (offset + the sum of
// the amplitudes) is; below about 2 sigma the noise dips under 0, where the
// closed form (clamping each cell's integral) and delta tracking (clamping
// each sample) see slightly different media: the clamped share is printed. A sun and the camera of
// the tests; HG g = 0.6, albedo 0.95, MaximumBounces 4. Each mode renders W x W pixels at S samples
// per pixel.
//
// Reported per mode, per sample per pixel (one full-image sample pass):
// - transmittance + distance sampling: CPU time inside the free-flight and
//   light-transmittance calls, summed over the threads, and each of the two;
// - total: CPU time of whole paths, summed over the threads;
// - wall: the render's wall-clock time / S;
// - variance: the variance of a one-sample estimate, averaged over the
//   pixels and channels (per pixel: S x the squared standard error of its
//   mean), and the relative efficiency (time x variance; lower is better).
//   "Equal variance" time ratio = (time_dt x var_dt) / (time_cf x var_cf);
// - work: flights and shadow rays per sample, and per flight and per shadow
//   ray the passes over the waves (delta tracking: noise evaluations; closed
//   form: trigonometric + cell passes), and the one-pass bound: delta
//   tracking's evaluations per ray, the most an exact closed form (at least
//   one trigonometric pass per ray, each dearer than an evaluation) can gain.
//
// A second scene is the paper's own setting: the same noise in its bounding
// box (a constant shape, so a ray crosses one cell), mean optical depth 8.
//
// Usage: BenchPathTracer [--quick] [--size W] [--spp S] [--offsets K,...]
//        [--scene cloud|box|both] [--help]
// --quick (what ctest runs): a 16^3 shape, 16 x 16 pixels, 2 samples,
// offsets non-negative and 2 sigma; checks
// only that both modes render and agree in magnitude, and the work counts
// (flights counted, passes made; in the box one trigonometric pass per
// closed-form shadow ray).
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkDataArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  bool Quick = false;
  int Size = 64;
  int Samples = 2;
  int Shape = 32;
  // The noise's offsets in standard deviations (0: non-negative).
  std::vector<double> Offsets = { 0.0, 3.0, 2.0, 1.5, 1.0 };
  bool Cloud = true;
  bool Box = true;
};

struct Result
{
  double Tracking = 0.0; // s per sample pass
  double Flight = 0.0;   // of which in free flights
  double Total = 0.0;
  double Wall = 0.0;
  double Variance = 0.0; // of a one-sample estimate
  double Mean = 0.0;
  double MeanError = 0.0; // standard error of Mean
  // Work: flights and shadow rays per sample per pixel; passes over the
  // waves per flight and per shadow ray (trigonometric, cell).
  double Flights = 0.0;
  double ShadowRays = 0.0;
  double FlightPasses[2] = { 0.0, 0.0 };
  double ShadowPasses[2] = { 0.0, 0.0 };
};

bool Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--quick")
    {
      options.Quick = true;
      options.Size = 16;
      options.Samples = 2;
      options.Shape = 16;
      options.Offsets = { 0.0, 2.0 };
    }
    else if (a == "--offsets" && i + 1 < argc)
    {
      options.Offsets.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        options.Offsets.push_back(std::max(0.0, std::atof(item.c_str())));
      }
    }
    else if (a == "--scene" && i + 1 < argc)
    {
      const std::string scene = argv[++i];
      options.Cloud = scene == "cloud" || scene == "both";
      options.Box = scene == "box" || scene == "both";
      if (!options.Cloud && !options.Box)
      {
        std::printf("--scene: cloud, box or both, not '%s'\n", scene.c_str());
        return false;
      }
    }
    else if ((a == "--size" || a == "--spp") && i + 1 < argc)
    {
      (a == "--size" ? options.Size : options.Samples) = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::printf("Usage: BenchPathTracer [--quick] [--size W] [--spp S] [--offsets K,K,...] "
                  "[--scene cloud|box|both] [--help]\n"
                  "  --offsets: the noise's offsets in its standard deviations (0: the "
                  "smallest\n  that keeps it non-negative); default 0,3,2,1.5,1\n");
      return false;
    }
  }
  return true;
}

// The share of the noise's mass that its clamp at 0 removes,
// E[max(0, -phi)] / E[phi], over random points of [-1, 1]^3.
double ClampedShare(vtkCosineNoise* noise)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double negative = 0.0, mean = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i)
  {
    double p[3] = { u(rng), u(rng), u(rng) };
    const double v = noise->EvaluateFunction(p);
    negative += std::max(0.0, -v) / n;
    mean += v / n;
  }
  return mean > 0.0 ? negative / mean : 0.0;
}

struct CloudScene
{
  vtkNew<vtkCosineNoiseSource> Source;
  vtkNew<vtkCosineNoise> Detail;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkGPUVolumeRayCastMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;

  // n: the shape's samples per axis; box: no envelope and a constant shape
  // (2^3 samples of 1: the noise in its bounding box, one cell per ray: the
  // paper's setting) with `boxDepth` the mean optical depth across the box.
  // offsetSigmas: the noise's offset in standard deviations of the noise
  // (its contrast is 1 / offsetSigmas); 0: the smallest offset that keeps
  // it non-negative everywhere (-minimum + 0.05).
  CloudScene(int n, bool box, double offsetSigmas, double boxDepth = 8.0)
  {
    this->Source->SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1);
    this->Source->SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1));
    this->Source->SetEnvelopeTypeToEllipsoid();
    this->Source->GetNoise()->SetNumberOfOctaves(2);
    if (box)
    {
      this->Source->SetEnvelopeTypeToNone();
      this->Source->GetNoise()->SetAmplitude(0.0);
      this->Source->GetNoise()->SetOffset(1.0);
    }
    this->Source->Update();
    const double* range = this->Source->GetOutput()->GetScalarRange();
    this->Opacity->AddPoint(range[0], box ? 0.3 : 0.0);
    this->Opacity->AddPoint(range[1] + (box ? 1.0 : 0.0), 0.3);
    this->Color->AddRGBPoint(range[0], 0.95, 0.95, 0.95);
    this->Color->AddRGBPoint(range[1], 0.95, 0.95, 0.95);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Property->SetScalarOpacityUnitDistance(0.05);
    this->Property->SetInterpolationTypeToLinear();
    this->Property->SetScatteringAnisotropy(0.6);
    this->Detail->SetNumberOfOctaves(6);
    this->Detail->SetNumberOfDirections(24);
    this->Detail->SetFrequency(2.0);
    this->Detail->SetOffset(0.0);
    this->Detail->SetOffset(offsetSigmas > 0.0 ? offsetSigmas * this->Detail->GetStandardDeviation()
                                               : -this->Detail->GetMinimumValue() + 0.05);
    this->Detail->SetExtinctionScale(1.0 / this->Detail->GetOffset());
    if (box)
    {
      // The shape's extinction is -ln(1 - 0.3) / 0.05 per unit; the box is 2 wide.
      const double shape = -std::log(0.7) / 0.05;
      this->Detail->SetExtinctionScale(boxDepth / (2.0 * shape * this->Detail->GetOffset()));
    }
    this->Property->SetDetailNoise(this->Detail);
    this->Mapper->SetInputConnection(this->Source->GetOutputPort());
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    vtkNew<vtkLight> sun;
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetPosition(1.0, 2.0, 0.5);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    sun->SetIntensity(2.0);
    this->Renderer->AddLight(sun);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -0.6, 4.2);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange();
  }
};

bool Run(CloudScene& scene, int mode, const Options& options, Result& result)
{
  vtkNew<vtkVolumetricPathTracer> tracer;
  tracer->SetDistanceSampling(mode);
  tracer->SetSamplesPerPixel(options.Samples);
  tracer->SetMaximumBounces(4);
  vtkImageData* image = tracer->Render(scene.Renderer, scene.Volume, options.Size, options.Size);
  if (!image || tracer->GetLastDistanceSampling() != mode)
  {
    return false;
  }
  result.Tracking = tracer->GetLastTrackingTimePerSample();
  result.Flight = tracer->GetLastFlightTimePerSample();
  result.Total = tracer->GetLastTotalTimePerSample();
  result.Wall = tracer->GetLastRenderTime() / options.Samples;
  result.Flights = tracer->GetLastFlightsPerSample();
  result.ShadowRays = tracer->GetLastShadowRaysPerSample();
  result.FlightPasses[0] = tracer->GetLastTrigonometricPassesPerFlight();
  result.FlightPasses[1] = tracer->GetLastCellPassesPerFlight();
  result.ShadowPasses[0] = tracer->GetLastTrigonometricPassesPerShadowRay();
  result.ShadowPasses[1] = tracer->GetLastCellPassesPerShadowRay();
  vtkDataArray* radiance = image->GetPointData()->GetArray("Radiance");
  vtkDataArray* error = image->GetPointData()->GetArray("RadianceStandardError");
  const vtkIdType values = radiance->GetNumberOfValues();
  for (vtkIdType i = 0; i < values; ++i)
  {
    const double se = error->GetVariantValue(i).ToDouble();
    result.Variance += se * se * options.Samples / values;
    result.Mean += radiance->GetVariantValue(i).ToDouble() / values;
    result.MeanError += se * se;
  }
  result.MeanError = std::sqrt(result.MeanError) / values;
  return true;
}

void Print(const Result& cf, const Result& dt, const Options& options)
{
  std::printf("\n%-34s %14s %14s %8s   %s\n", "per sample per pixel (image)", "closed form",
    "delta track.", "ratio", "paper (RTX 2080 Ti)");
  std::printf("%-34s %11.1f ms %11.1f ms %7.2fx   65 ms vs 1136 ms, 17x\n",
    "transmittance + distance sampling", cf.Tracking * 1e3, dt.Tracking * 1e3,
    dt.Tracking / cf.Tracking);
  std::printf("%-34s %11.1f ms %11.1f ms %7.2fx\n", "  of which distance sampling", cf.Flight * 1e3,
    dt.Flight * 1e3, dt.Flight / cf.Flight);
  std::printf("%-34s %11.1f ms %11.1f ms %7.2fx\n", "  of which light transmittance",
    (cf.Tracking - cf.Flight) * 1e3, (dt.Tracking - dt.Flight) * 1e3,
    (dt.Tracking - dt.Flight) / (cf.Tracking - cf.Flight));
  std::printf("%-34s %11.1f ms %11.1f ms %7.2fx   179 ms vs 1250 ms, 7x\n", "total (paths)",
    cf.Total * 1e3, dt.Total * 1e3, dt.Total / cf.Total);
  std::printf(
    "%-34s %11.1f ms %11.1f ms %7.2fx\n", "wall", cf.Wall * 1e3, dt.Wall * 1e3, dt.Wall / cf.Wall);
  std::printf("%-34s %14.4g %14.4g %7.2fx\n", "variance of a 1-spp estimate", cf.Variance,
    dt.Variance, dt.Variance / cf.Variance);
  std::printf("%-34s %14.4g %14.4g\n", "mean radiance", cf.Mean, dt.Mean);
  std::printf("%-34s %14.4g %14.4g %7.2fx   (time x variance; the equal-variance speed-up)\n",
    "efficiency cost (total x variance)", cf.Total * cf.Variance, dt.Total * dt.Variance,
    (dt.Total * dt.Variance) / (cf.Total * cf.Variance));
  std::printf("%-34s %14.3g %14.3g\n", "free flights per sample", cf.Flights, dt.Flights);
  std::printf("%-34s %14.3g %14.3g\n", "shadow rays per sample", cf.ShadowRays, dt.ShadowRays);
  std::printf("%-34s %8.2f + %-5.2f %14.2f %7.2fx   (closed form: trigonometric + cell passes)\n",
    "wave passes per flight", cf.FlightPasses[0], cf.FlightPasses[1], dt.FlightPasses[0],
    dt.FlightPasses[0] / cf.FlightPasses[0]);
  std::printf("%-34s %8.2f + %-5.2f %14.2f %7.2fx\n", "wave passes per shadow ray",
    cf.ShadowPasses[0], cf.ShadowPasses[1], dt.ShadowPasses[0],
    dt.ShadowPasses[0] / cf.ShadowPasses[0]);
  std::printf("(%d x %d pixels, %d spp, %d threads; CPU, not the paper's GPU: compare ratios)\n",
    options.Size, options.Size, options.Samples, vtkSMPTools::GetEstimatedNumberOfThreads());
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  std::string summary;
  for (const bool box : { false, true })
  {
    if (!(box ? options.Box : options.Cloud))
    {
      continue;
    }
    for (const double offset : options.Offsets)
    {
      CloudScene scene(box ? 2 : options.Shape, box, offset);
      vtkCosineNoise* noise = scene.Detail;
      const double majorant = (noise->GetMaximumValue()) / noise->GetOffset();
      const double clamped = ClampedShare(noise);
      char name[64];
      std::snprintf(name, sizeof(name), "%.3g sigma", offset);
      const std::string offsetName = offset > 0.0 ? name : "non-negative";
      std::printf("\nBenchPathTracer: %s x cosine noise (%d waves), offset %s (contrast %.3g, "
                  "majorant / mean %.3g, clamped share of the noise %.2g), %d x %d, %d spp, 4 "
                  "bounces\n",
        box ? "the paper's setting, a constant 2^3 shape (one cell per ray, mean optical depth "
              "8 across)"
            : (std::to_string(options.Shape) + "^3 cloud shape").c_str(),
        noise->GetNumberOfWaves(), offsetName.c_str(),
        noise->GetStandardDeviation() / noise->GetOffset(), majorant, clamped, options.Size,
        options.Size, options.Samples);
      Result cf, dt;
      if (!Run(scene, vtkVolumetricPathTracer::CLOSED_FORM, options, cf) ||
        !Run(scene, vtkVolumetricPathTracer::DELTA_TRACKING, options, dt))
      {
        std::printf("FAILED: a render failed\n");
        return EXIT_FAILURE;
      }
      Print(cf, dt, options);
      // The one-pass bound: delta tracking's noise evaluations per ray. An
      // exact closed form needs at least one trigonometric pass per ray
      // (the waves' phases at its far end), which costs at least one
      // evaluation (a sine and cosine per wave against a cosine), so its
      // T + sampling speed-up cannot exceed this.
      const double bound = (dt.Flights * dt.FlightPasses[0] + dt.ShadowRays * dt.ShadowPasses[0]) /
        (dt.Flights + dt.ShadowRays);
      char line[256];
      std::snprintf(line, sizeof(line),
        "%-6s %-13s %8.3g %8.2g %9.2fx %9.2fx %9.2fx %9.2fx %9.2fx %9.2fx %+8.2f%% (%.2f%%)\n",
        box ? "box" : "cloud", offsetName.c_str(), majorant, clamped, dt.Tracking / cf.Tracking,
        dt.Flight / cf.Flight, (dt.Tracking - dt.Flight) / (cf.Tracking - cf.Flight),
        dt.Total / cf.Total, (dt.Total * dt.Variance) / (cf.Total * cf.Variance), bound,
        100.0 * (cf.Mean / dt.Mean - 1.0),
        100.0 * std::hypot(cf.MeanError, dt.MeanError) / dt.Mean);
      summary += line;
      // Not a timing check: both modes must see the same medium (means within a
      // factor 2 even at one sample; empty images are an error).
      const bool same =
        cf.Mean > 0.0 && dt.Mean > 0.0 && cf.Mean < 2.0 * dt.Mean && dt.Mean < 2.0 * cf.Mean;
      if (!same)
      {
        std::printf("FAILED: the two modes' mean radiance differ\n");
      }
      // Not a timing check either: the work is counted. Delta tracking
      // evaluates the noise at least once per flight that meets the medium;
      // in the box, a shadow ray starts at a collision with its phases and
      // crosses one cell, so the closed form takes one trigonometric pass.
      const bool counted = cf.Flights >= 1.0 && dt.Flights >= 1.0 && dt.FlightPasses[0] > 0.0 &&
        cf.FlightPasses[0] > 0.0 && dt.FlightPasses[1] == 0.0 &&
        (!box ||
          (cf.ShadowRays > 0.0 && std::abs(cf.ShadowPasses[0] - 1.0) < 1e-9 &&
            cf.ShadowPasses[1] == 0.0));
      if (!counted)
      {
        std::printf("FAILED: the work counts are not as expected\n");
      }
      ok = ok && same && counted;
    }
  }
  std::printf("\nSummary: closed form against delta tracking (speed-ups; > 1: the closed form is "
              "faster; one-pass bound: the most an exact closed form can gain)\n"
              "%-6s %-12s %8s %8s %10s %10s %10s %10s %10s %10s %s\n%s",
    "scene", "offset", "maj/mean", "clamped", "T+sampl.", "sampling", "T alone", "total",
    "equal var.", "1-pass bd", "mean cf/dt - 1 (s.e.)", summary.c_str());
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
