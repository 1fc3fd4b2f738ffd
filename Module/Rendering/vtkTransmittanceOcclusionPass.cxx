#include "vtkTransmittanceOcclusionPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedFramebuffer.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtk_glew.h"

#include <vector>

vtkStandardNewMacro(vtkTransmittanceOcclusionPass);

namespace
{
// The visible opaque actors of the renderer.
std::vector<vtkActor*> Occluders(vtkRenderer* renderer)
{
  std::vector<vtkActor*> occluders;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (actor && actor->GetVisibility() && actor->GetMapper() && actor->HasOpaqueGeometry())
    {
      occluders.push_back(actor);
    }
  }
  return occluders;
}

// Draws with another active camera for a scope, then restores the view's.
class ScopedCamera
{
public:
  ScopedCamera(vtkRenderer* renderer, vtkCamera* camera)
    : Renderer(renderer)
    , Saved(renderer->GetActiveCamera())
  {
    renderer->SetActiveCamera(camera);
  }
  ~ScopedCamera() { this->Renderer->SetActiveCamera(this->Saved); }

private:
  vtkRenderer* Renderer;
  vtkSmartPointer<vtkCamera> Saved;
};
}

//------------------------------------------------------------------------------
vtkTransmittanceOcclusionPass::vtkTransmittanceOcclusionPass() = default;
vtkTransmittanceOcclusionPass::~vtkTransmittanceOcclusionPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceOcclusionPass::Allocate(const vtkTransmittanceFrame& frame)
{
  const int size = frame.Integrator.MapSize;
  const int slices = static_cast<int>(frame.Lights.size());
  if (this->OcclusionTexture && this->Size == size && this->Slices == slices)
  {
    return true;
  }
  this->ReleaseGraphicsResources(frame.Window);
  this->OcclusionTexture = vtkSmartPointer<vtkTextureObject>::New();
  this->LightDepthTexture = vtkSmartPointer<vtkTextureObject>::New();
  this->LightColorTexture = vtkSmartPointer<vtkTextureObject>::New();
  for (vtkTextureObject* texture :
    { this->OcclusionTexture.Get(), this->LightDepthTexture.Get(), this->LightColorTexture.Get() })
  {
    vtkTransmittanceOffscreenDraw::SetClamped(texture, frame.Window, false);
  }
  if (!this->OcclusionTexture->Create3DFromRaw(size, size, slices, 1, VTK_FLOAT, nullptr) ||
    !this->LightDepthTexture->AllocateDepth(size, size, vtkTextureObject::Float32) ||
    !this->LightColorTexture->Allocate2D(size, size, 4, VTK_UNSIGNED_CHAR))
  {
    this->ReleaseGraphicsResources(frame.Window);
    return false;
  }
  this->Size = size;
  this->Slices = slices;
  this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->Framebuffer->SetContext(frame.Window);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceOcclusionPass::Render(const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  this->Actors = frame.Lights.empty() ? std::vector<vtkActor*>() : Occluders(frame.Renderer);
  if (this->Actors.empty())
  {
    return false;
  }
  if (!this->Allocate(frame))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not allocate the light-space occlusion textures.");
    return false;
  }
  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkTransmittanceScopedFramebuffer bound(state, this->Framebuffer);
  bool ok = true;
  for (int l = 0; l < static_cast<int>(frame.Lights.size()) && ok; ++l)
  {
    if (frame.Lights[l].HasFrustum)
    {
      ok = this->RenderLight(frame, l, reporter);
    }
  }
  this->Actors.clear();
  return ok;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceOcclusionPass::RenderLight(
  const vtkTransmittanceFrame& frame, int light, vtkObject* reporter)
{
  vtkOpenGLState* state = frame.State;
  vtkTransmittanceLightFrustum* frustum = frame.Lights[light].Frustum;
  vtkNew<vtkCamera> lightCamera;
  frustum->ConfigureCamera(frame.Corners, lightCamera);

  // Depth of the opaque actors seen from the light.
  this->Framebuffer->AddColorAttachment(0, this->LightColorTexture);
  this->Framebuffer->AddDepthAttachment(this->LightDepthTexture);
  this->Framebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, this->Size, this->Size);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  {
    ScopedCamera fromLight(frame.Renderer, lightCamera);
    for (vtkActor* actor : this->Actors)
    {
      actor->RenderOpaqueGeometry(frame.Renderer);
    }
  }
  this->Framebuffer->RemoveDepthAttachment();

  // Depth -> distance along the map rays, into the light's slice.
  this->Framebuffer->AddColorAttachment(0, this->OcclusionTexture, light);
  this->Framebuffer->ActivateDrawBuffers(1);
  state->vtkglDisable(GL_DEPTH_TEST);
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(vtkTransmittanceShaderSource::OCCLUSION));
  const bool compiled = program != nullptr;
  if (compiled)
  {
    vtkTransmittanceScopedTextures textures({ this->LightDepthTexture });
    frame.SetMediumUniforms(program);
    program->SetUniformi("lightDepth", this->LightDepthTexture->GetTextureUnit());
    program->SetUniformi("lightIndex", light);
    program->SetUniformf("nearDistance", static_cast<float>(frustum->GetNearDistance()));
    program->SetUniformf("farDistance", static_cast<float>(frustum->GetFarDistance()));
    this->Quad.Render();
  }
  else
  {
    vtkErrorWithObjectMacro(reporter, << "The occlusion shader did not compile.");
  }
  // vtkOpenGLFramebufferObject keeps an attachment of the same texture even
  // for another slice: detach before the next light.
  this->Framebuffer->RemoveColorAttachments(1);
  return compiled;
}

//------------------------------------------------------------------------------
void vtkTransmittanceOcclusionPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture :
    { this->OcclusionTexture.Get(), this->LightDepthTexture.Get(), this->LightColorTexture.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Quad.Release(window);
  this->OcclusionTexture = nullptr;
  this->LightDepthTexture = nullptr;
  this->LightColorTexture = nullptr;
  this->Framebuffer = nullptr;
  this->Slices = this->Size = 0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size << "\n";
  os << indent << "Slices: " << this->Slices << "\n";
}
