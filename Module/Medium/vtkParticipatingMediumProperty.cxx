#include "vtkParticipatingMediumProperty.h"

#include "vtkColorTransferFunction.h"
#include "vtkCosineNoise.h"
#include "vtkImageData.h"
#include "vtkImplicitFunction.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkParticipatingMediumProperty);
vtkCxxSetObjectMacro(vtkParticipatingMediumProperty, EmissionColor, vtkColorTransferFunction);
vtkCxxSetObjectMacro(vtkParticipatingMediumProperty, DetailNoise, vtkCosineNoise);

//------------------------------------------------------------------------------
vtkParticipatingMediumProperty::vtkParticipatingMediumProperty()
  : LightScale(4.0 * vtkMath::Pi())
{
}

//------------------------------------------------------------------------------
vtkParticipatingMediumProperty::~vtkParticipatingMediumProperty()
{
  this->SetEmissionColor(nullptr);
  this->SetEmissionArrayName(nullptr);
  this->SetDetailNoise(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkParticipatingMediumProperty::GetScatteringModelAsString()
{
  return this->ScatteringModel == EMISSION_ABSORPTION ? "EmissionAbsorption" : "SingleScattering";
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumProperty::SetExtinctionColor(double red, double green, double blue)
{
  const double in[3] = { red, green, blue };
  double color[3];
  for (int k = 0; k < 3; ++k)
  {
    color[k] = std::isnan(in[k]) ? 1.0 : std::min(std::max(in[k], 0.0), 1.0);
  }
  if (!std::equal(color, color + 3, this->ExtinctionColor))
  {
    std::copy(color, color + 3, this->ExtinctionColor);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumProperty::DeepCopy(vtkVolumeProperty* p)
{
  CopyVolumeProperty(p, this);
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(p);
  if (!medium)
  {
    return;
  }
  this->SetScatteringModel(medium->ScatteringModel);
  this->SetDensityScale(medium->DensityScale);
  this->SetScatteringAnisotropy(medium->GetScatteringAnisotropy());
  this->SetLightScale(medium->LightScale);
  this->SetAmbientIntensity(medium->AmbientIntensity);
  this->SetExtinctionColor(medium->ExtinctionColor);
  this->SetScatteringOctaves(medium->ScatteringOctaves);
  this->SetOctaveScattering(medium->OctaveScattering);
  this->SetOctaveExtinction(medium->OctaveExtinction);
  this->SetOctaveAnisotropy(medium->OctaveAnisotropy);
  this->SetOctaveBuildUp(medium->OctaveBuildUp);
  this->SetEmissionScale(medium->EmissionScale);
  this->SetEmissionColor(medium->EmissionColor);
  this->SetEmissionArrayName(medium->EmissionArrayName);
  this->SetBlackbody(medium->Blackbody);
  this->SetTemperatureScale(medium->TemperatureScale);
  this->SetSceneShadows(medium->SceneShadows);
  this->SetSceneCompositing(medium->SceneCompositing);
  this->SetDetailNoise(medium->DetailNoise);
  this->SetDetailFilterWidth(medium->DetailFilterWidth);
}

//------------------------------------------------------------------------------
vtkVolumeProperty* vtkParticipatingMediumProperty::GetPlainCopy()
{
  if (!this->PlainCopy || this->GetMTime() > this->PlainCopyTime)
  {
    this->PlainCopy = vtkSmartPointer<vtkVolumeProperty>::New();
    CopyVolumeProperty(this, this->PlainCopy);
    // (After the copy: reading a component's missing function makes VTK
    // create it, which modifies this property.)
    this->PlainCopyTime = this->GetMTime();
  }
  return this->PlainCopy;
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumProperty::CopyVolumeProperty(
  vtkVolumeProperty* from, vtkVolumeProperty* to)
{
  if (!from || !to || from == to)
  {
    return;
  }
  to->vtkVolumeProperty::DeepCopy(from);
  // Each 2-D function copied (VTK 9.1's SetTransferFunction2D() cannot
  // clear one: it reads the function given without checking for null, so a
  // function `to` has where `from` has none stays, unused in TF_1D), then
  // the mode (setting a 2-D function sets TF_2D).
  for (int c = 0; c < VTK_MAX_VRCOMP; ++c)
  {
    if (vtkImageData* function = from->GetTransferFunction2D(c))
    {
      vtkNew<vtkImageData> copy;
      copy->DeepCopy(function);
      to->SetTransferFunction2D(c, copy);
    }
  }
  to->SetTransferFunctionMode(from->GetTransferFunctionMode());
  to->SetSliceFunction(from->GetSliceFunction());
  for (const int label : from->GetLabelMapLabels())
  {
    if (vtkColorTransferFunction* color = from->GetLabelColor(label))
    {
      vtkNew<vtkColorTransferFunction> copy;
      copy->DeepCopy(color);
      to->SetLabelColor(label, copy);
    }
    for (const bool gradient : { false, true })
    {
      vtkPiecewiseFunction* opacity =
        gradient ? from->GetLabelGradientOpacity(label) : from->GetLabelScalarOpacity(label);
      if (opacity)
      {
        vtkNew<vtkPiecewiseFunction> copy;
        copy->DeepCopy(opacity);
        if (gradient)
        {
          to->SetLabelGradientOpacity(label, copy);
        }
        else
        {
          to->SetLabelScalarOpacity(label, copy);
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkParticipatingMediumProperty::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->EmissionColor)
  {
    mtime = std::max(mtime, this->EmissionColor->GetMTime());
  }
  if (this->DetailNoise)
  {
    mtime = std::max(mtime, this->DetailNoise->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScatteringModel: " << this->GetScatteringModelAsString() << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "ScatteringAnisotropy: " << this->GetScatteringAnisotropy() << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "AmbientIntensity: " << this->AmbientIntensity << "\n";
  os << indent << "ExtinctionColor: (" << this->ExtinctionColor[0] << ", "
     << this->ExtinctionColor[1] << ", " << this->ExtinctionColor[2] << ")\n";
  os << indent << "ScatteringOctaves: " << this->ScatteringOctaves << "\n";
  os << indent << "OctaveScattering: " << this->OctaveScattering << "\n";
  os << indent << "OctaveExtinction: " << this->OctaveExtinction << "\n";
  os << indent << "OctaveAnisotropy: " << this->OctaveAnisotropy << "\n";
  os << indent << "OctaveBuildUp: " << this->OctaveBuildUp << "\n";
  os << indent << "EmissionScale: " << this->EmissionScale << "\n";
  os << indent << "EmissionColor: " << this->EmissionColor << "\n";
  os << indent
     << "EmissionArrayName: " << (this->EmissionArrayName ? this->EmissionArrayName : "(none)")
     << "\n";
  os << indent << "Blackbody: " << this->Blackbody << "\n";
  os << indent << "TemperatureScale: " << this->TemperatureScale << "\n";
  os << indent << "SceneShadows: " << (this->SceneShadows ? "On" : "Off") << "\n";
  os << indent << "SceneCompositing: " << (this->SceneCompositing ? "On" : "Off") << "\n";
  os << indent << "DetailNoise: " << this->DetailNoise << "\n";
  os << indent << "DetailFilterWidth: " << this->DetailFilterWidth << "\n";
}

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
//------------------------------------------------------------------------------
void vtkParticipatingMediumProperty::SetScatteringAnisotropy(float g)
{
  // NaN passes through, as it does VTK's clamp macros; the mapper refuses it.
  this->Superclass::SetScatteringAnisotropy(g < -0.99f ? -0.99f : (g > 0.99f ? 0.99f : g));
}
#endif
