/**
 * @class   vtkTransmittanceOffscreenDraw
 * @brief   what the passes that fill textures slice by slice share
 *
 * The map, transmittance-cache and occlusion passes render full-screen
 * quads into slices of 3-D textures. SetClamped() prepares such a texture
 * (clamp to edge on every axis; linear or nearest filtering); a
 * vtkTransmittanceOffscreenDraw object, for its scope, binds the pass's
 * framebuffer, saves the viewport, blending, depth test and scissor test,
 * turns the three tests off (the renderer's viewport scissor would clip the
 * slice) and sets the viewport to the slice, restoring everything when the
 * scope ends. Header only; internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceOffscreenDraw_h
#define vtkTransmittanceOffscreenDraw_h

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceScopedFramebuffer.h"
#include "vtk_glew.h"

class vtkTransmittanceOffscreenDraw
{
public:
  vtkTransmittanceOffscreenDraw(
    vtkOpenGLState* state, vtkOpenGLFramebufferObject* framebuffer, int width, int height)
    : Bound(state, framebuffer)
    , Viewport(state)
    , Blend(state, GL_BLEND)
    , Depth(state, GL_DEPTH_TEST)
    , Scissor(state, GL_SCISSOR_TEST)
  {
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglViewport(0, 0, width, height);
  }
  vtkTransmittanceOffscreenDraw(const vtkTransmittanceOffscreenDraw&) = delete;
  vtkTransmittanceOffscreenDraw& operator=(const vtkTransmittanceOffscreenDraw&) = delete;

  /// Context, clamp to edge on every axis, linear (else nearest) filtering.
  static void SetClamped(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, bool linear)
  {
    texture->SetContext(window);
    texture->SetWrapS(vtkTextureObject::ClampToEdge);
    texture->SetWrapT(vtkTextureObject::ClampToEdge);
    texture->SetWrapR(vtkTextureObject::ClampToEdge);
    const int filter = linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
    texture->SetMinificationFilter(filter);
    texture->SetMagnificationFilter(filter);
  }

private:
  vtkTransmittanceScopedFramebuffer Bound;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Depth;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
};

#endif
