/**
 * @class   vtkTransmittancePathTracePass
 * @brief   the progressive path-traced frame of vtkTransmittanceVolumeMapper
 *
 * One full-viewport quad (vtkTransmittancePathTraceFS.glsl, after the camera
 * rays' functions of vtkTransmittanceRayCastFS.glsl): each pixel traces a
 * few volumetric paths from its camera ray, with delta tracking against
 * the majorant grid's blocks (or the media's majorant; through procedural
 * detail in closed form with Settings::ClosedForm; spectral tracking with a
 * coloured extinction), next-event estimation towards every light at every
 * collision (the light transmittance read from the frame's maps, or
 * tracked: Settings::TrackedShadows), Henyey-Greenstein scattering, a bounce
 * limit and Russian roulette, emission arrays' light along every segment
 * (this volume's, and along the scattered ones the other volumes'), and the
 * renderer's sky (vtkTyndallEnvironment: drawn from at
 * every collision, its light tracked, and met by the paths that leave; the
 * power heuristic weighs the two): the estimator of vtkVolumetricPathTracer
 * (DELTA_TRACKING, or CLOSED_FORM through detail), its CPU twin. The
 * frames' images are averaged into a running mean
 * (vtkTransmittanceAccumulationPass; with a coloured extinction the
 * transmittance per channel beside it), which is composited over the
 * renderer's viewport.
 *
 * It is a fragment shader, not a compute shader: VTK's context is OpenGL
 * 3.2 (GLSL 1.50) on every platform it supports (macOS stops at 4.1, which
 * has no compute shaders), and the quad reuses the camera rays' code and
 * uniforms unchanged. The work a fragment may run is bounded
 * (vtkTransmittanceRayCastPass::IterationBudget loop trips: Mesa's
 * llvmpipe ends a fragment's loops after 65535, and other drivers reset a
 * GPU that runs too long): a frame traces fewer paths per pixel than asked
 * where the medium's optical depth across its box makes a path's bound
 * long, and at a new mean's first frames (NextSamples():
 * GetLastSamplesPerFrame()), and a path still running when the
 * budget is spent is kept as far as it got.
 *
 * What it draws is what the CPU tracer draws: a medium (a grid, with its
 * procedural detail, or a particle cloud's grid) and the other volumes that
 * share its shadows (guests: the camera ray through the media this volume
 * draws, scattered paths through every one), participating-medium or
 * emission-absorption, with the complete mapper's classification
 * (components, 2-D functions, gradient opacity, labels, clipping, missing
 * data). Refusal() names what it does not draw yet; the mapper then draws
 * its map-based frame and says why once.
 *
 * With Settings::Denoise the mean is composited through the denoiser
 * (vtkTransmittanceDenoisePass, vtkTyndallDenoiser): the map-based frame of
 * the same view, drawn when the mean starts (marched, full size; again
 * when its context or size is not the mean's), is its noise-free guide;
 * the mean itself is kept, so turning it on or off keeps the samples. A
 * finished mean's redraws composite the filtered image as it was; with
 * the denoiser off its images are freed. Where the map-based frame the
 * mapper draws before the paths start is already the guide's (full size,
 * full step, marched: CanGuide()), DrawGuide() draws it as the guide and
 * composites it, and the mean that starts next takes it (one map-based
 * frame fewer: GetGuideRenders()).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittancePathTracePass_h
#define vtkTransmittancePathTracePass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"
#include "vtkTransmittanceAccumulationPass.h"    // For vtkTransmittanceAccumulationPass
#include "vtkTransmittanceDenoisePass.h"         // For vtkTransmittanceDenoisePass
#include "vtkTransmittanceEnvironmentTextures.h" // For vtkTransmittanceEnvironmentTextures
#include "vtkTransmittanceRayCastPass.h"         // For vtkTransmittanceRayCastPass::Inputs
#include "vtkTransmittanceShaderQuad.h"          // For vtkTransmittanceShaderQuad
#include "vtkTransmittanceShaderSource.h"        // For vtkTransmittanceShaderSource::Variant

#include <string> // For std::string

class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittancePathTracePass : public vtkObject
{
public:
  static vtkTransmittancePathTracePass* New();
  vtkTypeMacro(vtkTransmittancePathTracePass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The tracer's settings (the mapper's).
  struct Settings
  {
    /// Paths per pixel a frame traces at most.
    int SamplesPerFrame = 4;
    /// The most scattering events of a path (1: single scattering).
    int MaximumBounces = 8;
    /// Light transmittance ratio tracked (true) or read from the frame's maps.
    bool TrackedShadows = false;
    /**
     * Free flights and tracked transmittance in closed form where the
     * medium has one (UsesClosedForm()); delta and ratio tracking otherwise.
     */
    bool ClosedForm = false;
    /// Picks the random numbers, with the frame's index and the pixel.
    int Seed = 0;
    /**
     * The mean is shown denoised (vtkTransmittanceDenoisePass, guided by the
     * map-based frame); it stays the mean of the paths.
     */
    bool Denoise = false;
  };

  /**
   * Why the frame cannot be path traced (empty: it can): a projection or
   * isosurface blend mode (neither is a medium: the CPU tracer refuses them
   * too), depth peeling (`peeling`), several processes (`distributed`).
   */
  static std::string Refusal(const vtkTransmittanceFrame& frame, bool peeling, bool distributed);

  /**
   * Whether another volume of the frame emits through its transfer
   * functions (its collisions glow in this volume's paths, by its own
   * EmissionScale).
   */
  static bool GuestsEmit(const vtkTransmittanceFrame& frame);

  /**
   * How many other volumes of the frame emit from an array (their light
   * along the scattered paths' segments, by their own EmissionScale).
   */
  static int GuestArrayEmitters(const vtkTransmittanceFrame& frame);

  /**
   * Traces a frame of `samples` paths per pixel (NextSamples()) and adds it
   * to the running mean, weighed by them, which it composites over the
   * viewport; `historyFrames` frames are in the mean before it (0 starts a
   * new mean; they must have been traced with the same settings). A pixel's
   * paths draw their random numbers by their index in the mean (from
   * GetSamples() on), not by frame: the mean of N samples is the same
   * picture however its frames split them. `inputs` are the camera rays'
   * (their depth, maps or cache, occluders; reduction and step unused).
   * False (with an error) when the shader does not compile or the images
   * cannot be made.
   */
  bool Render(const vtkTransmittanceFrame& frame, const vtkTransmittanceRayCastPass::Inputs& inputs,
    const Settings& settings, int historyFrames, int samples, vtkObject* reporter);

  /**
   * Composites the mean as it stands (no new paths), denoised with
   * Settings::Denoise; false (with an error) without one. `inputs` as
   * Render()'s (the denoiser's guide is drawn from them when the mean has
   * none yet).
   */
  bool Redraw(const vtkTransmittanceFrame& frame, const vtkTransmittanceRayCastPass::Inputs& inputs,
    const Settings& settings, vtkObject* reporter);

  /**
   * Draws the map-based frame of the camera rays' `inputs` (CanGuide())
   * into the denoiser's guide and composites it over the viewport: the same
   * picture as vtkTransmittanceRayCastPass::Render()'s, which the mean that
   * the next Render() starts takes as its guide instead of drawing it again.
   * False (with an error) when it cannot be drawn.
   */
  bool DrawGuide(const vtkTransmittanceFrame& frame,
    const vtkTransmittanceRayCastPass::Inputs& inputs, vtkObject* reporter);

  /**
   * Whether the camera rays' `inputs` draw the denoiser's guide: full size,
   * full step, marched (no samples of procedural detail), into the viewport.
   */
  static bool CanGuide(const vtkTransmittanceRayCastPass::Inputs& inputs);

  /// Forgets a guide DrawGuide() drew for the next mean (the view moved on without one).
  void DropGuide() { this->GuideForNextMean = false; }

  /// How many times the denoiser's guide was drawn (by DrawGuide() or for a mean without one).
  int GetGuideRenders() const { return this->GuideRenders; }

  /// The ray cast that draws the guide (its GetLast...() figures after DrawGuide()).
  vtkTransmittanceRayCastPass* GetGuideCast() const { return this->GuideCast; }

  /// Frames in the mean after the last Render().
  int GetHistoryFrames() const { return this->Accumulation->GetHistoryFrames(); }

  /// Paths per pixel the last Render() traced (0 before the first).
  int GetLastSamplesPerFrame() const { return this->LastSamplesPerFrame; }

  /// The samples per pixel in the mean (its frames' samples summed).
  int GetSamples() const { return this->Accumulation->GetHistorySamples(); }

  /**
   * The paths per pixel a frame traces when `requested` are asked for: at
   * most `requested`, fewer where a path's bound on loop trips (its
   * flights across the box at the majorant, the light loop and each
   * light's march or ratio tracking, over up to four bounces) times the
   * paths would pass half of IterationBudget; at least 1.
   */
  static int SamplesFor(const vtkTransmittanceFrame& frame, const Settings& settings);

  /**
   * The paths per pixel the frame after `historyFrames` frames of a mean
   * traces, when it still lacks `wanted`: 1 at its first frame, twice the
   * frame before's at each next (1, 2, 4, ...: the first picture of paths
   * after a change comes soonest, and the denoised one with it) up to
   * SamplesFor()'s; no more than `wanted` (the mean ends at its samples
   * exactly); at least 1.
   */
  static int NextSamples(
    const vtkTransmittanceFrame& frame, const Settings& settings, int historyFrames, int wanted);

  /**
   * Whether one path's bound on loop trips (as SamplesFor() counts it)
   * passes the whole budget: paths may then be cut short, their later
   * bounces lost (a darker picture). The mapper says so in a warning.
   */
  static bool MayCutPaths(const vtkTransmittanceFrame& frame, const Settings& settings);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittancePathTracePass();
  ~vtkTransmittancePathTracePass() override;

private:
  vtkTransmittancePathTracePass(const vtkTransmittancePathTracePass&) = delete;
  void operator=(const vtkTransmittancePathTracePass&) = delete;

  /**
   * The majorant the paths' flights track against (per world unit, above
   * 0): the medium's plus its guests', twice that with a coloured
   * extinction (SpectralFactor(); their shadow rays track against the
   * majorant itself, as the CPU tracer's).
   */
  static double Majorant(const vtkTransmittanceFrame& frame);
  /// Whether the medium has a coloured extinction (spectral tracking).
  static bool Chromatic(const vtkTransmittanceFrame& frame);
  /**
   * The longest flight (world length): the camera box's diagonal, with
   * guests the maps' box's (scattered flights cross every medium).
   */
  static double FlightLength(const vtkTransmittanceFrame& frame);
  /**
   * Spectral tracking's majorant factor for the flights: 2 with a coloured
   * extinction (a null collision's weight then stays below 2, the CPU
   * tracer's), else 1 (the uniform pathFlightScale).
   */
  static double SpectralFactor(const vtkTransmittanceFrame& frame);
  /// Whether the paths track against the majorant grid's blocks (Variant::PathBlocks).
  static bool UsesBlocks(const vtkTransmittanceFrame& frame);
  /**
   * Whether the paths' flights and tracked transmittance are in closed form
   * (Variant::PathClosedForm): asked for, and the medium has one with
   * nothing clipped (the CPU tracer's rule).
   */
  static bool UsesClosedForm(const vtkTransmittanceFrame& frame, const Settings& settings);
  /// The loop trips a closed-form flight or optical depth counts at most (a walk over the cells).
  static double ClosedFormCost(const vtkTransmittanceFrame& frame);
  /// Whether the paths sample the renderer's sky (it has light).
  static bool SamplesSky(const vtkTransmittanceFrame& frame);
  /// The loop trips a draw from the sky counts (its two searches).
  static int SkySearchCost(const vtkTransmittanceFrame& frame);
  /// The loop trips of a collision's light estimate from the maps (the light loop, brute-force
  /// marches).
  static double CollisionCost(const vtkTransmittanceFrame& frame);
  /// SamplesFor()'s bound on one path's loop trips.
  static double PathBound(const vtkTransmittanceFrame& frame, const Settings& settings);
  /**
   * Composites the mean denoised: the guide (the map-based frame, full
   * size, marched) drawn first when the mean has none, then the filter at
   * the mean's samples.
   */
  bool ShowDenoised(const vtkTransmittanceFrame& frame,
    const vtkTransmittanceRayCastPass::Inputs& inputs, vtkObject* reporter);
  /**
   * Draws the guide (the map-based frame, full size, marched) from the
   * camera rays' `inputs`; with `release`, frees its images but the guide
   * (DrawGuide() keeps them for the frames drawn while something moves).
   */
  bool RenderGuide(const vtkTransmittanceFrame& frame,
    const vtkTransmittanceRayCastPass::Inputs& inputs, bool release, vtkObject* reporter);
  /// Whether the guide is drawn for the mean: its view, its context and size.
  bool GuideFits(const vtkTransmittanceFrame& frame) const;
  /// Frees the guide's and the filter's images (the denoiser is off; `force`: whether or not
  /// they were made).
  void ReleaseDenoiser(vtkWindow* window, bool force = false);

  vtkTransmittanceShaderQuad Quad;
  vtkNew<vtkTransmittanceAccumulationPass> Accumulation;
  vtkNew<vtkTransmittanceRayCastPass> GuideCast; // the denoiser's guide, kept in its image
  vtkNew<vtkTransmittanceDenoisePass> Denoiser;
  vtkNew<vtkTransmittanceEnvironmentTextures> Sky; // the renderer's sky's tables
  bool GuideReady = false;              // GuideCast's image is the mean's map-based frame
  bool GuideForNextMean = false;        // DrawGuide() drew it for the mean that starts next
  int GuideRenders = 0;                 // the guides drawn
  bool DenoiserAllocated = false;       // the guide's or the filter's images may exist
  vtkMTimeType MeanSerial = 0;          // counts Render()'s frames added to the mean
  vtkMTimeType FilteredSerial = 0;      // MeanSerial when Denoised was filtered (0: not)
  vtkTextureObject* Denoised = nullptr; // the denoiser's last result
  int LastSamplesPerFrame = 0;
};

#endif
