#include "vtkTyndallIsosurfaces.h"

#include "vtkContourValues.h"
#include "vtkTyndallTransferTable.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// Whether the step from v0 to v1 crosses s: exactly one end below it.
bool Crosses(double v0, double v1, double s)
{
  return (v0 < s) != (v1 < s);
}

}

//------------------------------------------------------------------------------
bool vtkTyndallIsosurfaces::Read(
  vtkVolumeMapper* mapper, vtkVolumeProperty* property, std::string& error)
{
  this->On = mapper && property && mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND;
  this->Values.clear();
  if (!this->On)
  {
    return true;
  }
  vtkContourValues* values = property->GetIsoSurfaceValues();
  const int count = values->GetNumberOfContours();
  if (count > MaximumCount)
  {
    std::ostringstream message;
    message << "the property has " << count
            << " iso values; the isosurface blend mode draws at most " << MaximumCount;
    error = message.str();
    this->On = false;
    return false;
  }
  for (int i = 0; i < count; ++i)
  {
    const double s = values->GetValue(i);
    if (!std::isfinite(s))
    {
      std::ostringstream message;
      message << "iso value " << i << " of the property is " << s << ", not a finite number";
      error = message.str();
      this->On = false;
      this->Values.clear();
      return false;
    }
    this->Values.push_back(s);
  }
  std::sort(this->Values.begin(), this->Values.end());
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallIsosurfaces::Composite(const vtkTyndallTransferTable& table, double v0, double v1,
  double rgb[3], double& alpha, double& first) const
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  alpha = 0.0;
  first = 0.0;
  const int n = static_cast<int>(this->Values.size());
  bool crossed = false;
  // Rising values meet the surfaces in ascending order, falling ones in descending.
  for (int j = 0; j < n; ++j)
  {
    const double s = this->Values[v1 >= v0 ? j : n - 1 - j];
    if (!Crosses(v0, v1, s))
    {
      continue;
    }
    int k;
    double f;
    table.Locate(s, k, f);
    const double a = table.OpacityAt(k, f);
    if (!crossed && a > 0.0)
    {
      first = (s - v0) / (v1 - v0); // v0 != v1: one end lies below s
      crossed = true;
    }
    double color[3];
    vtkTyndallTransferTable::RGBAt(table.Albedo, k, f, color);
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] += (1.0 - alpha) * a * color[c];
    }
    alpha += (1.0 - alpha) * a;
  }
  return crossed;
}

//------------------------------------------------------------------------------
double vtkTyndallIsosurfaces::OpticalDepth(
  const vtkTyndallTransferTable& table, double v0, double v1) const
{
  double tau = 0.0;
  for (double s : this->Values)
  {
    if (Crosses(v0, v1, s))
    {
      tau -= std::log1p(-std::min(table.OpacityOf(s), MaximumOpacity));
    }
  }
  return tau;
}
