// vtkTyndallToneMapping against exact values (the CPU twin of the mapper's
// display transform, vtkTransmittanceOutputFS.glsl; the GPU side is
// TestTransmittanceMapperToneMapping):
// - sRGB: IEC 61966-2-1's published values (8-bit 128 decodes to
//   0.2158605001; linear 0.5 encodes to 0.7353569831), the two pieces meet
//   at 0.0031308 (within 1e-7), decode inverts encode, clamping above 1;
// - ACES (Narkowicz's fit): 0 at 0, 2.54 / 3.16 at 1, slope 0.03 / 0.14 at
//   0, 1 from 3.5 + sqrt(14) on, increasing;
// - Reinhard: 1/2 at 1, 3/4 at 3, below 1;
// - Map(): exposure in stops (2^EV), the identity bit for bit at exposure 0
//   with LINEAR and no sRGB (values above 1 kept), NaN and negatives 0;
// - InverseCurve() and Unmap() invert Curve() and Map();
// - MapOver(): over a background B the pixel is Map(L + (1 - a) Unmap(B)),
//   B kept without medium, Map(L) over black, exposure alone linear,
//   emission keeps its light;
// - the curves' names.
#include "vtkNew.h"
#include "vtkTyndallToneMapping.h"

#include "TyndallTestCheck.h"

#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>

int TestTyndallToneMapping(int, char*[])
{
  using tyndall_test::Check;
  using T = vtkTyndallToneMapping;
  vtkNew<vtkTyndallToneMapping> object;
  std::ostringstream print;
  object->Print(print);
  Check(print.str().find("vtkTyndallToneMapping") != std::string::npos, "PrintSelf");

  // sRGB.
  Check(std::abs(T::DecodeSRGB(128.0 / 255.0) - 0.2158605001) < 1e-9, "8-bit 128 decodes");
  Check(std::abs(T::EncodeSRGB(0.5) - 0.7353569831) < 1e-9, "0.5 encodes");
  Check(std::abs(T::EncodeSRGB(0.0031308) - 12.92 * 0.0031308) < 1e-7, "the pieces meet");
  Check(T::EncodeSRGB(0.001) == 12.92 * 0.001, "the linear piece");
  Check(std::abs(T::EncodeSRGB(1.0) - 1.0) < 1e-15 && T::EncodeSRGB(5.0) == T::EncodeSRGB(1.0),
    "1 and above encode to 1 (1.055 - 0.055 in doubles)");
  Check(T::EncodeSRGB(0.0) == 0.0 && T::EncodeSRGB(-1.0) == 0.0, "0 and below encode to 0");
  double roundTrip = 0.0;
  for (int i = 0; i <= 1000; ++i)
  {
    const double x = i / 1000.0;
    roundTrip = std::max(roundTrip, std::abs(T::DecodeSRGB(T::EncodeSRGB(x)) - x));
  }
  Check(roundTrip < 1e-12, "decode inverts encode");

  // ACES.
  Check(T::Curve(T::ACES, 0.0) == 0.0, "ACES(0) = 0");
  Check(std::abs(T::Curve(T::ACES, 1.0) - 2.54 / 3.16) < 1e-15, "ACES(1) = 2.54 / 3.16");
  const double h = 1e-7;
  Check(std::abs(T::Curve(T::ACES, h) / h - 0.03 / 0.14) < 1e-5, "ACES's slope at 0");
  const double white = 3.5 + std::sqrt(14.0);
  Check(T::Curve(T::ACES, white * (1.0 + 1e-9)) == 1.0 && T::Curve(T::ACES, 100.0) == 1.0 &&
      T::Curve(T::ACES, white * 0.99) < 1.0,
    "ACES is 1 from 3.5 + sqrt(14) on");
  bool increasing = true;
  for (int i = 1; i <= 1000; ++i)
  {
    increasing = increasing &&
      T::Curve(T::ACES, i * white / 1000.0) > T::Curve(T::ACES, (i - 1) * white / 1000.0);
  }
  Check(increasing, "ACES increases up to its white");

  // Reinhard.
  Check(T::Curve(T::REINHARD, 1.0) == 0.5 && T::Curve(T::REINHARD, 3.0) == 0.75,
    "Reinhard(1) = 1/2, Reinhard(3) = 3/4");
  Check(T::Curve(T::REINHARD, 1e6) < 1.0, "Reinhard stays below 1");

  // Map().
  bool identity = true;
  for (double x : { 0.0, 1e-6, 0.3, 1.0, 7.5, 1e5 })
  {
    identity = identity && T::Map(x, 0.0, T::LINEAR, false) == x;
  }
  Check(identity, "exposure 0, linear, no sRGB: the identity (above 1 too)");
  Check(T::IsIdentity(0.0, T::LINEAR, false) && !T::IsIdentity(0.5, T::LINEAR, false) &&
      !T::IsIdentity(0.0, T::REINHARD, false) && !T::IsIdentity(0.0, T::LINEAR, true),
    "IsIdentity()");
  Check(T::Map(0.25, 2.0, T::LINEAR, false) == 1.0 && T::Map(4.0, -3.0, T::LINEAR, false) == 0.5,
    "exposure in stops");
  Check(T::Map(0.5, 1.0, T::REINHARD, true) == T::EncodeSRGB(0.5), "the steps in order");
  Check(T::Map(1.0, 100.0, T::LINEAR, false) == std::exp2(T::MaximumExposure),
    "the exposure is clamped to its range");
  // InverseCurve() and Unmap(): the inverses on the curves' ranges.
  double inverse = 0.0;
  for (int curve : { T::LINEAR, T::REINHARD, T::ACES })
  {
    for (int i = 0; i <= 1000; ++i)
    {
      const double y = 0.999 * i / 1000.0;
      inverse = std::max(inverse, std::abs(T::Curve(curve, T::InverseCurve(curve, y)) - y));
      // Below ACES's white, and below 1 for the linear curve's sRGB.
      const double x = (curve == T::LINEAR ? 0.6 : 3.0) * i / 1000.0;
      inverse = std::max(inverse,
        std::abs(T::Unmap(T::Map(x, 0.7, curve, true), 0.7, curve, true) - x) /
          (curve == T::LINEAR ? 1.0 : std::max(x, 1.0)));
    }
  }
  std::cout << "largest error of the inverses: " << inverse << "\n";
  Check(inverse < 1e-9, "InverseCurve() and Unmap() invert Curve() and Map()");
  Check(std::abs(T::InverseCurve(T::ACES, 1.0) - white) < 1e-12 &&
      T::InverseCurve(T::ACES, 0.0) == 0.0 && T::InverseCurve(T::REINHARD, 0.5) == 1.0,
    "the inverses' exact points: ACES's white, 0; Reinhard's 1/2");

  // MapOver(): the pixel is Map(L + (1 - a) Unmap(B)).
  const double cloud[4] = { 0.3, 0.2, 0.1, 0.25 };
  const double sky[3] = { 0.55, 0.68, 0.82 };
  const double black[3] = { 0.0, 0.0, 0.0 };
  double out[4], pixel[3];
  T::MapOver(cloud, sky, 0.5, T::ACES, true, out, pixel);
  const double expected =
    T::Map(0.3 + 0.75 * T::Unmap(0.55, 0.5, T::ACES, true), 0.5, T::ACES, true);
  Check(std::abs(pixel[0] - expected) < 1e-15 &&
      std::abs(out[0] + 0.75 * 0.55 - pixel[0]) < 1e-15 && out[3] == 0.25,
    "over a background: the transform of its light seen through the medium plus the medium's");
  Check(pixel[0] > 0.55 && pixel[0] < 0.55 + T::Map(0.3, 0.5, T::ACES, true),
    "the medium brightens the sky less than over black (no halo)");
  T::MapOver(cloud, black, 0.5, T::ACES, true, out);
  Check(std::abs(out[1] - T::Map(0.2, 0.5, T::ACES, true)) < 1e-15, "over black: Map(L)");
  const double clear[4] = { 0.0, 0.0, 0.0, 0.0 };
  double worstClear = 0.0;
  for (int curve : { T::LINEAR, T::REINHARD, T::ACES })
  {
    for (double b : { 0.0, 0.02, 0.3, 0.9, 1.0 })
    {
      const double background[3] = { b, b, b };
      T::MapOver(clear, background, -1.0, curve, true, out);
      worstClear = std::max(worstClear, std::abs(out[0]));
    }
  }
  std::cout << "largest change of a background without medium: " << worstClear << "\n";
  Check(
    worstClear < 2e-4, "without medium the background keeps its value (Reinhard's white: 1e-4)");
  T::MapOver(cloud, sky, 2.0, T::LINEAR, false, out);
  Check(std::abs(out[0] - 1.2) < 1e-15 && std::abs(out[2] - 0.4) < 1e-15,
    "exposure alone scales the radiance, whatever the background");
  const double opaque[4] = { 0.7, 0.2, 3.0, 1.0 };
  T::MapOver(opaque, sky, -0.5, T::ACES, true, out);
  Check(out[2] == T::Map(3.0, -0.5, T::ACES, true), "an opaque medium hides the background");
  const double fire[4] = { 3.0, 1.0, 0.2, 0.05 };
  T::MapOver(fire, black, 0.0, T::REINHARD, false, out);
  Check(out[0] == 0.75, "emission brighter than its opacity keeps its light");
  Check(T::Curve(T::ACES, 1e300) == 1.0 &&
      T::Curve(T::REINHARD, 1e300) == T::Largest / (1.0 + T::Largest),
    "the bounded curves are clamped at Largest");

  for (int curve : { T::LINEAR, T::REINHARD, T::ACES })
  {
    Check(T::Map(std::nan(""), 0.0, curve, true) == 0.0 && T::Map(-2.0, 0.0, curve, false) == 0.0,
      std::string("NaN and negatives give 0: ") + T::GetCurveName(curve));
    Check(T::GetCurveFromName(T::GetCurveName(curve)) == curve, "a curve's name");
  }
  Check(T::GetCurveName(3) == nullptr && T::GetCurveFromName("filmic") == -1 &&
      T::GetCurveFromName(nullptr) == -1,
    "no other curves");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
