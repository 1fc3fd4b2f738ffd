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
  this->SetUpMedia(reader);
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetUpMedia(const vtkTyndallSceneReader& reader)
{
  this->Media.clear();
  const std::vector<const vtkTyndallMedium*>& media = reader.GetMedia();
  const std::vector<int>& camera = reader.GetCameraGuests();
  this->DrawnByAnother = reader.GetDrawnBy() != nullptr;
  for (size_t k = 0; k < media.size(); ++k)
  {
    Medium m;
    m.Medium = media[k];
    // Guest k - 1 is a camera guest when its index is listed.
    m.Camera =
      k == 0 || std::find(camera.begin(), camera.end(), static_cast<int>(k) - 1) != camera.end();
    this->Media.push_back(m);
  }
  this->Parameters = &media[0]->GetParameters();
  this->Octaves = this->Parameters->ScatteringOctaves;
  const vtkTyndallGridMedium& grid = reader.GetMedium();
  this->Projected = grid.GetProjection().Enabled() ? &grid : nullptr;
  this->ProjectionClasses = grid.GetProjectionClasses();
  this->Shaded = grid.GetShading().Enabled() ? &grid : nullptr;
  this->Isosurfaced = grid.GetIsosurfaces().Enabled() ? &grid : nullptr;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::LocalRays::Set(
  const vtkTyndallReferenceScene& scene, const double x[3], const double w[3])
{
  for (size_t k = 0; k < scene.Media.size(); ++k)
  {
    scene.Media[k].Medium->ToLocalPoint(x, this->O[k]);
    scene.Media[k].Medium->ToLocalDirection(w, this->D[k]);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallReferenceScene::ClipToCameraMedia(
  const double x[3], const double w[3], LocalRays& rays, double& t0, double& t1) const
{
  rays.Set(*this, x, w);
  double low = t1, high = t0;
  for (size_t k = 0; k < this->Media.size(); ++k)
  {
    const vtkTyndallMedium* medium = this->Media[k].Medium;
    double a = t0, b = t1;
    if (this->Media[k].Camera &&
      vtkTyndallMedium::ClipToBox(
        rays.O[k], rays.D[k], medium->GetBoxLow(), medium->GetBoxHigh(), a, b))
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
double vtkTyndallReferenceScene::GetCameraFinestFeature() const
{
  double finest = std::numeric_limits<double>::infinity();
  for (const Medium& m : this->Media)
  {
    if (m.Camera)
    {
      finest = std::min(finest, m.Medium->GetFinestFeature());
    }
  }
  return finest;
}

//------------------------------------------------------------------------------
double vtkTyndallReferenceScene::GetDiagonals() const
{
  double sum = 0.0;
  for (const Medium& m : this->Media)
  {
    sum += m.Medium->GetWorldDiagonal();
  }
  return sum;
}

//------------------------------------------------------------------------------
vtkTyndallReferenceScene::LightSource vtkTyndallReferenceScene::ToSource(
  const vtkTyndallLight& light)
{
  LightSource source;
  std::copy(light.Color, light.Color + 3, source.Color);
  source.Headlight = light.Headlight;
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
  return source;
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
  this->Footprint.SetCamera(renderer->GetActiveCamera(), this->Width, this->Height);
  this->SetUpLights(reader);
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallReferenceScene::SetUpLights(const vtkTyndallSceneReader& reader)
{
  this->Environment = &reader.GetEnvironment();
  this->Lights.clear();
  for (const vtkTyndallLight& light : reader.GetLights())
  {
    this->Lights.push_back(ToSource(light));
    this->Lights.back().Scaled = true; // (its Irradiance: the volume's LightScale times Color)
  }
  // The sky: sampled (the path tracer), or the map-based frame's lights and ambient term.
  this->SkyLights.clear();
  std::fill(this->ShadingSkyMean, this->ShadingSkyMean + 3, 0.0);
  if (this->SampleSky)
  {
    const double ambient = this->Parameters->AmbientIntensity;
    std::fill(this->Ambient, this->Ambient + 3, ambient);
    return;
  }
  for (const vtkTyndallLight& light : reader.GetSkyLights())
  {
    this->SkyLights.push_back(ToSource(light));
  }
  reader.GetMapAmbient(this->Ambient);
  reader.GetShadingSkyMean(this->ShadingSkyMean);
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
bool vtkTyndallReferenceScene::LightGeometry(
  const LightSource& light, const double x[3], double l[3], double& factor, double& tMax) const
{
  factor = 1.0;
  tMax = std::numeric_limits<double>::infinity();
  if (!light.Positional)
  {
    std::copy(light.ToLight, light.ToLight + 3, l);
    return true;
  }
  for (int c = 0; c < 3; ++c)
  {
    l[c] = light.Position[c] - x[c];
  }
  tMax = vtkMath::Normalize(l);
  factor = PositionalFactor(light, l, tMax);
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
