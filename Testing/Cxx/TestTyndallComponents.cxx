// Multi-component scalars (vtkTyndallComponents, vtkTyndallGridMedium;
// issue 36), on the CPU, against exact math:
//
// 1. the rules: 1 to 4 components, independent or dependent (2: colour and
//    opacity, 4: RGBA), 3 dependent and 5 refused, each table's function
//    and component;
// 2. the mixing: VTK's (sum sigma_i^2 / sum w_i sigma_i, colour sum w_i
//    sigma_i c_i / sigma) is the limit of VTK's own per-step compositing
//    (alpha sum a_i^2 / sum w_i a_i, premultiplied colour sum w_i a_i c_i)
//    through a slab, as the step shrinks; the additive mixture; the parts
//    (vtkTyndallComponents::Parts()) give the colour; the majorant bounds
//    the mixture;
// 3. the grid: each component interpolated on its own (linear fields: the
//    exact values), its own finite range, a NaN in any component is
//    missing data, the extinction is the mixture of the tables' at the
//    right components;
// 4. what several components are not drawn with: an error (the isosurface
//    blend mode but for independent ones whose first has the largest weight,
//    drawn as that component, as VTK 9.1 does; a 2-D transfer function; the
//    projections are drawn), or named (gradient opacity);
// 5. the majorant grid over several tables (what empty-space skipping
//    reads): each block's majorant bounds the mixture at every sample it
//    covers, for VTK's mixing and the additive one, and is 0 only where the
//    mixture is;
// 6. VTK 9.2's volumetric scattering weight (the blending's);
// 7. the projections of several components (vtkTyndallProjection::Ray)
//    against the rules worked by hand.
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTestErrorObserver.h"
#include "vtkTyndallComponents.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallMajorantGrid.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallShading.h"
#include "vtkTyndallTransferTable.h"
#include "vtkTyndallVolumeSettings.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;
constexpr int N = vtkTyndallComponents::MaximumCount;

void TestRules()
{
  vtkNew<vtkVolumeProperty> property;
  vtkTyndallComponents c;
  std::string error;
  Check(c.Read(property, 1, false, error) && !c.Enabled() && c.GetTableCount() == 1,
    "one component: the single classification");
  Check(property->GetIndependentComponents() && c.Read(property, 3, false, error) &&
      c.GetMode() == vtkTyndallComponents::Independent && c.GetTableCount() == 3 &&
      c.TableFunction(2) == 2 && c.TableComponent(2) == 2,
    "three independent components (VTK's default): a table each");
  Check(!c.Read(property, 5, false, error) && error.find("5 components") != std::string::npos &&
      !c.Enabled(),
    "five components: refused (" + error + ")");
  Check(!c.Read(property, 0, false, error), "no component: refused");
  property->IndependentComponentsOff();
  Check(c.Read(property, 2, false, error) && c.GetMode() == vtkTyndallComponents::DependentLA &&
      c.GetTableCount() == 2 && c.TableFunction(1) == 0 && c.TableComponent(1) == 1,
    "two dependent components: function 0 at components 0 and 1");
  Check(c.Read(property, 4, false, error) && c.GetMode() == vtkTyndallComponents::DependentRGBA &&
      c.GetTableCount() == 1 && c.TableComponent(0) == 3,
    "four dependent components: RGBA, the opacity at component 3");
  error.clear();
  Check(!c.Read(property, 3, false, error) && error.find("3 dependent") != std::string::npos,
    "three dependent components: refused");
  property->IndependentComponentsOn();
  Check(c.Read(property, 2, true, error) && c.GetAdditive(),
    "a participating medium's independent components add");
}

// VTK's compositing of independent components through a homogeneous slab
// of thickness L in steps dt (its step alpha and premultiplied colour):
// the transmittance and the colour.
void VTKSlab(const double sigma[N], const double color[N][3], const double w[N], int count,
  double L, double dt, double& T, double rgb[3])
{
  double a[N], alpha = 0.0, total = 0.0, premultiplied[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < count; ++i)
  {
    a[i] = 1.0 - std::exp(-sigma[i] * dt); // the table's opacity corrected for dt
    total += w[i] > 0.0 ? a[i] * w[i] : 0.0;
  }
  for (int i = 0; i < count; ++i)
  {
    if (w[i] > 0.0)
    {
      alpha += a[i] * a[i] / total;
      for (int c = 0; c < 3; ++c)
      {
        premultiplied[c] += color[i][c] * a[i] * w[i];
      }
    }
  }
  T = 1.0;
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  for (int n = 0; n < static_cast<int>(std::lround(L / dt)); ++n)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] += T * premultiplied[c];
    }
    T *= 1.0 - alpha;
  }
}

void TestMixing()
{
  vtkNew<vtkVolumeProperty> property;
  property->IndependentComponentsOn();
  const double weights[3] = { 1.0, 0.6, 0.3 };
  for (int i = 0; i < 3; ++i)
  {
    property->SetComponentWeight(i, weights[i]);
  }
  vtkTyndallComponents vtkMix, additive;
  std::string error;
  vtkMix.Read(property, 3, false, error);
  additive.Read(property, 3, true, error);
  const double sigma[N] = { 0.8, 0.3, 1.5, 0.0 };
  const double color[N][3] = { { 1.0, 0.2, 0.1 }, { 0.1, 0.9, 0.3 }, { 0.2, 0.3, 1.0 }, {} };
  const double unit[N] = { 0.0, 0.0, 0.0, 0.0 };
  double rgb[3], rgbAdd[3];
  const double s = vtkMix.Mix(sigma, color, unit, rgb);
  const double sAdd = additive.Mix(sigma, color, unit, rgbAdd);
  double squares = 0.0, weighted = 0.0, emission[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < 3; ++i)
  {
    squares += sigma[i] * sigma[i];
    weighted += weights[i] * sigma[i];
    for (int c = 0; c < 3; ++c)
    {
      emission[c] += weights[i] * sigma[i] * color[i][c];
    }
  }
  Check(std::abs(s - squares / weighted) < 1e-12, "VTK's mixture: sum sigma^2 / sum w sigma");
  Check(std::abs(sAdd - weighted) < 1e-12, "the additive mixture: sum w sigma");
  for (int c = 0; c < 3; ++c)
  {
    Check(std::abs(rgb[c] * s - emission[c]) < 1e-12 &&
        std::abs(rgbAdd[c] * sAdd - emission[c]) < 1e-12,
      "the colour per unit length: sum w sigma c, either mixture");
  }
  // VTK's own compositing converges to the mixture as its step shrinks.
  const double L = 1.5;
  double previous = 1.0;
  for (double dt : { 0.05, 0.005, 0.0005 })
  {
    double T, vtkRGB[3];
    VTKSlab(sigma, color, weights, 3, L, dt, T, vtkRGB);
    const double expectedT = std::exp(-s * L);
    double error2 = std::abs(T - expectedT);
    for (int c = 0; c < 3; ++c)
    {
      error2 = std::max(error2, std::abs(vtkRGB[c] - rgb[c] * (1.0 - expectedT)));
    }
    std::cout << "VTK's compositing at step " << dt << ": off by " << error2 << "\n";
    Check(error2 < 0.6 * previous,
      "VTK's compositing converges to the mixture (step " + std::to_string(dt) + ")");
    previous = error2;
  }
  Check(previous < 2e-4, "VTK's compositing at a small step is the mixture");
  // Parts: the colour is sum parts_i c_i.
  double parts[N];
  vtkMix.Parts(sigma, parts);
  for (int c = 0; c < 3; ++c)
  {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      sum += parts[i] * color[i][c];
    }
    Check(std::abs(sum - rgb[c]) < 1e-12, "the parts give the colour");
  }
  // A zero weight: the component is left out of both sums (VTK skips it).
  property->SetComponentWeight(1, 0.0);
  vtkMix.Read(property, 3, false, error);
  const double s0 = vtkMix.Mix(sigma, color, unit, rgb);
  Check(std::abs(s0 - (0.8 * 0.8 + 1.5 * 1.5) / (0.8 + 0.3 * 1.5)) < 1e-12,
    "a component of weight 0 is left out");
  // The majorant bounds the mixture over random samples under the bounds.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  const double bounds[N] = { 0.8, 0.3, 1.5, 0.0 };
  for (vtkTyndallComponents* m : { &vtkMix, &additive })
  {
    const double majorant = m->Majorant(bounds);
    bool below = true;
    for (int k = 0; k < 2000; ++k)
    {
      double x[N] = { 0.0, 0.0, 0.0, 0.0 };
      for (int i = 0; i < 3; ++i)
      {
        x[i] = bounds[i] * random->GetNextValue();
      }
      below = below && m->Mix(x, color, unit, rgb) <= majorant * (1.0 + 1e-12);
    }
    Check(below, "the majorant bounds the mixture");
  }
  // Dependent: LA reads table 1's extinction and table 0's colour; RGBA
  // the components on their ranges and table 0's extinction.
  property->IndependentComponentsOff();
  vtkTyndallComponents la, rgba;
  la.Read(property, 2, false, error);
  rgba.Read(property, 4, false, error);
  const double units[N] = { 0.25, 1.5, -0.5, 0.9 };
  Check(la.Mix(sigma, color, units, rgb) == sigma[1] && rgb[0] == color[0][0],
    "two dependent components: extinction of table 1, colour of table 0");
  Check(rgba.Mix(sigma, color, units, rgb) == sigma[0] && rgb[0] == 0.25 && rgb[1] == 1.0 &&
      rgb[2] == 0.0,
    "RGBA: the colour is the components on their ranges, clamped to [0, 1]");
}

// A 6^3 image of two components, linear in the index: c0 = i + 2j, c1 = 10 + 3k.
vtkSmartPointer<vtkImageData> MakeLinear()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(6, 6, 6);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfComponents(2);
  values->SetNumberOfTuples(216);
  for (int k = 0, n = 0; k < 6; ++k)
  {
    for (int j = 0; j < 6; ++j)
    {
      for (int i = 0; i < 6; ++i, ++n)
      {
        values->SetComponent(n, 0, i + 2.0 * j);
        values->SetComponent(n, 1, 10.0 + 3.0 * k);
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void TestGrid()
{
  vtkSmartPointer<vtkImageData> image = MakeLinear();
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkVolumeProperty> property;
  property->SetInterpolationTypeToLinear();
  property->IndependentComponentsOn();
  for (int c = 0; c < 2; ++c)
  {
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(c == 0 ? 0.0 : 10.0, 0.0);
    opacity->AddPoint(c == 0 ? 15.0 : 25.0, 0.5);
    property->SetScalarOpacity(c, opacity);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, c == 0 ? 1.0 : 0.0, 0.0, c == 1 ? 1.0 : 0.0);
    color->AddRGBPoint(30.0, c == 0 ? 1.0 : 0.0, 0.0, c == 1 ? 1.0 : 0.0);
    property->SetColor(c, color);
    property->SetScalarOpacityUnitDistance(c, 1.0 + c);
  }
  property->SetComponentWeight(1, 0.5);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkVolume> reporter;
  reporter->AddObserver(vtkCommand::ErrorEvent, observer);
  reporter->AddObserver(vtkCommand::WarningEvent, observer);
  vtkTyndallGridMedium grid;
  Check(grid.Update(volume, reporter) && !observer->GetError(), "two components: read");
  Check(grid.GetComponentRange(0)[0] == 0.0 && grid.GetComponentRange(0)[1] == 15.0 &&
      grid.GetComponentRange(1)[0] == 10.0 && grid.GetComponentRange(1)[1] == 25.0,
    "each component's own finite range");
  // Linear fields: trilinear interpolation is exact.
  const double p[3] = { 1.3, 2.6, 3.7 };
  double values[N];
  Check(grid.FieldComponents(p, values) && std::abs(values[0] - (1.3 + 5.2)) < 1e-12 &&
      std::abs(values[1] - (10.0 + 11.1)) < 1e-12,
    "each component interpolated on its own");
  // The extinction: VTK's mixture of each component's function at its value.
  auto sigma = [](double opacity, double unit) { return -std::log(1.0 - opacity) / unit; };
  const double s0 = sigma(0.5 * values[0] / 15.0, 1.0);
  const double s1 = sigma(0.5 * (values[1] - 10.0) / 15.0, 2.0);
  const double expected = (s0 * s0 + s1 * s1) / (s0 + 0.5 * s1);
  double world[4];
  const double index[4] = { p[0], p[1], p[2], 1.0 };
  for (int r = 0; r < 3; ++r)
  {
    world[r] = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      world[r] += grid.GetIndexToWorld()[4 * r + c] * index[c];
    }
  }
  const double got = grid.WorldExtinction(world);
  std::cout << "mixture at p: " << got << ", exact " << expected << "\n";
  Check(std::abs(got - expected) < 1e-3 * expected, "the extinction is the tables' mixture");
  Check(grid.GetMajorant() >= got, "the majorant bounds it");

  // A NaN in component 1 only: missing data where it is interpolated from.
  auto* array = vtkDoubleArray::SafeDownCast(image->GetPointData()->GetScalars());
  array->SetComponent(0, 1, std::numeric_limits<double>::quiet_NaN());
  array->Modified();
  image->Modified();
  Check(grid.Update(volume, reporter) && grid.GetNumberOfNaNScalars() == 1,
    "a NaN component: one missing sample");
  const double corner[3] = { 0.5, 0.5, 0.5 };
  Check(!grid.FieldComponents(corner, values), "interpolated from it: missing");
  array->SetComponent(0, 1, 10.0);
  image->Modified();

  // What several components are not drawn with.
  // (The projections are drawn: vtkTyndallProjection.)
  mapper->SetBlendModeToMaximumIntensity();
  Check(grid.Update(volume, reporter) &&
      grid.GetProjection().GetMode() == vtkTyndallProjection::MAXIMUM,
    "two components in the maximum intensity blend mode: read");
  observer->Clear();
  // Isosurfaces of independent components: VTK 9.1's are those of the
  // component of the largest weight, the first of equal ones: drawn as
  // that one component when it is component 0, else an error.
  mapper->SetBlendModeToIsoSurface();
  property->GetIsoSurfaceValues()->SetValue(0, 5.0);
  const bool independent = property->GetIndependentComponents() != 0;
  property->IndependentComponentsOn();
  Check(grid.Update(volume, reporter) && !grid.GetComponents().Enabled() &&
      grid.GetScalars()->GetNumberOfComponents() == 1 &&
      grid.GetScalars()->GetComponent(7, 0) == array->GetComponent(7, 0),
    "two independent components of equal weights in the isosurface blend mode: component 0's");
  property->SetComponentWeight(0, 0.25); // (below component 1's 0.5)
  Check(!grid.Update(volume, reporter) &&
      observer->GetErrorMessage().find("isosurface") != std::string::npos,
    "component 1 of the largest weight in the isosurface blend mode: an error");
  property->SetComponentWeight(0, 1.0);
  observer->Clear();
  property->IndependentComponentsOff();
  Check(!grid.Update(volume, reporter) &&
      observer->GetErrorMessage().find("isosurface") != std::string::npos,
    "two dependent components in the isosurface blend mode: an error");
  property->SetIndependentComponents(independent);
  property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  mapper->SetBlendModeToComposite();
  observer->Clear();
  vtkNew<vtkImageData> function;
  function->SetDimensions(4, 4, 1);
  function->AllocateScalars(VTK_FLOAT, 4);
  property->SetTransferFunction2D(function);
  property->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  Check(!grid.Update(volume, reporter) &&
      observer->GetErrorMessage().find("2-D transfer function") != std::string::npos,
    "two components with a 2-D transfer function: an error");
  property->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  Check(grid.Update(volume, reporter), "back to 1-D functions: read");
  vtkNew<vtkPiecewiseFunction> gradient;
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(5.0, 1.0);
  property->SetGradientOpacity(gradient);
  const std::string named =
    vtkTyndallVolumeSettings::Describe(vtkTyndallVolumeSettings::NotDrawn(volume));
  Check(named.find("gradient opacity with several components") != std::string::npos,
    "gradient opacity with several components: named (" + named + ")");
  Check(grid.Update(volume, reporter) && !grid.GetGradientOpacity(),
    "gradient opacity with several components: not applied");
}

void TestMajorants()
{
  const int dims[3] = { 20, 18, 17 };
  const int n = dims[0] * dims[1] * dims[2];
  std::vector<float> values(2 * static_cast<size_t>(n));
  for (int z = 0, i = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x, ++i)
      {
        // Component 0 above 12 only from x = 12 on, component 1 below 6 only
        // up to z = 2: the blocks of x < 8 from z = 8 on (3 x 2 of 3 x 3 x 3) are empty.
        values[2 * i] = static_cast<float>(x + 0.5 * std::sin(0.3 * y));
        values[2 * i + 1] = static_cast<float>(3.0 + z + 0.5 * std::cos(0.2 * x));
      }
    }
  }
  // Component 0 opaque at high values, component 1 at low ones (and empty
  // above 6): the blocks' majorants depend on both ranges.
  vtkNew<vtkVolumeProperty> property;
  property->IndependentComponentsOn();
  vtkNew<vtkPiecewiseFunction> rising, falling;
  rising->AddPoint(12.0, 0.0);
  rising->AddPoint(20.0, 0.8);
  falling->AddPoint(0.0, 0.5);
  falling->AddPoint(6.0, 0.0);
  property->SetScalarOpacity(0, rising);
  property->SetScalarOpacity(1, falling);
  property->SetComponentWeight(1, 0.4);
  vtkTyndallTransferTable tables[2];
  const vtkTyndallTransferTable* pointers[N] = { &tables[0], &tables[1], nullptr, nullptr };
  std::string error;
  const double ranges[2][2] = { { -0.5, 19.5 }, { 2.5, 19.5 } };
  for (int c = 0; c < 2; ++c)
  {
    Check(tables[c].Build(property, nullptr, ranges[c][0], ranges[c][1], error, false, c, c),
      "a component's table");
  }
  const double color[N][3] = {};
  const double unit[N] = { 0.0, 0.0, 0.0, 0.0 };
  for (bool additive : { false, true })
  {
    vtkTyndallComponents components;
    components.Read(property, 2, additive, error);
    vtkTyndallMajorantGrid grid;
    grid.BuildRanges(values.data(), 2, nullptr, dims);
    grid.BuildMajorants(pointers, components);
    const int* counts = grid.GetBlockCounts();
    const std::vector<float>& majorants = grid.GetMajorants();
    bool bounded = true, emptyExact = true;
    std::vector<double> largest(majorants.size(), 0.0);
    for (int z = 0, i = 0; z < dims[2]; ++z)
    {
      for (int y = 0; y < dims[1]; ++y)
      {
        for (int x = 0; x < dims[0]; ++x, ++i)
        {
          double sigma[N] = { 0.0, 0.0, 0.0, 0.0 }, rgb[3];
          for (int c = 0; c < 2; ++c)
          {
            int k;
            double f;
            tables[c].Locate(values[2 * i + c], k, f);
            sigma[c] = tables[c].ExtinctionAt(k, f);
          }
          const double mixture = components.Mix(sigma, color, unit, rgb);
          const size_t block =
            (static_cast<size_t>(z / vtkTyndallMajorantGrid::BlockSize) * counts[1] +
              static_cast<size_t>(y / vtkTyndallMajorantGrid::BlockSize)) *
              counts[0] +
            static_cast<size_t>(x / vtkTyndallMajorantGrid::BlockSize);
          bounded = bounded && mixture <= majorants[block] * (1.0 + 1e-6) + 1e-12;
          largest[block] = std::max(largest[block], mixture);
        }
      }
    }
    int empty = 0;
    for (size_t b = 0; b < majorants.size(); ++b)
    {
      empty += majorants[b] == 0.0f ? 1 : 0;
      emptyExact = emptyExact && (majorants[b] > 0.0f || largest[b] == 0.0);
    }
    const std::string mixing = additive ? "additive" : "VTK's";
    std::cout << mixing << " mixing: " << majorants.size() << " blocks, " << empty << " empty\n";
    Check(bounded, mixing + " mixing: each block's majorant bounds the mixture at its samples");
    Check(empty == 6, mixing + " mixing: the six blocks where both components are empty");
    Check(emptyExact, mixing + " mixing: a block is empty only where the mixture is 0");
  }
}

// VTK 9.2's volumetric scattering weight (vtkTyndallShading::Weight()): 0
// for b = 0, b exp(-b G a) below 1, exp(-G a) at 1 (its "smart" blend), 1
// (volumetric only) at 2, continuous at 1.
void TestBlendWeight()
{
  const double G = 0.8, a = 0.4;
  auto near = [](double x, double y) { return std::abs(x - y) < 1e-12; };
  Check(vtkTyndallShading::Weight(0.0, G, a) == 0.0, "blending 0: surface only");
  Check(near(vtkTyndallShading::Weight(0.5, G, a), 0.5 * std::exp(-0.5 * G * a)),
    "blending 0.5: b exp(-b G a)");
  Check(near(vtkTyndallShading::Weight(1.0, G, a), std::exp(-G * a)),
    "blending 1: VTK's smart blend exp(-G a)");
  Check(near(vtkTyndallShading::Weight(2.0, G, a), 1.0), "blending 2: volumetric only");
  Check(near(vtkTyndallShading::Weight(1.0 - 1e-9, G, a), vtkTyndallShading::Weight(1.0, G, a)) ||
      std::abs(vtkTyndallShading::Weight(1.0 - 1e-9, G, a) - vtkTyndallShading::Weight(1.0, G, a)) <
        1e-8,
    "continuous at 1");
  Check(near(vtkTyndallShading::Weight(1.5, 0.0, a), 1.0), "no gradient: volumetric for b >= 1");
}

// The projections of several components (vtkTyndallProjection::Ray, the CPU
// twin of the shader's) against the rules worked by hand: component 0's
// opacity function 0.05 v (red), component 1's 0.2 (green), both over
// [0, 10], weights 1 and 0.5, unit distances 1 and 2; three samples.
void TestProjections()
{
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkPiecewiseFunction> ramp, flat;
  ramp->AddPoint(0.0, 0.0);
  ramp->AddPoint(10.0, 0.5);
  flat->AddPoint(0.0, 0.2);
  flat->AddPoint(10.0, 0.2);
  vtkNew<vtkColorTransferFunction> red, green;
  red->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
  red->AddRGBPoint(10.0, 1.0, 0.0, 0.0);
  green->AddRGBPoint(0.0, 0.0, 1.0, 0.0);
  green->AddRGBPoint(10.0, 0.0, 1.0, 0.0);
  property->SetScalarOpacity(0, ramp);
  property->SetScalarOpacity(1, flat);
  property->SetColor(0, red);
  property->SetColor(1, green);
  property->SetComponentWeight(1, 0.5);
  property->SetScalarOpacityUnitDistance(1, 2.0);
  const double range[2] = { 0.0, 10.0 };
  const double samples[3][N] = { { 2.0, 5.0 }, { 7.0, 1.0 }, { 4.0, 8.0 } };
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetAverageIPScalarRange(1.5, 6.0);
  // Draws the three samples (steps of 0.5) in `mode` with the tables and
  // components `property` has for 2 components (`independent` or not).
  const auto draw = [&](int mode, bool independent, double rgba[4])
  {
    property->SetIndependentComponents(independent);
    mapper->SetBlendMode(mode);
    vtkTyndallComponents components;
    std::string error;
    Check(components.Read(property, 2, false, error), "two components read");
    vtkTyndallTransferTable tables[2];
    vtkTyndallProjection::Classes classes;
    classes.Components = &components;
    for (int t = 0; t < components.GetTableCount(); ++t)
    {
      Check(tables[t].Build(property, nullptr, range[0], range[1], error, false,
              components.TableFunction(t), components.TableComponent(t)),
        "a table built");
      classes.Tables[t] = &tables[t];
    }
    classes.Ranges[0] = classes.Ranges[1] = range;
    vtkTyndallProjection projection;
    projection.Read(mapper, property);
    vtkTyndallProjection::Ray ray(projection, classes);
    for (const double* v : samples)
    {
      ray.AddComponents(v, 0.5);
    }
    return ray.Pixel(rgba);
  };
  using M = vtkVolumeMapper;
  struct Case
  {
    int Mode;
    bool Independent;
    double Expected[4];
    const char* What;
  };
  const Case cases[] = {
    // Independent: each component its own extremum (7 and 5; 2 and 1).
    { M::MAXIMUM_INTENSITY_BLEND, true, { 0.35, 0.1, 0.0, 0.45 },
      "independent maximum: sum w a c, sum w a" },
    { M::MINIMUM_INTENSITY_BLEND, true, { 0.1, 0.1, 0.0, 0.2 }, "independent minimum" },
    // Average over [1.5, 6]: component 0 counts 2 and 4 (mean of 0.1 0.2 and
    // 0.2 0.4: 0.05), component 1 counts 5 alone (0.2 0.5); 0.05 + 0.5 0.1.
    { M::AVERAGE_INTENSITY_BLEND, true, { 0.1, 0.1, 0.1, 1.0 },
      "independent average: sum w mean(a u) per component" },
    // Additive: component 0 (0.02 + 0.245 + 0.08) 0.5 / 1, component 1
    // 0.2 (0.5 + 0.1 + 0.8) 0.5 / 2 = 0.07; 0.1725 + 0.5 0.07.
    { M::ADDITIVE_BLEND, true, { 0.2075, 0.2075, 0.2075, 1.0 },
      "independent additive: sum w sum(a u dt / d)" },
    // Dependent (colour function 0 at component 0, opacity function 0 at
    // component 1): the sample of the largest (4, 8) or smallest (7, 1)
    // component 1, red at opacity 0.4 or 0.05.
    { M::MAXIMUM_INTENSITY_BLEND, false, { 0.4, 0.0, 0.0, 0.4 },
      "dependent maximum: the sample of the largest opacity component" },
    { M::MINIMUM_INTENSITY_BLEND, false, { 0.05, 0.0, 0.0, 0.05 }, "dependent minimum" },
    // Dependent additive: a(component 1) u_0 dt / d_1 summed:
    // (0.25 0.2 + 0.05 0.7 + 0.4 0.4) 0.5 / 2.
    { M::ADDITIVE_BLEND, false, { 0.06125, 0.06125, 0.06125, 1.0 },
      "dependent additive: the opacity component's unit distance" },
  };
  for (const Case& c : cases)
  {
    double rgba[4];
    Check(draw(c.Mode, c.Independent, rgba), std::string(c.What) + " (drawn)");
    double worst = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      worst = std::max(worst, std::abs(rgba[k] - c.Expected[k]));
    }
    std::cout << c.What << ": (" << rgba[0] << ", " << rgba[1] << ", " << rgba[2] << ", " << rgba[3]
              << "), off by " << worst << "\n";
    Check(worst < 1e-6, c.What);
  }
}
}

int TestTyndallComponents(int, char*[])
{
  TestRules();
  TestMixing();
  TestGrid();
  TestMajorants();
  TestBlendWeight();
  TestProjections();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
