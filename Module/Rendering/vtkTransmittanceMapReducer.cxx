#include "vtkTransmittanceMapReducer.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkTransmittanceMapReducer);

//------------------------------------------------------------------------------
bool vtkTransmittanceMapReducer::AllReduceMax(double*, int)
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapReducer::AllReduceSum(float*, vtkIdType)
{
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMapReducer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfProcesses: " << this->GetNumberOfProcesses() << "\n";
  os << indent << "LastReductionTime: " << this->LastReductionTime << "\n";
  os << indent << "LastReductionSize: " << this->LastReductionSize << "\n";
}
