/**
 * @class   vtkTransmittanceFrame
 * @brief   what every pass of vtkTransmittanceVolumeMapper reads during one Render()
 *
 * The mapper fills one frame per Render(), after vtkTyndallSceneReader has read the
 * scene and vtkTransmittanceMediumTextures has uploaded the medium: the GL
 * context, the medium and its box, the integrator's settings, and the lights
 * with the frustum of each light's map and the method each light really
 * uses (a positional light inside the box has no frustum and falls back to
 * brute force). SetMediumUniforms() sets the uniforms that every pass's
 * shader shares (vtkTransmittanceCommonFS.glsl).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceFrame_h
#define vtkTransmittanceFrame_h

#include "TyndallRenderingModule.h"       // For export macro
#include "vtkSmartPointer.h"              // For vtkSmartPointer
#include "vtkTransmittanceShaderSource.h" // For vtkTransmittanceShaderSource::Variant
#include "vtkTyndallFootprint.h"          // For vtkTyndallFootprint
#include "vtkTyndallLight.h"              // For vtkTyndallLight

#include <vector> // For std::vector

class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;
class vtkShaderProgram;
class vtkTransmittanceLightFrustum;
class vtkTransmittanceMapReducer;
class vtkTransmittanceMediumAdapter;
class vtkTransmittanceMediumTextures;
class vtkTextureObject;
class vtkTyndallDetailMedium;
class vtkTyndallGridMedium;
class vtkTyndallMedium;
class vtkTyndallParticles;
class vtkTyndallSceneReader;
class vtkTyndallEnvironment;

class TYNDALLRENDERING_EXPORT vtkTransmittanceFrame
{
public:
  /// One light as the passes use it.
  struct Light
  {
    vtkTyndallLight Source;
    /// The method of this light: the mapper's, or BRUTE_FORCE without a frustum.
    int Method = 0;
    bool HasFrustum = false;
    vtkSmartPointer<vtkTransmittanceLightFrustum> Frustum;
  };

  /// The integrator's settings (the mapper's).
  struct Settings
  {
    int Method = 0;
    int Coefficients = 8;
    int MapSize = 256;
    int LightSampleCount = 128;
    double AdaptiveThreshold = 0.01;
    double SampleDistance = 0.0;
    bool Jitter = true;
    bool SkipEmptySpace = true;
    /// Longest side of the transmittance cache's lattice; 0: no cache.
    int CacheSize = 0;
    /**
     * Several processes draw the picture (vtkTransmittanceMapReducer): the
     * reducer, and the world box of the whole medium (xmin, xmax, ymin,
     * ymax, zmin, zmax) that every process fits its maps to. Null and
     * unused in one process.
     */
    vtkTransmittanceMapReducer* Reducer = nullptr;
    /// Composited by an 8-bit compositor (ShaderSource's OpacityCoversRadiance).
    bool OpacityCoversRadiance = false;
    bool HasMapBounds = false;
    double MapBounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
    /// The display transform (vtkTyndallToneMapping): stops, curve, sRGB.
    double Exposure = 0.0;
    int ToneCurve = 0;
    bool EncodeSRGB = false;
  };

  /// A guest (vtkTyndallSceneReader::GetGuests()): another medium the light crosses.
  struct Guest
  {
    const vtkTyndallGridMedium* Medium = nullptr;
    /// Its scalars and table (its own mapper's).
    const vtkTransmittanceMediumTextures* Textures = nullptr;
    /// World -> its box as [0, 1]^3, column-major.
    float WorldToBox[16];
    /**
     * Whether the camera rays sample it too (vtkTyndallSceneReader::
     * GetCameraGuests(): it overlaps this medium and is drawn with it).
     */
    bool Camera = false;
  };

  /**
   * A particle medium whose share of the extinction maps is splatted
   * (vtkTransmittanceSplatPass) instead of marched: the frame's method is
   * ETM and the medium's mapper splats (vtkTyndallGridMedium::
   * GetSplatParticles()).
   */
  struct Splat
  {
    const vtkTyndallParticles* Particles = nullptr;
    /// World <-> the particles' data coordinates, column-major.
    float WorldToData[16];
    float DataToWorld[16];
    double DensityScale = 1.0;
    /// The medium it is: -1 the frame's own, else the guest's index.
    int Guest = -1;
  };

  /**
   * Fills the frame. `lights` are reused between frames (their frusta).
   * `guestTextures` are the textures of the scene's guests, in their order.
   */
  void Prepare(vtkRenderer* renderer, vtkOpenGLRenderWindow* window,
    const vtkTyndallSceneReader& scene, const vtkTransmittanceMediumTextures& textures,
    const std::vector<const vtkTransmittanceMediumTextures*>& guestTextures,
    const Settings& settings);

  /**
   * Sets the uniforms of the light maps' lookup (vtkTransmittanceLightMapFS.glsl:
   * the box, the extinction colour, the light frusta) on `program`.
   */
  void SetLightMapUniforms(vtkShaderProgram* program) const;

  /// Sets the shared uniforms (the medium's, its adapter's; clipping, guests, light frusta).
  void SetMediumUniforms(vtkShaderProgram* program) const;

  /**
   * Sets the uniforms of the guests the camera samples (TYNDALL_CAMERA_GUESTS:
   * which guests are drawn with this medium, the coloured particle clouds'
   * scattering grids); `every`: the program samples every guest at times
   * (the path tracer's scattered flights), so every coloured cloud's colour
   * is read. SetMediumUniforms() sets them (`every` false) when the frame
   * has camera guests.
   */
  void SetCameraGuestUniforms(vtkShaderProgram* program, bool every) const;

  /**
   * Sets the sky's terms of the camera rays' light (vtkTransmittanceRayCastFS.
   * glsl's ambient and numberOfSkyLights, and gradient shading's
   * shadingSkyMean): the map-based frame's, MapAmbient, the SkyLights lights
   * and ShadingSkyMean; or, `sampled` (the path tracer, which samples the
   * sky), the medium's AmbientIntensity and no sky light.
   */
  void SetSkyUniforms(vtkShaderProgram* program, bool sampled) const;

  /**
   * Sets the lights' uniforms (vtkTransmittanceLightsFS.glsl, and the
   * camera rays' irradiances and methods) on `program`, and with the
   * medium's gradient shading (vtkTyndallShading) its coefficients.
   */
  void SetLightUniforms(vtkShaderProgram* program) const;

  /**
   * Sets the display transform's uniforms (vtkTransmittanceOutputFS.glsl):
   * the mapper's where `toWindow` (the program draws into the renderer's
   * frame buffer), else the identity (an image of the mapper's own). With
   * `background` false the background is taken as black (targets that are
   * not drawn over the renderer's background: depth peeling's).
   */
  void SetOutputUniforms(vtkShaderProgram* program, bool toWindow, bool background = true) const;

  /**
   * Sets the camera ray's uniforms (vtkTransmittanceCameraRayFS.glsl):
   * ndcToWorld from the renderer's active camera, depthTexture, and
   * fragToWindow for an image of `width` x `height` pixels over the
   * renderer's viewport `viewport` (x, y, width, height in the window;
   * `direct`: the quad's pixels are the window's).
   */
  void SetCameraUniforms(vtkShaderProgram* program, vtkTextureObject* depth, bool direct,
    const int viewport[4], int width, int height) const;

  /**
   * The shaders' variant for this frame (vtkTransmittanceShaderSource): the
   * medium's switches (its adapter's DeclareSwitches()), empty-space
   * skipping when the settings ask for it, the guests.
   */
  vtkTransmittanceShaderSource::Variant GetShaderVariant() const;

  /**
   * The camera rays' colour switches of this frame's medium alone (its
   * adapter's DeclareColorSwitches(), on an empty variant): whether it
   * emits from its table (Emission) or from an array (EmissionArray).
   */
  vtkTransmittanceShaderSource::Variant GetColorVariant() const;

  /**
   * GetShaderVariant() with the map lookup of the frame's method compiled
   * in (coefficients, ETM or TFM reconstruction, adaptive bounds), for the
   * shaders that read the maps.
   */
  vtkTransmittanceShaderSource::Variant GetMapVariant() const;

  /// Sets the map lookup's uniforms (GetMapVariant()) for `maps` of `slices` slices (all sets).
  void SetMapUniforms(vtkShaderProgram* program, vtkTextureObject* maps, int slices) const;

  /**
   * Sets densityScale and guestDensity for the map build's march: the
   * medium's and the guests' density scales, 0 for those that are splatted.
   */
  void SetMarchedDensities(vtkShaderProgram* program) const;

  /// Whether every medium of the frame is splatted (the march adds nothing).
  bool AllSplatted() const { return this->Splats.size() == this->Guests.size() + 1; }

  /// Whether some light uses a map method.
  bool NeedsMaps() const;

  /// Whether the camera rays sample guests too (some Guest::Camera).
  bool HasCameraGuests() const;

  /**
   * The camera-ray step: SampleDistance, or half the smallest spacing and
   * the medium's finest feature (vtkTyndallMedium::GetFinestFeature());
   * for isosurfaces the smallest spacing (VTK's automatic step).
   * With procedural detail vtkTyndallDetailMedium::GetCameraStep() at
   * `nearestPixel` (the narrowest pixel of the image drawn: NearestPixel,
   * times a reduced image's reduction), at most half the smallest spacing
   * and half GetLightingWidth(): a camera sample stands for its step's
   * exact mean of the waves, so the step follows what else varies along
   * the ray, the shape and the light; where the light carries every wave
   * (a brute-force light) or the noise often dips below 0, the step
   * resolves the waves the camera rays evaluate (two samples per period of
   * the finest where its amplitude is small, four where fine waves are
   * strong).
   */
  double GetStepLength(double nearestPixel) const;

  /**
   * The finest scale across the light on which the camera samples' light
   * varies: the narrowest texel of the lights' maps
   * (vtkTransmittanceLightFrustum::GetTexelWidth(); along the light a map
   * resolves its coefficients' and adaptive bounds' scale, which the step's
   * cap at half the spacing covers as for a voxel grid); 0 where a light's
   * transmittance is solved at each sample (BruteForce, or a light without
   * a map), which shows every wave of procedural detail; 1e300 without
   * shadowed lights.
   */
  double GetLightingWidth() const;

  /**
   * Whether the camera samples of procedural detail stand for their step's
   * means of the waves (vtkTyndallDetailMedium::UsesStepMeans()): the step
   * is then longer than the waves' own.
   */
  bool UsesDetailStepMeans(double nearestPixel) const;

  /**
   * The world width of a pixel along the camera rays (vtkTyndallFootprint),
   * and its narrowest over the medium's box in this frame.
   */
  vtkTyndallFootprint Footprint;
  double NearestPixel = 0.0;

  vtkRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr;
  vtkOpenGLState* State = nullptr;
  /// The grid of the medium (its own, or the one its procedural detail multiplies).
  const vtkTyndallGridMedium* Medium = nullptr;
  /// The procedural detail over the medium (Enabled() or not).
  const vtkTyndallDetailMedium* Detail = nullptr;
  /**
   * The frame's own medium (vtkTyndallSceneReader::GetMedia()'s first) and
   * its GPU adapter: its switches, uniforms and GLSL.
   */
  const vtkTyndallMedium* OwnMedium = nullptr;
  const vtkTransmittanceMediumAdapter* Adapter = nullptr;
  const vtkTransmittanceMediumTextures* Textures = nullptr;
  /**
   * The renderer's sky (vtkTyndallSceneReader::GetEnvironment()): the path
   * tracer samples it; the map-based frame has it as SkyLights lights (or
   * its mean radiance in MapAmbient).
   */
  const vtkTyndallEnvironment* Environment = nullptr;
  /// The map-based frame's ambient radiance (vtkTyndallSceneReader::GetMapAmbient()).
  double MapAmbient[3] = { 0.0, 0.0, 0.0 };
  /// The sky's mean the map-based frame's gradient shading sees (GetShadingSkyMean()).
  double ShadingSkyMean[3] = { 0.0, 0.0, 0.0 };
  Settings Integrator;
  /**
   * Whether the frame buffer holds the renderer's background under the
   * volume (its colour or gradient: no transparent clear, kept colour
   * buffer, textured background or visible skybox); SetOutputUniforms()'s
   * display transform composites over it. Found once per frame in Prepare().
   */
  bool BackgroundIsKnown = false;
  /// ceil(Coefficients / 4) (+1 for the adaptive methods) layers per light.
  int Layers = 0;
  /// The adaptive methods' bounds layer within a light's layers, else -1.
  int BoundsLayer = -1;
  /**
   * Sets of maps: 3 (one per channel, each light's layers per set) for the
   * transmittance-function methods with a coloured extinction, whose
   * reconstruction error near T = 0 a channel's power T^e would magnify;
   * else 1 (an extinction map gives every channel exactly: exp(-e tau)).
   */
  int MapSets = 1;
  /**
   * The lights with their maps: the renderer's (vtkTyndallSceneReader::
   * GetLights()), then the sky's SkyLights (GetSkyLights()), which light
   * the medium's scattering and gradient shading.
   */
  std::vector<Light> Lights;
  int SkyLights = 0;
  /// The renderer's lights: Lights' first.
  int GetSceneLights() const { return static_cast<int>(this->Lights.size()) - this->SkyLights; }
  double Corners[24];
  /// The world diagonal of the camera rays' box (CameraBoxExtents).
  double Diagonal = 1.0;
  /// The smallest world spacing of the medium and its camera guests.
  double MinimumSpacing = 1.0;
  /// World -> the box as [0, 1]^3, column-major for glUniformMatrix.
  float WorldToBox[16];
  /// Its inverse (column-major) and the box's world edge lengths.
  float BoxToWorld[16];
  double BoxExtents[3] = { 1.0, 1.0, 1.0 };
  /// The guests, whose extinction the map build and brute-force lights add to the medium's.
  std::vector<Guest> Guests;
  /// The media splatted into the extinction maps (see Splat).
  std::vector<Splat> Splats;
  /**
   * The light maps' box, whose corners the lights' frusta are fitted to:
   * the medium's box, or with guests the world-axis box around every
   * medium's box. Its corners and world -> [0, 1]^3 (column-major).
   */
  double MapCorners[24];
  float WorldToMapBox[16];
  /**
   * The camera rays' box: the medium's box, or with camera guests the
   * world-axis box around the medium's and theirs. World -> [0, 1]^3, its
   * inverse (column-major) and its world edge lengths; the transmittance
   * cache's lattice spans it.
   */
  float WorldToCameraBox[16];
  float CameraBoxToWorld[16];
  double CameraBoxExtents[3] = { 1.0, 1.0, 1.0 };

private:
  void SetClipUniforms(vtkShaderProgram* program) const;
  void SetGuestUniforms(vtkShaderProgram* program) const;
  void PrepareMapBox();
  void PrepareFootprint();
  void PrepareSplats();
  void FitAxisBox(bool cameraGuestsOnly, double corners[24], float worldToBox[16],
    float boxToWorld[16], double extents[3]) const;
};

#endif
