/**
 * @class   vtkTyndallToneMapping
 * @brief   the display transform of Tyndall's pictures: exposure, a tone curve and sRGB encoding
 *
 * Tyndall renders linear radiance. A bright, multiply scattering cloud has
 * radiance well above 1, which an 8-bit picture clips to white. These
 * functions map linear radiance to display values; they are the CPU twin of
 * vtkTransmittanceOutputFS.glsl (vtkTransmittanceVolumeMapper's Exposure,
 * ToneCurve and EncodeSRGB), and the tests compare the two.
 *
 * Map() applies, per channel, to a linear value x (premultiplied radiance):
 *
 * 1. exposure: x * 2^exposure (`exposure` in stops);
 * 2. the tone curve:
 *    - LINEAR: x itself, unclamped (a float frame buffer keeps values above
 *      1; an 8-bit one clamps them);
 *    - REINHARD: x / (1 + x) (Reinhard et al. 2002, the global operator
 *      without a white point);
 *    - ACES: Narkowicz's fit of the ACES reference rendering and output
 *      transforms ("ACES Filmic Tone Mapping Curve", 2016), clamped to
 *      [0, 1]: x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14). A film-like
 *      toe and shoulder: 0.18 maps to 0.27, 1 to 0.80, 7.2 and above to 1.
 * 3. with `srgb`, the sRGB encoding of IEC 61966-2-1 of the value clamped to
 *    [0, 1]: 12.92 x below 0.0031308, else 1.055 x^(1/2.4) - 0.055.
 *
 * Exposure 0, LINEAR and no sRGB is the identity: VTK's and Tyndall's
 * pictures unchanged (the default; the baseline tests keep it). NaN and
 * negative values give 0.
 *
 * Over a background: the mapper draws premultiplied light (radiance L,
 * opacity a) that the frame buffer blends over what it holds, B (display
 * values: the renderer's background). MapOver() gives the colour to draw so
 * that the pixel becomes D(L + (1 - a) D^-1(B)), D the transform above and
 * D^-1 its inverse (Unmap()): the transform of the light that shows B, seen
 * through the medium, plus the medium's own light. Where the medium is
 * absent (a = 0, L = 0) the pixel keeps B; over black it is D(L); the
 * medium's thin edges are not brightened by sRGB's steep start over a
 * bright background, and emission keeps its light.
 *
 * The curves act on each channel alone (as Narkowicz's fit is used in
 * games), so a saturated bright colour drifts towards white.
 */

#ifndef vtkTyndallToneMapping_h
#define vtkTyndallToneMapping_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkObject.h"

class TYNDALLCORE_EXPORT vtkTyndallToneMapping : public vtkObject
{
public:
  static vtkTyndallToneMapping* New();
  vtkTypeMacro(vtkTyndallToneMapping, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The tone curves (their numbers are the GLSL's and the mapper's).
  enum Curves
  {
    LINEAR = 0,
    REINHARD = 1,
    ACES = 2
  };

  /// The exposure's range in stops: [-MaximumExposure, MaximumExposure].
  static constexpr double MaximumExposure = 20.0;

  /// The tone curve `curve` at the exposed linear value x (step 2 above).
  static double Curve(int curve, double x);

  /// The sRGB encoding of a linear value (clamped to [0, 1] first).
  static double EncodeSRGB(double linear);

  /// The inverse of EncodeSRGB() on [0, 1].
  static double DecodeSRGB(double encoded);

  /// The whole transform of one channel's linear value (steps 1-3).
  static double Map(double linear, double exposure, int curve, bool srgb);

  /// Whether Map() is the identity: exposure 0, LINEAR and no sRGB.
  static bool IsIdentity(double exposure, int curve, bool srgb);

  /// Where the bounded curves are clamped: an exposed value above it is taken as it.
  static constexpr double Largest = 1.0e4;

  /**
   * The inverse of Curve() on its range: the exposed value whose curve is
   * y (LINEAR: y; REINHARD: y / (1 - y) with y at most Largest / (1 +
   * Largest); ACES: the root of a quadratic, y clamped to [0, 1], 1 giving
   * 3.5 + sqrt(14)).
   */
  static double InverseCurve(int curve, double y);

  /// The inverse of Map(): the linear value whose transform is `display`.
  static double Unmap(double display, double exposure, int curve, bool srgb);

  /**
   * The colour the mapper draws for the premultiplied colour `rgba` over
   * `background` (the description's MapOver(); `out`'s opacity is rgba's)
   * and, in `pixel` (may be null), the pixel that blending it over
   * `background` gives: Map(L + (1 - a) Unmap(B)).
   */
  static void MapOver(const double rgba[4], const double background[3], double exposure, int curve,
    bool srgb, double out[4], double pixel[3] = nullptr);

  /// "linear", "reinhard", "aces"; nullptr for another number.
  static const char* GetCurveName(int curve);

  /// The number of a curve's name (as GetCurveName() spells it); -1 for another.
  static int GetCurveFromName(const char* name);

protected:
  vtkTyndallToneMapping() = default;
  ~vtkTyndallToneMapping() override = default;

private:
  vtkTyndallToneMapping(const vtkTyndallToneMapping&) = delete;
  void operator=(const vtkTyndallToneMapping&) = delete;
};

#endif
