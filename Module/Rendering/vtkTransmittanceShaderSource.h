/**
 * @class   vtkTransmittanceShaderSource
 * @brief   the GLSL of vtkTransmittanceVolumeMapper's passes, with their constants injected
 *
 * The shaders live in glsl/*.glsl, embedded at build time. Every pass's
 * fragment shader is vtkTransmittanceCommonFS.glsl followed by the pass's
 * own file; the line `//TYNDALL::Constants` of the common file becomes the
 * #defines of the constants the shaders share with C++, each taken from its
 * one C++ definition:
 *
 * - TYNDALL_MAX_LIGHTS: vtkTyndallSceneReader::MaximumNumberOfLights;
 * - TYNDALL_MAX_COEFFICIENTS, TYNDALL_COEFFICIENTS_PER_LAYER:
 *   vtkTransmittanceMapMath::MapLimits;
 * - TYNDALL_NONE .. TYNDALL_ADAPTIVE_ETM:
 *   vtkTransmittanceMapMath::TransmittanceMethods;
 * - TYNDALL_TABLE_ALBEDO_ROW, TYNDALL_TABLE_EMISSION_ROW,
 *   TYNDALL_TABLE_GRADIENT_ROW: the texture rows of
 *   vtkTyndallTransferTable::GetTexture(), TYNDALL_TABLE_SIZE its entries;
 * - TYNDALL_NO_OCCLUDER: the occlusion texture's "no opaque surface";
 * - TYNDALL_VIEW_TERMINATION: camera rays stop below this transmittance;
 * - TYNDALL_PI;
 *
 * and the variant switches (Variant), compile-time rather than uniforms,
 * those that describe the medium declared by its vtkTransmittanceMediumAdapter:
 * drivers such as llvmpipe run both sides of a uniform branch's texture
 * fetch, and one more 3-D fetch per sample costs 15 to 45 % of a frame:
 *
 * - TYNDALL_MISSING_DATA: 1 when the medium has missing data (NaN voxels,
 *   vtkTransmittanceMediumTextures' validity texture), 0 otherwise;
 * - TYNDALL_CLIP: 1 when the mapper's clipping planes or cropping cut the
 *   medium (vtkTyndallClipRegion; TYNDALL_MAX_CLIP_PLANES planes at most);
 * - TYNDALL_SKIP_EMPTY: 1 when camera rays and map builds skip empty blocks
 *   of the majorant grid (vtkTyndallMajorantGrid), 0 otherwise;
 * - TYNDALL_DETAIL_GROUPS: groups of four cosine waves of the medium's
 *   procedural detail (0: none), with TYNDALL_DETAIL_FOR_GROUPS(X) expanding
 *   to X(0) .. X(groups - 1), and vtkTransmittanceDetailFS.glsl in place of
 *   the common file's `//TYNDALL::Medium` line (Variant::MediumCode);
 * - TYNDALL_DETAIL_SAMPLES: camera rays through procedural detail draw this
 *   many free-flight distances per pixel in closed form instead of marching
 *   (0: they march), each solved in at most TYNDALL_DETAIL_SOLVE_ITERATIONS
 *   Newton-bisection steps (DetailSolveIterations);
 * - the camera rays' TYNDALL_MAP_COEFFICIENTS (coefficients a map lookup
 *   reads, in TYNDALL_MAP_LAYERS layers; 0 when no light has a map),
 *   TYNDALL_MAP_EXTINCTION (the reconstruction of the ETM or the TFM
 *   family), TYNDALL_LIGHT_CACHE (map lights read the transmittance cache
 *   of vtkTransmittanceLightCachePass instead), TYNDALL_ADAPTIVE_MAPS (the bounds layer),
 * TYNDALL_GUESTS (other media the light crosses, with TYNDALL_FOR_GUESTS(X)
 * expanding to X(0) .. X(guests - 1): their extinction joins the medium's in
 * the map build and the brute-force light march),
 * TYNDALL_OCCLUSION (opaque occluders), TYNDALL_EMISSION, TYNDALL_BRUTE_FORCE_LIGHTS (a light
 * marches to the light), TYNDALL_EMISSION_ARRAY (emission from a separate array,
 * vtkTyndallGridMedium::GetEmissionValues()) and TYNDALL_OCTAVES (multiple-scattering octaves, 1:
 * none): only what the frame uses is compiled in (a None frame fetched 6 textures per sample, all
 * but 2 of them unused, and ran a masked brute-force light march, before).
 *
 * - TYNDALL_GRADIENT_OPACITY: a plain property's gradient opacity
 *   multiplies the medium's extinction (every pass), read from the table's
 *   row TYNDALL_TABLE_GRADIENT_ROW (TYNDALL_TABLE_SIZE entries);
 * - TYNDALL_SHADING (RAY_CAST only): a plain property's gradient shading
 *   (vtkTyndallShading) is the camera samples' source;
 * - TYNDALL_TRANSFER_2D: a plain property's 2-D transfer function classifies
 *   the medium (colour and opacity at the scalar and its gradient
 *   magnitude, transfer2DTexture);
 * - TYNDALL_LABEL_MAP: a label-map mask (vtkTyndallLabelMap) mixes the
 *   labels' functions into the medium's colour and extinction;
 * - TYNDALL_ISOSURFACES: VTK's isosurface blend mode (vtkTyndallIsosurfaces):
 *   the camera samples (RAY_CAST) and the light (every pass) meet the
 *   TYNDALL_ISO_COUNT surfaces a step crosses instead of the medium;
 * - TYNDALL_PATH_BLOCKS (PATH_TRACE only): free flights and ratio tracking
 *   against the majorant grid's blocks (Variant::PathBlocks);
 * - TYNDALL_PATH_ENVIRONMENT (PATH_TRACE only): the paths sample the
 *   renderer's sky (Variant::PathEnvironment);
 * - TYNDALL_PATH_CLOSED_FORM (PATH_TRACE only, with detail): free flights
 *   and tracked transmittance in closed form (Variant::PathClosedForm);
 * - TYNDALL_PROJECTION (PROJECTION only): the projection blend mode,
 *   one of TYNDALL_PROJECTION_MAXIMUM .. TYNDALL_PROJECTION_ADDITIVE
 *   (vtkTyndallProjection::Modes).
 *
 * The passes that march camera rays (RAY_CAST, PROJECTION) have
 * vtkTransmittanceCameraRayFS.glsl (the pixel's ray) before their own file.
 * RAY_CAST is vtkTransmittanceRayCastFS.glsl's functions and
 * vtkTransmittanceRayCastMainFS.glsl's march; PATH_TRACE the same
 * functions and vtkTransmittancePathTraceFS.glsl's paths.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceShaderSource_h
#define vtkTransmittanceShaderSource_h

#include "TyndallRenderingModule.h" // For export macro

#include <string> // For std::string

class TYNDALLRENDERING_EXPORT vtkTransmittanceShaderSource
{
public:
  enum Passes
  {
    MAP_BUILD,
    OCCLUSION,
    RAY_CAST,
    LIGHT_CACHE,    // with the map variant of the camera rays' (MapCoefficients ...)
    COMPOSITE,      // alone: it shares nothing with the others
    PROJECTION,     // VTK's projection blend modes (Variant::Projection)
    PEEL_RANGES,    // the depth ranges of a depth-peeling stage (vtkTransmittancePeelingPass)
    PEEL_COMPOSITE, // the ray-cast images into a depth-peeling stage's targets
    PATH_TRACE,     // progressive path tracing (vtkTransmittancePathTracePass), RAY_CAST's variant
    DENOISE         // a pass of the path-traced picture's denoiser (vtkTransmittanceDenoisePass)
  };

  /// The compile-time variants of the shaders.
  struct Variant
  {
    bool MissingData = false;
    /**
     * The volume, or a guest's, is in tiles of slices
     * (vtkTransmittanceVolumeTiling): its textures are read through
     * tyndallTiledTexel().
     */
    bool VolumeTiled = false;
    /**
     * The volume, or a guest's, is stored as the bricks that vary
     * (vtkTransmittanceVolumeBricks): its scalars are read through
     * tyndallBrickedTexel().
     */
    bool VolumeBricked = false;
    bool SkipEmpty = false;
    bool Clip = false; // the medium is clipped or cropped (vtkTyndallClipRegion)
    /// Groups of four waves of procedural detail (vtkTyndallDetailMedium); 0: none.
    int DetailGroups = 0;
    /**
     * The waves as GLSL constants (vtkTransmittanceDetailAdapter): literal
     * numbers, which llvmpipe folds into its code (read from uniform arrays,
     * they cost 3x the whole sample), so a change of the waves compiles anew.
     */
    std::string DetailWaves;
    /**
     * The camera samples of the detail (RAY_CAST): the groups they evaluate
     * (the waves a pixel of the frame shows; the first groups) and whether
     * they filter them by the pixel's footprint, and whether a sample stands
     * for its step's mean of the waves (vtkTransmittanceFrame::
     * UsesDetailStepMeans()).
     */
    int DetailCameraGroups = 0;
    bool DetailFilter = false;
    bool DetailStepMeans = false;
    /**
     * Procedural detail whose colour is one albedo (the colour table is
     * constant) and that emits nothing from the table: a sample needs the
     * shape alone, not the scalar (one trilinear fetch less).
     */
    bool DetailUniformAlbedo = false;
    /// Free-flight samples per camera ray through the detail (RAY_CAST); 0: a march.
    int DetailSamples = 0;
    /**
     * The medium's own GLSL functions (its vtkTransmittanceMediumAdapter's),
     * in place of the common file's `//TYNDALL::Medium` line; empty: none.
     */
    const char* MediumCode = "";
    ///@{
    /// The camera rays' variant (RAY_CAST only).
    int MapCoefficients = 0;    // coefficients a map lookup reads; 0: no maps
    bool MapExtinction = false; // the maps hold extinction (ETM), else transmittance (TFM)
    bool AdaptiveMaps = false;
    bool Occlusion = false;
    bool Emission = false;         // emission per unit extinction (the colour's table)
    bool EmissionArray = false;    // emission per unit length from a separate array
    bool ParticleColors = false;   // the albedo from a coloured particle cloud's grid
    bool Accumulate = false;       // continues the rays of an earlier pass
    bool DepthRanges = false;      // camera rays between given depths (depth peeling)
    bool BruteForceLights = false; // some light marches to the light
    bool LightCache = false;       // map lights read the transmittance cache
    int Octaves = 1;               // multiple-scattering octaves (1: single scattering)
    ///@}
    /**
     * Guests: other media the light crosses (vtkTyndallSceneReader::GetGuests()),
     * at most vtkTyndallSceneReader::MaximumNumberOfGuests; 0: none.
     */
    int Guests = 0;
    /**
     * The maps' box reaches beyond the medium's own (several processes'
     * pieces, vtkTransmittanceMapReducer): the medium is empty outside its
     * box, as guests are.
     */
    bool MapBeyondMedium = false;
    /**
     * The picture is composited by a compositor that blends 8-bit
     * premultiplied colours without clamping (IceT, ParaView under MPI): a
     * ray's opacity is raised to its radiance, so that no colour exceeds
     * its alpha and the blend cannot wrap around.
     */
    bool OpacityCoversRadiance = false;
    /// The camera rays sample some guests too (vtkTransmittanceFrame::Guest::Camera).
    bool CameraGuests = false;
    /// Some camera guest is a coloured particle cloud (its albedo from its scattering grid).
    bool GuestColors = false;
    /**
     * Some guest emits from an array (PATH_TRACE: its light along the
     * scattered paths' segments; such a guest is never a camera guest).
     */
    bool GuestEmissionArrays = false;
    /// Extinction per channel: light and view transmittances per channel.
    bool Chromatic = false;
    /// The projection blend mode (PROJECTION; vtkTyndallProjection::Modes).
    int Projection = 0;
    /// A plain property's gradient shading (RAY_CAST; vtkTyndallShading).
    bool Shading = false;
    /// A vtkParticipatingMediumProperty's: its surface term added to single scattering.
    bool ShadingAdditive = false;
    /// The shading's volumetric scattering blending is above 0 (vtkTyndallShading).
    bool ScatteringBlend = false;
    /// A plain property's gradient opacity (vtkTyndallGridMedium::GetGradientOpacity()).
    bool GradientOpacity = false;
    /// A plain property's 2-D transfer function (vtkTyndallTransferTable::Has2D()).
    bool Transfer2D = false;
    /// A label map (vtkTyndallLabelMap::Enabled()).
    bool LabelMap = false;
    /**
     * Several components (vtkTyndallComponents): their number (1: one),
     * how they are classified (vtkTyndallComponents::Mode) and whether
     * independent ones' extinctions add.
     */
    int Components = 1;
    int ComponentMode = 0;
    bool ComponentAdditive = false;
    /// VTK's isosurface blend mode (vtkTyndallIsosurfaces) and its number of iso values.
    bool Isosurfaces = false;
    int IsoCount = 0;
    /// Transmittance-function maps of a coloured extinction: one set per channel.
    bool ChannelMaps = false;
    /**
     * The path tracer (PATH_TRACE) tracks against the majorant grid's
     * blocks (with SkipEmpty: the grid's texture is bound) instead of one
     * majorant.
     */
    bool PathBlocks = false;
    /// The path tracer (PATH_TRACE) samples the renderer's sky
    /// (vtkTransmittanceEnvironmentFS.glsl).
    bool PathEnvironment = false;
    /**
     * The path tracer (PATH_TRACE) draws its free flights and tracked
     * transmittance through procedural detail in closed form
     * (vtkTransmittanceDetailFS.glsl's cell walk and solve).
     */
    bool PathClosedForm = false;
  };

  /// The fragment shader of a pass, constants injected.
  static std::string GetFragmentShader(int pass, const Variant& variant);

  /**
   * The light maps' lookup alone (vtkTransmittanceLightMapFS.glsl, its
   * constants first): declarations and functions for another program's
   * fragment shader, e.g. an opaque surface receiving the medium's shadow.
   */
  static std::string GetLightMapLookup(const Variant& variant);

  /**
   * GetLightMapLookup() and what an opaque surface's fragment shader needs
   * to receive the medium's shadow (vtkTransmittanceSurfaceFS.glsl:
   * tyndallSurfaceTransmittance()), for vtkVolumeShadowReceiverPass.
   */
  static std::string GetSurfaceLookup(const Variant& variant);

  /**
   * The particle splats' vertex and fragment shaders
   * (vtkTransmittanceSplatVS.glsl, vtkTransmittanceSplatFS.glsl), the light
   * maps' lookup and the constants inserted; the fragment shader's outputs
   * are left at `//TYNDALL::MapOutputs` (vtkTransmittanceSplatPass).
   */
  static void GetSplatShaders(const Variant& variant, std::string& vertex, std::string& fragment);
  static std::string GetFragmentShader(int pass) { return GetFragmentShader(pass, Variant()); }

  /// The #define lines that replace `//TYNDALL::Constants`.
  static std::string GetConstants(const Variant& variant);

  /**
   * The stages of VTK's dual depth peeling the mapper draws in
   * (vtkTransmittancePeelingPass::FindStage()), and their #define lines for the
   * PEEL_RANGES and PEEL_COMPOSITE shaders.
   */
  enum PeelStages
  {
    PeelInitializing = 0, // the volume outside the translucent geometry's range
    PeelPeeling = 1,      // one peel: a front part and a back part per pixel
    PeelBlending = 2      // what the peels left, alpha-blended
  };
  static std::string GetPeelingConstants();

  /**
   * The display transform's constants and functions
   * (vtkTransmittanceOutputFS.glsl, tyndallDisplay()) that replace
   * `//TYNDALL::Output` in the shaders that draw into the renderer's frame
   * buffer (RAY_CAST, PROJECTION, COMPOSITE, PEEL_COMPOSITE).
   */
  static std::string GetOutputSource();

  /// The denoiser's constants (vtkTyndallDenoiser's kernel and floor) for DENOISE's shader.
  static std::string GetDenoiseConstants();

  /// What an occlusion texel holds where the light's ray meets no opaque surface.
  static constexpr float NoOccluder = 1.0e30f;

  /// The most Newton-bisection steps that place one free-flight sample within a cell.
  static constexpr int DetailSolveIterations = 24;

  /// Camera rays stop when their transmittance falls below this.
  static constexpr float ViewTermination = 1.0e-5f;
};

#endif
