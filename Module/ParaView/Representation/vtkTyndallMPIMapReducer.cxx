#include "vtkTyndallMPIMapReducer.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <vector>

vtkStandardNewMacro(vtkTyndallMPIMapReducer);

//------------------------------------------------------------------------------
int vtkTyndallMPIMapReducer::GetNumberOfProcesses()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetNumberOfProcesses() : 1;
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkTyndallMPIMapReducer::GetController()
{
  vtkMultiProcessController* global = vtkMultiProcessController::GetGlobalController();
  if (!this->Controller && global && global->GetNumberOfProcesses() > 1)
  {
    // Collective: the first reduction runs on every process.
    this->Controller.TakeReference(global->PartitionController(0, global->GetLocalProcessId()));
  }
  return this->Controller ? this->Controller.Get() : global;
}

//------------------------------------------------------------------------------
bool vtkTyndallMPIMapReducer::AllReduceMax(double* values, int count)
{
  vtkMultiProcessController* controller = this->GetController();
  if (!controller || !values || count < 0)
  {
    return false;
  }
  const std::vector<double> mine(values, values + count);
  return controller->AllReduce(mine.data(), values, count, vtkCommunicator::MAX_OP) != 0;
}

//------------------------------------------------------------------------------
bool vtkTyndallMPIMapReducer::AllReduceSum(float* values, vtkIdType count)
{
  vtkMultiProcessController* controller = this->GetController();
  if (!controller || (!values && count > 0) || count < 0)
  {
    return false;
  }
  const std::vector<float> mine(values, values + count);
  return controller->AllReduce(mine.data(), values, count, vtkCommunicator::SUM_OP) != 0;
}

//------------------------------------------------------------------------------
void vtkTyndallMPIMapReducer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller.Get() << "\n";
}
