#include "vtkCosineNoise.h"
#include "vtkCosineNoiseMoments.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkCosineNoise);

namespace
{
constexpr int kMaxDirections = 1024;
constexpr int kMaxOctaves = 16;

// sin(x)/x, accurate to double precision also for tiny |x|.
inline double Sinc(double x)
{
  if (std::abs(x) < 1.0e-3)
  {
    const double x2 = x * x;
    return 1.0 - x2 / 6.0 + x2 * x2 / 120.0;
  }
  return std::sin(x) / x;
}

// Point i of the 2-D Sobol sequence: the first dimension is the base-2 van
// der Corput sequence, the second uses the direction numbers of the
// primitive polynomial x + 1 (v_j = v_{j-1} ^ (v_{j-1} >> 1)).
void Sobol2D(std::uint32_t i, double& u, double& v)
{
  std::uint32_t x = 0;
  std::uint32_t y = 0;
  std::uint32_t dir = 1u << 31;
  for (int bit = 0; bit < 32; ++bit, dir ^= dir >> 1)
  {
    if (i & (1u << bit))
    {
      x |= 1u << (31 - bit);
      y ^= dir;
    }
  }
  u = x * (1.0 / 4294967296.0);
  v = y * (1.0 / 4294967296.0);
}

// Uniform [0, 1) from the 32-bit Mersenne twister, whose output sequence is
// fixed by the C++ standard (std::uniform_real_distribution is not).
inline double Uniform(std::mt19937& engine)
{
  return engine() * (1.0 / 4294967296.0);
}
}

//------------------------------------------------------------------------------
// The wave table: noise(x) = offset + sum_j a_j cos(k_j . x + phase_j).
class vtkCosineNoise::vtkInternals
{
public:
  std::vector<double> Kx, Ky, Kz, Phase, Amp;
  double SumAbsAmplitude = 0.0;
  double MaxWaveNumber = 0.0;
  std::atomic<vtkMTimeType> BuiltFrom{ 0 };
  std::mutex Mutex;

  double Evaluate(double offset, const double x[3]) const
  {
    double sum = 0.0;
    const size_t n = this->Amp.size();
    for (size_t j = 0; j < n; ++j)
    {
      sum += this->Amp[j] *
        std::cos(this->Kx[j] * x[0] + this->Ky[j] * x[1] + this->Kz[j] * x[2] + this->Phase[j]);
    }
    return offset + sum;
  }

  // Exact integral of the signed noise over [t0, t1] along o + t w, |w| = 1.
  double Integrate(double offset, const double o[3], const double w[3], double t0, double t1) const
  {
    const double delta = t1 - t0;
    const double tMid = 0.5 * (t0 + t1);
    double sum = 0.0;
    const size_t n = this->Amp.size();
    for (size_t j = 0; j < n; ++j)
    {
      const double alpha =
        this->Kx[j] * o[0] + this->Ky[j] * o[1] + this->Kz[j] * o[2] + this->Phase[j];
      const double beta = this->Kx[j] * w[0] + this->Ky[j] * w[1] + this->Kz[j] * w[2];
      sum += this->Amp[j] * std::cos(alpha + beta * tMid) * Sinc(0.5 * beta * delta);
    }
    return delta * (offset + sum);
  }
};

//------------------------------------------------------------------------------
vtkCosineNoise::vtkCosineNoise()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkCosineNoise::~vtkCosineNoise()
{
  this->SetCustomDirections(nullptr);
}

//------------------------------------------------------------------------------
void vtkCosineNoise::SetNumberOfDirections(int n)
{
  if (n < 1 || n > kMaxDirections)
  {
    vtkErrorMacro(<< "NumberOfDirections must be in [1, " << kMaxDirections << "], got " << n
                  << "; clamping.");
    n = std::min(std::max(n, 1), kMaxDirections);
  }
  if (n != this->NumberOfDirections)
  {
    this->NumberOfDirections = n;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCosineNoise::SetNumberOfOctaves(int n)
{
  if (n < 1 || n > kMaxOctaves)
  {
    vtkErrorMacro(<< "NumberOfOctaves must be in [1, " << kMaxOctaves << "], got " << n
                  << "; clamping.");
    n = std::min(std::max(n, 1), kMaxOctaves);
  }
  if (n != this->NumberOfOctaves)
  {
    this->NumberOfOctaves = n;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCosineNoise::SetCustomDirections(vtkDataArray* directions)
{
  if (directions &&
    (directions->GetNumberOfComponents() != 3 || directions->GetNumberOfTuples() < 1 ||
      directions->GetNumberOfTuples() > kMaxDirections))
  {
    vtkErrorMacro(<< "Custom directions need 1 to " << kMaxDirections
                  << " tuples of 3 components; got " << directions->GetNumberOfTuples()
                  << " tuples of " << directions->GetNumberOfComponents()
                  << " components. Keeping the previous directions.");
    return;
  }
  if (directions == this->CustomDirections)
  {
    return;
  }
  if (this->CustomDirections)
  {
    this->CustomDirections->UnRegister(this);
  }
  this->CustomDirections = directions;
  if (directions)
  {
    directions->Register(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCosineNoise::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->CustomDirections)
  {
    mtime = std::max(mtime, this->CustomDirections->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
const vtkCosineNoise::vtkInternals& vtkCosineNoise::GetWaves()
{
  vtkInternals& w = *this->Internals;
  const vtkMTimeType mtime = this->GetMTime();
  if (w.BuiltFrom.load() == mtime)
  {
    return w;
  }
  std::lock_guard<std::mutex> lock(w.Mutex);
  if (w.BuiltFrom.load() == mtime)
  {
    return w;
  }

  // The directions S_i.
  std::vector<double> dirs;
  std::mt19937 engine(this->Seed);
  if (this->CustomDirections)
  {
    const vtkIdType n = this->CustomDirections->GetNumberOfTuples();
    dirs.resize(3 * n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      this->CustomDirections->GetTuple(i, &dirs[3 * i]);
    }
  }
  else
  {
    const int n = this->NumberOfDirections;
    dirs.resize(3 * n);
    for (int i = 0; i < n; ++i)
    {
      double u, v;
      Sobol2D(static_cast<std::uint32_t>(i), u, v);
      const double z = 1.0 - 2.0 * u;
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = 2.0 * vtkMath::Pi() * v;
      const double scale = 0.8 + 0.4 * Uniform(engine);
      dirs[3 * i + 0] = scale * r * std::cos(phi);
      dirs[3 * i + 1] = scale * r * std::sin(phi);
      dirs[3 * i + 2] = scale * z;
    }
  }
  const size_t nDirs = dirs.size() / 3;

  // The rotation between octaves (Rodrigues' formula).
  double rot[3][3];
  vtkMath::Identity3x3(rot);
  double axis[3] = { this->OctaveRotationAxis[0], this->OctaveRotationAxis[1],
    this->OctaveRotationAxis[2] };
  if (vtkMath::Normalize(axis) > 0.0 && this->OctaveRotationAngle != 0.0)
  {
    const double a = vtkMath::RadiansFromDegrees(this->OctaveRotationAngle);
    const double c = std::cos(a), s = std::sin(a), C = 1.0 - c;
    const double x = axis[0], y = axis[1], z = axis[2];
    const double m[3][3] = { { c + x * x * C, x * y * C - z * s, x * z * C + y * s },
      { y * x * C + z * s, c + y * y * C, y * z * C - x * s },
      { z * x * C - y * s, z * y * C + x * s, c + z * z * C } };
    std::copy(&m[0][0], &m[0][0] + 9, &rot[0][0]);
  }

  const size_t nWaves = nDirs * this->NumberOfOctaves;
  w.Kx.assign(nWaves, 0.0);
  w.Ky.assign(nWaves, 0.0);
  w.Kz.assign(nWaves, 0.0);
  w.Phase.assign(nWaves, 0.0);
  w.Amp.assign(nWaves, 0.0);
  w.SumAbsAmplitude = 0.0;
  w.MaxWaveNumber = 0.0;

  double rotPower[3][3]; // R^o
  vtkMath::Identity3x3(rotPower);
  double frequency = 2.0 * vtkMath::Pi() * this->Frequency;
  double amplitude = this->Amplitude;
  size_t j = 0;
  for (int o = 0; o < this->NumberOfOctaves; ++o)
  {
    for (size_t i = 0; i < nDirs; ++i, ++j)
    {
      // cos(S . (f R^o x)) = cos((f (R^o)^T S) . x)
      const double* S = &dirs[3 * i];
      double k[3];
      for (int c = 0; c < 3; ++c)
      {
        k[c] = frequency * (rotPower[0][c] * S[0] + rotPower[1][c] * S[1] + rotPower[2][c] * S[2]);
      }
      w.Kx[j] = k[0];
      w.Ky[j] = k[1];
      w.Kz[j] = k[2];
      w.Phase[j] = this->RandomPhases ? 2.0 * vtkMath::Pi() * Uniform(engine) : 0.0;
      w.Amp[j] = amplitude;
      w.SumAbsAmplitude += std::abs(amplitude);
      w.MaxWaveNumber = std::max(w.MaxWaveNumber, vtkMath::Norm(k));
    }
    vtkMath::Multiply3x3(rot, rotPower, rotPower);
    frequency *= this->Lacunarity;
    amplitude *= this->Gain;
  }
  w.BuiltFrom.store(mtime);
  return w;
}

//------------------------------------------------------------------------------
double vtkCosineNoise::EvaluateFunction(double x[3])
{
  return this->GetWaves().Evaluate(this->Offset, x);
}

//------------------------------------------------------------------------------
void vtkCosineNoise::EvaluateGradient(double x[3], double g[3])
{
  const vtkInternals& w = this->GetWaves();
  g[0] = g[1] = g[2] = 0.0;
  const size_t n = w.Amp.size();
  for (size_t j = 0; j < n; ++j)
  {
    const double s =
      -w.Amp[j] * std::sin(w.Kx[j] * x[0] + w.Ky[j] * x[1] + w.Kz[j] * x[2] + w.Phase[j]);
    g[0] += s * w.Kx[j];
    g[1] += s * w.Ky[j];
    g[2] += s * w.Kz[j];
  }
}

//------------------------------------------------------------------------------
int vtkCosineNoise::GetNumberOfWaves()
{
  return static_cast<int>(this->GetWaves().Amp.size());
}

//------------------------------------------------------------------------------
bool vtkCosineNoise::GetWave(int i, double k[3], double& phase, double& amplitude)
{
  const vtkInternals& w = this->GetWaves();
  if (i < 0 || static_cast<size_t>(i) >= w.Amp.size())
  {
    vtkErrorMacro(<< "Wave index " << i << " out of range [0, " << w.Amp.size() << ").");
    return false;
  }
  k[0] = w.Kx[i];
  k[1] = w.Ky[i];
  k[2] = w.Kz[i];
  phase = w.Phase[i];
  amplitude = w.Amp[i];
  return true;
}

//------------------------------------------------------------------------------
double vtkCosineNoise::GetMinimumValue()
{
  return this->Offset - this->GetWaves().SumAbsAmplitude;
}

//------------------------------------------------------------------------------
double vtkCosineNoise::GetMaximumValue()
{
  return this->Offset + this->GetWaves().SumAbsAmplitude;
}

//------------------------------------------------------------------------------
double vtkCosineNoise::GetStandardDeviation()
{
  const vtkInternals& w = this->GetWaves();
  double power = 0.0;
  for (double a : w.Amp)
  {
    power += 0.5 * a * a;
  }
  return std::sqrt(power);
}

//------------------------------------------------------------------------------
bool vtkCosineNoise::CheckRay(
  const double origin[3], const double direction[3], double w[3], const char* who)
{
  for (int c = 0; c < 3; ++c)
  {
    w[c] = direction[c];
    if (!std::isfinite(origin[c]) || !std::isfinite(direction[c]))
    {
      vtkErrorMacro(<< who << ": the ray's origin and direction must be finite.");
      return false;
    }
  }
  if (!(vtkMath::Normalize(w) > 0.0))
  {
    vtkErrorMacro(<< who << ": the ray direction is a zero vector.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkCosineNoise::ComputeIntegral(
  const double origin[3], const double direction[3], double t0, double t1)
{
  double w[3];
  if (!this->CheckRay(origin, direction, w, "ComputeIntegral"))
  {
    return 0.0;
  }
  if (!std::isfinite(t0) || !std::isfinite(t1))
  {
    vtkErrorMacro(<< "ComputeIntegral: the ray parameters t0, t1 must be finite.");
    return 0.0;
  }
  return this->GetWaves().Integrate(this->Offset, origin, w, t0, t1);
}

//------------------------------------------------------------------------------
void vtkCosineNoise::PolynomialWaveMoments(
  const double e[4], double theta, double cosTheta, double sinTheta, double& re, double& im)
{
  vtkCosineNoiseMoments::Compute(
    e, theta, theta != 0.0 ? 1.0 / theta : 0.0, cosTheta, sinTheta, re, im);
}

//------------------------------------------------------------------------------
double vtkCosineNoise::PolynomialWaveIntegral(
  const double c[4], double length, double alpha, double beta)
{
  // e_n = c_n L^n: the polynomial in u = s / L on [0, 1].
  const double e[4] = { c[0], c[1] * length, c[2] * length * length,
    c[3] * length * length * length };
  const double theta = beta * length;
  double re, im;
  PolynomialWaveMoments(e, theta, std::cos(theta), std::sin(theta), re, im);
  // Re(e^{i alpha} (re + i im)).
  return length * (std::cos(alpha) * re - std::sin(alpha) * im);
}

//------------------------------------------------------------------------------
double vtkCosineNoise::ComputeOpticalDepth(
  const double origin[3], const double direction[3], double t0, double t1)
{
  if (t1 < t0)
  {
    vtkErrorMacro(<< "ComputeOpticalDepth: t1 (" << t1 << ") < t0 (" << t0 << ").");
    return 0.0;
  }
  return this->ExtinctionScale * std::max(0.0, this->ComputeIntegral(origin, direction, t0, t1));
}

//------------------------------------------------------------------------------
double vtkCosineNoise::ComputeTransmittance(
  const double origin[3], const double direction[3], double t0, double t1)
{
  return std::exp(-this->ComputeOpticalDepth(origin, direction, t0, t1));
}

//------------------------------------------------------------------------------
int vtkCosineNoise::SampleDistance(const double origin[3], const double direction[3], double t0,
  double t1, double targetDepth, double& t)
{
  t = t0;
  double w[3];
  if (!this->CheckRay(origin, direction, w, "SampleDistance"))
  {
    return -1;
  }
  if (!std::isfinite(t0) || !std::isfinite(t1) || t1 < t0)
  {
    vtkErrorMacro(<< "SampleDistance: need finite t0 <= t1, got [" << t0 << ", " << t1 << "].");
    return -1;
  }
  if (!std::isfinite(targetDepth) || targetDepth < 0.0)
  {
    vtkErrorMacro(<< "SampleDistance: the target depth must be finite and >= 0, got " << targetDepth
                  << ".");
    return -1;
  }
  if (targetDepth == 0.0)
  {
    return 1;
  }
  const vtkInternals& waves = this->GetWaves();
  const double scale = this->ExtinctionScale;
  const double offset = this->Offset;
  // Cumulative optical depth from t0, and its derivative (the extinction).
  auto depth = [&](double tt) { return scale * waves.Integrate(offset, origin, w, t0, tt); };
  auto extinction = [&](double tt)
  {
    const double x[3] = { origin[0] + tt * w[0], origin[1] + tt * w[1], origin[2] + tt * w[2] };
    return scale * waves.Evaluate(offset, x);
  };

  // Bracket [a, b] with depth(a) < target <= depth(b).
  double a = t0, fa = -targetDepth;
  double b = t1, fb = depth(t1) - targetDepth;
  if (offset - waves.SumAbsAmplitude < 0.0 && waves.MaxWaveNumber > 0.0)
  {
    // Non-monotone: scan in quarter wavelengths for the first crossing.
    // At most 10^6 steps, so that huge segments cannot hang the caller.
    const double h = std::max(0.5 * vtkMath::Pi() / waves.MaxWaveNumber, (t1 - t0) * 1.0e-6);
    bool found = false;
    for (double lo = t0; lo < t1; lo += h)
    {
      const double hi = std::min(lo + h, t1);
      const double fhi = depth(hi) - targetDepth;
      if (fhi >= 0.0)
      {
        b = hi;
        fb = fhi;
        found = true;
        break;
      }
      a = hi;
      fa = fhi;
    }
    if (!found)
    {
      t = t1;
      return 0;
    }
  }
  else if (fb < 0.0)
  {
    t = t1;
    return 0;
  }

  // Safeguarded Newton on the bracket.
  const double tolerance = 1.0e-13 * std::max(1.0, targetDepth);
  double tt = (fb - fa) > 0.0 ? a + (b - a) * (-fa / (fb - fa)) : 0.5 * (a + b);
  for (int iteration = 0; iteration < 200; ++iteration)
  {
    const double f = depth(tt) - targetDepth;
    if (std::abs(f) <= tolerance)
    {
      break;
    }
    if (f < 0.0)
    {
      a = tt;
    }
    else
    {
      b = tt;
    }
    if (b - a <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b)))
    {
      break;
    }
    const double d = extinction(tt);
    double next = d > 0.0 ? tt - f / d : 0.5 * (a + b);
    if (!(next > a && next < b))
    {
      next = 0.5 * (a + b);
    }
    tt = next;
  }
  t = tt;
  return 1;
}

//------------------------------------------------------------------------------
void vtkCosineNoise::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "CustomDirections: " << this->CustomDirections << "\n";
  os << indent << "NumberOfOctaves: " << this->NumberOfOctaves << "\n";
  os << indent << "Lacunarity: " << this->Lacunarity << "\n";
  os << indent << "Gain: " << this->Gain << "\n";
  os << indent << "OctaveRotationAngle: " << this->OctaveRotationAngle << "\n";
  os << indent << "OctaveRotationAxis: (" << this->OctaveRotationAxis[0] << ", "
     << this->OctaveRotationAxis[1] << ", " << this->OctaveRotationAxis[2] << ")\n";
  os << indent << "Frequency: " << this->Frequency << "\n";
  os << indent << "Amplitude: " << this->Amplitude << "\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "ExtinctionScale: " << this->ExtinctionScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "RandomPhases: " << (this->RandomPhases ? "On" : "Off") << "\n";
}
