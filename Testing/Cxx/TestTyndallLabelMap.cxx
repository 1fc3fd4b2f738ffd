// A label-map mask's classification (vtkTyndallLabelMap, issue 36) on the
// CPU, against VTK 9.1's rules written out here:
//
// 1. the labels: the mask's values rounded, 0 or less label 0, at most 255;
//    a NaN refused;
// 2. the rows: label L's own functions, the property's where L has none,
//    tabulated as VTK's label table (1024 entries over the range, read at
//    the entry the scalar falls in); a label above the largest with a
//    function reads the last row;
// 3. the mix: label 0 and a blend factor of 0 leave the volume; f = 1 the
//    label's opacity per VTK's step as an extinction; between, VTK's
//    (1 - f) (rgb, a) + f (rgb_L, a_L), the volume's colour 0 where its
//    opacity is 0;
// 4. the bound (what empty-space skipping reads) is at least every mix at
//    scalars between the table's entries, at a density other than 1.
//
// Costs under 0.1 s.
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTyndallLabelMap.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
using tyndall_test::Check;

bool Near(double a, double b, double tolerance = 1e-6)
{
  return std::abs(a - b) <= tolerance;
}
}

int TestTyndallLabelMap(int, char*[])
{
  // 1. The labels.
  vtkNew<vtkDoubleArray> values;
  for (const double v : { -3.0, 0.0, 0.4, 0.6, 1.0, 2.49, 2.51, 300.0 })
  {
    values->InsertNextValue(v);
  }
  vtkTyndallLabelMap map;
  std::ostringstream error;
  Check(map.ReadLabels(values, values->GetNumberOfTuples(), error), "labels read");
  const int expected[] = { 0, 0, 0, 1, 1, 2, 3, 255 };
  bool labels = true;
  for (int i = 0; i < 8; ++i)
  {
    labels = labels && map.LabelAt(i) == expected[i];
  }
  Check(labels, "each value rounded to a label in [0, 255]");
  values->SetValue(2, std::numeric_limits<double>::quiet_NaN());
  Check(!map.ReadLabels(values, values->GetNumberOfTuples(), error) &&
      error.str().find("finite") != std::string::npos,
    "a NaN label refused with a message");

  // 2. The rows: the volume's functions, label 1's own, label 3 none (reads
  // the volume's), over [0, 100].
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
  color->AddRGBPoint(100.0, 0.0, 0.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(100.0, 0.5);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkColorTransferFunction> green;
  green->AddRGBPoint(0.0, 0.0, 1.0, 0.0);
  green->AddRGBPoint(100.0, 0.0, 1.0, 0.0);
  vtkNew<vtkPiecewiseFunction> flat;
  flat->AddPoint(0.0, 0.2);
  flat->AddPoint(100.0, 0.2);
  property->SetLabelColor(1, green);
  property->SetLabelScalarOpacity(1, flat);
  vtkNew<vtkPiecewiseFunction> rising;
  rising->AddPoint(0.0, 0.0);
  rising->AddPoint(100.0, 0.8);
  property->SetLabelScalarOpacity(3, rising);
  const double step = 0.5, density = 2.0;
  map.Tabulate(property, 0.0, 100.0, 1.0, step);
  values->SetValue(2, 0.0);
  map.ReadLabels(values, values->GetNumberOfTuples(), error);
  Check(map.Enabled() && map.GetRowCount() == 3, "rows up to the largest label with a function");
  Check(vtkTyndallLabelMap::Entry(0.0) == 0 && vtkTyndallLabelMap::Entry(0.5) == 512 &&
      vtkTyndallLabelMap::Entry(1.0) == 1023 && vtkTyndallLabelMap::Entry(-1.0) == 0,
    "the entry the scalar falls in, clamped");

  // 3. The mix at the scalar 50 (entry 512, u = 50.05 in VTK's table).
  const int entry = vtkTyndallLabelMap::Entry(0.5);
  const double u = entry * 100.0 / 1023.0; // the table's sample there
  const double sigma = 0.3;                // the volume's extinction, density applied
  const double rgbIn[3] = { 0.5, 0.0, 0.5 };
  double rgb[3] = { rgbIn[0], rgbIn[1], rgbIn[2] };
  Check(
    map.Mix(0, entry, sigma, density, rgb) == sigma && rgb[0] == 0.5, "label 0 keeps the volume");
  // f = 1, label 1: its flat opacity 0.2 per step 0.5, density 2; green.
  double mixed = map.Mix(1, entry, sigma, density, rgb);
  Check(
    Near(mixed, density * -std::log(1.0 - 0.2) / step) && Near(rgb[1], 1.0) && Near(rgb[0], 0.0),
    "f = 1: the label's opacity per VTK's step, its colour");
  // Label 2 (no function): the volume's opacity function as a per-step
  // opacity, the volume's colour; label 255 reads row 3 (label 3's rising
  // opacity, the volume's colour).
  std::copy(rgbIn, rgbIn + 3, rgb);
  mixed = map.Mix(2, entry, sigma, density, rgb);
  const double own2 = opacity->GetValue(u);
  Check(Near(mixed, density * -std::log(1.0 - own2) / step, 1e-5) && Near(rgb[0], 0.5, 1e-3) &&
      Near(rgb[2], 0.5, 1e-3),
    "a label without functions reads the volume's");
  std::copy(rgbIn, rgbIn + 3, rgb);
  mixed = map.Mix(255, entry, sigma, density, rgb);
  Check(Near(mixed, density * -std::log(1.0 - rising->GetValue(u)) / step, 1e-5),
    "a label above the last row reads the last row");
  // f = 0.5: VTK's mix of (rgb, a) at its step.
  map.Tabulate(property, 0.0, 100.0, 0.5, step);
  std::copy(rgbIn, rgbIn + 3, rgb);
  mixed = map.Mix(1, entry, sigma, density, rgb);
  const double own = 1.0 - std::exp(-sigma / density * step);
  const double alpha = 0.5 * own + 0.5 * 0.2;
  Check(Near(mixed, density * -std::log(1.0 - alpha) / step) && Near(rgb[0], 0.25) &&
      Near(rgb[1], 0.5) && Near(rgb[2], 0.25),
    "f = 0.5: (1 - f) (rgb, a) + f (rgb_L, a_L)");
  std::copy(rgbIn, rgbIn + 3, rgb);
  mixed = map.Mix(1, entry, 0.0, density, rgb);
  Check(
    Near(mixed, density * -std::log(1.0 - 0.1) / step) && Near(rgb[0], 0.0) && Near(rgb[1], 0.5),
    "the volume's colour is 0 where its opacity is");
  map.Tabulate(property, 0.0, 100.0, 0.0, step);
  Check(!map.Enabled(), "a blend factor of 0 draws no label");

  // 4. The bound over a table of 4096 entries, at density 3: at scalars
  // between the entries (the volume's extinction interpolated there), every
  // label's mix is at most the bound of both entries around it (what the
  // majorant grid's queries read).
  map.Tabulate(property, 0.0, 100.0, 0.7, step);
  const double density3 = 3.0;
  std::vector<double> extinction(4096);
  for (size_t k = 0; k < extinction.size(); ++k)
  {
    extinction[k] = 0.5 * k / 4095.0 + 0.2 * std::sin(0.01 * k) * std::sin(0.01 * k); // density 1
  }
  const std::vector<double> bound = map.Bound(extinction);
  bool bounded = true;
  for (int i = 0; i < 40000 && bounded; ++i)
  {
    const double uu = (i + 0.37) / 40000.0;
    const double x = uu * 4095.0;
    const size_t k0 = static_cast<size_t>(x), k1 = std::min(k0 + 1, extinction.size() - 1);
    const double own3 = density3 * (extinction[k0] + (x - k0) * (extinction[k1] - extinction[k0]));
    const int e = vtkTyndallLabelMap::Entry(uu);
    for (int label = 0; label <= 3; ++label)
    {
      double c[3] = { 0.0, 0.0, 0.0 };
      const double mix = map.Mix(label, e, own3, density3, c);
      bounded = bounded && mix <= density3 * std::min(bound[k0], bound[k1]) * (1 + 1e-9);
    }
  }
  Check(bounded, "the bound is at least every label's mix");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
