#include "vtkTyndallDenoiser.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkTyndallDenoiser);

//------------------------------------------------------------------------------
double vtkTyndallDenoiser::KernelWeight(int tap)
{
  static const double weights[5] = { 1.0, 4.0, 6.0, 4.0, 1.0 };
  return tap >= -2 && tap <= 2 ? weights[tap + 2] / 16.0 : 0.0;
}

//------------------------------------------------------------------------------
double vtkTyndallDenoiser::EdgeStopFor(int samples)
{
  return FirstEdgeStop / std::sqrt(static_cast<double>(std::max(samples, 1)));
}

//------------------------------------------------------------------------------
double vtkTyndallDenoiser::Difference(const float a[4], const float b[4])
{
  double difference = 0.0, size = Epsilon;
  for (int c = 0; c < 4; ++c)
  {
    const double d = static_cast<double>(a[c]) - b[c];
    difference += d * d;
    size += static_cast<double>(a[c]) * a[c] + static_cast<double>(b[c]) * b[c];
  }
  return difference / size;
}

//------------------------------------------------------------------------------
bool vtkTyndallDenoiser::Filter(const float* mean, const float* guide, int width, int height,
  int iterations, double edgeStop, float* out)
{
  if (!mean || !guide || !out || width < 1 || height < 1 || iterations < 0 ||
    iterations > MaximumIterations || !(edgeStop > 0.0))
  {
    return false;
  }
  const size_t values = static_cast<size_t>(width) * height * 4;
  std::vector<double> residual(values), next(values);
  for (size_t i = 0; i < values; ++i)
  {
    residual[i] = static_cast<double>(mean[i]) - guide[i];
  }
  const double scale = 1.0 / (edgeStop * edgeStop);
  for (int pass = 0; pass < iterations; ++pass)
  {
    const int step = 1 << pass;
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const size_t p = (static_cast<size_t>(y) * width + x) * 4;
        double sum[4] = { 0.0, 0.0, 0.0, 0.0 }, weights = 0.0;
        for (int dy = -2; dy <= 2; ++dy)
        {
          const int qy = y + dy * step;
          for (int dx = -2; dx <= 2 && qy >= 0 && qy < height; ++dx)
          {
            const int qx = x + dx * step;
            if (qx < 0 || qx >= width)
            {
              continue;
            }
            const size_t q = (static_cast<size_t>(qy) * width + qx) * 4;
            const double w = KernelWeight(dx) * KernelWeight(dy) *
              std::exp(-Difference(guide + p, guide + q) * scale);
            for (int c = 0; c < 4; ++c)
            {
              sum[c] += w * residual[q + c];
            }
            weights += w;
          }
        }
        for (int c = 0; c < 4; ++c)
        {
          next[p + c] = sum[c] / weights; // the tap at p weighs h(0)^2 at least
        }
      }
    }
    residual.swap(next);
  }
  for (size_t i = 0; i < values; i += 4)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double sum = guide[i + c] + residual[i + c];
      const double value = sum > 0.0 ? sum : 0.0; // NaN: 0
      out[i + c] = static_cast<float>(c == 3 ? std::min(value, 1.0) : value);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallDenoiser::Filter(vtkFloatArray* mean, vtkFloatArray* guide, int width, int height,
  int iterations, double edgeStop, vtkFloatArray* out)
{
  const vtkIdType tuples = static_cast<vtkIdType>(width) * height;
  if (!mean || !guide || !out || width < 1 || height < 1 || mean->GetNumberOfComponents() != 4 ||
    guide->GetNumberOfComponents() != 4 || mean->GetNumberOfTuples() != tuples ||
    guide->GetNumberOfTuples() != tuples || out == mean || out == guide)
  {
    return false;
  }
  std::vector<float> result(static_cast<size_t>(tuples) * 4);
  if (!Filter(mean->GetPointer(0), guide->GetPointer(0), width, height, iterations, edgeStop,
        result.data()))
  {
    return false;
  }
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(tuples);
  std::copy(result.begin(), result.end(), out->GetPointer(0));
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallDenoiser::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
