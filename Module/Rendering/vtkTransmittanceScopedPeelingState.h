/**
 * @class   vtkTransmittanceScopedPeelingState
 * @brief   GL's default blending and no culling for a scope inside VTK's depth peeling
 *
 * vtkDualDepthPeelingPass draws volumes with MAX blending and back-face
 * culling on, state the mapper's own passes (maps, occlusion, splats, ray
 * casts) do not expect: the splats add with blending, a MAX equation would
 * keep their largest. For its scope this object sets the blend equation to
 * ADD and turns culling off, and restores both when the scope ends, before
 * vtkTransmittancePeelingPass::Composite() writes the pass's targets in the
 * pass's own state. (VTK 9.1 draws a frame's first stage, where the maps are
 * built, with the ADD equation; the guard keeps the passes independent of
 * that order.) Header only; internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceScopedPeelingState_h
#define vtkTransmittanceScopedPeelingState_h

#include "vtkOpenGLState.h"
#include "vtk_glew.h"

class vtkTransmittanceScopedPeelingState
{
public:
  explicit vtkTransmittanceScopedPeelingState(vtkOpenGLState* state)
    : State(state)
    , Culling(state->GetEnumState(GL_CULL_FACE))
  {
    // vtkOpenGLState tracks the equation but does not say it: GL does.
    GLint rgb = GL_FUNC_ADD, alpha = GL_FUNC_ADD;
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &rgb);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &alpha);
    this->Equation[0] = static_cast<unsigned int>(rgb);
    this->Equation[1] = static_cast<unsigned int>(alpha);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglDisable(GL_CULL_FACE);
  }
  ~vtkTransmittanceScopedPeelingState()
  {
    this->State->vtkglBlendEquationSeparate(this->Equation[0], this->Equation[1]);
    if (this->Culling)
    {
      this->State->vtkglEnable(GL_CULL_FACE);
    }
  }
  vtkTransmittanceScopedPeelingState(const vtkTransmittanceScopedPeelingState&) = delete;
  vtkTransmittanceScopedPeelingState& operator=(const vtkTransmittanceScopedPeelingState&) = delete;

private:
  vtkOpenGLState* State;
  bool Culling;
  unsigned int Equation[2]; // RGB, alpha
};

#endif
