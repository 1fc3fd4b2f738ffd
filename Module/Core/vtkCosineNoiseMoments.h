/**
 * @class   vtkCosineNoiseMoments
 * @brief   the closed form of a cubic times one cosine wave, inline
 *
 * The innermost loop of every closed form of Tyndall's cosine-noise media
 * (vtkCosineNoise::PolynomialWaveIntegral(), and per wave and shape cell
 * the procedural medium's optical depth and distance sampling): with
 * \f$K_n(\theta) = \int_0^1 u^n e^{i\theta u} du\f$, Compute() gives
 * \f$\sum_{n=0}^{3} e_n K_n(\theta)\f$ for the cubic's coefficients
 * \f$e_n\f$ in \f$u \in [0, 1]\f$, given \f$\theta\f$, its cosine and sine
 * and \f$1/\theta\f$ (callers that integrate many cells of one ray divide
 * once per wave and once per cell instead of once per wave and cell).
 *
 * - \f$|\theta| < 0.5\f$: the Taylor series
 *   \f$K_n = \sum_m (i\theta)^m / (m!\,(n + m + 1))\f$ in Horner's form, no
 *   cancellation when a ray runs along a wave front. It stops at the first
 *   term below \f$2^{-56}\f$ of the sum: 16 terms at \f$|\theta| = 0.5\f$,
 *   5 at \f$10^{-3}\f$, 2 at \f$10^{-8}\f$ (the trigonometric arguments are not
 *   read).
 * - Otherwise the recurrence
 *   \f$K_0 = (e^{i\theta} - 1) / (i\theta)\f$,
 *   \f$K_n = (e^{i\theta} - n K_{n-1}) / (i\theta)\f$, whose error grows at
 *   most \f$3!/|\theta|^3 \le 48\f$ fold.
 * - A constant (\f$e_1 = e_2 = e_3 = 0\f$: a cell of equal shape samples,
 *   the bounding box of the paper's setting) needs \f$K_0\f$ alone.
 *
 * Header-only so that it inlines into those loops; not wrapped.
 *
 * @sa vtkCosineNoise vtkTyndallDetailMedium
 */

#ifndef vtkCosineNoiseMoments_h
#define vtkCosineNoiseMoments_h

#include <cmath> // For std::abs

class vtkCosineNoiseMoments
{
public:
  /// The Taylor series is used below this |theta|, the recurrence from it on.
  static constexpr double SeriesLimit = 0.5;

  /**
   * (re, im) = sum_n e_n K_n(theta). `inverseTheta` = 1 / theta, read only
   * where |theta| >= SeriesLimit; `cosTheta`, `sinTheta` likewise.
   */
  static void Compute(const double e[4], double theta, double inverseTheta, double cosTheta,
    double sinTheta, double& re, double& im)
  {
    const bool constant = e[1] == 0.0 && e[2] == 0.0 && e[3] == 0.0;
    const double magnitude = std::abs(theta);
    if (magnitude < SeriesLimit)
    {
      // acc = g_m + (i theta / (m + 1)) acc from the last term down,
      // g_m = sum_n e_n / (n + m + 1).
      static constexpr double inverse[21] = { 1.0, 1.0, 1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6,
        1.0 / 7, 1.0 / 8, 1.0 / 9, 1.0 / 10, 1.0 / 11, 1.0 / 12, 1.0 / 13, 1.0 / 14, 1.0 / 15,
        1.0 / 16, 1.0 / 17, 1.0 / 18, 1.0 / 19, 1.0 / 20 };
      const int last = LastTerm(magnitude);
      re = im = 0.0;
      for (int m = last; m >= 0; --m)
      {
        const double g = constant ? e[0] * inverse[m + 1]
                                  : e[0] * inverse[m + 1] + e[1] * inverse[m + 2] +
            e[2] * inverse[m + 3] + e[3] * inverse[m + 4];
        const double f = theta * inverse[m + 1];
        const double nextRe = g - f * im;
        im = f * re;
        re = nextRe;
      }
      return;
    }
    // Dividing by i theta maps (x, y) to (y, -x) / theta.
    double kRe = sinTheta * inverseTheta;
    double kIm = (1.0 - cosTheta) * inverseTheta;
    re = e[0] * kRe;
    im = e[0] * kIm;
    if (constant)
    {
      return;
    }
    for (int n = 1; n < 4; ++n)
    {
      const double xRe = cosTheta - n * kRe;
      const double xIm = sinTheta - n * kIm;
      kRe = xIm * inverseTheta;
      kIm = -xRe * inverseTheta;
      re += e[n] * kRe;
      im += e[n] * kIm;
    }
  }

  /**
   * The index m of the last Taylor term needed at |theta| = `magnitude`
   * (< SeriesLimit): the smallest M with |theta|^(M+1) / (M+1)! below
   * 2^-56 (about 1.4e-17), 15 at most.
   */
  static int LastTerm(double magnitude)
  {
    // Limit[M]: (2^-56 (M + 1)!)^(1 / (M + 1)), rounded down.
    static constexpr double limit[15] = { 0.0, 5.2e-9, 4.3e-6, 1.3e-4, 1.1e-3, 4.6e-3, 1.3e-2,
      2.9e-2, 5.3e-2, 9.3e-2, 0.143, 0.206, 0.282, 0.377, 0.481 };
    int m = 1;
    while (m < 15 && magnitude > limit[m])
    {
      ++m;
    }
    return m;
  }
};

#endif
