/**
 * @class   vtkTransmittanceVolumeMapper
 * @brief   single-scattering volume mapper with per-light transmittance maps
 *
 * vtkTransmittanceVolumeMapper renders a vtkImageData (point or cell
 * scalars, any numeric type, one component) as a participating medium with
 * physically based single scattering, inside a normal vtkRenderer beside
 * opaque actors and other props. The scene model (extinction from VTK's
 * opacity semantics, albedo from the colour transfer function,
 * Henyey-Greenstein phase, emission, ambient, the renderer's lights) is
 * defined in Documentation/rendering-model.md; vtkSingleScatteringReference
 * renders the same model on the CPU.
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
 * data, the transfer functions, DensityScale, the lights (position,
 * direction, type, cone), the volume's matrix, the method, the number of
 * coefficients, the map size, LightSampleCount or AdaptiveThreshold. A
 * camera move never rebuilds them (but a headlight or camera light moves
 * with the camera, and so rebuilds its map). GetMapBuildCount() counts
 * the rebuilds.
 *
 * Directional lights get an orthographic map fitted to the volume's bounds,
 * positional (point and spot) lights a perspective one. A positional light
 * inside the bounds, or one needing a field of view over 150 degrees, has
 * no map: that light falls back to brute-force marching (documented
 * fallback; everything else keeps using maps). Up to 8 lights are used
 * (GetMaximumNumberOfLights()); further lights are ignored with a warning.
 *
 * View rays stop at the depth of opaque geometry already drawn. Opaque
 * actors also block light entering the medium: each frame with visible
 * opaque vtkActors, their depth is rendered from every light's frustum
 * (the TFM paper's light-space depth) and samples behind it get no light
 * from that light, whatever the method. Lights inside the bounds (no
 * frustum) are not blocked by geometry.
 *
 * Bad input is reported with vtkErrorMacro and leaves the rest of the
 * render intact: no input, no or multi-component scalars, fewer than 2
 * points along an axis, a render window without OpenGL 3.2. NaN and Inf
 * scalars are replaced by the smallest finite scalar (a warning counts
 * them). A volume larger than the GPU's 3-D texture limit is downsampled
 * by the smallest integer factor that fits, with a warning.
 *
 * The shaders are GLSL files in glsl/ embedded at build time.
 *
 * @sa vtkSingleScatteringReference vtkTransmittanceMapMath
 * vtkTransmittanceLightFrustum
 */

#ifndef vtkTransmittanceVolumeMapper_h
#define vtkTransmittanceVolumeMapper_h

#include "TyndallRenderingModule.h"  // For export macro
#include "vtkTransmittanceMapMath.h" // For the method constants
#include "vtkVolumeMapper.h"

#include <memory> // For std::unique_ptr

class vtkColorTransferFunction;

class TYNDALLRENDERING_EXPORT vtkTransmittanceVolumeMapper : public vtkVolumeMapper
{
public:
  static vtkTransmittanceVolumeMapper* New();
  vtkTypeMacro(vtkTransmittanceVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ScatteringModels
  {
    EMISSION_ABSORPTION = 0,
    SINGLE_SCATTERING = 1
  };

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
   * The scattering model: EMISSION_ABSORPTION (the colour transfer function
   * is emitted colour, as in vtkGPUVolumeRayCastMapper's unshaded composite)
   * or SINGLE_SCATTERING (default; the colour is the albedo).
   */
  vtkSetClampMacro(ScatteringModel, int, EMISSION_ABSORPTION, SINGLE_SCATTERING);
  vtkGetMacro(ScatteringModel, int);
  void SetScatteringModelToEmissionAbsorption() { this->SetScatteringModel(EMISSION_ABSORPTION); }
  void SetScatteringModelToSingleScattering() { this->SetScatteringModel(SINGLE_SCATTERING); }
  ///@}

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
   * Henyey-Greenstein anisotropy g in [-0.99, 0.99]; default 0 (isotropic).
   */
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /**
   * Multiplier of the extinction, in [0, 1e6]; default 1.
   */
  vtkSetClampMacro(DensityScale, double, 0.0, 1.0e6);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /**
   * Transmittance threshold of the adaptive methods' first march, in
   * [1e-6, 0.5]; default 0.01.
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
   * [1, 2048]; default 128.
   */
  vtkSetClampMacro(LightSampleCount, int, 1, 2048);
  vtkGetMacro(LightSampleCount, int);
  ///@}

  ///@{
  /**
   * Converts a vtkLight's dimensionless intensity into irradiance, in
   * [0, 1e6]; default 4 pi (see Documentation/rendering-model.md).
   */
  vtkSetClampMacro(LightScale, double, 0.0, 1.0e6);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Unshadowed ambient in-scattering, in [0, 1e6]; default 0.
   */
  vtkSetClampMacro(AmbientIntensity, double, 0.0, 1.0e6);
  vtkGetMacro(AmbientIntensity, double);
  ///@}

  ///@{
  /**
   * Emission (single scattering only): EmissionScale in [0, 1e6] (default
   * 0) times the EmissionColor transfer function of the scalar (default
   * none: no emission) times the extinction.
   */
  vtkSetClampMacro(EmissionScale, double, 0.0, 1.0e6);
  vtkGetMacro(EmissionScale, double);
  void SetEmissionColor(vtkColorTransferFunction* emission);
  vtkGetObjectMacro(EmissionColor, vtkColorTransferFunction);
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

  /**
   * How many times the transmittance maps were built.
   */
  vtkGetMacro(MapBuildCount, int);

  /**
   * Wall-clock seconds of the last map build (with glFinish, so it measures
   * the GPU work).
   */
  vtkGetMacro(LastMapBuildTime, double);

  /**
   * The most lights used; further lights are ignored with a warning.
   */
  static int GetMaximumNumberOfLights() { return 8; }

  /**
   * Render the volume (called by the renderer).
   */
  void Render(vtkRenderer* renderer, vtkVolume* volume) override;

  /**
   * Release the OpenGL resources of the window.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

  vtkMTimeType GetMTime() override;

protected:
  vtkTransmittanceVolumeMapper();
  ~vtkTransmittanceVolumeMapper() override;

  int ScatteringModel = SINGLE_SCATTERING;
  int TransmittanceMethod = ADAPTIVE_ETM;
  int NumberOfCoefficients = 8;
  int TransmittanceMapSize = 256;
  double ScatteringAnisotropy = 0.0;
  double DensityScale = 1.0;
  double AdaptiveThreshold = 0.01;
  double SampleDistance = 0.0;
  int LightSampleCount = 128;
  double LightScale;
  double AmbientIntensity = 0.0;
  double EmissionScale = 0.0;
  vtkColorTransferFunction* EmissionColor = nullptr;
  bool Jitter = true;
  int MapBuildCount = 0;
  double LastMapBuildTime = 0.0;

private:
  vtkTransmittanceVolumeMapper(const vtkTransmittanceVolumeMapper&) = delete;
  void operator=(const vtkTransmittanceVolumeMapper&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
