/**
 * @class   vtkTransmittanceMapReducer
 * @brief   adds the transmittance maps of the processes that share a picture
 *
 * When a picture is drawn by several processes, each holding a piece of the
 * medium (ParaView's pvbatch or pvserver under MPI, compositing the camera
 * rays with IceT), the light must cross every piece. Extinction maps make
 * that a sum: an ETM coefficient is an integral of the extinction along the
 * texel's light ray, so each process projects its own piece over the same
 * rays and range and the processes add their coefficients (one reduction of
 * coefficients x map size^2 floats per light) before shading.
 *
 * vtkTransmittanceVolumeMapper::SetMapReducer() takes one. This base class
 * is one process (GetNumberOfProcesses() 1, reductions that leave the values
 * as they are); a subclass talks to the other processes (Tyndall's ParaView
 * plugin has one over VTK's vtkMultiProcessController). With more than one
 * process, vtkTransmittanceVolumeMapper::PrepareDistributedMaps(), called
 * on every process once per frame before the window renders, in this order:
 *
 * 1. agrees on the world box of the whole medium (AllReduceMax() of the
 *    negated lower and the upper corners of its piece's box): every
 *    process fits the maps to that box;
 * 2. agrees whether any process must rebuild its maps, and on their size
 *    (AllReduceMax());
 * 3. if so, rebuilds its maps from its piece and adds everyone's
 *    (AllReduceSum()); a process with nothing to draw takes part with
 *    zeros.
 *
 * Plain ETM adds exactly. The other methods do not: adaptive ranges depend
 * on the whole ray's transmittance, the TFM methods project transmittance,
 * not extinction, and brute-force marching sees only the process's own
 * piece. With several processes they are drawn as ETM (the mapper warns
 * once); NONE stays NONE.
 *
 * Every process must draw the same Tyndall volumes in the same order (one
 * per view is what is tested), or the reductions do not pair up.
 *
 * @sa vtkTransmittanceVolumeMapper
 */

#ifndef vtkTransmittanceMapReducer_h
#define vtkTransmittanceMapReducer_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"

class TYNDALLRENDERING_EXPORT vtkTransmittanceMapReducer : public vtkObject
{
public:
  static vtkTransmittanceMapReducer* New();
  vtkTypeMacro(vtkTransmittanceMapReducer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The processes drawing the picture together; 1 here. The mapper reduces
   * nothing when it is 1.
   */
  virtual int GetNumberOfProcesses() { return 1; }

  /**
   * Replaces each of `count` values by its maximum over the processes
   * (collective: every process calls it with the same count). False on a
   * communication error. Here: true, values unchanged.
   */
  virtual bool AllReduceMax(double* values, int count);

  /**
   * Replaces each of `count` values by its sum over the processes
   * (collective). False on a communication error. Here: true, values
   * unchanged.
   */
  virtual bool AllReduceSum(float* values, vtkIdType count);

  ///@{
  /**
   * Seconds of the last map reduction (read back, AllReduceSum(), upload)
   * and its size in floats, as the mapper reports them; 0 before the first.
   */
  vtkGetMacro(LastReductionTime, double);
  vtkSetMacro(LastReductionTime, double);
  vtkGetMacro(LastReductionSize, vtkIdType);
  vtkSetMacro(LastReductionSize, vtkIdType);
  ///@}

protected:
  vtkTransmittanceMapReducer() = default;
  ~vtkTransmittanceMapReducer() override = default;

private:
  vtkTransmittanceMapReducer(const vtkTransmittanceMapReducer&) = delete;
  void operator=(const vtkTransmittanceMapReducer&) = delete;

  double LastReductionTime = 0.0;
  vtkIdType LastReductionSize = 0;
};

#endif
