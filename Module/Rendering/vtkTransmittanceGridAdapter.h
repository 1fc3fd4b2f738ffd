/**
 * @class   vtkTransmittanceGridAdapter
 * @brief   the GPU side of a vtkTyndallGridMedium
 *
 * Uploads the grid's scalars, validity (missing data), transfer table,
 * majorant blocks and emission array (vtkTransmittanceMediumTextures);
 * declares the switches TYNDALL_MISSING_DATA, TYNDALL_CLIP, TYNDALL_COMPONENTS,
 * TYNDALL_CHROMATIC, TYNDALL_EMISSION and TYNDALL_EMISSION_ARRAY (and turns
 * TYNDALL_SKIP_EMPTY off for an emission array, which glows in blocks
 * without extinction); sets their uniforms. Its GLSL is the common
 * shader's grid lookup (vtkTransmittanceCommonFS.glsl: tyndallExtinction()).
 *
 * Internal to Tyndall::Rendering.
 * @sa vtkTransmittanceMediumAdapter
 */

#ifndef vtkTransmittanceGridAdapter_h
#define vtkTransmittanceGridAdapter_h

#include "vtkTransmittanceMediumAdapter.h"

class TYNDALLRENDERING_EXPORT vtkTransmittanceGridAdapter : public vtkTransmittanceMediumAdapter
{
public:
  const vtkTyndallGridMedium& GetGrid(const vtkTyndallMedium& medium) const override;
  void DeclareSwitches(const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures, Variant& variant) const override;
  void DeclareColorSwitches(const vtkTyndallMedium& medium, Variant& variant) const override;
  void SetUniforms(vtkShaderProgram* program, const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures) const override;
  /// None for a plain grid.
  vtkTransmittanceMediumTextures::Extras GetExtras(const vtkTyndallMedium& medium) const override;

private:
  // Several components' uniforms (vtkTyndallComponents; tyndallComponentMedium()).
  void SetComponentUniforms(vtkShaderProgram* program, const vtkTyndallGridMedium& grid,
    const vtkTransmittanceMediumTextures& textures) const;
};

#endif
