/**
 * @class   vtkTransmittanceVolumeMapper
 * @brief   single-scattering volume mapper with per-light transmittance maps
 *
 * vtkTransmittanceVolumeMapper renders a vtkImageData (point or cell
 * scalars, any numeric type, one component) as a participating medium with
 * physically based single scattering, inside a normal vtkRenderer beside
 * opaque actors and other props. The medium is described by the volume's
 * property: a vtkParticipatingMediumProperty (density scale, anisotropy,
 * light scale, ambient, emission, scattering model) or a plain
 * vtkVolumeProperty with VTK's meaning (Shade off: VTK's unlit
 * emission-absorption picture; Shade on: VTK's gradient shading, each
 * light shadowed by the medium, vtkTyndallShading; its nearest or linear interpolation); VTK's
 * projection blend modes (maximum, minimum and average intensity, additive, the slice) are drawn as
 * VTK draws them (vtkTyndallProjection), and its isosurface blend mode as VTK draws it, each
 * surface also shadowing what lies behind it from the light (vtkTyndallIsosurfaces); the model is
 * defined in Documentation/rendering-model.md, and vtkSingleScatteringReference renders the same
 * scene on the CPU, read by the same internal reader. This class holds only the GPU integrator's
 * settings.
 *
 * Light transmittance, the expensive part of single scattering, comes from
 * per-light transmittance maps built once and reused for every camera ray:
 *
 * - SetTransmittanceMethodToNone(): lit, no shadows.
 * - SetTransmittanceMethodToBruteForce(): march towards each light at every
 *   sample (LightSampleCount steps): the in-shader reference.
 * - SetTransmittanceMethodToTFM(): Transmittance Function Maps, a Fourier
 *   cosine series of transmittance per map texel.
 * - SetTransmittanceMethodToAdaptiveTFM(): dual ray marching with a
 *   transmittance threshold; coefficients over the tight range
 *   [s_min, s_max] stored with the bounds (for dense media).
 * - SetTransmittanceMethodToETM(): Extinction Transmittance Maps, the DCT of
 *   extinction with the integral evaluated inside the exponential.
 * - SetTransmittanceMethodToAdaptiveETM() (default): ETM over the adaptive
 *   tight range.
 *
 * Maps are rebuilt only when something they depend on changes: the input
 * data, the transfer functions, the density scale, the lights (position,
 * direction, type), the volume's matrix, the method, the number of
 * coefficients, the map size, LightSampleCount or AdaptiveThreshold (for the
 * adaptive methods also the medium's octave count and extinction factor). A
 * camera move never rebuilds them (but a headlight or camera light moves
 * with the camera, and so rebuilds its map). GetMapBuildCount() counts
 * the rebuilds.
 *
 * Several Tyndall volumes in one renderer shadow each other
 * (vtkParticipatingMediumProperty::SceneShadows, on by default): the light
 * crosses every one of them, the maps are fitted to the box around them all
 * and built once for all of them (by the first volume drawn; the others read
 * its maps when their settings match), and rebuilt when any of them changes.
 * Draw such volumes back to front (the renderer's vtkFrustumCoverageCuller,
 * SetSortingStyleToBackToFront()). Volumes whose boxes overlap are drawn as
 * one medium (vtkParticipatingMediumProperty::SceneCompositing, on by
 * default): the first of them in the renderer's order casts the camera rays
 * through all of them and the others draw nothing of their own (their
 * lights and maps are still reported: GetNumberOfRenderedLights(),
 * GetTransmittanceMap(); their ray-cast figures, such as
 * GetLastRayCastTime(), are 0) (Documentation/rendering-model.md, "Several
 * volumes").
 *
 * Directional lights get an orthographic map fitted to the volume's bounds,
 * positional (point and spot) lights a perspective one. A positional light
 * inside the bounds, or one needing a field of view over 150 degrees, has
 * no map: that light falls back to brute-force marching (documented
 * fallback; everything else keeps using maps). Up to 8 lights are used
 * (GetMaximumNumberOfLights()); further lights are ignored with a warning.
 * GetTransmittanceMap() reads a light's map back, for inspection and tests.
 *
 * View rays stop at the depth of opaque geometry already drawn. Opaque
 * actors also block light entering the medium: each frame with visible
 * opaque vtkActors, their depth is rendered from every light's frustum
 * (the TFM paper's light-space depth) and samples behind it get no light
 * from that light, whatever the method. Lights inside the bounds (no
 * frustum) are not blocked by geometry.
 *
 * Render() is an orchestrator of named passes, each its own class
 * (Documentation/architecture.md): the scene reader (vtkTyndallSceneReader), the
 * medium upload (vtkTransmittanceMediumTextures), the light-space occlusion
 * (vtkTransmittanceOcclusionPass), the maps (vtkTransmittanceMapPass), the
 * depth capture (vtkTransmittanceDepthPass) and the ray cast
 * (vtkTransmittanceRayCastPass). The shaders are GLSL files in glsl/
 * embedded at build time, their constants injected from C++
 * (vtkTransmittanceShaderSource).
 *
 * Bad input is reported with vtkErrorMacro and leaves the rest of the
 * render intact (see Documentation/rendering-model.md for what the scene
 * reader refuses, and how NaN scalars are rendered); so are a render window
 * that is not an OpenGL one and a shader that does not compile. A volume deeper than the GPU's
 * 3-D texture limit (GL_MAX_3D_TEXTURE_SIZE per side) is stored as tiles of slices side by side
 * in one texture and drawn whole (SetMaximumTextureSize()); one wider or taller than the limit,
 * or whose tiles do not fit, is downsampled by the smallest integer factor that fits, with a
 * warning. A texture the GPU cannot hold is an error that names its size.
 *
 * @sa vtkParticipatingMediumProperty vtkSingleScatteringReference
 * vtkTransmittanceMapMath vtkTransmittanceLightFrustum
 */

#ifndef vtkTransmittanceVolumeMapper_h
#define vtkTransmittanceVolumeMapper_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkParticipatingMediumMapper.h"
#include "vtkTransmittanceMapMath.h" // For the method constants

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkTransmittanceLightFrustum;
class vtkTransmittanceMapReducer;
class vtkTyndallParticles;

class TYNDALLRENDERING_EXPORT vtkTransmittanceVolumeMapper : public vtkParticipatingMediumMapper
{
public:
  static vtkTransmittanceVolumeMapper* New();
  vtkTypeMacro(vtkTransmittanceVolumeMapper, vtkParticipatingMediumMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The methods, shared with the CPU math (vtkTransmittanceMapMath).
  enum TransmittanceMethods
  {
    NONE = vtkTransmittanceMapMath::NONE,
    BRUTE_FORCE = vtkTransmittanceMapMath::BRUTE_FORCE,
    TFM = vtkTransmittanceMapMath::TFM,
    ADAPTIVE_TFM = vtkTransmittanceMapMath::ADAPTIVE_TFM,
    ETM = vtkTransmittanceMapMath::ETM,
    ADAPTIVE_ETM = vtkTransmittanceMapMath::ADAPTIVE_ETM
  };

  ///@{
  /**
   * How light transmittance is computed; default ADAPTIVE_ETM.
   */
  vtkSetClampMacro(TransmittanceMethod, int, NONE, ADAPTIVE_ETM);
  vtkGetMacro(TransmittanceMethod, int);
  void SetTransmittanceMethodToNone() { this->SetTransmittanceMethod(NONE); }
  void SetTransmittanceMethodToBruteForce() { this->SetTransmittanceMethod(BRUTE_FORCE); }
  void SetTransmittanceMethodToTFM() { this->SetTransmittanceMethod(TFM); }
  void SetTransmittanceMethodToAdaptiveTFM() { this->SetTransmittanceMethod(ADAPTIVE_TFM); }
  void SetTransmittanceMethodToETM() { this->SetTransmittanceMethod(ETM); }
  void SetTransmittanceMethodToAdaptiveETM() { this->SetTransmittanceMethod(ADAPTIVE_ETM); }
  const char* GetTransmittanceMethodAsString();
  ///@}

  ///@{
  /**
   * Coefficients per map texel, in [1, 16]; default 8.
   */
  vtkSetClampMacro(NumberOfCoefficients, int, 1, 16);
  vtkGetMacro(NumberOfCoefficients, int);
  ///@}

  ///@{
  /**
   * Width and height of each light's map in texels, in [16, 4096];
   * default 256.
   */
  vtkSetClampMacro(TransmittanceMapSize, int, 16, 4096);
  vtkGetMacro(TransmittanceMapSize, int);
  ///@}

  ///@{
  /**
   * Transmittance threshold of the adaptive methods' first march, in
   * [1e-6, 0.5]; default 0.01. With multiple-scattering octaves
   * (vtkParticipatingMediumProperty::ScatteringOctaves N, OctaveExtinction
   * b, OctaveScattering a) and a coloured extinction
   * (vtkParticipatingMediumProperty::ExtinctionColor, its smallest positive
   * component e relative to the largest) the maps are built to
   * (threshold / max(1, a)^(N-1))^(1 / (b^(N-1) e)), so that the last
   * octave's light and the faintest channel's are resolved as far as single
   * scattering's grey light is.
   */
  vtkSetClampMacro(AdaptiveThreshold, double, 1.0e-6, 0.5);
  vtkGetMacro(AdaptiveThreshold, double);
  ///@}

  ///@{
  /**
   * Step along camera rays in world units, in [0, 1e6]; default 0 =
   * automatic: half the smallest voxel spacing after the volume's matrix.
   */
  vtkSetClampMacro(SampleDistance, double, 0.0, 1.0e6);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /**
   * Samples per light ray, for building maps and for brute force, in
   * [1, 2048]; default 128. Brute force stays right at any count: camera
   * rays whose light marches need more loop iterations than a driver allows
   * a fragment are split over several passes (GetLastRayCastPassCount()).
   */
  vtkSetClampMacro(LightSampleCount, int, 1, 2048);
  vtkGetMacro(LightSampleCount, int);
  ///@}

  ///@{
  /**
   * Jitter the sample positions per pixel against banding (default on).
   * The jitter is a fixed function of the pixel, so images are
   * deterministic either way.
   */
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  ///@}

  ///@{
  /**
   * Skip empty space (default on): camera rays and the ETM map builds
   * (and the adaptive methods' first march) cross blocks of 8^3 voxels whose
   * largest extinction is zero in one step each, keeping every other sample
   * where it was, so pictures do not change. The block grid is rebuilt when
   * the scalars change (a pass over the voxels) and its majorants when the
   * transfer functions change (cheap; GetLastEmptySpaceGridTime()).
   */
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  ///@}

  ///@{
  /**
   * Cache the map lights' transmittance (default on; map methods only):
   * after the maps are built, each map light's transmittance is evaluated
   * once per texel of a lattice over the volume's box (the longest side
   * TransmittanceCacheSize texels, the others in proportion, half floats),
   * and camera samples read it with one trilinear fetch instead of looking
   * up and reconstructing the map at every sample. Rebuilt with the maps
   * (GetTransmittanceCacheBuildCount()). It trades a little accuracy (the
   * transmittance interpolated between lattice texels) for frame time:
   * measured per scene in Documentation/benchmarks.md. Off: every sample
   * reads the maps, at the maps' full resolution.
   */
  vtkSetMacro(TransmittanceCache, bool);
  vtkGetMacro(TransmittanceCache, bool);
  vtkBooleanMacro(TransmittanceCache, bool);
  ///@}

  ///@{
  /**
   * Texels along the longest side of the transmittance cache's lattice, in
   * [16, 1024]; default 256 (2 bytes per texel and light: 32 MiB for a cube
   * and one light). A cache over 1 GiB or the driver's largest 3-D texture
   * is refused with an error; the render then reads the maps per sample.
   */
  vtkSetClampMacro(TransmittanceCacheSize, int, 16, 1024);
  vtkGetMacro(TransmittanceCacheSize, int);
  ///@}

  /**
   * How many times the transmittance cache was built, and the last build's
   * wall-clock seconds (with glFinish).
   */
  int GetTransmittanceCacheBuildCount();
  double GetLastTransmittanceCacheBuildTime();

  /**
   * Seconds the last update of the empty-space grid took: the block ranges
   * (when the scalars changed) plus the majorants (when they or the
   * transfer functions changed); 0 before the first render.
   */
  double GetLastEmptySpaceGridTime();

  /**
   * The fraction of the empty-space grid's blocks that are empty, as of the
   * last render (0 before the first).
   */
  double GetEmptyBlockFraction();

  ///@{
  /**
   * Interactive level of detail (default on): honour the time VTK's
   * interactive/still protocol allocates to the volume
   * (vtkProp::GetAllocatedRenderTime(), from the render window's desired
   * update rate: high while the user drags, vtkRenderWindowInteractor's
   * StillUpdateRate when the interaction stops). When the camera rays of a
   * full-size image would take longer than that (predicted from the last
   * frame's measured cost per pixel), they are cast at 1 / r of the
   * viewport's width and height and upscaled, r the smallest integer that
   * fits, at most MaximumImageReduction; when the full frame would be more
   * than 4 times too slow, the camera steps are also made twice as long
   * (GetLastStepScale()). Shadows stay on, with the same maps; the still
   * frame is the full-size picture. Timing a frame waits for the GPU to
   * finish the camera rays (glFinish).
   */
  vtkSetMacro(InteractiveAdjustment, bool);
  vtkGetMacro(InteractiveAdjustment, bool);
  vtkBooleanMacro(InteractiveAdjustment, bool);
  ///@}

  ///@{
  /**
   * The largest reduction of the image's width and height while
   * interacting, in [1, 8]; default 4 (1 / 16 of the pixels).
   */
  vtkSetClampMacro(MaximumImageReduction, int, 1, 8);
  vtkGetMacro(MaximumImageReduction, int);
  ///@}

  ///@{
  /**
   * The most texels per side of the volume's 3-D textures, in [0, 65536]
   * (1 counts as 2); default 0: the GL's GL_MAX_3D_TEXTURE_SIZE (2048 on most GPUs and on
   * Mesa's llvmpipe); a value above it changes nothing. A volume whose
   * slices pass it is stored as tiles of slices side by side in one texture
   * (a 512 x 512 x 3000 CT in 1024 x 512 x 1501), every sample kept and
   * drawn as one volume: lit, shadowed and skipped as one; a volume whose
   * width or height passes it, or whose tiles do not fit, is drawn from
   * every n-th sample with a warning. Smaller values bound one texture's
   * size (and test the tiling on small data).
   */
  vtkSetClampMacro(MaximumTextureSize, int, 0, 65536);
  vtkGetMacro(MaximumTextureSize, int);
  ///@}

  ///@{
  /**
   * Whether the scalars go to the GPU as the bricks that vary
   * (vtkTransmittanceVolumeBricks: bricks of 8^3 samples, those whose
   * samples are all one value, such as OpenVDB's background, shared, the
   * others in an atlas, one indirection texel per brick): BRICKING_OFF (0)
   * never, BRICKING_ON (1) whenever the bricks take no more than the dense
   * texture's bytes, BRICKING_AUTO (2, the default) when they take at most
   * half of them; both whenever the dense texture does not fit the GPU,
   * and whatever they take for a volume wider or taller than the GPU's 3-D
   * texture size (of 8- or 16-bit integers or floats without NaN or
   * infinity), which is then drawn whole where their atlas fits instead of
   * from every n-th sample. The picture is the same either way (the atlas
   * holds every sample each brick's filtering reads). A volume with NaN
   * scalars or a mask, a label map, an emission array, a coloured particle
   * cloud, or one tiled or downsampled (SetMaximumTextureSize()) is dense.
   * A change uploads the volume again.
   */
  enum VolumeBrickings
  {
    BRICKING_OFF = 0,
    BRICKING_ON = 1,
    BRICKING_AUTO = 2
  };
  vtkSetClampMacro(VolumeBricking, int, BRICKING_OFF, BRICKING_AUTO);
  vtkGetMacro(VolumeBricking, int);
  ///@}

  ///@{
  /**
   * Camera rays through procedural detail
   * (vtkParticipatingMediumProperty::SetDetailNoise()), in [0, 64]; default 0.
   *
   * - 0: the rays march at a step of a quarter of the noise's shortest
   *   wavelength (or SampleDistance when shorter), evaluating every wave at
   *   every step: one frame is the finished picture.
   * - n > 0: the rays are importance-sampled in closed form (the cosine-noise
   *   paper's section 7): each pixel draws n free-flight distances,
   *   stratified in transmittance, by walking the shape's cells with the
   *   closed-form integral and solving within the cell, and shades only
   *   those; the view transmittance (alpha) is exact. A frame is unbiased but
   *   noisy; successive still frames draw new samples and are averaged, so
   *   the picture converges as 1 / sqrt(frames x n). The average restarts
   *   when anything that changes the picture changes (camera, viewport, the
   *   volume, its property, input and lights, the maps, the other 3-D props,
   *   this mapper's settings) and on ResetAccumulation(). Rendering-model.md
   *   measures both against the CPU reference.
   *
   * Fewer than n are drawn where a pixel's loop iterations would pass the
   * ray-cast pass's budget (GetLastDetailSamplesPerPixel()). No effect
   * without detail, and none with a coloured extinction
   * (vtkParticipatingMediumProperty::ExtinctionColor: the free flights
   * follow one transmittance), nor in VTK's depth peeling for volumes (a
   * frame draws the rays in parts, which one history cannot average), which
   * march.
   */
  vtkSetClampMacro(DetailSamplesPerPixel, int, 0, 64);
  vtkGetMacro(DetailSamplesPerPixel, int);
  ///@}

  /**
   * The free-flight samples per pixel the last Render() drew (0: it marched,
   * or rendered nothing).
   */
  int GetLastDetailSamplesPerPixel();

  ///@{
  /**
   * Path tracing, the cinematic mode (default off): a still picture is
   * refined by volumetric path tracing on the GPU, full multiple
   * scattering, until it has PathTraceSamplesPerPixel samples; while the
   * camera, the lights, the data or any setting change, the map-based
   * frame is drawn (never a noisy one), and the paths start anew at the
   * first Render() after they stop (the same key as DetailSamplesPerPixel's
   * average; ResetAccumulation()). An application renders again while
   * GetLastPathTraceSamples() is below PathTraceSamplesPerPixel (a timer, or
   * a loop: tyndall-render --path-trace). The paths are
   * vtkVolumetricPathTracer's estimator (DELTA_TRACKING) on the GPU:
   * delta tracking against the majorant grid's blocks, next-event estimation
   * towards every light at every collision, Henyey-Greenstein scattering,
   * Russian roulette, the pixel's centre, the ambient term and the
   * table's emission at every collision, an emission array's along every
   * segment (vtkTyndallMedium::PathEmissionSamples points), a coloured
   * extinction by spectral tracking (a view transmittance per channel); the
   * property's octaves are not used (the paths scatter for real). The
   * picture is unbiased but noisy; its noise falls as 1 / sqrt(samples).
   *
   * Several volumes sharing their shadows (guests) are traced as the CPU
   * tracer traces them: the camera ray through the media this mapper
   * draws, scattered paths through every one; a collision is one medium's,
   * drawn with its share of the extinction, and lit by that volume's own
   * scattering model, phase function, LightScale, ambient light and
   * EmissionScale. Another volume's emission array lights the scattered
   * paths along their segments, beside this volume's emission of any kind.
   *
   * A plain vtkVolumeProperty with Shade on (a shaded CT) is traced as the
   * CPU tracer traces it: each of its collisions scatters as VTK's shaded surface
   * (vtkTyndallSurfaceLobe: a lobe about the gradient, the lights' first
   * bounce VTK's shading term, VTK's ambient term an emission), with VTK
   * 9.2's volumetric scattering blending (an isotropic part of the lobe)
   * and over independent components (a collision shaded as one of them).
   * A vtkParticipatingMediumProperty with Shade on keeps Tyndall's meaning:
   * its collisions scatter by the phase function and add the surface term,
   * the lights' and the sky's light reflected by the same lobe (the lobe
   * not sampled: one bounce is the map-based frame's single scattering plus
   * its surface term).
   *
   * Not path traced yet, each said once in a warning, the map-based frame
   * drawn instead: VTK's depth peeling for volumes, several processes; and
   * never (they are not media; the CPU tracer refuses them too): the
   * projection and isosurface blend modes.
   */
  vtkSetMacro(PathTracing, bool);
  vtkGetMacro(PathTracing, bool);
  vtkBooleanMacro(PathTracing, bool);
  ///@}

  ///@{
  /**
   * The samples per pixel a path-traced picture converges to, in [1,
   * 1000000]; default 1024. Frames after it redraw the mean.
   */
  vtkSetClampMacro(PathTraceSamplesPerPixel, int, 1, 1000000);
  vtkGetMacro(PathTraceSamplesPerPixel, int);
  ///@}

  ///@{
  /**
   * Paths per pixel one Render() traces, in [1, 64]; default 4. Fewer
   * where a path's bound on loop iterations (the medium's optical depth
   * across its box) would pass a fragment's budget (the ray-cast pass's
   * IterationBudget); and the paths' first frames after a change ramp up to
   * it, 1, 2, 4, ... (their first picture, and the denoised one, in the
   * time of one sample), the last trimmed to end at
   * PathTraceSamplesPerPixel. Each frame is weighed by its samples, and a
   * path's random numbers are picked by its index in the mean: N samples
   * make the same picture whatever this setting.
   */
  vtkSetClampMacro(PathTraceSamplesPerFrame, int, 1, 64);
  vtkGetMacro(PathTraceSamplesPerFrame, int);
  ///@}

  ///@{
  /**
   * The most scattering events of a path, in [1, 1000]; default 8 (the
   * CPU tracer's). 1 is single scattering.
   */
  vtkSetClampMacro(PathTraceMaximumBounces, int, 1, 1000);
  vtkGetMacro(PathTraceMaximumBounces, int);
  ///@}

  /// How a path's next-event estimation sees the light's transmittance.
  enum PathTraceShadowModes
  {
    /// From the frame's maps (TransmittanceMethod; brute force marches): the fast default.
    PATH_SHADOWS_FROM_MAPS = 0,
    /// Ratio tracking to the light against the majorant: unbiased, the CPU tracer's.
    PATH_SHADOWS_TRACKED = 1
  };

  ///@{
  /**
   * How paths see the lights' transmittance: PATH_SHADOWS_FROM_MAPS
   * (default) or PATH_SHADOWS_TRACKED. A light whose method is NONE is
   * unshadowed either way.
   */
  vtkSetClampMacro(PathTraceShadows, int, PATH_SHADOWS_FROM_MAPS, PATH_SHADOWS_TRACKED);
  vtkGetMacro(PathTraceShadows, int);
  void SetPathTraceShadowsToFromMaps() { this->SetPathTraceShadows(PATH_SHADOWS_FROM_MAPS); }
  void SetPathTraceShadowsToTracked() { this->SetPathTraceShadows(PATH_SHADOWS_TRACKED); }
  ///@}

  /// How a path's free flights and tracked light transmittance are drawn.
  enum PathTraceDistanceSamplingModes
  {
    /**
     * In closed form where the medium has one (procedural detail,
     * vtkParticipatingMediumProperty::DetailNoise, with nothing clipped: the
     * cosine-noise paper's distance sampling and optical depth, the CPU
     * tracer's CLOSED_FORM); delta and ratio tracking elsewhere.
     */
    PATH_DISTANCE_CLOSED_FORM = 0,
    /// Delta and ratio tracking everywhere (the CPU tracer's DELTA_TRACKING).
    PATH_DISTANCE_DELTA_TRACKING = 1
  };

  ///@{
  /**
   * How paths sample distances: PATH_DISTANCE_CLOSED_FORM or
   * PATH_DISTANCE_DELTA_TRACKING (default), as vtkVolumetricPathTracer's
   * DistanceSampling. Only procedural detail has a closed form, and it is
   * used only with nothing clipped, one colour of extinction and no other
   * volumes sharing the shadows (else tracking, silently: the same picture,
   * other noise); it clamps each cell's integral at 0 where delta tracking
   * clamps each point's noise (a noise whose offset lets it dip below 0 is a
   * slightly different medium, as on the CPU). Delta tracking is the default because it was
   * faster where measured: on llvmpipe the closed form's paths ran at 0.14
   * (a cloud's shape) and 0.27 (the paper's box) times its rate, for 0.3 dB
   * less noise at equal samples (BenchCinematic --detail, 144 waves; the
   * closed form's per-cell wave integrals against delta tracking's point
   * evaluations). A GPU's trigonometric throughput may change that.
   */
  vtkSetClampMacro(
    PathTraceDistanceSampling, int, PATH_DISTANCE_CLOSED_FORM, PATH_DISTANCE_DELTA_TRACKING);
  vtkGetMacro(PathTraceDistanceSampling, int);
  void SetPathTraceDistanceSamplingToClosedForm()
  {
    this->SetPathTraceDistanceSampling(PATH_DISTANCE_CLOSED_FORM);
  }
  void SetPathTraceDistanceSamplingToDeltaTracking()
  {
    this->SetPathTraceDistanceSampling(PATH_DISTANCE_DELTA_TRACKING);
  }
  ///@}

  ///@{
  /**
   * The seed of the paths' random numbers (default 0): with a path's index
   * in the mean and the pixel it picks every number, so a picture depends
   * only on it, the settings and its samples (not on how frames split
   * them); another seed gives an independent picture.
   */
  vtkSetMacro(PathTraceSeed, int);
  vtkGetMacro(PathTraceSeed, int);
  ///@}

  ///@{
  /**
   * Shows the path-traced picture denoised (default off): an edge-avoiding
   * a-trous filter of what the paths add to the map-based frame, that frame
   * (noise free, with the same silhouette, shadows and classification) its
   * guide: guide + A(mean - guide) (vtkTyndallDenoiser, its CPU twin and
   * its description). The filter narrows as the samples grow, so the
   * picture tends to the paths' mean; the mean itself is kept, and turning
   * the denoiser on or off keeps its samples (as the display transform
   * does). Costs one map-based frame when the paths start (none where the
   * frame drawn just before them, while something moved, was full size and
   * marched: that frame is the guide) and two filtering passes per frame.
   * Off in the tests unless a test asks.
   */
  void SetPathTraceDenoise(bool denoise);
  vtkGetMacro(PathTraceDenoise, bool);
  vtkBooleanMacro(PathTraceDenoise, bool);
  ///@}

  /**
   * How many times the denoiser's guide was drawn (PathTraceDenoise): each
   * map-based frame drawn while something moves that is the guide's (full
   * size, full step, marched: drawn into the guide's image and composited
   * from it), and once by a mean of paths that starts without one (the
   * frame before it was reduced).
   */
  int GetPathTraceGuideRenderCount();

  ///@{
  /**
   * The display transform of the mapper's frame (vtkTyndallToneMapping, its
   * CPU twin): per channel, the medium's linear radiance times
   * 2^Exposure, then the tone curve, then the sRGB encoding, applied to
   * what the mapper draws into the renderer's frame buffer (the map-based
   * frame, the path-traced one, every blend mode), the opacity unchanged.
   * Blended over the renderer's background B, the pixel becomes
   * D(L + (1 - a) D^-1(B)) (L the medium's radiance, a its opacity, D the
   * transform): B where there is no medium, D(L) over black
   * (vtkTyndallToneMapping::MapOver(); Documentation/mapper.md, "Exposure,
   * tone curve and sRGB").
   *
   * - Exposure: stops, [-20, 20], default 0;
   * - ToneCurve: TONE_CURVE_LINEAR (default: none, values above 1 kept in
   *   a float frame buffer), TONE_CURVE_REINHARD (x / (1 + x)) or
   *   TONE_CURVE_ACES (Narkowicz's fit of the ACES curves);
   * - EncodeSRGB: the sRGB transfer function for 8-bit output, default off.
   *
   * The defaults leave VTK's and Tyndall's pictures unchanged. Changing
   * them does not restart the running averages (the path-traced picture,
   * sampled detail): they only change how the mean is shown.
   */
  enum ToneCurves
  {
    TONE_CURVE_LINEAR = 0,
    TONE_CURVE_REINHARD = 1,
    TONE_CURVE_ACES = 2
  };
  void SetExposure(double stops);
  vtkGetMacro(Exposure, double);
  void SetToneCurve(int curve);
  vtkGetMacro(ToneCurve, int);
  void SetToneCurveToLinear() { this->SetToneCurve(TONE_CURVE_LINEAR); }
  void SetToneCurveToReinhard() { this->SetToneCurve(TONE_CURVE_REINHARD); }
  void SetToneCurveToACES() { this->SetToneCurve(TONE_CURVE_ACES); }
  void SetEncodeSRGB(bool encode);
  vtkGetMacro(EncodeSRGB, bool);
  vtkBooleanMacro(EncodeSRGB, bool);
  ///@}

  /**
   * The samples per pixel in the last Render()'s picture: 0 when it was
   * the map-based frame (path tracing off or refused, something moved, or
   * nothing rendered).
   */
  int GetLastPathTraceSamples();

  /**
   * The waves of procedural detail the last Render()'s camera samples
   * evaluated: with the footprint filter
   * (vtkParticipatingMediumProperty::DetailFilterWidth) those a pixel of the
   * frame can show, coarsest first (a far volume needs fewer); all without
   * it; 0 without detail or when nothing was rendered.
   */
  int GetLastDetailCameraWaves();

  /**
   * The camera rays' step the last Render() marched with (world units; 0
   * when nothing was marched: free flights, a projection, nothing rendered).
   * With procedural detail and the footprint filter, a step longer than the
   * waves' own where the lights' maps allow it: GetLastDetailStepMeans()
   * says whether each camera sample then stood for its step's exact mean of
   * the waves (Documentation/rendering-model.md, "Steps that span waves").
   */
  double GetLastCameraStep();
  bool GetLastDetailStepMeans();

  /**
   * The still frames the last Render()'s picture averages (DetailSamplesPerPixel
   * > 0; 0 otherwise).
   */
  int GetAccumulatedFrames();

  /// Starts the average of still frames anew at the next Render().
  void ResetAccumulation();

  /**
   * The reduction the last Render() used (1: full size; 0 before the first
   * or after a failed render).
   */
  int GetLastImageReduction();

  /**
   * The tiles of slices the volume's texture holds since the last upload
   * (SetMaximumTextureSize(): 1 when the volume fits one texture; 0 before
   * the first upload).
   */
  int GetNumberOfVolumeTextureTiles();

  /**
   * Whether the last upload stored the scalars as bricks
   * (SetVolumeBricking()), and the bytes the scalars take on the GPU (the
   * atlas and its indirection, or the dense texture; 0 before the first
   * upload).
   */
  bool GetVolumeBricked();
  vtkIdType GetVolumeTextureBytes();

  /**
   * The factor the last Render() lengthened the camera steps by (1 or 2;
   * 0 before the first or after a failed render).
   */
  double GetLastStepScale();

  /**
   * The passes the last Render() split the camera rays over (each pass
   * runs a bounded number of loop iterations per pixel; see
   * LightSampleCount); 0 before the first or after a failed render.
   */
  int GetLastRayCastPassCount();

  /**
   * Seconds the camera rays of the last Render() took (measured with
   * InteractiveAdjustment on, else 0).
   */
  double GetLastRayCastTime();

  /**
   * How many times this mapper built transmittance maps (a mapper that reads
   * another Tyndall volume's maps, see the class description, builds none).
   */
  int GetMapBuildCount();

  /**
   * Wall-clock seconds of the last map build (with glFinish, so it measures
   * the GPU work); with several processes it includes the addition of the
   * maps over them (vtkTransmittanceMapReducer::GetLastReductionTime()).
   */
  double GetLastMapBuildTime();

  ///@{
  /**
   * Several processes drawing one picture, each with a piece of the medium
   * (ParaView under MPI; Tyndall's ParaView plugin sets one): with a
   * reducer of more than one process the maps are fitted to the whole
   * medium's box and are the sum of every process's, so the light crosses
   * every piece (vtkTransmittanceMapReducer says how, and which methods add:
   * others are drawn as ETM). The rays' alpha is then raised to their
   * colour, since the compositor's (IceT's) 8-bit blend does not clamp.
   * Default none: one process.
   */
  void SetMapReducer(vtkTransmittanceMapReducer* reducer);
  vtkTransmittanceMapReducer* GetMapReducer();
  ///@}

  /**
   * With a reducer of more than one process: builds this frame's maps from
   * this process's piece, fitted to the box of every piece, and adds them
   * over the processes. Collective: every process calls it once per frame
   * before the render window renders, at a point where the processes are in
   * step (Tyndall's ParaView representation calls it in its REQUEST_RENDER
   * pass). Not from Render(): ParaView's compositor (IceT) does not draw a
   * process whose piece is off-screen, so collectives there would hang.
   * Render() then shades with the added maps; if they no longer fit the
   * frame (the lights or the medium changed in between) it builds this
   * piece's maps alone and warns once. A process without a piece takes part
   * with zeros. Returns false on error or with nothing to build here; true
   * without a reducer (nothing to do).
   */
  bool PrepareDistributedMaps(vtkRenderer* renderer, vtkVolume* volume);

  /**
   * The most lights used; further lights are ignored with a warning.
   */
  static int GetMaximumNumberOfLights();

  ///@{
  /**
   * The lights of the last Render() (none when it failed or after
   * ReleaseGraphicsResources()), or of the last UpdateShadowMaps() when the
   * volume was not drawn after it (out of view, its shadow drawn by
   * vtkVolumeShadowReceiverPass; none when it failed), in the renderer's
   * order (switched-on lights with a positive intensity, at most
   * GetMaximumNumberOfLights();
   * none in the emission-absorption model), then the sky's directional
   * lights (SkyLightDirections, under a sky), each with its map: their number, the method each
   * used (the mapper's, or BRUTE_FORCE for a light without a map; -1 for an
   * index out of range) and the frustum of each one's map (null out of
   * range; meaningful when the light has a map).
   */
  int GetNumberOfRenderedLights();
  int GetLightTransmittanceMethod(int light);
  vtkTransmittanceLightFrustum* GetLightFrustum(int light);
  ///@}

  /**
   * Reads light `light`'s transmittance map, as the last Render() left it
   * (or the last UpdateShadowMaps() when the volume was not drawn after it),
   * back from the GPU into `map`: TransmittanceMapSize x TransmittanceMapSize
   * points, point (i, j) being texel (a, b) = ((i + 0.5) / size,
   * (j + 0.5) / size) (the origin and spacing say so), with the float
   * point-data arrays "Coefficients" (NumberOfCoefficients components, the
   * a_j or c_j of Documentation/rendering-model.md) and, for the adaptive
   * methods, "Bounds" (s_min, s_max, T_beyond). Returns false (with an
   * error) when the light has no map in the last render (or that render
   * failed) or there is no render window.
   */
  bool GetTransmittanceMap(int light, vtkImageData* map);

  /**
   * Render the volume (called by the renderer).
   */
  void Render(vtkRenderer* renderer, vtkVolume* volume) override;

  /**
   * For vtkVolumeShadowReceiverPass, before the opaque geometry is drawn:
   * brings this volume's transmittance maps up to date for `renderer` (built
   * only when stale; Render() then reuses them). False when no light of the
   * frame has a map (the None and BruteForce methods, a light inside the
   * volume's box) or on error.
   */
  bool UpdateShadowMaps(vtkRenderer* renderer, vtkVolume* volume);

#ifndef __VTK_WRAP__
  /**
   * Internal (vtkVolumeShadowReceiverPass): the frame of the last
   * UpdateShadowMaps() or Render() and its maps (`maps`, `slices` slices).
   */
  const vtkTransmittanceFrame& GetShadowFrame(vtkTextureObject*& maps, int& slices);

#endif

  /**
   * Release the OpenGL resources of the window.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkTransmittanceVolumeMapper();
  ~vtkTransmittanceVolumeMapper() override;

  int TransmittanceMethod = ADAPTIVE_ETM;
  int NumberOfCoefficients = 8;
  int TransmittanceMapSize = 256;
  double AdaptiveThreshold = 0.01;
  double SampleDistance = 0.0;
  int LightSampleCount = 128;
  bool Jitter = true;
  bool EmptySpaceSkipping = true;
  bool TransmittanceCache = true;
  int TransmittanceCacheSize = 256;
  bool InteractiveAdjustment = true;
  int MaximumImageReduction = 4;
  int MaximumTextureSize = 0;
  int VolumeBricking = BRICKING_AUTO;
  int DetailSamplesPerPixel = 0;
  bool PathTracing = false;
  int PathTraceSamplesPerPixel = 1024;
  int PathTraceSamplesPerFrame = 4;
  int PathTraceMaximumBounces = 8;
  int PathTraceShadows = PATH_SHADOWS_FROM_MAPS;
  int PathTraceDistanceSampling = PATH_DISTANCE_DELTA_TRACKING;
  int PathTraceSeed = 0;
  bool PathTraceDenoise = false;
  double Exposure = 0.0;
  int ToneCurve = TONE_CURVE_LINEAR;
  bool EncodeSRGB = false;
  // The modification time a change of the display transform set, and the
  // time before it: such a change keeps the running averages
  // (GetSceneMTime()).
  vtkMTimeType DisplayMTime = 0;
  vtkMTimeType MTimeBeforeDisplay = 0;

  /**
   * The modification time of what the picture shows: GetMTime(), except
   * where the last change was to the display transform (Exposure,
   * ToneCurve, EncodeSRGB) or the denoiser (PathTraceDenoise), which change
   * only how the picture is shown.
   */
  vtkMTimeType GetSceneMTime();

private:
  template <typename T>
  void SetDisplayValue(T& member, T value);

  vtkTransmittanceVolumeMapper(const vtkTransmittanceVolumeMapper&) = delete;
  void operator=(const vtkTransmittanceVolumeMapper&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
