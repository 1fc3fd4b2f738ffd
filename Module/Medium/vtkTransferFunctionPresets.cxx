#include "vtkTransferFunctionPresets.h"

#include "vtkParticipatingMediumProperty.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkTransferFunctionPresets);

namespace
{
struct Preset
{
  const char* Name;
  const char* Description;
};

const Preset kPresets[] = {
  { "CT", "computed tomography in Hounsfield units: air clear, soft tissue red, bone white" },
  { "MR", "magnetic resonance, relative to the range: noise clear, tissue grey to white" },
  { "Cloud", "fog density, relative to the range: thin blue-grey to dense white, unshaded" },
  { "Smoke", "fog density, relative to the range: light grey smoke, unshaded" },
  { "DenseSmoke", "fog density, relative to the range: dark, nearly opaque smoke, unshaded" },
};
constexpr int kNumberOfPresets = static_cast<int>(sizeof(kPresets) / sizeof(kPresets[0]));

std::string Normalise(const char* name)
{
  std::string out;
  for (const char* p = name; *p; ++p)
  {
    if (*p != ' ' && *p != '-' && *p != '_')
    {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(*p)));
    }
  }
  return out;
}

// The guessing rule's thresholds (see the class description).
constexpr double kAirLow = -1100.0, kAirHigh = -900.0;      // HU
constexpr double kTissueLow = -100.0, kTissueHigh = 3000.0; // HU
constexpr double kSignatureFraction = 0.01;
constexpr double kDensityMaximum = 100.0;

vtkDataArray* ScalarsOf(vtkImageData* image)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  return scalars ? scalars : (image ? image->GetCellData()->GetScalars() : nullptr);
}

// A string of the image's field data ("" when absent).
std::string FieldString(vtkImageData* image, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() > 0 ? array->GetValue(0) : std::string();
}

struct ValueSummary
{
  double Min = std::numeric_limits<double>::infinity();
  double Max = -std::numeric_limits<double>::infinity();
  vtkIdType Finite = 0, Air = 0, Tissue = 0;
};

ValueSummary Summarise(vtkDataArray* scalars)
{
  ValueSummary s;
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (!std::isfinite(v))
    {
      continue;
    }
    ++s.Finite;
    s.Min = std::min(s.Min, v);
    s.Max = std::max(s.Max, v);
    s.Air += v >= kAirLow && v <= kAirHigh ? 1 : 0;
    s.Tissue += v >= kTissueLow && v <= kTissueHigh ? 1 : 0;
  }
  return s;
}

// VTK's gradient shading for a plain property (a vtkParticipatingMediumProperty
// keeps Shade off: its surface term is the application's choice).
void Shade(vtkVolumeProperty* property)
{
  property->SetShade(vtkParticipatingMediumProperty::SafeDownCast(property) ? 0 : 1);
  property->SetAmbient(0.2);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.3);
  property->SetSpecularPower(10.0);
}
}

//------------------------------------------------------------------------------
int vtkTransferFunctionPresets::GetNumberOfPresets()
{
  return kNumberOfPresets;
}

//------------------------------------------------------------------------------
const char* vtkTransferFunctionPresets::GetPresetName(int i)
{
  return (i >= 0 && i < kNumberOfPresets) ? kPresets[i].Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkTransferFunctionPresets::GetPresetDescription(int i)
{
  return (i >= 0 && i < kNumberOfPresets) ? kPresets[i].Description : nullptr;
}

//------------------------------------------------------------------------------
int vtkTransferFunctionPresets::GetPresetIndex(const char* name)
{
  if (!name)
  {
    return -1;
  }
  const std::string wanted = Normalise(name);
  for (int i = 0; i < kNumberOfPresets; ++i)
  {
    if (!wanted.empty() && Normalise(kPresets[i].Name) == wanted)
    {
      return i;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionPresets::Apply(
  const char* name, vtkVolumeProperty* property, const double scalarRange[2])
{
  if (!scalarRange)
  {
    if (property)
    {
      vtkErrorWithObjectMacro(property, << "vtkTransferFunctionPresets: no scalar range given.");
    }
    else
    {
      vtkGenericWarningMacro(<< "vtkTransferFunctionPresets: no property and no scalar range.");
    }
    return false;
  }
  return vtkTransferFunctionPresets::Apply(name, property, scalarRange[0], scalarRange[1]);
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionPresets::Apply(
  const char* name, vtkVolumeProperty* property, double lo, double hi)
{
  if (!property)
  {
    vtkGenericWarningMacro(<< "vtkTransferFunctionPresets: no volume property given.");
    return false;
  }
  const int index = vtkTransferFunctionPresets::GetPresetIndex(name);
  if (index < 0)
  {
    std::string known;
    for (int i = 0; i < kNumberOfPresets; ++i)
    {
      known += std::string(i ? ", " : "") + kPresets[i].Name;
    }
    vtkErrorWithObjectMacro(property, << "vtkTransferFunctionPresets: unknown preset '"
                                      << (name ? name : "(null)") << "'; the presets are " << known
                                      << ".");
    return false;
  }
  const std::string preset = kPresets[index].Name;
  if (preset != "CT" && !(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
  {
    vtkErrorWithObjectMacro(property, << "vtkTransferFunctionPresets: preset '" << preset
                                      << "' needs a finite scalar range with min < max; got [" << lo
                                      << ", " << hi << "].");
    return false;
  }
  // Relative position t in [0, 1] of the range to a scalar value.
  auto at = [lo, hi](double t) { return lo + t * (hi - lo); };

  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  if (preset == "CT")
  {
    opacity->AddPoint(-3024.0, 0.0);
    opacity->AddPoint(-600.0, 0.0);
    opacity->AddPoint(-100.0, 0.02);
    opacity->AddPoint(40.0, 0.15);
    opacity->AddPoint(300.0, 0.4);
    opacity->AddPoint(1500.0, 1.0);
    opacity->AddPoint(3071.0, 1.0);
    color->AddRGBPoint(-3024.0, 0.0, 0.0, 0.0);
    color->AddRGBPoint(-600.0, 0.0, 0.0, 0.0);
    color->AddRGBPoint(-100.0, 0.90, 0.75, 0.50);
    color->AddRGBPoint(40.0, 0.75, 0.35, 0.28);
    color->AddRGBPoint(300.0, 0.95, 0.88, 0.78);
    color->AddRGBPoint(1500.0, 1.0, 1.0, 0.97);
    color->AddRGBPoint(3071.0, 1.0, 1.0, 1.0);
    Shade(property);
  }
  else if (preset == "MR")
  {
    opacity->AddPoint(at(0.0), 0.0);
    opacity->AddPoint(at(0.1), 0.0);
    opacity->AddPoint(at(0.3), 0.1);
    opacity->AddPoint(at(0.6), 0.4);
    opacity->AddPoint(at(1.0), 0.8);
    color->AddRGBPoint(at(0.0), 0.0, 0.0, 0.0);
    color->AddRGBPoint(at(0.1), 0.35, 0.25, 0.25);
    color->AddRGBPoint(at(0.3), 0.70, 0.55, 0.52);
    color->AddRGBPoint(at(0.6), 0.92, 0.85, 0.80);
    color->AddRGBPoint(at(1.0), 1.0, 1.0, 1.0);
    Shade(property);
  }
  else if (preset == "Cloud")
  {
    opacity->AddPoint(at(0.0), 0.0);
    opacity->AddPoint(at(1.0), 0.25);
    color->AddRGBPoint(at(0.0), 0.80, 0.85, 0.92);
    color->AddRGBPoint(at(1.0), 1.0, 1.0, 1.0);
    property->ShadeOff();
  }
  else if (preset == "Smoke")
  {
    opacity->AddPoint(at(0.0), 0.0);
    opacity->AddPoint(at(0.02), 0.0);
    opacity->AddPoint(at(1.0), 0.15);
    color->AddRGBPoint(at(0.0), 0.55, 0.55, 0.55);
    color->AddRGBPoint(at(1.0), 0.30, 0.30, 0.30);
    property->ShadeOff();
  }
  else // DenseSmoke
  {
    opacity->AddPoint(at(0.0), 0.0);
    opacity->AddPoint(at(0.02), 0.0);
    opacity->AddPoint(at(0.5), 0.6);
    opacity->AddPoint(at(1.0), 0.9);
    color->AddRGBPoint(at(0.0), 0.20, 0.20, 0.20);
    color->AddRGBPoint(at(1.0), 0.06, 0.06, 0.06);
    property->ShadeOff();
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  return true;
}

//------------------------------------------------------------------------------
const char* vtkTransferFunctionPresets::GuessPreset(vtkImageData* image)
{
  vtkDataArray* scalars = ScalarsOf(image);
  if (!scalars || scalars->GetNumberOfTuples() == 0)
  {
    vtkGenericWarningMacro(<< "vtkTransferFunctionPresets::GuessPreset: the image has no scalars.");
    return nullptr;
  }
  // 1. A modality named by the file.
  const std::string modality = FieldString(image, "TyndallModality");
  if (!modality.empty())
  {
    return modality == "CT" ? "CT" : "MR";
  }
  // 2. The Hounsfield signature: air and tissue.
  const ValueSummary values = Summarise(scalars);
  const double finite = static_cast<double>(std::max<vtkIdType>(values.Finite, 1));
  if (values.Air / finite >= kSignatureFraction && values.Tissue / finite >= kSignatureFraction)
  {
    return "CT";
  }
  // 3. The format.
  const std::string format = FieldString(image, "TyndallFormat");
  if (format == "OpenVDB")
  {
    return "Cloud";
  }
  if (format == "DICOM" || format == "NIfTI")
  {
    return "MR";
  }
  // 4. The values.
  const int type = scalars->GetDataType();
  const bool floating = type == VTK_FLOAT || type == VTK_DOUBLE;
  return floating && values.Min >= 0.0 && values.Max <= kDensityMaximum ? "Cloud" : "MR";
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionPresets::ApplyToImage(
  const char* name, vtkVolumeProperty* property, vtkImageData* image)
{
  vtkDataArray* scalars = ScalarsOf(image);
  if (!scalars)
  {
    vtkGenericWarningMacro(<< "vtkTransferFunctionPresets::ApplyToImage: "
                           << (image ? "the image has no scalars." : "no image given."));
    return false;
  }
  const ValueSummary values = Summarise(scalars);
  if (values.Finite == 0)
  {
    vtkGenericWarningMacro(
      << "vtkTransferFunctionPresets::ApplyToImage: the image has no finite scalar.");
    return false;
  }
  double lo = values.Min, hi = values.Max;
  if (!(hi > lo)) // a constant volume: from 0 to its value, so that it is visible
  {
    lo = std::min(0.0, values.Min);
    hi = std::max(0.0, values.Min);
    if (lo == hi)
    {
      hi = lo + 1.0;
    }
  }
  if (!vtkTransferFunctionPresets::Apply(name, property, lo, hi))
  {
    return false;
  }
  double spacing[3];
  image->GetSpacing(spacing);
  property->SetScalarOpacityUnitDistance(
    (std::fabs(spacing[0]) + std::fabs(spacing[1]) + std::fabs(spacing[2])) / 3.0);
  return true;
}

//------------------------------------------------------------------------------
void vtkTransferFunctionPresets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Presets:";
  for (int i = 0; i < kNumberOfPresets; ++i)
  {
    os << " " << kPresets[i].Name;
  }
  os << "\n";
}
