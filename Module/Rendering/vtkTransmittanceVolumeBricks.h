/**
 * @class   vtkTransmittanceVolumeBricks
 * @brief   a sparse volume's scalars on the GPU as the bricks that vary, in an atlas
 *
 * A sparse volume (an OpenVDB cache densified over its box, a CT with air
 * around the body) spends most of a dense 3-D texture on regions where the
 * scalars hold one value (OpenVDB's background). Cut into bricks of
 * BrickSize^3 samples, a brick whose samples, and the first samples of its
 * neighbours along +x, +y and +z (what linear filtering reads past its
 * last sample), are all one value is constant: Plan() counts them, and the
 * volume is stored as
 *
 * - an atlas: a 3-D texture of slots of (BrickSize + 1)^3 texels, one slot
 *   for each brick that varies (its samples and that one-sample apron,
 *   copied from the data) and one for each distinct constant value (at
 *   most MaximumConstants; bricks of further constants get slots of their
 *   own), in the data's own type;
 * - an indirection texture: one texel per brick (RGB, 8-bit normalized:
 *   3 bytes), the brick's slot (x, y, z) in the atlas, which holds at most
 *   MaximumSlotsPerAxis slots along each axis (256^3 slots: 8.6 billion
 *   samples that vary, more than any GL's 3-D texture).
 *
 * A sample's volume texture coordinate t (texel i's centre at (i + 0.5) /
 * n, as for a dense volume) maps to the atlas by MapCoordinate(), which the
 * shaders compute the same way (tyndallBrickedTexel() in
 * vtkTransmittanceCommonFS.glsl): the sample coordinate v = t n - 0.5 is
 * clamped to [0, n - 1] (clamp-to-edge), its brick is b = floor(v /
 * BrickSize) (the last brick on each axis holds its end), and the atlas
 * texel is slot (BrickSize + 1) + v - b BrickSize. Linear and nearest
 * filtering of the atlas then read exactly the samples the dense texture
 * reads: every sample a brick's filtering needs lies in its slot. So the
 * GPU holds the varying bricks and a few bytes per brick, not the box.
 *
 * Plan() declines (the volume stays dense) when the atlas and the
 * indirection would take more than `maximumShare` of the dense texture's
 * bytes, or do not fit the GL's 3-D texture size.
 *
 * Internal to Tyndall::Rendering; not wrapped.
 */

#ifndef vtkTransmittanceVolumeBricks_h
#define vtkTransmittanceVolumeBricks_h

#include "TyndallRenderingModule.h" // For export macro

#include <cstddef> // For size_t
#include <vector>  // For std::vector

class vtkTextureObject;

class TYNDALLRENDERING_EXPORT vtkTransmittanceVolumeBricks
{
public:
  /// A brick's samples per side (the slots hold one more).
  static constexpr int BrickSize = 8;
  /// The most constant values given one shared slot each.
  static constexpr int MaximumConstants = 8;
  /// The most slots along an atlas axis (an 8-bit indirection channel).
  static constexpr int MaximumSlotsPerAxis = 256;

  /**
   * Finds the constant bricks of `values` (`dims` samples, x fastest,
   * `components` values of `valueSize` bytes each; compared byte for byte)
   * and lays out the atlas in slots of at most `maximumSize` texels per
   * side. True when the bricks take at most `maximumShare` of the dense
   * texture's bytes (1: whenever they fit); false otherwise (the plan is
   * then cleared: IsBricked() false).
   */
  bool Plan(const int dims[3], int components, int valueSize, const void* values, int maximumSize,
    double maximumShare);

  /// Whether a plan is in place (Plan() succeeded, Clear() not called since).
  bool IsBricked() const { return this->Bricked; }
  void Clear();

  ///@{
  /// The plan: bricks per axis, slots in use, slots per axis of the atlas and its texels.
  const int* GetBrickCounts() const { return this->BrickCounts; }
  int GetSlots() const { return this->Slots; }
  const int* GetSlotCounts() const { return this->SlotCounts; }
  const int* GetAtlasDimensions() const { return this->AtlasDimensions; }
  ///@}

  ///@{
  /// Bytes on the GPU: the atlas, the indirection texture, and a dense texture's.
  size_t GetAtlasBytes() const;
  size_t GetIndirectionBytes() const;
  size_t GetDenseBytes() const;
  ///@}

  /**
   * The shaders' uniforms: the volume's samples, the bricks per axis and
   * the atlas's texels, as floats.
   */
  void GetUniforms(float dims[3], float brickCounts[3], float atlasDims[3]) const;

  /**
   * The CPU twin of the shaders' tyndallBrickedTexel(): the atlas texture
   * coordinate of volume texture coordinate `t`.
   */
  void MapCoordinate(const double t[3], double texel[3]) const;

  /**
   * The atlas's texels (AtlasDimensions, x fastest, the values' bytes) from
   * `values` (Plan()'s): what Upload() sends; for tests.
   */
  bool BuildAtlas(const void* values, std::vector<unsigned char>& atlas) const;

  /**
   * Creates `atlas` (the data's `components` of VTK `type`) and
   * `indirection` (RGB unsigned char, read nearest) with the planned
   * layout, their context current, from `values` (Plan()'s). False when
   * the GL cannot create them.
   */
  bool Upload(
    vtkTextureObject* atlas, vtkTextureObject* indirection, int type, const void* values) const;

private:
  // Brick b's slot, and each constant's first brick (its samples' source).
  std::vector<int> BrickSlot;
  std::vector<int> SlotBrick;
  int Dimensions[3] = { 1, 1, 1 };
  int BrickCounts[3] = { 1, 1, 1 };
  int SlotCounts[3] = { 1, 1, 1 };
  int AtlasDimensions[3] = { 1, 1, 1 };
  int Slots = 0;
  int Components = 1;
  int ValueSize = 1;
  bool Bricked = false;
};

#endif
