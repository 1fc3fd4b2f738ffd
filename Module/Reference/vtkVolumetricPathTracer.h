/**
 * @class   vtkVolumetricPathTracer
 * @brief   CPU Monte Carlo reference of Tyndall's media: volumetric path tracing with multiple
 * scattering
 *
 * vtkVolumetricPathTracer renders the scene that vtkSingleScatteringReference
 * renders (one vtkVolume seen by a vtkRenderer's active camera and lit by its
 * lights, read by the same internal reader), but by Monte Carlo: each pixel
 * traces SamplesPerPixel random paths of up to MaximumBounces scattering
 * events. It is the reference for multiple scattering and the test bed of the
 * closed-form distance sampling of cosine-noise media (Balint and Mantiuk,
 * "Closed Form Transmittance in Heterogeneous Media Using Cosine Noise",
 * Algorithm 2) against delta tracking.
 *
 * The media. The scene is read as vtkSingleScatteringReference reads it,
 * into the same list of media, each asked through one interface
 * (vtkTyndallMedium): the volume's own (a grid's extinction, the transfer
 * table's at the interpolated scalar (trilinear, or a plain property's
 * nearest); a particle cloud's exact
 * sum of particles; or, with a DetailNoise, the procedural shape x noise of
 * vtkTyndallDetailMedium, never voxelised), and the renderer's other
 * Tyndall volumes (SceneShadows), whose extinction the paths cross too.
 * Colour (the scattering albedo) and emission come from the medium at the
 * point; a sample whose scalar is missing (NaN) has colour and emission 0.
 *
 * The estimator. A path starts at the pixel centre's camera ray (unprojected
 * at the near and far planes exactly as vtkSingleScatteringReference does; no
 * jitter inside the pixel, so both compute the same pixel-centre integral).
 * At each step a free-flight distance is sampled with density
 * sigma_t(t) T(t), sigma_t the sum of the media's: each medium's own flight
 * (closed form or delta tracking against its majorant), the nearest
 * winning; the camera ray samples the media the volume draws (its own, and
 * the others it draws as one medium: SceneCompositing), scattered rays every
 * medium. If the ray leaves the media's boxes first, the path ends
 * (the background is not a light: it is added by Composite(), weighted by
 * the view transmittance). At a collision at x, reached with direction w and
 * throughput beta (1 for the camera ray), the path adds
 *
 * \f[
 *   \beta \left( c(x) \big(a + \textstyle\sum_l E_l\, f_l(x)\, p(\mu_l)\, T_l(x)\big)
 *     + e_s\, e(x) \right),
 * \f]
 *
 * c the colour, a the ambient intensity, E_l, f_l (attenuation and spot
 * cone) and mu_l exactly as in vtkSingleScatteringReference (next-event
 * estimation towards every light), T_l the light transmittance (estimated,
 * see DistanceSampling; the product of every medium's), e_s e the
 * emission. Then, unless the bounce limit is
 * reached, beta is multiplied by c and a new direction is drawn from the
 * Henyey-Greenstein phase function about w (SampleHenyeyGreenstein()), the
 * phase function cancelling against its own density. With MaximumBounces = 1
 * the expectation is therefore exactly vtkSingleScatteringReference's
 * integral of T_v sigma_t J (its source J = S / sigma_t); higher orders add
 * the light scattered more than once. The ambient term is an unshadowed,
 * isotropic in-scattered radiance and is added at every collision, like the
 * emission. In the emission-absorption model a collision adds beta c and the
 * path ends (J = c, as in the reference). Secondary rays are not clipped by
 * the camera's clipping range; they run to the box's exit. Paths are
 * continued with Russian roulette once the largest channel of beta drops
 * below 0.25 (survival probability that channel; unbiased).
 *
 * Emission from an array (EmissionArrayName) is per unit length, not per
 * collision: along every segment of a path through such a medium, four
 * stratified points of the segment add beta e_s e(x) T(x) times their share
 * of its length, T the transmittance from the segment's start (ratio
 * tracked, or exact in closed form): unbiased, and independent of where the
 * flight collides.
 *
 * A coloured extinction (ExtinctionColor, the medium then alone in its
 * scene) is tracked per channel against the densest one (spectral
 * tracking): flights against twice the densest channel's majorant m, each
 * channel's throughput weighted by e_c at a real collision and by
 * (2m - e_c sigma) / (2m - sigma) at a null one; shadow rays ratio track
 * every channel; the "Transmittance" output has three components. The
 * closed form then gives way to delta tracking, with a warning.
 *
 * Random numbers: one generator per pixel (xoshiro256+, seeded by SplitMix64
 * from Seed and the pixel index), used by that pixel's samples in order, so an
 * image depends only on Seed and the settings, never on the thread count.
 *
 * Render() returns an image like vtkSingleScatteringReference's (row 0 at the
 * bottom) with point-data arrays
 *
 * - "Radiance" (3 components, double, the active scalars): the mean of the
 *   samples, linear and premultiplied, without the background;
 * - "Transmittance" (1 component, 3 with a coloured extinction): the view
 *   transmittance T_v(t_far) of the camera ray: exact (closed form) when
 *   every medium the camera ray crosses has one, else the mean over the
 *   samples of their first flight's escape (with its spectral weights per
 *   channel: an unbiased estimate);
 * - "RadianceStandardError" (3 components): the standard error of each
 *   pixel's mean, sqrt(sample variance / SamplesPerPixel) (0 with one
 *   sample).
 *
 * Statistics: the time spent sampling free-flight distances and estimating
 * light transmittance (each call timed with std::chrono::steady_clock, two
 * clock reads per call, accumulated per thread: negligible beside the
 * microseconds a call takes through 100 and more waves) and the time of
 * whole paths, both summed over the threads (so they do not depend on the
 * thread count) and divided by SamplesPerPixel: the CPU time one sample per
 * pixel costs for the whole image (GetLastTrackingTimePerSample(),
 * GetLastTotalTimePerSample()), the quantities of the paper's Table 1.
 * The closed form's exact view transmittance (the "Transmittance" output)
 * is computed outside both: it is an output, not part of a path.
 *
 * Work, counted beside the time (it does not depend on the machine): the
 * free flights and light-transmittance (shadow) rays per sample per pixel,
 * and per flight and per shadow ray the passes over all the noise's waves.
 * Delta tracking makes one pass per tentative collision (the extinction at
 * a point: a cosine per wave); the closed form makes trigonometric passes
 * (a sine and cosine per wave: where a ray enters the medium, at a cell
 * whose phases are not carried, at each step of a solve) and cell passes
 * (products and polynomial moments, no trigonometry), see
 * vtkTyndallDetailMedium. A grid medium without noise counts no passes.
 *
 * Rows are rendered in parallel with vtkSMPTools in batches; between batches
 * the main thread fires vtkCommand::ProgressEvent and checks AbortExecute,
 * as in vtkSingleScatteringReference. Bad input (whatever the scene reader
 * refuses, a size outside [1, 16384], a camera projection that cannot be
 * inverted, a majorant so large that delta tracking would take more than
 * 10^7 steps across a medium's box; a volume whose mapper draws it in a
 * projection or isosurface blend mode, vtkTyndallProjection, which is not a
 * medium) is reported with vtkErrorMacro and
 * Render() returns nullptr. A volume drawn by another (a camera group's
 * later member) draws nothing of its own: radiance 0, transmittance 1.
 *
 * The sky. The renderer's environment (vtkTyndallEnvironment: EnvironmentalBG,
 * its gradient, an equirectangular EnvironmentTexture) lights the medium:
 * at every collision of the participating model a direction l is drawn from
 * the sky (its importance sampling) and c L(l) p(mu) T(l) / pdf(l) is added,
 * T ratio tracked (or exact in closed form) to the media's boxes' sides; a
 * scattered ray that leaves the media adds beta L(w). The two are weighed
 * by the power heuristic (the sky's density against the phase function's;
 * the sky's draw at the last collision, which scatters no further, by 1),
 * so a white, non-absorbing medium under a constant sky L with the
 * background L composites to L everywhere. The camera ray's escape adds no
 * sky (the background is composited behind). vtkSingleScatteringReference
 * has the sky as the GPU's map-based frame has it instead (the mapper's
 * SkyLightDirections lights, or its mean as ambient light).
 * The property's multiple-scattering octaves
 * (vtkParticipatingMediumProperty::ScatteringOctaves) are ignored: the paths
 * scatter for real, and are what the octaves are measured against
 * (BenchMultipleScattering).
 *
 * A shaded CT. A plain vtkVolumeProperty with Shade on (VTK's gradient
 * shading, vtkTyndallShading, a local model) is traced as a medium whose
 * collisions scatter as VTK's shaded surfaces (vtkTyndallSurfaceLobe): at a
 * collision in the volume, J = Ka c + sum_l E_l f(v, l) T_l (+ the sky's
 * next-event estimate, weighed against the lobe's draws), then a direction
 * drawn from the lobe, the throughput times f / pdf. The lobe is about the
 * scalar's unit gradient (0 where it is 0, but the blending's isotropic
 * part: without it the collision only glows with Ka c); such a collision
 * sees the lights and the sky vtkTyndallSurfaceLobe::LightUnit (2 pi)
 * brighter (its next-event estimates, and the sky met by a path its lobe
 * scattered), so that one bounce is VTK's shading exactly (without its clamp
 * to 1: vtkSingleScatteringReference's picture of it), and the bounces after
 * it do not add energy (the blending's isotropic part may: it scatters 2 k
 * Kd c). The other volumes' collisions see the lights, the sky and the
 * ambient light without LightUnit (as a medium's picture does; by that
 * volume's own LightScale, ambient light and phase function, as every
 * guest's collision): the unit is the shaded collision's, not the scene's. As the map-based
 * frame's shading takes T_l, a shaded collision exchanges its light from
 * vtkTyndallShading::ShadowOffset voxels along its direction: its shadow
 * rays and its scattered ray (a surface does not shadow itself; without the
 * offset one bounce is 26 % darker on the test's blob). A headlight lights
 * from where it is (VTK's shading takes its direction along the camera ray).
 * VTK 9.2's volumetric scattering blending mixes an isotropic part into the
 * lobe (its weight k at the collision, vtkTyndallShading::BlendWeight(); one
 * bounce is VTK's blended term). Independent components: a collision is
 * shaded as one of them (its gradient, colour, coefficients and k), drawn
 * with its share of their parts in the mixture, the lobe and Ka c times the
 * parts' sum (an unbiased estimate of VTK's mixture of their shadings).
 *
 * A vtkParticipatingMediumProperty's Shade (vtkTyndallShading's surface
 * term added to the medium's single scattering: Tyndall's meaning) is a
 * local term here too: a collision in the volume scatters by its phase
 * function as before (the lights not scaled), and adds to J the lights'
 * and the sky's light reflected by the surface lobe, LightUnit sum_l E_l
 * f(v, l) T_l (component 0's gradient and coefficients, the collision's
 * colour, no ambient term, no blending; T_l from the shadow offset above),
 * the sky's by its next-event estimate alone. The lobe is never sampled:
 * the surface term does not scatter further (the medium's scattering
 * does), so one bounce is vtkSingleScatteringReference's picture, single
 * scattering plus the surface term, and the bounces after it add the
 * medium's multiple scattering (sampled, a lobe of weight 2 pi Kd c, 4.4
 * at VTK's Kd 0.7, would multiply the light at every bounce).
 *
 * @sa vtkSingleScatteringReference vtkCosineNoise vtkParticipatingMediumProperty
 */

#ifndef vtkVolumetricPathTracer_h
#define vtkVolumetricPathTracer_h

#include "TyndallReferenceModule.h" // For export macro
#include "vtkOfflineMediumRenderer.h"

class vtkImageData;
class vtkRenderer;
class vtkVolume;

class TYNDALLREFERENCE_EXPORT vtkVolumetricPathTracer : public vtkOfflineMediumRenderer
{
public:
  static vtkVolumetricPathTracer* New();
  vtkTypeMacro(vtkVolumetricPathTracer, vtkOfflineMediumRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How free-flight distances are drawn and light transmittance estimated.
  enum DistanceSamplingMode
  {
    /**
     * Closed form (procedural detail media only): a free flight inverts the
     * closed-form optical depth at -ln(1 - xi)
     * (vtkTyndallDetailMedium::ClosedFormDistance, the paper's Algorithm 2);
     * light transmittance is exact, exp(-OpticalDepth). A medium without a
     * closed form (a grid, particles, the other volumes), a clipped one and
     * a coloured extinction use DELTA_TRACKING (the volume's own: with a
     * warning).
     */
    CLOSED_FORM = 0,
    /**
     * Delta (Woodcock) tracking against each medium's constant majorant
     * (vtkTyndallMedium::GetMajorant(): the detail's shape maximum x noise
     * maximum, a grid's largest table extinction, a particle cloud's bound of
     * its sum, each times DensityScale) for free flights; light transmittance
     * by ratio tracking against the same majorants (the product of
     * 1 - sigma_t / majorant over the tentative collisions: unbiased).
     */
    DELTA_TRACKING = 1
  };

  ///@{
  /**
   * The distance sampling mode, CLOSED_FORM (default) or DELTA_TRACKING.
   */
  vtkSetClampMacro(DistanceSampling, int, CLOSED_FORM, DELTA_TRACKING);
  vtkGetMacro(DistanceSampling, int);
  void SetDistanceSamplingToClosedForm() { this->SetDistanceSampling(CLOSED_FORM); }
  void SetDistanceSamplingToDeltaTracking() { this->SetDistanceSampling(DELTA_TRACKING); }
  ///@}

  ///@{
  /**
   * Paths per pixel, in [1, 1000000]; default 16.
   */
  vtkSetClampMacro(SamplesPerPixel, int, 1, 1000000);
  vtkGetMacro(SamplesPerPixel, int);
  ///@}

  ///@{
  /**
   * The most scattering events a path takes, in [1, 1000]; default 8. 1 is
   * single scattering: the same expectation as vtkSingleScatteringReference.
   */
  vtkSetClampMacro(MaximumBounces, int, 1, 1000);
  vtkGetMacro(MaximumBounces, int);
  ///@}

  ///@{
  /**
   * Seed of the random numbers; default 1. The same seed and settings give
   * the same image whatever the number of threads.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Facts about the last successful render: the mode actually used for the
   * volume's own medium (a grid medium falls back to DELTA_TRACKING), its
   * majorant of delta tracking (per world unit; 0 in closed form), and per
   * sample per pixel (whole image), in seconds of CPU time summed over
   * the threads: the time spent in free-flight sampling and light
   * transmittance, the part of it spent in free flights (the rest is light
   * transmittance), and the time of whole paths.
   */
  vtkGetMacro(LastDistanceSampling, int);
  vtkGetMacro(LastMajorant, double);
  vtkGetMacro(LastTrackingTimePerSample, double);
  vtkGetMacro(LastFlightTimePerSample, double);
  vtkGetMacro(LastTotalTimePerSample, double);
  ///@}

  ///@{
  /**
   * The work of the last successful render (see the class description):
   * free flights and shadow rays per sample per pixel (whole image); per
   * flight and per shadow ray, the passes over the noise's waves that take
   * trigonometry (delta tracking: its tentative collisions; closed form: its
   * sine-and-cosine passes) and those that do not (closed form only: cell
   * passes; 0 in delta tracking).
   */
  vtkGetMacro(LastFlightsPerSample, double);
  vtkGetMacro(LastShadowRaysPerSample, double);
  vtkGetMacro(LastTrigonometricPassesPerFlight, double);
  vtkGetMacro(LastTrigonometricPassesPerShadowRay, double);
  vtkGetMacro(LastCellPassesPerFlight, double);
  vtkGetMacro(LastCellPassesPerShadowRay, double);
  ///@}

  /**
   * Draws a direction from the Henyey-Greenstein phase function with
   * anisotropy g (clamped to [-0.99, 0.99], as
   * vtkTransmittanceMapMath::HenyeyGreenstein) about the unit direction w:
   * mu = dot(w, out) has density p(mu) 2 pi, the azimuth is uniform.
   * u1, u2 are uniform numbers in [0, 1).
   */
  static void SampleHenyeyGreenstein(
    double g, const double w[3], double u1, double u2, double out[3]);

protected:
  vtkVolumetricPathTracer();
  ~vtkVolumetricPathTracer() override;

  int DistanceSampling = CLOSED_FORM;
  int SamplesPerPixel = 16;
  int MaximumBounces = 8;
  unsigned int Seed = 1;

  int LastDistanceSampling = CLOSED_FORM;
  double LastMajorant = 0.0;
  double LastTrackingTimePerSample = 0.0;
  double LastTotalTimePerSample = 0.0;
  double LastFlightTimePerSample = 0.0;
  double LastFlightsPerSample = 0.0;
  double LastShadowRaysPerSample = 0.0;
  double LastTrigonometricPassesPerFlight = 0.0;
  double LastTrigonometricPassesPerShadowRay = 0.0;
  double LastCellPassesPerFlight = 0.0;
  double LastCellPassesPerShadowRay = 0.0;

  bool RenderImage(vtkRenderer* renderer, vtkVolume* volume, int width, int height) override;

private:
  vtkVolumetricPathTracer(const vtkVolumetricPathTracer&) = delete;
  void operator=(const vtkVolumetricPathTracer&) = delete;
};

#endif
