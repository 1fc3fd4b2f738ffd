#include "vtkParticipatingMediumMapper.h"

#include "vtkImageData.h"

//------------------------------------------------------------------------------
vtkParticipatingMediumMapper::vtkParticipatingMediumMapper() = default;

//------------------------------------------------------------------------------
vtkParticipatingMediumMapper::~vtkParticipatingMediumMapper() = default;

//------------------------------------------------------------------------------
vtkImageData* vtkParticipatingMediumMapper::GetMediumImage()
{
  return vtkImageData::SafeDownCast(this->GetDataSetInput());
}

//------------------------------------------------------------------------------
void vtkParticipatingMediumMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
