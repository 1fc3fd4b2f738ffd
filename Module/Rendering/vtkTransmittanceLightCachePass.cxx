#include "vtkTransmittanceLightCachePass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallGridMedium.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittanceLightCachePass);

//------------------------------------------------------------------------------
vtkTransmittanceLightCachePass::vtkTransmittanceLightCachePass() = default;
vtkTransmittanceLightCachePass::~vtkTransmittanceLightCachePass() = default;

//------------------------------------------------------------------------------
void vtkTransmittanceLightCachePass::LatticeSize(const double extents[3], int size, int lattice[3])
{
  const double longest = std::max({ extents[0], extents[1], extents[2] });
  for (int i = 0; i < 3; ++i)
  {
    const double share = longest > 0.0 && std::isfinite(longest) ? extents[i] / longest : 1.0;
    lattice[i] = std::max(2, static_cast<int>(std::lround(size * share)));
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceLightCachePass::Render(const vtkTransmittanceFrame& frame,
  vtkTextureObject* maps, int mapSlices, vtkMTimeType mapBuild, vtkObject* reporter)
{
  if (frame.Integrator.CacheSize < 2 || !maps || !frame.NeedsMaps())
  {
    return false;
  }
  int size[3];
  LatticeSize(frame.CameraBoxExtents, frame.Integrator.CacheSize, size);
  const int lights = static_cast<int>(frame.Lights.size());
  const double* color = frame.Medium->GetParameters().ExtinctionColor;
  const float* box = frame.CameraBoxToWorld;
  if (this->CacheTexture && mapBuild == this->BuiltFromMaps && lights == this->Lights &&
    std::equal(size, size + 3, this->Size) && std::equal(color, color + 3, this->Color) &&
    std::equal(box, box + 16, this->BoxToWorld))
  {
    return true;
  }
  this->BuiltFromMaps = 0;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  if (!this->Allocate(frame, size, reporter) || !this->Build(frame, maps, mapSlices, reporter))
  {
    return false;
  }
  glFinish();
  timer->StopTimer();
  this->BuiltFromMaps = mapBuild;
  std::copy(color, color + 3, this->Color);
  std::copy(box, box + 16, this->BoxToWorld);
  this->LastBuildTime = timer->GetElapsedTime();
  ++this->BuildCount;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceLightCachePass::Allocate(
  const vtkTransmittanceFrame& frame, const int size[3], vtkObject* reporter)
{
  const int lights = static_cast<int>(frame.Lights.size());
  const bool chromatic = frame.Medium->GetParameters().GetChromatic();
  if (this->CacheTexture && lights == this->Lights && std::equal(size, size + 3, this->Size) &&
    chromatic == this->Chromatic)
  {
    return true;
  }
  if (!this->CacheTexture)
  {
    this->CacheTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->CacheTexture->ReleaseGraphicsResources(frame.Window);
  vtkTransmittanceOffscreenDraw::SetClamped(this->CacheTexture, frame.Window, true);
  this->CacheTexture->SetInternalFormat(chromatic ? GL_RGBA16F : GL_R16F);
  const int components = chromatic ? 4 : 1;
  int maximum3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maximum3D);
  const int depth = size[2] * lights;
  const double bytes = 2.0 * components * size[0] * size[1] * static_cast<double>(depth);
  if (bytes > MaximumBytes || std::max({ size[0], size[1], depth }) > maximum3D ||
    !this->CacheTexture->Create3DFromRaw(size[0], size[1], depth, components, VTK_FLOAT, nullptr))
  {
    vtkErrorWithObjectMacro(
      reporter, << "Could not allocate the transmittance cache (" << size[0] << " x " << size[1]
                << " x " << depth << " half floats, " << bytes / (1 << 20) << " MiB; at most "
                << MaximumBytes / (1 << 20) << " MiB and a side of " << maximum3D
                << "); the camera rays read the maps instead. A smaller "
                   "TransmittanceCacheSize fits.");
    this->CacheTexture = nullptr;
    this->Lights = 0;
    std::fill(this->Size, this->Size + 3, 0);
    return false;
  }
  std::copy(size, size + 3, this->Size);
  this->Lights = lights;
  this->Chromatic = chromatic;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceLightCachePass::Build(
  const vtkTransmittanceFrame& frame, vtkTextureObject* maps, int mapSlices, vtkObject* reporter)
{
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(
      vtkTransmittanceShaderSource::LIGHT_CACHE, frame.GetMapVariant()));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The transmittance-cache shader did not compile.");
    return false;
  }
  vtkTransmittanceScopedTextures textures({ maps });
  frame.SetMediumUniforms(program);
  frame.SetMapUniforms(program, maps, mapSlices);
  const float size[3] = { float(this->Size[0]), float(this->Size[1]), float(this->Size[2]) };
  program->SetUniform3f("lightCacheSize", size);
  program->SetUniformMatrix4x4("boxToWorld", const_cast<float*>(frame.CameraBoxToWorld));

  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  vtkTransmittanceOffscreenDraw draw(frame.State, this->Framebuffer, this->Size[0], this->Size[1]);
  for (int l = 0; l < this->Lights; ++l)
  {
    if (!vtkTransmittanceMapMath::IsMapMethod(frame.Lights[l].Method))
    {
      continue; // brute force: the camera rays march to this light
    }
    program->SetUniformi("lightIndex", l);
    for (int k = 0; k < this->Size[2]; ++k)
    {
      this->Framebuffer->AddColorAttachment(0, this->CacheTexture, l * this->Size[2] + k);
      this->Framebuffer->ActivateDrawBuffers(1);
      const char* status = nullptr;
      const bool complete =
        vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status);
      if (complete)
      {
        program->SetUniformf("sliceCoordinate", static_cast<float>(k) / (this->Size[2] - 1));
        this->Quad.Render();
      }
      // vtkOpenGLFramebufferObject keeps an attachment of the same texture
      // even for another slice: detach before the next.
      this->Framebuffer->RemoveColorAttachments(1);
      if (!complete)
      {
        vtkErrorWithObjectMacro(
          reporter, << "The transmittance-cache framebuffer is incomplete: " << status);
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightCachePass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->CacheTexture)
  {
    this->CacheTexture->ReleaseGraphicsResources(window);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Quad.Release(window);
  this->CacheTexture = nullptr;
  this->Lights = 0;
  std::fill(this->Size, this->Size + 3, 0);
  this->BuiltFromMaps = 0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceLightCachePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " " << this->Size[1] << " " << this->Size[2] << "\n";
  os << indent << "Lights: " << this->Lights << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
  os << indent << "LastBuildTime: " << this->LastBuildTime << "\n";
}
