#include "vtkTyndallLabelMap.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <set>

//------------------------------------------------------------------------------
bool vtkTyndallLabelMap::ReadLabels(vtkDataArray* values, vtkIdType count, std::ostream& error)
{
  this->Labels.assign(static_cast<size_t>(count), 0);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double v = values->GetComponent(i, 0);
    if (!std::isfinite(v))
    {
      error << "its value at sample " << i << " is " << v << "; a label map's values are finite.";
      this->Labels.clear();
      return false;
    }
    const double label = std::min(std::max(std::round(v), 0.0), double(MaximumLabel));
    this->Labels[static_cast<size_t>(i)] = static_cast<unsigned char>(label);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallLabelMap::Clear()
{
  this->Labels.clear();
  this->Rows.clear();
  this->RowCount = 0;
}

//------------------------------------------------------------------------------
void vtkTyndallLabelMap::ClearRows()
{
  this->Rows.clear();
  this->RowCount = 0;
}

//------------------------------------------------------------------------------
void vtkTyndallLabelMap::Tabulate(
  vtkVolumeProperty* property, double minimum, double maximum, double blend, double step)
{
  this->Blend = blend;
  this->Step = step;
  const std::set<int> labels = property->GetLabelMapLabels();
  this->RowCount = labels.empty() ? 0 : std::min(*labels.rbegin(), int(MaximumLabel));
  this->Rows.assign(4 * static_cast<size_t>(Width) * (this->RowCount + 1), 0.0f);
  std::vector<double> rgb(3 * Width), opacity(Width);
  for (int row = 1; row <= this->RowCount; ++row)
  {
    // A label without its own functions reads the property's (VTK's rule;
    // a grey property's grey function, without making it an RGB one).
    vtkColorTransferFunction* color = property->GetLabelColor(row);
    vtkPiecewiseFunction* gray = nullptr;
    if (!color && property->GetColorChannels(0) == 1)
    {
      gray = property->GetGrayTransferFunction(0);
    }
    else if (!color)
    {
      color = property->GetRGBTransferFunction(0);
    }
    vtkPiecewiseFunction* alpha = property->GetLabelScalarOpacity(row);
    alpha = alpha ? alpha : property->GetScalarOpacity(0);
    std::fill(rgb.begin(), rgb.end(), 1.0);
    std::fill(opacity.begin(), opacity.end(), 1.0);
    if (color)
    {
      color->GetTable(minimum, maximum, Width, rgb.data());
    }
    else if (gray)
    {
      std::vector<double> values(Width);
      gray->GetTable(minimum, maximum, Width, values.data());
      for (int i = 0; i < Width; ++i)
      {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = values[i];
      }
    }
    if (alpha)
    {
      alpha->GetTable(minimum, maximum, Width, opacity.data());
    }
    float* out = this->Rows.data() + 4 * static_cast<size_t>(Width) * row;
    for (int i = 0; i < Width; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        out[4 * i + c] = static_cast<float>(std::min(std::max(rgb[3 * i + c], 0.0), 1.0));
      }
      out[4 * i + 3] = static_cast<float>(std::min(std::max(opacity[i], 0.0), 1.0));
    }
  }
}

//------------------------------------------------------------------------------
int vtkTyndallLabelMap::Entry(double u)
{
  const double x = std::floor(u * Width);
  return static_cast<int>(std::min(std::max(x, 0.0), Width - 1.0));
}

//------------------------------------------------------------------------------
double vtkTyndallLabelMap::Mix(
  int label, int entry, double sigma, double density, double color[3]) const
{
  if (label <= 0 || !this->Enabled())
  {
    return sigma;
  }
  const int row = std::min(label, this->RowCount);
  const float* rgba = this->Rows.data() + 4 * (static_cast<size_t>(Width) * row + entry);
  const double f = this->Blend;
  const double own = density > 0.0 ? 1.0 - std::exp(-sigma / density * this->Step) : 0.0;
  const double alpha = std::min((1.0 - f) * own + f * rgba[3], 0.999999);
  for (int c = 0; c < 3; ++c)
  {
    // VTK mixes in a colour of 0 where the volume's opacity is 0.
    color[c] = (1.0 - f) * (own > 0.0 ? color[c] : 0.0) + f * rgba[c];
  }
  return density * -std::log1p(-alpha) / this->Step;
}

//------------------------------------------------------------------------------
std::vector<double> vtkTyndallLabelMap::Bound(const std::vector<double>& extinction) const
{
  std::vector<double> bound = extinction;
  if (!this->Enabled() || extinction.size() < 2)
  {
    return bound;
  }
  // The mix's opacity is at most the larger of the two: the extinction at
  // most the larger of the volume's and the rows' (density 1).
  std::vector<double> rows(Width, 0.0);
  for (int i = 0; i < Width; ++i)
  {
    for (int row = 1; row <= this->RowCount; ++row)
    {
      const double a = std::min(
        static_cast<double>(this->Rows[4 * (static_cast<size_t>(Width) * row + i) + 3]), 0.999999);
      rows[i] = std::max(rows[i], -std::log1p(-a) / this->Step);
    }
  }
  // Table entry k (of n over the same range) stands for u in
  // [(k - 1) / (n - 1), (k + 1) / (n - 1)] (linear interpolation between
  // its neighbours): the rows' entries over that stretch.
  const size_t n = extinction.size();
  for (size_t k = 0; k < n; ++k)
  {
    const double lo = (k > 0 ? k - 1.0 : 0.0) / (n - 1.0);
    const double hi = std::min(k + 1.0, n - 1.0) / (n - 1.0);
    double largest = 0.0;
    for (int i = Entry(lo); i <= Entry(hi); ++i)
    {
      largest = std::max(largest, rows[i]);
    }
    bound[k] = std::max(bound[k], largest);
  }
  return bound;
}
