// vtkTransferFunctionPresets: the list of presets, name matching, and each
// preset's documented anchor values (CT in Hounsfield units, the others
// relative to the scalar range, hence scale invariant); errors leave the
// property unchanged; functions already on the property are replaced, not
// modified. The single guessing rule (GuessPreset) on volumes that fool a
// guess that looks only at the type and the minimum: an MR with a negative
// minimum, a padded MR, a floating-point MR, a CT, a density; and
// ApplyToImage.
#include "TyndallTestCheck.h"
#include "vtkColorTransferFunction.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransferFunctionPresets.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
using tyndall_test::Check;

bool Close(double a, double b)
{
  return std::abs(a - b) <= 1e-9;
}

double Opacity(vtkVolumeProperty* p, double v)
{
  return p->GetScalarOpacity()->GetValue(v);
}

double Brightness(vtkVolumeProperty* p, double v)
{
  double rgb[3];
  p->GetRGBTransferFunction()->GetColor(v, rgb);
  return rgb[0] + rgb[1] + rgb[2];
}

// A 20^3 image whose i-th value is value(i), of the array type T, with the
// field-data hints of vtkVolumeFileReader when given.
template <typename T>
vtkSmartPointer<vtkImageData> MakeVolume(const std::function<double(int)>& value,
  const char* format = nullptr, const char* modality = nullptr)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(20, 20, 20);
  image->SetSpacing(0.5, 1.0, 1.5);
  vtkNew<T> values;
  values->SetNumberOfTuples(8000);
  for (int i = 0; i < 8000; ++i)
  {
    values->SetTuple1(i, value(i));
  }
  image->GetPointData()->SetScalars(values);
  for (auto hint :
    { std::make_pair("TyndallFormat", format), std::make_pair("TyndallModality", modality) })
  {
    if (hint.second)
    {
      vtkNew<vtkStringArray> text;
      text->SetName(hint.first);
      text->InsertNextValue(hint.second);
      image->GetFieldData()->AddArray(text);
    }
  }
  return image;
}

void CheckGuess(vtkImageData* image, const std::string& expected, const std::string& what)
{
  const char* guess = vtkTransferFunctionPresets::GuessPreset(image);
  const std::string got = guess ? guess : "(null)";
  if (got != expected)
  {
    std::cerr << what << ": guessed " << got << ", expected " << expected << std::endl;
  }
  Check(got == expected, "guess: " + what);
}

void TestGuessing()
{
  // A head CT in HU: air around it, soft tissue and bone.
  auto ctHead = [](int i) { return i % 10 < 3 ? -1000.0 : (i % 10 < 9 ? 40.0 : 1200.0); };
  CheckGuess(MakeVolume<vtkShortArray>(ctHead), "CT", "a CT in HU (air and tissue)");
  CheckGuess(MakeVolume<vtkFloatArray>(ctHead), "CT", "a floating-point CT in HU");
  // An MR with a negative minimum (noise around 0): not a CT.
  auto mrNoisy = [](int i) { return i % 7 == 0 ? -50.0 + i % 13 : 200.0 + i % 600; };
  CheckGuess(MakeVolume<vtkShortArray>(mrNoisy), "MR", "an MR with a negative minimum");
  // An MR padded with -32768 outside the field of view: no air peak.
  auto mrPadded = [](int i) { return i % 5 == 0 ? -32768.0 : 100.0 + i % 900; };
  CheckGuess(MakeVolume<vtkShortArray>(mrPadded), "MR", "an MR padded with -32768");
  // A floating-point MR (intensities in the hundreds): not a cloud.
  auto mrFloat = [](int i) { return i % 4 == 0 ? 0.0 : 150.0 + 0.37 * (i % 2000); };
  CheckGuess(MakeVolume<vtkFloatArray>(mrFloat), "MR", "a floating-point MR");
  // A normalised floating-point MR looks like a density by its values; its
  // format says MR.
  auto normalised = [](int i) { return (i % 100) / 99.0; };
  CheckGuess(MakeVolume<vtkFloatArray>(normalised), "Cloud", "a density in [0, 1]");
  CheckGuess(
    MakeVolume<vtkFloatArray>(normalised, "NIfTI"), "MR", "a normalised MR read from NIfTI");
  CheckGuess(MakeVolume<vtkFloatArray>(normalised, "DICOM"), "MR", "a normalised image from DICOM");
  // An OpenVDB fog volume is a density whatever its values.
  CheckGuess(MakeVolume<vtkFloatArray>(mrFloat, "OpenVDB"), "Cloud", "an OpenVDB grid");
  // Integer scans without hints: MR.
  CheckGuess(
    MakeVolume<vtkUnsignedCharArray>([](int i) { return i % 256; }), "MR", "unsigned char data");
  // A modality named by the file wins.
  CheckGuess(MakeVolume<vtkShortArray>(mrNoisy, "MetaImage", "CT"), "CT", "modality CT");
  CheckGuess(MakeVolume<vtkShortArray>(ctHead, "MetaImage", "MR"), "MR", "modality MR");
  CheckGuess(MakeVolume<vtkShortArray>(ctHead, "MetaImage", "PT"), "MR", "modality PT");
  vtkNew<vtkImageData> empty;
  Check(vtkTransferFunctionPresets::GuessPreset(empty) == nullptr, "no scalars: no guess");

  // ApplyToImage: the range and the unit distance (the mean spacing).
  vtkNew<vtkVolumeProperty> property;
  Check(vtkTransferFunctionPresets::ApplyToImage(
          "MR", property, MakeVolume<vtkUnsignedCharArray>([](int i) { return 10 + i % 101; })),
    "ApplyToImage applies");
  Check(Close(property->GetScalarOpacityUnitDistance(), 1.0), "unit distance = mean spacing");
  Check(Close(Opacity(property, 10.0 + 0.6 * 100.0), 0.4), "over the data's range [10, 110]");
  Check(vtkTransferFunctionPresets::ApplyToImage(
          "Cloud", property, MakeVolume<vtkFloatArray>([](int) { return 3.0; })) &&
      Close(Opacity(property, 3.0), 0.25),
    "a constant volume c: over [0, c], so it is visible");
  Check(!vtkTransferFunctionPresets::ApplyToImage("Cloud", property, empty),
    "no scalars: ApplyToImage fails");
}

// Opacity and colour stay in [0, 1] and opacity never decreases over [lo, hi].
void CheckRanges(vtkVolumeProperty* p, double lo, double hi, const std::string& tag)
{
  bool ok = true, monotone = true;
  double previous = -1.0;
  for (int s = 0; s <= 200; ++s)
  {
    const double v = lo + (hi - lo) * s / 200.0;
    const double o = Opacity(p, v);
    double rgb[3];
    p->GetRGBTransferFunction()->GetColor(v, rgb);
    ok = ok && o >= 0.0 && o <= 1.0 && rgb[0] >= 0.0 && rgb[0] <= 1.0 && rgb[1] >= 0.0 &&
      rgb[1] <= 1.0 && rgb[2] >= 0.0 && rgb[2] <= 1.0;
    monotone = monotone && o >= previous;
    previous = o;
  }
  Check(ok, tag + ": opacity and colour in [0, 1]");
  Check(monotone, tag + ": opacity never decreases with the value");
}
}

int TestTransferFunctionPresets(int, char*[])
{
  using P = vtkTransferFunctionPresets;
  // The list.
  Check(P::GetNumberOfPresets() == 5, "five presets");
  const char* names[] = { "CT", "MR", "Cloud", "Smoke", "DenseSmoke" };
  for (int i = 0; i < 5; ++i)
  {
    Check(P::GetPresetName(i) && std::string(P::GetPresetName(i)) == names[i],
      std::string("preset ") + names[i]);
    Check(P::GetPresetDescription(i) && *P::GetPresetDescription(i), "a description");
    Check(P::GetPresetIndex(names[i]) == i, std::string("index of ") + names[i]);
  }
  Check(!P::GetPresetName(-1) && !P::GetPresetName(5) && !P::GetPresetDescription(5),
    "out-of-range indices give null");
  Check(P::GetPresetIndex("ct") == 0 && P::GetPresetIndex("dense smoke") == 4 &&
      P::GetPresetIndex("Dense_Smoke") == 4 && P::GetPresetIndex("dense-smoke") == 4,
    "names match ignoring case, spaces, '-' and '_'");
  Check(P::GetPresetIndex("bogus") == -1 && P::GetPresetIndex("") == -1 &&
      P::GetPresetIndex(nullptr) == -1,
    "unknown names give -1");

  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkVolumeProperty> property;
  property->AddObserver(vtkCommand::ErrorEvent, observer);

  // CT, in Hounsfield units; the range is ignored.
  Check(P::Apply("CT", property, 0.0, 1.0), "CT applies");
  CheckRanges(property, -1024.0, 3071.0, "CT");
  Check(Close(Opacity(property, -1000.0), 0.0) && Close(Opacity(property, -600.0), 0.0),
    "CT: air and lungs are transparent");
  Check(Close(Opacity(property, 40.0), 0.15), "CT: soft tissue opacity 0.15 at 40 HU");
  Check(Close(Opacity(property, 300.0), 0.4) && Close(Opacity(property, 1500.0), 1.0),
    "CT: bone from 0.4 at 300 HU to opaque at 1500 HU");
  double rgb[3];
  property->GetRGBTransferFunction()->GetColor(40.0, rgb);
  Check(rgb[0] > rgb[1] && rgb[0] > rgb[2], "CT: soft tissue is red");
  Check(Brightness(property, 1500.0) > Brightness(property, 40.0), "CT: bone is brighter");
  Check(property->GetShade() == 1 && property->GetInterpolationType() == VTK_LINEAR_INTERPOLATION,
    "CT: shaded, linear interpolation");
  const double soft = Opacity(property, 40.0);
  Check(P::Apply("ct", property, -5.0, 5.0) && Close(Opacity(property, 40.0), soft),
    "CT ignores the scalar range");

  // The relative presets are scale invariant: the same opacity at the same
  // relative position of two different ranges.
  struct Anchor
  {
    const char* Name;
    double T;
    double Opacity;
  };
  const Anchor anchors[] = {
    { "MR", 0.0, 0.0 },
    { "MR", 0.1, 0.0 },
    { "MR", 0.3, 0.1 },
    { "MR", 0.6, 0.4 },
    { "MR", 1.0, 0.8 },
    { "Cloud", 0.0, 0.0 },
    { "Cloud", 0.5, 0.125 },
    { "Cloud", 1.0, 0.25 },
    { "Smoke", 0.0, 0.0 },
    { "Smoke", 0.02, 0.0 },
    { "Smoke", 1.0, 0.15 },
    { "DenseSmoke", 0.02, 0.0 },
    { "DenseSmoke", 0.5, 0.6 },
    { "DenseSmoke", 1.0, 0.9 },
  };
  const double ranges[2][2] = { { 0.0, 255.0 }, { -1000.0, 3000.0 } };
  for (const Anchor& a : anchors)
  {
    for (const auto& r : ranges)
    {
      Check(P::Apply(a.Name, property, r), std::string(a.Name) + " applies");
      const double v = r[0] + a.T * (r[1] - r[0]);
      Check(Close(Opacity(property, v), a.Opacity),
        std::string(a.Name) + ": opacity " + std::to_string(a.Opacity) + " at t = " +
          std::to_string(a.T) + " of [" + std::to_string(r[0]) + ", " + std::to_string(r[1]) + "]");
      CheckRanges(property, r[0], r[1], a.Name);
    }
  }
  for (const char* name : { "Cloud", "Smoke", "DenseSmoke" })
  {
    P::Apply(name, property, 0.0, 1.0);
    Check(property->GetShade() == 0, std::string(name) + ": unshaded");
  }
  P::Apply("MR", property, 0.0, 1.0);
  Check(property->GetShade() == 1, "MR: shaded");
  P::Apply("Cloud", property, 0.0, 1.0);
  Check(
    Brightness(property, 1.0) > Brightness(property, 0.0) && Close(Brightness(property, 1.0), 3.0),
    "Cloud: white where dense");
  P::Apply("Smoke", property, 0.0, 1.0);
  Check(Brightness(property, 1.0) < Brightness(property, 0.0), "Smoke: darker where dense");
  const double smokeDense = Brightness(property, 1.0);
  P::Apply("DenseSmoke", property, 0.0, 1.0);
  Check(Brightness(property, 1.0) < smokeDense, "DenseSmoke: darker than Smoke");

  // Functions already on the property are replaced, not modified.
  {
    vtkNew<vtkPiecewiseFunction> mine;
    mine->AddPoint(0.0, 0.5);
    mine->AddPoint(1.0, 0.5);
    property->SetScalarOpacity(mine);
    P::Apply("Cloud", property, 0.0, 1.0);
    Check(property->GetScalarOpacity() != mine.GetPointer() && mine->GetSize() == 2 &&
        Close(mine->GetValue(0.0), 0.5),
      "the user's opacity function is replaced and left unchanged");
  }

  // Errors leave the property alone.
  {
    P::Apply("Smoke", property, 0.0, 1.0);
    vtkPiecewiseFunction* before = property->GetScalarOpacity();
    Check(!P::Apply("bogus", property, 0.0, 1.0), "an unknown preset fails");
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("unknown preset 'bogus'") != std::string::npos,
      "an unknown preset: an error naming it");
    observer->Clear();
    Check(!P::Apply("Cloud", property, 1.0, 1.0), "an empty range fails");
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("finite scalar range") != std::string::npos,
      "an empty range: an error");
    observer->Clear();
    Check(!P::Apply("MR", property, std::numeric_limits<double>::quiet_NaN(), 1.0),
      "a NaN range fails");
    observer->Clear();
    Check(!P::Apply("Cloud", property, 2.0, 1.0), "an inverted range fails");
    observer->Clear();
    const double* noRange = nullptr;
    Check(!P::Apply("Cloud", property, noRange), "no range fails");
    observer->Clear();
    Check(property->GetScalarOpacity() == before, "failures leave the property unchanged");
    Check(!P::Apply("Cloud", nullptr, 0.0, 1.0), "no property fails without crashing");
  }
  TestGuessing();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
