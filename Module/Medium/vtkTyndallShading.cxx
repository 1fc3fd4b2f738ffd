#include "vtkTyndallShading.h"

#include "vtkMath.h"
#include "vtkParticipatingMediumMapper.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallVolumeSettings.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
void vtkTyndallShading::Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  // Every blend mode but the projections is shaded: the composite medium,
  // the isosurfaces, a slice without a plane (drawn as composite, with a
  // warning), and as VTK 9.1 shades it the slice through a plane of one
  // component (unshadowed: a projection has no maps; not a medium, a
  // vtkParticipatingMediumProperty's slice too: ParaView's Volume's picture).
  vtkTyndallProjection projection;
  projection.Read(mapper, property);
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  const bool shadedProjection = vtkTyndallVolumeSettings::SliceReadsGradient(mapper, property);
  this->Additive = medium != nullptr;
  // A medium's isosurfaces, and a medium with procedural detail (whose
  // surfaces are the waves', not the grid's), are lit by its scattering
  // alone (a projection draws no detail).
  const bool isosurfaces = mapper && mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND;
  const bool detail = medium && medium->GetDetailNoise() && !projection.Enabled();
  this->On = property && property->GetShade(0) && (!projection.Enabled() || shadedProjection) &&
    !(medium && (isosurfaces || detail));
  // The isosurfaces are surfaces: no volumetric scattering blended in (nor
  // into a medium's scattering).
  auto* tyndall = vtkParticipatingMediumMapper::SafeDownCast(mapper);
  this->Blending =
    tyndall && !this->Additive && !isosurfaces ? tyndall->GetVolumetricScatteringBlending() : 0.0;
  for (int c = 0; c < 4 && property; ++c)
  {
    this->Coefficients[c][0] = property->GetAmbient(c);
    this->Coefficients[c][1] = property->GetDiffuse(c);
    this->Coefficients[c][2] = property->GetSpecular(c);
    this->Coefficients[c][3] = property->GetSpecularPower(c);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::Start(const double color[3], Sums& sums, int c) const
{
  for (int i = 0; i < 3; ++i)
  {
    sums.Surface[i] = sums.Volume[i] = this->Coefficients[c][0] * color[i];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::AddLight(const double n[3], const double l[3], const double v[3],
  const double color[3], const double E[3], const double T[3], Sums& sums, int c) const
{
  double h[3] = { l[0] + v[0], l[1] + v[1], l[2] + v[2] };
  const double length = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  for (int i = 0; i < 3; ++i)
  {
    h[i] = length > 0.0 ? h[i] / length : 0.0;
  }
  const double* k = this->Coefficients[c];
  const double nl = std::abs(n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
  const double nh = std::abs(n[0] * h[0] + n[1] * h[1] + n[2] * h[2]);
  const double specular = k[2] * std::pow(nh, k[3]);
  for (int i = 0; i < 3; ++i)
  {
    sums.Surface[i] += T[i] * E[i] * (k[1] * nl * color[i] + specular);
    sums.Volume[i] += T[i] * E[i] * k[1] * color[i];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallShading::AddSkyMean(
  const double n[3], const double color[3], const double m[3], Sums& sums, int c) const
{
  const double kd = this->Coefficients[c][1];
  const bool normal = n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
  for (int i = 0; i < 3; ++i)
  {
    sums.Surface[i] += normal ? 2.0 * vtkMath::Pi() * kd * m[i] * color[i] : 0.0;
    sums.Volume[i] += 4.0 * vtkMath::Pi() * kd * m[i] * color[i];
  }
}

//------------------------------------------------------------------------------
double vtkTyndallShading::BlendWeight(double gradient, double sigma, double range, double h) const
{
  const double G = range > 0.0 ? 2.0 * gradient / range : 0.0;
  return Weight(this->Blending, G, 1.0 - std::exp(-sigma * h));
}

//------------------------------------------------------------------------------
double vtkTyndallShading::Weight(double B, double G, double a)
{
  if (!(B > 0.0))
  {
    return 0.0;
  }
  // VTK 9.2 passes B / 2 to its shader and picks the branch by B.
  const double e = std::exp(-B * G * a);
  return B < 1.0 ? B * e : (2.0 - B) * e + B - 1.0;
}

//------------------------------------------------------------------------------
void vtkTyndallShading::Finish(const Sums& sums, double k, double rgb[3])
{
  for (int c = 0; c < 3; ++c)
  {
    const double v = (1.0 - k) * sums.Surface[c] + k * sums.Volume[c];
    rgb[c] = std::min(std::max(v, 0.0), 1.0);
  }
}
