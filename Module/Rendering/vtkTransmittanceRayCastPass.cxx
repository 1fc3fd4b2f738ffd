#include "vtkTransmittanceRayCastPass.h"

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
#include "vtkTransmittanceMediumAdapter.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallEnvironment.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallSceneReader.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittanceRayCastPass);

namespace
{
// The most camera steps a ray takes.
constexpr double kMaxSteps = 1 << 20;
// Brute-force light marches take this many samples per loop iteration.
constexpr double kBruteForceUnroll = 8.0;

}

//------------------------------------------------------------------------------
vtkTransmittanceRayCastPass::vtkTransmittanceRayCastPass() = default;
vtkTransmittanceRayCastPass::~vtkTransmittanceRayCastPass() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceRayCastPass::Render(
  const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkObject* reporter)
{
  this->LastPassCount = 0;
  // Sampled detail: one pass of free flights, averaged with the frames before.
  this->LastDetailSamples = DetailSamplesFor(frame, inputs.DetailSamples);
  const bool sampled = this->LastDetailSamples > 0;
  const int reduction = std::max(inputs.Reduction, 1);
  // A reduced image's pixels are `reduction` times wider: detail is filtered by them.
  const double nearestPixel = frame.NearestPixel * reduction;
  const double step = frame.GetStepLength(nearestPixel) * std::max(inputs.StepScale, 1.0);
  const int steps = static_cast<int>(std::min(kMaxSteps, frame.Diagonal / step + 2.0));
  const int perPass = sampled ? steps : StepsPerPass(frame);
  const int passes = (steps + perPass - 1) / perPass;
  // A coloured extinction needs a second render target: never drawn direct.
  const bool chromatic = frame.Medium->GetParameters().GetChromatic();
  const bool direct =
    !sampled && passes == 1 && reduction == 1 && !chromatic && !inputs.KeepsImage();
  // A ray drawn in one pass into an image (a reduced one, a depth-peeling
  // part) needs no earlier state: the shader of the direct draw, which
  // discards the rays that miss (the image is cleared). llvmpipe draws it 3
  // times faster than the accumulating one, which writes every pixel.
  const bool accumulate = passes > 1 || sampled || chromatic;
  vtkTransmittanceShaderSource::Variant variant = GetVariant(frame, inputs, accumulate);
  variant.DetailSamples = this->LastDetailSamples;
  frame.Adapter->DeclareCameraSwitches(*frame.OwnMedium, nearestPixel, variant);
  variant.DetailStepMeans = variant.DetailFilter && frame.UsesDetailStepMeans(nearestPixel);
  this->LastStepLength = sampled ? 0.0 : step;
  this->LastDetailStepMeans = variant.DetailStepMeans;
  this->LastDetailCameraWaves = 0;
  if (frame.Detail && frame.Detail->Enabled())
  {
    const int all = static_cast<int>(frame.Detail->GetWaves().size());
    this->LastDetailCameraWaves = variant.DetailCameraGroups >= 0
      ? std::min(all, frame.Detail->GetLiveWaves(nearestPixel))
      : all;
  }
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(
      vtkTransmittanceShaderSource::RAY_CAST, variant));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The ray-casting shader did not compile.");
    return false;
  }
  vtkTransmittanceScopedTextures textures(
    { inputs.Depth, inputs.Cache ? inputs.Cache : inputs.Maps, inputs.Occlusion });
  SetUniforms(frame, inputs, program);
  frame.SetSkyUniforms(program, false); // the map-based frame's sky: its lights, the ambient term
  int viewport[4];
  frame.Renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  const int width = (viewport[2] + reduction - 1) / reduction;
  const int height = (viewport[3] + reduction - 1) / reduction;
  frame.SetCameraUniforms(program, inputs.Depth, direct, viewport, width, height);
  program->SetUniformf("stepLength", static_cast<float>(step));
  frame.SetOutputUniforms(program, direct);
  if (sampled)
  {
    program->SetUniformi("detailFrame", inputs.HistoryFrames);
  }
  if (inputs.DepthRanges)
  {
    program->SetUniformi("depthRangeHalf", inputs.Segment);
  }
  this->LastPassCount = passes;
  if (direct)
  {
    this->DrawDirect(frame, program, steps);
    return true;
  }
  auto draw = [&](int pass, vtkTextureObject* previous, vtkTextureObject* previousOpacity)
  {
    if (accumulate)
    {
      program->SetUniformi("previousTexture", previous->GetTextureUnit());
    }
    if (previousOpacity)
    {
      program->SetUniformi("previousOpacityTexture", previousOpacity->GetTextureUnit());
    }
    program->SetUniformi("firstStep", pass * perPass);
    program->SetUniformi("endStep", std::min(steps, (pass + 1) * perPass));
    this->Quad.Render();
  };
  vtkTransmittanceAccumulationPass* accumulation = this->Accumulation[inputs.Segment == 1 ? 1 : 0];
  return accumulation->Render(frame, viewport, width, height, passes, draw, reporter,
    sampled ? std::max(inputs.HistoryFrames, 0) : -1, chromatic, !inputs.KeepsImage());
}

//------------------------------------------------------------------------------
int vtkTransmittanceRayCastPass::DetailSamplesFor(const vtkTransmittanceFrame& frame, int requested)
{
  // Free flights are drawn from one transmittance: not with a coloured extinction.
  if (requested <= 0 || !frame.Detail || !frame.Detail->Enabled() ||
    frame.Medium->GetParameters().GetChromatic())
  {
    return 0;
  }
  // A walk over the cells (each cell a loop trip and the check of its
  // samples), then per sample its solve, the light loop and a closed-form
  // walk per brute-force light.
  const int* n = frame.Detail->GetDimensions();
  const double cells = n[0] + n[1] + n[2] + 3.0;
  double perSample = vtkTransmittanceShaderSource::DetailSolveIterations + 1.0 +
    static_cast<double>(frame.Lights.size());
  for (const vtkTransmittanceFrame::Light& light : frame.Lights)
  {
    if (light.Method == vtkTransmittanceMapMath::BRUTE_FORCE)
    {
      perSample += cells;
    }
  }
  const double fit = (IterationBudget - 2.0 * cells) / perSample;
  return std::max(1, std::min(requested, static_cast<int>(fit)));
}

//------------------------------------------------------------------------------
vtkTransmittanceShaderSource::Variant vtkTransmittanceRayCastPass::GetVariant(
  const vtkTransmittanceFrame& frame, const Inputs& inputs, bool accumulate)
{
  const bool readsMaps = inputs.Maps && frame.NeedsMaps() && !inputs.Cache;
  vtkTransmittanceShaderSource::Variant variant =
    readsMaps ? frame.GetMapVariant() : frame.GetShaderVariant();
  variant.Accumulate = accumulate;
  variant.DepthRanges = inputs.DepthRanges;
  variant.LightCache = inputs.Cache != nullptr;
  variant.Occlusion = inputs.Occlusion != nullptr;
  for (const vtkTransmittanceFrame::Light& light : frame.Lights)
  {
    variant.BruteForceLights |= light.Method == vtkTransmittanceMapMath::BRUTE_FORCE;
  }
  frame.Adapter->DeclareColorSwitches(*frame.OwnMedium, variant);
  // Only the camera rays read colours: the other passes keep their programs.
  variant.GuestColors = std::any_of(frame.Guests.begin(), frame.Guests.end(),
    [](const vtkTransmittanceFrame::Guest& g)
    { return g.Camera && g.Textures->GetScatteringTexture(); });
  variant.Octaves = frame.Medium->GetParameters().ScatteringOctaves;
  variant.Shading = frame.Medium->GetShading().Enabled();
  variant.ShadingAdditive = frame.Medium->GetShading().GetAdditive();
  variant.ScatteringBlend = frame.Medium->GetShading().GetBlending() > 0.0;
  return variant;
}

//------------------------------------------------------------------------------
double vtkTransmittanceRayCastPass::LightMarchIterations(const vtkTransmittanceFrame& frame)
{
  return frame.Adapter->GetLightMarchIterations(
    *frame.OwnMedium, std::ceil(frame.Integrator.LightSampleCount / kBruteForceUnroll));
}

//------------------------------------------------------------------------------
int vtkTransmittanceRayCastPass::StepsPerPass(const vtkTransmittanceFrame& frame)
{
  // Loop iterations of one camera step: the step, the light loop, and a
  // brute-force light march per brute-force light (with procedural detail:
  // what the medium's adapter says).
  double perStep = 1.0 + static_cast<double>(frame.Lights.size());
  const double march = LightMarchIterations(frame);
  // A medium's Shade runs the light loop twice (its scattering, then its
  // surface term: vtkTyndallShading::GetAdditive()).
  const vtkTyndallShading& shading = frame.Medium->GetShading();
  const double loops = shading.Enabled() && shading.GetAdditive() ? 2.0 : 1.0;
  perStep += (loops - 1.0) * static_cast<double>(frame.Lights.size());
  for (const vtkTransmittanceFrame::Light& light : frame.Lights)
  {
    if (light.Method == vtkTransmittanceMapMath::BRUTE_FORCE)
    {
      perStep += loops * march;
    }
  }
  return std::max(1, static_cast<int>(IterationBudget / perStep));
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::DrawDirect(
  const vtkTransmittanceFrame& frame, vtkShaderProgram* program, int steps)
{
  program->SetUniformi("firstStep", 0);
  program->SetUniformi("endStep", steps);
  this->Quad.RenderOver(frame.State);
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::SetUniforms(
  const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkShaderProgram* program)
{
  frame.SetMediumUniforms(program);
  if (inputs.Cache)
  {
    const int* size = inputs.CacheSize;
    const float cacheSize[3] = { float(size[0]), float(size[1]), float(size[2]) };
    program->SetUniformi("lightCacheTexture", inputs.Cache->GetTextureUnit());
    program->SetUniform3f("lightCacheSize", cacheSize);
    program->SetUniformi("lightCacheLights", inputs.CacheLights);
  }
  else if (inputs.Maps)
  {
    frame.SetMapUniforms(program, inputs.Maps, inputs.MapSlices);
  }
  // The world width of a pixel along the rays (procedural detail's filter).
  const vtkTyndallFootprint& f = frame.Footprint;
  const float plane[4] = { float(f.Plane[0]), float(f.Plane[1]), float(f.Plane[2]),
    float(f.Plane[3]) };
  program->SetUniform4f("pixelDepthPlane", plane);
  const double reduction = std::max(inputs.Reduction, 1); // a reduced image's pixels are wider
  const float width[2] = { float(reduction * f.Constant), float(reduction * f.PerDepth) };
  program->SetUniform2f("pixelWidth", width);

  const vtkTransmittanceFrame::Settings& s = frame.Integrator;
  const vtkTyndallGridMedium& medium = *frame.Medium;
  program->SetUniformi("scatteringModel", medium.GetParameters().ScatteringModel);
  program->SetUniformi("lightSampleCount", s.LightSampleCount);
  program->SetUniformf(
    "anisotropy", static_cast<float>(medium.GetParameters().ScatteringAnisotropy));
  if (medium.GetParameters().ScatteringOctaves > 1)
  {
    const double* f = medium.GetParameters().OctaveFactors;
    const float factors[4] = { float(f[0]), float(f[1]), float(f[2]), float(f[3]) };
    program->SetUniform4f("octaveFactors", factors);
  }
  const float emissionScale = medium.GetParameters().HasEmission
    ? static_cast<float>(medium.GetParameters().EmissionScale)
    : 0.0f;
  program->SetUniformf("emissionScale", emissionScale);
  // The table's emission where this medium's variant reads it (not beside
  // an emission array, a 2-D function or isosurfaces: the path tracer turns
  // the variant on for its guests' emission alone).
  program->SetUniformf(
    "tableEmissionScale", frame.GetColorVariant().Emission ? emissionScale : 0.0f);
  if (inputs.Occlusion)
  {
    program->SetUniformi("occlusionTexture", inputs.Occlusion->GetTextureUnit());
    program->SetUniformi("occlusionSlices", inputs.OcclusionSlices);
    program->SetUniformf("occlusionBias", static_cast<float>(2.0 * frame.MinimumSpacing));
  }
  frame.SetLightUniforms(program);
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Quad.Release(window);
  for (vtkTransmittanceAccumulationPass* accumulation : this->Accumulation)
  {
    accumulation->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::ReleaseScratch(vtkWindow* window)
{
  for (vtkTransmittanceAccumulationPass* accumulation : this->Accumulation)
  {
    accumulation->ReleaseScratch(window);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceRayCastPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastPassCount: " << this->LastPassCount << "\n";
  os << indent << "LastDetailSamples: " << this->LastDetailSamples << "\n";
  os << indent << "LastDetailCameraWaves: " << this->LastDetailCameraWaves << "\n";
  os << indent << "LastStepLength: " << this->LastStepLength << "\n";
  os << indent << "LastDetailStepMeans: " << this->LastDetailStepMeans << "\n";
}
