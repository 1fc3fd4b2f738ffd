#include "vtkParticleKernel.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkTransmittanceMapMath.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkParticleKernel);

namespace
{
// A particle the formulas accept.
bool Valid(double radius, double density)
{
  return std::isfinite(radius) && radius > 0.0 && std::isfinite(density) && density >= 0.0;
}

// The chord's half length at the distance b from the centre; false when the ray misses.
bool HalfChord(double b, double radius, double& h)
{
  const double h2 = radius * radius - b * b;
  if (!(h2 > 0.0))
  {
    return false;
  }
  h = std::sqrt(h2);
  return true;
}

// The optical depth from the chord's entry -h to v, in units of rho / R^4.
double Primitive(double h, double v)
{
  v = std::min(std::max(v, -h), h);
  const double h2 = h * h, v2 = v * v;
  return h2 * h2 * v - 2.0 / 3.0 * h2 * v2 * v + 0.2 * v2 * v2 * v + 8.0 / 15.0 * h2 * h2 * h;
}
}

//------------------------------------------------------------------------------
void vtkParticleKernel::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kernel: rho (1 - r^2/R^2)^2 inside the radius R\n";
}

//------------------------------------------------------------------------------
double vtkParticleKernel::Extinction(double r, double radius, double density)
{
  if (!Valid(radius, density) || !(std::abs(r) < radius))
  {
    return 0.0;
  }
  const double t = r / radius; // |t| < 1 for any radius: no overflow
  return ExtinctionOfSquaredRatio(t * t, density);
}

//------------------------------------------------------------------------------
double vtkParticleKernel::Mass(double radius, double density)
{
  return Valid(radius, density) ? 32.0 * vtkMath::Pi() * density * radius * radius * radius / 105.0
                                : 0.0;
}

//------------------------------------------------------------------------------
double vtkParticleKernel::ChordDepth(double b, double radius, double density)
{
  double h;
  if (!Valid(radius, density) || !HalfChord(b, radius, h))
  {
    return 0.0;
  }
  const double r2 = radius * radius;
  return density * 16.0 / 15.0 * h * h * h * h * h / (r2 * r2);
}

//------------------------------------------------------------------------------
double vtkParticleKernel::PartialDepth(double b, double v, double radius, double density)
{
  double h;
  if (!Valid(radius, density) || std::isnan(v) || !HalfChord(b, radius, h))
  {
    return 0.0;
  }
  const double r2 = radius * radius;
  return density * Primitive(h, v) / (r2 * r2);
}

//------------------------------------------------------------------------------
double vtkParticleKernel::SegmentDepth(const double o[3], const double d[3], double t0, double t1,
  const double center[3], double radius, double density)
{
  if (!o || !d || !center || !Valid(radius, density) || !(t0 <= t1))
  {
    return 0.0;
  }
  const double e[3] = { center[0] - o[0], center[1] - o[1], center[2] - o[2] };
  const double tc = vtkMath::Dot(e, d);
  // The distance from the centre to the ray by the cross product (no
  // cancellation of |e|^2 - tc^2 far from the particle).
  double cross[3];
  vtkMath::Cross(e, d, cross);
  const double b = vtkMath::Norm(cross);
  double h;
  if (!std::isfinite(tc) || !HalfChord(b, radius, h))
  {
    return 0.0;
  }
  const double r2 = radius * radius;
  return density * (Primitive(h, t1 - tc) - Primitive(h, t0 - tc)) / (r2 * r2);
}

//------------------------------------------------------------------------------
double vtkParticleKernel::ProfileCosineIntegral(double x)
{
  if (std::isnan(x))
  {
    return 0.0;
  }
  x = std::abs(x);
  if (x < 0.5)
  {
    // sum_k (-1)^k x^2k / (2k)! * 16 / ((2k+1)(2k+3)(2k+5)); the terms
    // fall by at least 1/40 each: 8 reach double precision.
    double sum = 0.0, power = 1.0;
    for (int k = 0; k < 8; ++k)
    {
      sum += power * 16.0 / ((2.0 * k + 1.0) * (2.0 * k + 3.0) * (2.0 * k + 5.0));
      power *= -x * x / ((2.0 * k + 1.0) * (2.0 * k + 2.0));
    }
    return sum;
  }
  const double x2 = x * x;
  return 16.0 * ((3.0 - x2) * std::sin(x) - 3.0 * x * std::cos(x)) / (x2 * x2 * x);
}

//------------------------------------------------------------------------------
bool vtkParticleKernel::AddExtinctionCoefficients(double b, double tc, double length, double radius,
  double density, int count, double* coefficients)
{
  if (!coefficients || count < 1 ||
    count > vtkTransmittanceMapMath::GetMaximumNumberOfCoefficients() || !Valid(radius, density) ||
    !std::isfinite(tc) || !std::isfinite(length) || !(length > 0.0) || std::isnan(b))
  {
    return false;
  }
  double h;
  if (!HalfChord(b, radius, h))
  {
    return true; // the ray misses it: nothing to add
  }
  const double r2 = radius * radius;
  const double scale = 2.0 * density * h * h * h * h * h / (r2 * r2);
  for (int j = 0; j < count; ++j)
  {
    const double omega = j * vtkMath::Pi() / length;
    coefficients[j] += scale * std::cos(omega * tc) * ProfileCosineIntegral(omega * h);
  }
  return true;
}
