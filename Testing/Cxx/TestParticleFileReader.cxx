// vtkParticleFileReader: particle clouds from CSV (with and without a
// header or colours, commas or spaces), VTK XML and legacy polydata (named
// arrays, renamed arrays), the same particles from each; and bad files:
// missing, empty, ragged lines, words, NaN, a radius <= 0, a negative
// density, a colour out of range, a missing array, truncated polydata, an
// unknown extension: an error through VTK's error mechanism and an empty
// output, never a partial cloud.
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkParticleFileReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkTestErrorObserver.h"
#include "vtkXMLPolyDataWriter.h"

#include "TyndallTestCheck.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
using tyndall_test::Check;
const std::string Dir = "TestParticleFileReader";

// The three particles every good file holds: x y z radius density r g b.
const double Particles[3][8] = { { 0.0, 0.0, 0.0, 0.5, 2.0, 1.0, 0.5, 0.25 },
  { 1.5, -0.25, 3.0, 0.125, 0.0, 0.0, 0.0, 0.0 }, { -2.0, 1.0, 0.5, 1.0, 7.5, 0.2, 0.4, 0.6 } };

std::string Write(const std::string& name, const std::string& text)
{
  const std::string path = Dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

vtkPolyData* Read(vtkParticleFileReader* reader, const std::string& path)
{
  reader->SetFileName(path.c_str());
  reader->Modified();
  reader->Update();
  return reader->GetOutput();
}

// Whether `data` holds the three particles (colours when `colors`).
bool Holds(vtkPolyData* data, bool colors)
{
  vtkDataArray* radius = data->GetPointData()->GetArray("radius");
  vtkDataArray* density = data->GetPointData()->GetArray("density");
  vtkDataArray* color = data->GetPointData()->GetArray("color");
  if (data->GetNumberOfPoints() != 3 || data->GetNumberOfVerts() != 3 || !radius || !density ||
    (color != nullptr) != colors)
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    bool same = x[0] == Particles[i][0] && x[1] == Particles[i][1] && x[2] == Particles[i][2] &&
      radius->GetComponent(i, 0) == Particles[i][3] &&
      density->GetComponent(i, 0) == Particles[i][4];
    for (int c = 0; colors && c < 3; ++c)
    {
      same = same && color->GetComponent(i, c) == Particles[i][5 + c];
    }
    if (!same)
    {
      return false;
    }
  }
  return true;
}

std::string Csv(const std::string& separator, bool colors, const std::string& header)
{
  std::ostringstream s;
  s.precision(17);
  s << header;
  for (const auto& p : Particles)
  {
    for (int k = 0; k < (colors ? 8 : 5); ++k)
    {
      s << (k ? separator : "") << p[k];
    }
    s << "\n";
  }
  return s.str();
}

vtkSmartPointer<vtkPolyData> Cloud(const char* radiusName, bool floats)
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkSmartPointer<vtkDataArray> radius, density;
  radius.TakeReference(floats ? static_cast<vtkDataArray*>(vtkFloatArray::New())
                              : static_cast<vtkDataArray*>(vtkDoubleArray::New()));
  density.TakeReference(vtkDoubleArray::New());
  vtkNew<vtkDoubleArray> color;
  color->SetNumberOfComponents(3);
  radius->SetName(radiusName);
  density->SetName("density");
  color->SetName("color");
  for (const auto& p : Particles)
  {
    points->InsertNextPoint(p[0], p[1], p[2]);
    radius->InsertNextTuple1(p[3]);
    density->InsertNextTuple1(p[4]);
    color->InsertNextTuple3(p[5], p[6], p[7]);
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(radius);
  data->GetPointData()->AddArray(density);
  data->GetPointData()->AddArray(color);
  return data;
}

void Good()
{
  vtkNew<vtkParticleFileReader> reader;
  Check(Holds(Read(reader, Write("plain.csv", Csv(",", false, ""))), false), "CSV x,y,z,r,rho");
  Check(
    Holds(Read(reader, Write("header.csv", Csv(", ", true, "x,y,z,radius,density,r,g,b\n"))), true),
    "CSV with a header and colours");
  Check(Holds(Read(reader, Write("spaces.txt", "# a comment\n\n" + Csv(" \t", false, ""))), false),
    "text separated by spaces and tabs, comments and empty lines skipped");
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(Cloud("radius", false));
    w->SetFileName((Dir + "/cloud.vtp").c_str());
    w->Write();
  }
  Check(Holds(Read(reader, Dir + "/cloud.vtp"), true), "VTK XML polydata");
  {
    vtkNew<vtkPolyDataWriter> w;
    w->SetInputData(Cloud("size", true));
    w->SetFileName((Dir + "/cloud.vtk").c_str());
    w->Write();
  }
  reader->SetRadiusArrayName("size");
  Check(Holds(Read(reader, Dir + "/cloud.vtk"), true), "legacy polydata, a renamed float array");
  Check(vtkParticleFileReader::CanReadExtension("a/B.CSV") &&
      !vtkParticleFileReader::CanReadExtension("a.vti") &&
      !vtkParticleFileReader::CanReadExtension(nullptr),
    "extensions");
}

// Reading `path` fails with an error containing `text`, and the output is empty.
void Bad(const std::string& path, const std::string& text, const char* radiusName = "radius")
{
  vtkNew<vtkParticleFileReader> reader;
  reader->SetRadiusArrayName(radiusName);
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkPolyData* out = Read(reader, path);
  const bool ok = errors->GetError() && errors->GetErrorMessage().find(text) != std::string::npos &&
    out->GetNumberOfPoints() == 0;
  if (!ok)
  {
    std::cerr << path << ": " << errors->GetErrorMessage() << "\n";
  }
  Check(ok, path + ": an error naming '" + text + "' and no particles");
}

void BadFiles()
{
  Bad(Dir + "/missing.csv", "does not exist");
  Bad(Write("empty.csv", "# nothing\n"), "holds no particles");
  Bad(Write("header-only.csv", "x,y,z,radius,density\n"), "holds no particles");
  Bad(Write("ragged.csv", "0 0 0 1 1\n0 0 0 1\n"), "line 2");
  Bad(Write("mixed.csv", "0 0 0 1 1\n0 0 0 1 1 0.5 0.5 0.5\n"), "line 2: expected 5 numbers");
  Bad(Write("word.csv", "0 0 0 1 1\n0 0 zero 1 1\n"), "line 2");
  Bad(Write("nan.csv", "0 0 nan 1 1\n"), "particle 0 has a coordinate");
  Bad(Write("radius.csv", "0 0 0 1 1\n0 0 0 0 1\n"), "particle 1 has a radius");
  Bad(Write("density.csv", "0 0 0 1 -1\n"), "particle 0 has a density");
  Bad(Write("infinite.csv", "0 0 0 1e999 1\n"), "line 1");
  Bad(Write("color.csv", "0 0 0 1 1 0.5 1.5 0\n"), "colour component");
  Bad(Write("cloud.xyz", "0 0 0 1 1\n"), "unknown extension");
  Bad(Dir + "/cloud.vtp", "'size'", "size");
  std::string xml;
  {
    std::ifstream in(Dir + "/cloud.vtp");
    std::ostringstream s;
    s << in.rdbuf();
    xml = s.str();
  }
  Bad(Write("truncated.vtp", xml.substr(0, xml.size() / 2)), "not readable polydata");
  Bad(Write("garbage.vtk", "# vtk DataFile Version 3.0\nnot really\nASCII\nDATASET NONSENSE\n"),
    "not readable polydata");
  vtkNew<vtkParticleFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  Check(errors->GetError(), "no file name: an error");
  std::ostringstream os;
  reader->Print(os);
  Check(os.str().find("RadiusArrayName: radius") != std::string::npos, "PrintSelf");
}
}

int TestParticleFileReader(int, char*[])
{
  vtksys::SystemTools::MakeDirectory(Dir);
  Good();
  BadFiles();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
