#include "vtkSingleScatteringReference.h"

#include "vtkAbstractMapper.h"
#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkSingleScatteringReference);
vtkCxxSetObjectMacro(vtkSingleScatteringReference, EmissionColor, vtkColorTransferFunction);

namespace
{
constexpr double kPi = 3.14159265358979323846;
// The model's cap on the opacity, which keeps the extinction finite.
constexpr double kMaxAlpha = 1.0 - 1.0e-6;
// The most steps one ray may take across the volume's box.
constexpr double kMaxStepsPerRay = 1.0e7;
constexpr int kMaxImageSize = 16384;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double Normalize(double v[3])
{
  const double length = std::sqrt(Dot(v, v));
  if (length > 0.0)
  {
    v[0] /= length;
    v[1] /= length;
    v[2] /= length;
  }
  return length;
}

// Clips the parameter interval [t0, t1] of the ray o + t d to the box
// [0, boxMax] (all in index space); false if nothing is left.
inline bool ClipToBox(
  const double o[3], const double d[3], const double boxMax[3], double& t0, double& t1)
{
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < 0.0 || o[a] > boxMax[a])
      {
        return false;
      }
      continue;
    }
    const double inv = 1.0 / d[a];
    double ta = -o[a] * inv;
    double tb = (boxMax[a] - o[a]) * inv;
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

// One-component scalars, trilinearly interpolated at continuous point
// indices (relative to the extent's start), clamped at the border. Cell
// scalars are the point scalars of the cell centres: Offset -0.5 on the axes
// with cells.
template <typename T>
struct ScalarField
{
  const T* Data = nullptr;
  int Dims[3] = { 1, 1, 1 };
  vtkIdType Stride[3] = { 1, 1, 1 };
  double Offset[3] = { 0.0, 0.0, 0.0 };

  double Sample(const double p[3]) const
  {
    vtkIdType base = 0;
    vtkIdType step[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const int n = this->Dims[a];
      double x = p[a] + this->Offset[a];
      x = x > 0.0 ? (x < n - 1 ? x : n - 1) : 0.0;
      int i = static_cast<int>(x);
      if (i > n - 2)
      {
        i = n > 1 ? n - 2 : 0;
      }
      f[a] = x - i;
      base += i * this->Stride[a];
      step[a] = n > 1 ? this->Stride[a] : 0;
    }
    const T* d = this->Data + base;
    const double c000 = static_cast<double>(d[0]);
    const double c100 = static_cast<double>(d[step[0]]);
    const double c010 = static_cast<double>(d[step[1]]);
    const double c110 = static_cast<double>(d[step[0] + step[1]]);
    const double c001 = static_cast<double>(d[step[2]]);
    const double c101 = static_cast<double>(d[step[0] + step[2]]);
    const double c011 = static_cast<double>(d[step[1] + step[2]]);
    const double c111 = static_cast<double>(d[step[0] + step[1] + step[2]]);
    const double c00 = c000 + f[0] * (c100 - c000);
    const double c10 = c010 + f[0] * (c110 - c010);
    const double c01 = c001 + f[0] * (c101 - c001);
    const double c11 = c011 + f[0] * (c111 - c011);
    const double c0 = c00 + f[1] * (c10 - c00);
    const double c1 = c01 + f[1] * (c11 - c01);
    return c0 + f[2] * (c1 - c0);
  }
};

// Finite range and count of NaN values of the scalars.
template <typename T>
void ScanScalars(const T* data, vtkIdType n, double range[2], vtkIdType& nonFinite)
{
  range[0] = kInfinity;
  range[1] = -kInfinity;
  nonFinite = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = static_cast<double>(data[i]);
    if (!std::isfinite(v))
    {
      ++nonFinite;
      continue;
    }
    range[0] = std::min(range[0], v);
    range[1] = std::max(range[1], v);
  }
}

// Transfer functions tabulated over the scalar range, read with linear
// interpolation.
struct Tables
{
  int Size = 2;
  double SMin = 0.0;
  double Scale = 0.0; // entries per scalar unit
  std::vector<double> Alpha;
  std::vector<double> Color;    // RGB
  std::vector<double> Emission; // RGB; empty without emission

  void Locate(double s, int& k, double& f) const
  {
    double x = (s - this->SMin) * this->Scale;
    x = x > 0.0 ? (x < this->Size - 1 ? x : this->Size - 1) : 0.0;
    k = std::min(static_cast<int>(x), this->Size - 2);
    f = x - k;
  }
  double AlphaAt(int k, double f) const
  {
    return this->Alpha[k] + f * (this->Alpha[k + 1] - this->Alpha[k]);
  }
  static void RGBAt(const std::vector<double>& table, int k, double f, double rgb[3])
  {
    const double* a = table.data() + 3 * k;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = a[c] + f * (a[c + 3] - a[c]);
    }
  }
};

struct LightSource
{
  bool Positional = false;
  double ToLight[3] = { 0.0, 0.0, 1.0 };        // directional: unit, world
  double ToLightIndex[3] = { 0.0, 0.0, 1.0 };   // the same in index space
  double Position[3] = { 0.0, 0.0, 0.0 };       // positional, world
  double SpotDirection[3] = { 0.0, 0.0, -1.0 }; // unit, from the light to its focal point
  bool Spot = false;
  double CosCone = -1.0;
  double Exponent = 0.0;
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  double E[3] = { 0.0, 0.0, 0.0 }; // LightScale * Intensity * DiffuseColor
};

// Everything the rendering loop reads; read only inside the loop.
struct Scene
{
  int Width = 1;
  int Height = 1;
  double InverseProjection[16]; // world <- normalised device coordinates
  double A[3][3];               // world -> index: A x + B
  double B[3];
  double BoxMax[3];
  bool EmptyBox = false;
  double Step = 1.0;
  double LightStep = 1.0;
  double Threshold = 0.0;
  double MaxOpticalDepth = kInfinity;
  double DensityFactor = 1.0; // DensityScale / unit distance
  bool SingleScattering = true;
  double G = 0.0;
  double Ambient = 0.0;
  double EmissionScale = 0.0;
  std::vector<LightSource> Lights;
  Tables Tab;
  double* Radiance = nullptr;
  double* Transmittance = nullptr;

  void ToIndexDirection(const double w[3], double d[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      d[r] = this->A[r][0] * w[0] + this->A[r][1] * w[1] + this->A[r][2] * w[2];
    }
  }
  void ToIndexPoint(const double x[3], double p[3]) const
  {
    this->ToIndexDirection(x, p);
    for (int r = 0; r < 3; ++r)
    {
      p[r] += this->B[r];
    }
  }
  double Phase(double mu) const
  {
    const double g = this->G;
    const double denominator = 1.0 + g * g - 2.0 * g * mu;
    return (1.0 - g * g) / (4.0 * kPi * denominator * std::sqrt(denominator));
  }
};

template <typename T>
class RowRenderer
{
public:
  const Scene* S;
  ScalarField<T> Field;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType j = begin; j < end; ++j)
    {
      for (int i = 0; i < this->S->Width; ++i)
      {
        const vtkIdType pixel = j * this->S->Width + i;
        this->RenderPixel(
          i, static_cast<int>(j), this->S->Radiance + 3 * pixel, this->S->Transmittance[pixel]);
      }
    }
  }

private:
  // The extinction at an index-space point and its table position; false
  // for empty medium (zero opacity or a NaN scalar).
  bool Extinction(const double p[3], double& sigma, int& k, double& f) const
  {
    const double s = this->Field.Sample(p);
    if (std::isnan(s))
    {
      return false;
    }
    this->S->Tab.Locate(s, k, f);
    const double alpha = this->S->Tab.AlphaAt(k, f);
    if (!(alpha > 0.0))
    {
      return false;
    }
    sigma = -this->S->DensityFactor * std::log1p(-std::min(alpha, kMaxAlpha));
    return sigma > 0.0;
  }

  // T_l from the index-space point p along the index-space image d of a unit
  // world direction, up to the box's exit or the world distance tMax.
  double LightTransmittance(const double p[3], const double d[3], double tMax) const
  {
    double t0 = 0.0, t1 = tMax;
    if (!ClipToBox(p, d, this->S->BoxMax, t0, t1))
    {
      return 1.0;
    }
    const double length = t1;
    const double steps = std::max(1.0, std::ceil(length / this->S->LightStep));
    const int n = static_cast<int>(steps);
    const double dt = length / n;
    double tau = 0.0;
    for (int m = 0; m < n; ++m)
    {
      const double t = (m + 0.5) * dt;
      const double q[3] = { p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2] };
      double sigma;
      int k;
      double f;
      if (this->Extinction(q, sigma, k, f))
      {
        tau += sigma * dt;
        if (tau > this->S->MaxOpticalDepth)
        {
          break;
        }
      }
    }
    return std::exp(-tau);
  }

  void RenderPixel(int i, int j, double* radiance, double& transmittance) const
  {
    const Scene& s = *this->S;
    radiance[0] = radiance[1] = radiance[2] = 0.0;
    transmittance = 1.0;
    if (s.EmptyBox)
    {
      return;
    }
    // Unproject the pixel centre at the near and far planes.
    const double ndc[2] = { 2.0 * (i + 0.5) / s.Width - 1.0, 2.0 * (j + 0.5) / s.Height - 1.0 };
    double ends[2][3];
    for (int e = 0; e < 2; ++e)
    {
      const double in[4] = { ndc[0], ndc[1], e == 0 ? -1.0 : 1.0, 1.0 };
      double out[4];
      vtkMatrix4x4::MultiplyPoint(s.InverseProjection, in, out);
      for (int c = 0; c < 3; ++c)
      {
        ends[e][c] = out[c] / out[3];
      }
    }
    const double* origin = ends[0];
    double w[3] = { ends[1][0] - origin[0], ends[1][1] - origin[1], ends[1][2] - origin[2] };
    const double rayLength = Normalize(w);
    if (!(rayLength > 0.0))
    {
      return;
    }
    double o[3], d[3];
    s.ToIndexPoint(origin, o);
    s.ToIndexDirection(w, d);
    double t0 = 0.0, t1 = rayLength;
    if (!ClipToBox(o, d, s.BoxMax, t0, t1))
    {
      return;
    }
    const double steps = std::max(1.0, std::ceil((t1 - t0) / s.Step));
    const int n = static_cast<int>(steps);
    const double dt = (t1 - t0) / n;

    double Tv = 1.0;
    double L[3] = { 0.0, 0.0, 0.0 };
    for (int m = 0; m < n; ++m)
    {
      const double t = t0 + (m + 0.5) * dt;
      const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      double sigma;
      int k;
      double f;
      if (!this->Extinction(p, sigma, k, f))
      {
        continue;
      }
      double J[3];
      double color[3];
      Tables::RGBAt(s.Tab.Color, k, f, color);
      if (!s.SingleScattering)
      {
        J[0] = color[0];
        J[1] = color[1];
        J[2] = color[2];
      }
      else
      {
        double in[3] = { s.Ambient, s.Ambient, s.Ambient };
        if (color[0] != 0.0 || color[1] != 0.0 || color[2] != 0.0)
        {
          const double x[3] = { origin[0] + t * w[0], origin[1] + t * w[1], origin[2] + t * w[2] };
          for (const LightSource& light : s.Lights)
          {
            this->AddLight(light, x, p, w, in);
          }
        }
        for (int c = 0; c < 3; ++c)
        {
          J[c] = color[c] * in[c];
        }
        if (!s.Tab.Emission.empty())
        {
          double e[3];
          Tables::RGBAt(s.Tab.Emission, k, f, e);
          for (int c = 0; c < 3; ++c)
          {
            J[c] += s.EmissionScale * e[c];
          }
        }
      }
      // The step's medium is constant: integrate it exactly.
      const double a = -std::expm1(-sigma * dt);
      for (int c = 0; c < 3; ++c)
      {
        L[c] += Tv * J[c] * a;
      }
      Tv *= 1.0 - a;
      if (Tv < s.Threshold)
      {
        break;
      }
    }
    radiance[0] = L[0];
    radiance[1] = L[1];
    radiance[2] = L[2];
    transmittance = Tv;
  }

  // Adds E * p(mu) * T_l of one light at the world point x (index point p)
  // seen along the camera ray direction w.
  void AddLight(const LightSource& light, const double x[3], const double p[3], const double w[3],
    double in[3]) const
  {
    const Scene& s = *this->S;
    double l[3], dl[3];
    double factor = 1.0;
    double tMax = kInfinity;
    if (light.Positional)
    {
      l[0] = light.Position[0] - x[0];
      l[1] = light.Position[1] - x[1];
      l[2] = light.Position[2] - x[2];
      const double r = Normalize(l);
      if (!(r > 0.0))
      {
        return;
      }
      const double denominator =
        light.Attenuation[0] + light.Attenuation[1] * r + light.Attenuation[2] * r * r;
      if (!(denominator > 0.0))
      {
        return;
      }
      factor = 1.0 / denominator;
      if (light.Spot)
      {
        const double cosPhi = -Dot(l, light.SpotDirection);
        if (cosPhi < light.CosCone)
        {
          return;
        }
        factor *= std::pow(std::max(0.0, cosPhi), light.Exponent);
      }
      if (!(factor > 0.0))
      {
        return;
      }
      tMax = r;
      s.ToIndexDirection(l, dl);
    }
    else
    {
      std::copy(light.ToLight, light.ToLight + 3, l);
      std::copy(light.ToLightIndex, light.ToLightIndex + 3, dl);
    }
    // mu = dot(-l, -w): the light travels along -l, the camera is along -w.
    const double weight = factor * s.Phase(Dot(l, w)) * this->LightTransmittance(p, dl, tMax);
    for (int c = 0; c < 3; ++c)
    {
      in[c] += light.E[c] * weight;
    }
  }
};

template <typename T>
void RenderRows(const Scene& scene, const T* data, const int dims[3], const double offset[3],
  vtkIdType begin, vtkIdType end)
{
  RowRenderer<T> renderer;
  renderer.S = &scene;
  renderer.Field.Data = data;
  for (int a = 0; a < 3; ++a)
  {
    renderer.Field.Dims[a] = dims[a];
    renderer.Field.Offset[a] = offset[a];
  }
  renderer.Field.Stride[0] = 1;
  renderer.Field.Stride[1] = dims[0];
  renderer.Field.Stride[2] = static_cast<vtkIdType>(dims[0]) * dims[1];
  vtkSMPTools::For(begin, end, 1, renderer);
}

void TabulateColor(vtkColorTransferFunction* rgb, vtkPiecewiseFunction* gray, const Tables& tab,
  std::vector<double>& table)
{
  table.resize(3 * static_cast<size_t>(tab.Size));
  for (int k = 0; k < tab.Size; ++k)
  {
    const double s = tab.Scale > 0.0 ? tab.SMin + k / tab.Scale : tab.SMin;
    if (rgb)
    {
      rgb->GetColor(s, table.data() + 3 * k);
    }
    else
    {
      const double g = gray->GetValue(s);
      table[3 * k] = table[3 * k + 1] = table[3 * k + 2] = g;
    }
  }
}
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::vtkSingleScatteringReference()
{
  this->Output = vtkImageData::New();
  this->CompositeOutput = vtkImageData::New();
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::~vtkSingleScatteringReference()
{
  this->SetEmissionColor(nullptr);
  this->Output->Delete();
  this->CompositeOutput->Delete();
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
void vtkSingleScatteringReference::UpdateProgress(double progress)
{
  this->Progress = progress;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Render(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  this->AbortExecute = false;
  this->Progress = 0.0;
  this->Output->Initialize();
  this->CompositeOutput->Initialize();
  this->InvokeEvent(vtkCommand::StartEvent);
  const auto start = std::chrono::steady_clock::now();
  const bool ok = this->RenderInternal(renderer, volume, width, height);
  this->InvokeEvent(vtkCommand::EndEvent);
  if (!ok)
  {
    this->Output->Initialize();
    return nullptr;
  }
  this->LastRenderTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Output;
}

//------------------------------------------------------------------------------
bool vtkSingleScatteringReference::RenderInternal(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  if (width < 1 || width > kMaxImageSize || height < 1 || height > kMaxImageSize)
  {
    vtkErrorMacro(<< "Render: the image size " << width << " x " << height << " is outside [1, "
                  << kMaxImageSize << "] on some axis.");
    return false;
  }
  if (!renderer || !volume)
  {
    vtkErrorMacro(<< "Render: " << (renderer ? "the volume" : "the renderer") << " is null.");
    return false;
  }
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  if (!mapper)
  {
    vtkErrorMacro(<< "Render: the volume has no mapper.");
    return false;
  }

  // The input, brought up to date.
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    int producerPort = 0;
    vtkAlgorithm* producer = mapper->GetInputAlgorithm(0, 0, producerPort);
    if (producer)
    {
      producer->Update(producerPort);
    }
  }
  vtkDataSet* input = mapper->GetDataSetInput();
  if (!input)
  {
    vtkErrorMacro(<< "Render: the volume's mapper has no input.");
    return false;
  }
  vtkImageData* image = vtkImageData::SafeDownCast(input);
  if (!image)
  {
    vtkErrorMacro(<< "Render: the mapper's input is a " << input->GetClassName()
                  << "; only vtkImageData is supported.");
    return false;
  }
  int extent[6];
  image->GetExtent(extent);
  if (extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5] ||
    image->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "Render: the input image is empty.");
    return false;
  }
  if (image->GetDirectionMatrix() && !image->GetDirectionMatrix()->IsIdentity())
  {
    vtkErrorMacro(<< "Render: the input image has a non-identity direction matrix, which is not "
                     "supported; orient the volume with the vtkVolume's matrix instead.");
    return false;
  }
  const double* spacing = image->GetSpacing();
  const double* imageOrigin = image->GetOrigin();
  for (int a = 0; a < 3; ++a)
  {
    if (spacing[a] == 0.0 || !std::isfinite(spacing[a]) || !std::isfinite(imageOrigin[a]))
    {
      vtkErrorMacro(<< "Render: the input image's spacing must be non-zero and finite and its "
                       "origin finite.");
      return false;
    }
  }
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
  }

  // The scalars, selected as the mapper selects them.
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!scalars)
  {
    vtkErrorMacro(<< "Render: the input image has no scalars to render (check the mapper's "
                     "scalar mode and array selection).");
    return false;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "Render: the scalars '" << (scalars->GetName() ? scalars->GetName() : "")
                  << "' have " << scalars->GetNumberOfComponents()
                  << " components; only one-component scalars are supported.");
    return false;
  }
  int fieldDims[3];
  double fieldOffset[3] = { 0.0, 0.0, 0.0 };
  for (int a = 0; a < 3; ++a)
  {
    fieldDims[a] = dims[a];
    if (cellFlag == 1 && dims[a] > 1)
    {
      fieldDims[a] = dims[a] - 1;
      fieldOffset[a] = -0.5;
    }
  }
  const vtkIdType expected = static_cast<vtkIdType>(fieldDims[0]) * fieldDims[1] * fieldDims[2];
  if (cellFlag != 0 && cellFlag != 1)
  {
    vtkErrorMacro(<< "Render: the selected scalars are field data, which cannot be rendered.");
    return false;
  }
  if (scalars->GetNumberOfTuples() != expected)
  {
    vtkErrorMacro(<< "Render: the scalars have " << scalars->GetNumberOfTuples()
                  << " values; the image needs " << expected << ".");
    return false;
  }

  // Raw access to the values: the array itself, or a copy in doubles.
  vtkSmartPointer<vtkDataArray> values = scalars;
  bool supportedType = false;
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(supportedType = true);
  }
  if (!supportedType || !scalars->HasStandardMemoryLayout())
  {
    vtkNew<vtkDoubleArray> copy;
    copy->DeepCopy(scalars);
    values = copy;
  }
  double range[2] = { 0.0, 0.0 };
  vtkIdType nonFinite = 0;
  switch (values->GetDataType())
  {
    vtkTemplateMacro(ScanScalars(
      static_cast<const VTK_TT*>(values->GetVoidPointer(0)), expected, range, nonFinite));
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< "Render: " << nonFinite
                    << " scalars are not finite; NaN samples are rendered as empty medium and "
                       "infinite ones take the transfer functions' end values.");
  }
  if (!(range[0] <= range[1]))
  {
    range[0] = range[1] = 0.0; // no finite value: every sample is empty
  }

  // The volume's placement: world -> continuous point index.
  vtkMatrix4x4* matrix = volume->GetMatrix();
  const double(*m)[4] = matrix->Element;
  bool affine = m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == 0.0 && m[3][3] == 1.0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      affine = affine && std::isfinite(m[r][c]);
    }
  }
  const double linear[9] = { m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1],
    m[2][2] };
  const double determinant = vtkMatrix3x3::Determinant(linear);
  if (!affine || determinant == 0.0 || !std::isfinite(determinant))
  {
    vtkErrorMacro(<< "Render: the volume's matrix must be affine and invertible.");
    return false;
  }
  double inverse[16];
  vtkMatrix4x4::Invert(*matrix->Element, inverse);

  Scene scene;
  scene.Width = width;
  scene.Height = height;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      scene.A[r][c] = inverse[4 * r + c] / spacing[r];
    }
    scene.B[r] = (inverse[4 * r + 3] - imageOrigin[r]) / spacing[r] - extent[2 * r];
    scene.BoxMax[r] = dims[r] - 1;
    scene.EmptyBox = scene.EmptyBox || dims[r] < 2;
  }

  // Steps: the world length of one index step along each axis.
  double minVoxel = kInfinity, diagonal = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const double column[3] = { m[0][a], m[1][a], m[2][a] };
    const double voxel = std::abs(spacing[a]) * std::sqrt(Dot(column, column));
    minVoxel = std::min(minVoxel, voxel);
    diagonal += voxel * (dims[a] - 1);
  }
  scene.Step = this->StepSize > 0.0 ? this->StepSize : minVoxel / 4.0;
  scene.LightStep = this->LightStepSize > 0.0 ? this->LightStepSize : scene.Step;
  if (!(scene.Step > 0.0) || !(scene.LightStep > 0.0) ||
    diagonal / std::min(scene.Step, scene.LightStep) > kMaxStepsPerRay)
  {
    vtkErrorMacro(<< "Render: the step " << scene.Step << " (light step " << scene.LightStep
                  << ") would take more than " << kMaxStepsPerRay
                  << " steps across the volume; set a larger StepSize / LightStepSize.");
    return false;
  }
  scene.Threshold = this->EarlyTerminationThreshold;
  scene.MaxOpticalDepth =
    this->EarlyTerminationThreshold > 0.0 ? -std::log(this->EarlyTerminationThreshold) : kInfinity;

  // The volume property, tabulated.
  vtkVolumeProperty* property = volume->GetProperty();
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    vtkErrorMacro(<< "Render: the scalar opacity unit distance must be positive; it is "
                  << unitDistance << ".");
    return false;
  }
  scene.DensityFactor = this->DensityScale / unitDistance;
  scene.SingleScattering = this->ScatteringModel == SINGLE_SCATTERING;
  scene.G = this->ScatteringAnisotropy;
  scene.Ambient = this->AmbientIntensity;
  scene.EmissionScale = this->EmissionScale;
  Tables& tab = scene.Tab;
  tab.Size = this->TransferFunctionTableSize;
  tab.SMin = range[0];
  tab.Scale = range[1] > range[0] ? (tab.Size - 1) / (range[1] - range[0]) : 0.0;
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  tab.Alpha.resize(tab.Size);
  for (int k = 0; k < tab.Size; ++k)
  {
    tab.Alpha[k] = opacity->GetValue(tab.Scale > 0.0 ? tab.SMin + k / tab.Scale : tab.SMin);
  }
  if (property->GetColorChannels(0) == 1)
  {
    TabulateColor(nullptr, property->GetGrayTransferFunction(0), tab, tab.Color);
  }
  else
  {
    TabulateColor(property->GetRGBTransferFunction(0), nullptr, tab, tab.Color);
  }
  if (scene.SingleScattering && this->EmissionColor && this->EmissionScale > 0.0)
  {
    TabulateColor(this->EmissionColor, nullptr, tab, tab.Emission);
  }

  // The camera: world <- normalised device coordinates.
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0));
  const double projectionDeterminant = projection->Determinant();
  if (projectionDeterminant == 0.0 || !std::isfinite(projectionDeterminant))
  {
    vtkErrorMacro(<< "Render: the camera's projection cannot be inverted.");
    return false;
  }
  vtkMatrix4x4::Invert(*projection->Element, scene.InverseProjection);

  // The lights, placed as vtkRenderer places them before rendering.
  if (scene.SingleScattering)
  {
    const bool follow = renderer->GetLightFollowCamera() != 0;
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->GetSwitch())
      {
        continue;
      }
      double position[3], focalPoint[3];
      if (follow && light->LightTypeIsHeadlight())
      {
        camera->GetPosition(position);
        camera->GetFocalPoint(focalPoint);
      }
      else if (follow && light->LightTypeIsCameraLight())
      {
        vtkMatrix4x4* cameraLight = camera->GetCameraLightTransformMatrix();
        double in[4] = { 0.0, 0.0, 0.0, 1.0 }, out[4];
        light->GetPosition(in);
        cameraLight->MultiplyPoint(in, out);
        std::copy(out, out + 3, position);
        light->GetFocalPoint(in);
        cameraLight->MultiplyPoint(in, out);
        std::copy(out, out + 3, focalPoint);
      }
      else
      {
        light->GetTransformedPosition(position);
        light->GetTransformedFocalPoint(focalPoint);
      }
      LightSource source;
      const double* color = light->GetDiffuseColor();
      for (int c = 0; c < 3; ++c)
      {
        source.E[c] = this->LightScale * light->GetIntensity() * color[c];
      }
      source.Positional = light->GetPositional() != 0;
      if (source.Positional)
      {
        std::copy(position, position + 3, source.Position);
        const double* attenuation = light->GetAttenuationValues();
        std::copy(attenuation, attenuation + 3, source.Attenuation);
        source.Spot = light->GetConeAngle() < 90.0;
        if (source.Spot)
        {
          for (int c = 0; c < 3; ++c)
          {
            source.SpotDirection[c] = focalPoint[c] - position[c];
          }
          if (!(Normalize(source.SpotDirection) > 0.0))
          {
            vtkWarningMacro(<< "Render: a spot light's position and focal point coincide; the "
                               "light is ignored.");
            continue;
          }
          source.CosCone = std::cos(light->GetConeAngle() * kPi / 180.0);
          source.Exponent = light->GetExponent();
        }
      }
      else
      {
        for (int c = 0; c < 3; ++c)
        {
          source.ToLight[c] = position[c] - focalPoint[c];
        }
        if (!(Normalize(source.ToLight) > 0.0))
        {
          vtkWarningMacro(<< "Render: a directional light's position and focal point coincide; "
                             "the light is ignored.");
          continue;
        }
        scene.ToIndexDirection(source.ToLight, source.ToLightIndex);
      }
      scene.Lights.push_back(source);
    }
  }

  // The output.
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> transmittance;
  transmittance->SetName("Transmittance");
  if (!radiance->Allocate(3 * pixels) || !transmittance->Allocate(pixels))
  {
    vtkErrorMacro(<< "Render: cannot allocate a " << width << " x " << height << " image.");
    return false;
  }
  radiance->SetNumberOfTuples(pixels);
  transmittance->SetNumberOfTuples(pixels);
  scene.Radiance = radiance->GetPointer(0);
  scene.Transmittance = transmittance->GetPointer(0);

  // Render batches of rows, with progress and abort checks between them.
  const int batches = std::min(height, 50);
  this->UpdateProgress(0.0);
  for (int b = 0; b < batches; ++b)
  {
    if (this->AbortExecute)
    {
      return false;
    }
    const vtkIdType begin = static_cast<vtkIdType>(height) * b / batches;
    const vtkIdType end = static_cast<vtkIdType>(height) * (b + 1) / batches;
    switch (values->GetDataType())
    {
      vtkTemplateMacro(RenderRows(scene, static_cast<const VTK_TT*>(values->GetVoidPointer(0)),
        fieldDims, fieldOffset, begin, end));
    }
    this->UpdateProgress(static_cast<double>(b + 1) / batches);
  }
  if (this->AbortExecute)
  {
    return false;
  }

  this->Output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  this->Output->SetOrigin(0.0, 0.0, 0.0);
  this->Output->SetSpacing(1.0, 1.0, 1.0);
  this->Output->GetPointData()->SetScalars(radiance);
  this->Output->GetPointData()->AddArray(transmittance);
  this->LastStepSize = scene.Step;
  this->LastLightStepSize = scene.LightStep;
  renderer->GetBackground(this->LastBackground);
  return true;
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Composite()
{
  return this->Composite(this->LastBackground);
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Composite(const double background[3])
{
  vtkDoubleArray* radiance =
    vtkDoubleArray::SafeDownCast(this->Output->GetPointData()->GetArray("Radiance"));
  vtkDoubleArray* transmittance =
    vtkDoubleArray::SafeDownCast(this->Output->GetPointData()->GetArray("Transmittance"));
  this->CompositeOutput->Initialize();
  if (!radiance || !transmittance)
  {
    vtkErrorMacro(<< "Composite: there is no rendered image; call Render() first.");
    return nullptr;
  }
  if (!background)
  {
    vtkErrorMacro(<< "Composite: the background colour is null.");
    return nullptr;
  }
  const vtkIdType pixels = transmittance->GetNumberOfTuples();
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(pixels);
  const double* L = radiance->GetPointer(0);
  const double* T = transmittance->GetPointer(0);
  unsigned char* out = rgb->GetPointer(0);
  for (vtkIdType i = 0; i < pixels; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(1.0, std::max(0.0, L[3 * i + c] + T[i] * background[c]));
      out[3 * i + c] = static_cast<unsigned char>(std::floor(v * 255.0 + 0.5));
    }
  }
  this->CompositeOutput->SetExtent(this->Output->GetExtent());
  this->CompositeOutput->GetPointData()->SetScalars(rgb);
  return this->CompositeOutput;
}

//------------------------------------------------------------------------------
void vtkSingleScatteringReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScatteringModel: "
     << (this->ScatteringModel == EMISSION_ABSORPTION ? "EmissionAbsorption" : "SingleScattering")
     << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "AmbientIntensity: " << this->AmbientIntensity << "\n";
  os << indent << "EmissionScale: " << this->EmissionScale << "\n";
  os << indent << "EmissionColor: " << this->EmissionColor << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "LightStepSize: " << this->LightStepSize << "\n";
  os << indent << "EarlyTerminationThreshold: " << this->EarlyTerminationThreshold << "\n";
  os << indent << "TransferFunctionTableSize: " << this->TransferFunctionTableSize << "\n";
  os << indent << "AbortExecute: " << (this->AbortExecute ? "On" : "Off") << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "LastStepSize: " << this->LastStepSize << "\n";
  os << indent << "LastLightStepSize: " << this->LastLightStepSize << "\n";
  os << indent << "LastBackground: (" << this->LastBackground[0] << ", " << this->LastBackground[1]
     << ", " << this->LastBackground[2] << ")\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
}
