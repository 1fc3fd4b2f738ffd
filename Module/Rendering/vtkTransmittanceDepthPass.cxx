#include "vtkTransmittanceDepthPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceScopedFramebuffer.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkTransmittanceDepthPass);

namespace
{
// The depth format of the framebuffer bound for reading.
int ReadDepthFormat()
{
  GLint componentType = GL_FLOAT, bits = 32;
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
    GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
  if (componentType == GL_FLOAT)
  {
    return vtkTextureObject::Float32;
  }
  return bits <= 16 ? vtkTextureObject::Fixed16
                    : (bits <= 24 ? vtkTextureObject::Fixed24 : vtkTextureObject::Fixed32);
}
}

//------------------------------------------------------------------------------
vtkTransmittanceDepthPass::vtkTransmittanceDepthPass() = default;
vtkTransmittanceDepthPass::~vtkTransmittanceDepthPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceDepthPass::Render(const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  const int* size = frame.Window->GetSize();
  if (!this->DepthTexture)
  {
    this->DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->DepthTexture->SetContext(frame.Window);
  this->Framebuffer->SetContext(frame.Window);
  const int format = ReadDepthFormat();
  if (this->DepthTexture->GetWidth() != static_cast<unsigned int>(size[0]) ||
    this->DepthTexture->GetHeight() != static_cast<unsigned int>(size[1]) ||
    this->DepthFormat != format)
  {
    this->DepthFormat = format;
    this->DepthTexture->ReleaseGraphicsResources(frame.Window);
    this->DepthTexture->SetContext(frame.Window);
    this->DepthTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->DepthTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!this->DepthTexture->AllocateDepth(size[0], size[1], format))
    {
      vtkErrorWithObjectMacro(reporter, << "Could not allocate the depth texture.");
      this->DepthFormat = -1;
      return false;
    }
  }
  vtkTransmittanceScopedFramebuffer bound(frame.State, this->Framebuffer, GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddDepthAttachment(this->DepthTexture);
  glBlitFramebuffer(
    0, 0, size[0], size[1], 0, 0, size[0], size[1], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  this->Framebuffer->RemoveDepthAttachment();
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceDepthPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DepthTexture)
  {
    this->DepthTexture->ReleaseGraphicsResources(window);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->DepthTexture = nullptr;
  this->Framebuffer = nullptr;
  this->DepthFormat = -1;
}

//------------------------------------------------------------------------------
void vtkTransmittanceDepthPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthFormat: " << this->DepthFormat << "\n";
}
