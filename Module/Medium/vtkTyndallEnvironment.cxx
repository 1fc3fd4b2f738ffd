#include "vtkTyndallEnvironment.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace
{

// The mean of a texel's three channels: its weight in the sampling.
double Luminance(const float* L)
{
  return (static_cast<double>(L[0]) + L[1] + L[2]) / 3.0;
}

// The smallest k in [0, n - 1] with table[k] > u (table: the n cumulative
// probabilities of n bins, the last 1; u in [0, 1)): a bin of probability
// above 0 (its start, table[k - 1] or 0, is at most u).
int Search(const float* table, int n, double u)
{
  int low = 0;
  int high = n - 1;
  while (low < high)
  {
    const int middle = (low + high) / 2;
    if (table[middle] > u)
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  return low;
}

// Cumulative sums of `weights` normalised to end at 1 (table: n values, the
// last exactly 1); all zero weights give a uniform table. Returns the sum.
double Accumulate(const std::vector<double>& weights, float* table)
{
  const int n = static_cast<int>(weights.size());
  double sum = 0.0;
  for (double w : weights)
  {
    sum += w;
  }
  double running = 0.0;
  for (int k = 0; k < n; ++k)
  {
    running += weights[k];
    table[k] = static_cast<float>(sum > 0.0 ? running / sum : (k + 1.0) / n);
  }
  table[n - 1] = 1.0f;
  return sum;
}

// Whether n doubles are the same bits (a NaN setting is then the same
// setting, not a change every frame).
bool Same(const double* a, const double* b, int n)
{
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// Whether v is a radiance the tables hold: not negative, at most
// vtkTyndallEnvironment::MaximumRadiance (the GPU's float sums stay finite).
bool Usable(double v)
{
  return v >= 0.0 && v <= vtkTyndallEnvironment::MaximumRadiance;
}

// The sRGB decoding of IEC 61966-2-1, continued past 1 (a float texture
// marked sRGB keeps its highlights).
double DecodeSRGB(double v)
{
  return v < 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
}

//------------------------------------------------------------------------------
bool vtkTyndallEnvironment::Key::operator==(const Key& o) const
{
  return this->Image == o.Image && this->Texture == o.Texture &&
    this->TextureTime == o.TextureTime && this->Gradient == o.Gradient &&
    Same(this->Colors, o.Colors, 6) && Same(this->Up, o.Up, 3) && Same(this->Right, o.Right, 3);
}

//------------------------------------------------------------------------------
vtkTyndallEnvironment::Key vtkTyndallEnvironment::MakeKey(
  vtkRenderer* renderer, vtkImageData*& image)
{
  Key key;
  image = nullptr;
  if (!renderer)
  {
    return key; // black
  }
  renderer->GetEnvironmentalBG(key.Colors);
  renderer->GetEnvironmentalBG2(key.Colors + 3);
  key.Gradient = renderer->GetGradientEnvironmentalBG();
  renderer->GetEnvironmentUp(key.Up);
  renderer->GetEnvironmentRight(key.Right);
  vtkTexture* texture = renderer->GetEnvironmentTexture();
  if (renderer->GetUseImageBasedLighting() && texture)
  {
    int port = 0;
    if (vtkAlgorithm* producer = texture->GetNumberOfInputConnections(0) > 0
        ? texture->GetInputAlgorithm(0, 0, port)
        : nullptr)
    {
      producer->Update(port);
    }
    image = texture->GetInput();
    key.Image = image != nullptr || texture->GetCubeMap();
    key.Texture = texture;
    key.TextureTime = std::max(texture->GetMTime(), image ? image->GetMTime() : 0);
  }
  return key;
}

//------------------------------------------------------------------------------
bool vtkTyndallEnvironment::Update(vtkRenderer* renderer, vtkObject* reporter)
{
  vtkImageData* image = nullptr;
  const Key key = MakeKey(renderer, image);
  if (this->Read && key == this->Last)
  {
    return this->LastOk;
  }
  std::string why;
  this->LastOk = this->Build(key, image, why);
  if (!this->LastOk)
  {
    this->Clear();
    vtkErrorWithObjectMacro(reporter, << "The renderer's environment is not used: " << why);
  }
  this->Last = key;
  this->Read = true;
  ++this->Serial;
  return this->LastOk;
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::Clear()
{
  this->Width = this->Height = 1;
  this->Radiance.assign(3, 0.0f);
  this->Tabulate();
}

//------------------------------------------------------------------------------
bool vtkTyndallEnvironment::SetFrame(const double up[3], const double right[3], std::string& why)
{
  double u[3] = { up[0], up[1], up[2] };
  double r[3] = { right[0], right[1], right[2] };
  const double length = vtkMath::Normalize(u);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    why = "its up vector (EnvironmentUp) has no direction.";
    return false;
  }
  const double along = vtkMath::Dot(r, u);
  for (int c = 0; c < 3; ++c)
  {
    r[c] -= along * u[c];
  }
  const double across = vtkMath::Normalize(r);
  if (!(across > 1e-6 * vtkMath::Norm(right)) || !std::isfinite(across))
  {
    why = "its right vector (EnvironmentRight) is parallel to its up vector or has no direction.";
    return false;
  }
  std::copy(u, u + 3, this->Up);
  std::copy(r, r + 3, this->Right);
  vtkMath::Cross(this->Up, this->Right, this->Front);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallEnvironment::Build(const Key& key, vtkImageData* image, std::string& why)
{
  // A black sky lights nothing: its frame is not read (VTK's defaults with
  // any up vector). The colours read: the gradient's two, or one.
  const double* colorsEnd = key.Colors + (key.Gradient ? 6 : 3);
  const bool black =
    !key.Image && std::all_of(key.Colors, colorsEnd, [](double c) { return c == 0.0; });
  if (black)
  {
    this->Clear();
    return true;
  }
  if (!this->SetFrame(key.Up, key.Right, why))
  {
    return false;
  }
  if (key.Image && (!image || key.Texture->GetCubeMap()))
  {
    why = "a cube map is not read (give the environment texture an equirectangular image).";
    return false;
  }
  if (key.Image)
  {
    if (!this->ReadImage(image, key.Texture->GetUseSRGBColorSpace(), why))
    {
      return false;
    }
  }
  else
  {
    for (const double* c = key.Colors; c != colorsEnd; ++c)
    {
      if (!Usable(*c))
      {
        why = "its colours (EnvironmentalBG, EnvironmentalBG2) must be in [0, 1e20].";
        return false;
      }
    }
    this->Width = 1;
    this->Height = key.Gradient ? GradientRows : 1;
    this->Radiance.resize(3 * this->Height);
    for (int j = 0; j < this->Height; ++j)
    {
      const double f = key.Gradient ? (j + 0.5) / this->Height : 0.0;
      for (int c = 0; c < 3; ++c)
      {
        this->Radiance[3 * j + c] =
          static_cast<float>((1.0 - f) * key.Colors[c] + f * key.Colors[3 + c]);
      }
    }
  }
  this->Tabulate();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallEnvironment::ReadImage(vtkImageData* image, bool srgb, std::string& why)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  std::ostringstream reason;
  if (!scalars || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    reason << "its image is not a 2-D image with scalars (" << dims[0] << " x " << dims[1] << " x "
           << dims[2] << ").";
  }
  else if (dims[0] > MaximumImageSide || dims[1] > MaximumImageSide)
  {
    reason << "its image (" << dims[0] << " x " << dims[1] << ") has a side above "
           << MaximumImageSide << " texels.";
  }
  else if (scalars->GetNumberOfComponents() > 4)
  {
    reason << "its image has " << scalars->GetNumberOfComponents()
           << " components (1 to 4 are read).";
  }
  if (!reason.str().empty())
  {
    why = reason.str();
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  // Integers are display values: scaled to [0, 1] by their type's largest
  // and sRGB-decoded; floating point is linear radiance (decoded only when
  // the texture says it is sRGB).
  const int type = scalars->GetDataType();
  const bool integer = type != VTK_FLOAT && type != VTK_DOUBLE;
  if (integer && scalars->GetDataTypeSize() > 2)
  {
    why = std::string("its image's type (") + scalars->GetDataTypeAsString() +
      ") is not read: 8- or 16-bit integers, or floating point.";
    return false;
  }
  const double unit = integer ? 1.0 / scalars->GetDataTypeMax() : 1.0;
  srgb = srgb || integer;
  this->Width = dims[0];
  this->Height = dims[1];
  const vtkIdType texels = static_cast<vtkIdType>(this->Width) * this->Height;
  this->Radiance.resize(3 * texels);
  vtkIdType bad = 0;
  for (vtkIdType t = 0; t < texels; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      double v = unit * scalars->GetComponent(t, components < 3 ? 0 : c);
      if (!Usable(v))
      {
        ++bad;
        v = 0.0;
      }
      v = srgb ? DecodeSRGB(v) : v;
      this->Radiance[3 * t + c] = static_cast<float>(v);
    }
  }
  if (bad > 0)
  {
    reason << "its image holds " << bad << " negative, NaN or infinite values (or above "
           << MaximumRadiance << ").";
    why = reason.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallEnvironment::SolidAngle(int j) const
{
  const double e0 = vtkMath::Pi() * (static_cast<double>(j) / this->Height - 0.5);
  const double e1 = vtkMath::Pi() * (static_cast<double>(j + 1) / this->Height - 0.5);
  return 2.0 * vtkMath::Pi() / this->Width * (std::sin(e1) - std::sin(e0));
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::Tabulate()
{
  const int W = this->Width;
  const int H = this->Height;
  this->RowTable.assign(H, 0.0f);
  this->ColumnTable.assign(static_cast<size_t>(H) * W, 0.0f);
  std::vector<double> rows(H), columns(W);
  double mean[3] = { 0.0, 0.0, 0.0 };
  for (int j = 0; j < H; ++j)
  {
    const double omega = this->SolidAngle(j);
    for (int i = 0; i < W; ++i)
    {
      const float* L = &this->Radiance[3 * (static_cast<size_t>(j) * W + i)];
      columns[i] = Luminance(L) * omega;
      for (int c = 0; c < 3; ++c)
      {
        mean[c] += L[c] * omega;
      }
    }
    rows[j] = Accumulate(columns, &this->ColumnTable[static_cast<size_t>(j) * W]);
  }
  this->Total = Accumulate(rows, this->RowTable.data());
  for (int c = 0; c < 3; ++c)
  {
    this->Mean[c] = mean[c] / (4.0 * vtkMath::Pi());
  }
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::Texel(const double w[3], int& i, int& j) const
{
  const double x = vtkMath::Dot(w, this->Right);
  const double y = vtkMath::Dot(w, this->Up);
  const double z = vtkMath::Dot(w, this->Front);
  const double u = 0.5 + std::atan2(x, z) / (2.0 * vtkMath::Pi());
  const double v = 0.5 + std::atan2(y, std::sqrt(x * x + z * z)) / vtkMath::Pi();
  i = std::min(std::max(static_cast<int>(std::floor(u * this->Width)), 0), this->Width - 1);
  j = std::min(std::max(static_cast<int>(std::floor(v * this->Height)), 0), this->Height - 1);
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::Direction(double u, double v, double w[3]) const
{
  const double phi = 2.0 * vtkMath::Pi() * (u / this->Width - 0.5);
  const double elevation = vtkMath::Pi() * (v / this->Height - 0.5);
  const double x = std::cos(elevation) * std::sin(phi);
  const double y = std::sin(elevation);
  const double z = std::cos(elevation) * std::cos(phi);
  this->FromFrame(x, y, z, w);
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::FromFrame(double x, double y, double z, double w[3]) const
{
  for (int c = 0; c < 3; ++c)
  {
    w[c] = x * this->Right[c] + y * this->Up[c] + z * this->Front[c];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallEnvironment::Evaluate(const double w[3], double L[3]) const
{
  int i, j;
  this->Texel(w, i, j);
  const float* texel = &this->Radiance[3 * (static_cast<size_t>(j) * this->Width + i)];
  std::copy(texel, texel + 3, L);
}

//------------------------------------------------------------------------------
double vtkTyndallEnvironment::Pdf(const double w[3]) const
{
  if (!this->Enabled())
  {
    return 0.0;
  }
  int i, j;
  this->Texel(w, i, j);
  return Luminance(&this->Radiance[3 * (static_cast<size_t>(j) * this->Width + i)]) / this->Total;
}

//------------------------------------------------------------------------------
double vtkTyndallEnvironment::Sample(const double u[4], double w[3], double L[3]) const
{
  if (!this->Enabled())
  {
    L[0] = L[1] = L[2] = 0.0;
    return 0.0;
  }
  const int W = this->Width;
  const int H = this->Height;
  const int j = Search(this->RowTable.data(), H, u[0]);
  const int i = Search(&this->ColumnTable[static_cast<size_t>(j) * W], W, u[1]);
  const double phi = 2.0 * vtkMath::Pi() * ((i + u[2]) / W - 0.5);
  const double s0 = std::sin(vtkMath::Pi() * (static_cast<double>(j) / H - 0.5));
  const double s1 = std::sin(vtkMath::Pi() * (static_cast<double>(j + 1) / H - 0.5));
  const double s = std::min(1.0, std::max(-1.0, s0 + u[3] * (s1 - s0)));
  const double rho = std::sqrt(std::max(0.0, 1.0 - s * s));
  const double x = rho * std::sin(phi);
  const double z = rho * std::cos(phi);
  this->FromFrame(x, s, z, w);
  const float* texel = &this->Radiance[3 * (static_cast<size_t>(j) * W + i)];
  std::copy(texel, texel + 3, L);
  return Luminance(texel) / this->Total;
}
