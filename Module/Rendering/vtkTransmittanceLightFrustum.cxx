#include "vtkTransmittanceLightFrustum.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
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
double vtkTransmittanceLightFrustum::GetTexelWidth(const double corners[24], int mapSize) const
{
  const double side = std::min(vtkMath::Norm(this->AxisX), vtkMath::Norm(this->AxisY));
  const double n = std::max(mapSize, 1);
  if (!this->Positional)
  {
    return side / n;
  }
  // The ray of a changes direction by 2 AxisX / n per texel (AxisZ unit).
  double nearest = 1e300;
  for (int i = 0; i < 8; ++i)
  {
    const double v[3] = { corners[3 * i] - this->Origin[0], corners[3 * i + 1] - this->Origin[1],
      corners[3 * i + 2] - this->Origin[2] };
    nearest = std::min(nearest, vtkMath::Dot(v, this->AxisZ) / vtkMath::Norm(this->AxisZ));
  }
  return 2.0 * side * std::max(nearest, 0.0) / n;
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
void vtkTransmittanceLightFrustum::ComputeClipMatrix(const double corners[24], vtkMatrix4x4* clip)
{
  double x[3], y[3], z[3];
  std::copy(this->AxisX, this->AxisX + 3, x);
  std::copy(this->AxisY, this->AxisY + 3, y);
  std::copy(this->AxisZ, this->AxisZ + 3, z);
  const double lx = vtkMath::Normalize(x), ly = vtkMath::Normalize(y);
  vtkMath::Normalize(z);
  const double* o = this->Origin;
  double farDistance = 0.0, minDepth = VTK_DOUBLE_MAX;
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(corners, corners + 21));
  for (int c = 0; c < 8; ++c)
  {
    const double v[3] = { corners[3 * c] - o[0], corners[3 * c + 1] - o[1],
      corners[3 * c + 2] - o[2] };
    farDistance = std::max(farDistance, vtkMath::Dot(v, z));
    minDepth = std::min(minDepth, vtkMath::Dot(v, z));
  }
  farDistance += 0.01 * diagonal;
  clip->Zero();
  if (!this->Positional)
  {
    const double nearDistance = -10.0 * diagonal;
    const double sz = 2.0 / (farDistance - nearDistance);
    for (int k = 0; k < 3; ++k)
    {
      clip->SetElement(0, k, 2.0 / lx * x[k]);
      clip->SetElement(1, k, 2.0 / ly * y[k]);
      clip->SetElement(2, k, sz * z[k]);
    }
    clip->SetElement(0, 3, -2.0 / lx * vtkMath::Dot(o, x) - 1.0);
    clip->SetElement(1, 3, -2.0 / ly * vtkMath::Dot(o, y) - 1.0);
    clip->SetElement(2, 3, -sz * (vtkMath::Dot(o, z) + nearDistance) - 1.0);
    clip->SetElement(3, 3, 1.0);
    this->NearDistance = nearDistance;
  }
  else
  {
    const double nearDistance = 1e-3 * std::max(minDepth, 1e-6 * diagonal);
    const double a = (farDistance + nearDistance) / (farDistance - nearDistance);
    const double b = -2.0 * farDistance * nearDistance / (farDistance - nearDistance);
    for (int k = 0; k < 3; ++k)
    {
      clip->SetElement(0, k, x[k] / lx);
      clip->SetElement(1, k, y[k] / ly);
      clip->SetElement(2, k, a * z[k]);
      clip->SetElement(3, k, z[k]);
    }
    clip->SetElement(0, 3, -vtkMath::Dot(o, x) / lx);
    clip->SetElement(1, 3, -vtkMath::Dot(o, y) / ly);
    clip->SetElement(2, 3, -a * vtkMath::Dot(o, z) + b);
    clip->SetElement(3, 3, -vtkMath::Dot(o, z));
    this->NearDistance = nearDistance;
  }
  this->FarDistance = farDistance;
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightFrustum::ConfigureCamera(const double corners[24], vtkCamera* camera)
{
  vtkNew<vtkMatrix4x4> clip;
  this->ComputeClipMatrix(corners, clip);
  double y[3], z[3];
  std::copy(this->AxisY, this->AxisY + 3, y);
  std::copy(this->AxisZ, this->AxisZ + 3, z);
  vtkMath::Normalize(y);
  vtkMath::Normalize(z);
  const double* o = this->Origin;
  camera->SetPosition(o[0], o[1], o[2]);
  camera->SetFocalPoint(o[0] + z[0], o[1] + z[1], o[2] + z[2]);
  camera->SetViewUp(y);
  // The composite projection is projection * view: make it `clip`.
  vtkNew<vtkMatrix4x4> viewInverse, projection;
  vtkMatrix4x4::Invert(camera->GetViewTransformMatrix(), viewInverse);
  vtkMatrix4x4::Multiply4x4(clip, viewInverse, projection);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->UseExplicitProjectionTransformMatrixOn();
}

//------------------------------------------------------------------------------
double vtkTransmittanceLightFrustum::GetRayDistance(double a, double b, double depth) const
{
  const double n = this->NearDistance, f = this->FarDistance;
  if (!this->Positional)
  {
    // Orthographic: depth is linear in the distance from the origin plane,
    // where every ray starts.
    return n + depth * (f - n);
  }
  // Perspective: the view depth, then the distance along the texel's ray.
  const double zNdc = 2.0 * depth - 1.0;
  const double w = 2.0 * n * f / ((f + n) - zNdc * (f - n));
  double origin[3], direction[3], z[3];
  this->GetRay(a, b, origin, direction);
  std::copy(this->AxisZ, this->AxisZ + 3, z);
  vtkMath::Normalize(z);
  return w / vtkMath::Dot(direction, z);
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
  os << indent << "NearDistance: " << this->NearDistance << "\n";
  os << indent << "FarDistance: " << this->FarDistance << "\n";
}
