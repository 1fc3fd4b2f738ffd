#include "vtkTyndallVolumeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(vtkTyndallVolumeRepresentation);

//------------------------------------------------------------------------------
vtkTyndallVolumeRepresentation::vtkTyndallVolumeRepresentation()
{
  this->VolumeMapper = this->TyndallMapper.Get();
  this->Actor->SetProperty(this->Medium);
}

//------------------------------------------------------------------------------
vtkTyndallVolumeRepresentation::~vtkTyndallVolumeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  // The medium shares ParaView's transfer functions: setting the same
  // objects again modifies nothing, so the maps are rebuilt only when
  // ParaView edits a function.
  vtkVolumeProperty* paraview = this->Property;
  this->Medium->SetColor(paraview->GetRGBTransferFunction(0));
  // Emission (EmissionScale > 0) is coloured by the same colour map.
  this->Medium->SetEmissionColor(paraview->GetRGBTransferFunction(0));
  this->Medium->SetScalarOpacity(paraview->GetScalarOpacity(0));
  this->Medium->SetScalarOpacityUnitDistance(paraview->GetScalarOpacityUnitDistance(0));
  this->Medium->SetInterpolationType(paraview->GetInterpolationType());
  this->Medium->SetIndependentComponents(paraview->GetIndependentComponents());
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetTransmittanceMethod(int method)
{
  this->TyndallMapper->SetTransmittanceMethod(method);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetNumberOfCoefficients(int count)
{
  this->TyndallMapper->SetNumberOfCoefficients(count);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetTransmittanceMapSize(int size)
{
  this->TyndallMapper->SetTransmittanceMapSize(size);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringModel(int model)
{
  this->Medium->SetScatteringModel(model);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetDensityScale(double scale)
{
  this->Medium->SetDensityScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringAnisotropy(double g)
{
  this->Medium->SetScatteringAnisotropy(g);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetLightScale(double scale)
{
  this->Medium->SetLightScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetAmbientIntensity(double intensity)
{
  this->Medium->SetAmbientIntensity(intensity);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetEmissionScale(double scale)
{
  this->Medium->SetEmissionScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringOctaves(int octaves)
{
  this->Medium->SetScatteringOctaves(octaves);
}

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper* vtkTyndallVolumeRepresentation::GetTyndallMapper()
{
  return this->TyndallMapper;
}

//------------------------------------------------------------------------------
vtkParticipatingMediumProperty* vtkTyndallVolumeRepresentation::GetMediumProperty()
{
  return this->Medium;
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TyndallMapper:\n";
  this->TyndallMapper->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Medium:\n";
  this->Medium->PrintSelf(os, indent.GetNextIndent());
}
