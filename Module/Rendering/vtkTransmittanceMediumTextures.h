/**
 * @class   vtkTransmittanceMediumTextures
 * @brief   the upload pass of vtkTransmittanceVolumeMapper: a medium's scalars and table on the GPU
 *
 * Uploads a vtkTyndallGridMedium's cleaned scalars (+-Inf clamped:
 * vtkTyndallGridMedium::Clean()) as a 3-D texture with linear filtering and
 * clamp-to-edge, in the data's own size for 8- and 16-bit integers and as
 * floats otherwise (GetValueMap()), and its transfer table
 * (vtkTyndallTransferTable::GetTexture()) as a 2-D texture, each only when
 * it changed. When the scalars hold NaN (missing data), NaN voxels get the
 * range's minimum in the scalar texture and 0 in a validity texture (1
 * elsewhere, 8-bit, linear): a sample whose filtered validity is below 1
 * touches a NaN voxel and is empty, as on the CPU (vtkTyndallGridMedium). A volume whose slices
 * pass the GPU's 3-D texture limit (GL_MAX_3D_TEXTURE_SIZE, or SetMaximumTextureSize()) is
 * stored in tiles of slices side by side in each texture (vtkTransmittanceVolumeTiling: every
 * sample kept); one whose width or height passes it, or whose tiles do not fit, is stored as
 * bricks (vtkTransmittanceVolumeBricks, every sample kept) where their atlas fits the limit and
 * the bricking mode allows them, else downsampled by the smallest integer factor that fits,
 * with a warning.
 * GetTextureScale() and GetTextureShift() map the medium's box as [0, 1]^3
 * to texture coordinates (point scalars: texel centres at the box's corners;
 * cell scalars: the texels fill the box).
 *
 * It also keeps the volume's vtkTyndallMajorantGrid (block ranges rebuilt
 * with the scalars, majorants with the table) on the GPU as an R32F 3-D
 * texture, one texel per block, read with texelFetch: the shaders' empty-
 * space skipping. GetBlockScale() and GetBlockShift() map the box as
 * [0, 1]^3 to block coordinates (block b spans [b, b + 1) per axis).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceMediumTextures_h
#define vtkTransmittanceMediumTextures_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"              // For vtkSmartPointer
#include "vtkTextureObject.h"             // For the inline getters
#include "vtkTimeStamp.h"                 // For vtkTimeStamp
#include "vtkTransmittanceVolumeBricks.h" // For vtkTransmittanceVolumeBricks
#include "vtkTransmittanceVolumeTiling.h" // For vtkTransmittanceVolumeTiling
#include "vtkTyndallMajorantGrid.h"       // For vtkTyndallMajorantGrid

class vtkOpenGLRenderWindow;
class vtkTyndallDetailMedium;
class vtkTyndallGridMedium;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceMediumTextures : public vtkObject
{
public:
  static vtkTransmittanceMediumTextures* New();
  vtkTypeMacro(vtkTransmittanceMediumTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What a kind of medium adds to its grid's textures: its adapter
   * (vtkTransmittanceMediumAdapter) says; what is null is released.
   */
  struct Extras
  {
    /**
     * A coloured particle cloud's scattering density (RGB per sample, laid
     * out like the scalars: vtkTyndallParticleMedium::GetScatteringGrid()),
     * uploaded with the scalars.
     */
    const float* Scattering = nullptr;
    /// Procedural detail over the grid: its shape, uploaded when it changed.
    const vtkTyndallDetailMedium* Detail = nullptr;
  };

  /**
   * Uploads what changed since the last call of `medium` and `extras`.
   * Errors go through `reporter`; false when the medium cannot be rendered.
   */
  bool Update(vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium,
    const Extras& extras, vtkObject* reporter);

  ///@{
  /**
   * The most texels per side of a volume texture: 0 (the default) for the
   * GL's GL_MAX_3D_TEXTURE_SIZE, else the smaller of the two (the mapper's
   * vtkTransmittanceVolumeMapper::SetMaximumTextureSize()). A change uploads
   * the volume again.
   */
  void SetMaximumTextureSize(int size) { this->MaximumTextureSize = size; }
  int GetMaximumTextureSize() const { return this->MaximumTextureSize; }
  ///@}

  /// The volume's layout in its textures (the scalars, validity, labels, emission).
  const vtkTransmittanceVolumeTiling& GetTiling() const { return this->Tiling; }

  ///@{
  /**
   * Whether the scalars may be stored as the bricks that vary
   * (vtkTransmittanceVolumeBricks; the mapper's
   * vtkTransmittanceVolumeMapper::SetVolumeBricking()): BRICKING_OFF never,
   * BRICKING_ON when the bricks take no more than the dense texture's
   * bytes, BRICKING_AUTO (the default) when they take at most half of them;
   * both whenever the dense texture does not fit, and whatever they take
   * for a volume wider or taller than the limit (read in place: 8- and
   * 16-bit integers, clean floats), which they keep whole where their atlas
   * fits. A volume with another texture at its resolution (validity,
   * labels, an emission array, a coloured particle cloud's colours), tiled
   * or downsampled, is dense. A change of those or of the setting uploads
   * the volume again.
   */
  enum Brickings
  {
    BRICKING_OFF,
    BRICKING_ON,
    BRICKING_AUTO
  };
  void SetBricking(int bricking) { this->Bricking = bricking; }
  int GetBricking() const { return this->Bricking; }
  /// The bricks' plan (IsBricked() when the scalars are stored so) and their indirection texture.
  const vtkTransmittanceVolumeBricks& GetBricks() const { return this->Bricks; }
  vtkTextureObject* GetBrickTexture() const { return this->BrickTexture; }
  /// The bytes the scalars take on the GPU: the atlas and its indirection, or the dense texture.
  size_t GetVolumeTextureBytes() const;
  ///@}

  /// Null without procedural detail.
  vtkTextureObject* GetDetailTexture() const { return this->DetailTexture; }

  vtkTextureObject* GetVolumeTexture() const { return this->VolumeTexture; }
  /**
   * How the volume texture's texels give the scalars: value = texel *
   * GetValueMap()[0] + GetValueMap()[1]. 8- and 16-bit integer scalars are
   * stored in their own type as normalized textures (1 or 2 bytes per
   * component and voxel): (max of the type, 0), the lowest signed value
   * reading as minus the max (the GL's clamp); any other type as 32-bit
   * floats (4 bytes): (1, 0).
   */
  const float* GetValueMap() const { return this->ValueMap; }
  /// Null without an emission array (vtkTyndallGridMedium::GetEmissionValues()).
  vtkTextureObject* GetEmissionTexture() const { return this->EmissionTexture; }
  /// A coloured particle cloud's scattering density (Extras::Scattering); null for any other
  /// medium.
  vtkTextureObject* GetScatteringTexture() const { return this->ScatteringTexture; }
  /// Null when the scalars hold no NaN.
  vtkTextureObject* GetValidityTexture() const { return this->ValidityTexture; }
  vtkTextureObject* GetTransferTexture() const { return this->TransferTexture; }
  /// A plain property's 2-D transfer function (vtkTyndallTransferTable::Has2D()); null without.
  vtkTextureObject* GetTransfer2DTexture() const { return this->Transfer2DTexture; }
  /**
   * Several components' tables 1 .. (vtkTyndallComponents::GetTableCount();
   * table 0 is GetTransferTexture()): two rows each, the table's albedo row
   * (colour, extinction) and its emission row (emission, opacity function);
   * null for fewer than 2 tables.
   */
  vtkTextureObject* GetComponentTexture() const { return this->ComponentTexture; }

  /**
   * A label map (vtkTyndallLabelMap): the labels at the scalars' samples
   * (a one-byte 3-D texture read nearest, label / 255; uploaded with the
   * scalars) and, while the labels draw, their rows (RGBA, Width x
   * (RowCount + 1), read nearest; with the table); null without.
   */
  vtkTextureObject* GetLabelTexture() const { return this->LabelTexture; }
  vtkTextureObject* GetLabelRowsTexture() const { return this->LabelRowsTexture; }
  /**
   * When what a map build sees of the uploaded medium last changed: its
   * scalars, its extinction (not its colours) or its clipping.
   */
  vtkMTimeType GetExtinctionContentTime() const { return this->ExtinctionContentTime.GetMTime(); }
  const float* GetTextureScale() const { return this->TextureScale; }
  const float* GetTextureShift() const { return this->TextureShift; }
  vtkTextureObject* GetBlockTexture() const { return this->BlockTexture; }
  const float* GetBlockScale() const { return this->BlockScale; }
  const float* GetBlockShift() const { return this->BlockShift; }
  const vtkTyndallMajorantGrid& GetMajorantGrid() const { return this->Majorants; }

  ///@{
  /// Seconds the last block-range and majorant builds took.
  double GetLastBlockRangeTime() const { return this->BlockRangeTime; }
  double GetLastMajorantTime() const { return this->MajorantTime; }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceMediumTextures();
  ~vtkTransmittanceMediumTextures() override;

private:
  vtkTransmittanceMediumTextures(const vtkTransmittanceMediumTextures&) = delete;
  void operator=(const vtkTransmittanceMediumTextures&) = delete;

  bool UploadScalars(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  // The scalars at Dimensions (Factor), by their type: UploadStored() or UploadFloats().
  bool UploadValues(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  // The scalars of an 8- or 16-bit integer type T (unsigned or signed char
  // or short) in a normalized texture of T (no copy at every sample).
  template <typename T>
  bool UploadStored(vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium,
    const T* data, vtkObject* reporter);
  // Every other type's scalars as floats (NaN and +-Inf cleaned): a copy,
  // but for float scalars that need no cleaning, which are read in place.
  bool UploadFloats(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  // VolumeTexture from `values` (Dimensions, `components` of `type`) and,
  // for non-null `valid`, ValidityTexture; false with an error naming the
  // texture's size when the GPU cannot hold it.
  bool CreateVolumeTexture(vtkOpenGLRenderWindow* window, int components, int type, void* values,
    unsigned char* valid, vtkObject* reporter);
  // The scalars as bricks (Bricks planned): the atlas into VolumeTexture and
  // the indirection into BrickTexture; false with an error.
  bool UploadBricks(
    vtkOpenGLRenderWindow* window, int components, int type, void* values, vtkObject* reporter);
  // Whether the GL can create the volume texture (Dimensions, `components`
  // of `type`), asked with a proxy texture; false, with ReportTooLarge()
  // through `reporter` when it is not null.
  bool VolumeFits(vtkOpenGLRenderWindow* window, int components, int type, vtkObject* reporter);
  // The error of a volume texture the GPU cannot create, naming its size
  // (`when`: what to add after the MiB).
  void ReportTooLarge(int components, int type, const char* when, vtkObject* reporter) const;
  bool UploadTable(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  bool UploadEmission(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  bool UploadScattering(vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium,
    const float* scattering, vtkObject* reporter);
  // The detail's shape when it changed; released for null.
  bool UpdateDetail(
    vtkOpenGLRenderWindow* window, const vtkTyndallDetailMedium* detail, vtkObject* reporter);
  // Every Factor-th sample of `components`-component `values` (laid out like
  // the scalars) into `texture`, created when needed; false with an error
  // naming `what`.
  bool UploadSampled(vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium,
    const float* values, int components, vtkSmartPointer<vtkTextureObject>& texture,
    const char* what, vtkObject* reporter);
  bool UploadMajorants(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  bool UploadLabels(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  bool UploadLabelRows(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);
  bool UploadComponentTables(
    vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter);

  vtkSmartPointer<vtkTextureObject> VolumeTexture;
  vtkSmartPointer<vtkTextureObject> ValidityTexture;
  vtkSmartPointer<vtkTextureObject> TransferTexture;
  vtkSmartPointer<vtkTextureObject> Transfer2DTexture;
  vtkSmartPointer<vtkTextureObject> ComponentTexture;
  vtkSmartPointer<vtkTextureObject> LabelTexture;
  vtkSmartPointer<vtkTextureObject> LabelRowsTexture;
  vtkSmartPointer<vtkTextureObject> BlockTexture;
  vtkSmartPointer<vtkTextureObject> DetailTexture;
  vtkSmartPointer<vtkTextureObject> EmissionTexture;
  vtkSmartPointer<vtkTextureObject> ScatteringTexture;
  vtkSmartPointer<vtkTextureObject> BrickTexture;
  vtkTransmittanceVolumeBricks Bricks;
  int Bricking = BRICKING_AUTO;
  int UploadedBricking = BRICKING_AUTO;
  int UploadSize = 2048; // the 3-D texture size the last upload planned for
  bool BricksAllowed = false;
  bool WideBricks = false;      // every sample of a volume past the limit, as bricks or not at all
  bool WideBricksTried = false; // the last upload tried WideBricks (its failure is remembered)
  bool UploadedBlocked = false; // another texture at the scalars' resolution (no bricks)
  bool DenseFits = true;        // whether the GL can hold the dense volume texture
  // The last upload that failed after its copy and plan (DenseFits false).
  const vtkTyndallGridMedium* FailedMedium = nullptr;
  vtkMTimeType FailedScalarsTime = 0;
  int FailedBricking = -1;
  int FailedMaximumSize = -1;
  bool FailedBlocked = false;
  vtkMTimeType DetailTime = 0;
  vtkMTimeType DetailExtinctionTime = 0; // the detail's extinction the maps last saw
  vtkTyndallMajorantGrid Majorants;
  double BlockRangeTime = 0.0;
  double MajorantTime = 0.0;
  vtkMTimeType ScalarsTime = 0;
  vtkMTimeType EmissionTime = 0;
  vtkMTimeType TableTime = 0;
  const vtkTyndallGridMedium* UploadedMedium = nullptr;
  int Dimensions[3] = { 0, 0, 0 };
  int Factor = 1;
  vtkTransmittanceVolumeTiling Tiling;
  int MaximumTextureSize = 0;
  int UploadedMaximumSize = 0;
  vtkTimeStamp ExtinctionContentTime;
  vtkMTimeType SeenExtinctionTime = 0;
  float ValueMap[2] = { 1.0f, 0.0f };
  float TextureScale[3] = { 1.0f, 1.0f, 1.0f };
  float TextureShift[3] = { 0.0f, 0.0f, 0.0f };
  float BlockScale[3] = { 1.0f, 1.0f, 1.0f };
  float BlockShift[3] = { 0.0f, 0.0f, 0.0f };
};

#endif
