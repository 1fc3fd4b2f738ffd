#include "vtkTyndallFootprint.h"

#include "vtkCamera.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
bool vtkTyndallFootprint::SetCamera(vtkCamera* camera, int width, int height)
{
  *this = vtkTyndallFootprint();
  if (!camera || width <= 0 || height <= 0)
  {
    return false;
  }
  double eye[3], n[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(n);
  if (!std::isfinite(vtkMath::Normalize(n)) || !std::isfinite(vtkMath::Dot(n, eye)))
  {
    return false;
  }
  std::copy(n, n + 3, this->Plane);
  this->Plane[3] = -vtkMath::Dot(n, eye);
  const double pixels = camera->GetUseHorizontalViewAngle() ? width : height;
  if (camera->GetParallelProjection())
  {
    this->Constant = 2.0 * camera->GetParallelScale() / height;
  }
  else
  {
    this->PerDepth =
      2.0 * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / pixels;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallFootprint::At(const double x[3]) const
{
  const double depth = vtkMath::Dot(this->Plane, x) + this->Plane[3];
  return this->Constant + this->PerDepth * std::max(depth, 0.0);
}

//------------------------------------------------------------------------------
double vtkTyndallFootprint::Minimum(const double corners[24], double nearDepth) const
{
  double depth = vtkMath::Inf();
  for (int c = 0; c < 8; ++c)
  {
    depth = std::min(depth, vtkMath::Dot(this->Plane, corners + 3 * c) + this->Plane[3]);
  }
  return this->Constant + this->PerDepth * std::max(std::max(depth, nearDepth), 0.0);
}
