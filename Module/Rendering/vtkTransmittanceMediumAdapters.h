/**
 * @class   vtkTransmittanceMediumAdapters
 * @brief   the GPU adapter of each kind of medium
 *
 * For() is the one place on the GPU side that picks by the kind of a
 * vtkTyndallMedium: vtkTransmittanceGridAdapter (vtkTyndallGridMedium),
 * vtkTransmittanceParticleAdapter (vtkTyndallParticleMedium) and
 * vtkTransmittanceDetailAdapter (vtkTyndallDetailMedium, which asks For()
 * for the adapter of its grid). A new kind of medium adds its adapter and
 * one line here (Documentation/architecture.md, "Where new things go").
 *
 * Internal to Tyndall::Rendering.
 * @sa vtkTransmittanceMediumAdapter
 */

#ifndef vtkTransmittanceMediumAdapters_h
#define vtkTransmittanceMediumAdapters_h

#include "TyndallRenderingModule.h" // For export macro

class vtkTransmittanceMediumAdapter;
class vtkTyndallMedium;

class TYNDALLRENDERING_EXPORT vtkTransmittanceMediumAdapters
{
public:
  /// The adapter of `medium`'s kind (adapters hold no state: one of each).
  static const vtkTransmittanceMediumAdapter& For(const vtkTyndallMedium& medium);
};

#endif
