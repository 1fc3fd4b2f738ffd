#include "vtkParticleFileReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSmartPointer.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleFileReader);

namespace
{
// The lower-case extension of `fileName` (with its dot), or "".
std::string Extension(const char* fileName)
{
  return fileName
    ? vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName))
    : std::string();
}

// The fields of one line, separated by commas, semicolons, spaces or tabs.
std::vector<std::string> Split(const std::string& line)
{
  std::vector<std::string> fields;
  auto separator = [](char c)
  { return c == ',' || c == ';' || std::isspace(static_cast<unsigned char>(c)); };
  size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && separator(line[i]))
    {
      ++i;
    }
    size_t end = i;
    while (end < line.size() && !separator(line[end]))
    {
      ++end;
    }
    if (end > i)
    {
      fields.push_back(line.substr(i, end - i));
    }
    i = end;
  }
  return fields;
}

// A field as a number (out of double's range: not one); false when it is not one.
bool Number(const std::string& field, double& value)
{
  char* stop = nullptr;
  errno = 0;
  value = std::strtod(field.c_str(), &stop);
  return stop == field.c_str() + field.size() && errno != ERANGE;
}

// The numbers of one line; false when some field is not a number.
bool ParseNumbers(const std::string& line, std::vector<double>& values)
{
  values.clear();
  for (const std::string& field : Split(line))
  {
    double v;
    if (!Number(field, v))
    {
      return false;
    }
    values.push_back(v);
  }
  return true;
}

// A header: a line none of whose fields starts like a number ("x,y,z,radius,density").
bool IsHeader(const std::string& line)
{
  for (const std::string& field : Split(line))
  {
    char* stop = nullptr;
    std::strtod(field.c_str(), &stop);
    if (stop != field.c_str())
    {
      return false;
    }
  }
  return true;
}

// A named point-data array of `data` with `components` components, or null.
vtkDataArray* PointArray(vtkPolyData* data, const char* name, int components)
{
  vtkDataArray* array = name ? data->GetPointData()->GetArray(name) : nullptr;
  return array && array->GetNumberOfComponents() == components ? array : nullptr;
}
}

//------------------------------------------------------------------------------
vtkParticleFileReader::vtkParticleFileReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetRadiusArrayName("radius");
  this->SetDensityArrayName("density");
  this->SetColorArrayName("color");
}

//------------------------------------------------------------------------------
vtkParticleFileReader::~vtkParticleFileReader()
{
  this->SetFileName(nullptr);
  this->SetRadiusArrayName(nullptr);
  this->SetDensityArrayName(nullptr);
  this->SetColorArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkParticleFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto text = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "FileName: " << text(this->FileName) << "\n";
  os << indent << "RadiusArrayName: " << text(this->RadiusArrayName) << "\n";
  os << indent << "DensityArrayName: " << text(this->DensityArrayName) << "\n";
  os << indent << "ColorArrayName: " << text(this->ColorArrayName) << "\n";
}

//------------------------------------------------------------------------------
bool vtkParticleFileReader::CanReadExtension(const char* fileName)
{
  const std::string e = Extension(fileName);
  return e == ".csv" || e == ".txt" || e == ".vtp" || e == ".vtk";
}

//------------------------------------------------------------------------------
int vtkParticleFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No file name.");
    return 0;
  }
  if (!vtksys::SystemTools::FileExists(this->FileName, true))
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " does not exist.");
    return 0;
  }
  const std::string e = Extension(this->FileName);
  bool ok = false;
  if (e == ".csv" || e == ".txt")
  {
    ok = this->ReadText(output);
  }
  else if (e == ".vtp" || e == ".vtk")
  {
    ok = this->ReadPolyData(output, e == ".vtp");
  }
  else
  {
    vtkErrorMacro(<< "Particle file " << this->FileName
                  << ": unknown extension (.csv, .txt, .vtp or .vtk).");
  }
  if (!ok || !this->Validate(output))
  {
    output->Initialize(); // never a partial cloud
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkParticleFileReader::ReadText(vtkPolyData* output)
{
  std::ifstream in(this->FileName);
  if (!in)
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " cannot be opened.");
    return false;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius, density, color;
  radius->SetName("radius");
  density->SetName("density");
  color->SetName("color");
  color->SetNumberOfComponents(3);
  std::string line;
  std::vector<double> v;
  size_t columns = 0;
  long long lineNumber = 0;
  bool first = true;
  while (std::getline(in, line))
  {
    ++lineNumber;
    const size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#')
    {
      continue;
    }
    const bool numbers = ParseNumbers(line, v);
    if (!numbers && first && IsHeader(line))
    {
      first = false;
      continue;
    }
    first = false;
    if (!numbers || (v.size() != 5 && v.size() != 8) || (columns && v.size() != columns))
    {
      vtkErrorMacro(<< "Particle file " << this->FileName << ", line " << lineNumber
                    << ": expected " << (columns ? std::to_string(columns) : "5 or 8")
                    << " numbers (x y z radius density [r g b]).");
      return false;
    }
    columns = v.size();
    if (points->GetNumberOfPoints() >= MaximumNumberOfParticles)
    {
      vtkErrorMacro(<< "Particle file " << this->FileName << " holds more than "
                    << MaximumNumberOfParticles << " particles.");
      return false;
    }
    points->InsertNextPoint(v[0], v[1], v[2]);
    radius->InsertNextValue(v[3]);
    density->InsertNextValue(v[4]);
    if (columns == 8)
    {
      color->InsertNextTuple3(v[5], v[6], v[7]);
    }
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->AddArray(density);
  if (columns == 8)
  {
    output->GetPointData()->AddArray(color);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleFileReader::ReadPolyData(vtkPolyData* output, bool xml)
{
  vtkNew<vtkTyndallErrorObserver> errors;
  vtkSmartPointer<vtkAlgorithm> reader;
  if (xml)
  {
    auto xmlReader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xmlReader->SetFileName(this->FileName);
    xmlReader->SetParserErrorObserver(errors); // the XML parser's own errors
    xmlReader->SetReaderErrorObserver(errors);
    reader = xmlReader;
  }
  else
  {
    auto legacyReader = vtkSmartPointer<vtkPolyDataReader>::New();
    legacyReader->SetFileName(this->FileName);
    reader = legacyReader;
  }
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  reader->Update();
  vtkPolyData* data = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (errors->HasErrors() || !data || !data->GetPoints())
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " is not readable polydata"
                  << (errors->HasErrors() ? " (" + errors->GetMessages().front() + ")"
                                          : std::string())
                  << ".");
    return false;
  }
  vtkDataArray* radius = PointArray(data, this->RadiusArrayName, 1);
  vtkDataArray* density = PointArray(data, this->DensityArrayName, 1);
  if (!radius || !density)
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " has no one-component point array '"
                  << (radius ? this->DensityArrayName : this->RadiusArrayName)
                  << "' (RadiusArrayName / DensityArrayName).");
    return false;
  }
  const vtkIdType n = data->GetNumberOfPoints();
  if (n > MaximumNumberOfParticles)
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " holds more than "
                  << MaximumNumberOfParticles << " particles.");
    return false;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(data->GetPoints());
  auto copy = [n](vtkDataArray* from, const char* name)
  {
    vtkNew<vtkDoubleArray> to;
    to->SetName(name);
    to->SetNumberOfComponents(from->GetNumberOfComponents());
    to->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < from->GetNumberOfComponents(); ++c)
      {
        to->SetComponent(i, c, from->GetComponent(i, c));
      }
    }
    return vtkSmartPointer<vtkDoubleArray>(to.Get());
  };
  output->SetPoints(points);
  output->GetPointData()->AddArray(copy(radius, "radius"));
  output->GetPointData()->AddArray(copy(density, "density"));
  if (vtkDataArray* color = PointArray(data, this->ColorArrayName, 3))
  {
    output->GetPointData()->AddArray(copy(color, "color"));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleFileReader::Validate(vtkPolyData* output)
{
  const vtkIdType n = output->GetNumberOfPoints();
  if (n == 0)
  {
    vtkErrorMacro(<< "Particle file " << this->FileName << " holds no particles.");
    return false;
  }
  vtkDataArray* radius = output->GetPointData()->GetArray("radius");
  vtkDataArray* density = output->GetPointData()->GetArray("density");
  vtkDataArray* color = output->GetPointData()->GetArray("color");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    output->GetPoint(i, x);
    const double r = radius->GetComponent(i, 0), rho = density->GetComponent(i, 0);
    const char* problem = nullptr;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      problem = "a coordinate that is not finite";
    }
    else if (!std::isfinite(r) || !(r > 0.0))
    {
      problem = "a radius that is not a finite number > 0";
    }
    else if (!std::isfinite(rho) || !(rho >= 0.0))
    {
      problem = "a density that is not a finite number >= 0";
    }
    for (int c = 0; !problem && color && c < 3; ++c)
    {
      const double v = color->GetComponent(i, c);
      problem = v >= 0.0 && v <= 1.0 ? nullptr : "a colour component outside [0, 1]";
    }
    if (problem)
    {
      vtkErrorMacro(<< "Particle file " << this->FileName << ": particle " << i << " has "
                    << problem << ".");
      return false;
    }
  }
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    connectivity->SetValue(i, i);
  }
  vertices->SetData(1, connectivity);
  output->SetVerts(vertices);
  return true;
}
