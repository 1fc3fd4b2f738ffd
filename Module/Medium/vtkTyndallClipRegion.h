/**
 * @class   vtkTyndallClipRegion
 * @brief   the part of a medium that its mapper's clipping planes and cropping keep
 *
 * vtkTyndallClipRegion reads a volume mapper's clipping planes
 * (vtkAbstractMapper::GetClippingPlanes(), world coordinates; a point is
 * kept where n . (x - origin) >= 0 for every plane, VTK's convention, at
 * most MaximumPlanes of them) and cropping (vtkVolumeMapper's Cropping,
 * CroppingRegionPlanes in the input's data coordinates and
 * CroppingRegionFlags, one bit per region of the 3 x 3 x 3 split, region
 * i + 3 j + 9 k). Outside the region the medium is empty: for camera rays
 * and for the light, so a clipped-away part casts no shadow
 * (Documentation/rendering-model.md, "Clipping and cropping"). Both
 * renderers test the same points: the GPU in world coordinates (the planes
 * and the world -> data matrix as uniforms), the CPU in field index
 * coordinates (InsideIndex()).
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallClipRegion_h
#define vtkTyndallClipRegion_h

#include "TyndallMediumModule.h" // For export macro

#include <array>  // For std::array
#include <vector> // For std::vector

class vtkObject;
class vtkVolume;

class TYNDALLMEDIUM_EXPORT vtkTyndallClipRegion
{
public:
  /// The most clipping planes used (VTK's GPU mappers take 6 too).
  static constexpr int MaximumPlanes = 6;

  /**
   * Reads `volume`'s mapper's clipping planes and cropping;
   * `indexToWorld` and `indexToData` (row-major 4x4) place the medium's
   * field index space. Returns true when the region changed. Planes beyond
   * MaximumPlanes are ignored with a warning through `reporter`.
   */
  bool Update(vtkVolume* volume, const double indexToWorld[16], const double indexToData[16],
    vtkObject* reporter);

  /// Whether anything is clipped or cropped.
  bool Enabled() const { return !this->WorldPlanes.empty() || this->Cropping; }

  /// Whether the field index point p is kept.
  bool InsideIndex(const double p[3]) const;

  ///@{
  /**
   * For the shaders: the planes as (n, d) with n . x + d >= 0 kept (world),
   * whether cropping is on, its planes (data coordinates), flags and the
   * world -> data matrix (row-major 4x4).
   */
  const std::vector<std::array<double, 4>>& GetWorldPlanes() const { return this->WorldPlanes; }
  bool GetCropping() const { return this->Cropping; }
  const double* GetCroppingPlanes() const { return this->CroppingPlanes; }
  int GetCroppingFlags() const { return this->CroppingFlags; }
  const double* GetWorldToData() const { return this->WorldToData; }
  ///@}

  /// Everything the region depends on, for the caches' keys.
  const std::vector<double>& GetKey() const { return this->Key; }

private:
  std::vector<std::array<double, 4>> WorldPlanes;
  std::vector<std::array<double, 4>> IndexPlanes;
  bool Cropping = false;
  double CroppingPlanes[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  int CroppingFlags = 0;
  double WorldToData[16];
  double IndexToData[16];
  std::vector<double> Key;
};

#endif
