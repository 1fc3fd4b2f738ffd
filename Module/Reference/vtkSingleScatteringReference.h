/**
 * @class   vtkSingleScatteringReference
 * @brief   CPU reference renderer of Tyndall's rendering model (single scattering)
 *
 * vtkSingleScatteringReference renders one vtkVolume, seen by a vtkRenderer's
 * active camera and lit by the renderer's lights, with exactly the formulas of
 * Documentation/rendering-model.md, in double precision with fine steps and
 * no transmittance maps: the light transmittance T_l is marched towards each
 * light at every sample. It is the oracle of Tyndall's tests and can make
 * offline reference images.
 *
 * It reads the scene exactly as vtkTransmittanceVolumeMapper does (one
 * internal reader, vtkTyndallSceneReader): the medium from the volume (its mapper's
 * input and scalar selection, its matrix, its vtkParticipatingMediumProperty
 * or plain vtkVolumeProperty) and the renderer's lights; so a scene set up
 * for the mapper renders here with no extra settings. This class holds only
 * the integrator's settings: the step sizes and early termination.
 *
 * Render() returns an image of width x height pixels (row 0 is the bottom
 * row, like VTK images and screen captures) with two point-data arrays:
 *
 * - "Radiance" (3 components, double, the active scalars): the linear,
 *   premultiplied integral term of the pixel's ray, without the background;
 * - "Transmittance" (1 component, double): the view transmittance T_v(t_far)
 *   of the ray (the frame buffer's alpha would be 1 - T_v); 3 components,
 *   one per channel, for a coloured extinction
 *   (vtkParticipatingMediumProperty::ExtinctionColor with unequal
 *   components).
 *
 * Composite() blends that over a constant background colour
 * (Radiance + Transmittance * background per channel, what VTK's frame buffer gets from
 * the mapper's ONE, ONE_MINUS_SRC_ALPHA blending) and converts it like an
 * 8-bit frame buffer: clamp to [0, 1], round(x * 255).
 *
 * Camera: renderer->GetActiveCamera() with the aspect width / height. Pixel
 * centres are unprojected at the near and far clipping planes through the
 * inverse of vtkCamera::GetCompositeProjectionTransformMatrix(aspect, -1, 1),
 * so perspective (vertical ViewAngle, or horizontal with
 * UseHorizontalViewAngle), parallel projection, window centre, view shear
 * and off-axis projection are honoured as in VTK's own rendering. A ray
 * goes from its near-plane point to its far-plane point: the clipping range
 * clips the medium, as it does on the GPU. Remember
 * renderer->ResetCameraClippingRange() for a renderer that was never
 * rendered. VTK's renderer creates an automatic headlight at its first
 * render when no light is on; a renderer that was never rendered may
 * therefore have no lights, and then single scattering gives only ambient
 * light and emission (no error). The renderer's sky (vtkTyndallEnvironment)
 * lights the medium as in the GPU's map-based frame, of which this is the
 * twin: as the mapper's SkyLightDirections directional lights
 * (vtkTyndallSkyLights, shadowed like the others), or with 0 (or no slot
 * left) its mean radiance added to the ambient term (vtkVolumetricPathTracer
 * samples the sky). The mapper's clipping planes and cropping
 * cut the medium (vtkTyndallClipRegion's rules, as on the GPU): for camera
 * rays and for the light, unless LightIgnoresClipping is on. VTK's
 * projection blend modes (maximum, minimum and average intensity, additive)
 * are drawn by vtkTyndallProjection's rules (its Ray, at the middles of the
 * camera steps); the other blend modes are drawn as composite. A plain
 * vtkVolumeProperty with Shade on is gradient-shaded by vtkTyndallShading's
 * rules (its twin), each light's transmittance marched from one voxel
 * towards the light.
 *
 * Numerical method: a camera ray's segment inside the medium's box is cut
 * into n = ceil(length / StepSize) equal steps. The medium is sampled at each
 * step's midpoint and taken as constant over the step, which is integrated
 * exactly: the step adds T_v * J * (1 - exp(-sigma_t dt)) to the radiance,
 * J = S / sigma_t being the source per unit extinction, and multiplies T_v
 * by exp(-sigma_t dt) (the compositing of VTK's GPU ray caster with
 * alpha_step = 1 - (1 - alpha)^(dt / u)). A homogeneous emission-absorption
 * medium is thus integrated exactly; the error is second order in the step
 * otherwise. The light transmittance T_l at a sample is exp(-tau), tau being
 * the midpoint rule of sigma_t over n_l = ceil(d / LightStepSize) equal steps
 * of the segment from the sample to where the ray towards the light leaves
 * the box (or reaches a positional light inside it). Rays stop
 * when T_v (and light marches when T_l, or with multiple-scattering
 * octaves the last octave's T_l^(b^(N-1))) fall below
 * EarlyTerminationThreshold. Multiple-scattering octaves
 * (vtkParticipatingMediumProperty::ScatteringOctaves) are applied exactly
 * as defined (vtkTransmittanceMapMath::OctaveScattering()). The transfer functions are read from
 * the scene's table (vtkTyndallTransferTable, the GPU's table), interpolated linearly.
 *
 * Procedural detail (vtkParticipatingMediumProperty::SetDetailNoise): the
 * extinction at a sample is the detail medium's (pre-classified shape times
 * the cosine noise, vtkTyndallDetailMedium), and T_l is computed in closed
 * form, cell by cell of the shape grid, exact to rounding: LightStepSize is
 * then unused. The automatic camera step is then at most an eighth of the
 * noise's shortest wavelength.
 *
 * Rows of pixels are rendered in parallel with vtkSMPTools in batches;
 * between batches the main thread fires vtkCommand::ProgressEvent (call
 * data: a double* progress in [0, 1]) and checks AbortExecute. StartEvent
 * and EndEvent surround a render.
 *
 * Bad input (anything the scene reader refuses, see
 * Documentation/rendering-model.md; a size outside [1, 16384]; steps so
 * small that a ray would need more than 10^7 of them; a camera whose
 * projection cannot be inverted) is reported with vtkErrorMacro and Render()
 * returns nullptr.
 *
 * The reference renders the volume alone: no opaque geometry, no depth
 * buffer; L_behind is the background given to Composite().
 *
 * @sa vtkTransmittanceVolumeMapper vtkParticipatingMediumProperty
 */

#ifndef vtkSingleScatteringReference_h
#define vtkSingleScatteringReference_h

#include "TyndallReferenceModule.h" // For export macro
#include "vtkOfflineMediumRenderer.h"

class vtkImageData;
class vtkRenderer;
class vtkVolume;

class TYNDALLREFERENCE_EXPORT vtkSingleScatteringReference : public vtkOfflineMediumRenderer
{
public:
  static vtkSingleScatteringReference* New();
  vtkTypeMacro(vtkSingleScatteringReference, vtkOfflineMediumRenderer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Step along camera rays, in world units, in [0, 1e30]. 0 (the default)
   * chooses it automatically: a quarter of the finest feature of the media
   * the camera rays sample (vtkTyndallMedium::GetFinestFeature(): the
   * smallest voxel spacing after the volume's matrix, or half the shortest
   * wavelength of procedural detail).
   */
  vtkSetClampMacro(StepSize, double, 0.0, 1.0e30);
  vtkGetMacro(StepSize, double);
  ///@}

  ///@{
  /**
   * Step of the shadow rays towards the lights, in world units, in
   * [0, 1e30]. 0 (the default) uses the camera rays' step.
   */
  vtkSetClampMacro(LightStepSize, double, 0.0, 1.0e30);
  vtkGetMacro(LightStepSize, double);
  ///@}

  /**
   * The medium's light transmittance from the world point `point` (inside
   * the volume or anywhere else: the ground under a cloud) to light `light`
   * of the scene, the light-th one Tyndall reads (switched on, positive
   * intensity, in the renderer's order, at most 8), with this object's
   * LightStepSize and EarlyTerminationThreshold, clipping as in Render();
   * per channel (equal without a coloured extinction). What a surface in
   * the medium's shadow receives (vtkVolumeShadowReceiverPass). False (with
   * an error) on bad input or a light index out of range.
   */
  bool ComputeLightTransmittance(vtkRenderer* renderer, vtkVolume* volume, int light,
    const double point[3], double transmittance[3]);

  ///@{
  /**
   * Camera rays stop when their transmittance T_v, and shadow rays when their
   * transmittance T_l, falls below this value, in [0, 1]; default 1e-6. The
   * radiance then misses at most this fraction of the brightest source. 0
   * disables early termination.
   */
  vtkSetClampMacro(EarlyTerminationThreshold, double, 0.0, 1.0);
  vtkGetMacro(EarlyTerminationThreshold, double);
  ///@}

  ///@{
  /**
   * When on, light rays see the whole medium while camera rays see only what
   * the mapper's clipping planes and cropping keep: the picture of a renderer
   * whose shadows ignore clipping (VTK's own shadow rays), for comparison.
   * Default off: the clipped-away part casts no shadow, as in Tyndall's
   * mapper.
   */
  vtkSetMacro(LightIgnoresClipping, bool);
  vtkGetMacro(LightIgnoresClipping, bool);
  vtkBooleanMacro(LightIgnoresClipping, bool);
  ///@}

  ///@{
  /**
   * The step sizes the last successful render used (world units).
   */
  vtkGetMacro(LastStepSize, double);
  vtkGetMacro(LastLightStepSize, double);
  ///@}

protected:
  vtkSingleScatteringReference();
  ~vtkSingleScatteringReference() override;

  double StepSize = 0.0;
  double LightStepSize = 0.0;
  double EarlyTerminationThreshold = 1.0e-6;
  bool LightIgnoresClipping = false;

  double LastStepSize = 0.0;
  double LastLightStepSize = 0.0;

  bool RenderImage(vtkRenderer* renderer, vtkVolume* volume, int width, int height) override;

private:
  vtkSingleScatteringReference(const vtkSingleScatteringReference&) = delete;
  void operator=(const vtkSingleScatteringReference&) = delete;
};

#endif
