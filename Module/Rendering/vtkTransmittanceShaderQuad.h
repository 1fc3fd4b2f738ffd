/**
 * @class   vtkTransmittanceShaderQuad
 * @brief   a full-screen quad and the fragment shader it was built for
 *
 * Each pass of vtkTransmittanceVolumeMapper draws one full-screen quad
 * (vtkOpenGLQuadHelper) with its own fragment shader, whose source can
 * change between frames (vtkTransmittanceShaderSource's variants: the map
 * layout, whether the medium has missing data). Ready() builds the quad for
 * a source, rebuilds it when the source changes and otherwise only binds
 * its program. Header only; internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceShaderQuad_h
#define vtkTransmittanceShaderQuad_h

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkTransmittanceShaderQuad
{
public:
  /**
   * The quad's program for `fragmentShader`, bound and ready for its
   * uniforms; nullptr when the shader did not compile.
   */
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, const std::string& fragmentShader)
  {
    if (!this->Quad || fragmentShader != this->Source)
    {
      this->Release(window);
      this->Quad.reset(new vtkOpenGLQuadHelper(window,
        vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fragmentShader.c_str(),
        ""));
      this->Source = fragmentShader;
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
    }
    vtkShaderProgram* program = this->Quad->Program;
    return program && program->GetCompiled() ? program : nullptr;
  }

  /// Draws the quad with the program Ready() returned.
  void Render() { this->Quad->Render(); }

  /**
   * Draws the quad's premultiplied colour over what was drawn (blended ONE,
   * ONE_MINUS_SRC_ALPHA, or the factors given; no depth test or depth
   * writes), restoring the state after.
   */
  void RenderOver(vtkOpenGLState* state, GLenum sourceColor = GL_ONE,
    GLenum destinationColor = GL_ONE_MINUS_SRC_ALPHA, GLenum sourceAlpha = GL_ONE,
    GLenum destinationAlpha = GL_ONE_MINUS_SRC_ALPHA)
  {
    vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
    vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(sourceColor, destinationColor, sourceAlpha, destinationAlpha);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    this->Quad->Render();
  }

  /// Releases the quad's OpenGL resources.
  void Release(vtkWindow* window)
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(window);
    }
    this->Quad.reset();
    this->Source.clear();
  }

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Source;
};

#endif
