/**
 * @class   vtkBlackbody
 * @brief   the colour of a black body at a temperature: Planck's law integrated against the CIE
 * 1931 colour matching functions, in linear sRGB
 *
 * vtkBlackbody gives the emission colour of fire and explosions from a
 * temperature in Kelvin (vtkParticipatingMediumProperty's blackbody
 * emission; Documentation/rendering-model.md, "Fire: emission from a
 * temperature array"):
 *
 * - SpectralRadiance(): Planck's law, B(lambda, T) = 2 h c^2 / lambda^5 /
 *   (exp(h c / (lambda k T)) - 1), W / (m^2 sr m);
 * - ColorMatching(): the CIE 1931 2-degree standard observer's x, y, z bar,
 *   by the multi-lobe Gaussian fit of Wyman, Sloan and Shirley ("Simple
 *   Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT
 *   2013; within a few percent of the tabulated functions);
 * - XYZ(): the integral of B against them over 360-830 nm (1 nm trapezoids),
 *   W / (m^2 sr) before the luminous efficacy;
 * - LinearSRGB(): XYZ -> linear sRGB (IEC 61966-2-1, D65) of that, negative
 *   components (outside the sRGB gamut: the deep red of cool bodies lacks
 *   blue) clamped to 0, divided by the luminance Y of a black body at the
 *   temperature `normalization`, so that a body at that temperature has
 *   luminance 1 and the others their physical luminance relative to it
 *   (a body at 1000 K has about 1/2900 of the luminance of one at 1500 K).
 *
 * Accuracy (TestBlackbody): chromaticity within 0.0034 of the CIE 1931
 * Planckian locus from 2000 K to 10000 K, 0.0062 at 1500 K (the fit's red
 * tail, which dominates cool bodies).
 *
 * Temperatures at or below 0 K, or NaN, give black.
 */

#ifndef vtkBlackbody_h
#define vtkBlackbody_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkObject.h"

class TYNDALLCORE_EXPORT vtkBlackbody : public vtkObject
{
public:
  static vtkBlackbody* New();
  vtkTypeMacro(vtkBlackbody, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Planck's spectral radiance at the wavelength `lambda` (m) and temperature T (K).
  static double SpectralRadiance(double lambda, double T);

  /// The CIE 1931 colour matching functions at `nanometres` (the fit above).
  static void ColorMatching(double nanometres, double xyz[3]);

  /// CIE XYZ of a black body at T (K), Planck's law against ColorMatching().
  static void XYZ(double T, double xyz[3]);

  /**
   * Linear sRGB of a black body at T, normalised to luminance 1 at the
   * temperature `normalization` (K, > 0; see the class description).
   */
  static void LinearSRGB(double T, double normalization, double rgb[3]);

protected:
  vtkBlackbody() = default;
  ~vtkBlackbody() override = default;

private:
  vtkBlackbody(const vtkBlackbody&) = delete;
  void operator=(const vtkBlackbody&) = delete;
};

#endif
