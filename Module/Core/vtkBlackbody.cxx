#include "vtkBlackbody.h"

#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkBlackbody);

namespace
{
// A piecewise Gaussian: standard deviation `below` left of `mean`, `above` right of it.
double Lobe(double x, double mean, double below, double above)
{
  const double t = (x - mean) / (x < mean ? below : above);
  return std::exp(-0.5 * t * t);
}
}

//------------------------------------------------------------------------------
double vtkBlackbody::SpectralRadiance(double lambda, double T)
{
  if (!(T > 0.0) || !(lambda > 0.0))
  {
    return 0.0;
  }
  constexpr double h = 6.62607015e-34; // J s
  constexpr double c = 2.99792458e8;   // m / s
  constexpr double k = 1.380649e-23;   // J / K
  const double exponent = h * c / (lambda * k * T);
  if (exponent > 700.0)
  {
    return 0.0; // underflows
  }
  return 2.0 * h * c * c / std::pow(lambda, 5.0) / std::expm1(exponent);
}

//------------------------------------------------------------------------------
void vtkBlackbody::ColorMatching(double nm, double xyz[3])
{
  xyz[0] = 1.056 * Lobe(nm, 599.8, 37.9, 31.0) + 0.362 * Lobe(nm, 442.0, 16.0, 26.7) -
    0.065 * Lobe(nm, 501.1, 20.4, 26.2);
  xyz[1] = 0.821 * Lobe(nm, 568.8, 46.9, 40.5) + 0.286 * Lobe(nm, 530.9, 16.3, 31.1);
  xyz[2] = 1.217 * Lobe(nm, 437.0, 11.8, 36.0) + 0.681 * Lobe(nm, 459.0, 26.0, 13.8);
}

//------------------------------------------------------------------------------
void vtkBlackbody::XYZ(double T, double xyz[3])
{
  xyz[0] = xyz[1] = xyz[2] = 0.0;
  if (!(T > 0.0))
  {
    return;
  }
  for (int nm = 360; nm <= 830; ++nm)
  {
    const double weight = (nm == 360 || nm == 830) ? 0.5e-9 : 1.0e-9; // trapezoids of 1 nm
    const double b = SpectralRadiance(nm * 1.0e-9, T) * weight;
    double bar[3];
    ColorMatching(nm, bar);
    for (int c = 0; c < 3; ++c)
    {
      xyz[c] += b * bar[c];
    }
  }
}

//------------------------------------------------------------------------------
void vtkBlackbody::LinearSRGB(double T, double normalization, double rgb[3])
{
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  double reference[3];
  XYZ(normalization, reference);
  if (!(reference[1] > 0.0))
  {
    return;
  }
  double xyz[3];
  XYZ(T, xyz);
  const double m[3][3] = { { 3.2406, -1.5372, -0.4986 }, { -0.9689, 1.8758, 0.0415 },
    { 0.0557, -0.2040, 1.0570 } };
  for (int r = 0; r < 3; ++r)
  {
    const double v = (m[r][0] * xyz[0] + m[r][1] * xyz[1] + m[r][2] * xyz[2]) / reference[1];
    rgb[r] = v > 0.0 ? v : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkBlackbody::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
