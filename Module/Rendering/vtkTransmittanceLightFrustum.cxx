#include "vtkTransmittanceLightFrustum.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittanceLightFrustum);

namespace
{
// Two unit vectors perpendicular to the unit vector z and to each other.
void Perpendiculars(const double z[3], double x[3], double y[3])
{
  const double helper[3] = { std::abs(z[0]) < 0.9 ? 1.0 : 0.0, std::abs(z[0]) < 0.9 ? 0.0 : 1.0,
    0.0 };
  vtkMath::Cross(helper, z, x);
  vtkMath::Normalize(x);
  vtkMath::Cross(z, x, y);
}

bool Finite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkTransmittanceLightFrustum::FitDirectional(
  const double direction[3], const double corners[24])
{
  double z[3] = { direction[0], direction[1], direction[2] };
  if (!Finite(direction, 3) || !Finite(corners, 24) || !(vtkMath::Normalize(z) > 0.0))
  {
    return false;
  }
  double x[3], y[3];
  Perpendiculars(z, x, y);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int i = 0; i < 8; ++i)
  {
    const double* c = corners + 3 * i;
    const double p[3] = { vtkMath::Dot(c, x), vtkMath::Dot(c, y), vtkMath::Dot(c, z) };
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  // Pad the rectangle; a degenerate (flat) extent still gets a width.
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  for (int k = 0; k < 2; ++k)
  {
    const double pad = this->Padding * std::max(hi[k] - lo[k], 1e-6 * diagonal);
    lo[k] -= pad;
    hi[k] += pad;
  }
  // Start one box depth before the box on the light side.
  const double start = lo[2] - std::max(hi[2] - lo[2], 1e-6 * diagonal);
  for (int k = 0; k < 3; ++k)
  {
    this->Origin[k] = lo[0] * x[k] + lo[1] * y[k] + start * z[k];
    this->AxisX[k] = (hi[0] - lo[0]) * x[k];
    this->AxisY[k] = (hi[1] - lo[1]) * y[k];
    this->AxisZ[k] = z[k];
  }
  this->Positional = false;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceLightFrustum::FitPositional(const double position[3], const double corners[24])
{
  if (!Finite(position, 3) || !Finite(corners, 24))
  {
    return false;
  }
  double center[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < 8; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      center[k] += corners[3 * i + k] / 8.0;
    }
  }
  double z[3] = { center[0] - position[0], center[1] - position[1], center[2] - position[2] };
  if (!(vtkMath::Normalize(z) > 0.0))
  {
    return false;
  }
  double x[3], y[3];
  Perpendiculars(z, x, y);
  double tanX = 0.0, tanY = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    const double v[3] = { corners[3 * i] - position[0], corners[3 * i + 1] - position[1],
      corners[3 * i + 2] - position[2] };
    const double depth = vtkMath::Dot(v, z);
    if (!(depth > 1e-9 * vtkMath::Norm(v)))
    {
      return false; // a corner is beside or behind the light
    }
    tanX = std::max(tanX, std::abs(vtkMath::Dot(v, x)) / depth);
    tanY = std::max(tanY, std::abs(vtkMath::Dot(v, y)) / depth);
  }
  tanX *= 1.0 + 2.0 * this->Padding;
  tanY *= 1.0 + 2.0 * this->Padding;
  const double halfAngle = vtkMath::DegreesFromRadians(std::atan(std::max(tanX, tanY)));
  if (2.0 * halfAngle > this->MaximumFieldOfView)
  {
    return false;
  }
  // Corners on the axis: give the frustum a minimal width.
  tanX = std::max(tanX, 1e-6);
  tanY = std::max(tanY, 1e-6);
  for (int k = 0; k < 3; ++k)
  {
    this->Origin[k] = position[k];
    this->AxisX[k] = tanX * x[k];
    this->AxisY[k] = tanY * y[k];
    this->AxisZ[k] = z[k];
  }
  this->Positional = true;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightFrustum::GetRay(
  double a, double b, double origin[3], double direction[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    if (this->Positional)
    {
      origin[k] = this->Origin[k];
      direction[k] =
        this->AxisZ[k] + (2.0 * a - 1.0) * this->AxisX[k] + (2.0 * b - 1.0) * this->AxisY[k];
    }
    else
    {
      origin[k] = this->Origin[k] + a * this->AxisX[k] + b * this->AxisY[k];
      direction[k] = this->AxisZ[k];
    }
  }
  vtkMath::Normalize(direction);
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightFrustum::GetTexel(const double x[3], double ab[2]) const
{
  const double v[3] = { x[0] - this->Origin[0], x[1] - this->Origin[1], x[2] - this->Origin[2] };
  const double xx = vtkMath::Dot(this->AxisX, this->AxisX);
  const double yy = vtkMath::Dot(this->AxisY, this->AxisY);
  if (!this->Positional)
  {
    ab[0] = vtkMath::Dot(v, this->AxisX) / xx;
    ab[1] = vtkMath::Dot(v, this->AxisY) / yy;
    return;
  }
  const double depth = vtkMath::Dot(v, this->AxisZ);
  ab[0] = 0.5 * (vtkMath::Dot(v, this->AxisX) / (depth * xx) + 1.0);
  ab[1] = 0.5 * (vtkMath::Dot(v, this->AxisY) / (depth * yy) + 1.0);
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightFrustum::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "MaximumFieldOfView: " << this->MaximumFieldOfView << "\n";
  os << indent << "Positional: " << this->Positional << "\n";
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "AxisX: (" << this->AxisX[0] << ", " << this->AxisX[1] << ", " << this->AxisX[2]
     << ")\n";
  os << indent << "AxisY: (" << this->AxisY[0] << ", " << this->AxisY[1] << ", " << this->AxisY[2]
     << ")\n";
  os << indent << "AxisZ: (" << this->AxisZ[0] << ", " << this->AxisZ[1] << ", " << this->AxisZ[2]
     << ")\n";
}
