#include "vtkTransmittancePeelingPass.h"

#include "vtkAbstractMapper.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <string>

vtkStandardNewMacro(vtkTransmittancePeelingPass);

namespace
{
using Source = vtkTransmittanceShaderSource;

// The stage a pass's replacements for a volume's fragment shader declare:
// the samplers VTK 9.1's vtkDualDepthPeelingPass gives its own ray caster in
// each (PreReplaceVolumetricShaderValues).
int StageOf(const std::string& replaced)
{
  if (replaced.find("lastFrontColorTex") != std::string::npos)
  {
    return Source::PeelPeeling;
  }
  if (replaced.find("depthRangeTex") != std::string::npos)
  {
    return Source::PeelBlending;
  }
  if (replaced.find("outerDepthTex") != std::string::npos)
  {
    return Source::PeelInitializing;
  }
  return vtkTransmittancePeelingPass::NoStage;
}
}

//------------------------------------------------------------------------------
vtkTransmittancePeelingPass::vtkTransmittancePeelingPass() = default;
vtkTransmittancePeelingPass::~vtkTransmittancePeelingPass() = default;

//------------------------------------------------------------------------------
int vtkTransmittancePeelingPass::FindStage(
  vtkVolume* volume, vtkAbstractMapper* mapper, vtkOpenGLRenderPass*& pass)
{
  pass = nullptr;
  vtkInformation* keys = volume ? volume->GetPropertyKeys() : nullptr;
  if (!keys || !keys->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    return NoStage;
  }
  const int count = keys->Length(vtkOpenGLRenderPass::RenderPasses());
  for (int i = 0; i < count; ++i)
  {
    auto* peeling =
      vtkDualDepthPeelingPass::SafeDownCast(keys->Get(vtkOpenGLRenderPass::RenderPasses(), i));
    if (!peeling)
    {
      continue;
    }
    const std::string probe = "//VTK::DepthPeeling::Dec\n//VTK::CallWorker::Impl\n";
    std::string vertex, geometry, fragment = probe;
    peeling->PreReplaceShaderValues(vertex, geometry, fragment, mapper, volume);
    const int stage = StageOf(fragment);
    if (stage != NoStage || fragment != probe)
    {
      pass = peeling;
      return stage != NoStage ? stage : UnknownStage;
    }
  }
  return NoStage;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePeelingPass::AllocateRanges(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  const int* size = frame.Window->GetSize();
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  if (this->Ranges && this->Ranges->GetContext() == frame.Window &&
    this->Ranges->GetWidth() == static_cast<unsigned int>(size[0]) &&
    this->Ranges->GetHeight() == static_cast<unsigned int>(size[1]))
  {
    return true;
  }
  if (this->Ranges)
  {
    this->Ranges->ReleaseGraphicsResources(frame.Window);
  }
  this->Ranges = vtkSmartPointer<vtkTextureObject>::New();
  vtkTransmittanceOffscreenDraw::SetClamped(this->Ranges, frame.Window, false);
  if (!this->Ranges->Allocate2D(size[0], size[1], 4, VTK_FLOAT))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not allocate the " << size[0] << " x " << size[1]
                                      << " depth ranges for depth peeling.");
    this->Ranges = nullptr;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePeelingPass::RenderRanges(const vtkTransmittanceFrame& frame,
  vtkOpenGLRenderPass* pass, int stage, vtkAbstractMapper* mapper, vtkVolume* volume,
  vtkObject* reporter)
{
  if (!this->AllocateRanges(frame, reporter))
  {
    return false;
  }
  vtkShaderProgram* program =
    this->RangesQuad.Ready(frame.Window, Source::GetFragmentShader(Source::PEEL_RANGES));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The depth-peeling ranges shader did not compile.");
    return false;
  }
  int viewport[4];
  frame.Renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  const int* size = frame.Window->GetSize();
  vtkTransmittanceOffscreenDraw offscreen(frame.State, this->Framebuffer, size[0], size[1]);
  frame.State->vtkglViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  this->Framebuffer->AddColorAttachment(0, this->Ranges);
  this->Framebuffer->ActivateDrawBuffers(1);
  const char* status = nullptr;
  if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status))
  {
    this->Framebuffer->RemoveColorAttachments(1);
    vtkErrorWithObjectMacro(
      reporter, << "The depth-peeling ranges' framebuffer is incomplete: " << status);
    return false;
  }
  program->SetUniformi("peelStage", stage);
  const float viewportSize[2] = { static_cast<float>(viewport[2]),
    static_cast<float>(viewport[3]) };
  program->SetUniform2f("viewportSize", viewportSize);
  pass->SetShaderParameters(program, mapper, volume, nullptr); // the pass's textures
  this->RangesQuad.Render();
  this->Framebuffer->RemoveColorAttachments(1);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePeelingPass::Composite(const vtkTransmittanceFrame& frame,
  vtkOpenGLRenderPass* pass, int stage, vtkTextureObject* front, vtkTextureObject* back,
  vtkAbstractMapper* mapper, vtkVolume* volume, bool opacityCoversRadiance, vtkObject* reporter)
{
  vtkShaderProgram* program =
    this->CompositeQuad.Ready(frame.Window, Source::GetFragmentShader(Source::PEEL_COMPOSITE));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The depth-peeling compositing shader did not compile.");
    return false;
  }
  back = back ? back : front;
  for (vtkTextureObject* image : { front, back })
  {
    // A reduced image is upscaled, as vtkTransmittanceAccumulationPass does.
    image->SetMinificationFilter(vtkTextureObject::Linear);
    image->SetMagnificationFilter(vtkTextureObject::Linear);
  }
  vtkTransmittanceScopedTextures bind({ front, back });
  program->SetUniformi("frontImage", front->GetTextureUnit());
  program->SetUniformi("backImage", back->GetTextureUnit());
  program->SetUniformi("peelStage", stage);
  program->SetUniformi("opacityCoversRadiance", opacityCoversRadiance ? 1 : 0);
  // (Each peel's light is mapped alone, before VTK blends the peels; over
  // black, as the peels are not drawn over the background.)
  frame.SetOutputUniforms(program, true, false);
  pass->SetShaderParameters(program, mapper, volume, nullptr);
  // The pass's targets, blending and viewport as it set them; no depth test.
  vtkOpenGLState::ScopedglEnableDisable depth(frame.State, GL_DEPTH_TEST);
  frame.State->vtkglDisable(GL_DEPTH_TEST);
  this->CompositeQuad.Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittancePeelingPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Ranges)
  {
    this->Ranges->ReleaseGraphicsResources(window);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Ranges = nullptr;
  this->Framebuffer = nullptr;
  this->RangesQuad.Release(window);
  this->CompositeQuad.Release(window);
}

//------------------------------------------------------------------------------
void vtkTransmittancePeelingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Framebuffer: " << this->Framebuffer.GetPointer() << "\n";
  os << indent << "Ranges: "
     << (this->Ranges ? std::to_string(this->Ranges->GetWidth()) + " x " +
              std::to_string(this->Ranges->GetHeight())
                      : std::string("none"))
     << "\n";
}
