/**
 * @class   vtkTyndallMediumParameters
 * @brief   a medium's lighting and extinction settings, read once from its property
 *
 * What every renderer needs of a volume's vtkParticipatingMediumProperty
 * (or plain vtkVolumeProperty) beyond its transfer functions, in the convention they use, read once
 * by Read() (each medium holds one: vtkTyndallMedium::GetParameters()) and never copied again: the
 * GPU passes set their uniforms from it, the CPU integrators read it in place.
 *
 * - DensityScale holds the property's DensityScale times its largest
 *   ExtinctionColor component, and ExtinctionColor the components relative
 *   to it (the densest channel exactly 1): the extinction a medium reports
 *   is the densest channel's, and channel k's is ExtinctionColor[k] times it.
 * - ScatteringOctaves is 1 in the emission-absorption model.
 * - HasEmission: single scattering with an emission colour (or an emission
 *   array) and a positive EmissionScale.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallMediumParameters_h
#define vtkTyndallMediumParameters_h

#include "TyndallMediumModule.h" // For export macro

class vtkObject;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallMediumParameters
{
public:
  /// vtkParticipatingMediumProperty::ScatteringModel (0 emission-absorption, 1 single scattering).
  int ScatteringModel = 1;
  double DensityScale = 1.0;
  double ExtinctionColor[3] = { 1.0, 1.0, 1.0 };
  double ScatteringAnisotropy = 0.0;
  double LightScale = 1.0;
  double AmbientIntensity = 0.0;
  /// Multiple-scattering octaves: their count (1: single scattering alone) and factors a, b, c, k
  /// (vtkParticipatingMediumProperty: OctaveScattering, -Extinction, -Anisotropy, -BuildUp).
  int ScatteringOctaves = 1;
  double OctaveFactors[4] = { 0.0, 0.0, 0.0, 0.0 };
  double EmissionScale = 0.0;
  bool HasEmission = false;

  /**
   * Reads `property`: a vtkParticipatingMediumProperty's settings; for a
   * plain vtkVolumeProperty (or null) vtkParticipatingMediumProperty's
   * defaults, except that a plain property with Shade off (component 0) is
   * emission-absorption, VTK's unlit picture (Documentation/rendering-model.md,
   * "What is read from the scene"); `emits` says whether the
   * medium has an emission source (an emission colour function or an
   * emission array), which HasEmission needs. False, with an error through
   * `reporter` naming the setting, when a number is not finite (VTK's clamp
   * macros let NaN through): nothing of the medium can then be drawn.
   */
  bool Read(vtkVolumeProperty* property, bool emits, vtkObject* reporter);

  bool GetSingleScattering() const { return this->ScatteringModel == 1; }

  /// Whether the channels' extinctions differ (the renderers then track three transmittances).
  bool GetChromatic() const
  {
    return this->ExtinctionColor[0] != 1.0 || this->ExtinctionColor[1] != 1.0 ||
      this->ExtinctionColor[2] != 1.0;
  }

  /**
   * The smallest positive component of ExtinctionColor (1 for a grey
   * medium): the faintest channel's transmittance is the densest one's
   * raised to it.
   */
  double GetFaintestChannel() const;

  ///@{
  /**
   * How faint a light transmittance can still be seen, for a march that
   * stops there (the CPU reference) or maps that resolve it (the adaptive
   * maps), given the transmittance `threshold` below which a sample counts
   * as dark: the last multiple-scattering octave sees w T^(b^(N-1)), w =
   * max(1, a)^(N-1) its largest weight relative to single scattering (the
   * albedo is at most 1), and the faintest channel of a coloured extinction
   * T^e (e: GetFaintestChannel(); not where each channel has maps of its
   * own: `channelMaps`), so the light must be followed down to
   * (threshold / w)^(1 / (b^(N-1) e)).
   *
   * LightTransmittanceLimit() is that transmittance (0 when b = 0: the
   * octave sees only whether T > 0); LightDepthLimit() the optical depth
   * -ln of it for the faintest channel, infinite when b = 0 or the
   * threshold is 0.
   */
  double LightTransmittanceLimit(double threshold, bool channelMaps) const;
  double LightDepthLimit(double threshold) const;
  ///@}

  /**
   * Whether two media are lit alike, so that one camera ray can integrate
   * them as one medium: the same scattering model and, in single
   * scattering, the same emission (on or off, and its scale when on),
   * anisotropy, light scale, ambient intensity and octaves (their factors
   * when there are several).
   */
  bool SameLighting(const vtkTyndallMediumParameters& other) const;

private:
  // The octaves' exponent b^(N-1) and weight max(1, a)^(N-1) (1 and 1 for one octave).
  double OctaveExponent() const;
  double OctaveWeight() const;
};

#endif
