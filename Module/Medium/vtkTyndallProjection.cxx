#include "vtkTyndallProjection.h"

#include "vtkMath.h"
#include "vtkPlane.h"
#include "vtkTyndallTransferTable.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
void vtkTyndallProjection::Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  this->Mode = NONE;
  switch (mapper ? mapper->GetBlendMode() : vtkVolumeMapper::COMPOSITE_BLEND)
  {
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      this->Mode = MAXIMUM;
      break;
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      this->Mode = MINIMUM;
      break;
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      this->Mode = AVERAGE;
      break;
    case vtkVolumeMapper::ADDITIVE_BLEND:
      this->Mode = ADDITIVE;
      break;
    case vtkVolumeMapper::SLICE_BLEND:
      if (auto* plane = vtkPlane::SafeDownCast(property ? property->GetSliceFunction() : nullptr))
      {
        this->Mode = SLICE;
        double origin[3];
        plane->GetOrigin(origin);
        plane->GetNormal(this->SlicePlane);
        this->SlicePlane[3] = -vtkMath::Dot(this->SlicePlane, origin);
      }
      break;
    default:
      break;
  }
  if (mapper)
  {
    mapper->GetAverageIPScalarRange(this->AverageRange);
  }
  this->UnitDistance = property ? property->GetScalarOpacityUnitDistance(0) : 1.0;
}

//------------------------------------------------------------------------------
const char* vtkTyndallProjection::GetModeName(int mode)
{
  switch (mode)
  {
    case MAXIMUM:
      return "maximum intensity";
    case MINIMUM:
      return "minimum intensity";
    case AVERAGE:
      return "average intensity";
    case ADDITIVE:
      return "additive";
    case SLICE:
      return "slice";
    default:
      return "composite";
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallProjection::SliceDistance(const double origin[3], const double w[3], double& t) const
{
  const double denominator = vtkMath::Dot(this->SlicePlane, w);
  if (!(std::abs(denominator) > 1e-12))
  {
    return false;
  }
  t = -(vtkMath::Dot(this->SlicePlane, origin) + this->SlicePlane[3]) / denominator;
  return true;
}

//------------------------------------------------------------------------------
vtkTyndallProjection::Ray::Ray(
  const vtkTyndallProjection& projection, const vtkTyndallTransferTable& table)
  : P(&projection)
  , Table(&table)
{
}

//------------------------------------------------------------------------------
void vtkTyndallProjection::Ray::Add(double value, double dt)
{
  switch (this->P->Mode)
  {
    case MAXIMUM:
      this->Extremum = this->Count > 0 ? std::max(this->Extremum, value) : value;
      break;
    case MINIMUM:
      this->Extremum = this->Count > 0 ? std::min(this->Extremum, value) : value;
      break;
    case SLICE:
      this->Extremum = value; // the one sample, on the plane
      break;
    case AVERAGE:
      if (value < this->P->AverageRange[0] || value > this->P->AverageRange[1])
      {
        return; // not counted
      }
      this->Sum += this->Table->OpacityOf(value) * this->Table->Unit(value);
      break;
    case ADDITIVE:
      this->Sum +=
        this->Table->OpacityOf(value) * dt / this->P->UnitDistance * this->Table->Unit(value);
      break;
    default:
      return;
  }
  ++this->Count;
}

//------------------------------------------------------------------------------
bool vtkTyndallProjection::Ray::Pixel(double rgba[4]) const
{
  const int mode = this->P->Mode;
  if (mode == MAXIMUM || mode == MINIMUM || mode == SLICE)
  {
    if (this->Count == 0)
    {
      return false;
    }
    int k;
    double f;
    this->Table->Locate(this->Extremum, k, f);
    const double a = this->Table->OpacityAt(k, f);
    vtkTyndallTransferTable::RGBAt(this->Table->Albedo, k, f, rgba);
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] *= a;
    }
    rgba[3] = a;
    return true;
  }
  if (mode == AVERAGE && this->Count == 0)
  {
    return false;
  }
  const double sum = mode == AVERAGE ? this->Sum / this->Count : this->Sum;
  rgba[0] = rgba[1] = rgba[2] = std::min(std::max(sum, 0.0), 1.0);
  rgba[3] = 1.0;
  return mode == AVERAGE || mode == ADDITIVE;
}
