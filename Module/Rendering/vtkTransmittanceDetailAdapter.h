/**
 * @class   vtkTransmittanceDetailAdapter
 * @brief   the GPU side of a vtkTyndallDetailMedium: its grid's adapter, and the cosine waves
 *
 * Procedural detail multiplies a grid (vtkTyndallDetailMedium::GetGrid(),
 * itself drawn by its own adapter, e.g. a coloured particle cloud's) by a
 * sum of cosine waves. It adds to its grid's: the pre-classified shape as
 * a float 3-D texture (detailShapeTexture), the switch
 * TYNDALL_DETAIL_GROUPS (groups of four waves, 0: none), the waves as
 * GLSL constants (detailKx .. detailDecay, WaveConstants(): literal
 * numbers, which llvmpipe folds into the code where uniform arrays cost it
 * three times the rest of a sample) and its GLSL,
 * vtkTransmittanceDetailFS.glsl (the closed-form optical depth and free
 * flights of vtkTyndallDetailMedium, on the GPU). Its brute-force light
 * march walks the shape's cells: GetLightMarchIterations().
 *
 * Camera rays (DeclareCameraSwitches()) filter the waves by the pixel's
 * footprint (TYNDALL_DETAIL_FILTER; vtkParticipatingMediumProperty::
 * DetailFilterWidth) and evaluate only the first TYNDALL_DETAIL_CAMERA_GROUPS
 * groups: the waves, coarsest first, that a pixel as narrow as the frame's
 * narrowest over the volume keeps (vtkTyndallDetailMedium::GetLiveWaves()).
 *
 * Internal to Tyndall::Rendering.
 * @sa vtkTransmittanceMediumAdapter
 */

#ifndef vtkTransmittanceDetailAdapter_h
#define vtkTransmittanceDetailAdapter_h

#include "vtkTransmittanceMediumAdapter.h"

#include <string> // For std::string
#include <vector> // For std::vector

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
  void DeclareCameraSwitches(
    const vtkTyndallMedium& medium, double nearestPixel, Variant& variant) const override;
  void SetUniforms(vtkShaderProgram* program, const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures) const override;
  /// The cells of the closed form's walk along the ray (its wave loops are unrolled).
  double GetLightMarchIterations(const vtkTyndallMedium& medium, double gridMarch) const override;

  /**
   * The waves of `detail` as the GLSL constant arrays of
   * vtkTransmittanceDetailFS.glsl, in groups of four (the unused waves of
   * the last group have amplitude 0).
   */
  static std::string WaveConstants(const vtkTyndallDetailMedium& detail);

  /**
   * The most levels of the footprint filter a camera sample climbs from
   * one group's factor to the next's by powers of 1.5 (two operations
   * each); a wider gap takes an exponential of its own. The shader's
   * TYNDALL_DETAIL_FILTERED_GROUP must climb this many.
   */
  static constexpr int MaximumLevelSteps = 5;
  static_assert(MaximumLevelSteps == 5,
    "TYNDALL_DETAIL_FILTERED_GROUP in vtkTransmittanceDetailFS.glsl climbs five levels");

  /**
   * The most levels climbed by powers of 1.5 after an exponential before
   * the next group takes its own: each level multiplies the float's
   * relative error by 1.5, and a factor that rounds to 1 stays 1 (12
   * levels: 1.5^12 = 130, the factor within 1e-5 of the CPU's).
   */
  static constexpr int MaximumChainedLevels = 12;

  /**
   * Per group of four waves (vtkTyndallDetailMedium::Wave::FilterLevel):
   * the levels its footprint factor climbs from the group before's (0: the
   * same level; each a power of 1.5), or MaximumLevelSteps + 1 where the
   * group takes its own exponential (the first group, a group at level -1,
   * a gap wider than MaximumLevelSteps, or more than MaximumChainedLevels
   * since the last exponential). The shader's detailLevelSteps.
   */
  static std::vector<int> LevelSteps(const vtkTyndallDetailMedium& detail);

  /**
   * The shader's detailDecay of group `group`: exp2(decay pixel^2) =
   * exp(-FilterK2 (width pixel)^2 / 2), FilterK2 the level of the group's
   * waves and width the filter's (vtkTyndallDetailMedium).
   */
  static float FilterDecay(const vtkTyndallDetailMedium& detail, int group);

private:
  // The adapter of the grid under the detail.
  const vtkTransmittanceMediumAdapter& GridAdapter(const vtkTyndallDetailMedium& detail) const;
  Lookup GridLookup;
};

#endif
