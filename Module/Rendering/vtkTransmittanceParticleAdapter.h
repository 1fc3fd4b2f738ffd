/**
 * @class   vtkTransmittanceParticleAdapter
 * @brief   the GPU side of a vtkTyndallParticleMedium
 *
 * A particle cloud is drawn as its grid (vtkTransmittanceGridAdapter), and
 * when coloured, with its scattering density as a second 3-D texture
 * (TYNDALL_PARTICLE_COLORS, uniform scatteringTexture) that gives the
 * camera rays its albedo. Its splats into the extinction maps are the
 * frame's (vtkTransmittanceFrame::Splats, vtkTransmittanceSplatPass).
 *
 * Internal to Tyndall::Rendering.
 * @sa vtkTransmittanceMediumAdapter
 */

#ifndef vtkTransmittanceParticleAdapter_h
#define vtkTransmittanceParticleAdapter_h

#include "vtkTransmittanceGridAdapter.h"

class TYNDALLRENDERING_EXPORT vtkTransmittanceParticleAdapter : public vtkTransmittanceGridAdapter
{
public:
  void DeclareColorSwitches(const vtkTyndallMedium& medium, Variant& variant) const override;
  void SetUniforms(vtkShaderProgram* program, const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures) const override;
  /// The cloud when its mapper splats it (vtkTyndallParticleMedium::GetSplatParticles()).
  const vtkTyndallParticleMedium* GetSplatted(const vtkTyndallMedium& medium) const override;
  /// The scattering density of a coloured cloud.
  vtkTransmittanceMediumTextures::Extras GetExtras(const vtkTyndallMedium& medium) const override;
};

#endif
