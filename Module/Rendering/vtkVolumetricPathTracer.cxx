#include "vtkVolumetricPathTracer.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTyndallParticleMedium.h"
#include "vtkTyndallReferenceScene.h"
#include "vtkTyndallSceneReader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkVolumetricPathTracer);

class vtkVolumetricPathTracer::vtkInternals
{
public:
  vtkTyndallSceneReader Scene;
};

namespace
{
// The most tentative collisions delta tracking may expect across the box.
constexpr double kMaxStepsPerRay = 1.0e7;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Russian roulette: paths whose largest throughput channel falls below this.
constexpr double kRouletteThreshold = 0.25;
// Ratio tracking: Russian roulette (survival 1/2) below this transmittance.
constexpr double kRatioRouletteThreshold = 0.1;

using Clock = std::chrono::steady_clock;
using Phases = vtkTyndallDetailMedium::PointPhases;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

// xoshiro256+ seeded by SplitMix64: one per pixel.
class Random
{
public:
  Random(std::uint64_t seed, std::uint64_t stream)
  {
    std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + stream * 0xD1B54A32D192ED03ull + 1;
    for (std::uint64_t& word : this->State)
    {
      x += 0x9E3779B97F4A7C15ull;
      std::uint64_t z = x;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      word = z ^ (z >> 31);
    }
  }
  /// Uniform in [0, 1).
  double Uniform()
  {
    std::uint64_t* s = this->State;
    const std::uint64_t result = s[0] + s[3];
    const std::uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = (s[3] << 45) | (s[3] >> 19);
    return static_cast<double>(result >> 11) * 0x1.0p-53;
  }
  /// An exponential variate of unit mean, -ln(1 - xi).
  double Exponential() { return -std::log1p(-this->Uniform()); }

private:
  std::uint64_t State[4];
};

// Per-thread time accumulators (seconds).
struct Timing
{
  double Tracking = 0.0;
  double Total = 0.0;
  double FlightTime = 0.0; // the share of Tracking in free flights

  // Work (see the class description): counts, and the passes over the
  // waves of the flights and of the shadow rays.
  double Flights = 0.0;
  double ShadowRays = 0.0;
  vtkTyndallDetailMedium::Work FlightWork;
  vtkTyndallDetailMedium::Work ShadowWork;

  void Add(const Timing& other)
  {
    this->Tracking += other.Tracking;
    this->Total += other.Total;
    this->FlightTime += other.FlightTime;
    this->Flights += other.Flights;
    this->ShadowRays += other.ShadowRays;
    this->FlightWork.Add(other.FlightWork);
    this->ShadowWork.Add(other.ShadowWork);
  }
};

// Everything the rendering loop reads.
struct Scene : public vtkTyndallReferenceScene
{
  bool ClosedForm = false;
  double Majorant = 0.0;
  int Samples = 1;
  int MaxBounces = 1;
  std::uint64_t Seed = 1;
  double* StandardError = nullptr;
};

// A ray in world (origin X, unit direction W) and field index (O, D)
// coordinates, with its parameter range [T0, T1] (world distances).
struct Ray
{
  double X[3];
  double W[3];
  double O[3];
  double D[3];
  double T0 = 0.0;
  double T1 = kInfinity;

  // Sets the index-space twin and clips to the box; false if it misses it.
  bool Clip(const Scene& s)
  {
    s.ToIndexPoint(this->X, this->O);
    s.ToIndexDirection(this->W, this->D);
    return Scene::ClipToBox(this->O, this->D, s.BoxLow, s.BoxHigh, this->T0, this->T1);
  }
};

template <typename T>
class PathTracer
{
public:
  PathTracer(const Scene& scene, const vtkTyndallGridMedium& medium, vtkSMPThreadLocal<Timing>& t)
    : S(&scene)
    , Field(medium)
    , Times(&t)
  {
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    Timing& timing = this->Times->Local();
    for (vtkIdType j = begin; j < end; ++j)
    {
      for (int i = 0; i < this->S->Width; ++i)
      {
        this->RenderPixel(i, static_cast<int>(j), timing);
      }
    }
  }

private:
  const Scene* S;
  vtkTyndallGridMedium::Sampler<T> Field;
  vtkSMPThreadLocal<Timing>* Times;

  // sigma_t at a field index point inside the box; `passes` counts the
  // detail noise's evaluations.
  double Sigma(const double p[3], double& passes) const
  {
    if (!this->S->Inside(p))
    {
      return 0.0;
    }
    if (this->S->Detail)
    {
      return this->S->Detail->Extinction(p, &passes);
    }
    const double v = this->Field.ReferenceScalar(p);
    if (std::isnan(v))
    {
      return 0.0;
    }
    int k;
    double f;
    this->S->Table->Locate(v, k, f);
    return this->S->DensityScale * this->S->Table->ExtinctionAt(k, f);
  }

  // Colour and emission (scaled) at a field index point; 0 for missing data.
  void Material(const double p[3], double color[3], double emission[3]) const
  {
    std::fill(color, color + 3, 0.0);
    std::fill(emission, emission + 3, 0.0);
    const double v = this->Field.ReferenceScalar(p);
    if (std::isnan(v))
    {
      return;
    }
    int k;
    double f;
    this->S->Table->Locate(v, k, f);
    vtkTyndallTransferTable::RGBAt(this->S->Table->Albedo, k, f, color);
    this->Field.ReferenceColor(p, color); // a coloured particle cloud's own
    if (this->S->HasEmission && this->S->SingleScattering)
    {
      vtkTyndallTransferTable::RGBAt(this->S->Table->Emission, k, f, emission);
      for (int c = 0; c < 3; ++c)
      {
        emission[c] *= this->S->EmissionScale;
      }
    }
  }

  // A free flight along the clipped ray: true and t at a real collision,
  // false when the ray leaves [T0, T1] first.
  // The closed form reuses the waves' phases at the ray's start when it is
  // the last collision (`phases`), and leaves those at the new collision.
  bool FreeFlight(const Ray& ray, Random& rng, double& t, Timing& timing, Phases& phases) const
  {
    const auto start = Clock::now();
    bool hit;
    if (this->S->ClosedForm)
    {
      hit = this->S->Detail->SampleDistance(
        ray.O, ray.D, ray.T0, ray.T1, rng.Exponential(), t, &phases, &phases, &timing.FlightWork);
    }
    else
    {
      hit = this->DeltaTrack(ray, rng, t, timing.FlightWork.TrigonometricPasses);
    }
    const double seconds = Seconds(start, Clock::now());
    timing.Tracking += seconds;
    timing.FlightTime += seconds;
    timing.Flights += 1.0;
    return hit;
  }

  bool DeltaTrack(const Ray& ray, Random& rng, double& t, double& passes) const
  {
    const double majorant = this->S->Majorant;
    if (!(majorant > 0.0))
    {
      return false;
    }
    t = ray.T0;
    for (;;)
    {
      t += rng.Exponential() / majorant;
      if (t >= ray.T1)
      {
        return false;
      }
      const double p[3] = { ray.O[0] + t * ray.D[0], ray.O[1] + t * ray.D[1],
        ray.O[2] + t * ray.D[2] };
      if (rng.Uniform() * majorant < this->Sigma(p, passes))
      {
        return true;
      }
    }
  }

  // T_l from p along dl (index image of a unit world direction) to the box's
  // exit or the world distance tMax.
  double LightTransmittance(const double p[3], const double dl[3], double tMax, Random& rng,
    Timing& timing, const Phases& phases) const
  {
    const auto start = Clock::now();
    double t0 = 0.0, t1 = tMax;
    double transmittance = 1.0;
    if (Scene::ClipToBox(p, dl, this->S->BoxLow, this->S->BoxHigh, t0, t1))
    {
      transmittance = this->S->ClosedForm
        ? std::exp(-this->S->Detail->OpticalDepth(p, dl, t0, t1, &phases, &timing.ShadowWork))
        : this->RatioTrack(p, dl, t0, t1, rng, timing.ShadowWork.TrigonometricPasses);
    }
    timing.Tracking += Seconds(start, Clock::now());
    timing.ShadowRays += 1.0;
    return transmittance;
  }

  double RatioTrack(
    const double p[3], const double d[3], double t, double t1, Random& rng, double& passes) const
  {
    const double majorant = this->S->Majorant;
    double transmittance = 1.0;
    if (!(majorant > 0.0))
    {
      return transmittance;
    }
    for (;;)
    {
      t += rng.Exponential() / majorant;
      if (t >= t1)
      {
        return transmittance;
      }
      const double q[3] = { p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2] };
      transmittance *= std::max(0.0, 1.0 - this->Sigma(q, passes) / majorant);
      if (transmittance < kRatioRouletteThreshold)
      {
        if (transmittance <= 0.0 || rng.Uniform() < 0.5)
        {
          return 0.0;
        }
        transmittance *= 2.0;
      }
    }
  }

  // c (ambient + sum_l E_l f_l p(mu_l) T_l) + emission at a collision at the
  // world point x (index point p) reached along w.
  void Source(const double x[3], const double p[3], const double w[3], const double color[3],
    const double emission[3], Random& rng, Timing& timing, const Phases& phases, double J[3]) const
  {
    const Scene& s = *this->S;
    double in[3] = { s.Ambient, s.Ambient, s.Ambient };
    if (color[0] != 0.0 || color[1] != 0.0 || color[2] != 0.0)
    {
      s.AddInScattering(
        x, w, color,
        [&](const double dl[3], double tMax)
        { return this->LightTransmittance(p, dl, tMax, rng, timing, phases); },
        in);
    }
    for (int c = 0; c < 3; ++c)
    {
      J[c] = color[c] * in[c] + emission[c];
    }
  }

  // Russian roulette on the throughput; false when the path ends.
  static bool Survive(double beta[3], Random& rng)
  {
    const double q = std::max({ beta[0], beta[1], beta[2] });
    if (!(q > 0.0))
    {
      return false;
    }
    if (q >= kRouletteThreshold)
    {
      return true;
    }
    if (rng.Uniform() >= q)
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      beta[c] /= q;
    }
    return true;
  }

  // One path from the camera ray; adds its radiance to L. Returns whether the
  // first free flight left the medium.
  bool TracePath(Ray ray, Random& rng, Timing& timing, Phases& phases, double L[3]) const
  {
    const Scene& s = *this->S;
    double beta[3] = { 1.0, 1.0, 1.0 };
    for (int bounce = 0;; ++bounce)
    {
      double t;
      if (!ray.Clip(s) || !this->FreeFlight(ray, rng, t, timing, phases))
      {
        return bounce == 0;
      }
      const double x[3] = { ray.X[0] + t * ray.W[0], ray.X[1] + t * ray.W[1],
        ray.X[2] + t * ray.W[2] };
      const double p[3] = { ray.O[0] + t * ray.D[0], ray.O[1] + t * ray.D[1],
        ray.O[2] + t * ray.D[2] };
      double color[3], emission[3], J[3];
      this->Material(p, color, emission);
      if (!s.SingleScattering)
      {
        std::copy(color, color + 3, J);
      }
      else
      {
        this->Source(x, p, ray.W, color, emission, rng, timing, phases, J);
      }
      for (int c = 0; c < 3; ++c)
      {
        L[c] += beta[c] * J[c];
        beta[c] *= color[c];
      }
      if (!s.SingleScattering || bounce + 1 >= s.MaxBounces || !Survive(beta, rng))
      {
        return false;
      }
      std::copy(x, x + 3, ray.X);
      const double w[3] = { ray.W[0], ray.W[1], ray.W[2] };
      const double u1 = rng.Uniform();
      vtkVolumetricPathTracer::SampleHenyeyGreenstein(s.G, w, u1, rng.Uniform(), ray.W);
      ray.T0 = 0.0;
      ray.T1 = kInfinity;
    }
  }

  // The exact view transmittance of the camera ray (closed form only): an
  // output, not part of a path, so not timed.
  double ViewTransmittance(Ray ray) const
  {
    return ray.Clip(*this->S)
      ? std::exp(-this->S->Detail->OpticalDepth(ray.O, ray.D, ray.T0, ray.T1))
      : 1.0;
  }

  void RenderPixel(int i, int j, Timing& timing) const
  {
    const Scene& s = *this->S;
    const vtkIdType pixel = static_cast<vtkIdType>(j) * s.Width + i;
    double sum[3] = { 0.0, 0.0, 0.0 }, squares[3] = { 0.0, 0.0, 0.0 };
    int escapes = s.Samples;
    Ray camera;
    const bool valid = s.CameraRay(i, j, camera.X, camera.W, camera.T1);
    if (valid)
    {
      Random rng(s.Seed, static_cast<std::uint64_t>(pixel));
      Phases phases; // the closed form's at the last collision
      escapes = 0;
      for (int n = 0; n < s.Samples; ++n)
      {
        double L[3] = { 0.0, 0.0, 0.0 };
        const auto start = Clock::now();
        escapes += this->TracePath(camera, rng, timing, phases, L) ? 1 : 0;
        timing.Total += Seconds(start, Clock::now());
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += L[c];
          squares[c] += L[c] * L[c];
        }
      }
    }
    const double n = s.Samples;
    for (int c = 0; c < 3; ++c)
    {
      const double mean = sum[c] / n;
      const double variance = n > 1 ? std::max(0.0, squares[c] - n * mean * mean) / (n - 1) : 0.0;
      s.Radiance[3 * pixel + c] = mean;
      s.StandardError[3 * pixel + c] = std::sqrt(variance / n);
    }
    s.Transmittance[pixel] =
      (valid && s.ClosedForm) ? this->ViewTransmittance(camera) : escapes / n;
  }
};

template <typename T>
void RenderRows(const Scene& scene, const vtkTyndallGridMedium& medium,
  vtkSMPThreadLocal<Timing>& timing, vtkIdType begin, vtkIdType end)
{
  PathTracer<T> tracer(scene, medium, timing);
  vtkSMPTools::For(begin, end, 1, tracer);
}

// The majorant of delta tracking (per world unit): the table's largest
// extinction, or for a particle medium (sampled exactly, not on its grid) a
// bound of the particles' sum.
double GridMajorant(const vtkTyndallGridMedium& medium)
{
  if (const vtkTyndallParticleMedium* particles = medium.GetParticles())
  {
    return medium.GetDensityScale() * particles->GetDensityBound();
  }
  const std::vector<double>& extinction = medium.GetTable().Extinction;
  const double largest =
    extinction.empty() ? 0.0 : *std::max_element(extinction.begin(), extinction.end());
  return medium.GetDensityScale() * largest;
}

vtkSmartPointer<vtkDoubleArray> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}
}

//------------------------------------------------------------------------------
vtkVolumetricPathTracer::vtkVolumetricPathTracer()
  : Internals(new vtkInternals)
{
  this->Output = vtkImageData::New();
  this->CompositeOutput = vtkImageData::New();
}

//------------------------------------------------------------------------------
vtkVolumetricPathTracer::~vtkVolumetricPathTracer()
{
  this->Output->Delete();
  this->CompositeOutput->Delete();
}

//------------------------------------------------------------------------------
vtkImageData* vtkVolumetricPathTracer::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
void vtkVolumetricPathTracer::UpdateProgress(double progress)
{
  this->Progress = progress;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
}

//------------------------------------------------------------------------------
void vtkVolumetricPathTracer::SampleHenyeyGreenstein(
  double g, const double w[3], double u1, double u2, double out[3])
{
  g = std::isnan(g) ? 0.0 : std::min(std::max(g, -0.99), 0.99);
  double mu;
  if (std::abs(g) < 1.0e-5)
  {
    mu = 1.0 - 2.0 * u1;
  }
  else
  {
    const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
    mu = (1.0 + g * g - s * s) / (2.0 * g);
  }
  mu = std::min(1.0, std::max(-1.0, mu));
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double phi = 2.0 * vtkMath::Pi() * u2;
  // An orthonormal basis (u, v, w) (Duff et al. 2017).
  const double sign = std::copysign(1.0, w[2]);
  const double a = -1.0 / (sign + w[2]);
  const double b = w[0] * w[1] * a;
  const double u[3] = { 1.0 + sign * w[0] * w[0] * a, sign * b, -sign * w[0] };
  const double v[3] = { b, sign + w[1] * w[1] * a, -w[1] };
  const double cu = sinTheta * std::cos(phi), cv = sinTheta * std::sin(phi);
  for (int c = 0; c < 3; ++c)
  {
    out[c] = mu * w[c] + cu * u[c] + cv * v[c];
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkVolumetricPathTracer::Render(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  this->AbortExecute = false;
  this->Progress = 0.0;
  return vtkTyndallReferenceScene::TimedRender(
    this, this->Output, this->CompositeOutput,
    [&] { return this->RenderInternal(renderer, volume, width, height); }, this->LastRenderTime);
}

//------------------------------------------------------------------------------
namespace
{
// The distance sampling actually used and the majorant of delta tracking;
// false (with an error through `reporter`) when delta tracking would take
// too many steps.
bool SetUpSampling(
  const vtkTyndallSceneReader& tyndall, int mode, Scene& scene, vtkObject* reporter)
{
  const bool closedForm = mode == vtkVolumetricPathTracer::CLOSED_FORM;
  scene.ClosedForm = closedForm && scene.Detail && !scene.Clip;
  if (closedForm && !scene.Detail)
  {
    vtkWarningWithObjectMacro(
      reporter, << "Render: CLOSED_FORM distance sampling needs a procedural medium (a "
                   "DetailNoise); this grid medium is rendered with DELTA_TRACKING.");
  }
  else if (closedForm && scene.Clip)
  {
    vtkWarningWithObjectMacro(
      reporter, << "Render: the closed form integrates the unclipped medium; with clipping "
                   "planes or cropping the medium is rendered with DELTA_TRACKING.");
  }
  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  if (scene.EmissionArray)
  {
    vtkErrorWithObjectMacro(reporter, << "Render: emission from a separate array "
                                         "(EmissionArrayName) is not supported by the path "
                                         "tracer; vtkSingleScatteringReference renders it.");
    return false;
  }
  if (scene.Chromatic)
  {
    vtkErrorWithObjectMacro(reporter, << "Render: a coloured extinction (ExtinctionColor with "
                                         "unequal components) is not supported by the path "
                                         "tracer; vtkSingleScatteringReference renders it.");
    return false;
  }
  if (!scene.Guests.empty())
  {
    vtkErrorWithObjectMacro(reporter, << "Render: other Tyndall volumes in the renderer cast "
                                         "shadows into this one, which the path tracer does not "
                                         "trace; hide them or switch the property's SceneShadows "
                                         "off; vtkSingleScatteringReference renders them.");
    return false;
  }
  scene.Majorant =
    scene.ClosedForm ? 0.0 : (scene.Detail ? scene.Detail->GetMajorant() : GridMajorant(medium));
  if (!std::isfinite(scene.Majorant) ||
    scene.Majorant * medium.GetWorldDiagonal() > kMaxStepsPerRay)
  {
    vtkErrorWithObjectMacro(reporter, << "Render: delta tracking against the majorant "
                                      << scene.Majorant << " would take more than "
                                      << kMaxStepsPerRay
                                      << " steps across the volume; use CLOSED_FORM or a smaller "
                                         "density.");
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkVolumetricPathTracer::RenderInternal(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  vtkTyndallSceneReader& tyndall = this->Internals->Scene;
  Scene scene;
  if (!scene.ReadScene(tyndall, renderer, volume, width, height, this) ||
    !SetUpSampling(tyndall, this->DistanceSampling, scene, this))
  {
    return false;
  }
  // The paths scatter for real: the octaves' approximation is what they
  // are the reference for, so it is not applied to their light.
  scene.Octaves = 1;
  scene.Samples = this->SamplesPerPixel;
  scene.MaxBounces = this->MaximumBounces;
  scene.Seed = this->Seed;
  if (!scene.SetUpView(tyndall, renderer, this))
  {
    return false;
  }

  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  auto radiance = NewArray("Radiance", 3, pixels);
  auto transmittance = NewArray("Transmittance", 1, pixels);
  auto error = NewArray("RadianceStandardError", 3, pixels);
  scene.Radiance = radiance->GetPointer(0);
  scene.Transmittance = transmittance->GetPointer(0);
  scene.StandardError = error->GetPointer(0);

  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  vtkSMPThreadLocal<Timing> timing;
  const auto rows = [&](vtkIdType begin, vtkIdType end)
  {
    switch (medium.GetScalars()->GetDataType())
    {
      vtkTemplateMacro(RenderRows<VTK_TT>(scene, medium, timing, begin, end));
    }
  };
  if (!scene.RenderRowBatches(
        this->AbortExecute, [this](double progress) { this->UpdateProgress(progress); }, rows))
  {
    return false;
  }

  Timing sum;
  for (const Timing& t : timing)
  {
    sum.Add(t);
  }
  this->LastTrackingTimePerSample = sum.Tracking / this->SamplesPerPixel;
  this->LastTotalTimePerSample = sum.Total / this->SamplesPerPixel;
  this->LastFlightTimePerSample = sum.FlightTime / this->SamplesPerPixel;
  const double paths = static_cast<double>(pixels) * this->SamplesPerPixel;
  const auto per = [](double count, double of) { return of > 0.0 ? count / of : 0.0; };
  this->LastFlightsPerSample = sum.Flights / paths;
  this->LastShadowRaysPerSample = sum.ShadowRays / paths;
  this->LastTrigonometricPassesPerFlight = per(sum.FlightWork.TrigonometricPasses, sum.Flights);
  this->LastTrigonometricPassesPerShadowRay =
    per(sum.ShadowWork.TrigonometricPasses, sum.ShadowRays);
  this->LastCellPassesPerFlight = per(sum.FlightWork.CellPasses, sum.Flights);
  this->LastCellPassesPerShadowRay = per(sum.ShadowWork.CellPasses, sum.ShadowRays);
  this->LastDistanceSampling = scene.ClosedForm ? CLOSED_FORM : DELTA_TRACKING;
  this->LastMajorant = scene.Majorant;
  scene.SetOutput(this->Output, radiance, transmittance, error);
  renderer->GetBackground(this->LastBackground);
  return true;
}

//------------------------------------------------------------------------------
vtkImageData* vtkVolumetricPathTracer::Composite()
{
  return this->Composite(this->LastBackground);
}

//------------------------------------------------------------------------------
vtkImageData* vtkVolumetricPathTracer::Composite(const double background[3])
{
  vtkDataArray* radiance = this->Output->GetPointData()->GetArray("Radiance");
  vtkDataArray* transmittance = this->Output->GetPointData()->GetArray("Transmittance");
  this->CompositeOutput->Initialize();
  if (!radiance || !transmittance || !background)
  {
    vtkErrorMacro(<< "Composite: there is no rendered image (call Render() first) or the "
                     "background is null.");
    return nullptr;
  }
  vtkTyndallReferenceScene::Composite(
    this->Output, radiance, transmittance, background, this->CompositeOutput);
  return this->CompositeOutput;
}

//------------------------------------------------------------------------------
void vtkVolumetricPathTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DistanceSampling: "
     << (this->DistanceSampling == CLOSED_FORM ? "CLOSED_FORM" : "DELTA_TRACKING") << "\n";
  os << indent << "SamplesPerPixel: " << this->SamplesPerPixel << "\n";
  os << indent << "MaximumBounces: " << this->MaximumBounces << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "AbortExecute: " << (this->AbortExecute ? "On" : "Off") << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "LastDistanceSampling: " << this->LastDistanceSampling << "\n";
  os << indent << "LastMajorant: " << this->LastMajorant << "\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
  os << indent << "LastTrackingTimePerSample: " << this->LastTrackingTimePerSample << "\n";
  os << indent << "LastTotalTimePerSample: " << this->LastTotalTimePerSample << "\n";
  os << indent << "LastFlightTimePerSample: " << this->LastFlightTimePerSample << "\n";
  os << indent << "LastFlightsPerSample: " << this->LastFlightsPerSample << "\n";
  os << indent << "LastShadowRaysPerSample: " << this->LastShadowRaysPerSample << "\n";
  os << indent << "LastTrigonometricPassesPerFlight: " << this->LastTrigonometricPassesPerFlight
     << "\n";
  os << indent
     << "LastTrigonometricPassesPerShadowRay: " << this->LastTrigonometricPassesPerShadowRay
     << "\n";
  os << indent << "LastCellPassesPerFlight: " << this->LastCellPassesPerFlight << "\n";
  os << indent << "LastCellPassesPerShadowRay: " << this->LastCellPassesPerShadowRay << "\n";
  os << indent << "LastBackground: (" << this->LastBackground[0] << ", " << this->LastBackground[1]
     << ", " << this->LastBackground[2] << ")\n";
}
