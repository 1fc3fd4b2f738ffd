#include "vtkTyndallSkyLights.h"

#include "vtkMath.h"
#include "vtkTyndallEnvironment.h"

#include <algorithm>
#include <cmath>

namespace
{

// The sky's table, each texel cut into Sx x Sy equal parts so that the cut
// has at least MinimumColumns x MinimumRows cells to choose from (a
// constant sky is one texel, a gradient one column): a cell's radiance is
// its texel's, so every sum is the table's exactly. The rows' solid angles
// and the cells' directions are tabulated (a cut reads every cell).
class Grid
{
public:
  static constexpr int MinimumColumns = 64;
  static constexpr int MinimumRows = 32;

  explicit Grid(const vtkTyndallEnvironment& sky)
    : Sky(sky)
    , Sx((MinimumColumns + sky.GetWidth() - 1) / sky.GetWidth())
    , Sy((MinimumRows + sky.GetHeight() - 1) / sky.GetHeight())
    , W(sky.GetWidth() * Sx)
    , H(sky.GetHeight() * Sy)
  {
    this->Omega.resize(this->H);
    this->RowCos.resize(this->H);
    this->RowSin.resize(this->H);
    for (int j = 0; j < this->H; ++j)
    {
      const double e0 = vtkMath::Pi() * (static_cast<double>(j) / this->H - 0.5);
      const double e1 = vtkMath::Pi() * (static_cast<double>(j + 1) / this->H - 0.5);
      const double e = vtkMath::Pi() * ((j + 0.5) / this->H - 0.5);
      this->Omega[j] = 2.0 * vtkMath::Pi() / this->W * (std::sin(e1) - std::sin(e0));
      this->RowCos[j] = std::cos(e);
      this->RowSin[j] = std::sin(e);
    }
    this->ColumnCos.resize(this->W);
    this->ColumnSin.resize(this->W);
    for (int i = 0; i < this->W; ++i)
    {
      const double phi = 2.0 * vtkMath::Pi() * ((i + 0.5) / this->W - 0.5);
      this->ColumnCos[i] = std::cos(phi);
      this->ColumnSin[i] = std::sin(phi);
    }
  }

  const float* Radiance(int i, int j) const
  {
    return &this->Sky.GetRadiance()[3 *
      (static_cast<size_t>(j / this->Sy) * this->Sky.GetWidth() + i / this->Sx)];
  }
  double SolidAngle(int j) const { return this->Omega[j]; }
  // The light of cell (i, j): its mean channel x solid angle (the sampling's measure).
  double Light(int i, int j) const
  {
    const float* L = this->Radiance(i, j);
    return (static_cast<double>(L[0]) + L[1] + L[2]) / 3.0 * this->Omega[j];
  }
  // The direction of cell (i, j)'s centre (vtkTyndallEnvironment::Direction()).
  void Direction(int i, int j, double w[3]) const
  {
    const double x = this->RowCos[j] * this->ColumnSin[i];
    const double y = this->RowSin[j];
    const double z = this->RowCos[j] * this->ColumnCos[i];
    this->Sky.FromFrame(x, y, z, w);
  }

  const vtkTyndallEnvironment& Sky;
  const int Sx, Sy, W, H;

private:
  std::vector<double> Omega, RowCos, RowSin, ColumnCos, ColumnSin;
};

// A rectangle of the grid: columns [I0, I1), rows [J0, J1), and its light.
struct Region
{
  int I0, I1, J0, J1;
  double Light;
};

// Shrinks `r` to the rows and columns with light and cuts it in two across
// its longer side (the rows on a tie) where the light on either side is
// closest to half (both sides then have light); false when what has light
// is one cell.
bool Cut(const Grid& grid, Region r, Region& a, Region& b)
{
  std::vector<double> columns(r.I1 - r.I0, 0.0), rows(r.J1 - r.J0, 0.0);
  for (int j = r.J0; j < r.J1; ++j)
  {
    for (int i = r.I0; i < r.I1; ++i)
    {
      const double light = grid.Light(i, j);
      columns[i - r.I0] += light;
      rows[j - r.J0] += light;
    }
  }
  // The first and last bins with light, as [begin, end) offsets.
  auto lit = [](const std::vector<double>& profile, int& begin, int& end)
  {
    begin = 0;
    end = static_cast<int>(profile.size());
    while (begin < end && !(profile[begin] > 0.0))
    {
      ++begin;
    }
    while (end > begin && !(profile[end - 1] > 0.0))
    {
      --end;
    }
  };
  int c0, c1, r0, r1;
  lit(columns, c0, c1);
  lit(rows, r0, r1);
  const int n[2] = { c1 - c0, r1 - r0 };
  if (n[0] < 2 && n[1] < 2)
  {
    return false;
  }
  const int i0 = r.I0;
  const int j0 = r.J0;
  r.I0 = i0 + c0;
  r.I1 = i0 + c1;
  r.J0 = j0 + r0;
  r.J1 = j0 + r1;
  const double middle = vtkMath::Pi() * (0.5 * (r.J0 + r.J1) / grid.H - 0.5);
  const double width = 2.0 * vtkMath::Pi() * n[0] / grid.W * std::cos(middle);
  const double height = vtkMath::Pi() * n[1] / grid.H;
  const bool acrossRows = n[0] < 2 || (n[1] >= 2 && height >= width);
  const double* profile = acrossRows ? &rows[r0] : &columns[c0];
  const int bins = acrossRows ? n[1] : n[0];
  // The region's light summed again here (not inherited: a difference of
  // sums loses a dim region's light beside a sun of 1e20).
  double whole = 0.0;
  for (int k = 0; k < bins; ++k)
  {
    whole += profile[k];
  }
  // The cut k in [1, bins - 1] (k bins on the first side) whose first side is closest to half.
  int best = 1;
  double bestGap = -1.0, bestSum = 0.0, sum = 0.0;
  for (int k = 1; k < bins; ++k)
  {
    sum += profile[k - 1];
    const double gap = std::abs(sum - 0.5 * whole);
    if (bestGap < 0.0 || gap < bestGap)
    {
      best = k;
      bestGap = gap;
      bestSum = sum;
    }
  }
  a = b = r;
  if (acrossRows)
  {
    a.J1 = b.J0 = r.J0 + best;
  }
  else
  {
    a.I1 = b.I0 = r.I0 + best;
  }
  a.Light = bestSum;
  b.Light = 0.0;
  for (int k = best; k < bins; ++k)
  {
    b.Light += profile[k];
  }
  return true;
}

// The directional light of region r; false when it has no light.
bool RegionLight(const Grid& grid, const Region& r, vtkTyndallLight& light)
{
  double E[3] = { 0.0, 0.0, 0.0 }, mean[3] = { 0.0, 0.0, 0.0 }, total = 0.0;
  for (int j = r.J0; j < r.J1; ++j)
  {
    const double omega = grid.SolidAngle(j);
    for (int i = r.I0; i < r.I1; ++i)
    {
      const float* L = grid.Radiance(i, j);
      const double weight = (static_cast<double>(L[0]) + L[1] + L[2]) / 3.0 * omega;
      if (!(weight > 0.0))
      {
        continue;
      }
      double w[3];
      grid.Direction(i, j, w);
      total += weight;
      for (int c = 0; c < 3; ++c)
      {
        E[c] += L[c] * omega;
        mean[c] += weight * w[c];
      }
    }
  }
  if (!(total > 0.0))
  {
    return false;
  }
  if (!(vtkMath::Normalize(mean) > 1e-9 * total))
  {
    // Light spread evenly around a pole or a full circle: the region's centre.
    grid.Sky.Direction(0.5 * (r.I0 + r.I1) / grid.Sx, 0.5 * (r.J0 + r.J1) / grid.Sy, mean);
  }
  light = vtkTyndallLight();
  light.Positional = false;
  light.RendererIndex = -1;
  for (int c = 0; c < 3; ++c)
  {
    light.Direction[c] = -mean[c]; // it travels from the sky inwards
    light.Color[c] = light.Irradiance[c] = E[c];
  }
  return true;
}
}

//------------------------------------------------------------------------------
std::vector<vtkTyndallLight> vtkTyndallSkyLights::Split(const vtkTyndallEnvironment& sky, int count)
{
  std::vector<vtkTyndallLight> lights;
  if (count < 1 || !sky.Enabled())
  {
    return lights;
  }
  const Grid grid(sky);
  double total = 0.0;
  for (int j = 0; j < grid.H; ++j)
  {
    for (int i = 0; i < grid.W; ++i)
    {
      total += grid.Light(i, j);
    }
  }
  std::vector<Region> regions = { { 0, grid.W, 0, grid.H, total } };
  // Cut the region of most light until there are `count` (one cell, or a
  // region without light, is not cut).
  std::vector<bool> whole(1, false);
  while (static_cast<int>(regions.size()) < count)
  {
    int pick = -1;
    for (size_t k = 0; k < regions.size(); ++k)
    {
      if (!whole[k] && regions[k].Light > 0.0 &&
        (pick < 0 || regions[k].Light > regions[pick].Light))
      {
        pick = static_cast<int>(k);
      }
    }
    if (pick < 0)
    {
      break;
    }
    Region a, b;
    if (!Cut(grid, regions[pick], a, b))
    {
      whole[pick] = true;
      continue;
    }
    regions[pick] = a;
    regions.push_back(b);
    whole.push_back(false);
  }
  for (const Region& r : regions)
  {
    vtkTyndallLight light;
    if (RegionLight(grid, r, light))
    {
      lights.push_back(light);
    }
  }
  return lights;
}
