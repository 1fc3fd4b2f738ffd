#include "vtkTransmittanceMediumAdapter.h"

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumAdapter::Upload(vtkOpenGLRenderWindow* window,
  const vtkTyndallMedium& medium, vtkTransmittanceMediumTextures& textures,
  vtkObject* reporter) const
{
  return textures.Update(window, this->GetGrid(medium), this->GetExtras(medium), reporter);
}
