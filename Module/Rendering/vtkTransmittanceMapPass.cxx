#include "vtkTransmittanceMapPass.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceMapReducer.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTransmittanceSplatPass.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallParticles.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

vtkStandardNewMacro(vtkTransmittanceMapPass);

namespace
{
// The map-build shader's outputs for the frame's layout: layer k holds
// coefficients 4k .. 4k+3; the bounds layer (s_min, s_max, T_beyond, 0).
std::string MapOutputs(int layers, int boundsLayer)
{
  std::ostringstream os;
  for (int k = 0; k < layers; ++k)
  {
    os << "  gl_FragData[" << k << "] = ";
    if (k == boundsLayer)
    {
      os << "vec4(bounds, 0.0);\n";
      continue;
    }
    const int first = vtkTransmittanceMapMath::COEFFICIENTS_PER_LAYER * k;
    os << "vec4(coefficients[" << first << "], coefficients[" << first + 1 << "], coefficients["
       << first + 2 << "], coefficients[" << first + 3 << "]);\n";
  }
  return os.str();
}
}

//------------------------------------------------------------------------------
vtkTransmittanceMapPass::vtkTransmittanceMapPass() = default;
vtkTransmittanceMapPass::~vtkTransmittanceMapPass() = default;

//------------------------------------------------------------------------------
std::vector<double> vtkTransmittanceMapPass::Key(const vtkTransmittanceFrame& frame) const
{
  const vtkTransmittanceFrame::Settings& s = frame.Integrator;
  // The threshold only where the maps use it (the adaptive methods).
  const double threshold = frame.BoundsLayer >= 0 ? s.AdaptiveThreshold : -1.0;
  std::vector<double> key = { double(s.Method), double(s.Coefficients), double(s.MapSize),
    double(s.LightSampleCount), threshold, double(s.SkipEmptySpace), double(frame.MapSets) };
  if (frame.MapSets > 1)
  {
    const double* e = frame.Medium->GetParameters().ExtinctionColor;
    key.insert(key.end(), e, e + 3);
  }
  // Every medium the light crosses, as a set (sorted): the textures the
  // build samples (which mapper's, and their upload), its density scale and
  // placement (the maps' box is in the frusta below). Textures, not the
  // medium's own times: a guest is another reader's copy of the medium.
  std::vector<std::vector<double>> media;
  auto add = [&media](const vtkTyndallGridMedium& m, const vtkTransmittanceMediumTextures* t,
               const float worldToBox[16])
  {
    std::vector<double> k = { double(reinterpret_cast<std::uintptr_t>(t)),
      double(t->GetExtinctionContentTime()), m.GetParameters().DensityScale };
    k.insert(k.end(), worldToBox, worldToBox + 16);
    media.push_back(k);
  };
  add(*frame.Medium, frame.Textures, frame.WorldToBox);
  for (const vtkTransmittanceFrame::Guest& g : frame.Guests)
  {
    add(*g.Medium, g.Textures, g.WorldToBox);
  }
  std::sort(media.begin(), media.end());
  for (const std::vector<double>& k : media)
  {
    key.insert(key.end(), k.begin(), k.end());
  }
  key.push_back(double(media.size()));
  // The splatted particle media (their particles and which medium each is).
  for (const vtkTransmittanceFrame::Splat& splat : frame.Splats)
  {
    key.insert(key.end(), { double(splat.Guest), double(splat.Particles->GetReadTime()) });
  }
  key.push_back(double(frame.Splats.size()));
  // Per light, its method and, when it has a map, the frustum the map is
  // built along (which also covers the frustum's padding and field of view).
  for (const vtkTransmittanceFrame::Light& l : frame.Lights)
  {
    key.push_back(double(l.Method));
    if (vtkTransmittanceMapMath::IsMapMethod(l.Method))
    {
      vtkTransmittanceLightFrustum* f = l.Frustum;
      key.push_back(double(f->GetPositional()));
      for (const double* v : { f->GetOrigin(), f->GetAxisX(), f->GetAxisY(), f->GetAxisZ() })
      {
        key.insert(key.end(), v, v + 3);
      }
    }
  }
  return key;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::IsBuiltFor(const vtkTransmittanceFrame& frame) const
{
  return this->MapTexture && !this->BuiltKey.empty() && this->Key(frame) == this->BuiltKey;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::Render(const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  vtkTransmittanceMapReducer* reducer = frame.Integrator.Reducer;
  if (!frame.NeedsMaps())
  {
    return reducer ? this->SkipReduction(reducer, reporter) : true;
  }
  const std::vector<double> key = this->Key(frame);
  // With a reducer, maps that were built from this piece alone are rebuilt
  // and added (vtkTransmittanceVolumeMapper's fallback in Render()).
  bool build = key != this->BuiltKey || !this->MapTexture || (reducer && !this->BuiltAdded);
  vtkIdType count = 4 * static_cast<vtkIdType>(frame.Integrator.MapSize) *
    frame.Integrator.MapSize * static_cast<vtkIdType>(frame.Lights.size()) * frame.Layers *
    frame.MapSets;
  if (reducer && !this->Agree(reducer, build, count, reporter))
  {
    return false;
  }
  if (!build)
  {
    return true;
  }
  this->BuiltKey.clear();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  bool built = this->Allocate(frame, reporter) && this->Build(frame, reporter);
  if (reducer)
  {
    // Every process adds its maps, built or (on failure) zeros.
    built = this->Reduce(reducer, built, count, reporter) && built;
  }
  if (!built)
  {
    return false;
  }
  glFinish();
  timer->StopTimer();
  this->BuiltKey = key;
  this->BuiltAdded = reducer != nullptr;
  this->LastBuildTime = timer->GetElapsedTime();
  ++this->BuildCount;
  this->BuildTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::Agree(
  vtkTransmittanceMapReducer* reducer, bool& build, vtkIdType& count, vtkObject* reporter) const
{
  double agreed[2] = { build ? 1.0 : 0.0, static_cast<double>(count) };
  if (!reducer->AllReduceMax(agreed, 2))
  {
    vtkErrorWithObjectMacro(reporter, << "The processes could not agree on the maps.");
    return false;
  }
  build = agreed[0] > 0.0;
  if (build && count != 0 && static_cast<vtkIdType>(agreed[1]) != count)
  {
    vtkErrorWithObjectMacro(reporter, << "The processes' maps differ in size (" << count
                                      << " floats here, " << agreed[1]
                                      << " elsewhere): their lights or map settings differ.");
  }
  count = static_cast<vtkIdType>(agreed[1]);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::SkipReduction(
  vtkTransmittanceMapReducer* reducer, vtkObject* reporter)
{
  bool build = false;
  vtkIdType count = 0;
  if (!this->Agree(reducer, build, count, reporter))
  {
    return false;
  }
  return !build || this->Reduce(reducer, false, count, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::ReadBack(std::vector<float>& values) const
{
  if (!this->MapTexture ||
    values.size() != static_cast<size_t>(4) * this->Size * this->Size * this->Slices)
  {
    return false;
  }
  vtkOpenGLClearErrorMacro();
  {
    // RGBA floats: rows are 4-byte aligned whatever GL's pack alignment.
    vtkTransmittanceScopedTextures bound({ this->MapTexture });
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, values.data());
  }
  return glGetError() == GL_NO_ERROR;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::Reduce(
  vtkTransmittanceMapReducer* reducer, bool built, vtkIdType count, vtkObject* reporter)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const vtkIdType mine =
    built ? 4 * static_cast<vtkIdType>(this->Size) * this->Size * this->Slices : 0;
  bool readable = built && mine == count;
  std::vector<float> values(static_cast<size_t>(count), 0.0f);
  if (readable && !this->ReadBack(values))
  {
    vtkErrorWithObjectMacro(reporter, << "The maps could not be read back: zeros are added.");
    std::fill(values.begin(), values.end(), 0.0f);
    readable = false;
  }
  const bool summed = reducer->AllReduceSum(values.data(), count);
  if (readable && summed)
  {
    vtkTransmittanceScopedTextures bound({ this->MapTexture });
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, this->Size, this->Size, this->Slices, GL_RGBA,
      GL_FLOAT, values.data());
  }
  timer->StopTimer();
  reducer->SetLastReductionTime(timer->GetElapsedTime());
  reducer->SetLastReductionSize(count);
  if (!summed)
  {
    vtkErrorWithObjectMacro(reporter, << "The processes could not add their maps.");
    return false;
  }
  return !built || readable;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::Allocate(const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  const int size = frame.Integrator.MapSize;
  const int slices = static_cast<int>(frame.Lights.size()) * frame.Layers * frame.MapSets;
  if (this->MapTexture && this->Size == size && this->Slices == slices)
  {
    return true;
  }
  if (!this->MapTexture)
  {
    this->MapTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->MapTexture->ReleaseGraphicsResources(frame.Window);
  vtkTransmittanceOffscreenDraw::SetClamped(this->MapTexture, frame.Window, true);
  if (!this->MapTexture->Create3DFromRaw(size, size, slices, 4, VTK_FLOAT, nullptr))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not allocate the transmittance maps (" << size
                                      << " x " << size << " x " << slices << " RGBA float).");
    this->MapTexture = nullptr;
    this->Size = this->Slices = 0;
    return false;
  }
  this->Size = size;
  this->Slices = slices;
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkTransmittanceMapPass::ReadyProgram(const vtkTransmittanceFrame& frame)
{
  vtkTransmittanceShaderSource::Variant variant = frame.GetShaderVariant();
  // The empty blocks are the medium's: with guests the light ray crosses
  // other media there, so every sample is taken.
  variant.SkipEmpty = variant.SkipEmpty && variant.Guests == 0;
  std::string fs = vtkTransmittanceShaderSource::GetFragmentShader(
    vtkTransmittanceShaderSource::MAP_BUILD, variant);
  vtkShaderProgram::Substitute(
    fs, "//TYNDALL::MapOutputs", MapOutputs(frame.Layers, frame.BoundsLayer));
  return this->Quad.Ready(frame.Window, fs);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::Build(const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  vtkShaderProgram* program = this->ReadyProgram(frame);
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The transmittance-map shader did not compile.");
    return false;
  }
  const vtkTransmittanceFrame::Settings& s = frame.Integrator;
  frame.SetMediumUniforms(program);
  frame.SetMarchedDensities(program);
  program->SetUniformi("method", s.Method);
  program->SetUniformi("coefficientCount", s.Coefficients);
  program->SetUniformi("sampleCount", s.LightSampleCount);
  program->SetUniformf("adaptiveThreshold", static_cast<float>(s.AdaptiveThreshold));

  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  vtkTransmittanceOffscreenDraw draw(frame.State, this->Framebuffer, this->Size, this->Size);
  const int layers = frame.Layers;
  const int lights = static_cast<int>(frame.Lights.size());
  // Set k of lights x layers slices: channel k's maps (one set without them).
  for (int i = 0; i < lights * frame.MapSets; ++i)
  {
    const int l = i % lights;
    if (!vtkTransmittanceMapMath::IsMapMethod(frame.Lights[l].Method))
    {
      continue;
    }
    const int set = i / lights;
    program->SetUniformf("channelExtinction",
      frame.MapSets > 1 ? static_cast<float>(frame.Medium->GetParameters().ExtinctionColor[set])
                        : 1.0f);
    for (int k = 0; k < layers; ++k)
    {
      this->Framebuffer->AddColorAttachment(k, this->MapTexture, i * layers + k);
    }
    this->Framebuffer->ActivateDrawBuffers(layers);
    const char* status = nullptr;
    const bool complete =
      vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status);
    bool drawn = complete;
    if (complete && frame.AllSplatted())
    {
      // Nothing to march: the splats add to zero.
      vtkOpenGLState::ScopedglClearColor savedClear(frame.State);
      frame.State->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      frame.State->vtkglClear(GL_COLOR_BUFFER_BIT);
    }
    else if (complete)
    {
      frame.Window->GetShaderCache()->ReadyShaderProgram(program); // after a light's splats
      program->SetUniformi("lightIndex", l);
      this->Quad.Render();
    }
    if (complete && !frame.Splats.empty())
    {
      drawn = this->Splats->Render(frame, l, MapOutputs(layers, frame.BoundsLayer), reporter);
    }
    // vtkOpenGLFramebufferObject keeps an attachment of the same texture
    // even for another slice: detach before the next light's slices.
    this->Framebuffer->RemoveColorAttachments(layers);
    if (!complete)
    {
      vtkErrorWithObjectMacro(
        reporter, << "The transmittance-map framebuffer is incomplete: " << status);
      return false;
    }
    if (!drawn)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMapPass::GetMap(
  int light, int layers, int boundsLayer, int coefficients, vtkImageData* map)
{
  if (!this->MapTexture || !map || layers < 1 || light < 0 || (light + 1) * layers > this->Slices)
  {
    return false;
  }
  const size_t texels = static_cast<size_t>(this->Size) * this->Size;
  std::vector<float> all(4 * texels * this->Slices);
  if (!this->ReadBack(all))
  {
    return false;
  }
  vtkNew<vtkFloatArray> coefficientArray;
  coefficientArray->SetName("Coefficients");
  coefficientArray->SetNumberOfComponents(coefficients);
  coefficientArray->SetNumberOfTuples(static_cast<vtkIdType>(texels));
  vtkNew<vtkFloatArray> boundsArray;
  boundsArray->SetName("Bounds");
  boundsArray->SetNumberOfComponents(3);
  boundsArray->SetNumberOfTuples(boundsLayer >= 0 ? static_cast<vtkIdType>(texels) : 0);
  const int perLayer = vtkTransmittanceMapMath::COEFFICIENTS_PER_LAYER;
  for (size_t t = 0; t < texels; ++t)
  {
    for (int j = 0; j < coefficients; ++j)
    {
      const size_t slice = static_cast<size_t>(light) * layers + j / perLayer;
      coefficientArray->SetTypedComponent(
        static_cast<vtkIdType>(t), j, all[4 * (slice * texels + t) + j % perLayer]);
    }
    if (boundsLayer >= 0)
    {
      const size_t slice = static_cast<size_t>(light) * layers + boundsLayer;
      for (int c = 0; c < 3; ++c)
      {
        boundsArray->SetTypedComponent(
          static_cast<vtkIdType>(t), c, all[4 * (slice * texels + t) + c]);
      }
    }
  }
  map->Initialize();
  map->SetDimensions(this->Size, this->Size, 1);
  map->SetSpacing(1.0 / this->Size, 1.0 / this->Size, 1.0);
  map->SetOrigin(0.5 / this->Size, 0.5 / this->Size, 0.0);
  map->GetPointData()->AddArray(coefficientArray);
  if (boundsLayer >= 0)
  {
    map->GetPointData()->AddArray(boundsArray);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMapPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->MapTexture)
  {
    this->MapTexture->ReleaseGraphicsResources(window);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Quad.Release(window);
  this->Splats->ReleaseGraphicsResources(window);
  this->MapTexture = nullptr;
  this->Framebuffer = nullptr;
  this->BuiltKey.clear();
  this->Slices = this->Size = 0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Slices: " << this->Slices << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << "\n";
}
