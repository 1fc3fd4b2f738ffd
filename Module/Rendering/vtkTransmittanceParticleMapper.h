/**
 * @class   vtkTransmittanceParticleMapper
 * @brief   renders a particle cloud as a participating medium, splatted into the light maps
 *
 * vtkTransmittanceParticleMapper is a vtkTransmittanceVolumeMapper whose
 * input is a particle cloud: a vtkPolyData of points with the point-data
 * arrays "radius" and "density" (one value per point), as
 * vtkParticleFileReader reads them from CSV, text or VTK files. Each
 * particle is the smooth sphere of vtkParticleKernel, extinction
 * `density (1 - r^2/radius^2)^2` per world unit within its radius (times the
 * property's DensityScale); the medium is their sum. Put it in a vtkVolume
 * with a vtkParticipatingMediumProperty like an image: the volume's matrix
 * places the particles, and every other setting of the medium (albedo from
 * the colour transfer function of the summed density, anisotropy, light
 * scale, ambient, octaves, emission colour) is read as for an image. The
 * scalar opacity function is not used: a particle medium's extinction is its
 * density, so that particles add. With a three-component point-data array
 * "color" (components in [0, 1]), each particle's colour is its albedo
 * instead of the colour transfer function's, and where particles overlap
 * the albedo is their colours' mean weighted by their extinctions (their
 * scattering adds like their extinction); the GPU samples it from a grid of
 * the scattering density beside the density's, the CPU renderers exactly,
 * also where it is drawn as one medium with the volumes it overlaps
 * (SceneCompositing).
 *
 * How it is rendered (Documentation/rendering-model.md, "Particles"):
 *
 * - The extinction maps (TransmittanceMethod ETM, this mapper's default)
 *   take each particle's
 *   exact share in closed form: the particles are drawn into every light's
 *   map as screen-aligned squares over their footprints with additive
 *   blending, and each covered texel adds the cosine coefficients of the
 *   particle's extinction along its light ray (vtkParticleKernel::
 *   AddExtinctionCoefficients; the ETM paper's splatting), with no marching
 *   and no grid. Splatting (on by default) turns it off for comparison.
 * - Everything else samples the particles' sum on a grid (GridResolution
 *   samples along the longest side, exact at the nodes, re-sampled when the
 *   input or the resolution changes): the camera rays, the brute-force
 *   shadow rays, and the maps of the other methods (TFM, adaptive TFM and
 *   adaptive ETM), which march it like an image's.
 * - Like any Tyndall volume it shadows and is shadowed by the renderer's
 *   other Tyndall volumes and particle clouds (SceneShadows), is drawn as one
 *   medium with those it overlaps (SceneCompositing), and casts shadows on
 *   surfaces (vtkVolumeShadowReceiverPass).
 *
 * vtkSingleScatteringReference and vtkVolumetricPathTracer render the same
 * scene with the exact sum (no grid): the oracle the GPU is measured against.
 *
 * Bad input (no points, a missing or multi-component array, a non-finite
 * centre, a radius <= 0, a negative or non-finite density, a colour array
 * without three components or with a component outside [0, 1], more than 50
 * million particles) is an error through VTK's error mechanism and nothing
 * is drawn.
 *
 * @sa vtkParticleKernel vtkParticleFileReader vtkTransmittanceVolumeMapper
 */

#ifndef vtkTransmittanceParticleMapper_h
#define vtkTransmittanceParticleMapper_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkTransmittanceVolumeMapper.h"

#include <memory> // For std::unique_ptr

class vtkPolyData;

class TYNDALLRENDERING_EXPORT vtkTransmittanceParticleMapper : public vtkTransmittanceVolumeMapper
{
public:
  static vtkTransmittanceParticleMapper* New();
  vtkTypeMacro(vtkTransmittanceParticleMapper, vtkTransmittanceVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Samples along the longest side of the grid the particles' sum is
   * sampled on (camera rays, brute-force shadow rays, the maps of the
   * methods other than ETM), in [8, 1024]; default 128.
   */
  vtkSetClampMacro(GridResolution, int, 8, 1024);
  vtkGetMacro(GridResolution, int);
  ///@}

  ///@{
  /**
   * Whether the ETM maps add the particles in closed form (splatting) rather
   * than marching their grid; default on.
   */
  vtkSetMacro(Splatting, bool);
  vtkGetMacro(Splatting, bool);
  vtkBooleanMacro(Splatting, bool);
  ///@}

  /// The particle cloud to render.
  void SetInputData(vtkPolyData* particles);

  /// The bounds of the particles' spheres (data coordinates).
  double* GetBounds() VTK_SIZEHINT(6) override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }

  /// The number of particles last read (0 before a render or after an error).
  vtkIdType GetNumberOfParticles();

  /// The time the last re-sampling of the grid took, in seconds.
  vtkGetMacro(LastGridTime, double);

#ifndef __VTK_WRAP__
  vtkImageData* GetMediumImage() override;
  bool DrawsParticles() override
  {
    return true;
  }
  const vtkTyndallParticles* GetParticles() override;
  bool GetSplatsParticles() override
  {
    return this->Splatting;
  }
#endif

protected:
  vtkTransmittanceParticleMapper();
  ~vtkTransmittanceParticleMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  int GridResolution = 128;
  bool Splatting = true;
  double LastGridTime = 0.0;

private:
  vtkTransmittanceParticleMapper(const vtkTransmittanceParticleMapper&) = delete;
  void operator=(const vtkTransmittanceParticleMapper&) = delete;

  // Reads the input and re-samples the grid when they changed; false on
  // error (reported when `report`).
  bool UpdateParticles(bool report);

  class vtkParticles;
  std::unique_ptr<vtkParticles> Particles;
};

#endif
