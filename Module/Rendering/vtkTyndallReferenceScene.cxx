#include "vtkTyndallReferenceScene.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTyndallSceneReader.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace
{
constexpr int kMaxImageSize = 16384;

// The attenuation and spot cone factor of a positional light at the world
// distance r along the unit direction l towards it; 0 where it does not
// reach.
double PositionalFactor(
  const vtkTyndallReferenceScene::LightSource& light, const double l[3], double r)
{
  const double denominator =
    light.Attenuation[0] + light.Attenuation[1] * r + light.Attenuation[2] * r * r;
  if (!(r > 0.0) || !(denominator > 0.0))
  {
    return 0.0;
  }
  double factor = 1.0 / denominator;
  if (light.Spot)
  {
    const double cosPhi = -vtkMath::Dot(l, light.SpotDirection);
    if (cosPhi < light.CosCone)
    {
      return 0.0;
    }
    factor *= std::pow(std::max(0.0, cosPhi), light.Exponent);
  }
  return factor;
}

// The ray p + t d of a medium's index space in `guest`'s: o + t dg.
void GuestRay(const vtkTyndallReferenceScene::Guest& guest, const double p[3], const double d[3],
  double o[3], double dg[3])
{
  guest.ToGuest(p, o);
  for (int r = 0; r < 3; ++r)
  {
    dg[r] = guest.M[r][0] * d[0] + guest.M[r][1] * d[1] + guest.M[r][2] * d[2];
  }
}

// A guest's scalar at its own field index point q (NaN at missing data).
template <typename T>
std::function<double(const double q[3])> GuestScalar(const vtkTyndallGridMedium& medium)
{
  const vtkTyndallGridMedium::Sampler<T> sampler(medium);
  return [sampler](const double q[3]) { return sampler.ReferenceScalar(q); };
}
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::ReadScene(vtkTyndallSceneReader& reader, vtkRenderer* renderer,
  vtkVolume* volume, int width, int height, vtkObject* reporter)
{
  if (width < 1 || width > kMaxImageSize || height < 1 || height > kMaxImageSize)
  {
    vtkErrorWithObjectMacro(reporter, << "Render: the image size " << width << " x " << height
                                      << " is outside [1, " << kMaxImageSize << "] on some axis.");
    return false;
  }
  if (!reader.Update(renderer, volume, reporter))
  {
    return false;
  }
  this->Width = width;
  this->Height = height;
  this->SetUpMedium(reader.GetMedium());
  this->SetUpGuests(reader);
  const vtkTyndallDetailMedium& detail = reader.GetDetail();
  this->Detail = detail.Enabled() ? &detail : nullptr;
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetUpGuests(const vtkTyndallSceneReader& reader)
{
  this->Guests.clear();
  const double* toWorld = reader.GetMedium().GetIndexToWorld();
  const std::vector<int>& camera = reader.GetCameraGuests();
  this->CameraGuests = false;
  this->GuestDiagonals = 0.0;
  this->CameraGuestSpacing = std::numeric_limits<double>::infinity();
  this->DrawnByAnother = reader.GetDrawnBy() != nullptr;
  for (const vtkTyndallGridMedium* medium : reader.GetGuests())
  {
    Guest g;
    g.Camera = std::find(camera.begin(), camera.end(), static_cast<int>(this->Guests.size())) !=
      camera.end();
    if (g.Camera)
    {
      this->CameraGuests = true;
      this->CameraGuestSpacing =
        std::min(this->CameraGuestSpacing, medium->GetMinimumWorldSpacing());
    }
    this->GuestDiagonals += medium->GetWorldDiagonal();
    g.DensityScale = medium->GetDensityScale();
    g.Table = &medium->GetTable();
    g.Medium = medium;
    // This medium's index -> world -> the guest's index.
    double m[16];
    vtkMatrix4x4::Multiply4x4(medium->GetWorldToIndex(), toWorld, m);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        g.M[r][c] = m[4 * r + c];
      }
      g.C[r] = m[4 * r + 3];
      g.BoxLow[r] = medium->GetBoxLow()[r];
      g.BoxHigh[r] = medium->GetBoxHigh()[r];
    }
    switch (medium->GetScalars()->GetDataType())
    {
      vtkTemplateMacro(g.Scalar = GuestScalar<VTK_TT>(*medium));
    }
    this->Guests.push_back(std::move(g)); // every scalar type is one of vtkTemplateMacro's
  }
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::Guest::ToGuest(const double p[3], double q[3]) const
{
  for (int r = 0; r < 3; ++r)
  {
    q[r] = this->C[r] + this->M[r][0] * p[0] + this->M[r][1] * p[1] + this->M[r][2] * p[2];
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::Guest::Sample(
  const double q[3], double& sigma, int& k, double& f) const
{
  if (!InsideBox(q, this->BoxLow, this->BoxHigh))
  {
    return false;
  }
  const double s = this->Scalar(q);
  if (std::isnan(s))
  {
    return false;
  }
  this->Table->Locate(s, k, f);
  sigma = this->DensityScale * this->Table->ExtinctionAt(k, f);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::ClipToCameraBoxes(
  const double p[3], const double d[3], double& t0, double& t1) const
{
  double low = t1, high = t0;
  double a = t0, b = t1;
  if (ClipToBox(p, d, this->BoxLow, this->BoxHigh, a, b))
  {
    low = a;
    high = b;
  }
  for (const Guest& g : this->Guests)
  {
    double o[3], dg[3];
    GuestRay(g, p, d, o, dg);
    a = t0;
    b = t1;
    if (g.Camera && ClipToBox(o, dg, g.BoxLow, g.BoxHigh, a, b))
    {
      low = std::min(low, a);
      high = std::max(high, b);
    }
  }
  t0 = low;
  t1 = high;
  return t0 < t1;
}

//------------------------------------------------------------------------------
double vtkTyndallReferenceScene::GuestOpticalDepth(
  const double p[3], const double d[3], double tMax, double step, double maxDepth) const
{
  double tau = 0.0;
  for (const Guest& g : this->Guests)
  {
    double o[3], dg[3];
    GuestRay(g, p, d, o, dg);
    double t0 = 0.0, t1 = tMax;
    if (!ClipToBox(o, dg, g.BoxLow, g.BoxHigh, t0, t1))
    {
      continue;
    }
    const int n = static_cast<int>(std::max(1.0, std::ceil((t1 - t0) / step)));
    const double dt = (t1 - t0) / n;
    for (int i = 0; i < n && tau <= maxDepth; ++i)
    {
      const double t = t0 + (i + 0.5) * dt;
      const double q[3] = { o[0] + t * dg[0], o[1] + t * dg[1], o[2] + t * dg[2] };
      double sigma, f;
      int k;
      tau += g.Sample(q, sigma, k, f) ? sigma * dt : 0.0;
    }
  }
  return tau;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetUpMedium(const vtkTyndallGridMedium& medium)
{
  const double* worldToIndex = medium.GetWorldToIndex();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->A[r][c] = worldToIndex[4 * r + c];
    }
    this->B[r] = worldToIndex[4 * r + 3];
    this->BoxLow[r] = medium.GetBoxLow()[r];
    this->BoxHigh[r] = medium.GetBoxHigh()[r];
  }
  this->DensityScale = medium.GetDensityScale();
  this->Chromatic = medium.GetChromatic();
  std::copy(medium.GetExtinctionColor(), medium.GetExtinctionColor() + 3, this->ExtinctionColor);
  this->SingleScattering = medium.GetSingleScattering();
  this->G = medium.GetScatteringAnisotropy();
  this->Ambient = medium.GetAmbientIntensity();
  this->Octaves = medium.GetScatteringOctaves();
  std::copy(medium.GetOctaveFactors(), medium.GetOctaveFactors() + 4, this->OctaveFactors);
  this->EmissionScale = medium.GetEmissionScale();
  this->HasEmission = medium.GetHasEmission();
  this->Table = &medium.GetTable();
  this->Clip = medium.GetClip().Enabled() ? &medium.GetClip() : nullptr;
  this->Medium = &medium;
  this->EmissionArray = this->HasEmission && medium.GetEmissionFromArray();
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::SetUpView(
  const vtkTyndallSceneReader& reader, vtkRenderer* renderer, vtkObject* reporter)
{
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(this->Width) / this->Height, -1.0, 1.0));
  const double determinant = projection->Determinant();
  if (determinant == 0.0 || !std::isfinite(determinant))
  {
    vtkErrorWithObjectMacro(reporter, << "Render: the camera's projection cannot be inverted.");
    return false;
  }
  vtkMatrix4x4::Invert(*projection->Element, this->InverseProjection);
  this->SetUpLights(reader);
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetUpLights(const vtkTyndallSceneReader& reader)
{
  for (const vtkTyndallLight& light : reader.GetLights())
  {
    LightSource source;
    std::copy(light.Irradiance, light.Irradiance + 3, source.E);
    source.Positional = light.Positional;
    source.Spot = light.Spot;
    source.CosCone = light.ConeCosine;
    source.Exponent = light.Exponent;
    std::copy(light.Position, light.Position + 3, source.Position);
    std::copy(light.Attenuation, light.Attenuation + 3, source.Attenuation);
    std::copy(light.Direction, light.Direction + 3, source.SpotDirection);
    for (int c = 0; c < 3; ++c)
    {
      source.ToLight[c] = -light.Direction[c];
    }
    this->ToIndexDirection(source.ToLight, source.ToLightIndex);
    this->Lights.push_back(source);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::CameraRay(
  int i, int j, double origin[3], double w[3], double& length) const
{
  const double ndc[2] = { 2.0 * (i + 0.5) / this->Width - 1.0,
    2.0 * (j + 0.5) / this->Height - 1.0 };
  double ends[2][3];
  for (int e = 0; e < 2; ++e)
  {
    const double in[4] = { ndc[0], ndc[1], e == 0 ? -1.0 : 1.0, 1.0 };
    double out[4];
    vtkMatrix4x4::MultiplyPoint(this->InverseProjection, in, out);
    for (int c = 0; c < 3; ++c)
    {
      ends[e][c] = out[c] / out[3];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    origin[c] = ends[0][c];
    w[c] = ends[1][c] - ends[0][c];
  }
  length = vtkMath::Normalize(w);
  return length > 0.0;
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::LightGeometry(const LightSource& light, const double x[3],
  double l[3], double dl[3], double& factor, double& tMax) const
{
  factor = 1.0;
  tMax = std::numeric_limits<double>::infinity();
  if (!light.Positional)
  {
    std::copy(light.ToLight, light.ToLight + 3, l);
    std::copy(light.ToLightIndex, light.ToLightIndex + 3, dl);
    return true;
  }
  for (int c = 0; c < 3; ++c)
  {
    l[c] = light.Position[c] - x[c];
  }
  tMax = vtkMath::Normalize(l);
  factor = PositionalFactor(light, l, tMax);
  this->ToIndexDirection(l, dl);
  return factor > 0.0;
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::RenderRowBatches(const bool& abort,
  const std::function<void(double)>& progress,
  const std::function<void(vtkIdType, vtkIdType)>& rows) const
{
  const int batches = std::min(this->Height, 50);
  progress(0.0);
  for (int b = 0; b < batches && !abort; ++b)
  {
    const vtkIdType begin = static_cast<vtkIdType>(this->Height) * b / batches;
    const vtkIdType end = static_cast<vtkIdType>(this->Height) * (b + 1) / batches;
    rows(begin, end);
    progress(static_cast<double>(b + 1) / batches);
  }
  return !abort;
}

//------------------------------------------------------------------------------
vtkImageData* vtkTyndallReferenceScene::TimedRender(vtkObject* self, vtkImageData* output,
  vtkImageData* composite, const std::function<bool()>& render, double& seconds)
{
  output->Initialize();
  composite->Initialize();
  self->InvokeEvent(vtkCommand::StartEvent);
  const auto start = std::chrono::steady_clock::now();
  const bool ok = render();
  self->InvokeEvent(vtkCommand::EndEvent);
  if (!ok)
  {
    output->Initialize();
    return nullptr;
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return output;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetOutput(vtkImageData* output, vtkDataArray* radiance,
  vtkDataArray* transmittance, vtkDataArray* error) const
{
  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->GetPointData()->SetScalars(radiance);
  output->GetPointData()->AddArray(transmittance);
  if (error)
  {
    output->GetPointData()->AddArray(error);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::Composite(vtkImageData* image, vtkDataArray* radiance,
  vtkDataArray* transmittance, const double background[3], vtkImageData* output)
{
  const vtkIdType pixels = transmittance->GetNumberOfTuples();
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(pixels);
  unsigned char* out = rgb->GetPointer(0);
  for (vtkIdType i = 0; i < pixels; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double t =
        transmittance->GetComponent(i, transmittance->GetNumberOfComponents() == 3 ? c : 0);
      const double v =
        std::min(1.0, std::max(0.0, radiance->GetComponent(i, c) + t * background[c]));
      out[3 * i + c] = static_cast<unsigned char>(std::floor(v * 255.0 + 0.5));
    }
  }
  output->SetExtent(image->GetExtent());
  output->GetPointData()->SetScalars(rgb);
}
