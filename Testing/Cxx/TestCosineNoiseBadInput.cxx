// Bad input to vtkCosineNoise and vtkCosineNoiseSource: each case reports a
// clear error through VTK's error mechanism and gives a defined result (an
// empty image, a zero integral, a status code), never a crash or NaN.
#include "TyndallTestCheck.h"
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"

#include <cmath>
#include <iostream>
#include <limits>

namespace
{
using tyndall_test::Check;

// Expects exactly one error containing `text` since the last call.
void ExpectError(vtkTest::ErrorObserver* observer, const std::string& text, const std::string& what)
{
  const bool ok =
    observer->GetError() && observer->GetErrorMessage().find(text) != std::string::npos;
  if (!ok)
  {
    std::cerr << "expected an error containing '" << text << "', got '"
              << (observer->GetError() ? observer->GetErrorMessage() : std::string("none")) << "'"
              << std::endl;
  }
  Check(ok, what);
  observer->Clear();
}

// Updates the source and checks for an error and an empty image.
void ExpectEmptyOutput(vtkCosineNoiseSource* source, vtkTest::ErrorObserver* observer,
  vtkTest::ErrorObserver* executiveObserver, const std::string& text, const std::string& what)
{
  source->Modified();
  source->Update();
  ExpectError(observer, text, what + " (error)");
  executiveObserver->Clear();
  vtkImageData* out = source->GetOutput();
  Check(out->GetNumberOfPoints() == 0 && out->GetPointData()->GetScalars() == nullptr,
    what + " (empty output)");
}
}

int TestCosineNoiseBadInput(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkTest::ErrorObserver> observer;

  // The noise.
  vtkNew<vtkCosineNoise> noise;
  noise->AddObserver(vtkCommand::ErrorEvent, observer);
  noise->SetNumberOfDirections(0);
  ExpectError(observer, "NumberOfDirections", "zero directions is an error");
  Check(noise->GetNumberOfDirections() == 1, "zero directions clamps to 1");
  noise->SetNumberOfOctaves(0);
  ExpectError(observer, "NumberOfOctaves", "zero octaves is an error");
  Check(noise->GetNumberOfOctaves() == 1, "zero octaves clamps to 1");
  noise->SetNumberOfOctaves(100);
  ExpectError(observer, "NumberOfOctaves", "too many octaves is an error");
  Check(noise->GetNumberOfOctaves() == 16, "too many octaves clamps to 16");

  vtkNew<vtkDoubleArray> noDirections;
  noDirections->SetNumberOfComponents(3);
  noise->SetCustomDirections(noDirections);
  ExpectError(observer, "Custom directions", "an empty direction array is refused");
  Check(noise->GetCustomDirections() == nullptr, "the refused array is not kept");
  vtkNew<vtkDoubleArray> twoComponents;
  twoComponents->SetNumberOfComponents(2);
  twoComponents->InsertNextTuple2(1.0, 0.0);
  noise->SetCustomDirections(twoComponents);
  ExpectError(observer, "Custom directions", "a 2-component direction array is refused");

  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double nanDir[3] = { nan, 1.0, 0.0 };
  const double dir[3] = { 1.0, 0.0, 0.0 };
  Check(noise->ComputeIntegral(origin, zero, 0.0, 1.0) == 0.0, "zero direction integrates to 0");
  ExpectError(observer, "zero vector", "a zero ray direction is an error");
  Check(noise->ComputeOpticalDepth(origin, nanDir, 0.0, 1.0) == 0.0, "NaN direction gives 0");
  ExpectError(observer, "finite", "a NaN ray direction is an error");
  Check(noise->ComputeTransmittance(origin, dir, 0.0, nan) == 1.0, "NaN t1 gives T = 1");
  ExpectError(observer, "finite", "a NaN ray parameter is an error");
  Check(noise->ComputeOpticalDepth(origin, dir, 1.0, 0.0) == 0.0, "t1 < t0 gives depth 0");
  ExpectError(observer, "t1", "t1 < t0 is an error for the optical depth");
  double t = 123.0;
  Check(noise->SampleDistance(origin, zero, 0.0, 1.0, 0.5, t) == -1 && t == 0.0,
    "SampleDistance with a zero direction returns -1, t = t0");
  ExpectError(observer, "zero vector", "SampleDistance reports the zero direction");
  Check(noise->SampleDistance(origin, dir, 0.0, 1.0, nan, t) == -1, "NaN target returns -1");
  ExpectError(observer, "target", "SampleDistance reports a NaN target");
  Check(noise->SampleDistance(origin, dir, 0.0, 1.0, -1.0, t) == -1, "negative target returns -1");
  ExpectError(observer, "target", "SampleDistance reports a negative target");
  double k[3], phase, amplitude;
  Check(!noise->GetWave(-1, k, phase, amplitude), "GetWave(-1) fails");
  ExpectError(observer, "out of range", "GetWave reports a bad index");
  Check(!observer->GetError(), "no stray errors");

  // The source.
  vtkNew<vtkCosineNoiseSource> source;
  vtkNew<vtkTest::ErrorObserver> executiveObserver;
  source->AddObserver(vtkCommand::ErrorEvent, observer);
  source->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveObserver);
  source->SetWholeExtent(0, 10, 0, -1, 0, 10);
  ExpectEmptyOutput(source, observer, executiveObserver, "empty or inverted", "inverted extent");
  source->SetWholeExtent(5, 4, 0, 3, 0, 3);
  ExpectEmptyOutput(source, observer, executiveObserver, "empty or inverted", "empty extent");
  source->SetWholeExtent(0, 7, 0, 7, 0, 7);
  source->SetSpacing(0.1, 0.0, 0.1);
  ExpectEmptyOutput(source, observer, executiveObserver, "spacing", "zero spacing");
  source->SetSpacing(0.1, -0.1, 0.1);
  ExpectEmptyOutput(source, observer, executiveObserver, "spacing", "negative spacing");
  source->SetSpacing(0.1, nan, 0.1);
  ExpectEmptyOutput(source, observer, executiveObserver, "spacing", "NaN spacing");
  source->SetSpacing(0.1, 0.1, 0.1);
  source->SetOrigin(nan, 0.0, 0.0);
  ExpectEmptyOutput(source, observer, executiveObserver, "origin", "NaN origin");
  source->SetOrigin(0.0, 0.0, 0.0);
  source->SetEnvelopeRadii(1.0, 0.0, 1.0);
  ExpectEmptyOutput(source, observer, executiveObserver, "radii", "zero ellipsoid radius");
  source->SetEnvelopeRadii(1.0, 1.0, 1.0);
  source->SetWholeExtent(0, 1999999, 0, 1999999, 0, 1999999);
  ExpectEmptyOutput(source, observer, executiveObserver, "Cannot allocate", "huge extent");
  source->SetNoise(nullptr);
  ExpectError(observer, "cannot be null", "a null noise is refused");
  Check(source->GetNoise() != nullptr, "the noise stays set");

  // After all that, a valid request works again.
  source->SetWholeExtent(0, 7, 0, 7, 0, 7);
  source->Update();
  Check(!observer->GetError() && source->GetOutput()->GetNumberOfPoints() == 512,
    "a valid request after bad ones produces the image");
  double range[2];
  source->GetOutput()->GetPointData()->GetScalars()->GetRange(range);
  Check(std::isfinite(range[0]) && std::isfinite(range[1]), "finite values");

  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
