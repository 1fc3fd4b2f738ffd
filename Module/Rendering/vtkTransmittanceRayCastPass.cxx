#include "vtkTransmittanceRayCastPass.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallSceneReader.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkTransmittanceRayCastPass);

namespace
{
constexpr int kMaxLights = vtkTyndallSceneReader::MaximumNumberOfLights;
// llvmpipe's total loop-iteration limit per shader invocation.
constexpr double kLoopLimit = 65535.0;
// Brute-force light marches take this many samples per loop iteration.
constexpr double kBruteForceUnroll = 8.0;

// Column-major float copy of a VTK (row-major) matrix, for glUniformMatrix.
void ToColumnMajor(vtkMatrix4x4* m, float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[c * 4 + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}
}

//------------------------------------------------------------------------------
vtkTransmittanceRayCastPass::vtkTransmittanceRayCastPass() = default;
vtkTransmittanceRayCastPass::~vtkTransmittanceRayCastPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceRayCastPass::Render(
  const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkObject* reporter)
{
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(
      vtkTransmittanceShaderSource::RAY_CAST, frame.GetShaderVariant()));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The ray-casting shader did not compile.");
    return false;
  }
  vtkTransmittanceScopedTextures textures({ inputs.Depth, inputs.Maps, inputs.Occlusion });
  frame.SetMediumUniforms(program);
  if (inputs.Maps)
  {
    program->SetUniformi("mapTexture", inputs.Maps->GetTextureUnit());
  }
  vtkNew<vtkMatrix4x4> ndcToWorld;
  vtkMatrix4x4::Invert(frame.Renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                         frame.Renderer->GetTiledAspectRatio(), -1, 1),
    ndcToWorld);
  float ndcToWorldF[16];
  ToColumnMajor(ndcToWorld, ndcToWorldF);
  program->SetUniformMatrix4x4("ndcToWorld", ndcToWorldF);
  program->SetUniformi("depthTexture", inputs.Depth->GetTextureUnit());

  const vtkTransmittanceFrame::Settings& s = frame.Integrator;
  const vtkTyndallGridMedium& medium = *frame.Medium;
  program->SetUniformi("scatteringModel", medium.GetScatteringModel());
  program->SetUniformi("method", s.Method);
  program->SetUniformi("coefficientCount", s.Coefficients);
  program->SetUniformi("layersPerLight", std::max(frame.Layers, 1));
  program->SetUniformi("boundsLayer", std::max(frame.BoundsLayer, 0));
  program->SetUniformi("mapSlices", std::max(inputs.MapSlices, 1));
  const double step = frame.GetStepLength();
  this->WarnAboutLoopLimit(frame, reporter);
  program->SetUniformf("stepLength", static_cast<float>(step));
  program->SetUniformi(
    "maxSteps", static_cast<int>(std::min(65536.0, frame.Diagonal / step + 2.0)));
  program->SetUniformi("lightSampleCount", s.LightSampleCount);
  program->SetUniformi("jitter", s.Jitter ? 1 : 0);
  program->SetUniformf("anisotropy", static_cast<float>(medium.GetScatteringAnisotropy()));
  program->SetUniformf("ambient", static_cast<float>(medium.GetAmbientIntensity()));
  program->SetUniformf("emissionScale",
    medium.GetHasEmission() ? static_cast<float>(medium.GetEmissionScale()) : 0.0f);
  program->SetUniformi("useOcclusion", inputs.Occlusion ? 1 : 0);
  if (inputs.Occlusion)
  {
    program->SetUniformi("occlusionTexture", inputs.Occlusion->GetTextureUnit());
    program->SetUniformi("occlusionSlices", inputs.OcclusionSlices);
    program->SetUniformf("occlusionBias", static_cast<float>(2.0 * frame.MinimumSpacing));
  }
  this->SetLightUniforms(frame, program);

  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepth(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  this->Quad.Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::SetLightUniforms(
  const vtkTransmittanceFrame& frame, vtkShaderProgram* program) const
{
  float irradiance[kMaxLights][3] = {}, position[kMaxLights][3] = {}, direction[kMaxLights][3] = {},
        attenuation[kMaxLights][3] = {};
  float coneCosine[kMaxLights] = {}, exponent[kMaxLights] = {};
  int method[kMaxLights] = { 0 };
  for (size_t l = 0; l < frame.Lights.size(); ++l)
  {
    const vtkTransmittanceFrame::Light& light = frame.Lights[l];
    for (int k = 0; k < 3; ++k)
    {
      irradiance[l][k] = static_cast<float>(light.Source.Irradiance[k]);
      position[l][k] = static_cast<float>(light.Source.Position[k]);
      direction[l][k] = static_cast<float>(light.Source.Direction[k]);
      attenuation[l][k] = static_cast<float>(light.Source.Attenuation[k]);
    }
    coneCosine[l] = light.Source.Spot ? static_cast<float>(light.Source.ConeCosine) : -2.0f;
    exponent[l] = static_cast<float>(light.Source.Exponent);
    method[l] = light.Method;
  }
  program->SetUniformi("numberOfLights", static_cast<int>(frame.Lights.size()));
  program->SetUniform3fv("lightIrradiance", kMaxLights, irradiance);
  program->SetUniform3fv("lightPosition", kMaxLights, position);
  program->SetUniform3fv("lightDirection", kMaxLights, direction);
  program->SetUniform3fv("lightAttenuation", kMaxLights, attenuation);
  program->SetUniform1fv("lightConeCosine", kMaxLights, coneCosine);
  program->SetUniform1fv("lightExponent", kMaxLights, exponent);
  program->SetUniform1iv("lightMethod", kMaxLights, method);
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::WarnAboutLoopLimit(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  if (this->SoftwareRenderer < 0)
  {
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    this->SoftwareRenderer = name && std::strstr(name, "llvmpipe") ? 1 : 0;
  }
  if (this->SoftwareRenderer != 1 || this->WarnedLoopLimit)
  {
    return;
  }
  // Counted per camera ray: its steps, plus the brute-force light marches.
  int bruteForceLights = 0;
  for (const vtkTransmittanceFrame::Light& light : frame.Lights)
  {
    bruteForceLights += light.Method == vtkTransmittanceMapMath::BRUTE_FORCE ? 1 : 0;
  }
  const double iterations = (frame.Diagonal / frame.GetStepLength() + 2.0) *
    (1.0 + bruteForceLights * std::ceil(frame.Integrator.LightSampleCount / kBruteForceUnroll));
  if (iterations > kLoopLimit)
  {
    vtkWarningWithObjectMacro(reporter,
      << "llvmpipe stops a shader's loops after 65535 iterations; a camera ray here can need "
      << iterations << ". Increase SampleDistance or lower LightSampleCount, or rays end early.");
    this->WarnedLoopLimit = true;
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Quad.Release(window);
  this->SoftwareRenderer = -1;
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SoftwareRenderer: " << this->SoftwareRenderer << "\n";
}
