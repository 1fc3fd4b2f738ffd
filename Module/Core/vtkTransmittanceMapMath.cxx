#include "vtkTransmittanceMapMath.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittanceMapMath);

namespace
{
constexpr int kMaxCoefficients = vtkTransmittanceMapMath::MAXIMUM_NUMBER_OF_COEFFICIENTS;

bool IsTFM(int method)
{
  return method == vtkTransmittanceMapMath::TFM || method == vtkTransmittanceMapMath::ADAPTIVE_TFM;
}

// A usable extinction profile on a segment of the given length.
bool ValidProfile(const double* profile, int profileSize, double length)
{
  if (!profile || profileSize < 2 || !(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  for (int i = 0; i < profileSize; ++i)
  {
    if (!(profile[i] >= 0.0) || !std::isfinite(profile[i]))
    {
      return false;
    }
  }
  return true;
}

// Linear interpolation of the profile at s in [0, 1].
double SampleProfile(const double* profile, int profileSize, double s)
{
  const double x = std::min(std::max(s, 0.0), 1.0) * (profileSize - 1);
  const int i = std::min(static_cast<int>(x), profileSize - 2);
  const double f = x - i;
  return (1.0 - f) * profile[i] + f * profile[i + 1];
}

// The march of the specification over [sMin, sMax] with sampleCount
// midpoint samples, projected onto coefficientCount cosines: the TFM's a_j
// (of T_n) or the ETM's c_j (of D' sigma_n). Returns the optical depth of
// the whole range as the march sees it.
double MarchAndProject(bool tfm, const std::function<double(double)>& profile, double length,
  double sMin, double sMax, int sampleCount, int coefficientCount, double* coefficients)
{
  const double du = 1.0 / sampleCount;
  const double rangeLength = length * (sMax - sMin); // D'
  double sums[kMaxCoefficients] = {};
  double opticalDepth = 0.0; // sum_{m<n} sigma_m D' du
  for (int n = 0; n < sampleCount; ++n)
  {
    const double u = (n + 0.5) * du;
    const double extinction = profile(sMin + u * (sMax - sMin));
    const double stepDepth = extinction * rangeLength * du;
    const double value =
      tfm ? std::exp(-(opticalDepth + 0.5 * stepDepth)) : rangeLength * extinction;
    for (int j = 0; j < coefficientCount; ++j)
    {
      sums[j] += value * std::cos(j * vtkMath::Pi() * u);
    }
    opticalDepth += stepDepth;
  }
  for (int j = 0; j < coefficientCount; ++j)
  {
    coefficients[j] = 2.0 * sums[j] * du;
  }
  return opticalDepth;
}
}

//------------------------------------------------------------------------------
const char* vtkTransmittanceMapMath::GetMethodName(int method)
{
  switch (method)
  {
    case NONE:
      return "None";
    case BRUTE_FORCE:
      return "BruteForce";
    case TFM:
      return "TFM";
    case ADAPTIVE_TFM:
      return "AdaptiveTFM";
    case ETM:
      return "ETM";
    case ADAPTIVE_ETM:
      return "AdaptiveETM";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapMath::IsMapMethod(int method)
{
  return method >= TFM && method <= ADAPTIVE_ETM;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapMath::IsAdaptiveMethod(int method)
{
  return method == ADAPTIVE_TFM || method == ADAPTIVE_ETM;
}

//------------------------------------------------------------------------------
int vtkTransmittanceMapMath::GetNumberOfMapLayers(int method, int coefficientCount)
{
  if (!IsMapMethod(method) || coefficientCount < 1 || coefficientCount > kMaxCoefficients)
  {
    return 0;
  }
  return (coefficientCount + COEFFICIENTS_PER_LAYER - 1) / COEFFICIENTS_PER_LAYER +
    (IsAdaptiveMethod(method) ? 1 : 0);
}

//------------------------------------------------------------------------------
int vtkTransmittanceMapMath::GetBoundsLayer(int method, int coefficientCount)
{
  const int layers = GetNumberOfMapLayers(method, coefficientCount);
  return IsAdaptiveMethod(method) && layers > 0 ? layers - 1 : -1;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapMath::Project(int method, const double* profile, int profileSize,
  double length, int sampleCount, int coefficientCount, double adaptiveThreshold,
  double* coefficients, double bounds[3])
{
  if (!ValidProfile(profile, profileSize, length))
  {
    return false;
  }
  return Project(
    method, [=](double s) { return SampleProfile(profile, profileSize, s); }, length, sampleCount,
    coefficientCount, adaptiveThreshold, coefficients, bounds);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapMath::Project(int method, const std::function<double(double)>& extinction,
  double length, int sampleCount, int coefficientCount, double adaptiveThreshold,
  double* coefficients, double bounds[3])
{
  const bool adaptive = IsAdaptiveMethod(method);
  if (!IsMapMethod(method) || !extinction || !(length > 0.0) || !std::isfinite(length) ||
    sampleCount < 1 || coefficientCount < 1 || coefficientCount > kMaxCoefficients ||
    !coefficients || !bounds ||
    (adaptive && !(adaptiveThreshold >= 0.0 && adaptiveThreshold < 1.0)))
  {
    return false;
  }
  const bool tfm = IsTFM(method);

  if (!adaptive)
  {
    const double opticalDepth = MarchAndProject(
      tfm, extinction, length, 0.0, 1.0, sampleCount, coefficientCount, coefficients);
    bounds[0] = 0.0;
    bounds[1] = 1.0;
    bounds[2] = std::exp(-opticalDepth);
    return true;
  }

  // First march over [0, 1]: the first sample with extinction, and the
  // first sample whose midpoint transmittance falls below the threshold
  // (the range ends after it).
  const double du = 1.0 / sampleCount;
  int firstExtinct = -1;
  int firstBelow = -1;
  double opticalDepth = 0.0; // sum_{m<n} sigma_m D du
  for (int n = 0; n < sampleCount; ++n)
  {
    const double sigma = extinction((n + 0.5) * du);
    const double stepDepth = sigma * length * du;
    if (firstExtinct < 0 && sigma > 0.0)
    {
      firstExtinct = n;
    }
    if (std::exp(-(opticalDepth + 0.5 * stepDepth)) < adaptiveThreshold)
    {
      // The range ends after this sample, whose depth T_beyond includes: a
      // thin dense feature (a surface) may hold all of the ray's depth.
      firstBelow = n + 1;
      opticalDepth += stepDepth;
      break;
    }
    opticalDepth += stepDepth;
  }

  double sMin = 0.0;
  double sMax = 1.0;
  if (firstExtinct >= 0)
  {
    sMin = firstExtinct * du;
    sMax = firstBelow >= 0 ? firstBelow * du : 1.0;
  }
  const double transmittanceBeyond = std::exp(-opticalDepth);

  // Second march over the tight range.
  MarchAndProject(tfm, extinction, length, sMin, sMax, sampleCount, coefficientCount, coefficients);
  bounds[0] = sMin;
  bounds[1] = sMax;
  bounds[2] = transmittanceBeyond;
  return true;
}

//------------------------------------------------------------------------------
double vtkTransmittanceMapMath::Reconstruct(
  int method, const double* coefficients, int coefficientCount, const double bounds[3], double s)
{
  const bool adaptive = IsAdaptiveMethod(method);
  if (!IsMapMethod(method) || !coefficients || coefficientCount < 1 ||
    coefficientCount > kMaxCoefficients || std::isnan(s) || (adaptive && !bounds))
  {
    return 1.0;
  }

  double u = std::min(std::max(s, 0.0), 1.0);
  if (adaptive)
  {
    const double sMin = bounds[0];
    const double sMax = bounds[1];
    const double transmittanceBeyond = bounds[2];
    if (!(sMin >= 0.0 && sMin <= sMax && sMax <= 1.0 && transmittanceBeyond >= 0.0 &&
          transmittanceBeyond <= 1.0))
    {
      return 1.0;
    }
    if (s <= sMin)
    {
      return 1.0;
    }
    if (s >= sMax)
    {
      return transmittanceBeyond;
    }
    u = (s - sMin) / (sMax - sMin);
  }

  if (IsTFM(method))
  {
    double transmittance = 0.5 * coefficients[0];
    for (int j = 1; j < coefficientCount; ++j)
    {
      transmittance += coefficients[j] * std::cos(j * vtkMath::Pi() * u);
    }
    // NaN coefficients give 1, like other invalid input.
    return std::isnan(transmittance) ? 1.0 : std::min(std::max(transmittance, 0.0), 1.0);
  }

  double opticalDepth = 0.5 * coefficients[0] * u;
  for (int j = 1; j < coefficientCount; ++j)
  {
    const double frequency = j * vtkMath::Pi();
    opticalDepth += coefficients[j] * std::sin(frequency * u) / frequency;
  }
  // exp(-max(0, tau)); NaN coefficients (NaN tau) give 1, like other invalid input.
  return opticalDepth > 0.0 ? std::exp(-opticalDepth) : 1.0;
}

//------------------------------------------------------------------------------
double vtkTransmittanceMapMath::ExactTransmittance(
  const double* profile, int profileSize, double length, double s)
{
  if (!ValidProfile(profile, profileSize, length) || std::isnan(s))
  {
    return 1.0;
  }
  const double x = std::min(std::max(s, 0.0), 1.0) * (profileSize - 1);
  const int whole = std::min(static_cast<int>(x), profileSize - 2);
  const double h = 1.0 / (profileSize - 1); // profile interval in s
  double integral = 0.0;                    // of sigma_t over s in [0, s]
  for (int i = 0; i < whole; ++i)
  {
    integral += 0.5 * (profile[i] + profile[i + 1]) * h;
  }
  const double f = x - whole; // fraction of the last, partial interval
  const double extinctionAtS = (1.0 - f) * profile[whole] + f * profile[whole + 1];
  integral += 0.5 * (profile[whole] + extinctionAtS) * f * h;
  return std::exp(-length * integral);
}

//------------------------------------------------------------------------------
double vtkTransmittanceMapMath::HenyeyGreenstein(double g, double mu)
{
  g = std::isnan(g) ? 0.0 : std::min(std::max(g, -0.99), 0.99);
  mu = std::isnan(mu) ? 0.0 : std::min(std::max(mu, -1.0), 1.0);
  const double denominator = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * vtkMath::Pi() * denominator * std::sqrt(denominator));
}

//------------------------------------------------------------------------------
void vtkTransmittanceMapMath::OctaveScattering(int n, const double factors[4], double g, double mu,
  double T, const double albedo[3], double weight[3])
{
  weight[0] = weight[1] = weight[2] = 0.0;
  if (!(T > 0.0))
  {
    return;
  }
  T = std::min(T, 1.0);
  n = std::min(std::max(n, 1), 8);
  auto clamp = [](double v, double high)
  { return std::isnan(v) ? 0.0 : std::min(std::max(v, 0.0), high); };
  const double a = clamp(factors[0], 4.0);
  const double b = clamp(factors[1], 1.0);
  const double c = clamp(factors[2], 1.0);
  const double power = clamp(factors[3], 64.0);
  const double logT = std::log(T);
  const double buildUp = power > 0.0 ? 1.0 - std::exp(power * logT) : 1.0; // 1 - T^k
  double scale[3] = { 1.0, 1.0, 1.0 };                                     // (a rho)^i
  double extinction = 1.0;                                                 // b^i
  double anisotropy = g;                                                   // c^i g
  for (int i = 0; i < n; ++i)
  {
    const double term =
      HenyeyGreenstein(anisotropy, mu) * std::exp(extinction * logT) * (i > 0 ? buildUp : 1.0);
    for (int k = 0; k < 3; ++k)
    {
      weight[k] += scale[k] * term;
      scale[k] *= a * albedo[k];
    }
    extinction *= b;
    anisotropy *= c;
  }
}

//------------------------------------------------------------------------------
double vtkTransmittanceMapMath::ExtinctionFromOpacity(
  double alpha, double unitDistance, double densityScale)
{
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance) || !(densityScale >= 0.0) ||
    !std::isfinite(densityScale))
  {
    return 0.0;
  }
  alpha = std::isnan(alpha) ? 0.0 : std::min(std::max(alpha, 0.0), 1.0 - 1.0e-6);
  return densityScale * -std::log1p(-alpha) / unitDistance;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMapMath::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
