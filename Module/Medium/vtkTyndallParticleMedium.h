/**
 * @class   vtkTyndallParticleMedium
 * @brief   a particle cloud as a medium: its particles' exact sum, on the grid the GPU samples
 *
 * The medium of a volume drawn by a particle mapper
 * (vtkParticipatingMediumMapper::DrawsParticles(), vtkTransmittanceParticleMapper):
 * a vtkTyndallGridMedium whose scalars are the particles' grid (the
 * mapper's medium image, vtkTyndallParticles::Voxelize(); the GPU uploads
 * and samples it like any grid) and whose queries (vtkTyndallMedium) are the
 * particles' exact sum at the point, never the grid: the CPU integrators see
 * the particles themselves. Placement, clipping, the transfer functions and
 * the parameters are the grid's, read by its rules; the extinction is the
 * density itself (the scalar opacity is not used), so that particles add;
 * with colours the albedo is the particles' own (weighted by their
 * extinctions), not the colour transfer function's.
 *
 * Internal to Tyndall::Medium; not wrapped.
 *
 * @sa vtkTyndallParticles vtkTransmittanceParticleMapper
 */

#ifndef vtkTyndallParticleMedium_h
#define vtkTyndallParticleMedium_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkFloatArray.h"       // For vtkSmartPointer<vtkFloatArray>
#include "vtkSmartPointer.h"     // For vtkSmartPointer
#include "vtkTyndallGridMedium.h"

class vtkTyndallParticles;

class TYNDALLMEDIUM_EXPORT vtkTyndallParticleMedium : public vtkTyndallGridMedium
{
public:
  vtkTyndallParticleMedium();
  ~vtkTyndallParticleMedium() override;

  const char* GetKind() const override { return "particles"; }

  /// The particles (null before a successful Update()).
  const vtkTyndallParticles* GetParticles() const { return this->Particles; }

  /// Whether the extinction maps add the particles in closed form (splatting).
  bool GetSplatParticles() const { return this->Splat; }

  /**
   * A coloured cloud's scattering density (density times albedo, three
   * components per sample, beside the scalars: the GPU's albedo is its
   * interpolation over the scalars'); null without colours.
   */
  vtkFloatArray* GetScatteringGrid() const { return this->Scattering; }

  /// The particles' exact sum at the field index point p.
  double FieldScalar(const double p[3]) const override;

  /// The density scale times a bound of the particles' sum.
  double GetMajorant() const override;

protected:
  vtkDataSet* ReadInput(vtkVolume* volume, vtkObject* reporter) override;
  bool GetLinearExtinction() const override { return true; }
  bool FieldAlbedo(const double p[3], double color[3]) const override;

private:
  // The data point of the field index point p.
  void ToData(const double p[3], double x[3]) const;

  const vtkTyndallParticles* Particles = nullptr;
  bool Splat = false;
  vtkSmartPointer<vtkFloatArray> Scattering;
};

#endif
