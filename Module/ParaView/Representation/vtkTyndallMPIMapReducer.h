/**
 * @class   vtkTyndallMPIMapReducer
 * @brief   adds Tyndall's transmittance maps over VTK's global controller
 *
 * The vtkTransmittanceMapReducer of Tyndall's ParaView plugin: its
 * processes are those of vtkMultiProcessController::GetGlobalController()
 * (the ranks of pvbatch or pvserver under MPI), its reductions AllReduce()
 * with MAX_OP and SUM_OP over a controller of its own, partitioned from the
 * global one at the first reduction (collective), so that its messages never
 * mix with ParaView's.
 * vtkTyndallVolumeRepresentation gives one to its mapper when there is more
 * than one process.
 *
 * @sa vtkTransmittanceMapReducer vtkTyndallVolumeRepresentation
 */

#ifndef vtkTyndallMPIMapReducer_h
#define vtkTyndallMPIMapReducer_h

#include "TyndallParaViewRepresentationModule.h" // For export macro
#include "vtkSmartPointer.h"                     // For vtkSmartPointer
#include "vtkTransmittanceMapReducer.h"

class vtkMultiProcessController;

class TYNDALLPARAVIEWREPRESENTATION_EXPORT vtkTyndallMPIMapReducer
  : public vtkTransmittanceMapReducer
{
public:
  static vtkTyndallMPIMapReducer* New();
  vtkTypeMacro(vtkTyndallMPIMapReducer, vtkTransmittanceMapReducer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The global controller's number of processes (1 without one).
  int GetNumberOfProcesses() override;

  /// AllReduce() with MAX_OP (collective); false without a global controller.
  bool AllReduceMax(double* values, int count) override;

  /// AllReduce() with SUM_OP (collective); false without a global controller.
  bool AllReduceSum(float* values, vtkIdType count) override;

protected:
  vtkTyndallMPIMapReducer() = default;
  ~vtkTyndallMPIMapReducer() override = default;

private:
  vtkTyndallMPIMapReducer(const vtkTyndallMPIMapReducer&) = delete;
  void operator=(const vtkTyndallMPIMapReducer&) = delete;

  vtkMultiProcessController* GetController();
  vtkSmartPointer<vtkMultiProcessController> Controller;
};

#endif
