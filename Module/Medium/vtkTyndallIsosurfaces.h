/**
 * @class   vtkTyndallIsosurfaces
 * @brief   VTK's isosurface blend mode: the property's iso values as surfaces, lit and shadowed
 *
 * A volume whose mapper's blend mode is VTK's ISOSURFACE_BLEND shows the
 * surfaces where its scalar crosses the property's iso values
 * (vtkVolumeProperty::GetIsoSurfaceValues()), as VTK 9.1's GPU mapper draws
 * them, and, which VTK does not do, each surface casts a shadow (on the
 * others and on opaque geometry in the volume's shadow; not on other
 * volumes, whose guest it is not). Read() takes the mode
 * and the values; both renderers then draw them with the same rules (the
 * GPU: tyndallIsoCrossings() and tyndallIsoExtinction() in
 * vtkTransmittanceCommonFS.glsl; the CPU: vtkTyndallGridMedium through
 * Composite() and OpticalDepth(), this class's twins of the shader's):
 *
 * - a ray (the camera's or a light's) is cut into steps; the scalar is
 *   taken at each step's two ends (kept by the clipping planes and
 *   cropping, inside the volume's box, not missing: else the step crosses
 *   nothing); the step crosses iso value s when exactly one end lies below
 *   s (each crossing of a ray counts once, in one step);
 * - the camera: each surface crossed is drawn with the colour function's
 *   c(s) and the opacity function's a(s) at its value (not corrected for
 *   the step, as VTK reads them), shaded as a plain property's samples
 *   (vtkTyndallShading, with Shade on) where the first surface of the step
 *   lies (the scalar taken as linear over the step: the light is then
 *   looked up from the surface, not from wherever the step ended) and
 *   composited front to back; the surfaces of one step are composited in
 *   the order the ray crosses them (Composite());
 * - the light: each surface crossed transmits 1 - a(s), an optical depth
 *   -ln(1 - a(s)) over its step (OpticalDepth(); a(s) at most
 *   MaximumOpacity): a surface of opacity 1 shadows what lies behind it
 *   entirely, and a translucent one in part, whatever angle the light
 *   meets it at (as the camera sees it);
 * - the values are sorted; at most MaximumCount; a non-finite value is an
 *   error (nothing is drawn).
 *
 * What differs from VTK (Documentation/mapper.md): VTK draws at most one
 * surface per step (a second crossed in the same step is drawn one step
 * later), and shades it at the step's end (here at the surface, less than
 * a step before).
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallIsosurfaces_h
#define vtkTyndallIsosurfaces_h

#include "TyndallMediumModule.h" // For export macro

#include <string> // For the error
#include <vector> // For the values

class vtkTyndallTransferTable;
class vtkVolumeMapper;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallIsosurfaces
{
public:
  /// The most iso values drawn (the shaders' TYNDALL_MAX_ISOSURFACES).
  static constexpr int MaximumCount = 16;
  /// The largest opacity a surface blocks the light with (its optical depth is finite).
  static constexpr double MaximumOpacity = 0.999999;

  /**
   * Reads the blend mode of `mapper` (enabled for ISOSURFACE_BLEND) and the
   * iso values of `property` (component 0), sorted. False, with `error`
   * set, for a non-finite value or more than MaximumCount (then disabled).
   * Enabled with no value draws nothing.
   */
  bool Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property, std::string& error);

  bool Enabled() const { return this->On; }
  /// The iso values, ascending.
  const std::vector<double>& GetValues() const { return this->Values; }

  /**
   * The surfaces a step from scalar v0 to v1 crosses, composited front to
   * back: the premultiplied colour rgb and the opacity alpha (0 and false
   * when it crosses none of opacity above 0), and where the first of them
   * with an opacity above 0 lies in the step, `first` = (s - v0) / (v1 -
   * v0) (the scalar taken as linear over the step), 0..1.
   */
  bool Composite(const vtkTyndallTransferTable& table, double v0, double v1, double rgb[3],
    double& alpha, double& first) const;

  /// The optical depth a light ray's step from scalar v0 to v1 meets (see the class description).
  double OpticalDepth(const vtkTyndallTransferTable& table, double v0, double v1) const;

private:
  bool On = false;
  std::vector<double> Values;
};

#endif
