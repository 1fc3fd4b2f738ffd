/**
 * @class   vtkSingleScatteringReference
 * @brief   CPU reference renderer of Tyndall's rendering model (single scattering)
 *
 * vtkSingleScatteringReference renders one vtkVolume, seen by a vtkRenderer's
 * active camera and lit by the renderer's lights, with exactly the formulas of
 * Documentation/rendering-model.md: extinction from VTK's opacity semantics,
 * albedo (or emitted colour) from the colour transfer function, the
 * Henyey-Greenstein phase function normalised to 1/(4 pi), light irradiance
 * E = LightScale * Intensity * DiffuseColor with VTK's attenuation and spot
 * cone, unshadowed ambient, optional emission, and shadows (the light
 * transmittance T_l) computed by brute-force marching towards each light.
 * It is slow and accurate: double precision throughout, fine steps, no
 * transmittance maps. It is the oracle of Tyndall's tests and can be used to
 * make offline reference images.
 *
 * Render() returns an image of width x height pixels (row 0 is the bottom
 * row, like VTK images and screen captures) with two point-data arrays:
 *
 * - "Radiance" (3 components, double, the active scalars): the linear,
 *   premultiplied integral term of the pixel's ray, without the background;
 * - "Transmittance" (1 component, double): the view transmittance T_v(t_far)
 *   of the ray (the frame buffer's alpha would be 1 - T_v).
 *
 * Composite() blends that over a constant background colour
 * (Radiance + Transmittance * background, what VTK's frame buffer gets from
 * the mapper's ONE, ONE_MINUS_SRC_ALPHA blending) and converts it like an
 * 8-bit frame buffer: clamp to [0, 1], round(x * 255).
 *
 * What is taken from the scene:
 *
 * - Camera: renderer->GetActiveCamera() with the aspect width / height. Pixel
 *   centres are unprojected at the near and far clipping planes through the
 *   inverse of vtkCamera::GetCompositeProjectionTransformMatrix(aspect, -1, 1),
 *   so perspective (vertical ViewAngle, or horizontal with
 *   UseHorizontalViewAngle), parallel projection, window centre, view shear
 *   and off-axis projection are honoured as in VTK's own rendering. A ray
 *   goes from its near-plane point to its far-plane point (on the line
 *   through the camera position for perspective views): the clipping range
 *   clips the medium, as it does on the GPU. Remember
 *   renderer->ResetCameraClippingRange() for a renderer that was never
 *   rendered.
 * - Volume: the mapper's input (its producer is updated first), a
 *   vtkImageData with one-component scalars of any numeric type, selected by
 *   the mapper's ScalarMode / ArrayAccessMode / ArrayId / ArrayName (point
 *   scalars by default). Cell scalars are treated as point scalars of the
 *   cell centres (clamped over the outer half cells), as the model says. The
 *   image's origin, spacing and extent and the vtkVolume's matrix
 *   (position, orientation, scale, origin, user matrix or transform) are
 *   honoured; the medium fills the image's bounds (the box through the
 *   volume's matrix). A non-identity direction matrix is refused. The
 *   mapper's cropping, clipping planes and blend mode are ignored.
 * - Volume property: GetScalarOpacity(0), GetRGBTransferFunction(0) (or the
 *   gray transfer function for one colour channel) and
 *   GetScalarOpacityUnitDistance(0); interpolation is always trilinear (of
 *   the scalars, before the transfer functions). The renderer's lights:
 *   switched-on lights only. Scene lights use their transformed position and
 *   focal point; headlights sit at the camera's position and shine at its
 *   focal point, and camera lights are placed by the camera's
 *   GetCameraLightTransformMatrix(), as vtkRenderer places them before each
 *   render when LightFollowCamera is on (the default; with it off, the
 *   lights' stored geometry is used). The lights are not modified. Note that
 *   VTK's renderer creates an automatic headlight at its first render when
 *   no light is on; a renderer that was never rendered may therefore have
 *   no lights, and then single scattering gives only ambient light and
 *   emission (no error).
 *
 * Numerical method: a camera ray's segment inside the volume's box is cut
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
 * the volume's box (or reaches a positional light inside it). Rays stop
 * when T_v (and light marches when T_l) fall below
 * EarlyTerminationThreshold.
 *
 * Transfer functions are not thread safe, so before the parallel loop they
 * are tabulated over the data's finite scalar range into tables of
 * TransferFunctionTableSize entries (default 4096, the resolution of the GPU
 * mapper's tables), read with linear interpolation: the opacity alpha (the
 * extinction is computed per sample from the interpolated alpha), the colour
 * and the emission colour. Rows of pixels are rendered in parallel with
 * vtkSMPTools in batches; between batches the main thread fires
 * vtkCommand::ProgressEvent (call data: a double* progress in [0, 1]) and
 * checks AbortExecute. StartEvent and EndEvent surround a render.
 *
 * Bad input (no renderer, volume, mapper or input; input that is not a
 * vtkImageData or is empty; missing or multi-component scalars; a
 * non-identity direction matrix; zero or non-finite spacing; a singular or
 * projective volume matrix; a non-positive unit distance; a size outside
 * [1, 16384]; steps so small that a ray would need more than 10^7 of them)
 * is reported with vtkErrorMacro and Render() returns nullptr. NaN scalars
 * are treated as empty medium (any sample interpolated from a NaN is empty)
 * with one warning per render. A volume one point thick along an axis has a
 * box of zero thickness: it is valid and renders as empty space.
 *
 * The reference renders the volume alone: no opaque geometry, no depth
 * buffer; L_behind is the background given to Composite().
 *
 * @sa vtkTransmittanceVolumeMapper
 */

#ifndef vtkSingleScatteringReference_h
#define vtkSingleScatteringReference_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"

class vtkColorTransferFunction;
class vtkImageData;
class vtkRenderer;
class vtkVolume;

class TYNDALLRENDERING_EXPORT vtkSingleScatteringReference : public vtkObject
{
public:
  static vtkSingleScatteringReference* New();
  vtkTypeMacro(vtkSingleScatteringReference, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ScatteringModels
  {
    EMISSION_ABSORPTION = 0,
    SINGLE_SCATTERING = 1
  };

  ///@{
  /**
   * The light transport model: EMISSION_ABSORPTION (the colour transfer
   * function is the emitted colour, as in VTK) or SINGLE_SCATTERING (the
   * colour is the albedo; lights, ambient and emission; the default).
   */
  vtkSetClampMacro(ScatteringModel, int, EMISSION_ABSORPTION, SINGLE_SCATTERING);
  vtkGetMacro(ScatteringModel, int);
  void SetScatteringModelToEmissionAbsorption() { this->SetScatteringModel(EMISSION_ABSORPTION); }
  void SetScatteringModelToSingleScattering() { this->SetScatteringModel(SINGLE_SCATTERING); }
  ///@}

  ///@{
  /**
   * Multiplies the extinction coefficient derived from the opacity transfer
   * function, in [0, 1e6]; default 1.
   */
  vtkSetClampMacro(DensityScale, double, 0.0, 1.0e6);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /**
   * The Henyey-Greenstein asymmetry g, in [-0.99, 0.99]; default 0
   * (isotropic). g > 0 scatters forwards (bright when looking into a light).
   */
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /**
   * Converts a vtkLight's dimensionless intensity into irradiance, in
   * [0, 1e6]; default 4 pi (an isotropic, optically thin, white medium lit by
   * an intensity-1 light then has the brightness of its albedo).
   */
  vtkSetClampMacro(LightScale, double, 0.0, 1.0e6);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Unshadowed white ambient in-scattering A (single scattering only), in
   * [0, 1e6]; default 0.
   */
  vtkSetClampMacro(AmbientIntensity, double, 0.0, 1.0e6);
  vtkGetMacro(AmbientIntensity, double);
  ///@}

  ///@{
  /**
   * Emission (single scattering only): epsilon = EmissionScale * e(s) *
   * sigma_t, e being the EmissionColor transfer function. EmissionScale is in
   * [0, 1e6], default 0; EmissionColor defaults to null (no emission).
   */
  vtkSetClampMacro(EmissionScale, double, 0.0, 1.0e6);
  vtkGetMacro(EmissionScale, double);
  void SetEmissionColor(vtkColorTransferFunction* emission);
  vtkGetObjectMacro(EmissionColor, vtkColorTransferFunction);
  ///@}

  ///@{
  /**
   * Step along camera rays, in world units, in [0, 1e30]. 0 (the default)
   * chooses it automatically: a quarter of the smallest voxel spacing after
   * the volume's matrix (the world length of one index step along the
   * image's axes).
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
   * Number of entries of the transfer-function tables, in [2, 1048576];
   * default 4096.
   */
  vtkSetClampMacro(TransferFunctionTableSize, int, 2, 1048576);
  vtkGetMacro(TransferFunctionTableSize, int);
  ///@}

  ///@{
  /**
   * Set to true (from a ProgressEvent observer, for example) to stop the
   * current render after the running batch of rows; Render() then returns
   * nullptr without an error. Reset to false when a render starts.
   */
  vtkSetMacro(AbortExecute, bool);
  vtkGetMacro(AbortExecute, bool);
  vtkBooleanMacro(AbortExecute, bool);
  ///@}

  /**
   * Progress of the current render, in [0, 1].
   */
  vtkGetMacro(Progress, double);

  /**
   * Renders `volume` as seen by `renderer`'s active camera and lights into a
   * width x height image (each in [1, 16384]). Returns the image, owned by
   * this object and valid until the next Render() (see the class
   * description for its arrays), or nullptr on bad input (with an error) or
   * when aborted.
   */
  vtkImageData* Render(vtkRenderer* renderer, vtkVolume* volume, int width, int height);

  /**
   * The image of the last successful Render(); empty before one and after a
   * failed or aborted one.
   */
  vtkImageData* GetOutput();

  ///@{
  /**
   * Composites the last render over a constant background colour (by default
   * the background of the renderer passed to the last Render()) and converts
   * it like an 8-bit frame buffer: each channel clamp(Radiance + T *
   * background, 0, 1), rounded to the nearest of 0..255. Returns a width x
   * height image with 3-component unsigned char scalars "RGB" (row 0 at the
   * bottom), owned by this object and valid until the next call of Render()
   * or Composite(); nullptr (with an error) when there is no render.
   */
  vtkImageData* Composite();
  vtkImageData* Composite(const double background[3]);
  ///@}

  ///@{
  /**
   * Facts about the last successful render: the step sizes used (world
   * units), the renderer's background colour and the wall-clock time in
   * seconds.
   */
  vtkGetMacro(LastStepSize, double);
  vtkGetMacro(LastLightStepSize, double);
  vtkGetVector3Macro(LastBackground, double);
  vtkGetMacro(LastRenderTime, double);
  ///@}

protected:
  vtkSingleScatteringReference();
  ~vtkSingleScatteringReference() override;

  int ScatteringModel = SINGLE_SCATTERING;
  double DensityScale = 1.0;
  double ScatteringAnisotropy = 0.0;
  double LightScale = 12.566370614359172;
  double AmbientIntensity = 0.0;
  double EmissionScale = 0.0;
  vtkColorTransferFunction* EmissionColor = nullptr;
  double StepSize = 0.0;
  double LightStepSize = 0.0;
  double EarlyTerminationThreshold = 1.0e-6;
  int TransferFunctionTableSize = 4096;
  bool AbortExecute = false;
  double Progress = 0.0;

  double LastStepSize = 0.0;
  double LastLightStepSize = 0.0;
  double LastBackground[3] = { 0.0, 0.0, 0.0 };
  double LastRenderTime = 0.0;

  vtkImageData* Output = nullptr;
  vtkImageData* CompositeOutput = nullptr;

private:
  vtkSingleScatteringReference(const vtkSingleScatteringReference&) = delete;
  void operator=(const vtkSingleScatteringReference&) = delete;

  // Render() after the checks of its arguments; false on error or abort.
  bool RenderInternal(vtkRenderer* renderer, vtkVolume* volume, int width, int height);
  void UpdateProgress(double progress);
};

#endif
