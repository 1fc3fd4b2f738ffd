// Numerical integration used as the independent oracle of Tyndall's closed
// forms (tests and benchmarks). Header only; not part of the library.
#ifndef TyndallTestQuadrature_h
#define TyndallTestQuadrature_h

#include <cmath>
#include <functional>

namespace tyndall_test
{
// Adaptive Gauss-Kronrod (7-15) quadrature of f over [a, b] to an absolute
// tolerance; recursion depth bounded.
inline double GaussKronrod15(
  const std::function<double(double)>& f, double a, double b, double& err)
{
  static const double xgk[8] = { 0.991455371120812639206854697526329,
    0.949107912342758524526189684047851, 0.864864423359769072789712788640926,
    0.741531185599394439863864773280788, 0.586087235467691130294144845693013,
    0.405845151377397166906606412076961, 0.207784955007898467600689403773245,
    0.000000000000000000000000000000000 };
  static const double wgk[8] = { 0.022935322010529224963732008058970,
    0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
    0.140653259715525918745189590510238, 0.169004726639267902826583426598550,
    0.190350578064785409913256402421014, 0.204432940075298892414161999234649,
    0.209482141084727828012999174891714 };
  static const double wg[4] = { 0.129484966168869693270611432679082,
    0.279705391489276667901467771423780, 0.381830050505118944950369775488975,
    0.417959183673469387755102040816327 };
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double kronrod = fc * wgk[7], gauss = fc * wg[3];
  for (int j = 0; j < 7; ++j)
  {
    const double f1 = f(c - h * xgk[j]), f2 = f(c + h * xgk[j]);
    kronrod += wgk[j] * (f1 + f2);
    if (j % 2 == 1)
    {
      gauss += wg[j / 2] * (f1 + f2);
    }
  }
  err = std::abs((kronrod - gauss) * h);
  return kronrod * h;
}

inline double AdaptiveIntegrate(
  const std::function<double(double)>& f, double a, double b, double tolerance, int depth = 0)
{
  double err = 0.0;
  const double whole = GaussKronrod15(f, a, b, err);
  if (err <= tolerance || depth > 40)
  {
    return whole;
  }
  const double m = 0.5 * (a + b);
  return AdaptiveIntegrate(f, a, m, 0.5 * tolerance, depth + 1) +
    AdaptiveIntegrate(f, m, b, 0.5 * tolerance, depth + 1);
}

// Ray marching: the midpoint rule with n equal steps.
inline double MidpointRule(const std::function<double(double)>& f, double a, double b, int n)
{
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    sum += f(a + (i + 0.5) * h);
  }
  return sum * h;
}
}

#endif
