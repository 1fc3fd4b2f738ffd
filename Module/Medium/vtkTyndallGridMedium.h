/**
 * @class   vtkTyndallGridMedium
 * @brief   a voxel medium: validated scalars, their placement and the tabulated transfer functions
 *
 * vtkTyndallGridMedium is the medium (vtkTyndallMedium) of a vtkVolume
 * drawn by a Tyndall mapper: vtkTyndallSceneReader builds it, the GPU
 * mapper uploads it (scalars as a 3-D texture, the table as a 2-D texture)
 * and the CPU integrators ask it through vtkTyndallMedium's queries. The
 * other media are built on it: a particle cloud's (vtkTyndallParticleMedium,
 * a subclass whose scalars are the particles' grid and whose queries are
 * their exact sum) and procedural detail's (vtkTyndallDetailMedium, whose
 * shape it is). Every rule that decides what is rendered is applied here,
 * once (the policies are listed in Documentation/rendering-model.md, "What
 * is read from the scene"):
 *
 * - the scalars: vtkAbstractMapper::GetScalars() with the mapper's
 *   ScalarMode, ArrayAccessMode, ArrayId and ArrayName (by default point
 *   scalars, else cell scalars); 1 to 4 components (vtkTyndallComponents:
 *   dependent or independent, as VTK classifies them, composite blend mode
 *   only); field data refused;
 * - non-finite scalars: NaN is missing data, and every sample interpolated
 *   from a NaN voxel (a NaN among the 8 voxels around it) is empty medium;
 *   +-Inf take the finite range's ends; a warning counts them; no finite
 *   value at all is an error;
 * - geometry: the image's origin, spacing (non-zero, finite), direction
 *   matrix and extent, then the vtkVolume's matrix (affine and invertible);
 *   point scalars fill the box of the points, cell scalars the same box with
 *   their values at the cell centres (constant over the outer half cells);
 *   an image with fewer than 2 points along an axis is refused (flat);
 * - the medium's parameters (vtkTyndallMediumParameters): the volume's
 *   vtkParticipatingMediumProperty, or for a plain vtkVolumeProperty the
 *   defaults, emission-absorption when its Shade is off (VTK's unlit picture);
 * - the mapper's clipping planes and cropping (vtkTyndallClipRegion): the
 *   medium is empty outside them, for the camera and for the light;
 * - the interpolation: trilinear, or the nearest sample for a plain
 *   vtkVolumeProperty with nearest interpolation (VTK's default; GetNearest());
 * - a plain property's 2-D transfer function (TF_2D; the table's Has2D()) and
 *   the mapper's binary mask (GetMask(): masked samples are missing data);
 * - the mapper's blend mode (vtkTyndallProjection): a projection (maximum,
 *   minimum, average intensity, additive) is drawn as VTK draws it, the
 *   composite mode as a medium; the isosurface mode (vtkTyndallIsosurfaces)
 *   draws the property's iso values as surfaces, which are what the light
 *   meets too (OpticalDepth(), IsoSample()).
 *
 * "Field index" coordinates name the samples: index (i, j, k) is the
 * sample (point or cell centre) i, j, k from the first one; the medium
 * occupies the box [BoxLow, BoxHigh] of field index space.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallGridMedium_h
#define vtkTyndallGridMedium_h

#include "TyndallMediumModule.h"     // For export macro
#include "vtkDataArray.h"            // For the sampler
#include "vtkSmartPointer.h"         // For vtkSmartPointer
#include "vtkTimeStamp.h"            // For vtkTimeStamp
#include "vtkTyndallClipRegion.h"    // For the clip region
#include "vtkTyndallComponents.h"    // For the components
#include "vtkTyndallIsosurfaces.h"   // For the isosurfaces
#include "vtkTyndallLabelMap.h"      // For the label map
#include "vtkTyndallMedium.h"        // For the interface
#include "vtkTyndallProjection.h"    // For the projection
#include "vtkTyndallShading.h"       // For the shading
#include "vtkTyndallTransferTable.h" // For the table
#include "vtkType.h"                 // For vtkIdType

#include <cmath>   // For std::isnan
#include <limits>  // For std::numeric_limits
#include <memory>  // For std::unique_ptr
#include <ostream> // For std::ostream
#include <string>  // For std::string
#include <vector>  // For std::vector

class vtkDataSet;
class vtkImageData;
class vtkObject;
class vtkVolume;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallGridMedium : public vtkTyndallMedium
{
public:
  vtkTyndallGridMedium();
  ~vtkTyndallGridMedium() override;
  vtkTyndallGridMedium(const vtkTyndallGridMedium&) = delete;
  vtkTyndallGridMedium& operator=(const vtkTyndallGridMedium&) = delete;

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
  /**
   * The finite scalar range (component 0's), the count of samples with a
   * NaN component and the count of infinite values (any component); the
   * finite range of component c (0 .. 3).
   */
  const double* GetFiniteRange() const { return this->FiniteRange; }
  vtkIdType GetNumberOfNaNScalars() const { return this->NaNCount; }
  vtkIdType GetNumberOfInfiniteValues() const { return this->InfCount; }
  const double* GetComponentRange(int c) const
  {
    return this->ComponentRanges[c < 0 ? 0 : (c > 3 ? 3 : c)];
  }
  ///@}

  ///@{
  /**
   * The scalars' components (vtkTyndallComponents: how they are classified)
   * and table t of the components' GetTableCount() (table 0 is GetTable()).
   */
  const vtkTyndallComponents& GetComponents() const { return this->Components; }
  const vtkTyndallTransferTable& GetComponentTable(int t) const
  {
    return t <= 0 || t > static_cast<int>(this->ComponentTables.size())
      ? this->Table
      : this->ComponentTables[t - 1];
  }
  ///@}

  ///@{

  /**
   * The mapper's binary mask (vtkParticipatingMediumMapper::SetMaskInput()
   * with BinaryMaskType): per sample of the scalars, 1 where the mask is
   * above 0, 0 where it is not (empty when there is no binary mask). A
   * masked sample is missing data: every sample interpolated from it (the
   * nearest one with the nearest interpolation) is empty medium, on both
   * renderers (the GPU's validity texture holds it).
   */
  const std::vector<unsigned char>& GetMask() const { return this->Mask; }
  /// The number of masked samples (0 without a binary mask).
  vtkIdType GetNumberOfMaskedSamples() const { return this->MaskedCount; }
  /// Whether some samples are missing: NaN scalars or masked ones.
  bool HasMissingData() const { return this->NaNCount > 0 || this->MaskedCount > 0; }
  ///@}

  ///@{
  /**
   * The mapper's label map (vtkParticipatingMediumMapper::SetMaskInput()
   * with LabelMapMaskType; vtkTyndallLabelMap): drawn for a plain
   * single-component table (not with several components, a 2-D transfer
   * function, procedural detail, isosurfaces or a projection, which
   * vtkTyndallVolumeSettings names). GetMajorantTable() is the table whose
   * extinction bounds the labels' too (table 0's for the majorants).
   */
  const vtkTyndallLabelMap& GetLabelMap() const { return this->LabelMap; }
  const vtkTyndallTransferTable& GetMajorantTable(int t) const
  {
    return t == 0 && this->LabelMap.Enabled() ? this->LabelBoundTable : this->GetComponentTable(t);
  }
  ///@}

  ///@{
  /**
   * The box the medium fills, in field index coordinates, and the maps
   * between field index coordinates and world coordinates (row-major 4x4).
   */
  const double* GetBoxLow() const override { return this->BoxLow; }
  const double* GetBoxHigh() const override { return this->BoxHigh; }
  const double* GetIndexToWorld() const { return this->IndexToWorld; }
  const double* GetWorldToIndex() const { return this->WorldToIndex; }
  /// Field index -> the image's data coordinates (before the volume's matrix).
  const double* GetIndexToData() const { return this->IndexToData; }
  ///@}

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

  /// The transfer functions, tabulated.
  const vtkTyndallTransferTable& GetTable() const { return this->Table; }

  /// The medium's parameters (vtkTyndallMediumParameters::Read()'s rules).
  const vtkTyndallMediumParameters& GetParameters() const override { return this->Parameters; }

  ///@{
  /// vtkTyndallMedium's placement: field index coordinates are the local frame.
  const char* GetKind() const override { return "grid"; }
  const double* GetWorldToLocal() const override { return this->WorldToIndex; }
  const double* GetLocalToWorld() const override { return this->IndexToWorld; }
  ///@}

  /**
   * Whether the scalars are read at the nearest sample instead of
   * trilinearly: a plain vtkVolumeProperty whose InterpolationType is VTK's
   * default, nearest (a vtkParticipatingMediumProperty, and a particle
   * cloud, are always trilinear). Both renderers honour it (the GPU's volume
   * and validity textures filter nearest; Sampler rounds).
   */
  bool GetNearest() const { return this->Nearest; }

  /// The clip region when it clips (GetClip() always).
  const vtkTyndallClipRegion* GetClip() const override
  {
    return this->Clip.Enabled() ? &this->Clip : nullptr;
  }
  /// What the mapper's clipping planes and cropping keep (whether or not they clip).
  const vtkTyndallClipRegion& GetClipRegion() const { return this->Clip; }

  /// The mapper's projection blend mode (Enabled() for one; then not a medium).
  const vtkTyndallProjection& GetProjection() const { return this->Projection; }

  /**
   * A plain vtkVolumeProperty's gradient opacity (TF_1D, enabled, below 1
   * somewhere: vtkTyndallVolumeSettings::HasGradientOpacity(); not in a
   * projection blend mode but the slice of one component, whose alpha it
   * multiplies as VTK 9.1 does): the extinction is the table's times
   * GradientOpacityAt(), the table's gradient opacity (GetTable()) at the
   * scalar's change per average voxel, as VTK 9.1 reads it: the central
   * differences one sample apart along each index axis (per sample), each
   * times the mean spacing over that axis' spacing, their length. Both
   * renderers, for the camera and for the light.
   */
  bool GetGradientOpacity() const { return !this->Table.GradientOpacity.empty(); }
  double GradientOpacityAt(const double p[3]) const;
  /// The mean spacing over each axis' spacing (the factors above).
  const double* GetGradientToVoxel() const { return this->GradientToVoxel; }

  /// A plain property's gradient shading (Enabled() with Shade on, composite).
  const vtkTyndallShading& GetShading() const { return this->Shading; }

  /// The mapper's isosurface blend mode (Enabled() for one).
  const vtkTyndallIsosurfaces& GetIsosurfaces() const { return this->Isosurfaces; }

  /**
   * The isosurfaces (GetIsosurfaces()) a camera ray's step from the field
   * index point p0 to p1, of world length dt, crosses: their composite
   * (vtkTyndallIsosurfaces::Composite()) as an extinction over the step,
   * -ln(1 - alpha) / dt, and a colour (the premultiplied colour over alpha),
   * and where in the step the first surface lies (0..1: `first`); false
   * when it crosses none. A step with an end that is clipped away
   * or missing (NaN) crosses nothing; the ends are clamped to the box (the
   * camera rays' steps lie in it).
   */
  bool IsoSample(
    const double p0[3], const double p1[3], double dt, Point& point, double& first) const;

  /**
   * vtkTyndallMedium: the optical depth along a ray; with isosurfaces
   * (GetIsosurfaces()) the depth of the surfaces its steps cross
   * (vtkTyndallIsosurfaces::OpticalDepth(), the steps' ends as IsoSample()
   * reads them), else the base class's march.
   */
  double OpticalDepth(const double o[3], const double d[3], double t0, double t1, double step,
    double maxDepth, bool clip, const PathCache* cache, Work* work) const override;

  /**
   * The scalar's gradient at the field index point p, per world unit in
   * world axes (the CPU twin of the shaders' tyndallScalarGradient()):
   * central differences of FieldScalar() one sample apart along each index
   * axis (clamped at the border), mapped through the world -> index
   * matrix's transpose; 0 where a difference meets missing data. Of
   * component `component` (0 .. 3) of several (vtkTyndallComponents; then
   * 0 where any component is missing).
   */
  void FieldGradient(const double p[3], double gradient[3], int component = 0) const;

  /**
   * Independent components' parts at the field index point p
   * (vtkTyndallComponents::Parts(): each component's weight in the
   * mixture's colour), colours and extinctions (each table's, the density
   * scale applied); false at missing data. What their shading reads
   * (vtkTyndallShading).
   */
  bool ComponentParts(const double p[3], double weights[vtkTyndallComponents::MaximumCount],
    double colors[vtkTyndallComponents::MaximumCount][3],
    double sigma[vtkTyndallComponents::MaximumCount]) const;

  ///@{
  /// vtkTyndallMedium: emission from an array, the majorant (the table's largest extinction), a
  /// voxel.
  bool GetArrayEmission() const override
  {
    // Isosurfaces emit nothing (IsoSample()).
    return this->Parameters.HasEmission && this->GetEmissionFromArray() &&
      !this->Isosurfaces.Enabled();
  }
  void ArrayEmission(const double p[3], double rgb[3]) const override;
  double GetMajorant() const override;
  double GetFinestFeature() const override { return this->GetMinimumWorldSpacing(); }
  ///@}

  /**
   * The scalar the CPU integrators read at the field index point p (NaN at
   * missing data): trilinear interpolation of the scalars (Sampler;
   * component 0), or for a particle cloud the particles' exact sum.
   */
  virtual double FieldScalar(const double p[3]) const;

  /**
   * Every component at the field index point p, interpolated on its own
   * (Sampler); false when one is NaN (missing data).
   */
  bool FieldComponents(const double p[3], double values[vtkTyndallComponents::MaximumCount]) const;

  /**
   * The scalar at the field index point p as VTK's blend modes that read it
   * take it (the projections, an isosurface step's ends; the CPU twin of the
   * shaders' tyndallKeptScalar()): false where p is clipped away or cropped
   * (with `clip`) or its data are missing (NaN, masked).
   */
  bool KeptScalar(const double p[3], bool clip, double& value) const;

  /**
   * KeptScalar() for several components: every component at p (each
   * interpolated on its own); the twin of the shaders' tyndallKeptComponents().
   */
  bool KeptComponents(
    const double p[3], bool clip, double values[vtkTyndallComponents::MaximumCount]) const;

  /// What a projection's rays of several components read (vtkTyndallProjection::Ray).
  vtkTyndallProjection::Classes GetProjectionClasses() const;

  /**
   * The scalar's change per average voxel at the field index point p: the
   * central differences (IndexDifferences()) times GetGradientToVoxel(),
   * their length; what gradient opacity and 2-D transfer functions read.
   */
  double GradientMagnitudeAt(const double p[3]) const;

  /// The table position (k, f) of FieldScalar(p); false at missing data (NaN).
  bool TablePosition(const double p[3], int& k, double& f) const;

  /**
   * The albedo (the table's, or FieldAlbedo()'s) and the emission colour
   * (the table's, when the medium emits through it) at the table position
   * (k, f) of the point p.
   */
  void TableColors(const double p[3], int k, double f, Point& point) const;

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
   * A finite scalar of component c as both renderers see it: +-Inf become
   * the range's ends (NaN passes through: see Sampler).
   */
  double Clean(double v, int c = 0) const
  {
    const double* r = this->ComponentRanges[c];
    return v < r[0] ? r[0] : (v > r[1] ? r[1] : v);
  }

  /**
   * Trilinear interpolation of the cleaned scalars at field index
   * coordinates, clamped to the samples at the border (the GPU's
   * clamp-to-edge); NaN when one of the 8 voxels around the point is NaN
   * (missing data: empty medium). With the medium's GetNearest() the
   * nearest sample's value instead (the GPU's nearest filtering: index
   * round(p), clamped). T is the scalars' value type; `component` the
   * component read.
   */
  template <typename T>
  class Sampler
  {
  public:
    Sampler(const vtkTyndallGridMedium& medium, int component = 0);
    /// Another array of the same layout (the emission array), not cleaned.
    Sampler(const vtkTyndallGridMedium& medium, const T* data);
    double Scalar(const double p[3]) const;
    /// Every component at p at once (GetScalars()' components of them).
    void Values(const double p[3], double* values) const;

  private:
    // The sample (nearest: base, steps 0) or the cell (trilinear: its first
    // sample, the steps to the next along each axis, the fractions) p reads;
    // false when a sample it reads is masked.
    bool Cell(const double p[3], vtkIdType& base, vtkIdType step[3], double f[3]) const;
    double Interpolate(
      vtkIdType base, const vtkIdType step[3], const double f[3], int component) const;
    double Value(T v, int component) const
    {
      if (std::numeric_limits<T>::has_quiet_NaN && this->Clean)
      {
        return this->Medium->Clean(static_cast<double>(v), component);
      }
      return static_cast<double>(v);
    }
    const vtkTyndallGridMedium* Medium;
    const T* Data;
    int Components = 1;                  // values per sample
    int Component = 0;                   // the one read
    const unsigned char* Mask = nullptr; // the binary mask (GetMask()), or none
    bool Clean = true;
    bool Nearest = false;
    int Dims[3];
    vtkIdType Stride[3];
  };

  /**
   * Sigma_t (density scale applied) at a world point, through the table:
   * the CPU twin of the shaders' tyndallExtinction(); 0 outside the box.
   */
  double WorldExtinction(const double world[3]) const;

protected:
  double FieldExtinction(const double p[3], Work* work) const override;
  bool FieldSample(const double p[3], Point& point, double pixel) const override;
  bool FieldMaterial(const double p[3], Point& point) const override;

  /**
   * The image whose scalars are the medium: the mapper's medium image
   * (vtkParticipatingMediumMapper::GetMediumImage(): its input, or a
   * particle cloud's grid). A subclass reads more of the mapper here first;
   * null (with an error reported) when there is none to read.
   */
  virtual vtkDataSet* ReadInput(vtkVolume* volume, vtkObject* reporter);

  /// Whether the table's extinction is the scalar itself (a particle cloud's density).
  virtual bool GetLinearExtinction() const { return false; }

  /// The albedo at p where it does not come from the table (a coloured particle cloud); false.
  virtual bool FieldAlbedo(const double p[3], double color[3]) const;

private:
  bool UpdateScalars(vtkVolume* volume, vtkObject* reporter);
  bool ReadScalars(vtkImageData* image, vtkDataArray* scalars, int cellFlag, std::ostream& error,
    vtkObject* reporter);
  bool UpdateEmissionArray(vtkVolume* volume, vtkObject* reporter);
  // Reads the mapper's binary mask into Mask (see GetMask()), or its label
  // map into LabelMap's labels; false (with an error) for a mask that does
  // not lie on the scalars' samples.
  bool UpdateMask(vtkVolume* volume, vtkObject* reporter);
  bool ReadMask(vtkImageData* mask, bool labels, std::ostream& error);
  bool UpdateGeometry(vtkVolume* volume, vtkObject* reporter);
  bool UpdateTable(vtkVolume* volume, vtkObject* reporter);
  // A plain property's 2-D transfer function (TF_2D; the table's Has2D()) at
  // the field index point p: its RGBA at the scalar and the change per
  // average voxel (GradientOpacityAt()'s); false at missing data.
  bool Transfer2DSample(const double p[3], double rgba[4]) const;
  // The label map at the field index point p: the label of its nearest
  // sample and the label table's entry of its scalar; false where no label
  // applies (label 0, missing data, no label map).
  bool LabelAt(const double p[3], int& label, int& entry) const;
  // The table's extinction at p (entry k, fraction f): density scale and
  // gradient opacity applied.
  double TableExtinction(const double p[3], int k, double f) const;
  // Whether the property's label functions apply (see GetLabelMap()).
  bool LabelsApply(vtkVolumeProperty* property) const;
  // The extinction of a 2-D function's opacity: per VTK's automatic step
  // (the smallest world spacing), density scale applied.
  double Transfer2DExtinction(double opacity) const;
  // The central differences of FieldScalar() one sample apart along each
  // index axis at p, per sample; 0 (and false) where one meets missing data.
  bool IndexDifferences(const double p[3], double g[3], int component = 0) const;
  // Several components at p: their values, each table's extinction and
  // colour at its component's value, and table 0's position (k, f).
  struct ComponentLookup
  {
    double Values[vtkTyndallComponents::MaximumCount];
    double Sigma[vtkTyndallComponents::MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
    double Colors[vtkTyndallComponents::MaximumCount][3] = {};
    int K0 = 0;
    double F0 = 0.0;
  };
  // Fills `lookup` at p; false at missing data (ComponentSample(), ComponentParts()).
  bool LookUpComponents(const double p[3], ComponentLookup& lookup) const;
  // Several components' sample at p (vtkTyndallComponents::Mix()); false at
  // missing data.
  bool ComponentSample(const double p[3], Point& point) const;
  // Reads the components' classification (after the scalars); false (with
  // an error) for a setting multi-component scalars are not drawn with.
  bool UpdateComponents(vtkVolume* volume, vtkObject* reporter);

  // The samplers of the scalars' value type for FieldScalar() and
  // FieldComponents() (after a change of the scalars or of GetNearest()).
  void MakeField();

  // The scalars and what they were read from (Input: during Update() only).
  vtkImageData* Input = nullptr;
  vtkSmartPointer<vtkDataArray> Scalars;
  std::vector<double> ScalarsKey;
  std::string ScalarsError;
  vtkTimeStamp ScalarsTime;
  bool Valid = false;
  int Extent[6] = { 0, -1, 0, -1, 0, -1 };
  int Dimensions[3] = { 0, 0, 0 };
  bool CellScalars = false;
  double FiniteRange[2] = { 0.0, 0.0 };
  double ComponentRanges[vtkTyndallComponents::MaximumCount][2] = {};
  vtkTyndallComponents Components;
  std::vector<vtkTyndallTransferTable> ComponentTables; // tables 1 .. GetTableCount() - 1
  vtkIdType NaNCount = 0;
  std::vector<unsigned char> Mask;
  vtkTyndallLabelMap LabelMap;
  vtkTyndallTransferTable LabelBoundTable;
  std::vector<double> MaskKey;
  vtkIdType MaskedCount = 0;
  vtkIdType InfCount = 0;

  // Geometry.
  double BoxLow[3] = { 0.0, 0.0, 0.0 };
  double BoxHigh[3] = { 1.0, 1.0, 1.0 };
  double IndexToWorld[16];
  double IndexToData[16];
  double WorldToIndex[16];

  vtkTyndallClipRegion Clip;
  vtkTyndallProjection Projection;
  vtkTyndallShading Shading;
  vtkTyndallIsosurfaces Isosurfaces;
  bool Nearest = false;
  double GradientToVoxel[3] = { 1.0, 1.0, 1.0 };
  std::vector<float> EmissionValues;
  double EmissionRange[2] = { 0.0, 0.0 };
  std::vector<double> EmissionKey;
  vtkTimeStamp EmissionArrayTime;

  // The table and the parameters.
  vtkTyndallTransferTable Table;
  std::vector<double> TableKey;
  vtkTimeStamp TableTime;
  std::vector<double> ExtinctionKey;
  vtkTimeStamp ExtinctionTime;
  vtkTyndallMediumParameters Parameters;

  // The scalars' sampler for their value type (FieldScalar()).
  class FieldBase;
  template <typename T>
  class TypedField;
  std::vector<std::unique_ptr<FieldBase>> Field; // one per component
};

//------------------------------------------------------------------------------
template <typename T>
vtkTyndallGridMedium::Sampler<T>::Sampler(const vtkTyndallGridMedium& medium, int component)
  : Medium(&medium)
  , Data(static_cast<const T*>(medium.GetScalars()->GetVoidPointer(0)))
  , Components(medium.GetScalars()->GetNumberOfComponents())
  , Component(component)
  , Mask(medium.Mask.empty() ? nullptr : medium.Mask.data())
  , Nearest(medium.Nearest)
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
  this->Components = 1;
  this->Component = 0;
  this->Mask = nullptr; // another array: its own values
  this->Clean = false;
  this->Nearest = false; // another array (emission: never a plain property's)
}

//------------------------------------------------------------------------------
template <typename T>
bool vtkTyndallGridMedium::Sampler<T>::Cell(
  const double p[3], vtkIdType& base, vtkIdType step[3], double f[3]) const
{
  base = 0;
  if (this->Nearest)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int n = this->Dims[a];
      const double x = p[a] > 0.0 ? (p[a] < n - 1 ? p[a] : n - 1) : 0.0;
      base += static_cast<vtkIdType>(x + 0.5) * this->Stride[a];
      step[a] = 0; // the 8 corners are the nearest sample
      f[a] = 0.0;
    }
    return !this->Mask || this->Mask[base];
  }
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
  if (this->Mask)
  {
    const unsigned char* m = this->Mask + base;
    return m[0] && m[step[0]] && m[step[1]] && m[step[0] + step[1]] && m[step[2]] &&
      m[step[0] + step[2]] && m[step[1] + step[2]] && m[step[0] + step[1] + step[2]];
  }
  return true;
}

//------------------------------------------------------------------------------
template <typename T>
double vtkTyndallGridMedium::Sampler<T>::Interpolate(
  vtkIdType base, const vtkIdType step[3], const double f[3], int component) const
{
  const int nc = this->Components;
  const T* d = this->Data + base * nc + component;
  const double c000 = this->Value(d[0], component);
  const double c100 = this->Value(d[step[0] * nc], component);
  const double c010 = this->Value(d[step[1] * nc], component);
  const double c110 = this->Value(d[(step[0] + step[1]) * nc], component);
  const double c001 = this->Value(d[step[2] * nc], component);
  const double c101 = this->Value(d[(step[0] + step[2]) * nc], component);
  const double c011 = this->Value(d[(step[1] + step[2]) * nc], component);
  const double c111 = this->Value(d[(step[0] + step[1] + step[2]) * nc], component);
  const double c00 = c000 + f[0] * (c100 - c000);
  const double c10 = c010 + f[0] * (c110 - c010);
  const double c01 = c001 + f[0] * (c101 - c001);
  const double c11 = c011 + f[0] * (c111 - c011);
  const double c0 = c00 + f[1] * (c10 - c00);
  const double c1 = c01 + f[1] * (c11 - c01);
  return c0 + f[2] * (c1 - c0);
}

//------------------------------------------------------------------------------
template <typename T>
double vtkTyndallGridMedium::Sampler<T>::Scalar(const double p[3]) const
{
  vtkIdType base, step[3];
  double f[3];
  return this->Cell(p, base, step, f) ? this->Interpolate(base, step, f, this->Component)
                                      : std::numeric_limits<double>::quiet_NaN(); // masked
}

//------------------------------------------------------------------------------
template <typename T>
void vtkTyndallGridMedium::Sampler<T>::Values(const double p[3], double* values) const
{
  vtkIdType base, step[3];
  double f[3];
  const bool kept = this->Cell(p, base, step, f);
  for (int c = 0; c < this->Components; ++c)
  {
    values[c] =
      kept ? this->Interpolate(base, step, f, c) : std::numeric_limits<double>::quiet_NaN();
  }
}

#endif
