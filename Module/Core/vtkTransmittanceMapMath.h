/**
 * @class   vtkTransmittanceMapMath
 * @brief   CPU math of Tyndall's transmittance maps (TFM, ETM, adaptive)
 *
 * vtkTransmittanceMapMath is the reference implementation, on one light ray,
 * of the projection and reconstruction formulas of
 * Documentation/rendering-model.md. The GPU shaders of the mapper mirror it
 * and the tests check it against exact math. Like vtkMath, its useful API is
 * static; an instance has no state.
 *
 * A light ray is the segment [k_in, k_out] of world length D, parametrised
 * by s in [0, 1]. Here its extinction is a piecewise-linear profile:
 * profile[i] is \f$\sigma_t\f$ (per world unit) at \f$s_i = i/(P-1)\f$,
 * linearly interpolated in between.
 *
 * <b>Projection by ray marching.</b> A range [s_min, s_max] of length
 * \f$D' = D(s_{max}-s_{min})\f$ is marched with N samples at the midpoints
 * \f$u_n = (n+\frac12)/N\f$, \f$\Delta u = 1/N\f$, at
 * \f$s = s_{min} + u_n (s_{max}-s_{min})\f$, where the profile gives
 * \f$\sigma_n\f$. The optical depth at a sample's midpoint and the
 * transmittance there are
 * \f[
 *   \tau_n = \sum_{m<n} \sigma_m D' \Delta u + \sigma_n D' \Delta u / 2,
 *   \qquad T_n = e^{-\tau_n}.
 * \f]
 * With M coefficients (1 to 16), j = 0 .. M-1:
 *
 * - TFM (Fourier cosine series of the transmittance, Delalandre et al.):
 *   \f$a_j = 2\sum_n T_n \cos(j\pi u_n)\,\Delta u\f$ and
 *   \f$T(u) = \mathrm{clamp}_{[0,1]}\left(a_0/2 + \sum_{j\ge1} a_j\cos(j\pi u)\right)\f$.
 * - ETM (DCT of the extinction, integrated inside the exponential, Gautron
 *   et al.): \f$c_j = 2\sum_n D'\sigma_n \cos(j\pi u_n)\,\Delta u\f$,
 *   \f$\tau(u) = c_0 u/2 + \sum_{j\ge1} c_j \sin(j\pi u)/(j\pi)\f$ and
 *   \f$T(u) = e^{-\max(0,\tau(u))}\f$.
 *
 * The plain methods march [0, 1] (s_min = 0, s_max = 1, u = s).
 *
 * <b>Adaptive methods (dual ray marching, Delalandre et al.'s Algorithm 2).</b>
 * A first march covers [0, 1] with N samples. s_min is the start n0/N of
 * the first sample with \f$\sigma_n > 0\f$. If \f$T_n\f$ falls below the
 * adaptive threshold at sample n the ray is dense: s_max = n/N, the start
 * of that sample, and \f$T_{beyond}\f$ is the transmittance the first march
 * measured there, \f$e^{-\sum_{m<n}\sigma_m D/N}\f$. Otherwise s_max = 1 and
 * \f$T_{beyond}\f$ is the transmittance at the end of the segment. A ray
 * without extinction has s_min = 0, s_max = 1, \f$T_{beyond}\f$ = 1. The
 * second march projects [s_min, s_max] as above. Reconstruction gives 1 for
 * s <= s_min, \f$T_{beyond}\f$ for s >= s_max and the series at
 * \f$u = (s - s_{min})/(s_{max}-s_{min})\f$ in between.
 *
 * If the threshold is crossed within the first sample with extinction
 * (n = n0, an extremely dense sample) the rule would give the empty range
 * s_max = s_min, and T = 1 all along the ray; the range then covers that
 * sample, s_max = min(1, s_min + 1/N) = (n0+1)/N, and \f$T_{beyond}\f$ is
 * the transmittance the first march measured at its end.
 *
 * All functions are thread safe, allocate nothing and never return NaN:
 * invalid arguments give false (Project(), which then writes nothing) or a
 * documented defined value. From Python, profile and coefficients are
 * sequences of exactly profileSize and coefficientCount values (other
 * lengths raise a TypeError); coefficients and bounds are lists that
 * Project() fills in place.
 *
 * @sa vtkTransmittanceVolumeMapper vtkCosineNoise
 */

#ifndef vtkTransmittanceMapMath_h
#define vtkTransmittanceMapMath_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkObject.h"

#include <functional> // For std::function

class TYNDALLCORE_EXPORT vtkTransmittanceMapMath : public vtkObject
{
public:
  static vtkTransmittanceMapMath* New();
  vtkTypeMacro(vtkTransmittanceMapMath, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How light transmittance is computed; shared with the GPU mapper. NONE
   * is unshadowed (T = 1); BRUTE_FORCE marches every shadow ray in the
   * shader; the others are maps (the "map methods").
   */
  enum TransmittanceMethods
  {
    NONE = 0,
    BRUTE_FORCE = 1,
    TFM = 2,
    ADAPTIVE_TFM = 3,
    ETM = 4,
    ADAPTIVE_ETM = 5
  };

  /**
   * Name of a method: "None", "BruteForce", "TFM", "AdaptiveTFM", "ETM",
   * "AdaptiveETM"; "Unknown" for other values.
   */
  static const char* GetMethodName(int method);

  /**
   * The limits and layout of a map, one definition for the CPU math, the
   * mapper and (injected as #defines) its shaders: at most
   * MAXIMUM_NUMBER_OF_COEFFICIENTS coefficients per texel, stored
   * COEFFICIENTS_PER_LAYER to an RGBA layer.
   */
  enum MapLimits
  {
    MAXIMUM_NUMBER_OF_COEFFICIENTS = 16,
    COEFFICIENTS_PER_LAYER = 4
  };

  /**
   * Largest number of coefficients a map stores per texel.
   */
  static int GetMaximumNumberOfCoefficients() { return MAXIMUM_NUMBER_OF_COEFFICIENTS; }

  ///@{
  /**
   * Whether a method builds maps (TFM, ADAPTIVE_TFM, ETM, ADAPTIVE_ETM), and
   * whether it is one of the adaptive ones.
   */
  static bool IsMapMethod(int method);
  static bool IsAdaptiveMethod(int method);
  ///@}

  ///@{
  /**
   * The layout of one light's map: ceil(coefficientCount / 4) RGBA layers of
   * coefficients (four per layer, in order), plus, for the adaptive methods,
   * one layer (s_min, s_max, T_beyond, 0) at GetBoundsLayer(), the last.
   * GetNumberOfMapLayers() is 0 and GetBoundsLayer() -1 when there is none
   * (not a map method, count outside [1, 16]).
   */
  static int GetNumberOfMapLayers(int method, int coefficientCount);
  static int GetBoundsLayer(int method, int coefficientCount);
  ///@}

  /**
   * Projects one light ray. profile holds profileSize (>= 2) finite,
   * non-negative extinction values (per world unit) at s_i = i/(profileSize-1)
   * of a segment of world length `length` (> 0). The march takes
   * sampleCount (>= 1) samples; coefficientCount (1 to 16) coefficients are
   * written to coefficients, and bounds receives (s_min, s_max, T_beyond):
   * for TFM and ETM (0, 1, the transmittance at the end of the segment as
   * the march sees it). adaptiveThreshold, in [0, 1), is used only by the
   * adaptive methods. Returns false, writing nothing, for invalid arguments
   * or a method that is not a map method.
   */
  static bool Project(int method, const double* profile, int profileSize, double length,
    int sampleCount, int coefficientCount, double adaptiveThreshold, double* coefficients,
    double bounds[3]) VTK_SIZEHINT(profile, profileSize)
    VTK_SIZEHINT(coefficients, coefficientCount);

#ifndef __VTK_WRAP__
  /**
   * Project() for any extinction along the segment: `extinction(s)` is
   * sigma_t (per world unit, finite, >= 0) at s in [0, 1] of a segment of
   * world length `length`. The march samples it exactly where the shaders
   * do, so this is the CPU twin of a map texel given the medium along the
   * texel's ray. Not wrapped.
   */
  static bool Project(int method, const std::function<double(double)>& extinction, double length,
    int sampleCount, int coefficientCount, double adaptiveThreshold, double* coefficients,
    double bounds[3]);
#endif

  /**
   * Transmittance at s from the coefficients and bounds that Project()
   * wrote (the map texel). TFM and ETM use u = s clamped to [0, 1] and
   * ignore bounds (it may be null). The adaptive methods give 1 for
   * s <= s_min, T_beyond for s >= s_max. NONE gives 1. Invalid input (a
   * method that is not a map method other than NONE, a null pointer, a
   * count outside [1, 16], NaN s or bounds that are not
   * 0 <= s_min <= s_max <= 1, T_beyond in [0, 1]) gives 1. Mirrors the
   * shader: no allocation, O(coefficientCount).
   */
  static double Reconstruct(int method, const double* coefficients, int coefficientCount,
    const double bounds[3], double s) VTK_SIZEHINT(coefficients, coefficientCount);

  /**
   * Exact transmittance exp(-D * integral_0^s sigma_t) of the
   * piecewise-linear profile (the trapezoid rule per profile interval, exact
   * for a linear function), s clamped to [0, 1]. 1 for invalid arguments
   * (those that Project() refuses, or NaN s).
   */
  static double ExactTransmittance(const double* profile, int profileSize, double length, double s)
    VTK_SIZEHINT(profile, profileSize);

  /**
   * The Henyey-Greenstein phase function normalised over the sphere,
   * \f$p(\mu) = (1-g^2) / (4\pi (1 + g^2 - 2g\mu)^{3/2})\f$, so that
   * \f$2\pi\int_{-1}^{1} p\,d\mu = 1\f$. g is clamped to [-0.99, 0.99]
   * and mu (the cosine between the direction light travels and the
   * direction towards the camera) to [-1, 1]; NaN counts as 0.
   */
  static double HenyeyGreenstein(double g, double mu);

  /**
   * The light a sample scatters towards the camera per unit of light
   * irradiance and of its scattering albedo, with multiple scattering
   * approximated by octaves (Wrenninge, "Art-Directable Multiple Volumetric
   * Scattering", 2015; Documentation/rendering-model.md, "Multiple
   * scattering") with a build-up term: for each channel j,
   * \f[ w_j = p(g, \mu)\, T + (1 - T^{k}) \sum_{i=1}^{n-1} (a\,\rho_j)^i\,
   *     p(c^i g, \mu)\, T^{b^i}, \f]
   * T the light transmittance, rho the albedo; factors = {a, b, c, k}: a
   * the scattering, b the extinction and c the anisotropy factor of an
   * octave, k the build-up (multiply scattered light grows over the first
   * optical depths 1/k from the lit side, none where T = 1; k = 0 turns
   * the term off: Wrenninge's octaves); p the Henyey-Greenstein phase
   * function (HenyeyGreenstein()). One octave (n = 1) is single scattering,
   * p(g, mu) T. T <= 0 (or NaN) gives 0; n is clamped to [1, 8], a to
   * [0, 4], b and c to [0, 1], k to [0, 64] (NaN factors count as 0), T to
   * at most 1. The CPU twin of the ray-cast shader's tyndallOctaves().
   */
  static void OctaveScattering(int n, const double factors[4], double g, double mu, double T,
    const double albedo[3], double weight[3]);

  /**
   * Extinction coefficient that gives VTK's opacity alpha over a slab of
   * thickness unitDistance (ScalarOpacityUnitDistance):
   * \f$\sigma_t = \mathrm{densityScale}\cdot(-\ln(1 - \alpha)) / u\f$ with
   * alpha clamped to [0, 1 - 1e-6] (NaN counts as 0). Then
   * \f$1 - e^{-\sigma_t d} = 1 - (1-\alpha)^{d/u}\f$ for densityScale 1,
   * VTK's opacity correction. Returns 0 for unitDistance <= 0 and for a
   * negative or non-finite densityScale or unitDistance.
   */
  static double ExtinctionFromOpacity(double alpha, double unitDistance, double densityScale);

protected:
  vtkTransmittanceMapMath() = default;
  ~vtkTransmittanceMapMath() override = default;

private:
  vtkTransmittanceMapMath(const vtkTransmittanceMapMath&) = delete;
  void operator=(const vtkTransmittanceMapMath&) = delete;
};

#endif
