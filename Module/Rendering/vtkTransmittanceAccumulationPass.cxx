#include "vtkTransmittanceAccumulationPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceScopedFramebuffer.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkTransmittanceAccumulationPass);

//------------------------------------------------------------------------------
vtkTransmittanceAccumulationPass::vtkTransmittanceAccumulationPass() = default;
vtkTransmittanceAccumulationPass::~vtkTransmittanceAccumulationPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Allocate(
  const vtkTransmittanceFrame& frame, int width, int height, vtkObject* reporter)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  for (vtkSmartPointer<vtkTextureObject>& image : this->Images)
  {
    if (image && image->GetContext() == frame.Window &&
      image->GetWidth() == static_cast<unsigned int>(width) &&
      image->GetHeight() == static_cast<unsigned int>(height))
    {
      continue;
    }
    if (image)
    {
      image->ReleaseGraphicsResources(frame.Window);
    }
    image = vtkSmartPointer<vtkTextureObject>::New();
    image->SetContext(frame.Window);
    image->SetWrapS(vtkTextureObject::ClampToEdge);
    image->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!image->Allocate2D(width, height, 4, VTK_FLOAT))
    {
      vtkErrorWithObjectMacro(reporter,
        << "Could not allocate a " << width << " x " << height << " image for the camera rays.");
      image = nullptr;
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Render(const vtkTransmittanceFrame& frame,
  const int viewport[4], int width, int height, int passes, const DrawFunction& draw,
  vtkObject* reporter)
{
  if (!this->Allocate(frame, width, height, reporter))
  {
    return false;
  }
  vtkOpenGLState* state = frame.State;
  {
    vtkTransmittanceScopedFramebuffer bound(state, this->Framebuffer);
    vtkOpenGLState::ScopedglViewport savedViewport(state);
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglClearColor savedClear(state);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST); // the renderer's viewport scissor
    state->vtkglViewport(0, 0, width, height);
    // The state before the first pass: no radiance, transmittance 1.
    this->Framebuffer->AddColorAttachment(0, this->Images[1]);
    this->Framebuffer->ActivateDrawBuffers(1);
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->Framebuffer->RemoveColorAttachments(1);
    for (int pass = 0; pass < passes; ++pass)
    {
      this->Framebuffer->AddColorAttachment(0, this->Images[pass % 2]);
      this->Framebuffer->ActivateDrawBuffers(1);
      const char* status = nullptr;
      if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status))
      {
        this->Framebuffer->RemoveColorAttachments(1);
        vtkErrorWithObjectMacro(
          reporter, << "The camera rays' framebuffer is incomplete: " << status);
        return false;
      }
      vtkTextureObject* previous = this->Images[(pass + 1) % 2];
      previous->SetMinificationFilter(vtkTextureObject::Nearest);
      previous->SetMagnificationFilter(vtkTextureObject::Nearest);
      {
        vtkTransmittanceScopedTextures bind({ previous });
        draw(pass, previous);
      }
      this->Framebuffer->RemoveColorAttachments(1);
    }
  }
  const bool upscaled = width != viewport[2] || height != viewport[3];
  return this->Composite(frame, this->Images[(passes - 1) % 2], upscaled, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Composite(
  const vtkTransmittanceFrame& frame, vtkTextureObject* image, bool upscaled, vtkObject* reporter)
{
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(vtkTransmittanceShaderSource::COMPOSITE));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The compositing shader did not compile.");
    return false;
  }
  const int filter = upscaled ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  image->SetMinificationFilter(filter);
  image->SetMagnificationFilter(filter);
  vtkTransmittanceScopedTextures bind({ image });
  program->SetUniformi("accumulated", image->GetTextureUnit());
  this->Quad.RenderOver(frame.State);
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceAccumulationPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkSmartPointer<vtkTextureObject>& image : this->Images)
  {
    if (image)
    {
      image->ReleaseGraphicsResources(window);
    }
    image = nullptr;
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
  this->Quad.Release(window);
}

//------------------------------------------------------------------------------
void vtkTransmittanceAccumulationPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkTextureObject* image = this->Images[0];
  os << indent << "Images: "
     << (image ? std::to_string(this->Images[0]->GetWidth()) + " x " +
              std::to_string(this->Images[0]->GetHeight())
               : std::string("none"))
     << "\n";
}
