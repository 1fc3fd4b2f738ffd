/**
 * @class   vtkTyndallGridMedium
 * @brief   a voxel medium: validated scalars, their placement and the tabulated transfer functions
 *
 * vtkTyndallGridMedium is what both of Tyndall's renderers consume of a
 * vtkVolume drawn by a Tyndall mapper: vtkTyndallSceneReader builds it, the GPU
 * mapper uploads it (scalars as a 3-D texture, the table as a 2-D texture)
 * and the CPU reference samples it with GetSampler(). Every rule that
 * decides what is rendered is applied here, once (the policies are listed in
 * Documentation/rendering-model.md, "What is read from the scene"):
 *
 * - the scalars: vtkAbstractMapper::GetScalars() with the mapper's
 *   ScalarMode, ArrayAccessMode, ArrayId and ArrayName (by default point
 *   scalars, else cell scalars); one component; field data refused;
 * - non-finite scalars: NaN is missing data, and every sample interpolated
 *   from a NaN voxel (a NaN among the 8 voxels around it) is empty medium;
 *   +-Inf take the finite range's ends; a warning counts them; no finite
 *   value at all is an error;
 * - geometry: the image's origin, spacing (non-zero, finite), direction
 *   matrix and extent, then the vtkVolume's matrix (affine and invertible);
 *   point scalars fill the box of the points, cell scalars the same box with
 *   their values at the cell centres (constant over the outer half cells);
 *   an image with fewer than 2 points along an axis is refused (flat);
 * - the medium's parameters: the volume's vtkParticipatingMediumProperty, or
 *   the defaults for a plain vtkVolumeProperty;
 * - the mapper's clipping planes and cropping (vtkTyndallClipRegion): the
 *   medium is empty outside them, for the camera and for the light.
 *
 * "Field index" coordinates name the samples: index (i, j, k) is the
 * sample (point or cell centre) i, j, k from the first one; the medium
 * occupies the box [BoxLow, BoxHigh] of field index space.
 *
 * Internal to Tyndall::Rendering; not wrapped.
 */

#ifndef vtkTyndallGridMedium_h
#define vtkTyndallGridMedium_h

#include "TyndallRenderingModule.h"  // For export macro
#include "vtkDataArray.h"            // For the sampler
#include "vtkFloatArray.h"           // For vtkFloatArray
#include "vtkSmartPointer.h"         // For vtkSmartPointer
#include "vtkTimeStamp.h"            // For vtkTimeStamp
#include "vtkTyndallClipRegion.h"    // For the clip region
#include "vtkTyndallTransferTable.h" // For the table
#include "vtkType.h"                 // For vtkIdType

#include <cmath>   // For std::isnan
#include <limits>  // For std::numeric_limits
#include <ostream> // For std::ostream
#include <string>  // For std::string
#include <vector>  // For std::vector

class vtkAbstractVolumeMapper;
class vtkImageData;
class vtkObject;
class vtkTyndallParticleMedium;
class vtkVolume;

class TYNDALLRENDERING_EXPORT vtkTyndallGridMedium
{
public:
  /**
   * Reads the medium of `volume` (its mapper's input, its matrix and
   * property), updating the input first. Work is redone only for what
   * changed. Errors and warnings are reported through `reporter`'s
   * vtkErrorMacro / vtkWarningMacro; returns false on error (the medium is
   * then not renderable).
   */
  bool Update(vtkVolume* volume, vtkObject* reporter);

  ///@{
  /**
   * The scalars as selected (a standard-layout array, the input's own or a
   * copy) and the number of samples per axis.
   */
  vtkDataArray* GetScalars() const { return this->Scalars; }
  const int* GetDimensions() const { return this->Dimensions; }
  ///@}

  ///@{
  /// The finite scalar range, and the count of NaN scalars.
  const double* GetFiniteRange() const { return this->FiniteRange; }
  vtkIdType GetNumberOfNaNScalars() const { return this->NaNCount; }
  ///@}

  ///@{
  /**
   * The box the medium fills, in field index coordinates, and the maps
   * between field index coordinates and world coordinates (row-major 4x4).
   */
  const double* GetBoxLow() const { return this->BoxLow; }
  const double* GetBoxHigh() const { return this->BoxHigh; }
  const double* GetIndexToWorld() const { return this->IndexToWorld; }
  const double* GetWorldToIndex() const { return this->WorldToIndex; }
  /// Field index -> the image's data coordinates (before the volume's matrix).
  const double* GetIndexToData() const { return this->IndexToData; }
  ///@}

  /// The eight world corners of the box (24 doubles; corner c has bit 0, 1, 2 for x, y, z high).
  void GetWorldCorners(double corners[24]) const;

  /// The world length of one field index step along the shortest axis.
  double GetMinimumWorldSpacing() const;

  /// The length of the box's diagonal in world units.
  double GetWorldDiagonal() const;

  ///@{
  /**
   * Emission from a separate array (vtkParticipatingMediumProperty::
   * EmissionArrayName): its values, one per sample like the scalars
   * (non-finite values replaced by the finite minimum; empty without one),
   * their finite range, and the value at a field index point (trilinear,
   * clamped at the border like the scalars).
   */
  const std::vector<float>& GetEmissionValues() const { return this->EmissionValues; }
  bool GetEmissionFromArray() const { return !this->EmissionValues.empty(); }
  const double* GetEmissionRange() const { return this->EmissionRange; }
  double EmissionValue(const double p[3]) const;
  /// When the emission array (or its absence) last changed.
  vtkMTimeType GetEmissionTime() const { return this->EmissionArrayTime.GetMTime(); }
  ///@}

  ///@{
  /**
   * A particle cloud's medium (vtkTransmittanceParticleMapper): the
   * particles whose sum the scalars sample (the table's extinction is then
   * the scalar itself), and whether the extinction maps splat them instead
   * of marching the scalars. Null and false for an image.
   */
  const vtkTyndallParticleMedium* GetParticles() const { return this->Particles; }
  bool GetSplatParticles() const { return this->SplatParticles; }
  ///@}

  /**
   * A coloured particle cloud (vtkTyndallParticleMedium::HasColors()): the
   * grid of its scattering density (density times albedo, three components
   * per sample, beside the scalars: the GPU's albedo is its interpolation
   * over the scalars'); null otherwise. The colour transfer function is then
   * not used for the albedo.
   */
  vtkFloatArray* GetParticleScattering() const { return this->ParticleScattering; }

  /**
   * The albedo of a coloured particle cloud at the field index point p,
   * exact (the particles' colours weighted by their extinctions); false,
   * `color` untouched, for any other medium.
   */
  bool ParticleColor(const double p[3], double color[3]) const;

  /// What the mapper's clipping planes and cropping keep.
  const vtkTyndallClipRegion& GetClip() const { return this->Clip; }

  /// The transfer functions, tabulated.
  const vtkTyndallTransferTable& GetTable() const { return this->Table; }

  ///@{
  /**
   * The medium's parameters (vtkParticipatingMediumProperty, or its
   * defaults).
   */
  int GetScatteringModel() const { return this->ScatteringModel; }
  bool GetSingleScattering() const { return this->ScatteringModel == 1; }
  double GetDensityScale() const { return this->DensityScale; }
  double GetScatteringAnisotropy() const { return this->ScatteringAnisotropy; }
  double GetLightScale() const { return this->LightScale; }
  double GetAmbientIntensity() const { return this->AmbientIntensity; }
  /// Multiple-scattering octaves: their count (1: single scattering alone) and factors a, b, c, s
  /// (vtkParticipatingMediumProperty: OctaveScattering, -Extinction, -Anisotropy, -BuildUp).
  int GetScatteringOctaves() const { return this->ScatteringOctaves; }
  const double* GetOctaveFactors() const { return this->OctaveFactors; }
  double GetEmissionScale() const { return this->EmissionScale; }
  /**
   * Coloured extinction: channel k's extinction is GetExtinctionColor()[k]
   * times the extinction (GetDensityScale() already holds the property's
   * largest ExtinctionColor component, so the largest component here is 1,
   * and the extinction is the densest channel's: the maps and the majorants
   * need no change).
   */
  const double* GetExtinctionColor() const { return this->ExtinctionColor; }
  /// Whether the channels' extinctions differ (the renderers then track three transmittances).
  bool GetChromatic() const
  {
    return this->ExtinctionColor[0] != 1.0 || this->ExtinctionColor[1] != 1.0 ||
      this->ExtinctionColor[2] != 1.0;
  }
  /**
   * The smallest positive component of GetExtinctionColor() (1 for a grey
   * medium): the faintest channel's transmittance is the map's raised to it.
   */
  double GetFaintestChannel() const;
  /// Single scattering with an emission colour and a positive scale.
  bool GetHasEmission() const { return this->HasEmission; }
  ///@}

  ///@{
  /**
   * When the scalars (values, selection, image) and the table last changed:
   * the GPU re-uploads what is newer than its copy. The extinction time
   * covers only what the table's extinction depends on (opacity function,
   * unit distance, finite range): the transmittance maps are rebuilt on it,
   * not on a colour or emission edit, and on a change of the clip region.
   */
  vtkMTimeType GetScalarsTime() const { return this->ScalarsTime.GetMTime(); }
  vtkMTimeType GetTableTime() const { return this->TableTime.GetMTime(); }
  vtkMTimeType GetExtinctionTime() const { return this->ExtinctionTime.GetMTime(); }
  ///@}

  /**
   * A finite scalar as both renderers see it: +-Inf become the range's ends
   * (NaN passes through: see Sampler).
   */
  double Clean(double v) const
  {
    return v < this->FiniteRange[0] ? this->FiniteRange[0]
                                    : (v > this->FiniteRange[1] ? this->FiniteRange[1] : v);
  }

  /**
   * Trilinear interpolation of the cleaned scalars at field index
   * coordinates, clamped to the samples at the border (the GPU's
   * clamp-to-edge); NaN when one of the 8 voxels around the point is NaN
   * (missing data: empty medium). T is the scalars' value type.
   */
  template <typename T>
  class Sampler
  {
  public:
    Sampler(const vtkTyndallGridMedium& medium);
    /// Another array of the same layout (the emission array), not cleaned.
    Sampler(const vtkTyndallGridMedium& medium, const T* data);
    double Scalar(const double p[3]) const;
    /**
     * The scalar the CPU renderers integrate: Scalar(), or for a particle
     * medium (GetParticles()) the particles' exact sum at p, no grid.
     */
    double ReferenceScalar(const double p[3]) const
    {
      return this->Medium->Particles ? this->Medium->ParticleScalar(p) : this->Scalar(p);
    }
    /**
     * The albedo the CPU renderers use at p when it does not come from the
     * table: a coloured particle cloud's exact colour
     * (vtkTyndallGridMedium::ParticleColor()); false otherwise.
     */
    bool ReferenceColor(const double p[3], double color[3]) const
    {
      return this->Medium->ParticleColor(p, color);
    }

  private:
    double Value(T v) const
    {
      if (std::numeric_limits<T>::has_quiet_NaN && this->Clean)
      {
        return this->Medium->Clean(static_cast<double>(v));
      }
      return static_cast<double>(v);
    }
    const vtkTyndallGridMedium* Medium;
    const T* Data;
    bool Clean = true;
    int Dims[3];
    vtkIdType Stride[3];
  };

  /// The particles' exact sum at the field index point p (GetParticles() must be set).
  double ParticleScalar(const double p[3]) const;

  /**
   * Sigma_t (density scale applied) at a world point, through the table:
   * the CPU twin of the shaders' tyndallExtinction(). Slow (dispatches on
   * the scalar type per call): for tests; renderers use a Sampler.
   */
  double Extinction(const double world[3]) const;

private:
  bool UpdateScalars(vtkVolume* volume, vtkObject* reporter);
  bool ReadScalars(vtkImageData* image, vtkDataArray* scalars, int cellFlag, std::ostream& error,
    vtkObject* reporter);
  bool UpdateEmissionArray(vtkVolume* volume, vtkObject* reporter);
  bool UpdateGeometry(vtkVolume* volume, vtkObject* reporter);
  bool UpdateTable(vtkVolume* volume, vtkObject* reporter);

  // The scalars and what they were read from.
  vtkSmartPointer<vtkDataArray> Scalars;
  std::vector<double> ScalarsKey;
  std::string ScalarsError;
  vtkTimeStamp ScalarsTime;
  bool Valid = false;
  int Extent[6] = { 0, -1, 0, -1, 0, -1 };
  int Dimensions[3] = { 0, 0, 0 };
  bool CellScalars = false;
  double FiniteRange[2] = { 0.0, 0.0 };
  vtkIdType NaNCount = 0;
  vtkIdType InfCount = 0;

  // Geometry.
  double BoxLow[3] = { 0.0, 0.0, 0.0 };
  double BoxHigh[3] = { 1.0, 1.0, 1.0 };
  double IndexToWorld[16];
  double IndexToData[16];
  double WorldToIndex[16];

  vtkTyndallClipRegion Clip;
  std::vector<float> EmissionValues;
  double EmissionRange[2] = { 0.0, 0.0 };
  std::vector<double> EmissionKey;
  vtkTimeStamp EmissionArrayTime;

  // The table and the parameters.
  vtkTyndallTransferTable Table;
  const vtkTyndallParticleMedium* Particles = nullptr;
  bool SplatParticles = false;
  vtkSmartPointer<vtkFloatArray> ParticleScattering;
  std::vector<double> TableKey;
  vtkTimeStamp TableTime;
  std::vector<double> ExtinctionKey;
  vtkTimeStamp ExtinctionTime;
  int ScatteringModel = 1;
  double DensityScale = 1.0;
  double ScatteringAnisotropy = 0.0;
  double LightScale = 1.0;
  double AmbientIntensity = 0.0;
  double ExtinctionColor[3] = { 1.0, 1.0, 1.0 };
  int ScatteringOctaves = 1;
  double OctaveFactors[4] = { 0.0, 0.0, 0.0, 0.0 };
  double EmissionScale = 0.0;
  bool HasEmission = false;
};

//------------------------------------------------------------------------------
template <typename T>
vtkTyndallGridMedium::Sampler<T>::Sampler(const vtkTyndallGridMedium& medium)
  : Medium(&medium)
  , Data(static_cast<const T*>(medium.GetScalars()->GetVoidPointer(0)))
{
  for (int a = 0; a < 3; ++a)
  {
    this->Dims[a] = medium.Dimensions[a];
  }
  this->Stride[0] = 1;
  this->Stride[1] = this->Dims[0];
  this->Stride[2] = static_cast<vtkIdType>(this->Dims[0]) * this->Dims[1];
}

//------------------------------------------------------------------------------
template <typename T>
vtkTyndallGridMedium::Sampler<T>::Sampler(const vtkTyndallGridMedium& medium, const T* data)
  : Sampler(medium)
{
  this->Data = data;
  this->Clean = false;
}

//------------------------------------------------------------------------------
template <typename T>
double vtkTyndallGridMedium::Sampler<T>::Scalar(const double p[3]) const
{
  vtkIdType base = 0;
  vtkIdType step[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const int n = this->Dims[a];
    double x = p[a];
    x = x > 0.0 ? (x < n - 1 ? x : n - 1) : 0.0;
    int i = static_cast<int>(x);
    if (i > n - 2)
    {
      i = n > 1 ? n - 2 : 0;
    }
    f[a] = x - i;
    base += i * this->Stride[a];
    step[a] = n > 1 ? this->Stride[a] : 0;
  }
  const T* d = this->Data + base;
  const double c000 = this->Value(d[0]);
  const double c100 = this->Value(d[step[0]]);
  const double c010 = this->Value(d[step[1]]);
  const double c110 = this->Value(d[step[0] + step[1]]);
  const double c001 = this->Value(d[step[2]]);
  const double c101 = this->Value(d[step[0] + step[2]]);
  const double c011 = this->Value(d[step[1] + step[2]]);
  const double c111 = this->Value(d[step[0] + step[1] + step[2]]);
  const double c00 = c000 + f[0] * (c100 - c000);
  const double c10 = c010 + f[0] * (c110 - c010);
  const double c01 = c001 + f[0] * (c101 - c001);
  const double c11 = c011 + f[0] * (c111 - c011);
  const double c0 = c00 + f[1] * (c10 - c00);
  const double c1 = c01 + f[1] * (c11 - c01);
  return c0 + f[2] * (c1 - c0);
}

#endif
