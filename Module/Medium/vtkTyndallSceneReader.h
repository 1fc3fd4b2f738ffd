/**
 * @class   vtkTyndallSceneReader
 * @brief   the one reader of a scene for Tyndall's renderers: a medium and its lights
 *
 * vtkTyndallSceneReader turns (renderer, volume) into what both integrators
 * consume: the volume's vtkTyndallGridMedium (validated scalars, placement,
 * tabulated transfer functions, parameters) and the renderer's lights as
 * vtkTyndallLight. The GPU mapper (vtkTransmittanceVolumeMapper) and the CPU
 * reference (vtkSingleScatteringReference) each own one and call Update()
 * before they render, so they read the scene by the same rules:
 *
 * - only switched-on lights with a positive intensity are used, at most
 *   GetMaximumNumberOfLights() (8); further lights are ignored with a
 *   warning;
 * - lights are placed as vtkRenderer places them before rendering: with
 *   LightFollowCamera on (VTK's default), headlights at the camera looking
 *   at its focal point and camera lights through the camera's
 *   GetCameraLightTransformMatrix(); scene lights (and every light when
 *   LightFollowCamera is off) through their own transform
 *   (GetTransformedPosition/FocalPoint);
 * - a directional or spot light whose position and focal point coincide has
 *   no direction: it is ignored with a warning;
 * - in the emission-absorption model no light is used (nothing is shaded)
 *   but by a shaded slice;
 * - the renderer's environment (EnvironmentalBG, its gradient, its
 *   EnvironmentTexture) is read by vtkTyndallEnvironment's rules when the
 *   medium scatters (not a projection) and its mapper's SkyLight is on;
 * - a volume drawn in a projection blend mode (vtkTyndallProjection:
 *   maximum, minimum, average intensity, additive, slice) is not a medium:
 *   it uses no light (but a shaded slice's, vtkTyndallShading, unshadowed),
 *   has no guests and no procedural detail, and is no other volume's guest
 *   nor in a camera group;
 *   in single scattering each light's irradiance is the medium's LightScale
 *   times the light's colour;
 * - the medium is read by vtkTyndallGridMedium's rules (a particle cloud's,
 *   vtkTyndallParticleMedium, on the grid of its particles), and procedural
 *   detail (vtkTyndallDetailMedium) over it when the property has a
 *   DetailNoise;
 * - the guests, the other media the light crosses (unless the property's
 *   SceneShadows is off): every other visible vtkVolume of the renderer
 *   drawn by a vtkTransmittanceVolumeMapper, in the renderer's order, at most
 *   MaximumNumberOfGuests, each read by vtkTyndallGridMedium's rules. A
 *   guest with missing data (NaN), clipping or cropping, or procedural
 *   detail, and every guest of a scene with a coloured extinction, is left
 *   out with a warning naming the reason (the shaders' guest lookup has
 *   none of these);
 * - the camera group (the property's SceneCompositing): among the first
 *   MaximumNumberOfGuests + 1 visible Tyndall volumes of the renderer, those
 *   that can be drawn together (SceneShadows and SceneCompositing on, read
 *   as guests are, no emission array, the same lighting settings:
 *   vtkTyndallMediumParameters::SameLighting(), and mappers with the same
 *   SkyLight and SkyLightDirections) and whose world boxes overlap, directly or through
 *   others, form a group; the first of a group in the renderer's order
 *   draws it (GetCameraGuests(): the members among its guests) and the
 *   others draw nothing of their own (GetDrawnBy()). Every reader of the
 *   renderer finds the same groups, each from the volumes' own settings. A
 *   volume VTK's culler left out of the frame (its render time multiplier
 *   0: entirely outside the view) is in no group, so a group whose first
 *   volume is culled is drawn by its next one.
 *
 * The integrators read the media (GetMedia(), each a vtkTyndallMedium: the
 * volume's own first, then the guests), the GPU mapper the grids beneath
 * them (GetMedium(), GetDetail(), GetGuests()) for its textures.
 *
 * The settings of the volume and the renderer that Tyndall draws otherwise
 * than VTK 9.1's volume mappers (vtkTyndallVolumeSettings: what VTK draws
 * and Tyndall does not yet, and where VTK's shader draws other than it
 * means) are named in a warning.
 *
 * A Tyndall volume is one whose mapper is a vtkParticipatingMediumMapper
 * (the GL-free base of Tyndall's mappers).
 *
 * A warning is given once per change, not once per frame. Internal to
 * Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallSceneReader_h
#define vtkTyndallSceneReader_h

#include "TyndallMediumModule.h"    // For export macro
#include "vtkTyndallDetailMedium.h" // For the detail
#include "vtkTyndallEnvironment.h"  // For the environment
#include "vtkTyndallGridMedium.h"   // For the medium
#include "vtkTyndallLight.h"        // For the lights

#include <map>    // For std::map
#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkObject;
class vtkRenderer;
class vtkVolume;

class TYNDALLMEDIUM_EXPORT vtkTyndallSceneReader
{
public:
  vtkTyndallSceneReader();
  ~vtkTyndallSceneReader();
  vtkTyndallSceneReader(const vtkTyndallSceneReader&) = delete;
  vtkTyndallSceneReader& operator=(const vtkTyndallSceneReader&) = delete;

  /// The most lights a scene uses (the shaders' arrays).
  static constexpr int MaximumNumberOfLights = 8;

  /**
   * Reads `volume` as seen in `renderer`. Errors and warnings go through
   * `reporter`; false on error (nothing can be rendered).
   */
  bool Update(vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter);

  /**
   * The media the integrators read, each through vtkTyndallMedium: this
   * volume's own first (its detail when it has one, else its grid or particle
   * medium), then the guests in GetGuests()'s order. Empty after an error.
   */
  const std::vector<const vtkTyndallMedium*>& GetMedia() const { return this->Media; }

  /// The volume's grid medium (a particle cloud's is a vtkTyndallParticleMedium).
  const vtkTyndallGridMedium& GetMedium() const { return *this->Medium; }
  /// The procedural detail over the medium (Enabled() when the property has a DetailNoise).
  const vtkTyndallDetailMedium& GetDetail() const { return this->Detail; }
  const std::vector<vtkTyndallLight>& GetLights() const { return this->Lights; }
  /**
   * The renderer's environment (vtkTyndallEnvironment): black unless the
   * medium scatters (a projection and the emission-absorption model are lit
   * by no sky) and its mapper's SkyLight is on.
   */
  const vtkTyndallEnvironment& GetEnvironment() const
  {
    return this->SkyLit ? this->Environment : this->NoSky;
  }

  /**
   * The sky as directional lights for the map-based frame and its CPU
   * twin (vtkTyndallSkyLights): at most the mapper's SkyLightDirections, in
   * the slots GetLights() leaves of MaximumNumberOfLights; empty without a
   * sky (GetEnvironment() black). They light the medium's scattering and
   * gradient shading; the path tracers sample the sky instead.
   */
  const std::vector<vtkTyndallLight>& GetSkyLights() const
  {
    return this->SkyLit ? this->SkyLights : this->NoSkyLights;
  }

  /**
   * The map-based frame's ambient radiance per channel: the medium's
   * AmbientIntensity, plus the sky's mean radiance where no sky light
   * carries the sky (SkyLightDirections 0, or the renderer's lights take
   * every slot). The path tracers sample the sky and take AmbientIntensity
   * alone.
   */
  void GetMapAmbient(double ambient[3]) const;

  /**
   * The sky's mean radiance per channel that the map-based frame's gradient
   * shading takes as light from every direction
   * (vtkTyndallShading::AddSkyMean()): where no sky light carries the sky,
   * as GetMapAmbient() adds it; else 0 (the sky's lights light the shading).
   */
  void GetShadingSkyMean(double mean[3]) const;

  /// The most guests a medium is lit through (the shaders' guest arrays).
  static constexpr int MaximumNumberOfGuests = 3;

  ///@{
  /// The guests (see the class description) and their volumes, in the same order.
  const std::vector<const vtkTyndallGridMedium*>& GetGuests() const { return this->Guests; }
  const std::vector<vtkVolume*>& GetGuestVolumes() const { return this->GuestVolumes; }
  ///@}

  ///@{
  /**
   * The camera group (see the class description): the indices into
   * GetGuests() of the guests this volume's camera rays also sample (empty
   * unless this volume draws a group), and the volume that draws this one's
   * medium (null unless another does).
   */
  const std::vector<int>& GetCameraGuests() const { return this->CameraGuests; }
  vtkVolume* GetDrawnBy() const { return this->DrawnBy; }
  ///@}

  /// Whether a volume is drawn by a Tyndall mapper (a vtkParticipatingMediumMapper).
  static bool IsTyndallVolume(vtkVolume* volume);

  /**
   * Whether the renderer's volume `entry` is the volume being drawn. It is
   * when it is the same object, and also when it shares the drawn volume's
   * mapper, property and placement (matrix): a level-of-detail prop such as
   * ParaView's vtkPVLODVolume sits in the renderer's collection and draws an
   * inner vtkVolume of its own with the same mapper, property and matrix,
   * and the two are one medium (counted as another volume, the entry made
   * the mapper read its own medium as a guest, re-entering its own scene
   * update, and warn about several volumes). Volumes that share only a
   * mapper are two media.
   */
  static bool IsDrawnVolume(vtkVolume* entry, vtkVolume* volume);

private:
  void UpdateLights(vtkRenderer* renderer, vtkObject* reporter);
  void UpdateGuests(vtkRenderer* renderer, vtkVolume* volume, bool projection, vtkObject* reporter);
  void UpdateCameraGroup(vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter);
  /// Warns when this volume (volumes[me]) overlaps one it cannot be drawn with.
  void WarnLayers(const std::vector<vtkVolume*>& volumes,
    const std::vector<const vtkTyndallGridMedium*>& media, const std::vector<size_t>& group,
    size_t me, vtkObject* reporter);

  /// One slot per guest, kept between frames (its medium's caches) while the slot's volume stays.
  struct GuestSlot
  {
    vtkVolume* Volume = nullptr;
    std::unique_ptr<vtkTyndallGridMedium> Medium;
  };
  std::vector<GuestSlot> GuestSlots;
  std::vector<const vtkTyndallGridMedium*> Guests;
  std::vector<vtkVolume*> GuestVolumes;
  std::string LastGuestWarning;
  std::vector<int> CameraGuests;
  vtkVolume* DrawnBy = nullptr;
  std::string LastCameraWarning;

  // A grid medium of the kind `volume`'s mapper draws in `medium` (a new one unless it is).
  static void MakeMedium(vtkVolume* volume, std::unique_ptr<vtkTyndallGridMedium>& medium);

  std::unique_ptr<vtkTyndallGridMedium> Medium;
  vtkTyndallDetailMedium Detail;
  std::vector<const vtkTyndallMedium*> Media;
  std::vector<vtkTyndallLight> Lights;
  vtkTyndallEnvironment Environment;
  vtkTyndallEnvironment NoSky;              // black
  bool SkyLit = false;                      // GetEnvironment() is Environment
  std::vector<vtkTyndallLight> SkyLights;   // the Environment's, cut for SkyLightCount
  std::vector<vtkTyndallLight> NoSkyLights; // empty
  int SkyLightCount = 0;
  vtkMTimeType SkyLightSerial = 0; // the Environment's serial SkyLights were cut from
  void UpdateSkyLights(int count);
  std::string LastLightWarning;
  /// Warns once per change of the settings VTK draws and Tyndall does not
  /// (vtkTyndallVolumeSettings), per volume (a mapper may draw several).
  void WarnNotDrawn(vtkVolume* volume, vtkObject* reporter);
  std::map<vtkVolume*, std::string> LastNotDrawnWarning; // keys only compared
};

#endif
