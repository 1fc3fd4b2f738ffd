// VTK's isosurface blend mode as Tyndall reads it (vtkTyndallIsosurfaces and
// vtkTyndallGridMedium, the CPU twins of the shaders'): the iso values
// sorted; a step crossing exactly the values one end lies below (a sample
// landing on a value counts once over the two steps it ends and starts);
// the surfaces of one step composited front to back in the order the ray
// meets them (rising and falling values differ); the light's optical depth
// -ln(1 - a) per surface crossed, the same at any step; the camera step's
// extinction and colour; bad values refused with an error. Exact math
// against closed forms (no render window).
//
// Cost: well under a second.
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContourValues.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallIsosurfaces.h"
#include "vtkTyndallTransferTable.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

namespace
{
using tyndall_test::Check;

bool Near(double a, double b, double tolerance = 1e-12)
{
  return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
}

// Opacity a(s) = s / 100 over [0, 100]; colour (s / 100, 1 - s / 100, 0.5);
// linear interpolation.
void MakeProperty(vtkVolumeProperty* property)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(100.0, 1.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 1.0, 0.5);
  color->AddRGBPoint(100.0, 1.0, 0.0, 0.5);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
}

void TestValues(vtkVolumeProperty* property, vtkVolumeMapper* mapper)
{
  vtkTyndallIsosurfaces iso;
  std::string error;
  mapper->SetBlendModeToComposite();
  Check(iso.Read(mapper, property, error) && !iso.Enabled(), "composite: no isosurfaces");
  mapper->SetBlendModeToIsoSurface();
  property->GetIsoSurfaceValues()->SetValue(0, 70.0);
  property->GetIsoSurfaceValues()->SetValue(1, 20.0);
  property->GetIsoSurfaceValues()->SetValue(2, 50.0);
  Check(iso.Read(mapper, property, error) && iso.Enabled(), "isosurface blend mode read");
  Check(iso.GetValues() == std::vector<double>({ 20.0, 50.0, 70.0 }), "values sorted");

  property->GetIsoSurfaceValues()->SetValue(1, std::numeric_limits<double>::quiet_NaN());
  Check(!iso.Read(mapper, property, error) && !iso.Enabled() &&
      error.find("not a finite number") != std::string::npos,
    "a NaN iso value is refused: " + error);
  property->GetIsoSurfaceValues()->SetValue(1, std::numeric_limits<double>::infinity());
  Check(!iso.Read(mapper, property, error), "an infinite iso value is refused");
  property->GetIsoSurfaceValues()->SetNumberOfContours(vtkTyndallIsosurfaces::MaximumCount + 1);
  Check(!iso.Read(mapper, property, error) && error.find("at most") != std::string::npos,
    "too many iso values are refused: " + error);
  property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  Check(iso.Read(mapper, property, error) && iso.Enabled() && iso.GetValues().empty(),
    "no iso value: enabled, nothing drawn");
}

void TestComposite(vtkVolumeProperty* property, vtkVolumeMapper* mapper)
{
  property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  property->GetIsoSurfaceValues()->SetValue(0, 70.0);
  property->GetIsoSurfaceValues()->SetValue(1, 20.0);
  property->GetIsoSurfaceValues()->SetValue(2, 50.0);
  mapper->SetBlendModeToIsoSurface();
  vtkTyndallIsosurfaces iso;
  std::string error;
  iso.Read(mapper, property, error);
  vtkTyndallTransferTable table;
  Check(table.Build(property, nullptr, 0.0, 100.0, error), "table built");

  // Rising from 10 to 60: 20 (a fifth of the way) then 50, front to back.
  double rgb[3], alpha, first;
  Check(
    iso.Composite(table, 10.0, 60.0, rgb, alpha, first) && Near(first, 0.2), "10 -> 60 crosses");
  const double a20 = 0.2, a50 = 0.5;
  const double c20[3] = { 0.2, 0.8, 0.5 }, c50[3] = { 0.5, 0.5, 0.5 };
  bool ok = Near(alpha, a20 + (1.0 - a20) * a50, 1e-6);
  for (int c = 0; c < 3; ++c)
  {
    ok = ok && Near(rgb[c], a20 * c20[c] + (1.0 - a20) * a50 * c50[c], 1e-6);
  }
  Check(ok, "rising: 20 in front of 50");
  // Falling from 60 to 10: 50 (a fifth of the way) then 20.
  Check(
    iso.Composite(table, 60.0, 10.0, rgb, alpha, first) && Near(first, 0.2), "60 -> 10 crosses");
  ok = Near(alpha, a50 + (1.0 - a50) * a20, 1e-6);
  for (int c = 0; c < 3; ++c)
  {
    ok = ok && Near(rgb[c], a50 * c50[c] + (1.0 - a50) * a20 * c20[c], 1e-6);
  }
  Check(ok, "falling: 50 in front of 20");
  Check(
    !iso.Composite(table, 25.0, 45.0, rgb, alpha, first) && alpha == 0.0, "25 -> 45 crosses none");
  // A sample landing on a value: crossed once over the two steps around it.
  double a1, a2;
  const bool before = iso.Composite(table, 10.0, 20.0, rgb, a1, first);
  const bool after = iso.Composite(table, 20.0, 30.0, rgb, a2, first);
  Check(before != after, "a sample on an iso value counts once");

  // The light: -ln(1 - a) per surface crossed.
  Check(Near(iso.OpticalDepth(table, 10.0, 60.0), -std::log(1.0 - a20) - std::log(1.0 - a50), 1e-6),
    "optical depth of 10 -> 60");
  Check(Near(iso.OpticalDepth(table, 60.0, 10.0), iso.OpticalDepth(table, 10.0, 60.0)),
    "optical depth the same both ways");
  property->GetIsoSurfaceValues()->SetValue(3, 100.0); // opacity 1
  iso.Read(mapper, property, error);
  const double opaque = iso.OpticalDepth(table, 90.0, 100.0);
  Check(std::isfinite(opaque) &&
      Near(opaque, -std::log(1.0 - vtkTyndallIsosurfaces::MaximumOpacity), 1e-9),
    "an opaque surface's depth is finite");
}

// A ramp along x (value 10 i at index i, 11 x 3 x 3 points) drawn as
// isosurfaces 20, 50 and 70: a ray along x crosses each once.
void TestGrid(vtkVolumeProperty* property)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(11, 3, 3);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfTuples(11 * 9);
  for (vtkIdType p = 0; p < 11 * 9; ++p)
  {
    scalars->SetValue(p, static_cast<float>(10 * (p % 11)));
  }
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetBlendModeToIsoSurface();
  property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  property->GetIsoSurfaceValues()->SetValue(0, 70.0);
  property->GetIsoSurfaceValues()->SetValue(1, 20.0);
  property->GetIsoSurfaceValues()->SetValue(2, 50.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkGPUVolumeRayCastMapper> reporter;
  reporter->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkTyndallGridMedium grid;
  Check(grid.Update(volume, reporter) && grid.GetIsosurfaces().Enabled(), "grid read");
  const double expected = -std::log(0.8) - std::log(0.5) - std::log(0.3);
  const double o[3] = { -1.0, 1.0, 1.0 }, d[3] = { 1.0, 0.0, 0.0 };
  for (double step : { 0.3, 1.0, 2.7, 11.0 })
  {
    std::ostringstream what;
    what << "optical depth through the ramp at step " << step;
    const double tau = grid.OpticalDepth(o, d, 0.0, 20.0, step, 1e30, true, nullptr, nullptr);
    Check(Near(tau, expected, 1e-5), what.str());
  }
  // Across the box's middle only 50 is crossed; along y nothing.
  const double oy[3] = { 4.5, -1.0, 1.0 }, dy[3] = { 0.0, 1.0, 0.0 };
  Check(grid.OpticalDepth(oy, dy, 0.0, 5.0, 0.5, 1e30, true, nullptr, nullptr) == 0.0,
    "no surface along y");
  Check(Near(grid.OpticalDepth(o, d, 5.5, 7.5, 0.5, 1e30, true, nullptr, nullptr), -std::log(0.5),
          1e-5),
    "only 50 between x = 4.5 and 6.5");

  // The camera's step from x = 4 to 6 crosses 50, halfway: extinction -ln(0.5) / dt.
  vtkTyndallMedium::Point point;
  const double p0[3] = { 4.0, 1.0, 1.0 }, p1[3] = { 6.0, 1.0, 1.0 };
  double first;
  Check(grid.IsoSample(p0, p1, 2.0, point, first) && Near(first, 0.5, 1e-5) &&
      Near(point.Extinction, -std::log(0.5) / 2.0, 1e-5) && Near(point.Albedo[0], 0.5, 1e-5) &&
      Near(point.Albedo[1], 0.5, 1e-5),
    "camera step crossing 50");
  const double q0[3] = { 2.5, 1.0, 1.0 }, q1[3] = { 4.5, 1.0, 1.0 };
  Check(!grid.IsoSample(q0, q1, 2.0, point, first), "camera step crossing nothing");

  // A NaN iso value: the update fails with an error.
  property->GetIsoSurfaceValues()->SetValue(1, std::numeric_limits<double>::quiet_NaN());
  errors->Clear();
  Check(!grid.Update(volume, reporter) && errors->GetError() &&
      errors->GetErrorMessage().find("isosurfaces") != std::string::npos,
    "a NaN iso value: an error, nothing drawn");
}
}

int TestTyndallIsosurfaces(int, char*[])
{
  vtkNew<vtkVolumeProperty> property;
  MakeProperty(property);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  TestValues(property, mapper);
  TestComposite(property, mapper);
  TestGrid(property);
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
