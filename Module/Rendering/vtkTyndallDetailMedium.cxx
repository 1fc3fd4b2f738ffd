#include "vtkTyndallDetailMedium.h"

#include "vtkCosineNoise.h"
#include "vtkDataArray.h"
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

// The integral of P(s) over [0, s].
double PolynomialIntegral(const double c[4], double s)
{
  return s * (c[0] + s * (c[1] / 2.0 + s * (c[2] / 3.0 + s * c[3] / 4.0)));
}

double Evaluate(const double c[4], double s)
{
  return c[0] + s * (c[1] + s * (c[2] + s * c[3]));
}
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::Update(
  const vtkTyndallGridMedium& grid, vtkCosineNoise* noise, vtkObject* reporter)
{
  this->IsEnabled = false;
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
    amplitudes += std::abs(amplitude);
    if (!std::isfinite(w.K[0] + w.K[1] + w.K[2] + w.Phase + w.Amplitude))
    {
      vtkErrorWithObjectMacro(reporter, << "The detail noise has a non-finite wave.");
      return false;
    }
  }
  const vtkMTimeType source = std::max({ grid.GetScalarsTime(), grid.GetExtinctionTime() });
  const bool shapeStale = source != this->SourceTime || grid.GetDensityScale() != this->Density ||
    this->ShapeValues.empty();
  const bool wavesChanged = shapeStale || noise->GetMTime() != this->NoiseTime;
  this->Waves = std::move(waves);
  this->Offset = noise->GetOffset();
  this->Scale = noise->GetExtinctionScale();
  this->NoiseMaximum = this->Offset + amplitudes;
  this->NoiseTime = noise->GetMTime();
  if (shapeStale)
  {
    this->BuildShape(grid);
    this->SourceTime = source;
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
  this->Density = grid.GetDensityScale();
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
double vtkTyndallDetailMedium::Extinction(const double p[3]) const
{
  const double shape = this->Shape(p);
  return shape > 0.0 ? shape * this->Scale * std::max(0.0, this->Noise(p)) : 0.0;
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
double vtkTyndallDetailMedium::SegmentIntegral(
  const double pa[3], const double d[3], const double c[4], double length) const
{
  // The integral of P(s) phi(pa + s d), s in [0, length], unclamped, unscaled.
  double sum = this->Offset * PolynomialIntegral(c, length);
  for (const Wave& w : this->Waves)
  {
    const double alpha = w.K[0] * pa[0] + w.K[1] * pa[1] + w.K[2] * pa[2] + w.Phase;
    const double beta = w.K[0] * d[0] + w.K[1] * d[1] + w.K[2] * d[2];
    sum += w.Amplitude * vtkCosineNoise::PolynomialWaveIntegral(c, length, alpha, beta);
  }
  return sum;
}

//------------------------------------------------------------------------------
// The waves' phases along one ray, carried from cell to cell: the phase at
// a cell's end is its start's plus theta, so e^{i alpha} is advanced by a
// complex product with e^{i theta} (needed anyway) instead of a new sincos.
class vtkTyndallDetailMedium::RayWaves
{
public:
  RayWaves(const vtkTyndallDetailMedium& medium, const double d[3])
    : Medium(medium)
    , Beta(medium.Waves.size())
    , Cos(medium.Waves.size())
    , Sin(medium.Waves.size())
  {
    for (size_t i = 0; i < this->Beta.size(); ++i)
    {
      const double* k = medium.Waves[i].K;
      this->Beta[i] = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
    }
  }

  // The integral of P(s) phi over the cell [0, length] starting at pa (not
  // clamped, not scaled); the phases move on to the cell's end.
  double Integrate(const double pa[3], const double c[4], double length)
  {
    if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0 && c[3] == 0.0)
    {
      this->Valid = false; // an empty cell: no wave is evaluated
      return 0.0;
    }
    const std::vector<Wave>& waves = this->Medium.Waves;
    if (!this->Valid)
    {
      for (size_t i = 0; i < waves.size(); ++i)
      {
        const Wave& w = waves[i];
        const double alpha = w.K[0] * pa[0] + w.K[1] * pa[1] + w.K[2] * pa[2] + w.Phase;
        this->Cos[i] = std::cos(alpha);
        this->Sin[i] = std::sin(alpha);
      }
      this->Valid = true;
    }
    const double e[4] = { c[0], c[1] * length, c[2] * length * length,
      c[3] * length * length * length };
    double sum = this->Medium.Offset * (e[0] + e[1] / 2.0 + e[2] / 3.0 + e[3] / 4.0);
    for (size_t i = 0; i < waves.size(); ++i)
    {
      const double theta = this->Beta[i] * length;
      const double cosT = std::cos(theta);
      const double sinT = std::sin(theta);
      double re, im;
      vtkCosineNoise::PolynomialWaveMoments(e, theta, cosT, sinT, re, im);
      const double ca = this->Cos[i], sa = this->Sin[i];
      sum += waves[i].Amplitude * (ca * re - sa * im);
      this->Cos[i] = ca * cosT - sa * sinT;
      this->Sin[i] = sa * cosT + ca * sinT;
    }
    return length * sum;
  }

private:
  const vtkTyndallDetailMedium& Medium;
  std::vector<double> Beta;
  std::vector<double> Cos;
  std::vector<double> Sin;
  bool Valid = false;
};

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::OpticalDepth(
  const double o[3], const double d[3], double t0, double t1) const
{
  double tau = 0.0;
  RayWaves phases(*this, d);
  this->WalkCells(o, d, t0, t1,
    [&](const Segment& s, const double pa[3])
    {
      tau += std::max(0.0, phases.Integrate(pa, s.C, s.Tb - s.Ta));
      return true;
    });
  return this->Scale * tau;
}

//------------------------------------------------------------------------------
bool vtkTyndallDetailMedium::SampleDistance(
  const double o[3], const double d[3], double t0, double t1, double target, double& t) const
{
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
  RayWaves phases(*this, d);
  this->WalkCells(o, d, t0, t1,
    [&](const Segment& s, const double pa[3])
    {
      const double length = s.Tb - s.Ta;
      const double cell = std::max(0.0, phases.Integrate(pa, s.C, length));
      if (accumulated + cell < goal)
      {
        accumulated += cell;
        return true;
      }
      t = s.Ta + this->SolveInCell(pa, d, s.C, length, goal - accumulated, cell);
      found = true;
      return false;
    });
  return found;
}

//------------------------------------------------------------------------------
double vtkTyndallDetailMedium::SolveInCell(const double pa[3], const double d[3], const double c[4],
  double length, double goal, double whole) const
{
  // I(s) = SegmentIntegral over [0, s]; find I(s) = goal with I(0) = 0 <=
  // goal <= I(length) = whole: safeguarded Newton (I' = P phi, the
  // extinction), from the guess of a homogeneous cell.
  double lo = 0.0, hi = length;
  double s = whole > 0.0 ? length * std::min(1.0, goal / whole) : 0.5 * length;
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    const double value = this->SegmentIntegral(pa, d, c, s) - goal;
    if (std::abs(value) <= 1e-13 * goal)
    {
      break;
    }
    (value < 0.0 ? lo : hi) = s;
    if (hi - lo <= 1e-14 * length)
    {
      break;
    }
    const double p[3] = { pa[0] + s * d[0], pa[1] + s * d[1], pa[2] + s * d[2] };
    const double slope = Evaluate(c, s) * this->Noise(p);
    double next = slope > 0.0 ? s - value / slope : -1.0;
    if (!(next > lo && next < hi))
    {
      next = 0.5 * (lo + hi);
    }
    s = next;
  }
  return s;
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
