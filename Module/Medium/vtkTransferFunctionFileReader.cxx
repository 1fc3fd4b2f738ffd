#include "vtkTransferFunctionFileReader.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransferFunctionFileReader);

namespace
{
// Strict number parsing: the whole text, finite.
bool ParseNumber(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

struct Keyword
{
  const char* Name;
  size_t Numbers;
  const char* Syntax;
};
const Keyword kKeywords[] = { { "opacity", 2, "opacity <value> <alpha>" },
  { "color", 4, "color <value> <r> <g> <b>" }, { "colour", 4, "color <value> <r> <g> <b>" },
  { "emission", 4, "emission <value> <r> <g> <b>" }, { "unit-distance", 1, "unit-distance <d>" } };
}

//------------------------------------------------------------------------------
vtkTransferFunctionFileReader::vtkTransferFunctionFileReader() = default;

//------------------------------------------------------------------------------
vtkTransferFunctionFileReader::~vtkTransferFunctionFileReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkTransferFunctionFileReader::GetFormatDescription()
{
  return "one entry per line ('#' comments):\n"
         "  opacity <value> <alpha>       alpha in [0, 1]\n"
         "  color <value> <r> <g> <b>     in [0, 1]\n"
         "  emission <value> <r> <g> <b>  >= 0\n"
         "  unit-distance <d>             world units, > 0\n"
         "alpha is the opacity of a slab unit-distance thick (VTK's convention;\n"
         "default 1); no color lines: white\n";
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionFileReader::Read()
{
  this->Valid = false;
  this->Opacity->RemoveAllPoints();
  this->Color->RemoveAllPoints();
  this->Emission->RemoveAllPoints();
  this->HasEmission = false;
  this->UnitDistance = 1.0;
  const std::string path = this->FileName ? this->FileName : "";
  std::ifstream in(path);
  if (path.empty() || !in)
  {
    vtkErrorMacro(<< (path.empty() ? std::string("no file name") : path) +
        ": cannot open the transfer-function file");
    return false;
  }
  int opacityPoints = 0;
  bool unitDistanceSeen = false, hasColor = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (!this->ParseLine(line, where, opacityPoints, unitDistanceSeen, hasColor))
    {
      return false;
    }
  }
  if (in.bad())
  {
    vtkErrorMacro(<< path << ": read error");
    return false;
  }
  if (opacityPoints == 0)
  {
    vtkErrorMacro(<< path << ": no 'opacity <value> <alpha>' line: the medium would be empty");
    return false;
  }
  if (!hasColor)
  {
    this->Color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  }
  this->Valid = true;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionFileReader::ParseLine(const std::string& text, const std::string& where,
  int& opacityPoints, bool& unitDistanceSeen, bool& hasColor)
{
  std::string line = text.substr(0, text.find('#'));
  std::istringstream words(line);
  std::vector<std::string> w;
  for (std::string word; words >> word;)
  {
    w.push_back(word);
  }
  if (w.empty())
  {
    return true;
  }
  const Keyword* keyword = nullptr;
  for (const Keyword& k : kKeywords)
  {
    keyword = w[0] == k.Name ? &k : keyword;
  }
  if (!keyword)
  {
    vtkErrorMacro(<< where << "unknown keyword '" << w[0]
                  << "' (expected opacity, color, emission or unit-distance)");
    return false;
  }
  if (w.size() != keyword->Numbers + 1)
  {
    vtkErrorMacro(<< where << "expected '" << keyword->Syntax << "' (" << keyword->Numbers
                  << " number" << (keyword->Numbers == 1 ? "" : "s") << "), got " << w.size() - 1);
    return false;
  }
  double v[4] = { 0, 0, 0, 0 };
  for (size_t k = 0; k < keyword->Numbers; ++k)
  {
    if (!ParseNumber(w[k + 1], v[k]))
    {
      vtkErrorMacro(<< where << "'" << w[k + 1] << "' is not a finite number (in '"
                    << keyword->Syntax << "')");
      return false;
    }
  }
  const std::string key = keyword->Name;
  if (key == "opacity")
  {
    if (v[1] < 0.0 || v[1] > 1.0)
    {
      vtkErrorMacro(<< where << "alpha must be in [0, 1], got " << w[2]);
      return false;
    }
    this->Opacity->AddPoint(v[0], v[1]);
    ++opacityPoints;
    return true;
  }
  if (key == "unit-distance")
  {
    if (unitDistanceSeen || v[0] <= 0.0)
    {
      vtkErrorMacro(<< where
                    << (unitDistanceSeen ? "unit-distance given twice"
                                         : "unit-distance must be > 0, got " + w[1]));
      return false;
    }
    this->UnitDistance = v[0];
    unitDistanceSeen = true;
    return true;
  }
  const bool emission = key == "emission";
  for (int k = 1; k < 4; ++k)
  {
    if (v[k] < 0.0 || (!emission && v[k] > 1.0))
    {
      vtkErrorMacro(<< where
                    << (emission ? "emission components must be >= 0, got "
                                 : "colour components must be in [0, 1], got ")
                    << w[k + 1]);
      return false;
    }
  }
  (emission ? this->Emission.Get() : this->Color.Get())->AddRGBPoint(v[0], v[1], v[2], v[3]);
  (emission ? this->HasEmission : hasColor) = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionFileReader::Apply(vtkVolumeProperty* property)
{
  if (!this->Valid || !property)
  {
    vtkErrorMacro(<< "Apply: " << (property ? "no transfer function was read" : "null property"));
    return false;
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->DeepCopy(this->Opacity);
  vtkNew<vtkColorTransferFunction> color;
  color->DeepCopy(this->Color);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(this->UnitDistance);
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  if (medium && this->HasEmission)
  {
    vtkNew<vtkColorTransferFunction> emission;
    emission->DeepCopy(this->Emission);
    medium->SetEmissionColor(emission);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTransferFunctionFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "HasEmission: " << this->HasEmission << "\n";
  os << indent << "UnitDistance: " << this->UnitDistance << "\n";
}
