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
  for (int c = 0; c < vtkTyndallComponents::MaximumCount; ++c)
  {
    this->UnitDistances[c] = property ? property->GetScalarOpacityUnitDistance(c) : 1.0;
  }
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
vtkTyndallProjection::Ray::Ray(const vtkTyndallProjection& projection, const Classes& classes)
  : P(&projection)
  , Table(classes.Tables[0])
  , C(&classes)
{
}

//------------------------------------------------------------------------------
double vtkTyndallProjection::Ray::OpacityOf(int t, double v) const
{
  return this->C->Tables[t]->OpacityOf(v);
}

//------------------------------------------------------------------------------
double vtkTyndallProjection::Ray::UnitOf(int c, double v) const
{
  const double* r = this->C->Ranges[c];
  return r[1] > r[0] ? (v - r[0]) / (r[1] - r[0]) : 0.0;
}

//------------------------------------------------------------------------------
void vtkTyndallProjection::Ray::AddComponents(
  const double values[vtkTyndallComponents::MaximumCount], double dt)
{
  const vtkTyndallComponents& components = *this->C->Components;
  const int mode = this->P->Mode;
  const int count = components.GetCount();
  if (components.GetMode() == vtkTyndallComponents::Independent)
  {
    // Each component on its own (table i is component i's).
    for (int i = 0; i < count; ++i)
    {
      const double v = values[i];
      switch (mode)
      {
        case MAXIMUM:
          this->Values[i] = this->Count > 0 ? std::max(this->Values[i], v) : v;
          break;
        case MINIMUM:
          this->Values[i] = this->Count > 0 ? std::min(this->Values[i], v) : v;
          break;
        case SLICE:
          this->Values[i] = v;
          break;
        case AVERAGE:
          if (v >= this->P->AverageRange[0] && v <= this->P->AverageRange[1])
          {
            this->Sums[i] += this->OpacityOf(i, v) * this->UnitOf(i, v);
            ++this->Counts[i];
          }
          break;
        case ADDITIVE:
          this->Sums[i] +=
            this->OpacityOf(i, v) * dt / this->P->UnitDistances[i] * this->UnitOf(i, v);
          break;
        default:
          return;
      }
    }
    ++this->Count;
    return;
  }
  // Dependent: the opacity component is the last; its table is table 1 of
  // two components (table 0 is the colour's), table 0 of RGBA.
  const int s = count - 1;
  const int opacityTable = components.GetMode() == vtkTyndallComponents::DependentLA ? 1 : 0;
  switch (mode)
  {
    case MAXIMUM:
    case MINIMUM:
    case SLICE:
      if (this->Count == 0 || mode == SLICE ||
        (mode == MAXIMUM ? values[s] > this->Values[s] : values[s] < this->Values[s]))
      {
        std::copy(values, values + count, this->Values);
      }
      break;
    case AVERAGE:
      if (values[0] < this->P->AverageRange[0] || values[0] > this->P->AverageRange[1])
      {
        return; // not counted
      }
      this->Sum += this->OpacityOf(opacityTable, values[s]) * this->UnitOf(0, values[0]);
      break;
    case ADDITIVE:
      // (VTK's: the opacity component's unit distance.)
      this->Sum += this->OpacityOf(opacityTable, values[s]) * dt / this->P->UnitDistances[s] *
        this->UnitOf(0, values[0]);
      break;
    default:
      return;
  }
  ++this->Count;
}

//------------------------------------------------------------------------------
bool vtkTyndallProjection::Ray::ComponentPixel(double rgba[4]) const
{
  const vtkTyndallComponents& components = *this->C->Components;
  const int mode = this->P->Mode;
  const bool pick = mode == MAXIMUM || mode == MINIMUM || mode == SLICE;
  const auto clamp01 = [](double x) { return std::min(std::max(x, 0.0), 1.0); };
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  if (components.GetMode() == vtkTyndallComponents::Independent)
  {
    if (pick && this->Count == 0)
    {
      return false;
    }
    const double* w = components.GetWeights();
    double grey = 0.0;
    for (int i = 0; i < components.GetCount(); ++i)
    {
      if (pick)
      {
        int k;
        double f, c[3];
        const vtkTyndallTransferTable& table = *this->C->Tables[i];
        table.Locate(this->Values[i], k, f);
        const double a = table.OpacityAt(k, f);
        vtkTyndallTransferTable::RGBAt(table.Albedo, k, f, c);
        for (int j = 0; j < 3; ++j)
        {
          rgba[j] += w[i] * a * c[j];
        }
        rgba[3] += w[i] * a;
      }
      else if (mode == ADDITIVE)
      {
        grey += w[i] * this->Sums[i];
      }
      else if (this->Counts[i] > 0)
      {
        grey += w[i] * this->Sums[i] / this->Counts[i];
      }
    }
    if (!pick)
    {
      rgba[0] = rgba[1] = rgba[2] = grey;
      rgba[3] = 1.0;
    }
    for (int j = 0; j < 4; ++j)
    {
      rgba[j] = clamp01(rgba[j]);
    }
    return true;
  }
  if ((pick || mode == AVERAGE) && this->Count == 0)
  {
    return false;
  }
  if (!pick)
  {
    rgba[0] = rgba[1] = rgba[2] = clamp01(mode == AVERAGE ? this->Sum / this->Count : this->Sum);
    rgba[3] = 1.0;
    return true;
  }
  // The kept sample classified as the composite mode does.
  const int s = components.GetCount() - 1;
  double c[3];
  double a;
  if (components.GetMode() == vtkTyndallComponents::DependentLA)
  {
    int k;
    double f;
    this->C->Tables[0]->Locate(this->Values[0], k, f);
    vtkTyndallTransferTable::RGBAt(this->C->Tables[0]->Albedo, k, f, c);
    a = this->OpacityOf(1, this->Values[s]);
  }
  else
  {
    for (int j = 0; j < 3; ++j)
    {
      c[j] = clamp01(this->UnitOf(j, this->Values[j]));
    }
    a = this->OpacityOf(0, this->Values[s]);
  }
  for (int j = 0; j < 3; ++j)
  {
    rgba[j] = c[j] * a;
  }
  rgba[3] = a;
  return true;
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
        this->Table->OpacityOf(value) * dt / this->P->UnitDistances[0] * this->Table->Unit(value);
      break;
    default:
      return;
  }
  ++this->Count;
}

//------------------------------------------------------------------------------
bool vtkTyndallProjection::Ray::Pixel(double rgba[4]) const
{
  if (this->C && this->C->Components->Enabled())
  {
    return this->ComponentPixel(rgba);
  }
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
