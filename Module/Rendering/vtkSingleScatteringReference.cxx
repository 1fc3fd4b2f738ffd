#include "vtkSingleScatteringReference.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallSceneReader.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkSingleScatteringReference);

class vtkSingleScatteringReference::vtkInternals
{
public:
  vtkTyndallSceneReader Scene;
};

namespace
{
// The most steps one ray may take across the volume's box.
constexpr double kMaxStepsPerRay = 1.0e7;
constexpr int kMaxImageSize = 16384;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Clips the parameter interval [t0, t1] of the ray o + t d to the box
// [lo, hi] (all in field index space); false if nothing is left.
inline bool ClipToBox(const double o[3], const double d[3], const double lo[3], const double hi[3],
  double& t0, double& t1)
{
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0)
    {
      if (o[a] < lo[a] || o[a] > hi[a])
      {
        return false;
      }
      continue;
    }
    const double inv = 1.0 / d[a];
    double ta = (lo[a] - o[a]) * inv;
    double tb = (hi[a] - o[a]) * inv;
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

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
  double A[3][3];               // world -> field index: A x + B
  double B[3];
  double BoxLow[3];
  double BoxHigh[3];
  double Step = 1.0;
  double LightStep = 1.0;
  double Threshold = 0.0;
  double MaxOpticalDepth = kInfinity;
  double DensityScale = 1.0;
  bool SingleScattering = true;
  double G = 0.0;
  double Ambient = 0.0;
  double EmissionScale = 0.0;
  bool HasEmission = false;
  std::vector<LightSource> Lights;
  const vtkTyndallTransferTable* Table = nullptr;
  const vtkTyndallDetailMedium* Detail = nullptr; // procedural detail, or null
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
  double Phase(double mu) const { return vtkTransmittanceMapMath::HenyeyGreenstein(this->G, mu); }
};

template <typename T>
class RowRenderer
{
public:
  RowRenderer(const Scene& scene, const vtkTyndallGridMedium& medium)
    : S(&scene)
    , Field(medium)
  {
  }

  const Scene* S;
  vtkTyndallGridMedium::Sampler<T> Field;

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
  // The extinction at a field index point and its table position; false
  // for empty medium (missing data included: a NaN scalar).
  bool Extinction(const double p[3], double& sigma, int& k, double& f) const
  {
    const double s = this->Field.Scalar(p);
    if (std::isnan(s))
    {
      return false;
    }
    this->S->Table->Locate(s, k, f);
    sigma = this->S->Detail ? this->S->Detail->Extinction(p)
                            : this->S->DensityScale * this->S->Table->ExtinctionAt(k, f);
    return sigma > 0.0;
  }

  // T_l from the index-space point p along the index-space image d of a unit
  // world direction, up to the box's exit or the world distance tMax.
  double LightTransmittance(const double p[3], const double d[3], double tMax) const
  {
    double t0 = 0.0, t1 = tMax;
    if (!ClipToBox(p, d, this->S->BoxLow, this->S->BoxHigh, t0, t1))
    {
      return 1.0;
    }
    const double length = t1;
    if (this->S->Detail)
    {
      return std::exp(-this->S->Detail->OpticalDepth(p, d, 0.0, length)); // closed form
    }
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
    const double rayLength = vtkMath::Normalize(w);
    if (!(rayLength > 0.0))
    {
      return;
    }
    double o[3], d[3];
    s.ToIndexPoint(origin, o);
    s.ToIndexDirection(w, d);
    double t0 = 0.0, t1 = rayLength;
    if (!ClipToBox(o, d, s.BoxLow, s.BoxHigh, t0, t1))
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
      vtkTyndallTransferTable::RGBAt(s.Table->Albedo, k, f, color);
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
        if (s.HasEmission)
        {
          double e[3];
          vtkTyndallTransferTable::RGBAt(s.Table->Emission, k, f, e);
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
      const double r = vtkMath::Normalize(l);
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
        const double cosPhi = -vtkMath::Dot(l, light.SpotDirection);
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
    const double weight =
      factor * s.Phase(vtkMath::Dot(l, w)) * this->LightTransmittance(p, dl, tMax);
    for (int c = 0; c < 3; ++c)
    {
      in[c] += light.E[c] * weight;
    }
  }
};

template <typename T>
void RenderRows(
  const Scene& scene, const vtkTyndallGridMedium& medium, vtkIdType begin, vtkIdType end)
{
  RowRenderer<T> renderer(scene, medium);
  vtkSMPTools::For(begin, end, 1, renderer);
}
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::vtkSingleScatteringReference()
  : Internals(new vtkInternals)
{
  this->Output = vtkImageData::New();
  this->CompositeOutput = vtkImageData::New();
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::~vtkSingleScatteringReference()
{
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
namespace
{
// The medium's placement and parameters, as the integration reads them.
void SetUpMedium(const vtkTyndallGridMedium& medium, Scene& scene)
{
  const double* worldToIndex = medium.GetWorldToIndex();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      scene.A[r][c] = worldToIndex[4 * r + c];
    }
    scene.B[r] = worldToIndex[4 * r + 3];
    scene.BoxLow[r] = medium.GetBoxLow()[r];
    scene.BoxHigh[r] = medium.GetBoxHigh()[r];
  }
  scene.DensityScale = medium.GetDensityScale();
  scene.SingleScattering = medium.GetSingleScattering();
  scene.G = medium.GetScatteringAnisotropy();
  scene.Ambient = medium.GetAmbientIntensity();
  scene.EmissionScale = medium.GetEmissionScale();
  scene.HasEmission = medium.GetHasEmission();
  scene.Table = &medium.GetTable();
}

// The scene's lights (none in the emission-absorption model).
void SetUpLights(const vtkTyndallSceneReader& tyndall, Scene& scene)
{
  for (const vtkTyndallLight& light : tyndall.GetLights())
  {
    LightSource source;
    std::copy(light.Irradiance, light.Irradiance + 3, source.E);
    source.Positional = light.Positional;
    if (light.Positional)
    {
      std::copy(light.Position, light.Position + 3, source.Position);
      std::copy(light.Attenuation, light.Attenuation + 3, source.Attenuation);
      source.Spot = light.Spot;
      std::copy(light.Direction, light.Direction + 3, source.SpotDirection);
      source.CosCone = light.ConeCosine;
      source.Exponent = light.Exponent;
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        source.ToLight[c] = -light.Direction[c];
      }
      scene.ToIndexDirection(source.ToLight, source.ToLightIndex);
    }
    scene.Lights.push_back(source);
  }
}
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
  vtkTyndallSceneReader& tyndall = this->Internals->Scene;
  if (!tyndall.Update(renderer, volume, this))
  {
    return false;
  }
  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  Scene scene;
  scene.Width = width;
  scene.Height = height;
  SetUpMedium(medium, scene);

  // Steps: the world length of one field index step along the shortest axis.
  const double minVoxel = medium.GetMinimumWorldSpacing();
  const vtkTyndallDetailMedium& detail = tyndall.GetDetail();
  scene.Detail = detail.Enabled() ? &detail : nullptr;
  const double wavelength =
    detail.Enabled() ? detail.GetShortestWavelength(medium.GetWorldToIndex()) : 1e30;
  scene.Step = this->StepSize > 0.0 ? this->StepSize : std::min(minVoxel, wavelength / 2.0) / 4.0;
  scene.LightStep = this->LightStepSize > 0.0 ? this->LightStepSize : scene.Step;
  if (!(scene.Step > 0.0) || !(scene.LightStep > 0.0) ||
    medium.GetWorldDiagonal() / std::min(scene.Step, scene.LightStep) > kMaxStepsPerRay)
  {
    vtkErrorMacro(<< "Render: the step " << scene.Step << " (light step " << scene.LightStep
                  << ") would take more than " << kMaxStepsPerRay
                  << " steps across the volume; set a larger StepSize / LightStepSize.");
    return false;
  }
  scene.Threshold = this->EarlyTerminationThreshold;
  scene.MaxOpticalDepth =
    this->EarlyTerminationThreshold > 0.0 ? -std::log(this->EarlyTerminationThreshold) : kInfinity;

  // The camera: world <- normalised device coordinates.
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(width) / height, -1.0, 1.0));
  const double projectionDeterminant = projection->Determinant();
  if (projectionDeterminant == 0.0 || !std::isfinite(projectionDeterminant))
  {
    vtkErrorMacro(<< "Render: the camera's projection cannot be inverted.");
    return false;
  }
  vtkMatrix4x4::Invert(*projection->Element, scene.InverseProjection);
  SetUpLights(tyndall, scene);

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
  for (int b = 0; b < batches && !this->AbortExecute; ++b)
  {
    const vtkIdType begin = static_cast<vtkIdType>(height) * b / batches;
    const vtkIdType end = static_cast<vtkIdType>(height) * (b + 1) / batches;
    switch (medium.GetScalars()->GetDataType())
    {
      vtkTemplateMacro(RenderRows<VTK_TT>(scene, medium, begin, end));
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
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "LightStepSize: " << this->LightStepSize << "\n";
  os << indent << "EarlyTerminationThreshold: " << this->EarlyTerminationThreshold << "\n";
  os << indent << "AbortExecute: " << (this->AbortExecute ? "On" : "Off") << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "LastStepSize: " << this->LastStepSize << "\n";
  os << indent << "LastLightStepSize: " << this->LastLightStepSize << "\n";
  os << indent << "LastBackground: (" << this->LastBackground[0] << ", " << this->LastBackground[1]
     << ", " << this->LastBackground[2] << ")\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
}
