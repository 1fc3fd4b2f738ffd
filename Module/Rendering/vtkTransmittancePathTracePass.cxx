#include "vtkTransmittancePathTracePass.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceEnvironmentTextures.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallDenoiser.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallEnvironment.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallMajorantGrid.h"
#include "vtkTyndallMedium.h"
#include "vtkTyndallMediumParameters.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallShading.h"
#include "vtkTyndallSurfaceLobe.h"
#include "vtkTyndallTransferTable.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkTransmittancePathTracePass);

namespace
{
// A path's loop trips are bounded as if it scattered this many times (the
// bound of each flight is already the whole box at the majorant).
constexpr double kBoundedBounces = 4.0;
// The majorant is raised by this factor: the GPU's single-precision
// extinction may round above the CPU's double bound.
constexpr double kMajorantMargin = 1.0 + 1e-4;

// Whether a medium's emission array lights the paths (the CPU's
// vtkTyndallMedium::GetArrayEmission(), a positive EmissionScale).
bool EmitsFromArray(const vtkTyndallGridMedium& medium)
{
  return medium.GetArrayEmission() && medium.GetParameters().EmissionScale > 0.0;
}

// The guests' emission arrays (a guest without one: its own volume, never
// read), each value's table coordinate and each guest's EmissionScale (0
// without an array). Declared by the guests' emission-array variant only.
void SetGuestEmissionUniforms(const vtkTransmittanceFrame& frame, vtkShaderProgram* program)
{
  constexpr int guests = vtkTyndallSceneReader::MaximumNumberOfGuests;
  int textures[guests] = {};
  float toTable[guests][2] = {}, scale[guests] = {};
  const int n = static_cast<int>(std::min<size_t>(frame.Guests.size(), guests));
  for (int g = 0; g < n; ++g)
  {
    const vtkTransmittanceFrame::Guest& guest = frame.Guests[g];
    vtkTextureObject* emission = guest.Textures->GetEmissionTexture();
    const bool emits = emission && EmitsFromArray(*guest.Medium);
    textures[g] = (emits ? emission : guest.Textures->GetVolumeTexture())->GetTextureUnit();
    const vtkTyndallTransferTable& table = guest.Medium->GetTable();
    toTable[g][0] = static_cast<float>(table.EmissionTextureScale());
    toTable[g][1] = static_cast<float>(table.EmissionTextureShift());
    scale[g] = emits ? static_cast<float>(guest.Medium->GetParameters().EmissionScale) : 0.0f;
  }
  program->SetUniform1iv("guestEmission", n, textures);
  program->SetUniform2fv("guestEmissionToTable", n, toTable);
  program->SetUniform1fv("guestArrayEmissionScale", n, scale);
}

// How each medium a path collides in is lit, by its own parameters (the
// CPU tracer's `lit`; tyndallPathCollisionMedium() draws the medium):
// pathLighting[] this volume's, then each guest's (anisotropy, LightScale,
// AmbientIntensity, 1 for single scattering), and the renderer's lights'
// unscaled colours, pathLightColor[]. Declared by the guests' variant only.
void SetLightingUniforms(const vtkTransmittanceFrame& frame, vtkShaderProgram* program)
{
  constexpr int media = vtkTyndallSceneReader::MaximumNumberOfGuests + 1;
  constexpr int lights = vtkTyndallSceneReader::MaximumNumberOfLights;
  float lighting[media][4] = {};
  const int n = static_cast<int>(std::min<size_t>(frame.Guests.size() + 1, media));
  for (int m = 0; m < n; ++m)
  {
    const vtkTyndallMediumParameters& p =
      (m == 0 ? frame.Medium : frame.Guests[m - 1].Medium)->GetParameters();
    lighting[m][0] = static_cast<float>(p.ScatteringAnisotropy);
    lighting[m][1] = static_cast<float>(p.LightScale);
    lighting[m][2] = static_cast<float>(p.AmbientIntensity);
    lighting[m][3] = p.GetSingleScattering() ? 1.0f : 0.0f;
  }
  program->SetUniform4fv("pathLighting", n, lighting);
  float color[lights][3] = {};
  const int count = std::min(frame.GetSceneLights(), lights);
  for (int l = 0; l < count; ++l)
  {
    for (int c = 0; c < 3; ++c)
    {
      color[l][c] = static_cast<float>(frame.Lights[l].Source.Color[c]);
    }
  }
  program->SetUniform3fv("pathLightColor", lights, color);
}
}

//------------------------------------------------------------------------------
vtkTransmittancePathTracePass::vtkTransmittancePathTracePass() = default;
vtkTransmittancePathTracePass::~vtkTransmittancePathTracePass() = default;

//------------------------------------------------------------------------------
std::string vtkTransmittancePathTracePass::Refusal(
  const vtkTransmittanceFrame& frame, bool peeling, bool distributed)
{
  const vtkTyndallGridMedium& medium = *frame.Medium;
  if (medium.GetProjection().Enabled())
  {
    return "a projection blend mode is not a medium";
  }
  if (medium.GetIsosurfaces().Enabled())
  {
    return "the isosurface blend mode draws surfaces, not a medium";
  }
  if (distributed)
  {
    return "several processes draw the picture (a path would scatter between their pieces)";
  }
  if (peeling)
  {
    return "VTK's depth peeling for volumes draws the volume in parts, which one mean cannot "
           "average";
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::GuestsEmit(const vtkTransmittanceFrame& frame)
{
  return std::any_of(frame.Guests.begin(), frame.Guests.end(),
    [](const vtkTransmittanceFrame::Guest& g)
    { return g.Medium->GetParameters().HasEmission && !g.Medium->GetEmissionFromArray(); });
}

//------------------------------------------------------------------------------
int vtkTransmittancePathTracePass::GuestArrayEmitters(const vtkTransmittanceFrame& frame)
{
  return static_cast<int>(std::count_if(frame.Guests.begin(), frame.Guests.end(),
    [](const vtkTransmittanceFrame::Guest& g) { return EmitsFromArray(*g.Medium); }));
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::UsesBlocks(const vtkTransmittanceFrame& frame)
{
  // The blocks bound the grid's table extinction (times its density scale;
  // gradient opacity only lowers it): not procedural detail (its noise
  // rises above the shape); a 2-D function and labels are left to the one
  // majorant too (their tables' bounds are the blocks' as well, untested).
  const vtkTransmittanceShaderSource::Variant variant = frame.GetShaderVariant();
  return variant.SkipEmpty && variant.DetailGroups == 0 && !variant.Transfer2D &&
    !variant.LabelMap && !(frame.Detail && frame.Detail->Enabled()) && frame.Guests.empty();
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::UsesClosedForm(
  const vtkTransmittanceFrame& frame, const Settings& settings)
{
  const vtkTyndallMedium& medium = *frame.OwnMedium;
  return settings.ClosedForm && frame.Detail && frame.Detail->Enabled() && medium.HasClosedForm() &&
    !medium.GetClip() && !Chromatic(frame) && frame.Guests.empty();
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::ClosedFormCost(const vtkTransmittanceFrame& frame)
{
  // The shape's cells (detailMaxCells) and a flight's solve at its most.
  const int* n = frame.Detail->GetDimensions();
  return n[0] + n[1] + n[2] + 3.0 + vtkTransmittanceShaderSource::DetailSolveIterations;
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::FlightLength(const vtkTransmittanceFrame& frame)
{
  if (frame.Guests.empty())
  {
    return frame.Diagonal;
  }
  // The maps' box (every medium's): the longest distance between its corners.
  double longest = frame.Diagonal;
  for (int a = 0; a < 8; ++a)
  {
    for (int b = a + 1; b < 8; ++b)
    {
      longest = std::max(longest,
        std::sqrt(
          vtkMath::Distance2BetweenPoints(frame.MapCorners + 3 * a, frame.MapCorners + 3 * b)));
    }
  }
  return longest;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::Chromatic(const vtkTransmittanceFrame& frame)
{
  return frame.Medium->GetParameters().GetChromatic();
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::SpectralFactor(const vtkTransmittanceFrame& frame)
{
  return Chromatic(frame) ? 2.0 : 1.0;
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::Majorant(const vtkTransmittanceFrame& frame)
{
  // With guests the flights cross every medium: their extinctions add.
  double sum = frame.OwnMedium->GetMajorant();
  for (const vtkTransmittanceFrame::Guest& guest : frame.Guests)
  {
    sum += guest.Medium->GetMajorant();
  }
  const double majorant = sum * kMajorantMargin * SpectralFactor(frame);
  return std::isfinite(majorant) && majorant > 1e-30 ? majorant : 1e-30;
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::PathBound(
  const vtkTransmittanceFrame& frame, const Settings& settings)
{
  // A flight's tentative collisions across the whole box at the majorant,
  // and with the blocks a trip per block it crosses; in closed form a trip
  // per cell.
  double flight = 2.0 + Majorant(frame) * FlightLength(frame);
  if (UsesClosedForm(frame, settings))
  {
    flight = ClosedFormCost(frame);
  }
  else if (UsesBlocks(frame))
  {
    const int* counts = frame.Textures->GetMajorantGrid().GetBlockCounts();
    flight += counts[0] + counts[1] + counts[2] + 3.0;
  }
  const double lights = static_cast<double>(frame.GetSceneLights()); // the sky is sampled
  // A medium's Shade: the lights and the sky a second time (its surface term).
  const vtkTyndallShading& shading = frame.Medium->GetShading();
  const double loops = shading.Enabled() && shading.GetAdditive() ? 2.0 : 1.0;
  const double collision =
    1.0 + loops * (settings.TrackedShadows ? lights * (1.0 + flight) : CollisionCost(frame));
  const double sky = SamplesSky(frame) ? loops * (SkySearchCost(frame) + 1.0 + flight) : 0.0;
  // Emission arrays (this volume's, the guests'): each segment's stratified
  // points in each, tracked from point to point (a walk's start and end per
  // point, the walks one flight together); in closed form each point's
  // transmittance counts as a whole flight's cells, however short.
  const int emitters = (frame.GetColorVariant().EmissionArray ? 1 : 0) + GuestArrayEmitters(frame);
  const double points = vtkTyndallMedium::PathEmissionSamples;
  const double emission =
    emitters * (UsesClosedForm(frame, settings) ? points * (1.0 + flight) : 4.0 * points + flight);
  const double bounces = std::min(kBoundedBounces, double(std::max(settings.MaximumBounces, 1)));
  return bounces * (flight + collision + sky + emission);
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::SamplesSky(const vtkTransmittanceFrame& frame)
{
  return frame.Environment && frame.Environment->Enabled();
}

//------------------------------------------------------------------------------
int vtkTransmittancePathTracePass::SkySearchCost(const vtkTransmittanceFrame& frame)
{
  // The two binary searches' trips (vtkTransmittanceEnvironmentFS.glsl).
  const double rows = frame.Environment->GetHeight();
  const double columns = frame.Environment->GetWidth();
  return static_cast<int>(std::ceil(std::log2(rows)) + std::ceil(std::log2(columns))) + 2;
}

//------------------------------------------------------------------------------
double vtkTransmittancePathTracePass::CollisionCost(const vtkTransmittanceFrame& frame)
{
  const double march = vtkTransmittanceRayCastPass::LightMarchIterations(frame);
  double cost = 0.0;
  for (int l = 0; l < frame.GetSceneLights(); ++l) // the sky is sampled, not its lights
  {
    cost += 1.0 + (frame.Lights[l].Method == vtkTransmittanceMapMath::BRUTE_FORCE ? march : 0.0);
  }
  return cost;
}

//------------------------------------------------------------------------------
int vtkTransmittancePathTracePass::SamplesFor(
  const vtkTransmittanceFrame& frame, const Settings& settings)
{
  const double fit =
    0.5 * vtkTransmittanceRayCastPass::IterationBudget / PathBound(frame, settings);
  return std::max(1, std::min(settings.SamplesPerFrame, static_cast<int>(fit)));
}

//------------------------------------------------------------------------------
int vtkTransmittancePathTracePass::NextSamples(
  const vtkTransmittanceFrame& frame, const Settings& settings, int historyFrames, int wanted)
{
  const int ramp = 1 << std::min(std::max(historyFrames, 0), 6); // SamplesPerFrame is at most 64
  return std::max(1, std::min({ SamplesFor(frame, settings), ramp, wanted }));
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::MayCutPaths(
  const vtkTransmittanceFrame& frame, const Settings& settings)
{
  return PathBound(frame, settings) > vtkTransmittanceRayCastPass::IterationBudget;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::Render(const vtkTransmittanceFrame& frame,
  const vtkTransmittanceRayCastPass::Inputs& inputs, const Settings& settings, int historyFrames,
  int samples, vtkObject* reporter)
{
  vtkTransmittanceShaderSource::Variant variant =
    vtkTransmittanceRayCastPass::GetVariant(frame, inputs, false);
  variant.Octaves = 1;                   // the paths scatter for real
  variant.DetailCameraGroups = -1;       // every wave: no pixel footprint filters a path
  variant.OpacityCoversRadiance = false; // drawn into images
  variant.PathBlocks = UsesBlocks(frame);
  variant.PathClosedForm = UsesClosedForm(frame, settings);
  // A coloured extinction: the view transmittance per channel in a second
  // image, which the accumulation images (and their running mean) carry.
  const bool chromatic = Chromatic(frame);
  variant.Accumulate = variant.Accumulate || chromatic;
  // Another volume's table emission: the samples' emission (each medium's
  // by its own EmissionScale; this volume's by tableEmissionScale, 0 where
  // its own variant reads no table emission: none, an emission array, a 2-D
  // transfer function).
  if (GuestsEmit(frame))
  {
    variant.Emission = true;
  }
  // Guests: the scattered flights sample every one (tyndallEveryGuest), the
  // camera ray its camera guests; their emission arrays light the segments.
  if (!frame.Guests.empty())
  {
    variant.CameraGuests = true;
    variant.GuestColors = std::any_of(frame.Guests.begin(), frame.Guests.end(),
      [](const vtkTransmittanceFrame::Guest& g) { return g.Textures->GetScatteringTexture(); });
    variant.GuestEmissionArrays = GuestArrayEmitters(frame) > 0;
  }
  // The sky's textures (a failed upload, said once: the paths without the sky).
  variant.PathEnvironment =
    SamplesSky(frame) && this->Sky->Update(*frame.Environment, frame.Window, reporter);
  vtkShaderProgram* program = this->Quad.Ready(frame.Window,
    vtkTransmittanceShaderSource::GetFragmentShader(
      vtkTransmittanceShaderSource::PATH_TRACE, variant));
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The path-tracing shader did not compile.");
    return false;
  }
  vtkTransmittanceScopedTextures textures(
    { inputs.Depth, inputs.Cache ? inputs.Cache : inputs.Maps, inputs.Occlusion });
  vtkTransmittanceRayCastPass::SetUniforms(frame, inputs, program);
  frame.SetSkyUniforms(program, true); // the paths sample the sky
  if (!frame.Guests.empty())
  {
    frame.SetCameraGuestUniforms(program, true);
    SetLightingUniforms(frame, program);
  }
  if (variant.PathEnvironment)
  {
    for (vtkTextureObject* texture : this->Sky->GetTextures())
    {
      textures.Add(texture);
    }
    this->Sky->SetUniforms(*frame.Environment, program);
    program->SetUniformi("pathSkySearchCost", SkySearchCost(frame));
  }
  int viewport[4];
  frame.Renderer->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  frame.SetCameraUniforms(program, inputs.Depth, false, viewport, viewport[2], viewport[3]);
  this->LastSamplesPerFrame = std::max(samples, 1);
  program->SetUniformi("pathFirstSample", historyFrames > 0 ? this->GetSamples() : 0);
  program->SetUniformi("pathSeed", settings.Seed);
  program->SetUniformi("pathSamples", this->LastSamplesPerFrame);
  program->SetUniformi("pathBounces", std::max(settings.MaximumBounces, 1));
  // The grey majorants; the flights' (spectral tracking's) SpectralFactor
  // times them, the shadow rays' themselves (the CPU tracer's).
  program->SetUniformf("pathMajorant", static_cast<float>(Majorant(frame) / SpectralFactor(frame)));
  program->SetUniformf("pathFlightScale", static_cast<float>(SpectralFactor(frame)));
  if (variant.PathBlocks)
  {
    program->SetUniformf("pathBlockScale",
      static_cast<float>(frame.Medium->GetParameters().DensityScale * kMajorantMargin));
  }
  program->SetUniformi("pathTrackedShadows", settings.TrackedShadows ? 1 : 0);
  program->SetUniformi("pathBudget", vtkTransmittanceRayCastPass::IterationBudget);
  program->SetUniformi("pathCollisionCost", static_cast<int>(std::ceil(CollisionCost(frame))));
  if (variant.EmissionArray || variant.GuestEmissionArrays)
  {
    program->SetUniformi("pathEmissionSamples", vtkTyndallMedium::PathEmissionSamples);
  }
  if (variant.GuestEmissionArrays)
  {
    SetGuestEmissionUniforms(frame, program);
  }
  if (variant.Shading)
  {
    // Declared only by the shading variant: the lights' unit against the lobe.
    program->SetUniformf("pathLightUnit", static_cast<float>(vtkTyndallSurfaceLobe::LightUnit));
  }
  auto draw = [&](int, vtkTextureObject*, vtkTextureObject*) { this->Quad.Render(); };
  const bool drawn = this->Accumulation->Render(frame, viewport, viewport[2], viewport[3], 1, draw,
    reporter, std::max(historyFrames, 0), chromatic, !settings.Denoise, this->LastSamplesPerFrame);
  ++this->MeanSerial;
  if (this->Accumulation->GetHistoryFrames() <= 1)
  {
    // A new mean (asked for, or a new image): a new view, whose guide
    // DrawGuide() may have drawn just before.
    this->GuideReady = this->GuideReady && this->GuideForNextMean;
    if (this->GuideReady)
    {
      this->GuideCast->ReleaseScratch(frame.Window); // the guide is one image
    }
    this->GuideForNextMean = false;
  }
  if (!drawn)
  {
    return false;
  }
  if (!settings.Denoise)
  {
    this->ReleaseDenoiser(frame.Window);
    return true;
  }
  return this->ShowDenoised(frame, inputs, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::Redraw(const vtkTransmittanceFrame& frame,
  const vtkTransmittanceRayCastPass::Inputs& inputs, const Settings& settings, vtkObject* reporter)
{
  if (settings.Denoise && this->Accumulation->GetHistory())
  {
    return this->ShowDenoised(frame, inputs, reporter);
  }
  this->ReleaseDenoiser(frame.Window);
  return this->Accumulation->CompositeHistory(frame, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::CanGuide(const vtkTransmittanceRayCastPass::Inputs& inputs)
{
  return inputs.Reduction <= 1 && inputs.StepScale <= 1.0 && inputs.DetailSamples <= 0 &&
    !inputs.KeepsImage();
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::DrawGuide(const vtkTransmittanceFrame& frame,
  const vtkTransmittanceRayCastPass::Inputs& inputs, vtkObject* reporter)
{
  this->GuideForNextMean = false;
  this->DenoiserAllocated = true;
  if (!this->RenderGuide(frame, inputs, false, reporter))
  {
    return false;
  }
  this->GuideForNextMean = true;
  return this->GuideCast->CompositeImage(frame, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::RenderGuide(const vtkTransmittanceFrame& frame,
  const vtkTransmittanceRayCastPass::Inputs& inputs, bool release, vtkObject* reporter)
{
  this->FilteredSerial = 0;
  vtkTransmittanceRayCastPass::Inputs guide = inputs;
  guide.Offscreen = true;
  guide.Reduction = 1;
  guide.StepScale = 1.0;
  guide.DetailSamples = 0; // marched: no noise of its own
  guide.HistoryFrames = 0;
  ++this->GuideRenders;
  this->GuideReady = this->GuideCast->Render(frame, guide, reporter);
  if (this->GuideReady && release)
  {
    this->GuideCast->ReleaseScratch(frame.Window); // the guide is one image
  }
  return this->GuideReady;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::GuideFits(const vtkTransmittanceFrame& frame) const
{
  vtkTextureObject* guide = this->GuideCast->GetImage(0);
  vtkTextureObject* mean = this->Accumulation->GetHistory();
  return this->GuideReady && guide && mean && guide->GetContext() == frame.Window &&
    guide->GetWidth() == mean->GetWidth() && guide->GetHeight() == mean->GetHeight();
}

//------------------------------------------------------------------------------
void vtkTransmittancePathTracePass::ReleaseDenoiser(vtkWindow* window, bool force)
{
  if (this->DenoiserAllocated || force)
  {
    this->GuideCast->ReleaseGraphicsResources(window);
    this->Denoiser->ReleaseGraphicsResources(window);
  }
  this->DenoiserAllocated = false;
  this->GuideReady = false;
  this->GuideForNextMean = false;
  this->FilteredSerial = 0;
  this->Denoised = nullptr;
}

//------------------------------------------------------------------------------
bool vtkTransmittancePathTracePass::ShowDenoised(const vtkTransmittanceFrame& frame,
  const vtkTransmittanceRayCastPass::Inputs& inputs, vtkObject* reporter)
{
  this->DenoiserAllocated = true; // (whatever fails below: the images made so far)
  if (!this->GuideFits(frame))
  {
    if (!this->RenderGuide(frame, inputs, true, reporter))
    {
      return false;
    }
    if (!this->GuideFits(frame))
    {
      this->GuideReady = false;
      vtkErrorWithObjectMacro(
        reporter, << "The denoiser's guide is not the size of the paths' mean.");
      return false;
    }
  }
  // The mean as filtered last, while it has not changed (a finished picture's redraws).
  if (this->FilteredSerial != this->MeanSerial || !this->Denoised)
  {
    this->Denoised = this->Denoiser->Filter(frame, this->Accumulation->GetHistory(),
      this->GuideCast->GetImage(0), vtkTyndallDenoiser::DefaultIterations,
      vtkTyndallDenoiser::EdgeStopFor(this->GetSamples()), reporter);
    this->FilteredSerial = this->Denoised ? this->MeanSerial : 0;
  }
  return this->Denoised && this->Accumulation->CompositeImage(frame, this->Denoised, reporter);
}

//------------------------------------------------------------------------------
void vtkTransmittancePathTracePass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Quad.Release(window);
  this->Accumulation->ReleaseGraphicsResources(window);
  this->Sky->ReleaseGraphicsResources(window);
  this->ReleaseDenoiser(window, true);
  this->LastSamplesPerFrame = 0;
}

//------------------------------------------------------------------------------
void vtkTransmittancePathTracePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HistoryFrames: " << this->GetHistoryFrames() << "\n";
  os << indent << "LastSamplesPerFrame: " << this->LastSamplesPerFrame << "\n";
}
