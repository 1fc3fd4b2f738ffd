// vtkTyndallDenoiser (the CPU twin of the path-traced picture's denoiser,
// vtkTransmittanceDenoiseFS.glsl; the GPU side is
// TestTransmittanceMapperDenoise) against exact values:
// - D(): 1 / (1 + Epsilon) between a pixel and an empty one, 0 between
//   equal ones, r^2 / (2 + r^2 + ...) for a relative difference;
// - the B3 kernel sums to 1; EdgeStopFor() is 0.5 / sqrt(samples);
// - no passes: the mean itself; a mean equal to the guide: the guide; a
//   residual constant over the picture: kept (the weights are normalized);
// - one pass on a uniform guide spreads a residual impulse as the kernel,
//   h(dx) h(dy) times it, exactly; two passes as the kernel convolved with
//   itself spaced 2 pixels apart (reach 6);
// - an edge in the guide: a residual on one side (constant, with a
//   checkerboard on it) does not cross to the other beyond
//   exp(-D / EdgeStop^2), and its checkerboard is smoothed;
// - the output's radiance at least 0 and opacity in [0, 1];
// - bad parameters: false and the output untouched; the vtkFloatArray form.
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkTyndallDenoiser.h"

#include "TyndallTestCheck.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

namespace
{
using tyndall_test::Check;
using D = vtkTyndallDenoiser;

struct Picture
{
  int Width, Height;
  std::vector<float> Values;
  Picture(int w, int h, float r = 0.f, float g = 0.f, float b = 0.f, float a = 0.f)
    : Width(w)
    , Height(h)
    , Values(size_t(w) * h * 4)
  {
    for (size_t i = 0; i < Values.size(); i += 4)
    {
      Values[i] = r;
      Values[i + 1] = g;
      Values[i + 2] = b;
      Values[i + 3] = a;
    }
  }
  float* At(int x, int y) { return &Values[(size_t(y) * Width + x) * 4]; }
  const float* At(int x, int y) const { return &Values[(size_t(y) * Width + x) * 4]; }
};

Picture Filter(const Picture& mean, const Picture& guide, int iterations, double edgeStop)
{
  Picture out(mean.Width, mean.Height, -7.f, -7.f, -7.f, -7.f);
  Check(D::Filter(mean.Values.data(), guide.Values.data(), mean.Width, mean.Height, iterations,
          edgeStop, out.Values.data()),
    "Filter() accepts good parameters");
  return out;
}
}

int TestTyndallDenoiser(int, char*[])
{
  vtkNew<vtkTyndallDenoiser> object;
  std::ostringstream print;
  object->Print(print);
  Check(print.str().find("vtkTyndallDenoiser") != std::string::npos, "PrintSelf");

  // D().
  const float one[4] = { 1.f, 0.f, 0.f, 0.f }, none[4] = { 0.f, 0.f, 0.f, 0.f };
  const float a[4] = { 0.5f, 0.25f, 0.125f, 0.5f }, b[4] = { 0.55f, 0.275f, 0.1375f, 0.55f };
  Check(D::Difference(one, none) == 1.0 / (1.0 + D::Epsilon), "D against an empty pixel");
  Check(D::Difference(a, a) == 0.0, "D of equal pixels");
  double aa = 0.0;
  for (float v : a)
  {
    aa += double(v) * v;
  }
  const double expected = 0.01 * aa / (aa * (1.0 + 1.21) + D::Epsilon); // b = 1.1 a
  // (b rounded to floats: within 1e-5 of the exact ratio)
  Check(std::abs(D::Difference(a, b) - expected) < 1e-5 * expected, "D of a 10 % difference");
  double kernel = 0.0;
  for (int tap = -3; tap <= 3; ++tap)
  {
    kernel += D::KernelWeight(tap);
  }
  Check(kernel == 1.0 && D::KernelWeight(0) == 6.0 / 16.0 && D::KernelWeight(3) == 0.0,
    "the B3 kernel");
  Check(D::EdgeStopFor(4) == 0.25 && D::EdgeStopFor(0) == D::FirstEdgeStop &&
      std::abs(D::EdgeStopFor(1024) - 0.5 / 32.0) < 1e-15,
    "EdgeStopFor()");

  // No passes, mean = guide, a constant residual.
  Picture guide(16, 12, 0.3f, 0.2f, 0.1f, 0.4f);
  for (int x = 0; x < 16; ++x)
  {
    guide.At(x, 5)[0] = 0.05f * x; // some structure
  }
  Picture mean = guide;
  mean.At(3, 4)[1] = 0.9f;
  Check(Filter(mean, guide, 0, 0.3).Values == mean.Values, "no passes: the mean");
  Check(Filter(guide, guide, 3, 0.3).Values == guide.Values, "the mean equal to the guide");
  Picture shifted = guide;
  for (size_t i = 0; i < shifted.Values.size(); ++i)
  {
    shifted.Values[i] += i % 4 == 3 ? 0.25f : 0.125f;
  }
  double worst = 0.0;
  const Picture constant = Filter(shifted, guide, 3, 0.3);
  for (size_t i = 0; i < shifted.Values.size(); ++i)
  {
    worst = std::max(worst, std::abs(double(constant.Values[i]) - shifted.Values[i]));
  }
  Check(worst < 1e-6, "a constant residual is kept");

  // An impulse on a uniform guide: the kernel, then the kernel twice, spaced.
  Picture flat(21, 21, 0.5f, 0.5f, 0.5f, 0.5f);
  Picture impulse = flat;
  impulse.At(10, 10)[0] += 1.f;
  const Picture once = Filter(impulse, flat, 1, 0.3);
  worst = 0.0;
  for (int y = 6; y <= 14; ++y)
  {
    for (int x = 6; x <= 14; ++x)
    {
      const double h = D::KernelWeight(x - 10) * D::KernelWeight(y - 10);
      worst = std::max(worst, std::abs(double(once.At(x, y)[0]) - (0.5 + h)));
      worst = std::max(worst, std::abs(double(once.At(x, y)[1]) - 0.5));
    }
  }
  Check(worst < 1e-6, "one pass spreads an impulse as the kernel");
  const Picture twice = Filter(impulse, flat, 2, 0.3);
  // Two passes: r(d) = sum of h(i) h(j) over i + 2 j = d, per axis.
  auto response = [](int d)
  {
    double r = 0.0;
    for (int i = -2; i <= 2; ++i)
    {
      r += (d - i) % 2 == 0 ? D::KernelWeight(i) * D::KernelWeight((d - i) / 2) : 0.0;
    }
    return r;
  };
  worst = 0.0;
  for (int y = 3; y <= 17; ++y)
  {
    for (int x = 3; x <= 17; ++x)
    {
      const double r = response(x - 10) * response(y - 10);
      worst = std::max(worst, std::abs(double(twice.At(x, y)[0]) - (0.5 + r)));
    }
  }
  Check(worst < 1e-6 && response(6) > 0.0 && response(7) == 0.0,
    "the second pass's taps are 2 pixels apart (reach 6)");

  // An edge: left half bright, right half dark; a residual on the left
  // (0.3, with a checkerboard of +-0.1 on it), none on the right.
  Picture halves(20, 8);
  Picture noisy(20, 8);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 20; ++x)
    {
      const float v = x < 10 ? 0.8f : 0.2f;
      for (int c = 0; c < 4; ++c)
      {
        halves.At(x, y)[c] = v;
        noisy.At(x, y)[c] = v + (x < 10 ? ((x + y) % 2 ? 0.4f : 0.2f) : 0.f);
      }
    }
  }
  const double stop = 0.25;
  const Picture edge = Filter(noisy, halves, 2, stop);
  const float bright[4] = { 0.8f, 0.8f, 0.8f, 0.8f }, dark[4] = { 0.2f, 0.2f, 0.2f, 0.2f };
  const double crossing = std::exp(-D::Difference(bright, dark) / (stop * stop));
  double leaked = 0.0, smoothed = 0.0;
  for (int y = 0; y < 8; ++y)
  {
    leaked = std::max(leaked, std::abs(double(edge.At(10, y)[0]) - 0.2));
    smoothed = std::max(smoothed, std::abs(double(edge.At(5, y)[0]) - 1.1));
  }
  // At most 0.4 times the crossing taps' share, each at most `crossing`
  // against a tap of its own side's h(0)^2 (2 x the crossing's weight
  // bounds it; an edge stop twice as wide lets 0.02 through).
  std::cout << "an edge: leaked " << leaked << " (bound " << 0.4 * 2 * crossing
            << "), the noise left " << smoothed << " of 0.1\n";
  Check(leaked < 0.4 * 2 * crossing, "the residual does not cross the guide's edge");
  Check(smoothed < 0.02, "the residual's noise is smoothed on its side");

  // Clamping: radiance at least 0, opacity at most 1.
  Picture low(4, 4, 0.1f, 0.1f, 0.1f, 0.9f);
  Picture negative(4, 4, -0.5f, 0.1f, 0.1f, 1.5f);
  const Picture clamped = Filter(negative, low, 1, 0.3);
  Check(clamped.At(1, 1)[0] == 0.f && clamped.At(1, 1)[3] == 1.f, "radiance >= 0, opacity <= 1");
  Picture broken(4, 4, 0.1f, 0.1f, 0.1f, 0.9f);
  broken.At(2, 2)[1] = std::nanf("");
  const Picture cleaned = Filter(broken, low, 1, 0.3);
  Check(cleaned.At(2, 2)[1] == 0.f && cleaned.At(0, 0)[1] == 0.f && cleaned.At(0, 0)[0] > 0.f,
    "a NaN in the mean gives 0 where it reaches");

  // Bad parameters.
  Picture untouched(4, 4, 0.25f);
  const std::vector<float> before = untouched.Values;
  Check(!D::Filter(low.Values.data(), low.Values.data(), 4, 4, -1, 0.3, untouched.Values.data()) &&
      !D::Filter(low.Values.data(), low.Values.data(), 4, 4, D::MaximumIterations + 1, 0.3,
        untouched.Values.data()) &&
      !D::Filter(low.Values.data(), low.Values.data(), 4, 4, 1, 0.0, untouched.Values.data()) &&
      !D::Filter(
        low.Values.data(), low.Values.data(), 4, 4, 1, std::nan(""), untouched.Values.data()) &&
      !D::Filter(low.Values.data(), low.Values.data(), 0, 4, 1, 0.3, untouched.Values.data()) &&
      !D::Filter(nullptr, low.Values.data(), 4, 4, 1, 0.3, untouched.Values.data()),
    "bad parameters are refused");
  Check(untouched.Values == before, "a refused Filter() leaves the output");

  // The vtkFloatArray form.
  vtkNew<vtkFloatArray> m, g, o;
  for (vtkFloatArray* array : { m.Get(), g.Get() })
  {
    array->SetNumberOfComponents(4);
    array->SetNumberOfTuples(16 * 12);
  }
  std::copy(mean.Values.begin(), mean.Values.end(), m->GetPointer(0));
  std::copy(guide.Values.begin(), guide.Values.end(), g->GetPointer(0));
  Check(D::Filter(m, g, 16, 12, 2, 0.3, o), "the arrays' Filter()");
  const Picture direct = Filter(mean, guide, 2, 0.3);
  Check(o->GetNumberOfTuples() == 16 * 12 &&
      std::equal(direct.Values.begin(), direct.Values.end(), o->GetPointer(0)),
    "the arrays' Filter() is the pointers'");
  Check(!D::Filter(m, g, 16, 11, 2, 0.3, o) && !D::Filter(m, g, 16, 12, 2, 0.3, m),
    "the arrays' sizes and aliasing are checked");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
