#include "vtkTransmittanceAccumulationPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkTransmittanceAccumulationPass);

//------------------------------------------------------------------------------
vtkTransmittanceAccumulationPass::vtkTransmittanceAccumulationPass() = default;
vtkTransmittanceAccumulationPass::~vtkTransmittanceAccumulationPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::AllocateImage(const vtkTransmittanceFrame& frame,
  vtkSmartPointer<vtkTextureObject>& image, int width, int height, vtkObject* reporter)
{
  if (image && image->GetContext() == frame.Window &&
    image->GetWidth() == static_cast<unsigned int>(width) &&
    image->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
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
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Allocate(
  const vtkTransmittanceFrame& frame, int width, int height, bool chromatic, vtkObject* reporter)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Framebuffer->SetContext(frame.Window);
  for (int k = 0; k < 2; ++k)
  {
    if (!this->AllocateImage(frame, this->Images[k], width, height, reporter) ||
      (chromatic && !this->AllocateImage(frame, this->Opacities[k], width, height, reporter)))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkTransmittanceAccumulationPass::Attach(int k, bool chromatic)
{
  this->Framebuffer->AddColorAttachment(0, this->Images[k]);
  if (chromatic)
  {
    this->Framebuffer->AddColorAttachment(1, this->Opacities[k]);
  }
  const int targets = chromatic ? 2 : 1;
  this->Framebuffer->ActivateDrawBuffers(targets);
  return targets;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkTransmittanceAccumulationPass::CompositeProgram(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(vtkTransmittanceShaderSource::COMPOSITE));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The compositing shader did not compile.");
  }
  return program;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::AddToHistory(const vtkTransmittanceFrame& frame,
  vtkTextureObject* image, vtkTextureObject* opacity, int width, int height, int historyFrames,
  int samples, vtkObject* reporter)
{
  vtkTextureObject* old = this->History;
  vtkTextureObject* oldOpacity = this->HistoryOpacity;
  if (!this->AllocateImage(frame, this->History, width, height, reporter) ||
    (opacity && !this->AllocateImage(frame, this->HistoryOpacity, width, height, reporter)))
  {
    this->HistoryFrames = 0;
    return false;
  }
  if (!opacity && this->HistoryOpacity)
  {
    // A grey mean: no opacity images beside it (GetHistoryOpacity() null).
    this->HistoryOpacity->ReleaseGraphicsResources(frame.Window);
    this->HistoryOpacity = nullptr;
  }
  if (old != this->History.GetPointer() ||
    (opacity && oldOpacity != this->HistoryOpacity.GetPointer()))
  {
    historyFrames = 0; // a new image (or the first opacity image): nothing to average with
  }
  vtkShaderProgram* program = this->CompositeProgram(frame, reporter);
  if (!program)
  {
    return false;
  }
  vtkOpenGLState* state = frame.State;
  vtkTransmittanceOffscreenDraw offscreen(state, this->Framebuffer, width, height);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  // history = image s / (n + s) + history n / (n + s): the mean of the n
  // samples before it and the image's s; each channel's opacity image beside
  // it alike.
  samples = std::max(samples, 1);
  const int before = historyFrames > 0 ? this->HistorySamples : 0;
  if (historyFrames > 0)
  {
    state->vtkglEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f,
      static_cast<float>(static_cast<double>(samples) / (static_cast<double>(before) + samples)));
    state->vtkglBlendFuncSeparate(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA,
      GL_ONE_MINUS_CONSTANT_ALPHA);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
  for (vtkTextureObject* mean : { this->History.GetPointer(), this->HistoryOpacity.GetPointer() })
  {
    vtkTextureObject* added = mean == this->History ? image : opacity;
    if (!added)
    {
      continue;
    }
    this->Framebuffer->AddColorAttachment(0, mean);
    this->Framebuffer->ActivateDrawBuffers(1);
    added->SetMinificationFilter(vtkTextureObject::Nearest);
    added->SetMagnificationFilter(vtkTextureObject::Nearest);
    {
      vtkTransmittanceScopedTextures bind({ added });
      program->SetUniformi("accumulated", added->GetTextureUnit());
      program->SetUniformi("opacityCoversRadiance", 0); // an image, not the picture
      program->SetUniformi("chromaticBehind", 0);
      frame.SetOutputUniforms(program, false);
      this->Quad.Render();
    }
    this->Framebuffer->RemoveColorAttachments(1);
  }
  glBlendColor(0.0f, 0.0f, 0.0f, 0.0f); // GL's default; VTK does not track it
  this->HistoryFrames = historyFrames + 1;
  this->HistorySamples = before + samples;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Render(const vtkTransmittanceFrame& frame,
  const int viewport[4], int width, int height, int passes, const DrawFunction& draw,
  vtkObject* reporter, int historyFrames, bool chromatic, bool composite, int samples)
{
  this->Result = nullptr;
  this->ResultOpacity = nullptr;
  if (!this->Allocate(frame, width, height, chromatic, reporter))
  {
    return false;
  }
  vtkOpenGLState* state = frame.State;
  {
    vtkTransmittanceOffscreenDraw offscreen(state, this->Framebuffer, width, height);
    vtkOpenGLState::ScopedglClearColor savedClear(state);
    // The state before the first pass, in both images: no radiance,
    // transmittance 1 (what the pixels of a one-pass draw whose rays miss
    // keep: they discard).
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    int targets = 0;
    for (int k = 0; k < 2; ++k)
    {
      targets = this->Attach(k, chromatic);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      this->Framebuffer->RemoveColorAttachments(targets);
    }
    for (int pass = 0; pass < passes; ++pass)
    {
      targets = this->Attach(pass % 2, chromatic);
      const char* status = nullptr;
      if (!vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_DRAW_FRAMEBUFFER, status))
      {
        this->Framebuffer->RemoveColorAttachments(targets);
        vtkErrorWithObjectMacro(
          reporter, << "The camera rays' framebuffer is incomplete: " << status);
        return false;
      }
      vtkTextureObject* previous = this->Images[(pass + 1) % 2];
      vtkTextureObject* previousOpacity = chromatic ? this->Opacities[(pass + 1) % 2] : nullptr;
      for (vtkTextureObject* image : { previous, previousOpacity })
      {
        if (image)
        {
          image->SetMinificationFilter(vtkTextureObject::Nearest);
          image->SetMagnificationFilter(vtkTextureObject::Nearest);
        }
      }
      {
        vtkTransmittanceScopedTextures bind({ previous, previousOpacity });
        draw(pass, previous, previousOpacity);
      }
      this->Framebuffer->RemoveColorAttachments(targets);
    }
  }
  const bool upscaled = width != viewport[2] || height != viewport[3];
  vtkTextureObject* result = this->Images[(passes - 1) % 2];
  vtkTextureObject* opacity = chromatic ? this->Opacities[(passes - 1) % 2].GetPointer() : nullptr;
  this->Result = result;
  this->ResultOpacity = opacity;
  if (historyFrames < 0)
  {
    this->HistoryFrames = 0;
    return !composite || this->Composite(frame, result, opacity, upscaled, reporter);
  }
  return this->AddToHistory(
           frame, result, opacity, width, height, historyFrames, samples, reporter) &&
    (!composite ||
      this->Composite(frame, this->History, this->GetHistoryOpacity(), upscaled, reporter));
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::CompositeResult(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  if (!this->Result)
  {
    vtkErrorWithObjectMacro(reporter, << "There is no image to draw.");
    return false;
  }
  return this->Composite(frame, this->Result, this->ResultOpacity, false, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::CompositeHistory(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  if (this->HistoryFrames <= 0 || !this->History)
  {
    vtkErrorWithObjectMacro(reporter, << "There is no running average to draw.");
    return false;
  }
  return this->Composite(frame, this->History, this->GetHistoryOpacity(), false, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::CompositeImage(
  const vtkTransmittanceFrame& frame, vtkTextureObject* image, vtkObject* reporter)
{
  return this->Composite(frame, image, this->GetHistoryOpacity(), false, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceAccumulationPass::Composite(const vtkTransmittanceFrame& frame,
  vtkTextureObject* image, vtkTextureObject* opacity, bool upscaled, vtkObject* reporter)
{
  vtkShaderProgram* program = this->CompositeProgram(frame, reporter);
  if (!program)
  {
    return false;
  }
  const int filter = upscaled ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  for (vtkTextureObject* texture : { image, opacity })
  {
    if (texture)
    {
      texture->SetMinificationFilter(filter);
      texture->SetMagnificationFilter(filter);
    }
  }
  const int covers = frame.Integrator.OpacityCoversRadiance ? 1 : 0;
  if (!opacity)
  {
    vtkTransmittanceScopedTextures bind({ image });
    program->SetUniformi("accumulated", image->GetTextureUnit());
    program->SetUniformi("opacityCoversRadiance", covers);
    program->SetUniformi("chromaticBehind", 0);
    frame.SetOutputUniforms(program, true);
    this->Quad.RenderOver(frame.State);
    return true;
  }
  // Per channel: background x transmittance, then + radiance.
  {
    vtkTransmittanceScopedTextures bind({ opacity });
    program->SetUniformi("accumulated", opacity->GetTextureUnit());
    program->SetUniformi("opacityCoversRadiance", 0);
    program->SetUniformi("chromaticBehind", 0);
    frame.SetOutputUniforms(program, false); // a transmittance, not light
    this->Quad.RenderOver(
      frame.State, GL_ZERO, GL_ONE_MINUS_SRC_COLOR, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
  }
  // (The display transform sees the background through the transmittance
  // per channel, as the draw before applied it.)
  vtkTransmittanceScopedTextures bind({ image, opacity });
  program->SetUniformi("accumulated", image->GetTextureUnit());
  program->SetUniformi("opacityCoversRadiance", covers);
  program->SetUniformi("chromaticBehind", 1);
  program->SetUniformi("transmittanceImage", opacity->GetTextureUnit());
  frame.SetOutputUniforms(program, true);
  this->Quad.RenderOver(frame.State, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceAccumulationPass::ReleaseScratch(vtkWindow* window)
{
  for (int k = 0; k < 2; ++k)
  {
    if (this->Images[k] == this->Result)
    {
      continue;
    }
    for (vtkSmartPointer<vtkTextureObject>* image : { &this->Images[k], &this->Opacities[k] })
    {
      if (*image)
      {
        (*image)->ReleaseGraphicsResources(window);
      }
      *image = nullptr;
    }
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceAccumulationPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkSmartPointer<vtkTextureObject>* image : { &this->Images[0], &this->Images[1],
         &this->Opacities[0], &this->Opacities[1], &this->History, &this->HistoryOpacity })
  {
    if (*image)
    {
      (*image)->ReleaseGraphicsResources(window);
    }
    *image = nullptr;
  }
  this->HistoryFrames = 0;
  this->Result = nullptr;
  this->ResultOpacity = nullptr;
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
  os << indent << "HistoryFrames: " << this->HistoryFrames << "\n";
  os << indent << "HistorySamples: " << this->GetHistorySamples() << "\n";
}
