// Shape x cosine noise in closed form (vtkTyndallDetailMedium, issue 12's
// first target) against adaptive Gauss-Kronrod quadrature:
//
// 1. vtkCosineNoise::PolynomialWaveIntegral (a cubic times one cosine) on
//    20 000 random (polynomial, length, alpha, beta), beta from 1e-9 to 1e3
//    so that both the series and the recurrence branch are hit, with
//    |beta L| near 1 where they meet;
// 2. the optical depth of a random 9x7x6 shape grid times 6 octaves of noise
//    (144 waves, non-negative) along 2000 random rays (inside, entering,
//    leaving, crossing the box, axis-aligned ones, rays on cell planes), the
//    quadrature split at every plane where the ray crosses a sample plane
//    (found independently of the DDA): relative error below 1e-9;
// 3. a rotated, anisotropically spaced image, so that the waves are taken to
//    field index coordinates correctly: the medium's Noise() against
//    vtkCosineNoise::EvaluateFunction at the data point;
// 4. SampleDistance: the depth up to the returned t equals the target;
// 5. the per-cell clamp with negative noise: never above the depth with
//    the noise replaced by max(0, noise) (and equal when non-negative);
// 6. a constant shape (the paper's box): depths against quadrature, flights
//    solved in the cell by the bound without its whole integral, and one
//    trigonometric pass for a ray from a collision with its phases.
//
// Measured (Release, 2 cores): polynomial-wave integrals 3.6e-15 of the
// integral of |P|; optical depths 5.3e-14 relative (worst of 2000).
#include "vtkCommand.h"
#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTestErrorObserver.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallGridMedium.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestQuadrature.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

namespace
{
using tyndall_test::Check;

class Random
{
public:
  double Uniform(double a, double b)
  {
    this->Sequence->Next();
    return this->Sequence->GetRangeValue(a, b);
  }

private:
  vtkNew<vtkMinimalStandardRandomSequence> Sequence;
};

// Composite 15-point Gauss-Kronrod with a panel per half period of a wave
// of angular frequency `omega` (at least 4 panels): the oracle for smooth
// integrands, at a fixed cost.
double Composite(const std::function<double(double)>& f, double a, double b, double omega)
{
  const double period = omega > 0.0 ? 3.14159265358979 / omega : (b - a);
  const int n = std::max(4, static_cast<int>(std::ceil((b - a) / period)));
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int j = 0; j < n; ++j)
  {
    double err;
    sum += tyndall_test::GaussKronrod15(f, a + j * h, a + (j + 1) * h, err);
  }
  return sum;
}

void TestPolynomialWave(Random& random)
{
  double worst = 0.0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    // Every third polynomial a constant (vtkCosineNoiseMoments' K_0 alone).
    const bool constant = trial % 3 == 0;
    const double c[4] = { random.Uniform(-2, 2), constant ? 0.0 : random.Uniform(-2, 2),
      constant ? 0.0 : random.Uniform(-2, 2), constant ? 0.0 : random.Uniform(-2, 2) };
    const double length = std::pow(10.0, random.Uniform(-3, 0.5));
    const double alpha = random.Uniform(-10, 10);
    const double beta = (trial % 2 ? 1 : -1) *
      (trial % 5 == 0 ? random.Uniform(0.7, 1.4) / length : std::pow(10.0, random.Uniform(-9, 3)));
    auto f = [&](double s)
    { return (c[0] + s * (c[1] + s * (c[2] + s * c[3]))) * std::cos(alpha + beta * s); };
    auto magnitude = [&](double s) { return std::abs(c[0] + s * (c[1] + s * (c[2] + s * c[3]))); };
    const double scale = Composite(magnitude, 0, length, 1.0);
    const double exact = Composite(f, 0, length, std::abs(beta));
    const double closed = vtkCosineNoise::PolynomialWaveIntegral(c, length, alpha, beta);
    worst = std::max(worst, std::abs(closed - exact) / std::max(scale, 1e-300));
  }
  std::cout << "polynomial x wave: worst error / integral of |P| = " << worst << "\n";
  Check(worst < 1e-12, "the polynomial-wave closed form matches quadrature to 1e-12");
}

struct Scene
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkSmartVolumeMapper> Mapper;
  vtkNew<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkCosineNoise> Noise;
  vtkTyndallGridMedium Grid;
  vtkTyndallDetailMedium Detail;

  Scene(Random& random)
  {
    tyndall_test::SetSkewedGeometry(this->Image);
    vtkNew<vtkFloatArray> values;
    values->SetName("density");
    values->SetNumberOfTuples(this->Image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetValue(i, static_cast<float>(random.Uniform(0.0, 1.0)));
    }
    this->Image->GetPointData()->SetScalars(values);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(0.5, 0.3);
    opacity->AddPoint(1.0, 0.9);
    this->Property->SetScalarOpacity(opacity);
    this->Property->SetDensityScale(2.0);
    this->Property->SetScatteringOctaves(1);
    this->Mapper->SetInputData(this->Image);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Volume->SetPosition(0.3, -0.2, 0.1); // the detail must not depend on it
    this->Noise->SetNumberOfOctaves(6);
    this->Noise->SetFrequency(1.0);
    this->Noise->SetOffset(-this->Noise->GetMinimumValue() + 0.0); // non-negative
    this->Noise->SetExtinctionScale(0.7);
  }

  bool Update()
  {
    return this->Grid.Update(this->Volume, this->Volume) &&
      this->Detail.Update(this->Grid, this->Noise, this->Volume);
  }
};

// Quadrature of the extinction along o + t d, split at the sample planes.
// With `weight`, the integral of the extinction times weight(t), whose
// angular frequency is at most weightOmega.
double QuadratureDepth(const vtkTyndallDetailMedium& detail, const vtkTyndallGridMedium& grid,
  const double o[3], const double d[3], double t0, double t1, bool clampNoise,
  const std::function<double(double)>& weight = nullptr, double weightOmega = 0.0)
{
  const double* lo = grid.GetBoxLow();
  const double* hi = grid.GetBoxHigh();
  std::vector<double> cuts = { t0, t1 };
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      continue;
    }
    for (int plane = static_cast<int>(std::floor(lo[a])); plane <= std::ceil(hi[a]); ++plane)
    {
      const double t = (plane - o[a]) / d[a];
      if (t > t0 && t < t1)
      {
        cuts.push_back(t);
      }
      for (const double bound : { lo[a], hi[a] })
      {
        const double tb = (bound - o[a]) / d[a];
        if (tb > t0 && tb < t1)
        {
          cuts.push_back(tb);
        }
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  auto inside = [&](const double p[3])
  {
    for (int a = 0; a < 3; ++a)
    {
      if (p[a] < lo[a] - 1e-12 || p[a] > hi[a] + 1e-12)
      {
        return false;
      }
    }
    return true;
  };
  auto f = [&](double t)
  {
    const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    if (!inside(p))
    {
      return 0.0;
    }
    const double noise = detail.Noise(p);
    return detail.Shape(p) * detail.GetScale() * (clampNoise ? std::max(0.0, noise) : noise) *
      (weight ? weight(t) : 1.0);
  };
  // Composite 15-point Gauss-Kronrod, a panel per half period of the
  // fastest wave along the ray (the integrand is smooth between the cuts).
  double fastest = 0.0;
  for (const vtkTyndallDetailMedium::Wave& w : detail.GetWaves())
  {
    fastest = std::max(fastest, std::abs(w.K[0] * d[0] + w.K[1] * d[1] + w.K[2] * d[2]));
  }
  double sum = 0.0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    sum += Composite(f, cuts[i], cuts[i + 1], fastest + weightOmega);
  }
  return sum;
}

void RandomRay(Random& random, int trial, double o[3], double d[3], double& t0, double& t1)
{
  // From anywhere around the box towards a random point of it (so that
  // most rays cross the medium), or in a random direction.
  const double aim[3] = { random.Uniform(0, 8), random.Uniform(0, 6), random.Uniform(0, 5) };
  const bool aimed = trial % 3 != 0;
  for (int a = 0; a < 3; ++a)
  {
    o[a] = random.Uniform(-2.0, 10.0);
    d[a] = aimed ? aim[a] - o[a] : random.Uniform(-1.0, 1.0);
  }
  if (trial % 7 == 0)
  {
    d[0] = d[1] = 0.0; // axis-aligned
  }
  if (trial % 11 == 0)
  {
    o[1] = std::floor(o[1]); // on a sample plane
    d[1] = 0.0;
  }
  if (vtkMath::Norm(d) == 0.0)
  {
    d[2] = 1.0;
  }
  const double speed = random.Uniform(0.5, 3.0);
  vtkMath::Normalize(d);
  for (int a = 0; a < 3; ++a)
  {
    d[a] *= speed; // index units per world unit
  }
  t0 = random.Uniform(-2.0, 2.0);
  t1 = t0 + random.Uniform(0.0, 12.0);
}

// The closed-form extinction coefficients of a segment (a map texel's
// projection without marching) against quadrature of 2 int sigma cos(j pi u).
void TestProjection(Scene& scene, Random& random)
{
  const int count = 8;
  const double pi = 3.14159265358979323846;
  double worst = 0.0;
  int nonzero = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    double o[3], d[3], t0, t1;
    RandomRay(random, trial, o, d, t0, t1);
    if (!(t1 > t0))
    {
      continue;
    }
    double c[count];
    scene.Detail.ProjectExtinction(o, d, t0, t1, count, c);
    const double depth = QuadratureDepth(scene.Detail, scene.Grid, o, d, t0, t1, false);
    nonzero += depth > 0.0 ? 1 : 0;
    for (int j = 0; j < count; ++j)
    {
      const double omega = j * pi / (t1 - t0);
      const double exact = 2.0 *
        QuadratureDepth(
          scene.Detail, scene.Grid, o, d, t0, t1, false,
          [&](double t) { return std::cos(omega * (t - t0)); }, omega);
      worst = std::max(worst, std::abs(c[j] - exact) / std::max(depth, 1e-300));
      if (depth == 0.0 && c[j] != 0.0)
      {
        worst = 1.0;
      }
    }
  }
  std::cout << "closed-form extinction coefficients (8 per ray): worst error " << worst
            << " of the ray's optical depth over 200 rays (" << nonzero << " through the medium)\n";
  Check(nonzero > 80, "many random rays cross the medium");
  Check(worst < 1e-9, "closed-form extinction coefficients match quadrature to 1e-9");
}

void TestOpticalDepth(Scene& scene, Random& random)
{
  double worst = 0.0;
  int nonzero = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    double o[3], d[3], t0, t1;
    RandomRay(random, trial, o, d, t0, t1);
    const double closed = scene.Detail.ClosedFormDepth(o, d, t0, t1);
    const double exact = QuadratureDepth(scene.Detail, scene.Grid, o, d, t0, t1, true);
    if (exact > 0.0)
    {
      ++nonzero;
    }
    worst = std::max(worst, std::abs(closed - exact) / std::max(exact, 1e-300));
    if (exact == 0.0 && closed != 0.0)
    {
      worst = 1.0;
    }
  }
  std::cout << "shape x noise optical depth: worst relative error " << worst << " over 2000 rays ("
            << nonzero << " through the medium)\n";
  Check(nonzero > 1000, "most random rays cross the medium");
  Check(worst < 1e-9, "closed-form optical depth matches quadrature to 1e-9 relative");
}

void TestNoisePlacement(Scene& scene, Random& random)
{
  double worst = 0.0;
  const double* m = scene.Grid.GetIndexToData();
  for (int trial = 0; trial < 200; ++trial)
  {
    const double p[3] = { random.Uniform(0, 8), random.Uniform(0, 6), random.Uniform(0, 5) };
    double x[3];
    for (int r = 0; r < 3; ++r)
    {
      x[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
    }
    worst = std::max(worst, std::abs(scene.Detail.Noise(p) - scene.Noise->EvaluateFunction(x)));
  }
  std::cout << "noise at data coordinates: worst difference " << worst << "\n";
  Check(worst < 1e-9, "the detail noise is the vtkCosineNoise at the image's data coordinates");
}

void TestSampleDistance(Scene& scene, Random& random)
{
  double worst = 0.0;
  int found = 0;
  for (int trial = 0; trial < 500; ++trial)
  {
    double o[3], d[3], t0, t1;
    RandomRay(random, trial, o, d, t0, t1);
    const double total = scene.Detail.ClosedFormDepth(o, d, t0, t1);
    const double target = random.Uniform(0.0, 1.2) * total;
    double t;
    const bool hit = scene.Detail.ClosedFormDistance(o, d, t0, t1, target, t);
    if (hit != (target <= total))
    {
      worst = 1.0;
      continue;
    }
    if (hit)
    {
      ++found;
      worst = std::max(worst,
        std::abs(scene.Detail.ClosedFormDepth(o, d, t0, t) - target) / std::max(total, 1e-300));
    }
  }
  std::cout << "distance sampling: worst depth error / segment depth " << worst << " (" << found
            << " found)\n";
  Check(found > 200 && worst < 1e-10, "SampleDistance inverts the closed form");
}

// The phases at a collision (PointPhases) start the rays from it as a path
// tracer does: a shadow ray and the next flight in new directions, from
// the collision point recomputed by the caller. The depths and distances
// must equal those computed without them; phases of another point must
// not be used.
void TestCollisionPhases(Scene& scene, Random& random)
{
  double worst = 0.0;
  int reused = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    double o[3], d[3], t0, t1;
    RandomRay(random, trial, o, d, t0, t1);
    const double total = scene.Detail.ClosedFormDepth(o, d, t0, t1);
    vtkTyndallDetailMedium::PointPhases phases;
    double t;
    if (!scene.Detail.ClosedFormDistance(
          o, d, t0, t1, random.Uniform(0.0, 1.0) * total, t, nullptr, &phases) ||
      !phases.Valid)
    {
      continue;
    }
    const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    double e[3] = { random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0),
      random.Uniform(-1.0, 1.0) }; // a new direction
    const double plain = scene.Detail.ClosedFormDepth(p, e, 0.0, 1e30);
    const double with = scene.Detail.ClosedFormDepth(p, e, 0.0, 1e30, &phases);
    worst = std::max(worst, std::abs(with - plain) / std::max(plain, 1e-300));
    // The phases are really used: the same point's phases turned by pi
    // (negated) must change the depth.
    vtkTyndallDetailMedium::PointPhases negated = phases;
    for (size_t i = 0; i < negated.Cos.size(); ++i)
    {
      negated.Cos[i] = -negated.Cos[i];
      negated.Sin[i] = -negated.Sin[i];
    }
    const double wrong = scene.Detail.ClosedFormDepth(p, e, 0.0, 1e30, &negated);
    reused += std::abs(wrong - plain) > 1e-6 * plain ? 1 : 0;
    // Phases of a point 0.01 away are turned by up to |k| x 0.01 (far above
    // the 1e-4 rad the reuse takes): they must be ignored.
    vtkTyndallDetailMedium::PointPhases moved = phases;
    moved.Point[0] += 0.01;
    const double ignored = scene.Detail.ClosedFormDepth(p, e, 0.0, 1e30, &moved);
    worst = std::max(worst, std::abs(ignored - plain) / std::max(plain, 1e-300));
    // The next flight from the collision, the phases both its start and
    // where the new collision's go (as the path tracer passes them).
    double ta, tb;
    const double target = 0.5 * plain;
    const bool hitA = scene.Detail.ClosedFormDistance(p, e, 0.0, 1e30, target, ta);
    const bool hitB =
      scene.Detail.ClosedFormDistance(p, e, 0.0, 1e30, target, tb, &phases, &phases);
    worst = std::max(worst, hitA == hitB ? std::abs(ta - tb) / std::max(std::abs(ta), 1.0) : 1.0);
    const double q[3] = { p[0] + tb * e[0], p[1] + tb * e[1], p[2] + tb * e[2] };
    if (hitB && phases.Valid)
    {
      // ...and the phases left are those at the new collision.
      const double from = scene.Detail.ClosedFormDepth(q, d, 0.0, 1e30);
      const double reusing = scene.Detail.ClosedFormDepth(q, d, 0.0, 1e30, &phases);
      worst = std::max(worst, std::abs(reusing - from) / std::max(from, 1e-300));
    }
  }
  std::cout << "rays from a collision with its phases: worst relative difference " << worst
            << "; the phases were used (negating them changed the depth) on " << reused
            << " rays\n";
  Check(reused > 100 && worst < 1e-12,
    "the phases at a collision are used and give the same depths and flights");
}

void TestNegativeNoise(Scene& scene, Random& random)
{
  scene.Noise->SetOffset(0.2); // the noise now dips below zero
  Check(scene.Update(), "negative noise is accepted");
  int below = 0, trials = 300;
  bool bounded = true;
  for (int trial = 0; trial < trials; ++trial)
  {
    double o[3], d[3], t0, t1;
    RandomRay(random, trial, o, d, t0, t1);
    const double closed = scene.Detail.ClosedFormDepth(o, d, t0, t1);
    const double clamped = QuadratureDepth(scene.Detail, scene.Grid, o, d, t0, t1, true);
    bounded = bounded && closed >= 0.0 && closed <= clamped * (1 + 1e-9) + 1e-12;
    below += closed < clamped * (1 - 1e-6) ? 1 : 0;
  }
  std::cout << "negative noise: " << below << " of " << trials
            << " rays below the clamped extinction's depth\n";
  Check(bounded, "per-cell clamping never exceeds the clamped extinction's depth");
  Check(below > 0, "with negative noise the per-cell clamp is visible (documented)");
}

// The paper's setting: the noise in its bounding box (a constant shape,
// one cell per ray). Optical depths against quadrature; flights solved in
// the cell by the bound, without the cell's whole integral, still invert
// the closed form; and the work the benchmark reports: a ray from a
// collision, with its phases, takes one trigonometric pass (the exit).
void TestConstantShape(Scene& scene, Random& random)
{
  scene.Image->SetDimensions(2, 2, 2); // one cell, 2 wide: 4 cycles of the first octave
  scene.Image->SetSpacing(2.0, 2.0, 2.0);
  scene.Noise->SetFrequency(2.0);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(8);
  values->Fill(0.75f);
  scene.Image->GetPointData()->SetScalars(values);
  scene.Noise->SetOffset(2.0 * scene.Noise->GetStandardDeviation()); // contrast 0.5
  Check(scene.Update(), "the constant shape updates");
  // Rays from around the cell [0, 1]^3 (index units) through a point of it.
  auto ray = [&](double o[3], double d[3], double& t0, double& t1)
  {
    for (int a = 0; a < 3; ++a)
    {
      o[a] = random.Uniform(-1.0, 2.0);
      d[a] = random.Uniform(0.0, 1.0) - o[a];
    }
    const double speed = random.Uniform(0.2, 1.0) / vtkMath::Norm(d);
    vtkMath::MultiplyScalar(d, speed);
    t0 = random.Uniform(-1.0, 1.0);
    t1 = t0 + random.Uniform(1.0, 12.0);
  };
  double depthError = 0.0, sampleError = 0.0;
  int found = 0;
  vtkTyndallDetailMedium::Work flights, shadows;
  int shadowRays = 0;
  bool oneExitPass = true;
  for (int trial = 0; trial < 300; ++trial)
  {
    double o[3], d[3], t0, t1;
    ray(o, d, t0, t1);
    const double total = scene.Detail.ClosedFormDepth(o, d, t0, t1);
    const double exact = QuadratureDepth(scene.Detail, scene.Grid, o, d, t0, t1, false);
    depthError = std::max(depthError, std::abs(total - exact) / std::max(exact, 1e-300));
    vtkTyndallDetailMedium::PointPhases phases;
    double t;
    const double target = random.Uniform(0.0, 0.6) * total;
    if (!scene.Detail.ClosedFormDistance(o, d, t0, t1, target, t, nullptr, &phases, &flights) ||
      target == 0.0)
    {
      continue;
    }
    ++found;
    sampleError =
      std::max(sampleError, std::abs(scene.Detail.ClosedFormDepth(o, d, t0, t) - target) / total);
    if (phases.Valid)
    {
      // A shadow ray from the collision in a new direction.
      const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      double e[3] = { random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0), 0.5 };
      vtkMath::MultiplyScalar(e, vtkMath::Norm(d) / vtkMath::Norm(e));
      vtkTyndallDetailMedium::Work one;
      scene.Detail.ClosedFormDepth(p, e, 0.0, 1e30, &phases, &one);
      oneExitPass = oneExitPass && one.TrigonometricPasses == 1.0 && one.CellPasses == 0.0;
      ++shadowRays;
    }
  }
  std::cout << "constant shape: optical depth " << depthError << " relative to quadrature; "
            << found << " flights, depth error / segment depth " << sampleError << ", "
            << flights.BoundSolves << " solved in the cell by the bound (" << flights.BoundPasses
            << " bound passes); " << shadowRays << " shadow rays from collisions\n";
  Check(depthError < 1e-9, "constant-shape optical depths match quadrature");
  Check(found > 100 && sampleError < 1e-10, "constant-shape flights invert the closed form");
  // Measured: 100 of 262 (the targets reach 0.6 of the segment's depth,
  // where the bound is too loose); 0 if the bound never holds.
  Check(flights.BoundSolves > 0.25 * found,
    "flights in a constant cell are solved without the cell's whole integral");
  Check(shadowRays > 50 && oneExitPass,
    "a ray from a collision with its phases takes one trigonometric pass through one cell");
}

// Rays whose cells end on two or three axes' planes at once (diagonals
// through sample points), along an axis, backwards, and across empty cells
// between occupied ones (two planes of zero samples): the phase sequences
// and their resets against quadrature.
void TestTiesAndGaps(Scene& scene)
{
  scene.Noise->SetOffset(-scene.Noise->GetMinimumValue()); // non-negative again
  auto* values = vtkFloatArray::SafeDownCast(scene.Image->GetPointData()->GetScalars());
  int dims[3];
  scene.Image->GetDimensions(dims);
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 3; j <= 4; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        values->SetValue((k * dims[1] + j) * dims[0] + i, 0.0f);
      }
    }
  }
  values->Modified();
  Check(scene.Update(), "the shape with a gap updates");
  const double directions[][3] = { { 1, 1, 1 }, { 1, 1, 0 }, { -1, 1, 1 }, { 1, -1, -1 },
    { 2, 1, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 1, 2, 2 } };
  double worst = 0.0;
  int crossing = 0;
  for (const auto& d : directions)
  {
    for (int start = 0; start < 4; ++start)
    {
      // From a sample point (or a cell centre) before the box.
      const double shift = start < 2 ? 0.0 : 0.5;
      const double o[3] = { (d[0] > 0 ? -1.0 : dims[0]) + shift + start,
        (d[1] > 0 ? -1.0 : dims[1]) + shift, (d[2] > 0 ? -1.0 : dims[2]) + shift + start % 2 };
      const double closed = scene.Detail.ClosedFormDepth(o, d, 0.0, 40.0);
      const double exact = QuadratureDepth(scene.Detail, scene.Grid, o, d, 0.0, 40.0, true);
      crossing += exact > 0.0 ? 1 : 0;
      worst = std::max(worst, std::abs(closed - exact) / std::max(exact, 1e-300));
    }
  }
  std::cout << "ties and gaps: worst relative error " << worst << " over " << crossing
            << " rays through the medium\n";
  Check(crossing > 10 && worst < 1e-9, "rays through plane ties and empty cells match quadrature");
}
}

int TestTyndallDetailMedium(int, char*[])
{
  Random random;
  TestPolynomialWave(random);
  Scene scene(random);
  Check(scene.Update(), "the detail medium updates");
  Check(scene.Detail.Enabled() && scene.Detail.GetWaves().size() == 144, "144 waves");
  TestOpticalDepth(scene, random);
  TestNoisePlacement(scene, random);
  TestSampleDistance(scene, random);
  TestCollisionPhases(scene, random);
  TestProjection(scene, random);
  TestNegativeNoise(scene, random);
  TestTiesAndGaps(scene);
  TestConstantShape(scene, random);

  vtkNew<vtkCosineNoise> huge;
  huge->SetNumberOfDirections(100);
  huge->SetNumberOfOctaves(3);
  vtkTyndallDetailMedium tooMany;
  vtkNew<vtkTest::ErrorObserver> errors;
  scene.Volume->AddObserver(vtkCommand::ErrorEvent, errors);
  Check(!tooMany.Update(scene.Grid, huge, scene.Volume) && errors->GetError(),
    "300 waves are refused with an error");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
