/**
 * @class   vtkTransmittanceDetailAdapter
 * @brief   the GPU side of a vtkTyndallDetailMedium: its grid's adapter, and the cosine waves
 *
 * Procedural detail multiplies a grid (vtkTyndallDetailMedium::GetGrid(),
 * itself drawn by its own adapter, e.g. a coloured particle cloud's) by a
 * sum of cosine waves. It adds to its grid's: the pre-classified shape as
 * a float 3-D texture (detailShapeTexture), the switch
 * TYNDALL_DETAIL_GROUPS (groups of four waves, 0: none), the waves as
 * uniforms (detailKx .. detailAmplitude) and its GLSL,
 * vtkTransmittanceDetailFS.glsl (the closed-form optical depth and free
 * flights of vtkTyndallDetailMedium, on the GPU). Its brute-force light
 * march walks the shape's cells: GetLightMarchIterations().
 *
 * Internal to Tyndall::Rendering.
 * @sa vtkTransmittanceMediumAdapter
 */

#ifndef vtkTransmittanceDetailAdapter_h
#define vtkTransmittanceDetailAdapter_h

#include "vtkTransmittanceMediumAdapter.h"

class vtkTyndallDetailMedium;

class TYNDALLRENDERING_EXPORT vtkTransmittanceDetailAdapter : public vtkTransmittanceMediumAdapter
{
public:
  /// Gives the adapter of a medium (vtkTransmittanceMediumAdapters::For()).
  using Lookup = const vtkTransmittanceMediumAdapter& (*)(const vtkTyndallMedium&);

  /// `lookup` gives the adapter of the grid under the detail.
  explicit vtkTransmittanceDetailAdapter(Lookup lookup)
    : GridLookup(lookup)
  {
  }

  const vtkTyndallGridMedium& GetGrid(const vtkTyndallMedium& medium) const override;
  vtkTransmittanceMediumTextures::Extras GetExtras(const vtkTyndallMedium& medium) const override;
  void DeclareSwitches(const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures, Variant& variant) const override;
  void DeclareColorSwitches(const vtkTyndallMedium& medium, Variant& variant) const override;
  void SetUniforms(vtkShaderProgram* program, const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures) const override;
  /// The cells of the closed form's walk along the ray (its wave loops are unrolled).
  double GetLightMarchIterations(const vtkTyndallMedium& medium, double gridMarch) const override;

private:
  // The adapter of the grid under the detail.
  const vtkTransmittanceMediumAdapter& GridAdapter(const vtkTyndallDetailMedium& detail) const;
  Lookup GridLookup;
};

#endif
