// vtkBlackbody against Planck's law and the CIE 1931 Planckian locus:
// - chromaticity (x, y) of black bodies from 2000 K to 10000 K against the
//   locus (CIE 1931 2-degree values of the literature, 4 decimals): within
//   0.005 (the target; measured 0.0034 at 2000 K, under 0.0014 from
//   3000 K); 1500 K within 0.01 (measured 0.0062: the fit's red tail);
// - Wien's displacement law: the spectral radiance peaks at b / T;
// - the Stefan-Boltzmann law: pi times the integral of B over wavelength is
//   sigma T^4 (1e-4 relative);
// - the sRGB normalisation: luminance 1 at the normalisation temperature,
//   about white (R = G = B within 8 %) at D65's 6504 K, red above blue when
//   cool, physical luminance ratios between temperatures; 0 K, NaN black.
#include "vtkBlackbody.h"
#include "vtkNew.h"

#include "TyndallTestCheck.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

int TestBlackbody(int, char*[])
{
  using tyndall_test::Check;
  vtkNew<vtkBlackbody> object;
  std::ostringstream print;
  object->Print(print);
  Check(print.str().find("vtkBlackbody") != std::string::npos, "PrintSelf");

  // The Planckian locus (CIE 1931 2 degrees).
  const double locus[][3] = { { 1500.0, 0.5857, 0.3931 }, { 2000.0, 0.5267, 0.4133 },
    { 2500.0, 0.4770, 0.4137 }, { 3000.0, 0.4369, 0.4041 }, { 4000.0, 0.3805, 0.3768 },
    { 5000.0, 0.3451, 0.3516 }, { 6500.0, 0.3135, 0.3237 }, { 10000.0, 0.2807, 0.2884 } };
  double worst = 0.0;
  for (const auto& p : locus)
  {
    double xyz[3];
    vtkBlackbody::XYZ(p[0], xyz);
    const double sum = xyz[0] + xyz[1] + xyz[2];
    const double dx = xyz[0] / sum - p[1], dy = xyz[1] / sum - p[2];
    const double error = std::sqrt(dx * dx + dy * dy);
    std::cout << p[0] << " K: x " << xyz[0] / sum << " y " << xyz[1] / sum << " (locus " << p[1]
              << ", " << p[2] << "), distance " << error << "\n";
    // The colour matching functions' fit is least accurate in the red tail,
    // which dominates below 2000 K (measured 0.0062 at 1500 K).
    worst = std::max(worst, p[0] >= 2000.0 ? error : 0.0);
    Check(error < 0.01, "chromaticity within 0.01 of the locus at " + std::to_string(p[0]) + " K");
  }
  Check(worst < 0.005, "chromaticity within 0.005 of the Planckian locus from 2000 to 10000 K");

  // Wien: the peak at 2.897771955e-3 / T.
  for (double T : { 1000.0, 3000.0, 6000.0 })
  {
    const double peak = 2.897771955e-3 / T;
    Check(
      vtkBlackbody::SpectralRadiance(peak, T) > vtkBlackbody::SpectralRadiance(peak * 1.01, T) &&
        vtkBlackbody::SpectralRadiance(peak, T) > vtkBlackbody::SpectralRadiance(peak * 0.99, T),
      "Wien's displacement law at " + std::to_string(T) + " K");
  }
  // Stefan-Boltzmann: pi integral B dlambda = sigma T^4 (log-spaced midpoints).
  {
    const double T = 2000.0;
    double integral = 0.0;
    const int n = 200000;
    const double a = std::log(1e-8), b = std::log(1e-3);
    for (int i = 0; i < n; ++i)
    {
      const double l0 = std::exp(a + (b - a) * i / n), l1 = std::exp(a + (b - a) * (i + 1) / n);
      integral += vtkBlackbody::SpectralRadiance(0.5 * (l0 + l1), T) * (l1 - l0);
    }
    const double sigma = 5.670374419e-8;
    Check(std::abs(3.14159265358979 * integral / (sigma * T * T * T * T) - 1.0) < 1e-4,
      "Stefan-Boltzmann: pi integral B = sigma T^4");
  }
  // sRGB: luminance 1 at the normalisation, white at 6504 K, warm when cool.
  double rgb[3];
  vtkBlackbody::LinearSRGB(6504.0, 6504.0, rgb);
  const double luminance = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
  std::cout << "6504 K: " << rgb[0] << " " << rgb[1] << " " << rgb[2] << ", luminance " << luminance
            << "\n";
  Check(std::abs(luminance - 1.0) < 0.01, "luminance 1 at the normalisation temperature");
  Check(std::abs(rgb[0] / rgb[1] - 1.0) < 0.08 && std::abs(rgb[2] / rgb[1] - 1.0) < 0.08,
    "about white at 6504 K");
  double warm[3], dim[3];
  vtkBlackbody::LinearSRGB(1500.0, 1500.0, warm);
  vtkBlackbody::LinearSRGB(1000.0, 1500.0, dim);
  Check(warm[0] > warm[1] && warm[1] > warm[2], "1500 K is orange: R > G > B");
  double y1000[3], y1500[3];
  vtkBlackbody::XYZ(1000.0, y1000);
  vtkBlackbody::XYZ(1500.0, y1500);
  const double ratio = y1000[1] / y1500[1];
  const double dimLuminance = 0.2126 * dim[0] + 0.7152 * dim[1] + 0.0722 * dim[2];
  std::cout << "luminance 1000 K / 1500 K: " << ratio << " (sRGB " << dimLuminance << ")\n";
  Check(ratio > 1e-4 && ratio < 1e-3 && std::abs(dimLuminance / ratio - 1.0) < 0.05,
    "1000 K is about 3000 times dimmer than 1500 K, in sRGB too");
  vtkBlackbody::LinearSRGB(0.0, 1500.0, rgb);
  Check(rgb[0] == 0.0 && rgb[1] == 0.0 && rgb[2] == 0.0, "0 K is black");
  vtkBlackbody::LinearSRGB(std::nan(""), 1500.0, rgb);
  Check(rgb[0] == 0.0, "NaN is black");
  vtkBlackbody::LinearSRGB(1500.0, 0.0, rgb);
  Check(rgb[0] == 0.0, "a normalisation at 0 K gives black, not infinity");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
