#include "vtkParticipatingMediumMapper.h"

#include "vtkImageData.h"

//------------------------------------------------------------------------------
vtkParticipatingMediumMapper::vtkParticipatingMediumMapper() = default;

//------------------------------------------------------------------------------
vtkParticipatingMediumMapper::~vtkParticipatingMediumMapper()
{
  this->SetMaskInput(nullptr);
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumMapper::SetMaskInput(vtkImageData* mask)
{
  vtkSetObjectBodyMacro(MaskInput, vtkImageData, mask);
}

//------------------------------------------------------------------------------
vtkImageData* vtkParticipatingMediumMapper::GetMediumImage()
{
  return vtkImageData::SafeDownCast(this->GetDataSetInput());
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaskInput: " << this->MaskInput << "\n";
  os << indent << "MaskType: " << (this->MaskType == BinaryMaskType ? "Binary" : "LabelMap")
     << "\n";
  os << indent << "MaskBlendFactor: " << this->MaskBlendFactor << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->VolumetricScatteringBlending << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "SkyLight: " << (this->SkyLight ? "On" : "Off") << "\n";
  os << indent << "SkyLightDirections: " << this->SkyLightDirections << "\n";
}
