#include "vtkTransferFunctionPresets.h"

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <cctype>
#include <cmath>
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

void Shade(vtkVolumeProperty* property)
{
  property->ShadeOn();
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
