#include "vtkTyndallToneMapping.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkTyndallToneMapping);

namespace
{
const char* const CurveNames[] = { "linear", "reinhard", "aces" };
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::Curve(int curve, double x)
{
  // Negative or NaN: 0; the bounded curves: white far above it.
  x = x > 0.0 ? x : 0.0;
  x = curve == LINEAR ? x : std::min(x, Largest);
  switch (curve)
  {
    case REINHARD:
      return x / (1.0 + x);
    case ACES:
    {
      const double value = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
      return std::min(std::max(value, 0.0), 1.0);
    }
    default:
      return x;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::InverseCurve(int curve, double y)
{
  switch (curve)
  {
    case REINHARD:
      y = std::min(std::max(y, 0.0), Largest / (1.0 + Largest));
      return y / (1.0 - y);
    case ACES:
    {
      // (2.51 - 2.43 y) x^2 + (0.03 - 0.59 y) x - 0.14 y = 0, its root >= 0
      // (the form without cancellation for B >= 0).
      y = std::min(std::max(y, 0.0), 1.0);
      const double a = 2.51 - 2.43 * y;
      const double b = 0.03 - 0.59 * y;
      const double root = std::sqrt(b * b + 0.56 * a * y);
      return b >= 0.0 ? 0.28 * y / std::max(b + root, 1e-300) : (root - b) / (2.0 * a);
    }
    default:
      return y;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::EncodeSRGB(double linear)
{
  if (!(linear > 0.0))
  {
    return 0.0;
  }
  const double x = std::min(linear, 1.0);
  return x < 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::DecodeSRGB(double encoded)
{
  if (!(encoded > 0.0))
  {
    return 0.0;
  }
  const double v = std::min(encoded, 1.0);
  return v < 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace
{
double ClampExposure(double exposure)
{
  const double limit = vtkTyndallToneMapping::MaximumExposure;
  return std::min(std::max(exposure, -limit), limit);
}
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::Map(double linear, double exposure, int curve, bool srgb)
{
  const double mapped = Curve(curve, linear * std::exp2(ClampExposure(exposure)));
  return srgb ? EncodeSRGB(mapped) : mapped;
}

//------------------------------------------------------------------------------
double vtkTyndallToneMapping::Unmap(double display, double exposure, int curve, bool srgb)
{
  const double mapped = srgb ? DecodeSRGB(display) : display;
  return InverseCurve(curve, mapped) / std::exp2(ClampExposure(exposure));
}

//------------------------------------------------------------------------------
void vtkTyndallToneMapping::MapOver(const double rgba[4], const double background[3],
  double exposure, int curve, bool srgb, double out[4], double pixel[3])
{
  const double behind = 1.0 - std::min(std::max(rgba[3], 0.0), 1.0);
  for (int k = 0; k < 3; ++k)
  {
    const double shown =
      Map(rgba[k] + behind * Unmap(background[k], exposure, curve, srgb), exposure, curve, srgb);
    out[k] = shown - behind * background[k];
    if (pixel)
    {
      pixel[k] = shown;
    }
  }
  out[3] = rgba[3];
}

//------------------------------------------------------------------------------
bool vtkTyndallToneMapping::IsIdentity(double exposure, int curve, bool srgb)
{
  return exposure == 0.0 && curve == LINEAR && !srgb;
}

//------------------------------------------------------------------------------
const char* vtkTyndallToneMapping::GetCurveName(int curve)
{
  return curve >= LINEAR && curve <= ACES ? CurveNames[curve] : nullptr;
}

//------------------------------------------------------------------------------
int vtkTyndallToneMapping::GetCurveFromName(const char* name)
{
  for (int curve = LINEAR; name && curve <= ACES; ++curve)
  {
    if (std::strcmp(name, CurveNames[curve]) == 0)
    {
      return curve;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
void vtkTyndallToneMapping::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
