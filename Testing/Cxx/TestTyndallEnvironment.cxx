// vtkTyndallEnvironment, the renderer's sky as both path tracers read it,
// against exact values:
// 1. VTK's rule: black by default; EnvironmentalBG constant; the gradient
//    from EnvironmentalBG (down) to EnvironmentalBG2 (up) when
//    GradientEnvironmentalBG is on; the texture's image only with
//    UseImageBasedLighting; an 8- or 16-bit image is scaled and sRGB-decoded;
// 2. the image placed as vtkSkybox places it (its front at the image's
//    centre, its right a quarter further, up on the last row), with the
//    renderer's up and right;
// 3. the sampling: a constant sky's density is 1 / (4 pi); each texel is
//    drawn as often as its share of mean channel x solid angle (400000
//    draws, every texel within 5 standard deviations); the density a draw
//    returns is Pdf() of its direction and the draw lies in its texel; the
//    density integrates to 1 and L / pdf to 4 pi times the mean radiance;
// 4. bad input refused with an error (once) and a black sky: a cube map, a
//    3-D image, 32-bit integers, a NaN value, colour or up vector, a value
//    above MaximumRadiance, a side too large, no up vector, a right vector
//    along up (but not for a black sky, whose frame is not read);
// 5. the tables rebuilt only when something changes (the serial);
// 6. the sky as directional lights (vtkTyndallSkyLights, the map-based
//    frame's): the irradiances add up to 4 pi times the mean radiance, per
//    channel, for a constant, a gradient and an image sky and every count;
//    a constant sky (one texel) cut into 2 is two opposite lights of 2 pi L
//    each, into 4 four of pi L; a sun (one bright texel) is where one
//    light comes from (Direction() Texel()'s inverse); the gradient's light
//    comes from above; no light for a black sky or a count of 0; as many
//    lights as cells with light when they are fewer.
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkTyndallEnvironment.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkTyndallSkyLights.h"
#include "vtkTyndallToneMapping.h"
#include "vtkUnsignedCharArray.h"

#include "TyndallTestCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;
constexpr double kPi = 3.14159265358979323846;

bool Near(double a, double b, double tolerance)
{
  return std::abs(a - b) <= tolerance;
}

// A W x H image of `components` floats, texel t's channel c = f(t, c).
template <typename F>
vtkSmartPointer<vtkImageData> MakeImage(int W, int H, int components, F f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(static_cast<vtkIdType>(W) * H);
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(W) * H; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      values->SetComponent(t, c, f(t, c));
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void UseImage(vtkRenderer* renderer, vtkImageData* image)
{
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  renderer->SetEnvironmentTexture(texture);
  renderer->UseImageBasedLightingOn();
}

// A unit direction uniform on the sphere.
void UniformDirection(std::mt19937_64& rng, double w[3])
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = 1.0 - 2.0 * u(rng);
  const double phi = 2.0 * kPi * u(rng);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  w[0] = r * std::cos(phi);
  w[1] = r * std::sin(phi);
  w[2] = z;
}

// 1. the rule.
void Rule()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkObject> reporter;
  vtkTyndallEnvironment sky;
  Check(sky.Update(renderer, reporter) && !sky.Enabled(), "VTK's default sky is black");
  Check(sky.Update(nullptr, reporter) && !sky.Enabled(), "no renderer: black");
  renderer->SetEnvironmentalBG(0.5, 0.25, 1.0);
  Check(sky.Update(renderer, reporter) && sky.Enabled(), "a constant sky has light");
  const double up[3] = { 0.0, 1.0, 0.0 };
  double L[3];
  sky.Evaluate(up, L);
  Check(Near(L[0], 0.5, 1e-6) && Near(L[1], 0.25, 1e-6) && Near(L[2], 1.0, 1e-6),
    "the constant sky is EnvironmentalBG");
  Check(Near(sky.GetMeanRadiance()[2], 1.0, 1e-6), "its mean radiance is its radiance");
  Check(Near(sky.Pdf(up), 1.0 / (4.0 * kPi), 1e-9), "a constant sky's density is 1 / (4 pi)");

  renderer->GradientEnvironmentalBGOn();
  renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  renderer->SetEnvironmentalBG2(1.0, 1.0, 1.0);
  sky.Update(renderer, reporter);
  const double down[3] = { 0.0, -1.0, 0.0 };
  const double side[3] = { 1.0, 0.0, 0.0 };
  const double half = 0.5 / vtkTyndallEnvironment::GradientRows;
  sky.Evaluate(up, L);
  Check(Near(L[0], 1.0 - half, 1e-6), "the gradient is EnvironmentalBG2 straight up");
  sky.Evaluate(down, L);
  Check(Near(L[0], half, 1e-6), "the gradient is EnvironmentalBG straight down");
  // 30 degrees above the horizon: 2/3 of the way up (linear in elevation).
  const double raised[3] = { std::cos(kPi / 6.0), std::sin(kPi / 6.0), 0.0 };
  sky.Evaluate(raised, L);
  Check(Near(L[0], 2.0 / 3.0, 1.0 / vtkTyndallEnvironment::GradientRows),
    "the gradient is linear in the elevation angle");
  sky.Evaluate(side, L);
  Check(Near(L[0], 0.5, 1.0 / vtkTyndallEnvironment::GradientRows), "half way at the horizon");
  Check(Near(sky.GetMeanRadiance()[0], 0.5, 1e-4), "the gradient's mean is half way");

  // The image only with UseImageBasedLighting.
  auto image = MakeImage(4, 2, 3, [](vtkIdType, int) { return 3.0; });
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  renderer->SetEnvironmentTexture(texture);
  sky.Update(renderer, reporter);
  Check(sky.GetWidth() == 1, "the texture is not read without UseImageBasedLighting");
  renderer->UseImageBasedLightingOn();
  sky.Update(renderer, reporter);
  sky.Evaluate(side, L);
  Check(sky.GetWidth() == 4 && sky.GetHeight() == 2 && Near(L[1], 3.0, 1e-6),
    "the texture's image with UseImageBasedLighting");

  // Integers are display values: scaled by their type's largest and sRGB-decoded.
  for (int type : { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT })
  {
    auto integers = vtkSmartPointer<vtkImageData>::New();
    integers->SetDimensions(2, 1, 1);
    integers->AllocateScalars(type, 3);
    vtkDataArray* scalars = integers->GetPointData()->GetScalars();
    const double stored = type == VTK_UNSIGNED_CHAR ? 128.0 : 30000.0;
    scalars->Fill(stored);
    UseImage(renderer, integers);
    sky.Update(renderer, reporter);
    sky.Evaluate(side, L);
    Check(Near(L[1], vtkTyndallToneMapping::DecodeSRGB(stored / scalars->GetDataTypeMax()), 1e-6),
      std::string(type == VTK_UNSIGNED_CHAR ? "an 8-bit" : "a 16-bit") +
        " image is scaled to [0, 1] and sRGB-decoded");
  }
}

// 2. the placement: vtkSkybox's equirectangular lookup.
void Placement()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkObject> reporter;
  vtkTyndallEnvironment sky;
  const int W = 8, H = 4;
  UseImage(renderer, MakeImage(W, H, 3, [](vtkIdType t, int) { return double(t); }));
  // Up +z, right +x: front = up x right = +y.
  renderer->SetEnvironmentUp(0.0, 0.0, 2.0);
  renderer->SetEnvironmentRight(1.0, 0.0, 0.5); // made orthogonal to up
  Check(sky.Update(renderer, reporter), "the image is read");
  struct Case
  {
    double W[3];
    int I, J;
    const char* What;
  };
  const double e = 0.1; // a little above the horizon: row H / 2
  const Case cases[] = {
    { { 0.0, 1.0, e }, W / 2, H / 2, "the front at the image's centre" },
    { { 1.0, 0.0, e }, 3 * W / 4, H / 2, "the right a quarter further" },
    { { -1.0, 0.0, e }, W / 4, H / 2, "the left a quarter before" },
    { { 0.0, -1.0, e }, W - 1, H / 2, "the back at the edge" },
    { { 0.1, 0.0, 1.0 }, 3 * W / 4, H - 1, "up on the last row" },
    { { 0.1, 0.0, -1.0 }, 3 * W / 4, 0, "down on the first" },
  };
  for (const Case& c : cases)
  {
    double w[3] = { c.W[0], c.W[1], c.W[2] };
    vtkMath::Normalize(w);
    int i, j;
    sky.Texel(w, i, j);
    double L[3];
    sky.Evaluate(w, L);
    Check(i == c.I && j == c.J && L[0] == j * W + i,
      std::string(c.What) + ": texel " + std::to_string(i) + ", " + std::to_string(j));
  }
  Check(Near(sky.GetFront()[1], 1.0, 1e-12), "front = up x right");
}

// 3. the sampling.
void Sampling()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkObject> reporter;
  vtkTyndallEnvironment sky;
  const int W = 6, H = 5;
  // Coloured, with one bright texel and a black row.
  UseImage(renderer,
    MakeImage(W, H, 3,
      [](vtkIdType t, int c)
      {
        const int row = static_cast<int>(t / 6);
        return row == 1 ? 0.0 : (t == 20 ? 40.0 : 1.0 + 0.3 * c + 0.1 * (t % 7));
      }));
  renderer->SetEnvironmentUp(0.3, 1.0, -0.2);
  renderer->SetEnvironmentRight(1.0, 0.0, 0.0);
  Check(sky.Update(renderer, reporter), "the image is read");
  // Expected shares: mean channel x solid angle.
  std::vector<double> share(W * H);
  double total = 0.0;
  for (int j = 0; j < H; ++j)
  {
    const double omega = 2.0 * kPi / W *
      (std::sin(kPi * ((j + 1.0) / H - 0.5)) - std::sin(kPi * (double(j) / H - 0.5)));
    for (int i = 0; i < W; ++i)
    {
      const float* L = &sky.GetRadiance()[3 * (j * W + i)];
      share[j * W + i] = (double(L[0]) + L[1] + L[2]) / 3.0 * omega;
      total += share[j * W + i];
    }
  }
  Check(Near(sky.GetTotal(), total, 1e-9 * total), "the normaliser is the sum of the shares");
  const int draws = 400000;
  std::vector<int> counts(W * H, 0);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double integral[3] = { 0.0, 0.0, 0.0 };
  int mismatched = 0;
  for (int n = 0; n < draws; ++n)
  {
    const double u[4] = { uniform(rng), uniform(rng), uniform(rng), uniform(rng) };
    double w[3], L[3];
    const double pdf = sky.Sample(u, w, L);
    int i, j;
    sky.Texel(w, i, j);
    ++counts[j * W + i];
    double at[3];
    sky.Evaluate(w, at);
    if (!Near(pdf, sky.Pdf(w), 1e-9 * pdf) || !Near(vtkMath::Norm(w), 1.0, 1e-9) || at[0] != L[0] ||
      !(pdf > 0.0))
    {
      ++mismatched;
    }
    for (int c = 0; c < 3; ++c)
    {
      integral[c] += L[c] / pdf / draws;
    }
  }
  Check(mismatched == 0,
    std::to_string(mismatched) + " draws whose density, radiance or texel is not their own");
  double worst = 0.0;
  for (int k = 0; k < W * H; ++k)
  {
    const double p = share[k] / total;
    const double sigma = std::sqrt(draws * p * (1.0 - p)) + 1e-9;
    worst = std::max(worst, std::abs(counts[k] - draws * p) / sigma);
    if (p == 0.0 && counts[k] != 0)
    {
      worst = 1e9;
    }
  }
  std::cout << "texel frequencies: worst " << worst << " standard deviations" << std::endl;
  Check(worst < 5.0, "each texel drawn as often as its share");
  for (int c = 0; c < 3; ++c)
  {
    const double expected = 4.0 * kPi * sky.GetMeanRadiance()[c];
    Check(Near(integral[c], expected, 5e-3 * expected),
      "L / pdf integrates to 4 pi times the mean radiance (channel " + std::to_string(c) + ")");
  }
  // The density integrates to 1 (uniform directions).
  double mass = 0.0;
  const int uniformDraws = 400000;
  for (int n = 0; n < uniformDraws; ++n)
  {
    double w[3];
    UniformDirection(rng, w);
    mass += 4.0 * kPi * sky.Pdf(w) / uniformDraws;
  }
  std::cout << "the density's integral: " << mass << std::endl;
  Check(Near(mass, 1.0, 0.02), "the density integrates to 1");
}

// 4. bad input.
void BadInput()
{
  vtkNew<vtkObject> reporter;
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(reporter);
  auto refused = [&](vtkRenderer* renderer, const char* what, const char* says)
  {
    errors->Clear();
    vtkTyndallEnvironment sky;
    const bool ok = sky.Update(renderer, reporter);
    const bool named =
      errors->HasErrors() && errors->GetMessages().front().find(says) != std::string::npos;
    Check(!ok && !sky.Enabled() && named, std::string(what) + ": refused with an error");
    // Once per change: the same settings again say nothing more.
    errors->Clear();
    sky.Update(renderer, reporter);
    Check(!errors->HasErrors(), std::string(what) + ": the error is not repeated");
  };
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(1.0, 1.0, 1.0);
    vtkNew<vtkTexture> cube;
    cube->CubeMapOn();
    renderer->SetEnvironmentTexture(cube);
    renderer->UseImageBasedLightingOn();
    refused(renderer, "a cube map", "cube map");
  }
  {
    vtkNew<vtkRenderer> renderer;
    auto volume = vtkSmartPointer<vtkImageData>::New();
    volume->SetDimensions(4, 4, 4);
    volume->AllocateScalars(VTK_FLOAT, 3);
    UseImage(renderer, volume);
    refused(renderer, "a 3-D image", "2-D");
  }
  {
    vtkNew<vtkRenderer> renderer;
    UseImage(renderer, MakeImage(4, 2, 3, [](vtkIdType t, int) { return t == 3 ? NAN : 1.0; }));
    refused(renderer, "a NaN", "NaN");
  }
  {
    vtkNew<vtkRenderer> renderer;
    UseImage(renderer,
      MakeImage(
        vtkTyndallEnvironment::MaximumImageSide + 1, 1, 1, [](vtkIdType, int) { return 1.0; }));
    refused(renderer, "a side too large", "side");
  }
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(1.0, 1.0, 1.0);
    renderer->SetEnvironmentUp(0.0, 0.0, 0.0);
    refused(renderer, "no up vector", "EnvironmentUp");
  }
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(1.0, 1.0, 1.0);
    renderer->SetEnvironmentRight(0.0, 3.0, 0.0);
    refused(renderer, "a right vector along up", "EnvironmentRight");
  }
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(-1.0, 1.0, 1.0);
    refused(renderer, "a negative colour", "EnvironmentalBG");
  }
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(NAN, 1.0, 1.0);
    refused(renderer, "a NaN colour", "EnvironmentalBG");
  }
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentalBG(1.0, 1.0, 1.0);
    renderer->SetEnvironmentUp(NAN, 1.0, 0.0);
    refused(renderer, "a NaN up vector", "EnvironmentUp");
  }
  {
    vtkNew<vtkRenderer> renderer;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(2, 1, 1);
    image->AllocateScalars(VTK_DOUBLE, 1);
    static_cast<double*>(image->GetScalarPointer())[0] = 1.0;
    static_cast<double*>(image->GetScalarPointer())[1] = 1e300;
    UseImage(renderer, image);
    refused(renderer, "a value above MaximumRadiance", "above");
  }
  {
    vtkNew<vtkRenderer> renderer;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(2, 1, 1);
    image->AllocateScalars(VTK_INT, 3);
    UseImage(renderer, image);
    refused(renderer, "32-bit integers", "type");
  }
  {
    // A black sky lights nothing: its frame is not read.
    vtkNew<vtkRenderer> renderer;
    renderer->SetEnvironmentRight(0.0, 1.0, 0.0);
    errors->Clear();
    vtkTyndallEnvironment sky;
    Check(sky.Update(renderer, reporter) && !errors->HasErrors() && !sky.Enabled(),
      "a black sky with a right vector along up: no error");
  }
}

// 5. the serial.
void Serial()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkObject> reporter;
  vtkTyndallEnvironment sky;
  renderer->SetEnvironmentalBG(1.0, 1.0, 1.0);
  sky.Update(renderer, reporter);
  const vtkMTimeType first = sky.GetSerial();
  sky.Update(renderer, reporter);
  Check(sky.GetSerial() == first, "nothing changed: not rebuilt");
  renderer->SetEnvironmentalBG(2.0, 2.0, 2.0);
  sky.Update(renderer, reporter);
  Check(sky.GetSerial() > first, "a new colour: rebuilt");
  auto image = MakeImage(2, 2, 3, [](vtkIdType, int) { return 1.0; });
  UseImage(renderer, image);
  sky.Update(renderer, reporter);
  const vtkMTimeType read = sky.GetSerial();
  sky.Update(renderer, reporter);
  Check(sky.GetSerial() == read, "the same image: not rebuilt");
  image->GetPointData()->GetScalars()->SetComponent(0, 0, 5.0);
  image->Modified();
  sky.Update(renderer, reporter);
  Check(sky.GetSerial() > read && sky.GetRadiance()[0] == 5.0f, "a modified image: read again");
}

// The lights' irradiances add up to 4 pi times the sky's mean radiance.
bool Conserved(const vtkTyndallEnvironment& sky, const std::vector<vtkTyndallLight>& lights)
{
  for (int c = 0; c < 3; ++c)
  {
    double sum = 0.0;
    for (const vtkTyndallLight& l : lights)
    {
      sum += l.Irradiance[c];
    }
    const double expected = 4.0 * kPi * sky.GetMeanRadiance()[c];
    if (!Near(sum, expected, 1e-9 * std::max(1.0, expected)))
    {
      std::cout << "channel " << c << ": the lights carry " << sum << ", the sky " << expected
                << std::endl;
      return false;
    }
  }
  return true;
}

// 6. the sky as lights.
void SkyLights()
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkObject> reporter;
  vtkTyndallEnvironment sky;
  sky.Update(renderer, reporter);
  Check(vtkTyndallSkyLights::Split(sky, 4).empty(), "a black sky has no light");
  renderer->SetEnvironmentalBG(0.5, 0.25, 1.0);
  sky.Update(renderer, reporter);
  Check(vtkTyndallSkyLights::Split(sky, 0).empty(), "a count of 0: no light");
  bool conserved = true, counted = true, usable = true;
  for (int n = 1; n <= 8; ++n)
  {
    const std::vector<vtkTyndallLight> lights = vtkTyndallSkyLights::Split(sky, n);
    conserved = conserved && Conserved(sky, lights);
    counted = counted && static_cast<int>(lights.size()) == n;
    for (const vtkTyndallLight& l : lights)
    {
      usable = usable && !l.Positional && l.RendererIndex == -1 &&
        Near(vtkMath::Norm(l.Direction), 1.0, 1e-9);
    }
  }
  Check(conserved, "a constant sky's lights carry all its light");
  Check(counted, "a constant sky (one texel) is cut into as many lights as asked");
  Check(usable, "the sky's lights are directional, unit, and no renderer light");
  std::vector<vtkTyndallLight> two = vtkTyndallSkyLights::Split(sky, 2);
  Check(two.size() == 2 && Near(vtkMath::Dot(two[0].Direction, two[1].Direction), -1.0, 1e-3) &&
      Near(two[0].Irradiance[0], 2.0 * kPi * 0.5, 1e-9) &&
      Near(two[1].Irradiance[2], 2.0 * kPi * 1.0, 1e-9),
    "a constant sky cut in two: opposite halves of 2 pi L each");
  bool quarters = true;
  for (const vtkTyndallLight& l : vtkTyndallSkyLights::Split(sky, 4))
  {
    quarters = quarters && Near(l.Irradiance[1], kPi * 0.25, 1e-9);
  }
  Check(quarters, "a constant sky cut in four: quarters of pi L each");

  // The gradient: black down, white up: the brightest light looks up.
  renderer->GradientEnvironmentalBGOn();
  renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  renderer->SetEnvironmentalBG2(1.0, 1.0, 1.0);
  sky.Update(renderer, reporter);
  conserved = true;
  for (int n = 1; n <= 8; ++n)
  {
    conserved = conserved && Conserved(sky, vtkTyndallSkyLights::Split(sky, n));
  }
  Check(conserved, "a gradient sky's lights carry all its light");
  // The median cut gives the lights about equal light: most of them come
  // from above, where the light is (their irradiance-weighted direction).
  const std::vector<vtkTyndallLight> lights = vtkTyndallSkyLights::Split(sky, 4);
  double from[3] = { 0.0, 0.0, 0.0 };
  for (const vtkTyndallLight& l : lights)
  {
    for (int c = 0; c < 3; ++c)
    {
      from[c] -= l.Irradiance[0] * l.Direction[c];
    }
  }
  vtkMath::Normalize(from);
  Check(lights.size() == 4 && from[1] > 0.9 && std::abs(from[0]) < 0.05,
    "the gradient's light comes from above");

  // A dim image with a sun: texel (40, 24) of 64 x 32, 1000 times brighter.
  renderer->GradientEnvironmentalBGOff();
  const int sunColumn = 40, sunRow = 24;
  auto image = MakeImage(64, 32, 3,
    [&](vtkIdType t, int c) { return t == sunRow * 64 + sunColumn ? 1000.0 : 0.01 * (c + 1); });
  UseImage(renderer, image);
  sky.Update(renderer, reporter);
  conserved = true;
  for (int n = 1; n <= 8; ++n)
  {
    conserved = conserved && Conserved(sky, vtkTyndallSkyLights::Split(sky, n));
  }
  Check(conserved, "an image sky's lights carry all its light");
  double sun[3];
  sky.Direction(sunColumn + 0.5, sunRow + 0.5, sun);
  int i, j;
  sky.Texel(sun, i, j);
  Check(i == sunColumn && j == sunRow, "Direction() is Texel()'s inverse");
  bool found = false;
  for (const vtkTyndallLight& l : vtkTyndallSkyLights::Split(sky, 6))
  {
    // Where the light comes from is the sun's texel.
    const double towards[3] = { -l.Direction[0], -l.Direction[1], -l.Direction[2] };
    double L[3];
    sky.Evaluate(towards, L);
    found = found || L[0] == 1000.0;
  }
  Check(found, "the sun is one light's direction");
  // A 1 x 2 image (down dark, up bright) has 64 x 32 cells: 8 lights.
  UseImage(renderer, MakeImage(1, 2, 1, [](vtkIdType t, int) { return t == 0 ? 0.0 : 1.0; }));
  sky.Update(renderer, reporter);
  Check(vtkTyndallSkyLights::Split(sky, 8).size() == 8, "a small image is cut into its cells");
  // Light in one cell only: one light, whatever the count.
  UseImage(
    renderer, MakeImage(64, 32, 1, [](vtkIdType t, int) { return t == 5 * 64 + 7 ? 3.0 : 0.0; }));
  sky.Update(renderer, reporter);
  Check(vtkTyndallSkyLights::Split(sky, 8).size() == 1, "one texel of light: one light");
  // Two texels of light in one column: two lights (the dark cells are not cut off one by one).
  UseImage(renderer,
    MakeImage(
      64, 32, 1, [](vtkIdType t, int) { return t == 5 * 64 + 7 || t == 20 * 64 + 7 ? 3.0 : 0.0; }));
  sky.Update(renderer, reporter);
  Check(vtkTyndallSkyLights::Split(sky, 8).size() == 2, "two texels of light: two lights");
}
}

int TestTyndallEnvironment(int, char*[])
{
  Rule();
  Placement();
  Sampling();
  BadInput();
  Serial();
  SkyLights();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
