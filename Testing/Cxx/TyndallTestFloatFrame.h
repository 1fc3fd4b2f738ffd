// The tests' float frame buffer: the renderer draws through a
// vtkFramebufferPass with an RGBA32F colour texture, so the mapper's linear
// values (above 1 included) can be read back unrounded. Header only; not
// part of the library.
#ifndef TyndallTestFloatFrame_h
#define TyndallTestFloatFrame_h

#include "vtkFramebufferPass.h"
#include "vtkNew.h"
#include "vtkPixelBufferObject.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"

#include "TyndallTestCheck.h"

#include <vector>

namespace tyndall_test
{
// Renders the window and reads its float frame buffer back (RGBA, bottom-up).
inline std::vector<float> RenderFloat(vtkRenderWindow* window, vtkFramebufferPass* pass)
{
  window->Render();
  window->MakeCurrent();
  vtkTextureObject* texture = pass->GetColorTexture();
  std::vector<float> rgba;
  vtkPixelBufferObject* pbo = texture ? texture->Download() : nullptr;
  const float* data = pbo ? static_cast<const float*>(pbo->MapPackedBuffer()) : nullptr;
  if (data)
  {
    rgba.assign(data, data + size_t(texture->GetWidth()) * texture->GetHeight() * 4);
    pbo->UnmapPackedBuffer();
  }
  if (pbo)
  {
    pbo->Delete();
  }
  Check(!rgba.empty(), "the float frame buffer reads back");
  return rgba;
}

// A renderer drawn into a float frame buffer for the object's lifetime.
struct FloatFrame
{
  vtkNew<vtkFramebufferPass> Pass;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkRenderer* Renderer;
  vtkRenderWindow* Window;

  FloatFrame(vtkRenderer* renderer, vtkRenderWindow* window)
    : Renderer(renderer)
    , Window(window)
  {
    this->Pass->SetColorFormat(vtkTextureObject::Float32);
    this->Pass->SetDelegatePass(this->Steps);
    renderer->SetPass(this->Pass);
  }
  ~FloatFrame()
  {
    this->Renderer->SetPass(nullptr);
    this->Pass->ReleaseGraphicsResources(this->Window);
  }
  FloatFrame(const FloatFrame&) = delete;
  FloatFrame& operator=(const FloatFrame&) = delete;

  std::vector<float> Render() { return RenderFloat(this->Window, this->Pass); }
};
}

#endif
