#include "vtkTransmittanceDenoisePass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceAccumulationPass.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallDenoiser.h"

vtkStandardNewMacro(vtkTransmittanceDenoisePass);

//------------------------------------------------------------------------------
vtkTransmittanceDenoisePass::vtkTransmittanceDenoisePass() = default;
vtkTransmittanceDenoisePass::~vtkTransmittanceDenoisePass() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkTransmittanceDenoisePass::Filter(const vtkTransmittanceFrame& frame,
  vtkTextureObject* mean, vtkTextureObject* guide, int iterations, double edgeStop,
  vtkObject* reporter)
{
  if (!mean || !guide || mean->GetWidth() != guide->GetWidth() ||
    mean->GetHeight() != guide->GetHeight() || iterations < 1 ||
    iterations > vtkTyndallDenoiser::MaximumIterations || !(edgeStop > 0.0))
  {
    vtkErrorWithObjectMacro(reporter, << "The denoiser needs a mean and a guide of one size.");
    return nullptr;
  }
  const int width = static_cast<int>(mean->GetWidth());
  const int height = static_cast<int>(mean->GetHeight());
  for (vtkSmartPointer<vtkTextureObject>& image : this->Images)
  {
    if (!vtkTransmittanceAccumulationPass::AllocateImage(frame, image, width, height, reporter))
    {
      return nullptr;
    }
  }
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(vtkTransmittanceShaderSource::DENOISE));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The denoising shader did not compile.");
    return nullptr;
  }
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  for (vtkTextureObject* image : { mean, guide, this->Images[0].Get(), this->Images[1].Get() })
  {
    image->SetMinificationFilter(vtkTextureObject::Nearest);
    image->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  vtkTransmittanceOffscreenDraw offscreen(frame.State, this->Framebuffer, width, height);
  program->SetUniformf("denoiseScale", static_cast<float>(1.0 / (edgeStop * edgeStop)));
  for (int pass = 0; pass < iterations; ++pass)
  {
    vtkTextureObject* target = this->Images[pass % 2];
    vtkTextureObject* residual = pass == 0 ? mean : this->Images[(pass + 1) % 2].Get();
    this->Framebuffer->AddColorAttachment(0, target);
    this->Framebuffer->ActivateDrawBuffers(1);
    {
      vtkTransmittanceScopedTextures bind({ mean, guide, residual == mean ? nullptr : residual });
      program->SetUniformi("meanImage", mean->GetTextureUnit());
      program->SetUniformi("guideImage", guide->GetTextureUnit());
      program->SetUniformi("residualImage", residual->GetTextureUnit());
      program->SetUniformi("denoiseFirst", pass == 0 ? 1 : 0);
      program->SetUniformi("denoiseLast", pass + 1 == iterations ? 1 : 0);
      program->SetUniformi("denoiseStep", 1 << pass);
      this->Quad.Render();
    }
    this->Framebuffer->RemoveColorAttachments(1);
  }
  return this->Images[(iterations - 1) % 2];
}

//------------------------------------------------------------------------------
void vtkTransmittanceDenoisePass::ReleaseGraphicsResources(vtkWindow* window)
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
void vtkTransmittanceDenoisePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Images: "
     << (this->Images[0] ? std::to_string(this->Images[0]->GetWidth()) + " x " +
              std::to_string(this->Images[0]->GetHeight())
                         : std::string("none"))
     << "\n";
}
