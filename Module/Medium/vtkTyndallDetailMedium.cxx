#include "vtkTyndallDetailMedium.h"

#include "vtkCosineNoise.h"
#include "vtkCosineNoiseMoments.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkObject.h"
#include "vtkTyndallGridMedium.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// A linear polynomial a + b s and products of them, as cubic coefficients.
struct Linear
{
  double A;
  double B;
};

void Multiply(const double p[4], const Linear& l, double out[4])
{
  out[0] = p[0] * l.A;
  out[1] = p[1] * l.A + p[0] * l.B;
  out[2] = p[2] * l.A + p[1] * l.B;
  out[3] = p[3] * l.A + p[2] * l.B;
}

void AddScaled(double acc[4], const double p[4], double f)
{
  for (int n = 0; n < 4; ++n)
  {
    acc[n] += f * p[n];
  }
}

double Evaluate(const double c[4], double s)
{
  return c[0] + s * (c[1] + s * (c[2] + s * c[3]));
}

// The integral of the cubic from 0 to s, over s.
double Integral(const double c[4], double s)
{
  return c[0] + s * (c[1] / 2.0 + s * (c[2] / 3.0 + s * c[3] / 4.0));
}

// |A^T k|^2: the squared world wave number of the field index wave vector k
// (A: the world -> field index matrix, row-major 4x4).
double WorldK2(const double k[3], const double* a)
{
  double sum = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double kc = k[0] * a[c] + k[1] * a[4 + c] + k[2] * a[8 + c];
    sum += kc * kc;
  }
  return sum;
}

// The footprint filter's levels (vtkTyndallDetailMedium::FilterFactor()):
// group g of four (waves sorted by WorldK2) is filtered with |k|^2 =
// K0 FilterLevelRatio^n, n the largest level at or below its first (coarsest)
// wave's WorldK2, K0 the coarsest positive WorldK2; a group whose first wave
// has k = 0 takes FilterK2 0 (level -1: no filter).
// The share of the clamped noise's mean max(0, n) that the clamp adds,
// E[max(0, -n)] / E[max(0, n)], for n Gaussian around `offset` with the
// waves' variance sum a^2 / 2 (a sum of many waves of independent phases);
// exactly 0 where the noise cannot dip below 0.
double NoiseClampShare(double offset, const std::vector<vtkTyndallDetailMedium::Wave>& waves)
{
  double sum = 0.0, variance = 0.0;
  for (const auto& w : waves)
  {
    sum += std::abs(w.Amplitude);
    variance += 0.5 * w.Amplitude * w.Amplitude;
  }
  if (offset >= sum)
  {
    return 0.0;
  }
  const double s = std::sqrt(variance);
  const double z = offset / s;
  const double negative = s * std::exp(-0.5 * z * z) / std::sqrt(2.0 * vtkMath::Pi()) -
    offset * 0.5 * std::erfc(z / std::sqrt(2.0));
  const double positive = offset + negative;
  return positive > 0.0 ? std::max(0.0, negative) / positive : 1.0;
}

void SetFilterLevels(std::vector<vtkTyndallDetailMedium::Wave>& waves)
{
  double base = 0.0;
  for (const auto& w : waves)
  {
    if (w.WorldK2 > 0.0)
    {
      base = w.WorldK2;
      break;
    }
  }
  const double ratio = vtkTyndallDetailMedium::FilterLevelRatio;
  for (size_t g = 0; g < waves.size(); g += 4)
  {
    const double first = waves[g].WorldK2;
    int level = -1;
    double k2 = 0.0;
    if (first > 0.0 && base > 0.0 && std::isfinite(std::log(first / base)))
    {
      level = static_cast<int>(std::floor(std::log(first / base) / std::log(ratio)));
      level = std::max(level, 0);
      while (base * std::pow(ratio, level + 1) <= first)
      {
        ++level;
      }
      while (level > 0 && base * std::pow(ratio, level) > first)
      {
        --level;
      }
      k2 = base * std::pow(ratio, level);
    }
    for (size_t i = g; i < std::min(g + 4, waves.size()); ++i)
    {
      waves[i].FilterK2 = k2;
      waves[i].FilterLevel = level;
    }
  }
}
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::Update(
  const vtkTyndallGridMedium& grid, vtkCosineNoise* noise, vtkObject* reporter, double filterWidth)
{
  this->IsEnabled = false;
  this->Grid = &grid;
  if (!noise)
  {
    return true;
  }
  const int count = noise->GetNumberOfWaves();
  if (count > MaximumNumberOfWaves)
  {
    vtkErrorWithObjectMacro(reporter, << "The detail noise has " << count
                                      << " waves (directions x octaves); the shaders take at most "
                                      << MaximumNumberOfWaves << ".");
    return false;
  }
  // Waves: k . (M p + e) + phase = (M^T k) . p + (k . e + phase), M and e
  // from field index -> data.
  const double* m = grid.GetIndexToData();
  std::vector<Wave> waves(count);
  double amplitudes = 0.0;
  for (int i = 0; i < count; ++i)
  {
    double k[3], phase, amplitude;
    noise->GetWave(i, k, phase, amplitude);
    Wave& w = waves[i];
    for (int c = 0; c < 3; ++c)
    {
      w.K[c] = k[0] * m[c] + k[1] * m[4 + c] + k[2] * m[8 + c];
    }
    w.Phase = phase + k[0] * m[3] + k[1] * m[7] + k[2] * m[11];
    w.Amplitude = amplitude;
    w.WorldK2 = WorldK2(w.K, grid.GetWorldToIndex());
    amplitudes += std::abs(amplitude);
    if (!std::isfinite(w.K[0] + w.K[1] + w.K[2] + w.Phase + w.Amplitude + w.WorldK2))
    {
      vtkErrorWithObjectMacro(reporter, << "The detail noise has a non-finite wave.");
      return false;
    }
  }
  // Coarsest first: the footprint filter keeps a prefix of them.
  std::stable_sort(
    waves.begin(), waves.end(), [](const Wave& a, const Wave& b) { return a.WorldK2 < b.WorldK2; });
  SetFilterLevels(waves);
  const vtkMTimeType source = std::max({ grid.GetScalarsTime(), grid.GetExtinctionTime() });
  const bool shapeStale = source != this->SourceTime ||
    grid.GetParameters().DensityScale != this->Density || this->ShapeValues.empty();
  const double width = filterWidth > 0.0 ? filterWidth : 0.0; // NaN: 0
  const bool extinctionChanged = shapeStale || noise->GetMTime() != this->NoiseTime;
  const bool wavesChanged = extinctionChanged || width != this->FilterWidth;
  this->FilterWidth = width;
  this->Waves = std::move(waves);
  this->Offset = noise->GetOffset();
  this->Scale = noise->GetExtinctionScale();
  this->NoiseMaximum = this->Offset + amplitudes;
  this->AmplitudeSum = amplitudes;
  this->ClampShare = NoiseClampShare(this->Offset, this->Waves);
  this->NoiseTime = noise->GetMTime();
  if (shapeStale)
  {
    this->BuildShape(grid);
    this->SourceTime = source;
  }
  if (extinctionChanged)
  {
    this->ExtinctionTime.Modified();
  }
  if (wavesChanged)
  {
    this->Time.Modified();
  }
  this->IsEnabled = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallDetailMedium::BuildShape(const vtkTyndallGridMedium& grid)
{
  vtkDataArray* scalars = grid.GetScalars();
  const vtkTyndallTransferTable& table = grid.GetTable();
  const int* dims = grid.GetDimensions();
  std::copy(dims, dims + 3, this->Dimensions);
  std::copy(grid.GetBoxLow(), grid.GetBoxLow() + 3, this->BoxLow);
  std::copy(grid.GetBoxHigh(), grid.GetBoxHigh() + 3, this->BoxHigh);
  this->Density = grid.GetParameters().DensityScale;
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  this->ShapeValues.assign(n, 0.0f);
  double maximum = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (std::isnan(v))
    {
      continue; // missing data: empty
    }
    int k;
    double f;
    table.Locate(grid.Clean(v), k, f);
    const double sigma = this->Density * table.ExtinctionAt(k, f);
    this->ShapeValues[i] = static_cast<float>(sigma);
    maximum = std::max(maximum, static_cast<double>(this->ShapeValues[i]));
  }
  this->ShapeMaximum = maximum;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::ShapeAt(int i, int j, int k) const
{
  const int* n = this->Dimensions;
  return this->ShapeValues[(static_cast<size_t>(k) * n[1] + j) * n[0] + i];
}

//------------------------------------------------------------------------------
void vtkTyndallDetailMedium::Corners(const int cell[3], double v[8]) const
{
  for (int c = 0; c < 8; ++c)
  {
    v[c] = this->ShapeAt(cell[0] + (c & 1), cell[1] + ((c >> 1) & 1), cell[2] + ((c >> 2) & 1));
  }
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::Shape(const double p[3]) const
{
  int cell[3];
  double u[3];
  for (int a = 0; a < 3; ++a)
  {
    const int n = this->Dimensions[a];
    const double x = std::min(std::max(p[a], 0.0), static_cast<double>(n - 1));
    cell[a] = std::min(static_cast<int>(x), n - 2);
    u[a] = x - cell[a];
  }
  double v[8];
  this->Corners(cell, v);
  const double x00 = v[0] + u[0] * (v[1] - v[0]);
  const double x10 = v[2] + u[0] * (v[3] - v[2]);
  const double x01 = v[4] + u[0] * (v[5] - v[4]);
  const double x11 = v[6] + u[0] * (v[7] - v[6]);
  const double y0 = x00 + u[1] * (x10 - x00);
  const double y1 = x01 + u[1] * (x11 - x01);
  return y0 + u[2] * (y1 - y0);
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::Noise(const double p[3]) const
{
  double sum = this->Offset;
  for (const Wave& w : this->Waves)
  {
    sum += w.Amplitude * std::cos(w.K[0] * p[0] + w.K[1] * p[1] + w.K[2] * p[2] + w.Phase);
  }
  return sum;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::FilterFactor(int i, double sigma) const
{
  const double f = std::exp(-0.5 * this->Waves[i].FilterK2 * sigma * sigma);
  return f >= FilterCutoff ? f : 0.0;
}

//------------------------------------------------------------------------------
int vtkTyndallDetailMedium::GetLiveWaves(double pixel) const
{
  const int n = static_cast<int>(this->Waves.size());
  const double sigma = this->FilterWidth * pixel;
  if (!(sigma > 0.0))
  {
    return n;
  }
  int live = 0;
  while (live<n&& this->FilterFactor(live, sigma)> 0.0)
  {
    ++live;
  }
  return live;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetFinestWavelength(int n) const
{
  double k2 = 0.0;
  for (int i = 0; i < n && i < static_cast<int>(this->Waves.size()); ++i)
  {
    if (this->Waves[i].Amplitude != 0.0)
    {
      k2 = std::max(k2, this->Waves[i].WorldK2);
    }
  }
  return k2 > 0.0 ? 2.0 * vtkMath::Pi() / std::sqrt(k2) : 1e30;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::FilteredNoise(const double p[3], double pixel) const
{
  const double sigma = this->FilterWidth * pixel;
  if (!(sigma > 0.0))
  {
    return this->Noise(p);
  }
  double sum = this->Offset;
  const int n = static_cast<int>(this->Waves.size());
  for (int i = 0; i < n; ++i)
  {
    const double f = this->FilterFactor(i, sigma);
    if (f == 0.0)
    {
      break; // coarsest first: the finer ones are below the cutoff too
    }
    const Wave& w = this->Waves[i];
    sum += f * w.Amplitude * std::cos(w.K[0] * p[0] + w.K[1] * p[1] + w.K[2] * p[2] + w.Phase);
  }
  return sum;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::StepMeanNoise(
  const double p[3], double pixel, const double span[3]) const
{
  const double sigma = this->FilterWidth * pixel;
  double sum = this->Offset;
  const int n = static_cast<int>(this->Waves.size());
  for (int i = 0; i < n; ++i)
  {
    const double f = sigma > 0.0 ? this->FilterFactor(i, sigma) : 1.0;
    if (f == 0.0)
    {
      break; // coarsest first: the finer ones are below the cutoff too
    }
    const Wave& w = this->Waves[i];
    const double x = 0.5 * (w.K[0] * span[0] + w.K[1] * span[1] + w.K[2] * span[2]);
    const double sinc = std::abs(x) > 1e-8 ? std::sin(x) / x : 1.0;
    sum +=
      f * sinc * w.Amplitude * std::cos(w.K[0] * p[0] + w.K[1] * p[1] + w.K[2] * p[2] + w.Phase);
  }
  return sum;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetCameraStep(
  double pixel, double maximumStep, double lightingWidth) const
{
  if (this->UsesStepMeans(pixel, maximumStep, lightingWidth))
  {
    // Each wave's exact mean over the step (StepMeanNoise()): the step
    // follows the shape and the light.
    return std::min(maximumStep, 0.5 * lightingWidth);
  }
  return this->GetWaveStep(pixel, maximumStep);
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::UsesStepMeans(
  double pixel, double maximumStep, double lightingWidth) const
{
  return this->FilterWidth > 0.0 && this->ClampShare <= ClampTolerance && lightingWidth > 0.0 &&
    std::min(maximumStep, 0.5 * lightingWidth) > this->GetWaveStep(pixel, maximumStep);
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetWaveStep(double pixel, double maximumStep) const
{
  const int live = this->GetLiveWaves(pixel);
  const double longest = std::min(maximumStep, 0.5 * this->GetFinestWavelength(live));
  if (live == 0 || !(this->AmplitudeSum > 0.0))
  {
    return longest;
  }
  auto error = [&](double h)
  {
    double sum = 0.0;
    for (int i = 0; i < live; ++i)
    {
      const Wave& w = this->Waves[i];
      const double x = 0.5 * std::sqrt(w.WorldK2) * h;
      const double sinc = x > 1e-8 ? std::sin(x) / x : 1.0;
      sum += std::abs(w.Amplitude) * (1.0 - sinc);
    }
    return sum / this->AmplitudeSum;
  };
  if (error(longest) <= StepTolerance)
  {
    return longest;
  }
  // The error grows with h up to half the finest wavelength: bisection.
  double lo = 0.0, hi = longest;
  for (int i = 0; i < 40; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (error(mid) <= StepTolerance ? lo : hi) = mid;
  }
  return lo;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::FieldExtinction(const double p[3], Work* work) const
{
  if (this->Grid->HasMissingData() && std::isnan(this->Grid->FieldScalar(p)))
  {
    return 0.0; // missing data, as the grid's
  }
  const double shape = this->Shape(p);
  if (!(shape > 0.0))
  {
    return 0.0;
  }
  if (work)
  {
    work->TrigonometricPasses += 1.0;
  }
  return shape * this->Scale * std::max(0.0, this->Noise(p));
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::FieldSample(const double p[3], Point& point, double pixel) const
{
  // The colours at the grid's scalar, the extinction the detail's (filtered
  // by the pixel's footprint).
  if (!this->FieldMaterial(p, point))
  {
    return false;
  }
  if (!(this->FilterWidth * pixel > 0.0))
  {
    point.Extinction = this->FieldExtinction(p, nullptr);
    return point.Extinction > 0.0;
  }
  const double shape = this->Shape(p);
  point.Extinction =
    shape > 0.0 ? shape * this->Scale * std::max(0.0, this->FilteredNoise(p, pixel)) : 0.0;
  return point.Extinction > 0.0;
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::FieldMaterial(const double p[3], Point& point) const
{
  int k;
  double f;
  if (!this->Grid->TablePosition(p, k, f))
  {
    return false; // missing data
  }
  this->Grid->TableColors(p, k, f, point);
  return true;
}

//------------------------------------------------------------------------------
const double* vtkTyndallDetailMedium::GetWorldToLocal() const
{
  return this->Grid->GetWorldToLocal();
}

//------------------------------------------------------------------------------
const double* vtkTyndallDetailMedium::GetLocalToWorld() const
{
  return this->Grid->GetLocalToWorld();
}

//------------------------------------------------------------------------------
const vtkTyndallMediumParameters& vtkTyndallDetailMedium::GetParameters() const
{
  return this->Grid->GetParameters();
}

//------------------------------------------------------------------------------
const vtkTyndallClipRegion* vtkTyndallDetailMedium::GetClip() const
{
  return this->Grid->GetClip();
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::GetArrayEmission() const
{
  return this->Grid->GetArrayEmission();
}

//------------------------------------------------------------------------------
void vtkTyndallDetailMedium::ArrayEmission(const double p[3], double rgb[3]) const
{
  this->Grid->ArrayEmission(p, rgb);
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetFinestFeature() const
{
  return std::min(this->Grid->GetMinimumWorldSpacing(),
    this->GetShortestWavelength(this->Grid->GetWorldToIndex()) / 2.0);
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::OpticalDepth(const double o[3], const double d[3], double t0,
  double t1, double step, double maxDepth, bool clip, const PathCache* start, Work* work) const
{
  if (clip && this->GetClip())
  {
    return this->vtkTyndallMedium::OpticalDepth(o, d, t0, t1, step, maxDepth, clip, start, work);
  }
  double a = t0, b = t1;
  if (!ClipToBox(o, d, this->BoxLow, this->BoxHigh, a, b))
  {
    return 0.0;
  }
  return this->ClosedFormDepth(o, d, a, b, start, work);
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::SampleDistance(const double o[3], const double d[3], double t0,
  double t1, double target, double& t, const PathCache* start, PathCache* collision,
  Work* work) const
{
  return this->ClosedFormDistance(o, d, t0, t1, target, t, start, collision, work);
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetMajorant() const
{
  return this->ShapeMaximum * this->Scale * std::max(0.0, this->NoiseMaximum);
}

//------------------------------------------------------------------------------
void vtkTyndallDetailMedium::CellPolynomial(
  const int region[3], const double pa[3], const double d[3], double c[4]) const
{
  // Per axis the local coordinate u(s) = u0 + s du inside the cell; fixed at
  // 0 or 1 in the clamped half cells outside the samples.
  int cell[3];
  Linear u[3];
  for (int a = 0; a < 3; ++a)
  {
    const int n = this->Dimensions[a];
    if (region[a] < 0)
    {
      cell[a] = 0;
      u[a] = { 0.0, 0.0 };
    }
    else if (region[a] > n - 2)
    {
      cell[a] = n - 2;
      u[a] = { 1.0, 0.0 };
    }
    else
    {
      cell[a] = region[a];
      u[a] = { pa[a] - region[a], d[a] };
    }
  }
  double v[8];
  this->Corners(cell, v);
  // f = A + B x + C y + D z + E xy + F xz + G yz + H xyz.
  const double A = v[0], B = v[1] - v[0], C = v[2] - v[0], D = v[4] - v[0];
  const double E = v[3] - v[1] - v[2] + v[0];
  const double F = v[5] - v[1] - v[4] + v[0];
  const double G = v[6] - v[2] - v[4] + v[0];
  const double H = v[7] - v[3] - v[5] - v[6] + v[1] + v[2] + v[4] - v[0];
  const double one[4] = { 1.0, 0.0, 0.0, 0.0 };
  double x[4], y[4], z[4], xy[4], xz[4], yz[4], xyz[4];
  Multiply(one, u[0], x);
  Multiply(one, u[1], y);
  Multiply(one, u[2], z);
  Multiply(x, u[1], xy);
  Multiply(x, u[2], xz);
  Multiply(y, u[2], yz);
  Multiply(xy, u[2], xyz);
  c[0] = A;
  c[1] = c[2] = c[3] = 0.0;
  AddScaled(c, x, B);
  AddScaled(c, y, C);
  AddScaled(c, z, D);
  AddScaled(c, xy, E);
  AddScaled(c, xz, F);
  AddScaled(c, yz, G);
  AddScaled(c, xyz, H);
}

//------------------------------------------------------------------------------
template <typename F>
void vtkTyndallDetailMedium::WalkCells(
  const double o[3], const double d[3], double t0, double t1, F&& visit) const
{
  // Clip to the box.
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < this->BoxLow[a] || o[a] > this->BoxHigh[a])
      {
        return;
      }
      continue;
    }
    double ta = (this->BoxLow[a] - o[a]) / d[a];
    double tb = (this->BoxHigh[a] - o[a]) / d[a];
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1))
  {
    return;
  }
  // Regions per axis: -1 below sample 0, r in [0, n - 2] the cell [r, r + 1],
  // n - 1 above the last sample. Boundaries are the sample planes.
  int region[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = o[a] + t0 * d[a];
    int r = static_cast<int>(std::floor(x));
    if (d[a] < 0.0 && r == x)
    {
      --r;
    }
    region[a] = std::min(std::max(r, -1), this->Dimensions[a] - 1);
  }
  double t = t0;
  while (t < t1)
  {
    double tNext = t1;
    for (int a = 0; a < 3; ++a)
    {
      const int plane = d[a] > 0.0 ? region[a] + 1 : region[a];
      if (d[a] != 0.0 && plane >= 0 && plane <= this->Dimensions[a] - 1)
      {
        tNext = std::min(tNext, (plane - o[a]) / d[a]);
      }
    }
    tNext = std::max(tNext, t);
    if (tNext > t)
    {
      Segment s;
      s.Ta = t;
      s.Tb = tNext;
      for (int a = 0; a < 3; ++a)
      {
        const int plane = d[a] > 0.0 ? region[a] + 1 : region[a];
        const bool crossed = tNext < t1 && d[a] != 0.0 && plane >= 0 &&
          plane <= this->Dimensions[a] - 1 && (plane - o[a]) / d[a] <= tNext;
        s.Plane[a] = crossed ? plane : NoPlane;
      }
      const double pa[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      this->CellPolynomial(region, pa, d, s.C);
      if (!visit(s, pa))
      {
        return;
      }
    }
    if (tNext >= t1)
    {
      return;
    }
    for (int a = 0; a < 3; ++a)
    {
      const int plane = d[a] > 0.0 ? region[a] + 1 : region[a];
      if (d[a] != 0.0 && plane >= 0 && plane <= this->Dimensions[a] - 1 &&
        (plane - o[a]) / d[a] <= tNext)
      {
        region[a] += d[a] > 0.0 ? 1 : -1;
      }
    }
    t = tNext;
  }
}

//------------------------------------------------------------------------------
// The waves' phases along one ray, carried from cell to cell: the phase at
// a cell's end is its start's plus theta, so e^{i alpha} is advanced by a
// complex product with e^{i theta} (needed anyway) instead of a new sincos.
class vtkTyndallDetailMedium::RayWaves
{
public:
  // Adds this ray's passes over the waves to `work` (if any).
  void AddWork(Work* work) const
  {
    if (work)
    {
      work->Add(this->Passes);
    }
  }

  RayWaves(
    const vtkTyndallDetailMedium& medium, const double d[3], const PointPhases* start = nullptr)
    : Medium(medium)
    , Start(start)
    , Beta(medium.Waves.size())
    , Cos(medium.Waves.size())
    , Sin(medium.Waves.size())
    , CosStep(medium.Waves.size())
    , SinStep(medium.Waves.size())
    , StartCos(medium.Waves.size())
    , StartSin(medium.Waves.size())
    , InverseBeta(medium.Waves.size())
  {
    std::copy(d, d + 3, this->D);
    for (size_t i = 0; i < this->Beta.size(); ++i)
    {
      const double* k = medium.Waves[i].K;
      this->Beta[i] = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
      this->InverseBeta[i] =
        this->Beta[i] != 0.0 ? 1.0 / this->Beta[i] : std::numeric_limits<double>::infinity();
    }
  }

  // The integral of P(s) phi over the cell `seg` starting at pa (not
  // clamped, not scaled); the phases move on to the cell's end.
  //
  // The phase at the end is the start's times e^{i theta}, theta = beta x
  // length: a sincos per wave. But the cells of a grid end on sample
  // planes, and an axis's planes are crossed at times 1 / |d_a| apart, so
  // the phases at its consecutive crossings form a geometric sequence: from
  // an axis's second crossing on, the end phase is the phase at its last
  // crossing times e^{i beta / |d_a|} (computed once per ray), and
  // e^{i theta} is the end's over the start's. No trigonometry then.
  double Integrate(const Segment& seg, const double pa[3])
  {
    const double* c = seg.C;
    const double length = seg.Tb - seg.Ta;
    if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0 && c[3] == 0.0)
    {
      this->Valid = false; // an empty cell: no wave is evaluated
      std::fill(this->AxisPlane, this->AxisPlane + 3, NoPlane);
      return 0.0;
    }
    const std::vector<Wave>& waves = this->Medium.Waves;
    const size_t count = waves.size();
    this->PhasesAt(pa);
    const double inverseLength = 1.0 / length;
    const int axis = this->SequenceAxis(seg);
    const double* stepCos = axis >= 0 ? this->AxisStepCos[axis].data() : nullptr;
    const double* stepSin = axis >= 0 ? this->AxisStepSin[axis].data() : nullptr;
    const double* lastCos = axis >= 0 ? this->AxisCos[axis].data() : nullptr;
    const double* lastSin = axis >= 0 ? this->AxisSin[axis].data() : nullptr;
    (axis >= 0 ? this->Passes.CellPasses : this->Passes.TrigonometricPasses) += 1.0;
    const double e[4] = { c[0], c[1] * length, c[2] * length * length,
      c[3] * length * length * length };
    double sum = this->Medium.Offset * (e[0] + e[1] / 2.0 + e[2] / 3.0 + e[3] / 4.0);
    for (size_t i = 0; i < count; ++i)
    {
      const double theta = this->Beta[i] * length;
      const double ca = this->Cos[i], sa = this->Sin[i];
      double endCos, endSin, cosT, sinT;
      if (axis >= 0)
      {
        endCos = lastCos[i] * stepCos[i] - lastSin[i] * stepSin[i];
        endSin = lastSin[i] * stepCos[i] + lastCos[i] * stepSin[i];
        cosT = endCos * ca + endSin * sa; // end x conj(start)
        sinT = endSin * ca - endCos * sa;
      }
      else
      {
        cosT = std::cos(theta);
        sinT = std::sin(theta);
        endCos = ca * cosT - sa * sinT;
        endSin = sa * cosT + ca * sinT;
      }
      double re, im;
      vtkCosineNoiseMoments::Compute(
        e, theta, this->InverseBeta[i] * inverseLength, cosT, sinT, re, im);
      sum += waves[i].Amplitude * (ca * re - sa * im);
      this->Cos[i] = endCos;
      this->Sin[i] = endSin;
      this->CosStep[i] = cosT;
      this->SinStep[i] = sinT;
    }
    this->RecordCrossings(seg);
    return length * sum;
  }

  // After Integrate() over a cell whose integral `whole` reaches `goal`
  // (0 < goal <= whole): the s in [0, length] at which the integral from
  // the cell's start reaches goal. Safeguarded Halley iteration (I' = P phi,
  // I'' = P' phi + P phi'), from the guess of a homogeneous cell; the
  // phases at s are the cell's start's times e^{i beta s}, one sincos per
  // wave and step gives I, phi and phi' together.
  double Solve(const double pa[3], const double c[4], double length, double goal, double whole,
    PointPhases* collision)
  {
    const size_t count = this->Beta.size();
    for (size_t i = 0; i < count; ++i)
    {
      // Back from the cell's end to its start: times e^{-i theta}.
      const double ce = this->Cos[i], se = this->Sin[i];
      this->StartCos[i] = ce * this->CosStep[i] + se * this->SinStep[i];
      this->StartSin[i] = se * this->CosStep[i] - ce * this->SinStep[i];
    }
    const double guess = whole > 0.0 ? length * std::min(1.0, goal / whole) : 0.5 * length;
    return this->SolveFromStart(pa, c, length, goal, guess, collision);
  }

  // Whether the cell `seg` (from pa) surely holds the point where its
  // integral reaches `goal` > 0, by a bound that needs no trigonometry
  // beyond the phases at the cell's start (which the cell needs anyway); if
  // so, SolveInCell() finds it without the cell's whole integral. With
  // P >= 0 on the cell (a trilinear interpolant of extinctions), Q its
  // integral and V >= int |P'|, one integration by parts gives per wave
  //   a int_0^L P cos(alpha + beta s) ds
  //     = (a / beta) (P(L) sin(alpha + beta L) - P(0) sin alpha - int P' sin)
  //     >= -|a / beta| (P(L) + V) - (a / beta) P(0) sin alpha,
  // and it is at least -|a| Q; the integral is at least offset Q plus the
  // larger of the two per wave.
  bool Holds(const Segment& seg, const double pa[3], double goal)
  {
    const double* c = seg.C;
    const double length = seg.Tb - seg.Ta;
    const double q = length * Integral(c, length);
    const double offset = this->Medium.Offset;
    if (!(q > 0.0) || offset <= 0.0 || (offset + this->Medium.AmplitudeSum) * q < goal)
    {
      return false; // not even the largest integral the noise allows reaches it
    }
    this->PhasesAt(pa);
    this->Passes.BoundPasses += 1.0;
    const double variation =
      length * (std::abs(c[1]) + length * (std::abs(c[2]) + length * std::abs(c[3])));
    const double end = std::abs(Evaluate(c, length)) + variation;
    const std::vector<Wave>& waves = this->Medium.Waves;
    double bound = offset * q;
    for (size_t i = 0; i < waves.size(); ++i)
    {
      const double a = waves[i].Amplitude;
      const double r = a * this->InverseBeta[i];
      const double parts = std::abs(r) * end + r * c[0] * this->Sin[i];
      bound -= std::isfinite(parts) ? std::min(std::abs(a) * q, parts) : std::abs(a) * q;
    }
    if (bound < goal)
    {
      return false;
    }
    std::copy(this->Cos.begin(), this->Cos.end(), this->StartCos.begin());
    std::copy(this->Sin.begin(), this->Sin.end(), this->StartSin.begin());
    this->Passes.BoundSolves += 1.0;
    return true;
  }

  // After Holds(): the s in [0, length] at which the cell's integral
  // reaches goal, from the guess of a homogeneous medium of the noise's
  // offset (offset int_0^s P = goal).
  double SolveInCell(
    const double pa[3], const double c[4], double length, double goal, PointPhases* collision)
  {
    const double offset = this->Medium.Offset;
    double s = length;
    for (int iteration = 0; iteration < 8; ++iteration)
    {
      const double q = s * Integral(c, s);
      const double p = Evaluate(c, s);
      if (!(p > 0.0))
      {
        break;
      }
      const double next = std::min(length, std::max(0.0, s - (q - goal / offset) / p));
      const bool converged = std::abs(next - s) <= 1e-3 * length;
      s = next;
      if (converged)
      {
        break;
      }
    }
    return this->SolveFromStart(pa, c, length, goal, s, collision);
  }

  // The solve from the phases at the cell's start (StartCos, StartSin) and
  // a first guess.
  double SolveFromStart(const double pa[3], const double c[4], double length, double goal,
    double guess, PointPhases* collision)
  {
    const std::vector<Wave>& waves = this->Medium.Waves;
    const size_t count = waves.size();
    const double offset = this->Medium.Offset;
    double lo = 0.0, hi = length;
    double s = guess > 0.0 && guess < length ? guess : 0.5 * length;
    double evaluated = -1.0; // where the phases of `collision` are
    if (collision)
    {
      collision->Valid = false; // it may be the start, read by now
      collision->Cos.resize(count);
      collision->Sin.resize(count);
    }
    for (int iteration = 0; iteration < 100; ++iteration)
    {
      const double e[4] = { c[0], c[1] * s, c[2] * s * s, c[3] * s * s * s };
      const double inverseS = 1.0 / s;
      this->Passes.TrigonometricPasses += 1.0;
      double integral = offset * (e[0] + e[1] / 2.0 + e[2] / 3.0 + e[3] / 4.0);
      double phi = offset, slope = 0.0;
      for (size_t i = 0; i < count; ++i)
      {
        const double theta = this->Beta[i] * s;
        const double cosT = std::cos(theta);
        const double sinT = std::sin(theta);
        double re, im;
        vtkCosineNoiseMoments::Compute(
          e, theta, this->InverseBeta[i] * inverseS, cosT, sinT, re, im);
        const double ca = this->StartCos[i], sa = this->StartSin[i];
        const double a = waves[i].Amplitude;
        const double cs = ca * cosT - sa * sinT, ss = sa * cosT + ca * sinT; // e^{i alpha(s)}
        integral += a * (ca * re - sa * im);
        phi += a * cs;
        slope -= a * this->Beta[i] * ss;
        if (collision)
        {
          collision->Cos[i] = cs;
          collision->Sin[i] = ss;
        }
      }
      evaluated = s;
      const double value = s * integral - goal;
      if (std::abs(value) <= 1e-13 * goal)
      {
        break;
      }
      (value < 0.0 ? lo : hi) = s;
      if (hi - lo <= 1e-14 * length)
      {
        break;
      }
      const double p = Evaluate(c, s);
      const double first = p * phi;
      const double second = (c[1] + s * (2.0 * c[2] + 3.0 * s * c[3])) * phi + p * slope;
      const double denominator = 2.0 * first * first - value * second;
      const bool halley = first > 0.0 && denominator > 0.0;
      double next =
        halley ? s - 2.0 * value * first / denominator : (first > 0.0 ? s - value / first : -1.0);
      if (!(next > lo && next < hi))
      {
        next = 0.5 * (lo + hi);
      }
      else if (halley && std::abs(next - s) <= 1e-8 * length && std::abs(value) <= 1e-6 * goal)
      {
        // Halley converges cubically: after a step this small (from a
        // residual this small: not a step shrunk by an extinction near 0)
        // the error is of the order of its cube, below the tolerance.
        this->Record(collision, pa, evaluated);
        return next;
      }
      s = next;
    }
    this->Record(collision, pa, evaluated);
    return s;
  }

private:
  // Makes Cos, Sin the phases at pa, the start of the next cell, unless
  // they are carried there: from the ray's start phases, or a sincos per wave.
  void PhasesAt(const double pa[3])
  {
    if (this->Valid)
    {
      return;
    }
    if (!this->TakeStart(pa))
    {
      this->Passes.TrigonometricPasses += 1.0;
      const std::vector<Wave>& waves = this->Medium.Waves;
      for (size_t i = 0; i < waves.size(); ++i)
      {
        const Wave& w = waves[i];
        const double alpha = w.K[0] * pa[0] + w.K[1] * pa[1] + w.K[2] * pa[2] + w.Phase;
        this->Cos[i] = std::cos(alpha);
        this->Sin[i] = std::sin(alpha);
      }
    }
    this->Valid = true;
  }

  // Uses the start phases (once, for the ray's first cell) when they are at
  // pa but for rounding: turned by k . (pa - point), each below 1e-4 rad,
  // whose sine and cosine to fifth order are exact to rounding.
  bool TakeStart(const double pa[3])
  {
    const PointPhases* start = this->Start;
    this->Start = nullptr;
    const std::vector<Wave>& waves = this->Medium.Waves;
    if (!start || !start->Valid || start->Cos.size() != waves.size())
    {
      return false;
    }
    const double delta[3] = { pa[0] - start->Point[0], pa[1] - start->Point[1],
      pa[2] - start->Point[2] };
    for (size_t i = 0; i < waves.size(); ++i)
    {
      this->Cos[i] = waves[i].K[0] * delta[0] + waves[i].K[1] * delta[1] + waves[i].K[2] * delta[2];
      if (!(std::abs(this->Cos[i]) <= 1e-4))
      {
        return false;
      }
    }
    for (size_t i = 0; i < waves.size(); ++i)
    {
      const double x = this->Cos[i], x2 = x * x;
      const double cosX = 1.0 - x2 / 2.0 * (1.0 - x2 / 12.0);
      const double sinX = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0));
      this->Cos[i] = start->Cos[i] * cosX - start->Sin[i] * sinX;
      this->Sin[i] = start->Sin[i] * cosX + start->Cos[i] * sinX;
    }
    return true;
  }

  // The phases written by Solve() are at pa + evaluated d.
  void Record(PointPhases* collision, const double pa[3], double evaluated) const
  {
    if (collision && evaluated >= 0.0)
    {
      for (int a = 0; a < 3; ++a)
      {
        collision->Point[a] = pa[a] + evaluated * this->D[a];
      }
      collision->Valid = true;
    }
  }

  // The axis whose sequence gives this cell's end phase: one whose plane
  // is crossed at the end, right after the plane of its last recorded
  // crossing; -1 if none. Computes that axis's step once per ray.
  int SequenceAxis(const Segment& seg)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (seg.Plane[a] == NoPlane || this->AxisPlane[a] == NoPlane ||
        seg.Plane[a] != this->AxisPlane[a] + (this->D[a] > 0.0 ? 1 : -1))
      {
        continue;
      }
      if (this->AxisStepCos[a].empty())
      {
        const size_t count = this->Beta.size();
        this->Passes.TrigonometricPasses += 1.0;
        this->AxisStepCos[a].resize(count);
        this->AxisStepSin[a].resize(count);
        for (size_t i = 0; i < count; ++i)
        {
          const double angle = this->Beta[i] / std::abs(this->D[a]);
          this->AxisStepCos[a][i] = std::cos(angle);
          this->AxisStepSin[a][i] = std::sin(angle);
        }
      }
      return a;
    }
    return -1;
  }

  // The phases at the cell's end are those at each plane crossed there;
  // an axis not crossed keeps its last crossing (its next one is then the
  // plane after it, whatever the other axes crossed in between).
  void RecordCrossings(const Segment& seg)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (seg.Plane[a] != NoPlane)
      {
        this->AxisPlane[a] = seg.Plane[a];
        this->AxisCos[a] = this->Cos;
        this->AxisSin[a] = this->Sin;
      }
    }
  }

  const vtkTyndallDetailMedium& Medium;
  const PointPhases* Start;
  double D[3];
  int AxisPlane[3] = { NoPlane, NoPlane, NoPlane };
  std::vector<double> AxisCos[3]; // the phases at each axis's last crossing
  std::vector<double> AxisSin[3];
  std::vector<double> AxisStepCos[3]; // e^{i beta / |d_a|}, once needed
  std::vector<double> AxisStepSin[3];
  std::vector<double> Beta;
  std::vector<double> Cos;
  std::vector<double> Sin;
  std::vector<double> CosStep; // e^{i theta} of the last cell
  std::vector<double> SinStep;
  std::vector<double> StartCos; // the phases at the solved cell's start
  std::vector<double> StartSin;
  std::vector<double> InverseBeta; // 1 / beta (infinite for beta = 0)
  Work Passes;
  bool Valid = false; // whether Cos, Sin are the phases at the next cell's start
};

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::ClosedFormDepth(const double o[3], const double d[3], double t0,
  double t1, const PointPhases* start, Work* work) const
{
  double tau = 0.0;
  RayWaves phases(*this, d, start);
  this->WalkCells(o, d, t0, t1,
    [&](const Segment& s, const double pa[3])
    {
      tau += std::max(0.0, phases.Integrate(s, pa));
      return true;
    });
  phases.AddWork(work);
  return this->Scale * tau;
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::ClosedFormDistance(const double o[3], const double d[3], double t0,
  double t1, double target, double& t, const PointPhases* start, PointPhases* collision,
  Work* work) const
{
  if (collision && collision != start)
  {
    collision->Valid = false; // until a solve fills it
  }
  if (target == 0.0)
  {
    t = t0;
    return true;
  }
  t = t1;
  if (!(target > 0.0) || this->Scale <= 0.0)
  {
    return false;
  }
  const double goal = target / this->Scale; // in units of the unscaled integral
  double accumulated = 0.0;
  bool found = false;
  RayWaves phases(*this, d, start);
  this->WalkCells(o, d, t0, t1,
    [&](const Segment& s, const double pa[3])
    {
      const double length = s.Tb - s.Ta;
      if (phases.Holds(s, pa, goal - accumulated))
      {
        t = s.Ta + phases.SolveInCell(pa, s.C, length, goal - accumulated, collision);
        found = true;
        return false;
      }
      const double cell = std::max(0.0, phases.Integrate(s, pa));
      if (accumulated + cell < goal)
      {
        accumulated += cell;
        return true;
      }
      t = s.Ta + phases.Solve(pa, s.C, length, goal - accumulated, cell, collision);
      found = true;
      return false;
    });
  phases.AddWork(work);
  return found;
}

//------------------------------------------------------------------------------
void vtkTyndallDetailMedium::ProjectExtinction(
  const double o[3], const double d[3], double t0, double t1, int count, double* c) const
{
  std::fill(c, c + std::max(count, 0), 0.0);
  const double length = t1 - t0;
  if (count <= 0 || !(length > 0.0))
  {
    return;
  }
  const double pi = 3.14159265358979323846;
  this->WalkCells(o, d, t0, t1,
    [&](const Segment& s, const double pa[3])
    {
      const double cellLength = s.Tb - s.Ta;
      if (s.C[0] == 0.0 && s.C[1] == 0.0 && s.C[2] == 0.0 && s.C[3] == 0.0)
      {
        return true; // an empty cell
      }
      for (int j = 0; j < count; ++j)
      {
        // cos(j pi u) = cos(gamma + omega s) along the cell, s = t - Ta.
        const double omega = j * pi / length;
        const double gamma = omega * (s.Ta - t0);
        double sum =
          this->Offset * vtkCosineNoise::PolynomialWaveIntegral(s.C, cellLength, gamma, omega);
        for (const Wave& w : this->Waves)
        {
          const double alpha = w.K[0] * pa[0] + w.K[1] * pa[1] + w.K[2] * pa[2] + w.Phase;
          const double beta = w.K[0] * d[0] + w.K[1] * d[1] + w.K[2] * d[2];
          sum += 0.5 * w.Amplitude *
            (vtkCosineNoise::PolynomialWaveIntegral(s.C, cellLength, alpha + gamma, beta + omega) +
              vtkCosineNoise::PolynomialWaveIntegral(s.C, cellLength, alpha - gamma, beta - omega));
        }
        // c_j = 2 int D sigma cos(j pi u) du = 2 int sigma(t) cos(...) dt.
        c[j] += 2.0 * this->Scale * sum;
      }
      return true;
    });
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::GetShortestWavelength(const double worldToIndex[16]) const
{
  // k . p = k . (A x + b): the wave vector in world units is A^T k.
  double longest = 0.0;
  for (const Wave& w : this->Waves)
  {
    if (w.Amplitude == 0.0)
    {
      continue;
    }
    double k[3];
    for (int c = 0; c < 3; ++c)
    {
      k[c] = w.K[0] * worldToIndex[c] + w.K[1] * worldToIndex[4 + c] + w.K[2] * worldToIndex[8 + c];
    }
    longest = std::max(longest, std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]));
  }
  return longest > 0.0 ? 2.0 * 3.14159265358979323846 / longest : 1e30;
}
