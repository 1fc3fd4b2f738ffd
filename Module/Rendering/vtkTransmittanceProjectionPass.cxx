#include "vtkTransmittanceProjectionPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallProjection.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittanceProjectionPass);

//------------------------------------------------------------------------------
vtkTransmittanceProjectionPass::vtkTransmittanceProjectionPass() = default;
vtkTransmittanceProjectionPass::~vtkTransmittanceProjectionPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceProjectionPass::Render(
  const vtkTransmittanceFrame& frame, vtkTextureObject* depth, vtkObject* reporter, int segment)
{
  const bool direct = segment < 0;
  // The medium's switches alone: no empty-space skipping (an empty block
  // still holds samples a maximum, minimum or average counts), no guests.
  vtkTransmittanceShaderSource::Variant variant = frame.GetShaderVariant();
  variant.SkipEmpty = false;
  variant.Chromatic = false;
  variant.Projection = frame.Medium->GetProjection().GetMode();
  // The slice of one component is shaded as VTK 9.1 shades it (vtkTyndallShading).
  variant.Shading = frame.Medium->GetShading().Enabled();
  variant.DepthRanges = !direct;
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(
      vtkTransmittanceShaderSource::PROJECTION, variant));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The projection shader did not compile.");
    return false;
  }
  vtkTransmittanceScopedTextures textures({ depth });
  frame.SetMediumUniforms(program);
  int viewport[4];
  frame.Renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  frame.SetCameraUniforms(program, depth, direct, viewport, viewport[2], viewport[3]);
  if (!direct)
  {
    program->SetUniformi("depthRangeHalf", segment);
  }
  // The mapper's SampleDistance, else VTK's automatic step (the smallest
  // world spacing: a projection needs no finer one); longer where a ray
  // across the box would take more than MaximumSteps.
  const double sampleDistance = frame.Integrator.SampleDistance;
  double step = sampleDistance > 0.0 ? sampleDistance : frame.MinimumSpacing;
  // (The slice takes one sample: never lengthened.)
  const bool lengthened = frame.Medium->GetProjection().GetMode() != vtkTyndallProjection::SLICE &&
    frame.Diagonal / step > MaximumSteps - 2;
  if (lengthened)
  {
    step = frame.Diagonal / (MaximumSteps - 2);
    if (!this->WarnedLongSteps)
    {
      vtkWarningWithObjectMacro(reporter, << "The projection's rays would take more than "
                                          << MaximumSteps << " steps; they take steps of " << step
                                          << " instead (set a larger SampleDistance).");
    }
  }
  this->WarnedLongSteps = lengthened;
  this->LastStepLength = step;
  program->SetUniformf("stepLength", static_cast<float>(step));
  program->SetUniformi("endStep", static_cast<int>(std::ceil(frame.Diagonal / step)) + 2);
  this->SetUniforms(frame, program);
  frame.SetLightUniforms(program);
  frame.SetOutputUniforms(program, direct);
  if (direct)
  {
    this->Quad.RenderOver(frame.State);
    return true;
  }
  // One pass into an image of the viewport's size, kept for the peeling
  // stage; cleared first: the projection discards the pixels it leaves.
  auto draw = [this, &frame](int, vtkTextureObject*, vtkTextureObject*)
  {
    frame.State->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    frame.State->vtkglClear(GL_COLOR_BUFFER_BIT);
    this->Quad.Render();
  };
  return this->Offscreen[segment == 1 ? 1 : 0]->Render(
    frame, viewport, viewport[2], viewport[3], 1, draw, reporter, -1, false, false);
}

//------------------------------------------------------------------------------
void vtkTransmittanceProjectionPass::SetUniforms(
  const vtkTransmittanceFrame& frame, vtkShaderProgram* program) const
{
  const vtkTyndallTransferTable& table = frame.Medium->GetTable();
  const vtkTyndallProjection& projection = frame.Medium->GetProjection();
  const float toUnit[2] = { static_cast<float>(table.UnitScale()),
    static_cast<float>(table.UnitShift()) };
  program->SetUniform2f("valueToUnit", toUnit);
  const double* range = projection.GetAverageRange();
  const float average[2] = { static_cast<float>(std::max(range[0], -1e38)),
    static_cast<float>(std::min(range[1], 1e38)) };
  program->SetUniform2f("averageRange", average);
  program->SetUniformf("additiveScale", static_cast<float>(1.0 / projection.GetUnitDistance()));
  if (frame.Medium->GetComponents().Enabled())
  {
    // Declared only by the components' variant: each component's (dependent
    // ones read their opacity component's, as VTK).
    float scales[4];
    for (int c = 0; c < 4; ++c)
    {
      scales[c] = static_cast<float>(1.0 / projection.GetUnitDistance(c));
    }
    program->SetUniform4f("componentAdditiveScale", scales);
  }
  if (projection.GetMode() == vtkTyndallProjection::SLICE)
  {
    // Declared only by the slice variant.
    const double* plane = projection.GetSlicePlane();
    const float slice[4] = { float(plane[0]), float(plane[1]), float(plane[2]), float(plane[3]) };
    program->SetUniform4f("slicePlane", slice);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceProjectionPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Quad.Release(window);
  for (vtkTransmittanceAccumulationPass* offscreen : this->Offscreen)
  {
    offscreen->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceProjectionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastStepLength: " << this->LastStepLength << "\n";
}
