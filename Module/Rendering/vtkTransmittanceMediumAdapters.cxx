#include "vtkTransmittanceMediumAdapters.h"

#include "vtkTransmittanceDetailAdapter.h"
#include "vtkTransmittanceGridAdapter.h"
#include "vtkTransmittanceParticleAdapter.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallParticleMedium.h"

//------------------------------------------------------------------------------
const vtkTransmittanceMediumAdapter& vtkTransmittanceMediumAdapters::For(
  const vtkTyndallMedium& medium)
{
  static const vtkTransmittanceGridAdapter grid;
  static const vtkTransmittanceParticleAdapter particles;
  // The detail asks this function for the adapter of the grid it multiplies.
  static const vtkTransmittanceDetailAdapter detail(&vtkTransmittanceMediumAdapters::For);
  // Most derived first: a particle medium is a grid medium, and every
  // medium of the scene reader that is neither detail nor particles is a grid.
  if (dynamic_cast<const vtkTyndallDetailMedium*>(&medium))
  {
    return detail;
  }
  if (dynamic_cast<const vtkTyndallParticleMedium*>(&medium))
  {
    return particles;
  }
  return grid;
}
