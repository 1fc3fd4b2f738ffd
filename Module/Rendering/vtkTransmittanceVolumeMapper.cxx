#include "vtkTransmittanceVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

// The GLSL sources, embedded at build time from glsl/*.glsl.
#include "vtkTransmittanceCommonFS.h"
#include "vtkTransmittanceMapBuildFS.h"
#include "vtkTransmittanceOcclusionFS.h"
#include "vtkTransmittanceRayCastFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransmittanceVolumeMapper);
vtkCxxSetObjectMacro(vtkTransmittanceVolumeMapper, EmissionColor, vtkColorTransferFunction);

namespace
{
constexpr int kMaxLights = 8;
constexpr int kTableSize = 4096;

bool IsMapMethod(int method)
{
  return method >= vtkTransmittanceVolumeMapper::TFM;
}

bool IsAdaptive(int method)
{
  return method == vtkTransmittanceVolumeMapper::ADAPTIVE_TFM ||
    method == vtkTransmittanceVolumeMapper::ADAPTIVE_ETM;
}

// Column-major float copy of a VTK (row-major) matrix, for glUniformMatrix.
void ToColumnMajor(vtkMatrix4x4* m, float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[c * 4 + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}

struct LightParameters
{
  bool Positional = false;
  double Position[3] = { 0, 0, 0 };
  double Direction[3] = { 0, 0, -1 }; // the direction the light travels
  double Irradiance[3] = { 0, 0, 0 };
  double Attenuation[3] = { 1, 0, 0 };
  double ConeCosine = -2.0; // -2: not a spot light
  double Exponent = 1.0;
  int Method = 0; // per light, after fallbacks
  bool HasFrustum = false;
  vtkNew<vtkTransmittanceLightFrustum> Frustum;
};
}

//------------------------------------------------------------------------------
class vtkTransmittanceVolumeMapper::vtkInternals
{
public:
  vtkSmartPointer<vtkTextureObject> VolumeTexture;
  vtkSmartPointer<vtkTextureObject> TransferTexture;
  vtkSmartPointer<vtkTextureObject> MapTexture;
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> MapFramebuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFramebuffer;
  // Occluders seen from the lights: a depth render per light, converted to
  // distances along the map rays in one slice per light of OcclusionTexture.
  vtkSmartPointer<vtkTextureObject> OcclusionTexture;
  vtkSmartPointer<vtkTextureObject> LightDepthTexture;
  vtkSmartPointer<vtkTextureObject> LightColorTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> OcclusionFramebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> OcclusionQuad;
  int OcclusionSlices = 0;
  int OcclusionSize = 0;
  std::unique_ptr<vtkOpenGLQuadHelper> RayCastQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> MapQuad;
  std::string MapQuadSource;
  vtkOpenGLRenderWindow* Window = nullptr;

  // The uploaded volume: geometry of the texture's point grid.
  std::vector<double> VolumeKey;
  int Dimensions[3] = { 0, 0, 0 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double ScalarRange[2] = { 0, 1 };
  bool VolumeValid = false;

  std::vector<double> TransferKey;
  std::vector<double> MapKey;
  int MapSlices = 0;
  int MapSize = 0;
  int DepthFormat = -1;
  int SoftwareRenderer = -1; // llvmpipe: 1, other: 0, unknown: -1
  bool WarnedLoopLimit = false;

  std::vector<LightParameters> Lights;
  double WorldToVolume[16];

  void Release(vtkWindow* window)
  {
    for (auto* texture : { this->VolumeTexture.Get(), this->TransferTexture.Get(),
           this->MapTexture.Get(), this->DepthTexture.Get(), this->OcclusionTexture.Get(),
           this->LightDepthTexture.Get(), this->LightColorTexture.Get() })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
    for (auto* framebuffer : { this->MapFramebuffer.Get(), this->DepthFramebuffer.Get(),
           this->OcclusionFramebuffer.Get() })
    {
      if (framebuffer)
      {
        framebuffer->ReleaseGraphicsResources(window);
      }
    }
    if (this->RayCastQuad)
    {
      this->RayCastQuad->ReleaseGraphicsResources(window);
    }
    if (this->MapQuad)
    {
      this->MapQuad->ReleaseGraphicsResources(window);
    }
    if (this->OcclusionQuad)
    {
      this->OcclusionQuad->ReleaseGraphicsResources(window);
    }
    this->VolumeTexture = nullptr;
    this->TransferTexture = nullptr;
    this->MapTexture = nullptr;
    this->DepthTexture = nullptr;
    this->MapFramebuffer = nullptr;
    this->DepthFramebuffer = nullptr;
    this->OcclusionTexture = nullptr;
    this->LightDepthTexture = nullptr;
    this->LightColorTexture = nullptr;
    this->OcclusionFramebuffer = nullptr;
    this->OcclusionQuad.reset();
    this->OcclusionSlices = 0;
    this->OcclusionSize = 0;
    this->RayCastQuad.reset();
    this->MapQuad.reset();
    this->MapQuadSource.clear();
    this->VolumeKey.clear();
    this->TransferKey.clear();
    this->MapKey.clear();
    this->VolumeValid = false;
    this->Window = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper::vtkTransmittanceVolumeMapper()
  : LightScale(4.0 * vtkMath::Pi())
  , Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper::~vtkTransmittanceVolumeMapper()
{
  this->SetEmissionColor(nullptr);
}

//------------------------------------------------------------------------------
const char* vtkTransmittanceVolumeMapper::GetTransmittanceMethodAsString()
{
  return vtkTransmittanceMapMath::GetMethodName(this->TransmittanceMethod);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkTransmittanceVolumeMapper::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->EmissionColor)
  {
    mtime = std::max(mtime, this->EmissionColor->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Release(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
namespace
{
// Uploads the input's scalars as a float 3-D texture. Returns false (after an
// error) when the input cannot be rendered.
bool UploadVolume(vtkTransmittanceVolumeMapper* self, vtkImageData* input,
  vtkOpenGLRenderWindow* window, vtkTextureObject* texture, int dims[3], double origin[3],
  double spacing[3], double range[2])
{
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  int pointDims[3];
  input->GetDimensions(pointDims);
  input->GetSpacing(spacing);
  // `origin` is the physical position of the first sample: the image's
  // origin plus its direction times the extent's start (not always 0).
  const int* extent = input->GetExtent();
  double firstIndex[3] = { double(extent[0]), double(extent[2]), double(extent[4]) };
  if (!scalars && input->GetCellData()->GetScalars())
  {
    // Cell scalars: the point grid of the cell centres.
    scalars = input->GetCellData()->GetScalars();
    for (int k = 0; k < 3; ++k)
    {
      pointDims[k] = std::max(pointDims[k] - 1, 1);
      firstIndex[k] += 0.5;
    }
  }
  input->TransformContinuousIndexToPhysicalPoint(firstIndex, origin);
  if (!scalars)
  {
    vtkErrorWithObjectMacro(self, << "The input has no scalars to render.");
    return false;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorWithObjectMacro(self, << "The input's scalars have " << scalars->GetNumberOfComponents()
                                  << " components; vtkTransmittanceVolumeMapper renders one.");
    return false;
  }
  if (pointDims[0] < 2 || pointDims[1] < 2 || pointDims[2] < 2)
  {
    vtkErrorWithObjectMacro(self, << "The input has " << pointDims[0] << " x " << pointDims[1]
                                  << " x " << pointDims[2]
                                  << " samples; at least 2 along each axis are needed.");
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!(spacing[k] > 0.0) || !std::isfinite(spacing[k]) || !std::isfinite(origin[k]))
    {
      vtkErrorWithObjectMacro(self, << "The input's spacing must be positive and finite.");
      return false;
    }
  }
  // Downsample by the smallest integer factor that fits the 3-D texture limit.
  const int maxSize = vtkTextureObject::GetMaximumTextureSize3D(window);
  int factor = 1;
  for (int k = 0; k < 3; ++k)
  {
    if (maxSize > 0)
    {
      factor = std::max(factor, (pointDims[k] + maxSize - 1) / maxSize);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    dims[k] = (pointDims[k] - 1) / factor + 1;
    spacing[k] *= factor;
  }
  if (factor > 1)
  {
    vtkWarningWithObjectMacro(self, << "The volume (" << pointDims[0] << " x " << pointDims[1]
                                    << " x " << pointDims[2]
                                    << ") exceeds the GPU's 3-D texture size " << maxSize
                                    << "; rendering every " << factor << "th sample.");
  }
  const size_t count = static_cast<size_t>(dims[0]) * dims[1] * dims[2];
  std::vector<float> values;
  try
  {
    values.resize(count);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(self, << "Cannot allocate " << count << " floats for the volume.");
    return false;
  }
  double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
  size_t nonFinite = 0;
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x, ++i)
      {
        const vtkIdType id =
          (static_cast<vtkIdType>(z) * factor * pointDims[1] + y * factor) * pointDims[0] +
          x * factor;
        const double v = scalars->GetComponent(id, 0);
        if (!std::isfinite(v))
        {
          ++nonFinite;
          values[i] = std::numeric_limits<float>::quiet_NaN();
          continue;
        }
        values[i] = static_cast<float>(v);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  if (lo > hi)
  {
    vtkErrorWithObjectMacro(self, << "The input's scalars have no finite value.");
    return false;
  }
  if (nonFinite)
  {
    vtkWarningWithObjectMacro(self, << nonFinite
                                    << " NaN or Inf scalars were replaced by the smallest finite "
                                       "scalar, "
                                    << lo << ".");
    for (float& v : values)
    {
      if (!std::isfinite(v))
      {
        v = static_cast<float>(lo);
      }
    }
  }
  range[0] = lo;
  range[1] = hi;
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!texture->Create3DFromRaw(dims[0], dims[1], dims[2], 1, VTK_FLOAT, values.data()))
  {
    vtkErrorWithObjectMacro(self, << "Could not create the volume's 3-D texture.");
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  vtkInternals& in = *this->Internals;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro(<< "vtkTransmittanceVolumeMapper needs an OpenGL render window.");
    return;
  }
  if (in.Window && in.Window != window)
  {
    in.Release(in.Window);
  }
  in.Window = window;
  if (this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  if (!input)
  {
    vtkErrorMacro(<< "No vtkImageData input to render.");
    return;
  }
  vtkVolumeProperty* property = volume->GetProperty();
  vtkOpenGLState* state = window->GetState();

  // 1. The volume texture.
  vtkDataArray* pointScalars = input->GetPointData()->GetScalars();
  vtkDataArray* cellScalars = input->GetCellData()->GetScalars();
  const std::vector<double> volumeKey = { static_cast<double>(input->GetMTime()),
    pointScalars ? static_cast<double>(pointScalars->GetMTime()) : -1.0,
    cellScalars ? static_cast<double>(cellScalars->GetMTime()) : -1.0,
    static_cast<double>(reinterpret_cast<uintptr_t>(input)) };
  if (volumeKey != in.VolumeKey)
  {
    in.VolumeKey = volumeKey;
    if (!in.VolumeTexture)
    {
      in.VolumeTexture = vtkSmartPointer<vtkTextureObject>::New();
    }
    in.VolumeValid = UploadVolume(
      this, input, window, in.VolumeTexture, in.Dimensions, in.Origin, in.Spacing, in.ScalarRange);
    vtkMatrix3x3* direction = input->GetDirectionMatrix();
    for (int k = 0; k < 9; ++k)
    {
      in.Direction[k] = direction->GetData()[k];
    }
  }
  if (!in.VolumeValid)
  {
    return;
  }

  // 2. The transfer-function table.
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  const std::vector<double> transferKey = { static_cast<double>(property->GetMTime()),
    static_cast<double>(opacity->GetMTime()), static_cast<double>(color->GetMTime()),
    this->EmissionColor ? static_cast<double>(this->EmissionColor->GetMTime()) : -1.0,
    in.ScalarRange[0], in.ScalarRange[1] };
  if (transferKey != in.TransferKey)
  {
    in.TransferKey = transferKey;
    std::vector<double> alpha(kTableSize), rgb(3 * kTableSize), emission(3 * kTableSize, 0.0);
    opacity->GetTable(in.ScalarRange[0], in.ScalarRange[1], kTableSize, alpha.data());
    color->GetTable(in.ScalarRange[0], in.ScalarRange[1], kTableSize, rgb.data());
    if (this->EmissionColor)
    {
      this->EmissionColor->GetTable(
        in.ScalarRange[0], in.ScalarRange[1], kTableSize, emission.data());
    }
    std::vector<float> table(4 * kTableSize * 2);
    for (int i = 0; i < kTableSize; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        table[4 * i + c] = static_cast<float>(rgb[3 * i + c]);
        table[4 * (kTableSize + i) + c] = static_cast<float>(emission[3 * i + c]);
      }
      table[4 * i + 3] = static_cast<float>(
        vtkTransmittanceMapMath::ExtinctionFromOpacity(alpha[i], unitDistance, 1.0));
      table[4 * (kTableSize + i) + 3] = 0.0f;
    }
    if (!in.TransferTexture)
    {
      in.TransferTexture = vtkSmartPointer<vtkTextureObject>::New();
    }
    in.TransferTexture->SetContext(window);
    in.TransferTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    in.TransferTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    in.TransferTexture->SetMinificationFilter(vtkTextureObject::Linear);
    in.TransferTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    if (!in.TransferTexture->Create2DFromRaw(kTableSize, 2, 4, VTK_FLOAT, table.data()))
    {
      vtkErrorMacro(<< "Could not create the transfer-function texture.");
      in.TransferKey.clear();
      return;
    }
  }

  // 3. Geometry: world -> normalised volume space [0,1]^3 over the point grid.
  vtkNew<vtkMatrix4x4> dataToWorld; // volume matrix * (origin + direction * index-space)
  {
    vtkNew<vtkMatrix4x4> indexToData;
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        // normalised q in [0,1] -> index q * (n - 1) -> physical
        indexToData->SetElement(
          r, c, in.Direction[3 * r + c] * in.Spacing[c] * (in.Dimensions[c] - 1));
      }
      indexToData->SetElement(r, 3, in.Origin[r]);
    }
    vtkMatrix4x4::Multiply4x4(volume->GetMatrix(), indexToData, dataToWorld);
  }
  vtkNew<vtkMatrix4x4> worldToVolume;
  vtkMatrix4x4::Invert(dataToWorld, worldToVolume);
  float worldToVolumeF[16];
  ToColumnMajor(worldToVolume, worldToVolumeF);
  double corners[24];
  for (int i = 0; i < 8; ++i)
  {
    const double q[4] = { double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1), 1.0 };
    double p[4];
    dataToWorld->MultiplyPoint(q, p);
    std::copy(p, p + 3, corners + 3 * i);
  }
  double minWorldSpacing = VTK_DOUBLE_MAX;
  for (int c = 0; c < 3; ++c)
  {
    const double axis[3] = { dataToWorld->GetElement(0, c), dataToWorld->GetElement(1, c),
      dataToWorld->GetElement(2, c) };
    minWorldSpacing = std::min(minWorldSpacing, vtkMath::Norm(axis) / (in.Dimensions[c] - 1));
  }
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(corners, corners + 21));

  // 4. The lights.
  in.Lights.clear();
  const bool scattering = this->ScatteringModel == SINGLE_SCATTERING;
  if (scattering)
  {
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    int ignored = 0;
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
      {
        continue;
      }
      if (static_cast<int>(in.Lights.size()) == kMaxLights)
      {
        ++ignored;
        continue;
      }
      in.Lights.emplace_back();
      LightParameters& p = in.Lights.back();
      double focal[3];
      light->GetTransformedPosition(p.Position);
      light->GetTransformedFocalPoint(focal);
      for (int k = 0; k < 3; ++k)
      {
        p.Direction[k] = focal[k] - p.Position[k];
        p.Irradiance[k] = this->LightScale * light->GetIntensity() * light->GetDiffuseColor()[k];
      }
      if (!(vtkMath::Normalize(p.Direction) > 0.0))
      {
        p.Direction[0] = p.Direction[1] = 0.0;
        p.Direction[2] = -1.0;
      }
      p.Positional = light->GetPositional() != 0;
      if (p.Positional)
      {
        light->GetAttenuationValues(p.Attenuation);
        if (light->GetConeAngle() < 90.0)
        {
          p.ConeCosine = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
          p.Exponent = light->GetExponent();
        }
      }
      // Every light gets a frustum (maps and opaque occluders use it).
      p.HasFrustum = p.Positional ? p.Frustum->FitPositional(p.Position, corners)
                                  : p.Frustum->FitDirectional(p.Direction, corners);
      p.Method = this->TransmittanceMethod;
      if (IsMapMethod(p.Method) && !p.HasFrustum)
      {
        p.Method = BRUTE_FORCE; // documented fallback: light inside the bounds
      }
    }
    if (ignored)
    {
      vtkWarningMacro(<< ignored << " lights beyond the first " << kMaxLights << " are ignored.");
    }
  }
  const int numberOfLights = static_cast<int>(in.Lights.size());
  const int layers =
    (this->NumberOfCoefficients + 3) / 4 + (IsAdaptive(this->TransmittanceMethod) ? 1 : 0);

  // Uniforms shared by both passes.
  auto setCommonUniforms = [&](vtkShaderProgram* program)
  {
    program->SetUniformi("volumeTexture", in.VolumeTexture->GetTextureUnit());
    program->SetUniformi("transferTexture", in.TransferTexture->GetTextureUnit());
    program->SetUniformMatrix4x4("worldToVolume", worldToVolumeF);
    float scale[3], shift[3];
    for (int k = 0; k < 3; ++k)
    {
      scale[k] = static_cast<float>(in.Dimensions[k] - 1) / in.Dimensions[k];
      shift[k] = 0.5f / in.Dimensions[k];
    }
    program->SetUniform3f("volumeTexScale", scale);
    program->SetUniform3f("volumeTexShift", shift);
    const double width = in.ScalarRange[1] - in.ScalarRange[0];
    const double a = width > 0.0 ? (kTableSize - 1.0) / (kTableSize * width) : 0.0;
    const float toTable[2] = { static_cast<float>(a),
      static_cast<float>(0.5 / kTableSize - in.ScalarRange[0] * a) };
    program->SetUniform2f("scalarToTable", toTable);
    program->SetUniformf("densityScale", static_cast<float>(this->DensityScale));
    int positional[kMaxLights] = { 0 };
    float origin[kMaxLights][3] = {}, axisX[kMaxLights][3] = {}, axisY[kMaxLights][3] = {},
          axisZ[kMaxLights][3] = {};
    for (int l = 0; l < numberOfLights; ++l)
    {
      vtkTransmittanceLightFrustum* f = in.Lights[l].Frustum;
      positional[l] = in.Lights[l].Positional ? 1 : 0;
      for (int k = 0; k < 3; ++k)
      {
        origin[l][k] = static_cast<float>(f->GetOrigin()[k]);
        axisX[l][k] = static_cast<float>(f->GetAxisX()[k]);
        axisY[l][k] = static_cast<float>(f->GetAxisY()[k]);
        axisZ[l][k] = static_cast<float>(f->GetAxisZ()[k]);
      }
    }
    int hasFrustum[kMaxLights] = { 0 };
    for (int l = 0; l < numberOfLights; ++l)
    {
      hasFrustum[l] = in.Lights[l].HasFrustum ? 1 : 0;
    }
    program->SetUniform1iv("lightHasFrustum", kMaxLights, hasFrustum);
    program->SetUniform1iv("lightPositional", kMaxLights, positional);
    program->SetUniform3fv("lightOrigin", kMaxLights, origin);
    program->SetUniform3fv("lightAxisX", kMaxLights, axisX);
    program->SetUniform3fv("lightAxisY", kMaxLights, axisY);
    program->SetUniform3fv("lightAxisZ", kMaxLights, axisZ);
  };

  in.VolumeTexture->Activate();
  in.TransferTexture->Activate();

  // 5. Opaque geometry seen from each light: the distance along each map
  // ray to the first opaque surface, so that geometry shadows the medium.
  std::vector<vtkActor*> occluders;
  if (scattering && numberOfLights > 0)
  {
    vtkPropCollection* props = renderer->GetViewProps();
    vtkCollectionSimpleIterator pit;
    props->InitTraversal(pit);
    while (vtkProp* prop = props->GetNextProp(pit))
    {
      auto* actor = vtkActor::SafeDownCast(prop);
      if (actor && actor->GetVisibility() && actor->GetMapper() && actor->HasOpaqueGeometry())
      {
        occluders.push_back(actor);
      }
    }
  }
  auto buildOcclusion = [&]() -> bool
  {
    const int size = this->TransmittanceMapSize;
    if (!in.OcclusionTexture || in.OcclusionSize != size || in.OcclusionSlices != numberOfLights)
    {
      in.OcclusionTexture = vtkSmartPointer<vtkTextureObject>::New();
      in.LightDepthTexture = vtkSmartPointer<vtkTextureObject>::New();
      in.LightColorTexture = vtkSmartPointer<vtkTextureObject>::New();
      for (auto* texture :
        { in.OcclusionTexture.Get(), in.LightDepthTexture.Get(), in.LightColorTexture.Get() })
      {
        texture->SetContext(window);
        texture->SetWrapS(vtkTextureObject::ClampToEdge);
        texture->SetWrapT(vtkTextureObject::ClampToEdge);
        texture->SetWrapR(vtkTextureObject::ClampToEdge);
        texture->SetMinificationFilter(vtkTextureObject::Nearest);
        texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      }
      if (!in.OcclusionTexture->Create3DFromRaw(
            size, size, numberOfLights, 1, VTK_FLOAT, nullptr) ||
        !in.LightDepthTexture->AllocateDepth(size, size, vtkTextureObject::Float32) ||
        !in.LightColorTexture->Allocate2D(size, size, 4, VTK_UNSIGNED_CHAR))
      {
        vtkErrorMacro(<< "Could not allocate the light-space occlusion textures.");
        in.OcclusionTexture = nullptr;
        return false;
      }
      in.OcclusionSize = size;
      in.OcclusionSlices = numberOfLights;
      in.OcclusionFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    }
    std::string fs = std::string(vtkTransmittanceCommonFS) + vtkTransmittanceOcclusionFS;
    if (!in.OcclusionQuad)
    {
      in.OcclusionQuad.reset(new vtkOpenGLQuadHelper(
        window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
    }
    in.OcclusionFramebuffer->SetContext(window);
    vtkCamera* viewCamera = renderer->GetActiveCamera();
    viewCamera->Register(this);
    vtkNew<vtkCamera> lightCamera;
    bool ok = true;
    state->PushFramebufferBindings();
    {
      vtkOpenGLState::ScopedglViewport savedViewport(state);
      vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
      vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
      vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
      in.OcclusionFramebuffer->Bind();
      for (int l = 0; l < numberOfLights && ok; ++l)
      {
        const LightParameters& p = in.Lights[l];
        if (!p.HasFrustum)
        {
          continue;
        }
        // World -> clip of the light's frustum (see vtkTransmittanceLightFrustum).
        vtkTransmittanceLightFrustum* f = p.Frustum;
        double x[3], y[3], z[3];
        std::copy(f->GetAxisX(), f->GetAxisX() + 3, x);
        std::copy(f->GetAxisY(), f->GetAxisY() + 3, y);
        std::copy(f->GetAxisZ(), f->GetAxisZ() + 3, z);
        const double lx = vtkMath::Normalize(x), ly = vtkMath::Normalize(y);
        vtkMath::Normalize(z);
        const double* o = f->GetOrigin();
        double nearDistance, farDistance = 0.0, minDepth = VTK_DOUBLE_MAX;
        for (int c = 0; c < 8; ++c)
        {
          const double v[3] = { corners[3 * c] - o[0], corners[3 * c + 1] - o[1],
            corners[3 * c + 2] - o[2] };
          farDistance = std::max(farDistance, vtkMath::Dot(v, z));
          minDepth = std::min(minDepth, vtkMath::Dot(v, z));
        }
        farDistance += 0.01 * diagonal;
        vtkNew<vtkMatrix4x4> lightClip;
        lightClip->Zero();
        if (!p.Positional)
        {
          nearDistance = -10.0 * diagonal; // occluders far towards the light count too
          const double sz = 2.0 / (farDistance - nearDistance);
          for (int k = 0; k < 3; ++k)
          {
            lightClip->SetElement(0, k, 2.0 / lx * x[k]);
            lightClip->SetElement(1, k, 2.0 / ly * y[k]);
            lightClip->SetElement(2, k, sz * z[k]);
          }
          lightClip->SetElement(0, 3, -2.0 / lx * vtkMath::Dot(o, x) - 1.0);
          lightClip->SetElement(1, 3, -2.0 / ly * vtkMath::Dot(o, y) - 1.0);
          lightClip->SetElement(2, 3, -sz * (vtkMath::Dot(o, z) + nearDistance) - 1.0);
          lightClip->SetElement(3, 3, 1.0);
        }
        else
        {
          nearDistance = 1e-3 * std::max(minDepth, 1e-6 * diagonal);
          const double a = (farDistance + nearDistance) / (farDistance - nearDistance);
          const double b = -2.0 * farDistance * nearDistance / (farDistance - nearDistance);
          for (int k = 0; k < 3; ++k)
          {
            lightClip->SetElement(0, k, x[k] / lx);
            lightClip->SetElement(1, k, y[k] / ly);
            lightClip->SetElement(2, k, a * z[k]);
            lightClip->SetElement(3, k, z[k]);
          }
          lightClip->SetElement(0, 3, -vtkMath::Dot(o, x) / lx);
          lightClip->SetElement(1, 3, -vtkMath::Dot(o, y) / ly);
          lightClip->SetElement(2, 3, -a * vtkMath::Dot(o, z) + b);
          lightClip->SetElement(3, 3, -vtkMath::Dot(o, z));
        }
        // A camera whose composite projection is exactly lightClip.
        lightCamera->SetPosition(o[0], o[1], o[2]);
        lightCamera->SetFocalPoint(o[0] + z[0], o[1] + z[1], o[2] + z[2]);
        lightCamera->SetViewUp(y);
        vtkNew<vtkMatrix4x4> viewInverse, projection;
        vtkMatrix4x4::Invert(lightCamera->GetViewTransformMatrix(), viewInverse);
        vtkMatrix4x4::Multiply4x4(lightClip, viewInverse, projection);
        lightCamera->SetExplicitProjectionTransformMatrix(projection);
        lightCamera->UseExplicitProjectionTransformMatrixOn();

        // Depth of the opaque actors from the light.
        in.OcclusionFramebuffer->AddColorAttachment(0, in.LightColorTexture);
        in.OcclusionFramebuffer->AddDepthAttachment(in.LightDepthTexture);
        in.OcclusionFramebuffer->ActivateDrawBuffers(1);
        state->vtkglViewport(0, 0, size, size);
        state->vtkglDisable(GL_SCISSOR_TEST);
        state->vtkglDisable(GL_BLEND);
        state->vtkglEnable(GL_DEPTH_TEST);
        state->vtkglDepthMask(GL_TRUE);
        state->vtkglClearDepth(1.0);
        state->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
        renderer->SetActiveCamera(lightCamera);
        for (vtkActor* actor : occluders)
        {
          actor->RenderOpaqueGeometry(renderer);
        }
        renderer->SetActiveCamera(viewCamera);
        in.OcclusionFramebuffer->RemoveDepthAttachment();

        // Depth -> distance along the map rays, into slice l.
        in.OcclusionFramebuffer->AddColorAttachment(0, in.OcclusionTexture, l);
        in.OcclusionFramebuffer->ActivateDrawBuffers(1);
        state->vtkglDisable(GL_DEPTH_TEST);
        window->GetShaderCache()->ReadyShaderProgram(in.OcclusionQuad->Program);
        vtkShaderProgram* program = in.OcclusionQuad->Program;
        if (!program || !program->GetCompiled())
        {
          vtkErrorMacro(<< "The occlusion shader did not compile.");
          ok = false;
          break;
        }
        setCommonUniforms(program);
        in.LightDepthTexture->Activate();
        program->SetUniformi("lightDepth", in.LightDepthTexture->GetTextureUnit());
        program->SetUniformi("lightIndex", l);
        program->SetUniformf("nearDistance", static_cast<float>(nearDistance));
        program->SetUniformf("farDistance", static_cast<float>(farDistance));
        in.OcclusionQuad->Render();
        in.LightDepthTexture->Deactivate();
        in.OcclusionFramebuffer->RemoveColorAttachments(1); // see the map build
      }
      in.OcclusionFramebuffer->RemoveColorAttachments(1);
    }
    state->PopFramebufferBindings();
    viewCamera->UnRegister(this);
    return ok;
  };
  const bool occlusion = !occluders.empty() && buildOcclusion();

  // 6. Transmittance maps, rebuilt only when what they depend on changed.
  const bool needMaps = scattering && IsMapMethod(this->TransmittanceMethod) &&
    std::any_of(in.Lights.begin(), in.Lights.end(),
      [](const LightParameters& p) { return IsMapMethod(p.Method); });
  if (needMaps)
  {
    std::vector<double> mapKey = { double(this->TransmittanceMethod),
      double(this->NumberOfCoefficients), double(this->TransmittanceMapSize),
      double(this->LightSampleCount), this->AdaptiveThreshold, this->DensityScale };
    mapKey.insert(mapKey.end(), in.VolumeKey.begin(), in.VolumeKey.end());
    mapKey.insert(mapKey.end(), in.TransferKey.begin(), in.TransferKey.end());
    mapKey.insert(mapKey.end(), corners, corners + 24);
    for (const LightParameters& p : in.Lights)
    {
      mapKey.insert(mapKey.end(),
        { double(p.Positional), double(p.Method), p.Position[0], p.Position[1], p.Position[2],
          p.Direction[0], p.Direction[1], p.Direction[2] });
    }
    if (mapKey != in.MapKey)
    {
      vtkNew<vtkTimerLog> timer;
      timer->StartTimer();
      const int size = this->TransmittanceMapSize;
      const int slices = numberOfLights * layers;
      if (!in.MapTexture || in.MapSize != size || in.MapSlices != slices)
      {
        if (!in.MapTexture)
        {
          in.MapTexture = vtkSmartPointer<vtkTextureObject>::New();
        }
        in.MapTexture->ReleaseGraphicsResources(window);
        in.MapTexture->SetContext(window);
        in.MapTexture->SetWrapS(vtkTextureObject::ClampToEdge);
        in.MapTexture->SetWrapT(vtkTextureObject::ClampToEdge);
        in.MapTexture->SetWrapR(vtkTextureObject::ClampToEdge);
        in.MapTexture->SetMinificationFilter(vtkTextureObject::Linear);
        in.MapTexture->SetMagnificationFilter(vtkTextureObject::Linear);
        if (!in.MapTexture->Create3DFromRaw(size, size, slices, 4, VTK_FLOAT, nullptr))
        {
          vtkErrorMacro(<< "Could not allocate the transmittance maps (" << size << " x " << size
                        << " x " << slices << " RGBA float).");
          in.VolumeTexture->Deactivate();
          in.TransferTexture->Deactivate();
          return;
        }
        in.MapSize = size;
        in.MapSlices = slices;
      }
      // The map-build program for this number of layers.
      std::string outputs;
      for (int k = 0; k < layers; ++k)
      {
        std::ostringstream line;
        if (IsAdaptive(this->TransmittanceMethod) && k == layers - 1)
        {
          line << "  gl_FragData[" << k << "] = vec4(bounds, 0.0);\n";
        }
        else
        {
          line << "  gl_FragData[" << k << "] = vec4(coefficients[" << 4 * k << "], coefficients["
               << 4 * k + 1 << "], coefficients[" << 4 * k + 2 << "], coefficients[" << 4 * k + 3
               << "]);\n";
        }
        outputs += line.str();
      }
      std::string fs = std::string(vtkTransmittanceCommonFS) + vtkTransmittanceMapBuildFS;
      vtkShaderProgram::Substitute(fs, "//TYNDALL::MapOutputs", outputs);
      if (!in.MapQuad || fs != in.MapQuadSource)
      {
        in.MapQuad.reset(new vtkOpenGLQuadHelper(window,
          vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
        in.MapQuadSource = fs;
      }
      else
      {
        window->GetShaderCache()->ReadyShaderProgram(in.MapQuad->Program);
      }
      vtkShaderProgram* program = in.MapQuad->Program;
      if (!program || !program->GetCompiled())
      {
        vtkErrorMacro(<< "The transmittance-map shader did not compile.");
        in.VolumeTexture->Deactivate();
        in.TransferTexture->Deactivate();
        return;
      }
      setCommonUniforms(program);
      program->SetUniformi("method", this->TransmittanceMethod);
      program->SetUniformi("coefficientCount", this->NumberOfCoefficients);
      program->SetUniformi("sampleCount", this->LightSampleCount);
      program->SetUniformf("adaptiveThreshold", static_cast<float>(this->AdaptiveThreshold));

      if (!in.MapFramebuffer)
      {
        in.MapFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      }
      in.MapFramebuffer->SetContext(window);
      state->PushFramebufferBindings();
      in.MapFramebuffer->Bind();
      vtkOpenGLState::ScopedglViewport savedViewport(state);
      vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
      vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
      state->vtkglDisable(GL_BLEND);
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_SCISSOR_TEST); // the renderer's viewport scissor
      state->vtkglViewport(0, 0, size, size);
      bool ok = true;
      for (int l = 0; l < numberOfLights && ok; ++l)
      {
        if (!IsMapMethod(in.Lights[l].Method))
        {
          continue;
        }
        for (int k = 0; k < layers; ++k)
        {
          in.MapFramebuffer->AddColorAttachment(k, in.MapTexture, l * layers + k);
        }
        in.MapFramebuffer->ActivateDrawBuffers(layers);
        const char* status = nullptr;
        if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status))
        {
          vtkErrorMacro(<< "The transmittance-map framebuffer is incomplete: " << status);
          ok = false;
          break;
        }
        program->SetUniformi("lightIndex", l);
        in.MapQuad->Render();
        // vtkOpenGLFramebufferObject keeps an attachment of the same texture
        // even for another slice: detach before the next light's slices.
        in.MapFramebuffer->RemoveColorAttachments(layers);
      }
      in.MapFramebuffer->RemoveColorAttachments(layers);
      state->PopFramebufferBindings();
      glFinish();
      timer->StopTimer();
      if (!ok)
      {
        in.VolumeTexture->Deactivate();
        in.TransferTexture->Deactivate();
        return;
      }
      in.MapKey = mapKey;
      this->LastMapBuildTime = timer->GetElapsedTime();
      ++this->MapBuildCount;
    }
  }

  // 7. The depth of opaque geometry already drawn, resolved by a blit (the
  // window's frame buffer may be multisampled, which glCopyTexImage refuses).
  const int* windowSize = window->GetSize();
  if (!in.DepthTexture)
  {
    in.DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    in.DepthFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  in.DepthTexture->SetContext(window);
  in.DepthFramebuffer->SetContext(window);
  // A blit needs the same depth format on both sides: ask the window's.
  int depthFormat = vtkTextureObject::Float32;
  {
    GLint componentType = GL_FLOAT, bits = 32;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
      GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    if (componentType != GL_FLOAT)
    {
      depthFormat = bits <= 16
        ? vtkTextureObject::Fixed16
        : (bits <= 24 ? vtkTextureObject::Fixed24 : vtkTextureObject::Fixed32);
    }
  }
  if (in.DepthTexture->GetWidth() != static_cast<unsigned int>(windowSize[0]) ||
    in.DepthTexture->GetHeight() != static_cast<unsigned int>(windowSize[1]) ||
    in.DepthFormat != depthFormat)
  {
    in.DepthFormat = depthFormat;
    in.DepthTexture->ReleaseGraphicsResources(window);
    in.DepthTexture->SetContext(window);
    in.DepthTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    in.DepthTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    in.DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    in.DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    in.DepthTexture->AllocateDepth(windowSize[0], windowSize[1], depthFormat);
  }
  state->PushFramebufferBindings();
  in.DepthFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  in.DepthFramebuffer->AddDepthAttachment(in.DepthTexture);
  glBlitFramebuffer(0, 0, windowSize[0], windowSize[1], 0, 0, windowSize[0], windowSize[1],
    GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  in.DepthFramebuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  in.DepthTexture->Activate();

  // 8. The camera rays.
  std::string fs = std::string(vtkTransmittanceCommonFS) + vtkTransmittanceRayCastFS;
  if (!in.RayCastQuad)
  {
    in.RayCastQuad.reset(new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), ""));
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(in.RayCastQuad->Program);
  }
  vtkShaderProgram* program = in.RayCastQuad->Program;
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro(<< "The ray-casting shader did not compile.");
    in.DepthTexture->Deactivate();
    in.VolumeTexture->Deactivate();
    in.TransferTexture->Deactivate();
    return;
  }
  if (in.MapTexture)
  {
    in.MapTexture->Activate();
    program->SetUniformi("mapTexture", in.MapTexture->GetTextureUnit());
  }
  setCommonUniforms(program);
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> ndcToWorld;
  vtkMatrix4x4::Invert(
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1),
    ndcToWorld);
  float ndcToWorldF[16];
  ToColumnMajor(ndcToWorld, ndcToWorldF);
  program->SetUniformMatrix4x4("ndcToWorld", ndcToWorldF);
  program->SetUniformi("depthTexture", in.DepthTexture->GetTextureUnit());
  program->SetUniformi("useDepthTexture", 1);
  program->SetUniformi("scatteringModel", this->ScatteringModel);
  program->SetUniformi("method", this->TransmittanceMethod);
  program->SetUniformi("coefficientCount", this->NumberOfCoefficients);
  program->SetUniformi("layersPerLight", layers);
  program->SetUniformi("mapSlices", std::max(in.MapSlices, 1));
  const double step = this->SampleDistance > 0.0 ? this->SampleDistance : 0.5 * minWorldSpacing;
  // Mesa's llvmpipe (software OpenGL) stops all loops of a shader invocation
  // after 65535 iterations in total, silently: a ray would end early. Warn
  // when a frame can get there (counted per camera ray: its steps, plus the
  // brute-force light marches, eight samples per iteration).
  if (in.SoftwareRenderer < 0)
  {
    const char* rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    in.SoftwareRenderer = rendererName && std::strstr(rendererName, "llvmpipe") ? 1 : 0;
  }
  if (in.SoftwareRenderer == 1)
  {
    int bruteForceLights = 0;
    for (const LightParameters& p : in.Lights)
    {
      bruteForceLights += p.Method == BRUTE_FORCE ? 1 : 0;
    }
    const double iterations =
      (diagonal / step + 2.0) * (1.0 + bruteForceLights * std::ceil(this->LightSampleCount / 8.0));
    if (iterations > 65535.0 && !in.WarnedLoopLimit)
    {
      vtkWarningMacro(<< "llvmpipe stops a shader's loops after 65535 iterations; a camera ray "
                      << "here can need " << iterations
                      << ". Increase SampleDistance or lower LightSampleCount, or rays end early.");
      in.WarnedLoopLimit = true;
    }
  }
  program->SetUniformf("stepLength", static_cast<float>(step));
  program->SetUniformi("maxSteps", static_cast<int>(std::min(65536.0, diagonal / step + 2.0)));
  program->SetUniformi("lightSampleCount", this->LightSampleCount);
  program->SetUniformi("jitter", this->Jitter ? 1 : 0);
  program->SetUniformf("anisotropy", static_cast<float>(this->ScatteringAnisotropy));
  program->SetUniformf("ambient", static_cast<float>(this->AmbientIntensity));
  program->SetUniformf(
    "emissionScale", this->EmissionColor ? static_cast<float>(this->EmissionScale) : 0.0f);
  program->SetUniformi("numberOfLights", numberOfLights);
  program->SetUniformi("useOcclusion", occlusion ? 1 : 0);
  if (occlusion)
  {
    in.OcclusionTexture->Activate();
    program->SetUniformi("occlusionTexture", in.OcclusionTexture->GetTextureUnit());
    program->SetUniformi("occlusionSlices", in.OcclusionSlices);
    program->SetUniformf("occlusionBias", static_cast<float>(2.0 * minWorldSpacing));
  }
  float irradiance[kMaxLights][3] = {}, position[kMaxLights][3] = {}, direction[kMaxLights][3] = {},
        attenuation[kMaxLights][3] = {};
  float coneCosine[kMaxLights] = {}, exponent[kMaxLights] = {};
  int method[kMaxLights] = { 0 };
  for (int l = 0; l < numberOfLights; ++l)
  {
    const LightParameters& p = in.Lights[l];
    for (int k = 0; k < 3; ++k)
    {
      irradiance[l][k] = static_cast<float>(p.Irradiance[k]);
      position[l][k] = static_cast<float>(p.Position[k]);
      direction[l][k] = static_cast<float>(p.Direction[k]);
      attenuation[l][k] = static_cast<float>(p.Attenuation[k]);
    }
    coneCosine[l] = static_cast<float>(p.ConeCosine);
    exponent[l] = static_cast<float>(p.Exponent);
    method[l] = p.Method;
  }
  program->SetUniform3fv("lightIrradiance", kMaxLights, irradiance);
  program->SetUniform3fv("lightPosition", kMaxLights, position);
  program->SetUniform3fv("lightDirection", kMaxLights, direction);
  program->SetUniform3fv("lightAttenuation", kMaxLights, attenuation);
  program->SetUniform1fv("lightConeCosine", kMaxLights, coneCosine);
  program->SetUniform1fv("lightExponent", kMaxLights, exponent);
  program->SetUniform1iv("lightMethod", kMaxLights, method);

  {
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    in.RayCastQuad->Render();
  }

  if (in.MapTexture)
  {
    in.MapTexture->Deactivate();
  }
  if (occlusion)
  {
    in.OcclusionTexture->Deactivate();
  }
  in.DepthTexture->Deactivate();
  in.VolumeTexture->Deactivate();
  in.TransferTexture->Deactivate();
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScatteringModel: " << this->ScatteringModel << "\n";
  os << indent << "TransmittanceMethod: " << this->GetTransmittanceMethodAsString() << "\n";
  os << indent << "NumberOfCoefficients: " << this->NumberOfCoefficients << "\n";
  os << indent << "TransmittanceMapSize: " << this->TransmittanceMapSize << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "AdaptiveThreshold: " << this->AdaptiveThreshold << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "LightSampleCount: " << this->LightSampleCount << "\n";
  os << indent << "LightScale: " << this->LightScale << "\n";
  os << indent << "AmbientIntensity: " << this->AmbientIntensity << "\n";
  os << indent << "EmissionScale: " << this->EmissionScale << "\n";
  os << indent << "EmissionColor: " << this->EmissionColor << "\n";
  os << indent << "Jitter: " << (this->Jitter ? "On" : "Off") << "\n";
  os << indent << "MapBuildCount: " << this->MapBuildCount << "\n";
  os << indent << "LastMapBuildTime: " << this->LastMapBuildTime << "\n";
}
