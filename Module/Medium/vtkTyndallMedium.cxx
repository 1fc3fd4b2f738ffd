#include "vtkTyndallMedium.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkTyndallClipRegion.h"

#include <cmath>

//------------------------------------------------------------------------------
vtkTyndallMedium::~vtkTyndallMedium() = default;

//------------------------------------------------------------------------------
void vtkTyndallMedium::ArrayEmission(const double*, double rgb[3]) const
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
}

//------------------------------------------------------------------------------
double vtkTyndallMedium::OpticalDepth(const double o[3], const double d[3], double t0, double t1,
  double step, double maxDepth, bool clip, const PathCache*, Work* work) const
{
  if (!ClipToBox(o, d, this->GetBoxLow(), this->GetBoxHigh(), t0, t1))
  {
    return 0.0;
  }
  // [t0, t1]: the part of the ray in the box (a point outside it, such as a
  // surface receiving the shadow, samples no clamped voxels on its way in).
  const vtkTyndallClipRegion* region = clip ? this->GetClip() : nullptr;
  const double length = t1 - t0;
  const int n = static_cast<int>(std::max(1.0, std::ceil(length / step)));
  const double dt = length / n;
  double tau = 0.0;
  for (int m = 0; m < n; ++m)
  {
    const double t = t0 + (m + 0.5) * dt;
    const double q[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    if (region && !region->InsideIndex(q))
    {
      continue;
    }
    const double sigma = this->FieldExtinction(q, work);
    if (sigma > 0.0)
    {
      tau += sigma * dt;
      if (tau > maxDepth)
      {
        break;
      }
    }
  }
  return tau;
}

//------------------------------------------------------------------------------
bool vtkTyndallMedium::SampleDistance(const double*, const double*, double, double t1, double,
  double& t, const PathCache*, PathCache*, Work*) const
{
  t = t1;
  return false;
}

//------------------------------------------------------------------------------
void vtkTyndallMedium::ToLocalPoint(const double x[3], double p[3]) const
{
  const double* m = this->GetWorldToLocal();
  for (int r = 0; r < 3; ++r)
  {
    p[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallMedium::ToLocalDirection(const double w[3], double d[3]) const
{
  const double* m = this->GetWorldToLocal();
  for (int r = 0; r < 3; ++r)
  {
    d[r] = m[4 * r] * w[0] + m[4 * r + 1] * w[1] + m[4 * r + 2] * w[2];
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallMedium::Inside(const double p[3]) const
{
  const vtkTyndallClipRegion* clip = this->GetClip();
  return InsideBox(p, this->GetBoxLow(), this->GetBoxHigh()) && (!clip || clip->InsideIndex(p));
}

//------------------------------------------------------------------------------
void vtkTyndallMedium::GetWorldCorners(double corners[24]) const
{
  const double* low = this->GetBoxLow();
  const double* high = this->GetBoxHigh();
  for (int c = 0; c < 8; ++c)
  {
    const double p[4] = { (c & 1) ? high[0] : low[0], (c & 2) ? high[1] : low[1],
      (c & 4) ? high[2] : low[2], 1.0 };
    double w[4];
    vtkMatrix4x4::MultiplyPoint(this->GetLocalToWorld(), p, w);
    std::copy(w, w + 3, corners + 3 * c);
  }
}

//------------------------------------------------------------------------------
double vtkTyndallMedium::GetMinimumWorldSpacing() const
{
  const double* m = this->GetLocalToWorld();
  double spacing = VTK_DOUBLE_MAX;
  for (int c = 0; c < 3; ++c)
  {
    const double column[3] = { m[c], m[4 + c], m[8 + c] };
    spacing = std::min(spacing, vtkMath::Norm(column));
  }
  return spacing;
}

//------------------------------------------------------------------------------
double vtkTyndallMedium::GetWorldDiagonal() const
{
  double corners[24];
  this->GetWorldCorners(corners);
  return std::sqrt(vtkMath::Distance2BetweenPoints(corners, corners + 21));
}
