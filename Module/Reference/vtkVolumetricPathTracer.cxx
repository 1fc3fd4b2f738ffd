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
#include "vtkTyndallComponents.h"
#include "vtkTyndallEnvironment.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallReferenceScene.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallShading.h"
#include "vtkTyndallSurfaceLobe.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkVolumetricPathTracer);

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
  vtkTyndallMedium::Work FlightWork;
  vtkTyndallMedium::Work ShadowWork;

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

constexpr int kMaxMedia = vtkTyndallReferenceScene::MaximumNumberOfMedia;
using Cache = vtkTyndallMedium::PathCache;
using Point = vtkTyndallMedium::Point;

// Everything the rendering loop reads.
struct Scene : public vtkTyndallReferenceScene
{
  /// Per medium: its free flights and light transmittance in closed form,
  /// and delta tracking's majorant otherwise.
  bool ClosedForm[kMaxMedia] = {};
  double Majorant[kMaxMedia] = {};
  int Samples = 1;
  int MaxBounces = 1;
  std::uint64_t Seed = 1;
  double* StandardError = nullptr;
  /// The volume's grid when its collisions scatter as VTK's shaded surfaces
  /// (vtkTyndallSurfaceLobe; a plain property with Shade on) or add their
  /// surface term (SurfaceAdded), else null.
  const vtkTyndallGridMedium* Surface = nullptr;
  /// A vtkParticipatingMediumProperty's Shade: the collisions scatter by
  /// the phase function and add the lobe's light, LightUnit times (the
  /// lights not scaled; the lobe never sampled).
  bool SurfaceAdded = false;
  /// How far a shaded collision's light is exchanged from (world, along its direction).
  double SurfaceOffset = 0.0;
};

// A ray in world (origin X, unit direction W) and in every medium's frame,
// with its parameter range [T0, T1] (world distances) and, per medium, its
// part in that medium's box (Crosses: whether it has one).
struct Ray
{
  double X[3];
  double W[3];
  double T0 = 0.0;
  double T1 = kInfinity;
  /// The sky's radiance factor when this ray, scattered, leaves the media:
  /// vtkTyndallSurfaceLobe::LightUnit after a plain property's shaded
  /// collision (its lobe's unit), else 1.
  double SkyUnit = 1.0;
  vtkTyndallReferenceScene::LocalRays Local;
  double Low[kMaxMedia];
  double High[kMaxMedia];
  bool Crosses[kMaxMedia];

  // Sets the media's images and parts of the ray among the media `camera`
  // selects (the camera media, or all); false if it misses them all.
  bool Clip(const Scene& s, bool camera)
  {
    this->Local.Set(s, this->X, this->W);
    bool any = false;
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      const vtkTyndallMedium& m = *s.Media[k].Medium;
      this->Low[k] = this->T0;
      this->High[k] = this->T1;
      this->Crosses[k] = (!camera || s.Media[k].Camera) &&
        vtkTyndallMedium::ClipToBox(this->Local.O[k], this->Local.D[k], m.GetBoxLow(),
          m.GetBoxHigh(), this->Low[k], this->High[k]);
      any = any || this->Crosses[k];
    }
    return any;
  }
};

// One path's state: the media's caches at its last collision (the detail's
// phases), shared by its flights and shadow rays.
struct PathState
{
  Cache Caches[kMaxMedia];
};

class PathTracer
{
public:
  PathTracer(const Scene& scene, vtkSMPThreadLocal<Timing>& t)
    : S(&scene)
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
  vtkSMPThreadLocal<Timing>* Times;

  // A free flight in medium k along its part of the ray: true and t at a
  // real collision of that medium, false when the ray leaves it first. With
  // a coloured extinction (the medium alone in its scene), spectral
  // tracking: the densest channel's collisions, each channel's throughput
  // weighted by its ratio to them (`weight`: e_c at the real collision,
  // (m - e_c sigma) / (m - sigma) at each null one), against twice the
  // majorant m so that a null weight stays below 2 (against the majorant
  // itself it grows without bound where sigma nears it: a heavy tail that
  // biased the mean of 512 samples by 1 %).
  bool FlightIn(int k, const Ray& ray, Random& rng, double& t, Timing& timing, PathState& path,
    double weight[3]) const
  {
    const Scene& s = *this->S;
    const vtkTyndallMedium& medium = *s.Media[k].Medium;
    const double* o = ray.Local.O[k];
    const double* d = ray.Local.D[k];
    if (s.ClosedForm[k])
    {
      return medium.SampleDistance(o, d, ray.Low[k], ray.High[k], rng.Exponential(), t,
        &path.Caches[k], &path.Caches[k], &timing.FlightWork);
    }
    const bool chromatic = s.GetChromatic();
    const double majorant = (chromatic ? 2.0 : 1.0) * s.Majorant[k];
    if (!(majorant > 0.0))
    {
      return false;
    }
    const double* e = s.Parameters->ExtinctionColor;
    t = ray.Low[k];
    for (;;)
    {
      t += rng.Exponential() / majorant;
      if (t >= ray.High[k])
      {
        return false;
      }
      const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      const double sigma = medium.Extinction(p, &timing.FlightWork);
      if (rng.Uniform() * majorant < sigma)
      {
        if (chromatic)
        {
          for (int c = 0; c < 3; ++c)
          {
            weight[c] *= e[c];
          }
        }
        return true;
      }
      if (chromatic)
      {
        for (int c = 0; c < 3; ++c)
        {
          weight[c] *= (majorant - e[c] * sigma) / (majorant - sigma);
        }
      }
    }
  }

  // A free flight through the media the ray crosses: the first real
  // collision of any (each medium's own flight, the nearest wins: their
  // extinctions add). True with t and the medium k; false when the ray
  // leaves them all. `weight`: see FlightIn().
  bool FreeFlight(const Ray& ray, Random& rng, double& t, int& k, Timing& timing, PathState& path,
    double weight[3]) const
  {
    const auto start = Clock::now();
    bool hit = false;
    t = kInfinity;
    for (size_t m = 0; m < this->S->Media.size(); ++m)
    {
      double tm;
      if (ray.Crosses[m] &&
        this->FlightIn(static_cast<int>(m), ray, rng, tm, timing, path, weight) && tm < t)
      {
        t = tm;
        k = static_cast<int>(m);
        hit = true;
      }
    }
    const double seconds = Seconds(start, Clock::now());
    timing.Tracking += seconds;
    timing.FlightTime += seconds;
    timing.Flights += 1.0;
    return hit;
  }

  // Ratio tracking through medium k from o along d over [t, t1]: an
  // unbiased estimate of each channel's transmittance.
  void RatioTrack(int k, const double o[3], const double d[3], double t, double t1, Random& rng,
    Timing& timing, double T[3]) const
  {
    const Scene& s = *this->S;
    const vtkTyndallMedium& medium = *s.Media[k].Medium;
    const double majorant = s.Majorant[k];
    T[0] = T[1] = T[2] = 1.0;
    if (!(majorant > 0.0))
    {
      return;
    }
    const bool chromatic = s.GetChromatic();
    const double* e = s.Parameters->ExtinctionColor;
    for (;;)
    {
      t += rng.Exponential() / majorant;
      if (t >= t1)
      {
        return;
      }
      const double q[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      const double sigma = medium.Extinction(q, &timing.ShadowWork);
      for (int c = 0; c < 3; ++c)
      {
        T[c] *= std::max(0.0, 1.0 - (chromatic ? e[c] : 1.0) * sigma / majorant);
      }
      const double largest = std::max({ T[0], T[1], T[2] });
      if (largest < kRatioRouletteThreshold)
      {
        if (largest <= 0.0 || rng.Uniform() < 0.5)
        {
          T[0] = T[1] = T[2] = 0.0;
          return;
        }
        for (int c = 0; c < 3; ++c)
        {
          T[c] *= 2.0;
        }
      }
    }
  }

  // The transmittance of medium k along o + t d over [t0, t1] (its part in
  // the box), per channel: exact in closed form, else ratio tracked.
  void MediumTransmittance(int k, const double o[3], const double d[3], double t0, double t1,
    Random& rng, Timing& timing, const PathState& path, double T[3]) const
  {
    const Scene& s = *this->S;
    const vtkTyndallMedium& medium = *s.Media[k].Medium;
    if (!vtkTyndallMedium::ClipToBox(o, d, medium.GetBoxLow(), medium.GetBoxHigh(), t0, t1))
    {
      T[0] = T[1] = T[2] = 1.0;
      return;
    }
    if (s.ClosedForm[k])
    {
      s.ChannelTransmittances(std::exp(-medium.OpticalDepth(o, d, t0, t1, 0.0, kInfinity, true,
                                &path.Caches[k], &timing.ShadowWork)),
        T);
      return;
    }
    this->RatioTrack(k, o, d, t0, t1, rng, timing, T);
  }

  // T_l per channel from the collision at the world distance t of `ray`
  // (world point x) along the unit world direction l to the world distance
  // tMax: the product of every medium's.
  void LightTransmittance(const Ray& ray, double t, const double x[3], const double l[3],
    double tMax, Random& rng, Timing& timing, const PathState& path, double T[3]) const
  {
    double own[3];
    ray.Local.At(0, t, own); // the path's own frame, as the collision was found
    this->MediaTransmittance(x, own, l, tMax, rng, timing, path, T);
  }

  // T_l per channel from the world point x (`own`: its point in the
  // volume's own frame, or null to map x) along the unit world direction l
  // to the world distance tMax: the product of every medium's.
  void MediaTransmittance(const double x[3], const double* own, const double l[3], double tMax,
    Random& rng, Timing& timing, const PathState& path, double T[3]) const
  {
    const auto start = Clock::now();
    const Scene& s = *this->S;
    T[0] = T[1] = T[2] = 1.0;
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      const vtkTyndallMedium& medium = *s.Media[k].Medium;
      double p[3], d[3], Tk[3];
      if (k == 0 && own)
      {
        std::copy(own, own + 3, p);
      }
      else
      {
        medium.ToLocalPoint(x, p);
      }
      medium.ToLocalDirection(l, d);
      this->MediumTransmittance(static_cast<int>(k), p, d, 0.0, tMax, rng, timing, path, Tk);
      for (int c = 0; c < 3; ++c)
      {
        T[c] *= Tk[c];
      }
    }
    timing.Tracking += Seconds(start, Clock::now());
    timing.ShadowRays += 1.0;
  }

  // c (ambient + sum_l E_l f_l p(mu_l) T_l) + emission at a collision in
  // the medium lit as `lit` (its own parameters) at the world distance t of
  // `ray` (world point x): the light transmittance per channel is each
  // channel's own estimate with a coloured extinction.
  void Source(const Ray& ray, double t, const vtkTyndallMediumParameters& lit, const double x[3],
    const Point& point, Random& rng, Timing& timing, const PathState& path, double J[3]) const
  {
    this->S->Source(
      point, x, ray.W, lit,
      [&](const double l[3], double tMax, double T[3])
      { this->LightTransmittance(ray, t, x, l, tMax, rng, timing, path, T); },
      J);
  }

  // Adds beta times an estimate of the emission from arrays along the ray's
  // parts [Low, High] in the media that have one: per unit length, seen
  // through the media the ray crosses (stratified samples of the segment,
  // the transmittance to each ratio tracked, or exact in closed form). The
  // samples ascend: the transmittance to each is the one before's times
  // that of the part between them (independent estimates, so their
  // product's mean is the transmittance): each medium with an array tracks
  // the ray once, from its start to its last sample, not once per sample.
  void AddArrayEmission(const Ray& ray, const double beta[3], Random& rng, Timing& timing,
    const PathState& path, double L[3]) const
  {
    const Scene& s = *this->S;
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      const vtkTyndallMedium& medium = *s.Media[k].Medium;
      if (!ray.Crosses[k] || !medium.GetArrayEmission())
      {
        continue;
      }
      const int n = vtkTyndallMedium::PathEmissionSamples;
      const double length = (ray.High[k] - ray.Low[k]) / n;
      double T[3] = { 1.0, 1.0, 1.0 }; // from the ray's start to `from`
      double from = ray.T0;
      for (int i = 0; i < n && (T[0] > 0.0 || T[1] > 0.0 || T[2] > 0.0); ++i)
      {
        const double t = ray.Low[k] + (i + rng.Uniform()) * length;
        double p[3], e[3];
        ray.Local.At(static_cast<int>(k), t, p);
        medium.ArrayEmission(p, e);
        if (e[0] == 0.0 && e[1] == 0.0 && e[2] == 0.0)
        {
          continue;
        }
        // Times the transmittance from `from` to t through the media the ray crosses.
        for (size_t m = 0; m < s.Media.size(); ++m)
        {
          double Tm[3];
          if (!ray.Crosses[m])
          {
            continue;
          }
          this->MediumTransmittance(
            static_cast<int>(m), ray.Local.O[m], ray.Local.D[m], from, t, rng, timing, path, Tm);
          for (int c = 0; c < 3; ++c)
          {
            T[c] *= Tm[c];
          }
        }
        from = t;
        for (int c = 0; c < 3; ++c)
        {
          L[c] += beta[c] * length * T[c] * medium.GetParameters().EmissionScale * e[c];
        }
      }
    }
  }

  // The surface lobe of a collision in the shaded volume at its own point p
  // (vtkTyndallSurfaceLobe): the gradient's normal, towards where the path
  // came from (-w), with the blending's weight k (vtkTyndallShading::
  // BlendWeight()); `ambient`: VTK's ambient term Ka c. Independent
  // components: one drawn with its share of their parts in the mixture
  // (vtkTyndallGridMedium::ComponentParts(), which add up to P, not always
  // 1), whose gradient, colour, coefficients and weight k are taken, the
  // lobe and Ka c times P: an unbiased estimate of the map-based frame's
  // mixture of their shadings.
  vtkTyndallSurfaceLobe SurfaceLobe(
    const double p[3], const double w[3], const Point& point, Random& rng, double ambient[3]) const
  {
    const vtkTyndallGridMedium& grid = *this->S->Surface;
    const vtkTyndallShading& shading = grid.GetShading();
    constexpr int most = vtkTyndallComponents::MaximumCount;
    double weights[most] = { 1.0 }, colors[most][3] = {}, sigma[most] = {};
    std::copy(point.Albedo, point.Albedo + 3, colors[0]);
    int part = 0;
    double parts = 1.0; // P
    vtkTyndallSurfaceLobe lobe;
    ambient[0] = ambient[1] = ambient[2] = 0.0;
    // (An added surface term: component 0's, the mixture's colour.)
    if (!this->S->SurfaceAdded &&
      grid.GetComponents().GetMode() == vtkTyndallComponents::Independent)
    {
      if (!grid.ComponentParts(p, weights, colors, sigma))
      {
        return lobe; // missing data: no colour, no lobe
      }
      part = DrawPart(weights, grid.GetComponents().GetCount(), rng.Uniform(), parts);
    }
    else if (shading.GetBlending() > 0.0)
    {
      sigma[0] = grid.Extinction(p);
    }
    double n[3];
    grid.FieldGradient(p, n, part);
    const double length = vtkMath::Norm(n);
    for (int c = 0; c < 3; ++c)
    {
      n[c] = length > 0.0 ? n[c] / length : 0.0;
      ambient[c] = parts * shading.GetAmbient(part) * colors[part][c];
    }
    const double* range = grid.GetComponentRange(part);
    const double blend =
      shading.BlendWeight(length, sigma[part], range[1] - range[0], grid.GetMinimumWorldSpacing());
    const double v[3] = { -w[0], -w[1], -w[2] };
    lobe.Set(shading, n, v, colors[part], part, blend, parts);
    return lobe;
  }

  // The part drawn by u in [0, 1) with the probabilities `weights` / P (of
  // `count`; P, their sum, in `sum`; the last one of positive weight takes
  // what rounding leaves).
  static int DrawPart(const double* weights, int count, double u, double& sum)
  {
    sum = 0.0;
    for (int i = 0; i < count; ++i)
    {
      sum += std::max(weights[i], 0.0);
    }
    double below = 0.0;
    int last = 0;
    for (int i = 0; i < count; ++i)
    {
      if (weights[i] > 0.0)
      {
        below += weights[i];
        last = i;
        if (u * sum < below)
        {
          return i;
        }
      }
    }
    return last;
  }

  // T_l per channel of a shaded collision at the world point x towards l
  // (up to tMax): from SurfaceOffset along l (vtkTyndallShading::ShadowOffset,
  // as the map-based frame and vtkSingleScatteringReference take it).
  void SurfaceTransmittance(const double x[3], const double l[3], double tMax, Random& rng,
    Timing& timing, const PathState& path, double T[3]) const
  {
    const double offset = this->S->SurfaceOffset;
    const double y[3] = { x[0] + offset * l[0], x[1] + offset * l[1], x[2] + offset * l[2] };
    this->MediaTransmittance(y, nullptr, l, std::max(tMax - offset, 0.0), rng, timing, path, T);
  }

  // The lights' and the sky's light a shaded collision at the world point x
  // reflects by its lobe, in its unit (vtkTyndallSurfaceLobe::LightUnit
  // times each light's E f(v, l) T_l and, with a sky, its next-event
  // estimate weighted by the power heuristic against the lobe's sampling,
  // 1 at the path's last collision), added to J.
  void AddLobeLight(const double x[3], const vtkTyndallSurfaceLobe& lobe, bool last, Random& rng,
    Timing& timing, const PathState& path, double J[3]) const
  {
    const Scene& s = *this->S;
    const double unit = vtkTyndallSurfaceLobe::LightUnit;
    if (!lobe.Scatters())
    {
      return;
    }
    double l[3], f[3], T[3];
    for (const Scene::LightSource& light : s.Lights)
    {
      double factor, tMax;
      if (!s.LightGeometry(light, x, l, factor, tMax))
      {
        continue;
      }
      lobe.Evaluate(l, f);
      this->SurfaceTransmittance(x, l, tMax, rng, timing, path, T);
      for (int c = 0; c < 3; ++c)
      {
        J[c] += unit * factor * light.Color[c] * f[c] * T[c];
      }
    }
    if (!s.Environment || !s.Environment->Enabled())
    {
      return;
    }
    const double u[4] = { rng.Uniform(), rng.Uniform(), rng.Uniform(), rng.Uniform() };
    double sky[3];
    const double pdf = s.Environment->Sample(u, l, sky);
    if (!(pdf > 0.0))
    {
      return;
    }
    lobe.Evaluate(l, f);
    this->SurfaceTransmittance(x, l, kInfinity, rng, timing, path, T);
    const double weight = (last ? 1.0 : PowerWeight(pdf, lobe.Pdf(l))) * unit / pdf;
    for (int c = 0; c < 3; ++c)
    {
      J[c] += sky[c] * f[c] * T[c] * weight;
    }
  }

  // The power heuristic's weight of a strategy of density a against one of density b.
  static double PowerWeight(double a, double b) { return a * a / (a * a + b * b); }

  // Next-event estimation of the sky at a collision at the world distance t
  // of `ray` (world point x): adds albedo L(l) p(mu) T / pdf(l) times the
  // power heuristic's weight against the phase function's sampling (1 at
  // the path's last collision, which draws no direction), l drawn from the
  // environment (vtkTyndallEnvironment::Sample()), T ratio tracked.
  void AddSkyEvent(const Ray& ray, double t, const double x[3], const double albedo[3],
    const vtkTyndallMediumParameters& lit, bool last, Random& rng, Timing& timing,
    const PathState& path, double J[3]) const
  {
    const Scene& s = *this->S;
    const double u[4] = { rng.Uniform(), rng.Uniform(), rng.Uniform(), rng.Uniform() };
    double l[3], sky[3];
    const double pdf = s.Environment->Sample(u, l, sky);
    if (!(pdf > 0.0))
    {
      return;
    }
    const double phase = Scene::Phase(lit, vtkMath::Dot(l, ray.W));
    double T[3];
    this->LightTransmittance(ray, t, x, l, kInfinity, rng, timing, path, T);
    const double weight = (last ? 1.0 : PowerWeight(pdf, phase)) * phase / pdf;
    for (int c = 0; c < 3; ++c)
    {
      J[c] += albedo[c] * sky[c] * T[c] * weight;
    }
  }

  // A scattered ray that leaves the media: adds beta L(w) times the power
  // heuristic's weight of the phase function's density `phasePdf` (the
  // direction's) against the sky's, in the unit of the collision it left
  // (Ray::SkyUnit).
  void AddSkyEscape(const Ray& ray, const double beta[3], double phasePdf, double L[3]) const
  {
    const vtkTyndallEnvironment& sky = *this->S->Environment;
    double radiance[3];
    sky.Evaluate(ray.W, radiance);
    const double weight = PowerWeight(phasePdf, sky.Pdf(ray.W)) * ray.SkyUnit;
    for (int c = 0; c < 3; ++c)
    {
      L[c] += beta[c] * radiance[c] * weight;
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

  // One path from the camera ray; adds its radiance to L and the weight of
  // its escape, per channel, to `escape` (the view transmittance's
  // estimate: 0 unless the first flight leaves the media).
  void TracePath(
    Ray ray, Random& rng, Timing& timing, PathState& path, double L[3], double escape[3]) const
  {
    const Scene& s = *this->S;
    const bool sky = s.Environment && s.Environment->Enabled();
    double beta[3] = { 1.0, 1.0, 1.0 };
    double phasePdf = 0.0; // the density of the last scattered direction
    for (int bounce = 0;; ++bounce)
    {
      // The camera ray samples the camera media; scattered light, every medium.
      double t, weight[3] = { 1.0, 1.0, 1.0 };
      int k = 0;
      const bool crosses = ray.Clip(s, bounce == 0);
      if (crosses)
      {
        this->AddArrayEmission(ray, beta, rng, timing, path, L);
      }
      if (!crosses || !this->FreeFlight(ray, rng, t, k, timing, path, weight))
      {
        if (bounce == 0)
        {
          std::copy(weight, weight + 3, escape); // the camera sees the background, not the sky
        }
        else if (sky)
        {
          for (int c = 0; c < 3; ++c)
          {
            beta[c] *= weight[c];
          }
          this->AddSkyEscape(ray, beta, phasePdf, L);
        }
        return;
      }
      for (int c = 0; c < 3; ++c)
      {
        beta[c] *= weight[c];
      }
      if (!this->Scatter(
            ray, t, k, bounce + 1 >= s.MaxBounces, rng, timing, path, beta, phasePdf, L))
      {
        return;
      }
    }
  }

  // At a real collision of medium k at the distance t of `ray`: adds beta J
  // to L and, unless the path ends there (`last`, an emission-absorption
  // medium, Russian roulette), turns `ray` into the scattered one, beta
  // times the scattering's weight and phasePdf its direction's density.
  // False when the path ends.
  bool Scatter(Ray& ray, double t, int k, bool last, Random& rng, Timing& timing, PathState& path,
    double beta[3], double& phasePdf, double L[3]) const
  {
    const Scene& s = *this->S;
    const double x[3] = { ray.X[0] + t * ray.W[0], ray.X[1] + t * ray.W[1],
      ray.X[2] + t * ray.W[2] };
    double p[3];
    ray.Local.At(k, t, p);
    Point point;
    if (!s.Media[k].Medium->Material(p, point))
    {
      point = Point(); // missing data: no colour, no emission
    }
    // Lit as its own medium: its scattering model, phase function, light
    // scale, ambient and emission scale.
    const vtkTyndallMediumParameters& lit = s.Media[k].Medium->GetParameters();
    const bool single = lit.GetSingleScattering();
    if (single && k == 0 && s.Surface && !s.SurfaceAdded)
    {
      return this->ScatterAtSurface(ray, x, p, point, last, rng, timing, path, beta, phasePdf, L);
    }
    double J[3];
    if (!single)
    {
      std::copy(point.Albedo, point.Albedo + 3, J);
    }
    else
    {
      this->Source(ray, t, lit, x, point, rng, timing, path, J);
      if (s.Environment && s.Environment->Enabled())
      {
        this->AddSkyEvent(ray, t, x, point.Albedo, lit, last, rng, timing, path, J);
      }
      if (k == 0 && s.SurfaceAdded)
      {
        this->AddSurfaceTerm(ray.W, x, p, point, rng, timing, path, J);
      }
    }
    for (int c = 0; c < 3; ++c)
    {
      L[c] += beta[c] * J[c];
      beta[c] *= point.Albedo[c];
    }
    if (!single || last || !Survive(beta, rng))
    {
      return false;
    }
    std::copy(x, x + 3, ray.X);
    const double w[3] = { ray.W[0], ray.W[1], ray.W[2] };
    const double u1 = rng.Uniform();
    vtkVolumetricPathTracer::SampleHenyeyGreenstein(
      lit.ScatteringAnisotropy, w, u1, rng.Uniform(), ray.W);
    phasePdf = Scene::Phase(lit, vtkMath::Dot(ray.W, w));
    ray.T0 = 0.0;
    ray.T1 = kInfinity;
    ray.SkyUnit = 1.0;
    return true;
  }

  // A vtkParticipatingMediumProperty's Shade at a collision in the volume
  // (world point x, own point p, reached along w): adds its surface term to
  // J, the lobe's light (no ambient term), the sky's by its next-event
  // estimate alone (weight 1: the lobe is not sampled).
  void AddSurfaceTerm(const double w[3], const double x[3], const double p[3], const Point& point,
    Random& rng, Timing& timing, const PathState& path, double J[3]) const
  {
    double ambient[3];
    const vtkTyndallSurfaceLobe lobe = this->SurfaceLobe(p, w, point, rng, ambient);
    this->AddLobeLight(x, lobe, true, rng, timing, path, J);
  }

  // Scatter() at a collision in the shaded volume (world point x, own point
  // p): its lobe's source term, then a direction drawn from the lobe, the
  // scattered ray leaving from SurfaceOffset along it (as its light does).
  bool ScatterAtSurface(Ray& ray, const double x[3], const double p[3], const Point& point,
    bool last, Random& rng, Timing& timing, PathState& path, double beta[3], double& phasePdf,
    double L[3]) const
  {
    double J[3];
    const vtkTyndallSurfaceLobe lobe = this->SurfaceLobe(p, ray.W, point, rng, J);
    this->AddLobeLight(x, lobe, last, rng, timing, path, J);
    for (int c = 0; c < 3; ++c)
    {
      L[c] += beta[c] * J[c];
    }
    if (last)
    {
      return false;
    }
    double weight[3];
    const double u[3] = { rng.Uniform(), rng.Uniform(), rng.Uniform() };
    phasePdf = lobe.Sample(u[0], u[1], u[2], ray.W, weight);
    for (int c = 0; c < 3; ++c)
    {
      beta[c] *= weight[c];
    }
    if (!(phasePdf > 0.0) || !Survive(beta, rng))
    {
      return false;
    }
    const double offset = this->S->SurfaceOffset;
    for (int c = 0; c < 3; ++c)
    {
      ray.X[c] = x[c] + offset * ray.W[c];
    }
    ray.T0 = 0.0;
    ray.T1 = kInfinity;
    ray.SkyUnit = vtkTyndallSurfaceLobe::LightUnit;
    return true;
  }

  // The exact view transmittance of the camera ray, per channel, when every
  // camera medium has a closed form: an output, not part of a path, so not
  // timed; false otherwise.
  bool ViewTransmittance(Ray ray, double T[3]) const
  {
    const Scene& s = *this->S;
    T[0] = T[1] = T[2] = 1.0;
    if (!ray.Clip(s, true))
    {
      return true;
    }
    double tau = 0.0;
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      if (!ray.Crosses[k])
      {
        continue;
      }
      if (!s.ClosedForm[k])
      {
        return false;
      }
      tau += s.Media[k].Medium->OpticalDepth(
        ray.Local.O[k], ray.Local.D[k], ray.Low[k], ray.High[k], 0.0, kInfinity);
    }
    s.ChannelTransmittances(std::exp(-tau), T);
    return true;
  }

  void RenderPixel(int i, int j, Timing& timing) const
  {
    const Scene& s = *this->S;
    const vtkIdType pixel = static_cast<vtkIdType>(j) * s.Width + i;
    double sum[3] = { 0.0, 0.0, 0.0 }, squares[3] = { 0.0, 0.0, 0.0 };
    double escapes[3] = { 0.0, 0.0, 0.0 };
    Ray camera;
    const bool valid = !s.DrawnByAnother && s.CameraRay(i, j, camera.X, camera.W, camera.T1);
    if (valid)
    {
      Random rng(s.Seed, static_cast<std::uint64_t>(pixel));
      PathState path; // the media's caches at the last collision
      for (int n = 0; n < s.Samples; ++n)
      {
        double L[3] = { 0.0, 0.0, 0.0 }, escape[3] = { 0.0, 0.0, 0.0 };
        const auto start = Clock::now();
        this->TracePath(camera, rng, timing, path, L, escape);
        timing.Total += Seconds(start, Clock::now());
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += L[c];
          squares[c] += L[c] * L[c];
          escapes[c] += escape[c];
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
    double T[3] = { 1.0, 1.0, 1.0 };
    if (valid && !this->ViewTransmittance(camera, T))
    {
      for (int c = 0; c < 3; ++c)
      {
        T[c] = escapes[c] / n;
      }
    }
    const int channels = s.GetChromatic() ? 3 : 1;
    std::copy(T, T + channels, s.Transmittance + channels * pixel);
  }
};

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
vtkVolumetricPathTracer::vtkVolumetricPathTracer() = default;

//------------------------------------------------------------------------------
vtkVolumetricPathTracer::~vtkVolumetricPathTracer() = default;

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
namespace
{
// The distance sampling of each medium and the majorants of delta tracking;
// false (with an error through `reporter`) when delta tracking would take
// too many steps. Closed forms serve grey media (a coloured extinction's
// channels are tracked together: spectral tracking against the densest).
bool SetUpSampling(int mode, Scene& scene, vtkObject* reporter)
{
  const bool closedForm = mode == vtkVolumetricPathTracer::CLOSED_FORM;
  const vtkTyndallMedium& own = *scene.Media[0].Medium;
  if (closedForm && !own.HasClosedForm())
  {
    vtkWarningWithObjectMacro(
      reporter, << "Render: CLOSED_FORM distance sampling needs a procedural medium (a "
                   "DetailNoise); this "
                << own.GetKind() << " medium is rendered with DELTA_TRACKING.");
  }
  else if (closedForm && own.GetClip())
  {
    vtkWarningWithObjectMacro(
      reporter, << "Render: the closed form integrates the unclipped medium; with clipping "
                   "planes or cropping the medium is rendered with DELTA_TRACKING.");
  }
  else if (closedForm && scene.GetChromatic())
  {
    vtkWarningWithObjectMacro(
      reporter, << "Render: a coloured extinction is tracked per channel against the densest "
                   "one; the medium is rendered with DELTA_TRACKING.");
  }
  for (size_t k = 0; k < scene.Media.size(); ++k)
  {
    const vtkTyndallMedium& medium = *scene.Media[k].Medium;
    scene.ClosedForm[k] =
      closedForm && medium.HasClosedForm() && !medium.GetClip() && !scene.GetChromatic();
    scene.Majorant[k] = scene.ClosedForm[k] ? 0.0 : medium.GetMajorant();
    if (!std::isfinite(scene.Majorant[k]) ||
      scene.Majorant[k] * medium.GetWorldDiagonal() > kMaxStepsPerRay)
    {
      vtkErrorWithObjectMacro(reporter,
        << "Render: delta tracking against the majorant " << scene.Majorant[k]
        << " would take more than " << kMaxStepsPerRay << " steps across the " << medium.GetKind()
        << " medium " << (k == 0 ? "of the volume" : "of another volume")
        << "; use CLOSED_FORM or a smaller density.");
      return false;
    }
  }
  return true;
}

// A plain property's Shade: its collisions scatter as VTK's shaded surfaces
// (vtkTyndallSurfaceLobe; independent components each with its own
// gradient, VTK 9.2's volumetric scattering blending in the lobe); a
// vtkParticipatingMediumProperty's: they add the lobe's light.
void SetUpSurface(Scene& scene)
{
  const vtkTyndallGridMedium& grid = *scene.Shaded;
  scene.Surface = &grid;
  scene.SurfaceAdded = grid.GetShading().GetAdditive();
  scene.SurfaceOffset = vtkTyndallShading::ShadowOffset * grid.GetMinimumWorldSpacing();
}
}

//------------------------------------------------------------------------------
bool vtkVolumetricPathTracer::RenderImage(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  vtkTyndallSceneReader& tyndall = *this->SceneReader;
  Scene scene;
  if (!scene.ReadScene(tyndall, renderer, volume, width, height, this) ||
    !SetUpSampling(this->DistanceSampling, scene, this))
  {
    return false;
  }
  if (scene.Shaded)
  {
    SetUpSurface(scene);
  }
  if (scene.Isosurfaced)
  {
    vtkErrorMacro(<< "The volume's mapper draws it in the isosurface blend mode: surfaces, not a "
                     "medium the path tracer can scatter in (vtkSingleScatteringReference draws "
                     "them).");
    return false;
  }
  if (scene.Projected)
  {
    vtkErrorMacro(<< "The volume's mapper draws it in the "
                  << vtkTyndallProjection::GetModeName(scene.Projected->GetProjection().GetMode())
                  << " blend mode, a projection and not a medium: the path tracer draws "
                     "media (vtkSingleScatteringReference draws projections).");
    return false;
  }
  // The paths scatter for real: the octaves' approximation is what they
  // are the reference for, so it is not applied to their light.
  scene.Octaves = 1;
  scene.Samples = this->SamplesPerPixel;
  scene.MaxBounces = this->MaximumBounces;
  scene.Seed = this->Seed;
  scene.SampleSky = true;
  if (!scene.SetUpView(tyndall, renderer, this))
  {
    return false;
  }

  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  auto radiance = NewArray("Radiance", 3, pixels);
  auto transmittance = NewArray("Transmittance", scene.GetChromatic() ? 3 : 1, pixels);
  auto error = NewArray("RadianceStandardError", 3, pixels);
  scene.Radiance = radiance->GetPointer(0);
  scene.Transmittance = transmittance->GetPointer(0);
  scene.StandardError = error->GetPointer(0);

  vtkSMPThreadLocal<Timing> timing;
  const auto rows = [&](vtkIdType begin, vtkIdType end)
  {
    PathTracer tracer(scene, timing);
    vtkSMPTools::For(begin, end, 1, tracer);
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
  this->LastDistanceSampling = scene.ClosedForm[0] ? CLOSED_FORM : DELTA_TRACKING;
  this->LastMajorant = scene.Majorant[0];
  scene.SetOutput(this->Output, radiance, transmittance, error);
  return true;
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
  os << indent << "LastDistanceSampling: " << this->LastDistanceSampling << "\n";
  os << indent << "LastMajorant: " << this->LastMajorant << "\n";
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
}
