#include "vtkTyndallShading.h"

#include "vtkParticipatingMediumProperty.h"
#include "vtkTyndallProjection.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
void vtkTyndallShading::Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  // Every blend mode but the projections (the slice through a plane
  // included) is shaded: the composite medium, the isosurfaces, a slice
  // without a plane (drawn as composite, with a warning).
  vtkTyndallProjection projection;
  projection.Read(mapper, property);
  this->On = property && !vtkParticipatingMediumProperty::SafeDownCast(property) &&
    property->GetShade(0) && !projection.Enabled();
  if (property)
  {
    this->Ambient = property->GetAmbient(0);
    this->Diffuse = property->GetDiffuse(0);
    this->Specular = property->GetSpecular(0);
    this->SpecularPower = property->GetSpecularPower(0);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::Start(const double color[3], double rgb[3]) const
{
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = this->Ambient * color[c];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::AddLight(const double n[3], const double l[3], const double v[3],
  const double color[3], const double E[3], const double T[3], double rgb[3]) const
{
  double h[3] = { l[0] + v[0], l[1] + v[1], l[2] + v[2] };
  const double length = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (int c = 0; c < 3; ++c)
  {
    h[c] = length > 0.0 ? h[c] / length : 0.0;
  }
  const double nl = std::abs(n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
  const double nh = std::abs(n[0] * h[0] + n[1] * h[1] + n[2] * h[2]);
  const double specular = this->Specular * std::pow(nh, this->SpecularPower);
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] += T[c] * E[c] * (this->Diffuse * nl * color[c] + specular);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::Finish(double rgb[3])
{
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = std::min(std::max(rgb[c], 0.0), 1.0);
  }
}
