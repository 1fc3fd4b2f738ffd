/**
 * @class   vtkParticipatingMediumProperty
 * @brief   the optical properties of a participating medium, shared by Tyndall's renderers
 *
 * vtkParticipatingMediumProperty is a vtkVolumeProperty (set it on a vtkVolume
 * with SetProperty()) that adds what Tyndall's rendering model needs beyond
 * VTK's transfer functions. It is the one description of a medium: the GPU
 * mapper (vtkTransmittanceVolumeMapper) and the CPU reference
 * (vtkSingleScatteringReference) both read it from the volume, so a scene is
 * described once and both renderers draw the same thing.
 *
 * From vtkVolumeProperty, for component 0:
 *
 * - GetScalarOpacity() and GetScalarOpacityUnitDistance(): VTK's opacity
 *   semantics, turned into the extinction coefficient
 *   sigma_t = DensityScale * -ln(1 - alpha) / unit distance (the unit
 *   distance must be positive);
 * - GetRGBTransferFunction(), or GetGrayTransferFunction() when
 *   GetColorChannels() is 1: the single-scattering albedo, or the emitted
 *   colour in the emission-absorption model;
 * - GetIsoSurfaceValues(), when the mapper's blend mode is VTK's isosurface
 *   mode (vtkTyndallIsosurfaces): the surfaces drawn, lit by scattering.
 *
 * With Shade on (component 0), VTK's gradient surface term with the
 * Diffuse, Specular and SpecularPower coefficients is added to the
 * medium's scattering, shadowed like it (vtkTyndallShading: its surfaces
 * catch highlights; Ambient is not read, the medium's AmbientIntensity
 * is). Several components are read as vtkTyndallComponents reads them
 * (independent ones' extinctions add). The classification is VTK's:
 * gradient opacity and a 2-D transfer function (TF_2D, over the scalar and
 * its gradient magnitude: ParaView's Use Transfer 2D) give the extinction
 * and the albedo as they give a plain property's opacity and colour
 * (vtkTyndallGridMedium; not with procedural detail, which multiplies the
 * 1-D extinction, nor where vtkTyndallVolumeSettings names them, nor for
 * a particle cloud; the emission colour, of the 1-D scalar, emits nothing
 * with a 2-D function). Such a volume is drawn apart from the volumes it
 * overlaps (not in a SceneCompositing group). The
 * interpolation type is ignored: Tyndall interpolates the scalars
 * trilinearly and lights the medium by scattering. A plain
 * vtkVolumeProperty can be used too, with VTK's meaning: the settings below
 * have their defaults, except that with Shade off (VTK's default) it is
 * VTK's unlit emission-absorption picture, with Shade on VTK's gradient
 * shading shadowed by the medium (vtkTyndallShading), and its nearest
 * interpolation is honoured.
 *
 * The model is defined in Documentation/rendering-model.md.
 *
 * @sa vtkTransmittanceVolumeMapper vtkSingleScatteringReference
 */

#ifndef vtkParticipatingMediumProperty_h
#define vtkParticipatingMediumProperty_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkSmartPointer.h"     // For vtkSmartPointer
#include "vtkVersionMacros.h"    // For VTK_VERSION_NUMBER
#include "vtkVolumeProperty.h"

class vtkColorTransferFunction;
class vtkCosineNoise;

class TYNDALLMEDIUM_EXPORT vtkParticipatingMediumProperty : public vtkVolumeProperty
{
public:
  static vtkParticipatingMediumProperty* New();
  vtkTypeMacro(vtkParticipatingMediumProperty, vtkVolumeProperty);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ScatteringModels
  {
    EMISSION_ABSORPTION = 0,
    SINGLE_SCATTERING = 1
  };

  ///@{
  /**
   * The light transport model: EMISSION_ABSORPTION (the colour transfer
   * function is the emitted colour, as in vtkGPUVolumeRayCastMapper's
   * unshaded composite) or SINGLE_SCATTERING (the colour is the albedo; the
   * renderer's lights, ambient and emission; the default).
   */
  vtkSetClampMacro(ScatteringModel, int, EMISSION_ABSORPTION, SINGLE_SCATTERING);
  vtkGetMacro(ScatteringModel, int);
  void SetScatteringModelToEmissionAbsorption() { this->SetScatteringModel(EMISSION_ABSORPTION); }
  void SetScatteringModelToSingleScattering() { this->SetScatteringModel(SINGLE_SCATTERING); }
  const char* GetScatteringModelAsString();
  ///@}

  ///@{
  /**
   * Multiplies the extinction derived from the opacity transfer function,
   * in [0, 1e6]; default 1.
   */
  vtkSetClampMacro(DensityScale, double, 0.0, 1.0e6);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /**
   * The Henyey-Greenstein asymmetry g, in [-0.99, 0.99]; default 0
   * (isotropic). g > 0 scatters forwards (bright when looking into a light).
   *
   * VTK 9.2 and later declare this setting in vtkVolumeProperty itself (a
   * float in [-1, 1], for VTK's own volumetric scattering): built against
   * such a VTK (ParaView 5.11's, for Tyndall's plugin) this class keeps
   * vtkVolumeProperty's member and narrows its setter to [-0.99, 0.99], so
   * code that sets it builds against either VTK and means the same.
   */
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  void SetScatteringAnisotropy(float g) override;
#else
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
#endif
  ///@}

  ///@{
  /**
   * Irradiance per unit of vtkLight intensity, in [0, 1e6]; default 4 pi:
   * an isotropic, optically thin, white medium lit by an intensity-1 light
   * then has the brightness of its albedo. Per medium, like VTK's Diffuse
   * coefficient.
   */
  vtkSetClampMacro(LightScale, double, 0.0, 1.0e6);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Multiple scattering approximated by octaves (single scattering only;
   * Documentation/rendering-model.md, "Multiple scattering"): each sample
   * adds, per light, ScatteringOctaves terms; term i scatters a^i times the
   * albedo^i more light (a = OctaveScattering), sees the light through
   * b^i times the extinction (b = OctaveExtinction: the map's
   * transmittance raised to b^i, so the octaves cost no extra map) and
   * scatters with anisotropy c^i g (c = OctaveAnisotropy); the terms i >= 1
   * are multiplied by 1 - T^k (k = OctaveBuildUp: multiply scattered light
   * builds up over the first optical depths 1/k from the lit side and is
   * absent where the light has crossed no medium; 0 turns it off, giving
   * Wrenninge's octaves). One octave is single scattering alone. The camera
   * rays and the maps are unchanged. Ranges: ScatteringOctaves [1, 8],
   * default 2; OctaveScattering [0, 4], default 1.3 (above 1: the one
   * further octave stands for every order of scattering after the first);
   * OctaveExtinction and OctaveAnisotropy [0, 1], defaults 0.45 and 0;
   * OctaveBuildUp [0, 64], default 6. The defaults were chosen by
   * BenchMultipleScattering --fit against the path tracer with up to 128
   * bounces: 3.2x less error than single scattering on the dense medium and
   * the thick cloud (see the documentation).
   */
  vtkSetClampMacro(ScatteringOctaves, int, 1, 8);
  vtkGetMacro(ScatteringOctaves, int);
  vtkSetClampMacro(OctaveScattering, double, 0.0, 4.0);
  vtkGetMacro(OctaveScattering, double);
  vtkSetClampMacro(OctaveExtinction, double, 0.0, 1.0);
  vtkGetMacro(OctaveExtinction, double);
  vtkSetClampMacro(OctaveAnisotropy, double, 0.0, 1.0);
  vtkGetMacro(OctaveAnisotropy, double);
  vtkSetClampMacro(OctaveBuildUp, double, 0.0, 64.0);
  vtkGetMacro(OctaveBuildUp, double);
  ///@}

  ///@{
  /**
   * Coloured extinction (a chromatic medium: coloured smoke, stained
   * tissue, a Rayleigh-like tint; Documentation/rendering-model.md,
   * "Coloured extinction"): the extinction of channel k is ExtinctionColor[k]
   * times the extinction the opacity transfer function gives, so light
   * crossing the medium takes the colour of its transmittance. Each
   * component in [0, 1]; default (1, 1, 1), grey. Equal components are the
   * same as a DensityScale (and cost nothing more); different ones make
   * the view transmittance and the light transmittance per channel (the
   * maps are unchanged: each channel's optical depth is a multiple of the
   * densest channel's, so its transmittance is a power of the map's).
   * vtkVolumetricPathTracer refuses a chromatic medium.
   */
  void SetExtinctionColor(double red, double green, double blue);
  void SetExtinctionColor(const double color[3])
  {
    this->SetExtinctionColor(color[0], color[1], color[2]);
  }
  vtkGetVector3Macro(ExtinctionColor, double);
  ///@}

  ///@{
  /**
   * Unshadowed white ambient in-scattering (single scattering only), in
   * [0, 1e6]; default 0.
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
   * Emission from a separate array, for fire and explosions
   * (Documentation/rendering-model.md, "Fire: emission from a temperature
   * array"). With EmissionArrayName set (default none) to a one-component
   * array of the input image beside the rendered scalars (same point or
   * cell association; a VDB's grid read with vtkOpenVDBImageReader::
   * AddGridName()), single scattering emits, per unit length and
   * independently of the extinction, EmissionScale times the emission colour
   * of that array's value a: with Blackbody on (default off) the colour of a
   * black body at a * TemperatureScale Kelvin (TemperatureScale in
   * [0, 1e6], default 1; vtkBlackbody::LinearSRGB normalised to luminance 1
   * at the array's largest temperature), else the EmissionColor transfer
   * function of a (or the colour transfer function without one). Non-finite
   * values emit nothing. The extinction and albedo still follow the
   * rendered scalars. A name the input lacks is an error.
   */
  vtkSetStringMacro(EmissionArrayName);
  vtkGetStringMacro(EmissionArrayName);
  vtkSetMacro(Blackbody, bool);
  vtkGetMacro(Blackbody, bool);
  vtkBooleanMacro(Blackbody, bool);
  vtkSetClampMacro(TemperatureScale, double, 0.0, 1.0e6);
  vtkGetMacro(TemperatureScale, double);
  ///@}

  ///@{
  /**
   * Procedural detail (default none): with a vtkCosineNoise set, the medium
   * is the volume's pre-classified extinction (each voxel's scalar through
   * the opacity transfer function, times DensityScale, interpolated
   * trilinearly) times the noise's ExtinctionScale times max(0, noise), the
   * noise evaluated at the image's data coordinates and never sampled into
   * a grid. Light transmittance through it is integrated in closed form,
   * cell by cell of the volume (Documentation/rendering-model.md, "Procedural
   * detail"). The noise has at most 256 waves (directions x octaves). Colour
   * and emission still follow the scalar at the sample.
   */
  void SetDetailNoise(vtkCosineNoise* noise);
  vtkGetObjectMacro(DetailNoise, vtkCosineNoise);
  ///@}

  ///@{
  /**
   * The width of the filter of procedural detail on camera rays, in pixels
   * (range [0, 4], default 0.5): a camera sample sees each wave of the
   * noise filtered by a Gaussian whose standard deviation is DetailFilterWidth
   * times the world width of a pixel at the sample (vtkTyndallFootprint),
   * that is the wave with its amplitude times exp(-|k|^2 sigma^2 / 2), and
   * a wave whose factor falls below 1/100 not at all. Waves finer than a
   * pixel or two fade out instead of aliasing, and cost nothing where none
   * of the volume is near enough to show them. 0: unfiltered (every wave
   * everywhere, as before). Light rays and the transmittance maps see the
   * unfiltered noise (Documentation/rendering-model.md, "Procedural detail").
   */
  vtkSetClampMacro(DetailFilterWidth, double, 0.0, 4.0);
  vtkGetMacro(DetailFilterWidth, double);
  ///@}

  ///@{
  /**
   * Whether the medium is lit through the other media of its renderer (On,
   * the default): every other visible vtkVolume drawn by a
   * vtkTransmittanceVolumeMapper (at most three) absorbs the light on its way
   * to this one, so a volume in another's shadow is darker by exactly that
   * other volume's transmittance, and the light maps span them all
   * (Documentation/rendering-model.md, "Several volumes"). Off: the medium is
   * lit as if it were alone. Read by the GPU mapper and both CPU references.
   */
  vtkSetMacro(SceneShadows, bool);
  vtkGetMacro(SceneShadows, bool);
  vtkBooleanMacro(SceneShadows, bool);
  ///@}

  ///@{
  /**
   * Whether volumes whose boxes overlap are drawn as one medium (On, the
   * default): where the world boxes of several volumes lit through each
   * other (SceneShadows on for each) overlap, the first of them in the
   * renderer's order casts the camera rays through all of them, summing
   * their extinctions and mixing their colours and emission by extinction,
   * and the others draw nothing of their own; the picture is then exact
   * where they interpenetrate, which drawing each volume as a layer is not
   * (Documentation/rendering-model.md, "Several volumes"). Only volumes
   * with this switch on, the same lighting settings (scattering model,
   * anisotropy, light scale, ambient, octaves, emission) and no missing data,
   * clipping, cropping, detail, coloured extinction, emission array,
   * gradient opacity or 2-D transfer function are drawn together; the
   * others are drawn as layers. Off: this volume is
   * always drawn by its own mapper. Read by the GPU mapper and the CPU
   * reference.
   */
  vtkSetMacro(SceneCompositing, bool);
  vtkGetMacro(SceneCompositing, bool);
  vtkBooleanMacro(SceneCompositing, bool);
  ///@}

  /**
   * Copies vtkVolumeProperty's settings (CopyVolumeProperty()) and, when
   * `p` is a vtkParticipatingMediumProperty, these (the emission colour and
   * the detail noise shared). Hides vtkVolumeProperty::DeepCopy(), which is
   * not virtual: call it on this class.
   */
  void DeepCopy(vtkVolumeProperty* p);

  /**
   * vtkVolumeProperty::DeepCopy() of `from` into `to` (either class: the
   * vtkVolumeProperty part), and what VTK 9.1's leaves out: the
   * transfer-function mode and each component's 2-D transfer function, the
   * slice function (shared) and the label maps' colour, opacity and
   * gradient opacity functions (copied, as VTK copies the 1-D functions).
   * What `to` has and `from` lacks stays (a 2-D function, a label's
   * functions: VTK 9.1 cannot remove them); into a new property the copy is
   * exact. A plain copy of a medium's settings is VTK's picture of them
   * (tyndall-render's --vtk-property).
   */
  static void CopyVolumeProperty(vtkVolumeProperty* from, vtkVolumeProperty* to);

  /**
   * A plain vtkVolumeProperty of this medium's settings (CopyVolumeProperty()
   * into a new one: VTK's meaning of its transfer functions and shading),
   * made anew only when this property was modified since the last call
   * (GetMTime(), its functions' times included), else the same object: a
   * mapper given a new property rebuilds its maps. What tyndall-render's
   * --vtk-property and ParaView's VTK Property draw. Owned by this property
   * (changing the copy changes nothing of it: the next change of this
   * property replaces the copy).
   */
  vtkVolumeProperty* GetPlainCopy();

  /**
   * Includes the emission colour's and the detail noise's modification times.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkParticipatingMediumProperty();
  ~vtkParticipatingMediumProperty() override;

  int ScatteringModel = SINGLE_SCATTERING;
  double DensityScale = 1.0;
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 2, 0)
  double ScatteringAnisotropy = 0.0;
#endif
  double LightScale;
  double AmbientIntensity = 0.0;
  double ExtinctionColor[3] = { 1.0, 1.0, 1.0 };
  int ScatteringOctaves = 2;
  double OctaveScattering = 1.3;
  double OctaveExtinction = 0.45;
  double OctaveAnisotropy = 0.0;
  double OctaveBuildUp = 6.0;
  double EmissionScale = 0.0;
  vtkColorTransferFunction* EmissionColor = nullptr;
  char* EmissionArrayName = nullptr;
  bool Blackbody = false;
  double TemperatureScale = 1.0;
  bool SceneShadows = true;
  bool SceneCompositing = true;
  vtkCosineNoise* DetailNoise = nullptr;
  double DetailFilterWidth = 0.5;

private:
  vtkSmartPointer<vtkVolumeProperty> PlainCopy; // GetPlainCopy()'s, made at PlainCopyTime
  vtkMTimeType PlainCopyTime = 0;

  vtkParticipatingMediumProperty(const vtkParticipatingMediumProperty&) = delete;
  void operator=(const vtkParticipatingMediumProperty&) = delete;
};

#endif
