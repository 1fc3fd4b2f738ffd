#include "vtkTyndallTransferTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

//------------------------------------------------------------------------------
bool vtkTyndallTransferTable::Build(vtkVolumeProperty* property, vtkColorTransferFunction* emission,
  double lo, double hi, std::string& error, bool linearExtinction, int function, int unitComponent)
{
  const double unitDistance = property->GetScalarOpacityUnitDistance(unitComponent);
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    std::ostringstream os;
    os << "the volume property's scalar opacity unit distance must be positive and finite; it is "
       << unitDistance << ".";
    error = os.str();
    return false;
  }
  this->Minimum = lo;
  this->Maximum = hi;
  this->EmissionFromArray = false;
  this->Transfer2D.clear(); // until Tabulate2D()
  this->Transfer2DSize[0] = this->Transfer2DSize[1] = 0;
  this->Scale = this->Maximum > this->Minimum ? (Size - 1) / (this->Maximum - this->Minimum) : 0.0;

  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(function);
  const bool gray = property->GetColorChannels(function) == 1;
  vtkPiecewiseFunction* grayFunction = gray ? property->GetGrayTransferFunction(function) : nullptr;
  vtkColorTransferFunction* rgbFunction =
    gray ? nullptr : property->GetRGBTransferFunction(function);
  this->Extinction.assign(Size, 0.0);
  this->Albedo.assign(3 * Size, 0.0);
  this->Emission.assign(3 * Size, 0.0);
  this->Opacity.assign(Size, 0.0);
  for (int i = 0; i < Size; ++i)
  {
    const double s = std::min(this->Scale > 0.0 ? lo + i / this->Scale : lo, hi);
    this->Opacity[i] = opacity->GetValue(s);
    this->Extinction[i] = linearExtinction
      ? std::max(s, 0.0)
      : vtkTransmittanceMapMath::ExtinctionFromOpacity(this->Opacity[i], unitDistance, 1.0);
    double* albedo = this->Albedo.data() + 3 * i;
    if (gray)
    {
      albedo[0] = albedo[1] = albedo[2] = grayFunction->GetValue(s);
    }
    else
    {
      rgbFunction->GetColor(s, albedo);
    }
    if (emission)
    {
      emission->GetColor(s, this->Emission.data() + 3 * i);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::TabulateEmission(
  double lo, double hi, const std::function<void(double, double[3])>& color)
{
  this->EmissionFromArray = true;
  this->EmissionMinimum = lo;
  this->EmissionEntries = hi > lo ? (Size - 1) / (hi - lo) : 0.0;
  this->Emission.assign(3 * Size, 0.0);
  for (int i = 0; i < Size; ++i)
  {
    const double v =
      std::min(this->EmissionEntries > 0.0 ? lo + i / this->EmissionEntries : lo, hi);
    color(v, this->Emission.data() + 3 * i);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::TabulateGradientOpacity(vtkPiecewiseFunction* function)
{
  this->GradientOpacity.clear();
  this->GradientMaximum =
    0.25 * (this->Maximum > this->Minimum ? this->Maximum - this->Minimum : 1.0);
  if (!function)
  {
    return;
  }
  this->GradientOpacity.resize(Size);
  for (int i = 0; i < Size; ++i)
  {
    const double g = this->GradientMaximum * i / (Size - 1);
    this->GradientOpacity[i] = std::min(std::max(function->GetValue(g), 0.0), 1.0);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallTransferTable::Tabulate2D(
  vtkImageData* function, double distance, bool nearest, std::string& error)
{
  this->Transfer2DNearest = nearest;
  this->Transfer2D.clear();
  this->Transfer2DSize[0] = this->Transfer2DSize[1] = 0;
  vtkDataArray* values =
    function ? function->GetPointData()->GetScalars() : static_cast<vtkDataArray*>(nullptr);
  int dims[3] = { 0, 0, 0 };
  if (function)
  {
    function->GetDimensions(dims);
  }
  std::ostringstream os;
  if (!function || !values || dims[0] < 1 || dims[1] < 1 || dims[2] != 1 ||
    values->GetNumberOfComponents() != 4 ||
    values->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    os << "the property's 2-D transfer function must be a W x H x 1 image of 4-component point "
          "scalars (RGBA)";
    if (function)
    {
      os << "; it is " << dims[0] << " x " << dims[1] << " x " << dims[2] << " of "
         << (values ? values->GetNumberOfComponents() : 0) << " components";
    }
    error = os.str() + ".";
    return false;
  }
  if (dims[0] > Largest2D || dims[1] > Largest2D)
  {
    os << "the property's 2-D transfer function is " << dims[0] << " x " << dims[1]
       << " pixels; at most " << Largest2D << " on each side (VTK's texture of it would be "
       << "larger still).";
    error = os.str();
    return false;
  }
  const vtkIdType count = values->GetNumberOfTuples();
  std::vector<float> rgba(4 * static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double v = values->GetComponent(i, c);
      if (!(v >= 0.0 && v <= 1.0))
      {
        os << "the property's 2-D transfer function has " << (c < 3 ? "a colour" : "an opacity")
           << " of " << v << " at pixel " << i << "; each lies in [0, 1].";
        error = os.str();
        return false;
      }
      rgba[4 * i + c] = static_cast<float>(v);
    }
  }
  this->Resample2D(rgba, dims);
  // The extinction row, an upper bound of the function's extinction between
  // entries i - 1 and i + 1 (so that interpolating the row bounds it too):
  // the largest opacity of the pixel columns that reach that stretch of u,
  // over every gradient.
  std::vector<double> columns(dims[0], 0.0);
  for (int x = 0; x < dims[0]; ++x)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      columns[x] =
        std::max(columns[x], static_cast<double>(this->Transfer2D[4 * (y * dims[0] + x) + 3]));
    }
  }
  for (int i = 0; i < Size; ++i)
  {
    const double lo = std::max(i - 1, 0) / (Size - 1.0) * dims[0] - 0.5;
    const double hi = std::min(i + 1, Size - 1) / (Size - 1.0) * dims[0] - 0.5;
    const int first = std::max(static_cast<int>(std::floor(lo)) - 1, 0);
    const int last = std::min(static_cast<int>(std::ceil(hi)) + 1, dims[0] - 1);
    double largest = 0.0;
    for (int x = first; x <= last; ++x)
    {
      largest = std::max(largest, columns[x]);
    }
    this->Extinction[i] =
      vtkTransmittanceMapMath::ExtinctionFromOpacity(std::min(largest, 0.999999), distance, 1.0);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::Resample2D(std::vector<float>& rgba, int dims[3])
{
  // VTK 9.1's texture (vtkOpenGLVolumeLookupTable::GetMaximumSupportedTextureWidth()):
  // each side the next power of two, at least 1024 (a height of 1 stays 1).
  const int width = std::max(vtkMath::NearestPowerOfTwo(dims[0]), 1024);
  const int height = dims[1] > 1 ? std::max(vtkMath::NearestPowerOfTwo(dims[1]), 1024) : 1;
  if (width != dims[0] || height != dims[1])
  {
    // vtkOpenGLVolumeTransferFunction2D's resampling: vtkImageResize at its
    // defaults (a Lanczos sinc, the corner pixels' centres kept).
    vtkNew<vtkImageData> image;
    image->SetDimensions(dims[0], dims[1], 1);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfComponents(4);
    values->SetArray(rgba.data(), static_cast<vtkIdType>(rgba.size()), 1);
    image->GetPointData()->SetScalars(values);
    vtkNew<vtkImageResize> resize;
    resize->SetInputData(image);
    resize->SetResizeMethodToOutputDimensions();
    resize->SetOutputDimensions(width, height, 1);
    resize->Update();
    auto* resampled =
      vtkFloatArray::SafeDownCast(resize->GetOutput()->GetPointData()->GetScalars());
    const float* first = resampled->GetPointer(0);
    std::vector<float> table(first, first + 4 * static_cast<size_t>(width) * height);
    // The sinc rings a little past a hard edge: VTK composites no negative
    // opacity; colour and opacity are kept in [0, 1] (an albedo's range).
    for (float& v : table)
    {
      v = std::min(std::max(v, 0.0f), 1.0f);
    }
    rgba.swap(table);
    dims[0] = width;
    dims[1] = height;
  }
  this->Transfer2D.swap(rgba);
  this->Transfer2DSize[0] = dims[0];
  this->Transfer2DSize[1] = dims[1];
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::Transfer2DAt(double u, double g, double rgba[4]) const
{
  const int w = this->Transfer2DSize[0], h = this->Transfer2DSize[1];
  if (this->Transfer2DNearest)
  {
    // The pixel u and g fall in (the GPU's nearest filtering).
    const int i = std::min(std::max(static_cast<int>(std::floor(u * w)), 0), w - 1);
    const int j = std::min(std::max(static_cast<int>(std::floor(g * h)), 0), h - 1);
    const float* p = this->Transfer2D.data() + 4 * (static_cast<size_t>(j) * w + i);
    std::copy(p, p + 4, rgba);
    return;
  }
  // Pixel centres at (i + 0.5) / W: the position in pixels, clamped to the centres.
  const double x = std::min(std::max(u * w - 0.5, 0.0), w - 1.0);
  const double y = std::min(std::max(g * h - 0.5, 0.0), h - 1.0);
  const int i = std::min(static_cast<int>(x), std::max(w - 2, 0));
  const int j = std::min(static_cast<int>(y), std::max(h - 2, 0));
  const int i1 = std::min(i + 1, w - 1), j1 = std::min(j + 1, h - 1);
  const double fx = x - i, fy = y - j;
  const float* p00 = this->Transfer2D.data() + 4 * (static_cast<size_t>(j) * w + i);
  const float* p10 = this->Transfer2D.data() + 4 * (static_cast<size_t>(j) * w + i1);
  const float* p01 = this->Transfer2D.data() + 4 * (static_cast<size_t>(j1) * w + i);
  const float* p11 = this->Transfer2D.data() + 4 * (static_cast<size_t>(j1) * w + i1);
  for (int c = 0; c < 4; ++c)
  {
    const double bottom = p00[c] + fx * (p10[c] - p00[c]);
    const double top = p01[c] + fx * (p11[c] - p01[c]);
    rgba[c] = bottom + fy * (top - bottom);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::GetTexture(std::vector<float>& rgba) const
{
  rgba.assign(4 * Rows * static_cast<size_t>(Size), 0.0f);
  float* albedo = rgba.data() + 4 * static_cast<size_t>(AlbedoRow) * Size;
  float* emission = rgba.data() + 4 * static_cast<size_t>(EmissionRow) * Size;
  float* gradient = rgba.data() + 4 * static_cast<size_t>(GradientRow) * Size;
  for (int i = 0; i < Size; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      albedo[4 * i + c] = static_cast<float>(this->Albedo[3 * i + c]);
      emission[4 * i + c] = static_cast<float>(this->Emission[3 * i + c]);
    }
    albedo[4 * i + 3] = static_cast<float>(this->Extinction[i]);
    emission[4 * i + 3] = static_cast<float>(this->Opacity[i]);
    gradient[4 * i] =
      this->GradientOpacity.empty() ? 1.0f : static_cast<float>(this->GradientOpacity[i]);
  }
}
