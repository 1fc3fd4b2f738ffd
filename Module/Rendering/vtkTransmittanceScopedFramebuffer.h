/**
 * @class   vtkTransmittanceScopedFramebuffer
 * @brief   binds a framebuffer for a scope and restores the previous bindings after it
 *
 * Saves the window's framebuffer bindings (vtkOpenGLState's
 * PushFramebufferBindings), binds `framebuffer` (for drawing and reading, or
 * for `mode` alone), and restores the saved bindings when the scope ends,
 * whatever path leaves it. Header only; internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceScopedFramebuffer_h
#define vtkTransmittanceScopedFramebuffer_h

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLState.h"

class vtkTransmittanceScopedFramebuffer
{
public:
  vtkTransmittanceScopedFramebuffer(vtkOpenGLState* state, vtkOpenGLFramebufferObject* framebuffer)
    : State(state)
  {
    state->PushFramebufferBindings();
    framebuffer->Bind();
  }
  vtkTransmittanceScopedFramebuffer(
    vtkOpenGLState* state, vtkOpenGLFramebufferObject* framebuffer, unsigned int mode)
    : State(state)
  {
    state->PushFramebufferBindings();
    framebuffer->Bind(mode);
  }
  ~vtkTransmittanceScopedFramebuffer() { this->State->PopFramebufferBindings(); }
  vtkTransmittanceScopedFramebuffer(const vtkTransmittanceScopedFramebuffer&) = delete;
  vtkTransmittanceScopedFramebuffer& operator=(const vtkTransmittanceScopedFramebuffer&) = delete;

private:
  vtkOpenGLState* State;
};

#endif
