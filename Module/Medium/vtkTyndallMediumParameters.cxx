#include "vtkTyndallMediumParameters.h"

#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkParticipatingMediumProperty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace
{
// The property's numbers must be finite: VTK's clamp macros let NaN through,
// which would draw a NaN picture on the GPU (and a different one on the CPU).
bool FiniteSettings(vtkParticipatingMediumProperty* p, vtkObject* reporter)
{
  const double* c = p->GetExtinctionColor();
  const std::pair<const char*, double> settings[] = { { "DensityScale", p->GetDensityScale() },
    { "ScatteringAnisotropy", p->GetScatteringAnisotropy() }, { "LightScale", p->GetLightScale() },
    { "AmbientIntensity", p->GetAmbientIntensity() }, { "ExtinctionColor (red)", c[0] },
    { "ExtinctionColor (green)", c[1] }, { "ExtinctionColor (blue)", c[2] },
    { "OctaveScattering", p->GetOctaveScattering() },
    { "OctaveExtinction", p->GetOctaveExtinction() },
    { "OctaveAnisotropy", p->GetOctaveAnisotropy() }, { "OctaveBuildUp", p->GetOctaveBuildUp() },
    { "EmissionScale", p->GetEmissionScale() }, { "TemperatureScale", p->GetTemperatureScale() },
    { "ScalarOpacityUnitDistance", p->GetScalarOpacityUnitDistance(0) } };
  for (const auto& s : settings)
  {
    if (!std::isfinite(s.second))
    {
      vtkErrorWithObjectMacro(reporter, << "The medium's " << s.first << " is " << s.second
                                        << ", not a finite number: nothing is drawn.");
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkTyndallMediumParameters::Read(vtkVolumeProperty* property, bool emits, vtkObject* reporter)
{
  vtkNew<vtkParticipatingMediumProperty> defaults;
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  vtkParticipatingMediumProperty* source = medium ? medium : defaults.Get();
  if (!medium && property)
  {
    // VTK's meaning: shade off is VTK's unlit emission-absorption picture.
    defaults->SetScatteringModel(property->GetShade(0)
        ? vtkParticipatingMediumProperty::SINGLE_SCATTERING
        : vtkParticipatingMediumProperty::EMISSION_ABSORPTION);
  }
  if (!FiniteSettings(source, reporter))
  {
    return false;
  }
  this->ScatteringModel = source->GetScatteringModel();
  // The densest channel's extinction scales the density; the channels are
  // relative to it.
  const double* color = source->GetExtinctionColor();
  const double densest = std::max(std::max(color[0], color[1]), color[2]);
  this->DensityScale = source->GetDensityScale() * densest;
  for (int k = 0; k < 3; ++k)
  {
    this->ExtinctionColor[k] = densest > 0.0 ? color[k] / densest : 1.0;
  }
  if (densest > 0.0)
  {
    // Exactly 1 for the densest channel, whatever the division rounds to.
    this->ExtinctionColor[std::max_element(color, color + 3) - color] = 1.0;
  }
  this->ScatteringAnisotropy = source->GetScatteringAnisotropy();
  this->LightScale = source->GetLightScale();
  this->AmbientIntensity = source->GetAmbientIntensity();
  this->ScatteringOctaves = this->GetSingleScattering() ? source->GetScatteringOctaves() : 1;
  this->OctaveFactors[0] = source->GetOctaveScattering();
  this->OctaveFactors[1] = source->GetOctaveExtinction();
  this->OctaveFactors[2] = source->GetOctaveAnisotropy();
  this->OctaveFactors[3] = source->GetOctaveBuildUp();
  this->EmissionScale = source->GetEmissionScale();
  this->HasEmission = this->GetSingleScattering() && emits && this->EmissionScale > 0.0;
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallMediumParameters::GetFaintestChannel() const
{
  double faintest = 1.0;
  for (double e : this->ExtinctionColor)
  {
    if (e > 0.0)
    {
      faintest = std::min(faintest, e);
    }
  }
  return faintest;
}

//------------------------------------------------------------------------------
double vtkTyndallMediumParameters::OctaveExponent() const
{
  return this->ScatteringOctaves > 1 ? std::pow(this->OctaveFactors[1], this->ScatteringOctaves - 1)
                                     : 1.0;
}

//------------------------------------------------------------------------------
double vtkTyndallMediumParameters::OctaveWeight() const
{
  return this->ScatteringOctaves > 1
    ? std::pow(std::max(1.0, this->OctaveFactors[0]), this->ScatteringOctaves - 1)
    : 1.0;
}

//------------------------------------------------------------------------------
double vtkTyndallMediumParameters::LightTransmittanceLimit(double threshold, bool channelMaps) const
{
  const double exponent = this->OctaveExponent() * (channelMaps ? 1.0 : this->GetFaintestChannel());
  const double faintest = threshold / this->OctaveWeight();
  if (exponent == 1.0)
  {
    return faintest;
  }
  return exponent > 0.0 ? std::pow(faintest, 1.0 / exponent) : 0.0;
}

//------------------------------------------------------------------------------
double vtkTyndallMediumParameters::LightDepthLimit(double threshold) const
{
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double depth = threshold > 0.0 ? -std::log(threshold) : infinity;
  if (this->ScatteringOctaves > 1)
  {
    const double exponent = this->OctaveExponent();
    depth = exponent > 0.0 && threshold > 0.0 ? (depth + std::log(this->OctaveWeight())) / exponent
                                              : infinity;
  }
  return depth / this->GetFaintestChannel();
}

//------------------------------------------------------------------------------
bool vtkTyndallMediumParameters::SameLighting(const vtkTyndallMediumParameters& other) const
{
  const vtkTyndallMediumParameters& a = *this;
  const vtkTyndallMediumParameters& b = other;
  if (a.ScatteringModel != b.ScatteringModel)
  {
    return false;
  }
  // Emission-absorption: the colour is the emission, no light: nothing more to agree on.
  return !a.GetSingleScattering() ||
    (a.HasEmission == b.HasEmission && (!a.HasEmission || a.EmissionScale == b.EmissionScale) &&
      a.ScatteringAnisotropy == b.ScatteringAnisotropy && a.LightScale == b.LightScale &&
      a.AmbientIntensity == b.AmbientIntensity && a.ScatteringOctaves == b.ScatteringOctaves &&
      (a.ScatteringOctaves == 1 ||
        std::equal(a.OctaveFactors, a.OctaveFactors + 4, b.OctaveFactors)));
}
