#include "vtkTransmittanceParticleAdapter.h"

#include "vtkFloatArray.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTyndallParticleMedium.h"

namespace
{
// For() gives this adapter particle media only.
const vtkTyndallParticleMedium& Particles(const vtkTyndallMedium& medium)
{
  return static_cast<const vtkTyndallParticleMedium&>(medium);
}
}

//------------------------------------------------------------------------------
vtkTransmittanceMediumTextures::Extras vtkTransmittanceParticleAdapter::GetExtras(
  const vtkTyndallMedium& medium) const
{
  vtkTransmittanceMediumTextures::Extras extras;
  if (vtkFloatArray* scattering = Particles(medium).GetScatteringGrid())
  {
    extras.Scattering = scattering->GetPointer(0);
  }
  return extras;
}

//------------------------------------------------------------------------------
void vtkTransmittanceParticleAdapter::DeclareColorSwitches(
  const vtkTyndallMedium& medium, Variant& variant) const
{
  this->vtkTransmittanceGridAdapter::DeclareColorSwitches(medium, variant);
  variant.ParticleColors = Particles(medium).GetScatteringGrid() != nullptr;
}

//------------------------------------------------------------------------------
void vtkTransmittanceParticleAdapter::SetUniforms(vtkShaderProgram* program,
  const vtkTyndallMedium& medium, const vtkTransmittanceMediumTextures& textures) const
{
  this->vtkTransmittanceGridAdapter::SetUniforms(program, medium, textures);
  if (vtkTextureObject* scattering = textures.GetScatteringTexture())
  {
    // Declared only by the camera rays' particle-colour variant.
    program->SetUniformi("scatteringTexture", scattering->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
const vtkTyndallParticleMedium* vtkTransmittanceParticleAdapter::GetSplatted(
  const vtkTyndallMedium& medium) const
{
  const vtkTyndallParticleMedium& particles = Particles(medium);
  // Drawn as isosurfaces, the cloud's light meets the surfaces, not its density.
  return particles.GetSplatParticles() && !particles.GetIsosurfaces().Enabled() ? &particles
                                                                                : nullptr;
}
