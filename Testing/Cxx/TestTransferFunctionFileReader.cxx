// vtkTransferFunctionFileReader: a file with every keyword (comments, blank
// lines, colour spelt both ways) read and applied to a
// vtkParticipatingMediumProperty (emission included), and each malformed
// line reported with its file and line number, leaving nothing applied.
#include "TyndallTestCheck.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransferFunctionFileReader.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

std::string Write(const std::string& name, const std::string& text)
{
  const std::string path = "TestTransferFunctionFileReader-" + name + ".tf";
  std::ofstream(path) << text;
  return path;
}
}

int TestTransferFunctionFileReader(int, char*[])
{
  vtkNew<vtkTransferFunctionFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);

  const std::string good = Write("good",
    "# a smoke\n"
    "opacity 0 0\n"
    "opacity 10 0.5   # half\n"
    "\n"
    "color 0 0.2 0.3 0.4\n"
    "colour 10 1 1 1\n"
    "emission 5 2 1 0.5\n"
    "unit-distance 0.25\n");
  reader->SetFileName(good.c_str());
  Check(reader->Read() && !errors->GetError(), "a good file reads");
  Check(std::abs(reader->GetScalarOpacity()->GetValue(5.0) - 0.25) < 1e-12, "opacity points");
  double rgb[3];
  reader->GetColor()->GetColor(0.0, rgb);
  Check(std::abs(rgb[1] - 0.3) < 1e-12, "color points ('color' and 'colour')");
  Check(reader->GetHasEmission() && reader->GetUnitDistance() == 0.25, "emission, unit distance");
  vtkNew<vtkParticipatingMediumProperty> property;
  Check(reader->Apply(property), "Apply");
  Check(property->GetScalarOpacityUnitDistance() == 0.25 && property->GetEmissionColor() &&
      std::abs(property->GetScalarOpacity()->GetValue(10.0) - 0.5) < 1e-12,
    "the property gets the opacity, colour, unit distance and emission");

  // Without color lines: white.
  reader->SetFileName(Write("white", "opacity 0 0.1\n").c_str());
  Check(reader->Read(), "opacity only");
  reader->GetColor()->GetColor(3.0, rgb);
  Check(rgb[0] == 1.0 && rgb[1] == 1.0 && rgb[2] == 1.0 && !reader->GetHasEmission(),
    "no color lines: white, no emission");

  struct Bad
  {
    const char* Name;
    const char* Text;
    const char* Message;
  };
  const Bad bad[] = {
    { "keyword", "opacity 0 0\nalbedo 1 1 1 1\n", ":2: unknown keyword 'albedo'" },
    { "count", "opacity 0 0 0\n", ":1: expected 'opacity <value> <alpha>' (2 numbers), got 3" },
    { "number", "opacity 0 0.x\n", ":1: '0.x' is not a finite number" },
    { "nan", "opacity nan 0.5\n", "'nan' is not a finite number" },
    { "alpha", "opacity 0 1.5\n", ":1: alpha must be in [0, 1], got 1.5" },
    { "colour", "opacity 0 1\ncolor 0 1 2 0\n", ":2: colour components must be in [0, 1]" },
    { "emission", "opacity 0 1\nemission 0 1 -1 0\n", "emission components must be >= 0" },
    { "unit", "opacity 0 1\nunit-distance 0\n", "unit-distance must be > 0" },
    { "twice", "opacity 0 1\nunit-distance 1\nunit-distance 2\n", "unit-distance given twice" },
    { "empty", "# nothing\ncolor 0 1 1 1\n", "no 'opacity <value> <alpha>' line" },
  };
  for (const Bad& b : bad)
  {
    errors->Clear();
    const std::string path = Write(b.Name, b.Text);
    reader->SetFileName(path.c_str());
    const bool read = reader->Read();
    const std::string message = errors->GetErrorMessage();
    Check(!read && errors->GetError() && message.find(b.Message) != std::string::npos &&
        message.find(path) != std::string::npos,
      std::string("a bad file (") + b.Name + ") is refused with '" + b.Message + "', got '" +
        message + "'");
    Check(
      !reader->Apply(property), std::string("nothing to apply after a bad file (") + b.Name + ")");
  }
  errors->Clear();
  reader->SetFileName("no-such-file.tf");
  Check(!reader->Read() &&
      errors->GetErrorMessage().find("no-such-file.tf: cannot open") != std::string::npos,
    "a missing file");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
