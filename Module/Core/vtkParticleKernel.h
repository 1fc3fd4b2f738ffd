/**
 * @class   vtkParticleKernel
 * @brief   the extinction of one particle of a particle cloud, and its exact integrals along rays
 *
 * A particle of centre c, radius R > 0 and peak extinction rho >= 0 (per
 * world unit) is a smooth sphere:
 * \f[
 *   \sigma(x) = \rho \left(1 - \frac{|x - c|^2}{R^2}\right)^2 \quad (|x - c| < R),
 *   \qquad 0 \text{ outside,}
 * \f]
 * smooth (its gradient vanishes on the sphere) and of compact support, so a
 * particle touches only the rays and map texels its sphere covers, and
 * every integral below is a polynomial or an elementary function: exact,
 * with no marching (the Extinction Transmittance Maps paper's point: each
 * element of a medium adds its own extinction coefficients to the map).
 * Chosen over a Gaussian, whose integral along a ray is exact only over the
 * whole line and which never ends.
 *
 * Along a ray passing at the distance b < R from c, the chord has half
 * length \f$h = \sqrt{R^2 - b^2}\f$ and, v being the signed distance along
 * the ray from the chord's midpoint,
 * \f[
 *   \sigma = \frac{\rho}{R^4}(h^2 - v^2)^2, \qquad
 *   \int_{-h}^{v}\sigma = \frac{\rho}{R^4}\left(h^4 v - \frac{2}{3}h^2 v^3
 *   + \frac{v^5}{5} + \frac{8}{15}h^5\right), \qquad
 *   \int_{-h}^{h}\sigma = \frac{16}{15}\frac{\rho h^5}{R^4}.
 * \f]
 * Its total over space (its extinction "mass") is \f$32\pi\rho R^3/105\f$.
 *
 * Extinction map coefficients (vtkTransmittanceMapMath's ETM: \f$c_j =
 * 2\int_0^D \sigma(t)\cos(j\pi t/D)\,dt\f$ along a light ray of length D) of
 * one particle whose chord has its midpoint at the distance t_c along the ray:
 * \f[
 *   c_j = 2\cos(\omega t_c)\frac{\rho h^5}{R^4}\,g(\omega h), \quad
 *   \omega = \frac{j\pi}{D}, \quad
 *   g(x) = \int_{-1}^{1}(1-s^2)^2\cos(xs)\,ds
 *        = \frac{16\left((3 - x^2)\sin x - 3x\cos x\right)}{x^5},
 * \f]
 * exact when the chord lies within [0, D] (g by its series for |x| < 0.5,
 * where the closed form cancels). The coefficients of a cloud are the sums
 * of its particles': splatting, the map built without a march.
 *
 * Invalid arguments (NaN, a radius <= 0, a negative density, a null
 * pointer, a coefficient count outside [1, 16], a length <= 0) give 0 or
 * write nothing: never NaN. Like vtkMath, the API is static; an instance
 * has no state.
 *
 * @sa vtkTransmittanceMapMath
 */

#ifndef vtkParticleKernel_h
#define vtkParticleKernel_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

class TYNDALLCORE_EXPORT vtkParticleKernel : public vtkObject
{
public:
  static vtkParticleKernel* New();
  vtkTypeMacro(vtkParticleKernel, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The extinction at the distance r from the centre.
  static double Extinction(double r, double radius, double density);

  /**
   * The kernel at the squared ratio `s2` = |x - c|^2 / R^2 of the distance to
   * the radius: rho (1 - s2)^2 below 1, 0 from 1 on and for a NaN s2.
   * Extinction() checks its arguments and calls it; this checks nothing (a
   * NaN or negative density passes through): for a caller that has checked
   * the density and computes s2 itself. Inline, with no square root: the
   * CPU's sums over every particle near a sample (vtkTyndallParticles). Not
   * wrapped.
   */
  VTK_WRAPEXCLUDE static double ExtinctionOfSquaredRatio(double s2, double density)
  {
    const double q = 1.0 - s2;
    return s2 < 1.0 ? density * q * q : 0.0;
  }

  /// The extinction integrated over space: 32 pi rho R^3 / 105.
  static double Mass(double radius, double density);

  /// The optical depth of the whole chord at the distance b from the centre (0 for b >= R).
  static double ChordDepth(double b, double radius, double density);

  /**
   * The optical depth of the chord at the distance b from the centre, from
   * its entry to the signed distance v from its midpoint (clamped to the
   * chord).
   */
  static double PartialDepth(double b, double v, double radius, double density);

  /**
   * The optical depth of the segment t in [t0, t1] of the ray o + t d (d of
   * unit length, t0 <= t1) through the particle of centre `center`.
   */
  static double SegmentDepth(const double o[3], const double d[3], double t0, double t1,
    const double center[3], double radius, double density);

  /**
   * Adds the particle's extinction map coefficients c_0 .. c_{count-1}
   * (see the class description) to `coefficients`, for a light ray of
   * length `length` that passes at the distance b from the centre, the
   * chord's midpoint at the distance tc along the ray. Returns false,
   * adding nothing, for invalid arguments.
   */
  static bool AddExtinctionCoefficients(double b, double tc, double length, double radius,
    double density, int count, double* coefficients) VTK_SIZEHINT(coefficients, count);

  /// g(x) = integral over [-1, 1] of (1 - s^2)^2 cos(x s) ds (16/15 at 0).
  static double ProfileCosineIntegral(double x);

protected:
  vtkParticleKernel() = default;
  ~vtkParticleKernel() override = default;

private:
  vtkParticleKernel(const vtkParticleKernel&) = delete;
  void operator=(const vtkParticleKernel&) = delete;
};

#endif
