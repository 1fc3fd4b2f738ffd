// Sampling a volume on the CPU as the GPU's filters do, for the tests of
// the volume's texture layouts (vtkTransmittanceVolumeTiling,
// vtkTransmittanceVolumeBricks): their CPU twins map a volume texture
// coordinate into the layout, and the layout sampled there must equal the
// volume sampled at the coordinate.
#ifndef TyndallTestSampling_h
#define TyndallTestSampling_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tyndall_test
{
/**
 * The sample of `values` (`dims` samples, x fastest) at texture coordinate
 * t (sample i's centre at (i + 0.5) / n), clamp-to-edge: trilinear, as the
 * GPU's linear filter, or the nearest sample, as its nearest filter.
 */
inline double TextureSample(
  const std::vector<double>& values, const int dims[3], const double t[3], bool nearest = false)
{
  int i0[3], i1[3];
  double w[3];
  for (int a = 0; a < 3; ++a)
  {
    if (nearest)
    {
      const int i = static_cast<int>(std::floor(t[a] * dims[a]));
      i0[a] = i1[a] = std::min(std::max(i, 0), dims[a] - 1);
      w[a] = 0.0;
      continue;
    }
    const double v = t[a] * dims[a] - 0.5;
    const double f = std::floor(v);
    w[a] = v - f;
    i0[a] = std::min(std::max(static_cast<int>(f), 0), dims[a] - 1);
    i1[a] = std::min(std::max(static_cast<int>(f) + 1, 0), dims[a] - 1);
  }
  double sum = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    const int i = (c & 1) ? i1[0] : i0[0], j = (c & 2) ? i1[1] : i0[1], k = (c & 4) ? i1[2] : i0[2];
    const double weight =
      ((c & 1) ? w[0] : 1.0 - w[0]) * ((c & 2) ? w[1] : 1.0 - w[1]) * ((c & 4) ? w[2] : 1.0 - w[2]);
    sum += weight * values[(static_cast<size_t>(k) * dims[1] + j) * dims[0] + i];
  }
  return sum;
}
}

#endif
