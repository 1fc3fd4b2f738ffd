#include "vtkTransmittanceFrame.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSkybox.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceMediumAdapter.h"
#include "vtkTransmittanceMediumAdapters.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallParticleMedium.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallToneMapping.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace
{
// Whether the frame buffer holds the renderer's background colour or
// gradient under the volume (vtkOpenGLRenderer::Clear() drew it, and no
// skybox over it).
bool BackgroundKnown(vtkRenderer* r)
{
  vtkRenderWindow* w = r ? r->GetRenderWindow() : nullptr;
  if (!w || r->Transparent() || !r->GetErase() || !w->GetErase() || r->GetTexturedBackground() ||
    r->GetBackgroundAlpha() < 1.0)
  {
    return false;
  }
  vtkPropCollection* props = r->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (vtkSkybox::SafeDownCast(prop) && prop->GetVisibility())
    {
      return false;
    }
  }
  return true;
}

constexpr int kMaxLights = vtkTyndallSceneReader::MaximumNumberOfLights;
constexpr int kMaxGuests = vtkTyndallSceneReader::MaximumNumberOfGuests;

// World -> field index -> the medium's box as [0, 1]^3 (column-major floats).
void WorldToBoxMatrix(const vtkTyndallGridMedium& medium, float worldToBox[16])
{
  const double* toIndex = medium.GetWorldToIndex();
  const double* low = medium.GetBoxLow();
  const double* high = medium.GetBoxHigh();
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      double v = toIndex[4 * r + c];
      if (r < 3)
      {
        v = (v - (c == 3 ? low[r] : 0.0)) / (high[r] - low[r]);
      }
      worldToBox[4 * c + r] = static_cast<float>(v);
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::Prepare(vtkRenderer* renderer, vtkOpenGLRenderWindow* window,
  const vtkTyndallSceneReader& scene, const vtkTransmittanceMediumTextures& textures,
  const std::vector<const vtkTransmittanceMediumTextures*>& guestTextures, const Settings& settings)
{
  using M = vtkTransmittanceMapMath;
  this->Renderer = renderer;
  this->Window = window;
  this->State = window->GetState();
  this->Medium = &scene.GetMedium();
  this->Detail = &scene.GetDetail();
  this->Environment = &scene.GetEnvironment();
  this->OwnMedium = scene.GetMedia().front();
  this->Adapter = &vtkTransmittanceMediumAdapters::For(*this->OwnMedium);
  this->Textures = &textures;
  this->Integrator = settings;
  this->BackgroundIsKnown = BackgroundKnown(renderer);
  this->Layers = M::GetNumberOfMapLayers(settings.Method, settings.Coefficients);
  this->BoundsLayer = M::GetBoundsLayer(settings.Method, settings.Coefficients);
  this->MapSets = this->Medium->GetParameters().GetChromatic() &&
      (settings.Method == M::TFM || settings.Method == M::ADAPTIVE_TFM)
    ? 3
    : 1;
  this->Medium->GetWorldCorners(this->Corners);
  this->Diagonal = this->Medium->GetWorldDiagonal();
  this->MinimumSpacing = this->Medium->GetMinimumWorldSpacing();
  this->PrepareFootprint();

  WorldToBoxMatrix(*this->Medium, this->WorldToBox);
  // Box -> world: its columns are the box's world edges and origin.
  vtkNew<vtkMatrix4x4> toBox, toWorld;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      toBox->SetElement(r, c, this->WorldToBox[4 * c + r]);
    }
  }
  vtkMatrix4x4::Invert(toBox, toWorld);
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      this->BoxToWorld[4 * c + r] = static_cast<float>(toWorld->GetElement(r, c));
    }
    if (c < 3)
    {
      const double edge[3] = { toWorld->GetElement(0, c), toWorld->GetElement(1, c),
        toWorld->GetElement(2, c) };
      this->BoxExtents[c] = vtkMath::Norm(edge);
    }
  }

  const std::vector<const vtkTyndallGridMedium*>& guests = scene.GetGuests();
  const std::vector<int>& cameraGuests = scene.GetCameraGuests();
  this->Guests.clear();
  for (size_t g = 0; g < guests.size() && g < guestTextures.size(); ++g)
  {
    Guest guest;
    guest.Medium = guests[g];
    guest.Textures = guestTextures[g];
    guest.Camera = std::find(cameraGuests.begin(), cameraGuests.end(), static_cast<int>(g)) !=
      cameraGuests.end();
    WorldToBoxMatrix(*guest.Medium, guest.WorldToBox);
    if (guest.Camera)
    {
      this->MinimumSpacing = std::min(this->MinimumSpacing, guest.Medium->GetMinimumWorldSpacing());
    }
    this->Guests.push_back(guest);
  }
  this->PrepareMapBox();
  this->PrepareSplats();

  // The lights, each with its map's frustum: the renderer's, then the sky's.
  std::vector<vtkTyndallLight> lights = scene.GetLights();
  const std::vector<vtkTyndallLight>& skyLights = scene.GetSkyLights();
  lights.insert(lights.end(), skyLights.begin(), skyLights.end());
  this->SkyLights = static_cast<int>(skyLights.size());
  scene.GetMapAmbient(this->MapAmbient);
  scene.GetShadingSkyMean(this->ShadingSkyMean);
  this->Lights.resize(lights.size());
  for (size_t l = 0; l < lights.size(); ++l)
  {
    Light& light = this->Lights[l];
    light.Source = lights[l];
    if (!light.Frustum)
    {
      light.Frustum = vtkSmartPointer<vtkTransmittanceLightFrustum>::New();
    }
    light.HasFrustum = light.Source.Positional
      ? light.Frustum->FitPositional(light.Source.Position, this->MapCorners)
      : light.Frustum->FitDirectional(light.Source.Direction, this->MapCorners);
    // A projection's lights (a shaded slice's) cast no shadow: no map.
    light.Method = this->Medium->GetProjection().Enabled() ? M::NONE : settings.Method;
    if (M::IsMapMethod(light.Method) && !light.HasFrustum)
    {
      light.Method = M::BRUTE_FORCE; // documented fallback: a light inside the box
    }
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::PrepareFootprint()
{
  int size[2], origin[2];
  this->Renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  this->Footprint.SetCamera(camera, size[0], size[1]);
  double range[2];
  camera->GetClippingRange(range);
  this->NearestPixel = this->Footprint.Minimum(this->Corners, range[0]);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::PrepareMapBox()
{
  std::copy(this->Corners, this->Corners + 24, this->MapCorners);
  std::copy(this->WorldToBox, this->WorldToBox + 16, this->WorldToMapBox);
  std::copy(this->WorldToBox, this->WorldToBox + 16, this->WorldToCameraBox);
  std::copy(this->BoxToWorld, this->BoxToWorld + 16, this->CameraBoxToWorld);
  std::copy(this->BoxExtents, this->BoxExtents + 3, this->CameraBoxExtents);
  if (!this->Guests.empty() || this->Integrator.HasMapBounds)
  {
    double extents[3];
    float boxToWorld[16];
    this->FitAxisBox(false, this->MapCorners, this->WorldToMapBox, boxToWorld, extents);
  }
  if (this->HasCameraGuests())
  {
    double corners[24];
    this->FitAxisBox(
      true, corners, this->WorldToCameraBox, this->CameraBoxToWorld, this->CameraBoxExtents);
    this->Diagonal = vtkMath::Norm(this->CameraBoxExtents);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::PrepareSplats()
{
  this->Splats.clear();
  if (this->Integrator.Method != vtkTransmittanceMapMath::ETM)
  {
    return;
  }
  auto add = [this](const vtkTyndallGridMedium& grid, int guest)
  {
    // A particle cloud whose maps splat its particles (vtkTyndallParticleMedium).
    const vtkTyndallParticleMedium* medium =
      vtkTransmittanceMediumAdapters::For(grid).GetSplatted(grid);
    if (!medium)
    {
      return;
    }
    Splat splat;
    splat.Particles = medium->GetParticles();
    splat.DensityScale = medium->GetParameters().DensityScale;
    splat.Guest = guest;
    // World -> field index -> data, and back.
    vtkNew<vtkMatrix4x4> toIndex, toData, worldToData, dataToWorld;
    toIndex->DeepCopy(medium->GetWorldToIndex());
    toData->DeepCopy(medium->GetIndexToData());
    vtkMatrix4x4::Multiply4x4(toData, toIndex, worldToData);
    vtkMatrix4x4::Invert(worldToData, dataToWorld);
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        splat.WorldToData[4 * c + r] = static_cast<float>(worldToData->GetElement(r, c));
        splat.DataToWorld[4 * c + r] = static_cast<float>(dataToWorld->GetElement(r, c));
      }
    }
    this->Splats.push_back(splat);
  };
  add(*this->Medium, -1);
  for (size_t g = 0; g < this->Guests.size(); ++g)
  {
    add(*this->Guests[g].Medium, static_cast<int>(g));
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetMarchedDensities(vtkShaderProgram* program) const
{
  float own = static_cast<float>(this->Medium->GetParameters().DensityScale);
  float guests[kMaxGuests] = {};
  const int n = static_cast<int>(std::min<size_t>(this->Guests.size(), kMaxGuests));
  for (int g = 0; g < n; ++g)
  {
    guests[g] = static_cast<float>(this->Guests[g].Medium->GetParameters().DensityScale);
  }
  for (const Splat& splat : this->Splats)
  {
    (splat.Guest < 0 ? own : guests[splat.Guest]) = 0.0f;
  }
  program->SetUniformf("densityScale", own);
  if (n > 0)
  {
    program->SetUniform1fv("guestDensity", n, guests);
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceFrame::HasCameraGuests() const
{
  return std::any_of(
    this->Guests.begin(), this->Guests.end(), [](const Guest& g) { return g.Camera; });
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::FitAxisBox(bool cameraGuestsOnly, double corners[24],
  float worldToBox[16], float boxToWorld[16], double extents[3]) const
{
  double low[3], high[3];
  for (int a = 0; a < 3; ++a)
  {
    low[a] = high[a] = this->Corners[a];
  }
  auto extend = [&low, &high](const double c[24])
  {
    for (int i = 0; i < 8; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        low[a] = std::min(low[a], c[3 * i + a]);
        high[a] = std::max(high[a], c[3 * i + a]);
      }
    }
  };
  extend(this->Corners);
  if (!cameraGuestsOnly && this->Integrator.HasMapBounds)
  {
    // The whole medium of several processes (vtkTransmittanceMapReducer).
    const double* b = this->Integrator.MapBounds;
    const double whole[24] = { b[0], b[2], b[4], b[1], b[3], b[5], b[0], b[2], b[4], b[1], b[3],
      b[5], b[0], b[2], b[4], b[1], b[3], b[5], b[0], b[2], b[4], b[1], b[3], b[5] };
    extend(whole);
  }
  for (const Guest& guest : this->Guests)
  {
    if (guest.Camera || !cameraGuestsOnly)
    {
      double c[24];
      guest.Medium->GetWorldCorners(c);
      extend(c);
    }
  }
  std::fill(worldToBox, worldToBox + 16, 0.0f);
  std::fill(boxToWorld, boxToWorld + 16, 0.0f);
  for (int a = 0; a < 3; ++a)
  {
    const double size = std::max(high[a] - low[a], 1e-30);
    worldToBox[5 * a] = static_cast<float>(1.0 / size);
    worldToBox[12 + a] = static_cast<float>(-low[a] / size);
    boxToWorld[5 * a] = static_cast<float>(size);
    boxToWorld[12 + a] = static_cast<float>(low[a]);
    extents[a] = size;
  }
  worldToBox[15] = boxToWorld[15] = 1.0f;
  for (int i = 0; i < 8; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      corners[3 * i + a] = ((i >> a) & 1) ? high[a] : low[a];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceFrame::NeedsMaps() const
{
  return std::any_of(this->Lights.begin(), this->Lights.end(),
    [](const Light& l) { return vtkTransmittanceMapMath::IsMapMethod(l.Method); });
}

//------------------------------------------------------------------------------
bool vtkTransmittanceFrame::UsesDetailStepMeans(double nearestPixel) const
{
  // The step and the shader's switch decide alike (GetStepLength()); the
  // switch must never be on where a light marches the detail in the
  // camera's program (a brute-force light: GetLightingWidth() 0) or
  // isosurfaces sample it: its samples would take the camera step's means.
  return !(this->Integrator.SampleDistance > 0.0) && this->Detail && this->Detail->Enabled() &&
    !(this->Medium && this->Medium->GetIsosurfaces().Enabled()) &&
    this->Detail->UsesStepMeans(nearestPixel, 0.5 * this->MinimumSpacing, this->GetLightingWidth());
}

//------------------------------------------------------------------------------
double vtkTransmittanceFrame::GetLightingWidth() const
{
  double width = 1e300;
  for (const Light& light : this->Lights)
  {
    if (light.Method == vtkTransmittanceMapMath::NONE)
    {
      continue; // unshadowed
    }
    if (!vtkTransmittanceMapMath::IsMapMethod(light.Method) || !light.HasFrustum)
    {
      return 0.0;
    }
    width =
      std::min(width, light.Frustum->GetTexelWidth(this->MapCorners, this->Integrator.MapSize));
  }
  return width;
}

//------------------------------------------------------------------------------
double vtkTransmittanceFrame::GetStepLength(double nearestPixel) const
{
  if (this->Integrator.SampleDistance > 0.0)
  {
    return this->Integrator.SampleDistance;
  }
  if (this->Medium && this->Medium->GetIsosurfaces().Enabled())
  {
    // VTK's automatic step: its surfaces are where VTK finds them.
    return this->MinimumSpacing;
  }
  if (this->Detail && this->Detail->Enabled())
  {
    // The waves' means over the step, or the midpoint rule's error on them.
    return this->Detail->GetCameraStep(
      nearestPixel, 0.5 * this->MinimumSpacing, this->GetLightingWidth());
  }
  // The medium's finest feature: its spacing, or a particle's size.
  return 0.5 * std::min(this->MinimumSpacing, this->OwnMedium->GetFinestFeature());
}

//------------------------------------------------------------------------------
vtkTransmittanceShaderSource::Variant vtkTransmittanceFrame::GetShaderVariant() const
{
  vtkTransmittanceShaderSource::Variant variant;
  variant.SkipEmpty = this->Integrator.SkipEmptySpace;
  if (this->Adapter)
  {
    this->Adapter->DeclareSwitches(*this->OwnMedium, *this->Textures, variant);
  }
  variant.Guests = static_cast<int>(this->Guests.size());
  for (const Guest& guest : this->Guests)
  {
    variant.VolumeTiled = variant.VolumeTiled || guest.Textures->GetTiling().IsTiled();
    variant.VolumeBricked = variant.VolumeBricked || guest.Textures->GetBricks().IsBricked();
  }
  variant.MapBeyondMedium = this->Integrator.HasMapBounds;
  variant.OpacityCoversRadiance = this->Integrator.OpacityCoversRadiance;
  variant.CameraGuests = this->HasCameraGuests();
  if (variant.CameraGuests)
  {
    variant.SkipEmpty = false; // the blocks are this medium's alone
  }
  return variant;
}

//------------------------------------------------------------------------------
vtkTransmittanceShaderSource::Variant vtkTransmittanceFrame::GetColorVariant() const
{
  vtkTransmittanceShaderSource::Variant variant;
  if (this->Adapter)
  {
    this->Adapter->DeclareColorSwitches(*this->OwnMedium, variant);
  }
  return variant;
}

//------------------------------------------------------------------------------
vtkTransmittanceShaderSource::Variant vtkTransmittanceFrame::GetMapVariant() const
{
  using M = vtkTransmittanceMapMath;
  vtkTransmittanceShaderSource::Variant variant = this->GetShaderVariant();
  const int method = this->Integrator.Method;
  variant.MapCoefficients = this->Integrator.Coefficients;
  variant.MapExtinction = method == M::ETM || method == M::ADAPTIVE_ETM;
  variant.AdaptiveMaps = this->BoundsLayer >= 0;
  variant.ChannelMaps = this->MapSets > 1;
  return variant;
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetMapUniforms(
  vtkShaderProgram* program, vtkTextureObject* maps, int slices) const
{
  program->SetUniformi("mapTexture", maps->GetTextureUnit());
  program->SetUniformi("layersPerLight", std::max(this->Layers, 1));
  program->SetUniformi("boundsLayer", std::max(this->BoundsLayer, 0));
  program->SetUniformi("mapSlices", std::max(slices, 1));
  program->SetUniformi(
    "mapSetStride", static_cast<int>(this->Lights.size()) * std::max(this->Layers, 1));
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetMediumUniforms(vtkShaderProgram* program) const
{
  this->SetLightMapUniforms(program);
  this->Adapter->SetUniforms(program, *this->OwnMedium, *this->Textures);
  program->SetUniformMatrix4x4("worldToVolume", const_cast<float*>(this->WorldToBox));
  program->SetUniformMatrix4x4("worldToCameraBox", const_cast<float*>(this->WorldToCameraBox));
  this->SetClipUniforms(program);
  this->SetGuestUniforms(program);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetCameraUniforms(vtkShaderProgram* program, vtkTextureObject* depth,
  bool direct, const int viewport[4], int width, int height) const
{
  vtkNew<vtkMatrix4x4> ndcToWorld;
  vtkMatrix4x4::Invert(this->Renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                         this->Renderer->GetTiledAspectRatio(), -1, 1),
    ndcToWorld);
  float columns[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columns[c * 4 + r] = static_cast<float>(ndcToWorld->GetElement(r, c));
    }
  }
  program->SetUniformMatrix4x4("ndcToWorld", columns);
  program->SetUniformi("depthTexture", depth->GetTextureUnit());
  const float direct1[4] = { 1.0f, 1.0f, 0.0f, 0.0f };
  const float reduced[4] = { static_cast<float>(viewport[2]) / width,
    static_cast<float>(viewport[3]) / height, static_cast<float>(viewport[0]),
    static_cast<float>(viewport[1]) };
  program->SetUniform4f("fragToWindow", direct ? direct1 : reduced);
  program->SetUniformi("jitter", this->Integrator.Jitter ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetLightMapUniforms(vtkShaderProgram* program) const
{
  program->SetUniformMatrix4x4("worldToMapBox", const_cast<float*>(this->WorldToMapBox));
  if (this->Medium->GetParameters().GetChromatic())
  {
    const double* e = this->Medium->GetParameters().ExtinctionColor;
    const float color[3] = { float(e[0]), float(e[1]), float(e[2]) };
    program->SetUniform3f("extinctionColor", color);
  }
  int positional[kMaxLights] = { 0 }, hasFrustum[kMaxLights] = { 0 };
  float origin[kMaxLights][3] = {}, axisX[kMaxLights][3] = {}, axisY[kMaxLights][3] = {},
        axisZ[kMaxLights][3] = {};
  for (size_t l = 0; l < this->Lights.size(); ++l)
  {
    vtkTransmittanceLightFrustum* f = this->Lights[l].Frustum;
    positional[l] = this->Lights[l].Source.Positional ? 1 : 0;
    hasFrustum[l] = this->Lights[l].HasFrustum ? 1 : 0;
    for (int k = 0; k < 3; ++k)
    {
      origin[l][k] = static_cast<float>(f->GetOrigin()[k]);
      axisX[l][k] = static_cast<float>(f->GetAxisX()[k]);
      axisY[l][k] = static_cast<float>(f->GetAxisY()[k]);
      axisZ[l][k] = static_cast<float>(f->GetAxisZ()[k]);
    }
  }
  program->SetUniform1iv("lightHasFrustum", kMaxLights, hasFrustum);
  program->SetUniform1iv("lightPositional", kMaxLights, positional);
  program->SetUniform3fv("lightOrigin", kMaxLights, origin);
  program->SetUniform3fv("lightAxisX", kMaxLights, axisX);
  program->SetUniform3fv("lightAxisY", kMaxLights, axisY);
  program->SetUniform3fv("lightAxisZ", kMaxLights, axisZ);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetOutputUniforms(
  vtkShaderProgram* program, bool toWindow, bool background) const
{
  static_assert(vtkTyndallToneMapping::LINEAR == 0 && vtkTyndallToneMapping::ACES == 2,
    "the mapper's ToneCurve numbers are vtkTyndallToneMapping's");
  const Settings& s = this->Integrator;
  const bool identity =
    !toWindow || vtkTyndallToneMapping::IsIdentity(s.Exposure, s.ToneCurve, s.EncodeSRGB);
  program->SetUniformi("outputTransform", identity ? 0 : 1);
  program->SetUniformf("outputScale", static_cast<float>(std::exp2(s.Exposure)));
  program->SetUniformi("outputCurve", s.ToneCurve);
  program->SetUniformi("outputSRGB", s.EncodeSRGB ? 1 : 0);
  // The background the renderer drew under the medium (vtkOpenGLRenderer::
  // Clear()): its clear colour, or its gradient from Background (bottom) to
  // Background2 (top) over the viewport, of colours truncated to 8 bits.
  // Unknown (taken as black) where the renderer or the window keeps the
  // colour buffer, draws a texture or a skybox, clears to a transparent
  // background, or the caller says so (depth peeling's targets).
  vtkRenderer* r = this->Renderer;
  const bool known = background && this->BackgroundIsKnown;
  float bottom[3] = { 0.0f, 0.0f, 0.0f }, top[3] = { 0.0f, 0.0f, 0.0f };
  float viewportY[2] = { 0.0f, 1.0f };
  if (known)
  {
    const bool gradient = r->GetGradientBackground();
    const double* b = r->GetBackground();
    const double* t = gradient ? r->GetBackground2() : b;
    for (int k = 0; k < 3; ++k)
    {
      // (VTK gives the gradient's corners as unsigned chars: truncated.)
      bottom[k] =
        gradient ? std::floor(static_cast<float>(b[k] * 255)) / 255.0f : static_cast<float>(b[k]);
      top[k] =
        gradient ? std::floor(static_cast<float>(t[k] * 255)) / 255.0f : static_cast<float>(t[k]);
    }
    // gl_FragCoord is relative to the frame buffer drawn into: the
    // viewport the draw uses.
    GLint viewport[4] = { 0, 0, 1, 1 };
    this->State->vtkglGetIntegerv(GL_VIEWPORT, viewport);
    viewportY[0] = static_cast<float>(viewport[1]);
    viewportY[1] = static_cast<float>(std::max(viewport[3], 1));
  }
  program->SetUniformi("outputBackground", known ? 1 : 0);
  program->SetUniform3f("outputBottom", bottom);
  program->SetUniform3f("outputTop", top);
  program->SetUniform2f("outputViewportY", viewportY);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetSkyUniforms(vtkShaderProgram* program, bool sampled) const
{
  float ambient[3];
  for (int c = 0; c < 3; ++c)
  {
    ambient[c] = static_cast<float>(
      sampled ? this->Medium->GetParameters().AmbientIntensity : this->MapAmbient[c]);
  }
  program->SetUniform3f("ambient", ambient);
  program->SetUniformi("numberOfSkyLights", sampled ? 0 : this->SkyLights);
  if (this->Medium->GetShading().Enabled())
  {
    float mean[3]; // declared only by the shading variant
    for (int c = 0; c < 3; ++c)
    {
      mean[c] = sampled ? 0.0f : static_cast<float>(this->ShadingSkyMean[c]);
    }
    program->SetUniform3f("shadingSkyMean", mean);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetLightUniforms(vtkShaderProgram* program) const
{
  float irradiance[kMaxLights][3] = {}, position[kMaxLights][3] = {}, direction[kMaxLights][3] = {},
        attenuation[kMaxLights][3] = {};
  float coneCosine[kMaxLights] = {}, exponent[kMaxLights] = {}, color[kMaxLights][3] = {};
  int method[kMaxLights] = { 0 }, headlight[kMaxLights] = { 0 };
  for (size_t l = 0; l < this->Lights.size(); ++l)
  {
    const Light& light = this->Lights[l];
    for (int k = 0; k < 3; ++k)
    {
      irradiance[l][k] = static_cast<float>(light.Source.Irradiance[k]);
      position[l][k] = static_cast<float>(light.Source.Position[k]);
      direction[l][k] = static_cast<float>(light.Source.Direction[k]);
      attenuation[l][k] = static_cast<float>(light.Source.Attenuation[k]);
      color[l][k] = static_cast<float>(light.Source.Color[k]);
    }
    headlight[l] = light.Source.Headlight ? 1 : 0;
    coneCosine[l] = light.Source.Spot ? static_cast<float>(light.Source.ConeCosine) : -2.0f;
    exponent[l] = static_cast<float>(light.Source.Exponent);
    method[l] = light.Method;
  }
  program->SetUniformi("numberOfLights", this->GetSceneLights());
  program->SetUniform3fv("lightIrradiance", kMaxLights, irradiance);
  program->SetUniform3fv("lightPosition", kMaxLights, position);
  program->SetUniform3fv("lightDirection", kMaxLights, direction);
  program->SetUniform3fv("lightAttenuation", kMaxLights, attenuation);
  program->SetUniform1fv("lightConeCosine", kMaxLights, coneCosine);
  program->SetUniform1fv("lightExponent", kMaxLights, exponent);
  program->SetUniform1iv("lightMethod", kMaxLights, method);
  const vtkTyndallShading& shading = this->Medium->GetShading();
  if (shading.Enabled())
  {
    // Declared only by the shading variant.
    program->SetUniform3fv("lightColor", kMaxLights, color);
    program->SetUniform1iv("lightHeadlight", kMaxLights, headlight);
    // Per component (independent components are shaded each with its own).
    float coefficients[4][4];
    for (int c = 0; c < 4; ++c)
    {
      coefficients[c][0] = static_cast<float>(shading.GetAmbient(c));
      coefficients[c][1] = static_cast<float>(shading.GetDiffuse(c));
      coefficients[c][2] = static_cast<float>(shading.GetSpecular(c));
      coefficients[c][3] = static_cast<float>(shading.GetSpecularPower(c));
    }
    program->SetUniform4fv("shadingCoefficients", 4, coefficients);
    // The volumetric scattering blending (vtkTyndallShading::BlendWeight()):
    // per component 2 / (s_max - s_min); h the smallest world spacing.
    const double h = this->Medium->GetMinimumWorldSpacing();
    float gradientScale[4];
    for (int c = 0; c < 4; ++c)
    {
      const double* range = this->Medium->GetComponentRange(c);
      gradientScale[c] =
        range[1] > range[0] ? static_cast<float>(2.0 / (range[1] - range[0])) : 0.0f;
    }
    if (shading.GetBlending() > 0.0)
    {
      // Declared only by the blending variant.
      program->SetUniformf("scatteringBlending", static_cast<float>(shading.GetBlending()));
      program->SetUniform4f("blendGradientScale", gradientScale);
      program->SetUniformf("blendStep", static_cast<float>(h));
    }
  }
  if (shading.Enabled() || this->Medium->GetIsosurfaces().Enabled())
  {
    // Declared only by the shading and isosurface variants.
    program->SetUniformf("shadowOffset",
      static_cast<float>(vtkTyndallShading::ShadowOffset * this->Medium->GetMinimumWorldSpacing()));
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetGuestUniforms(vtkShaderProgram* program) const
{
  const int n = static_cast<int>(this->Guests.size());
  if (n == 0)
  {
    return; // declared only by the variant with guests (GetShaderVariant())
  }
  int volumes[kMaxGuests] = {}, tables[kMaxGuests] = {};
  float toBox[16 * kMaxGuests] = {}, scale[kMaxGuests][3] = {}, shift[kMaxGuests][3] = {},
                   toTable[kMaxGuests][2] = {}, density[kMaxGuests] = {};
  for (int g = 0; g < n; ++g)
  {
    const Guest& guest = this->Guests[g];
    volumes[g] = guest.Textures->GetVolumeTexture()->GetTextureUnit();
    tables[g] = guest.Textures->GetTransferTexture()->GetTextureUnit();
    std::copy(guest.WorldToBox, guest.WorldToBox + 16, toBox + 16 * g);
    std::copy(guest.Textures->GetTextureScale(), guest.Textures->GetTextureScale() + 3, scale[g]);
    std::copy(guest.Textures->GetTextureShift(), guest.Textures->GetTextureShift() + 3, shift[g]);
    const vtkTyndallTransferTable& table = guest.Medium->GetTable();
    // The guest's texel straight to its table coordinate (its value map
    // folded in: value = texel * map[0] + map[1]).
    const float* map = guest.Textures->GetValueMap();
    toTable[g][0] = static_cast<float>(table.TextureScale() * map[0]);
    toTable[g][1] = static_cast<float>(table.TextureScale() * map[1] + table.TextureShift());
    density[g] = static_cast<float>(guest.Medium->GetParameters().DensityScale);
  }
  program->SetUniform1iv("guestVolume", n, volumes);
  program->SetUniform1iv("guestTransfer", n, tables);
  program->SetUniformMatrix4x4v("guestWorldToBox", n, toBox);
  program->SetUniform3fv("guestTexScale", n, scale);
  program->SetUniform3fv("guestTexShift", n, shift);
  program->SetUniform2fv("guestScalarToTable", n, toTable);
  program->SetUniform1fv("guestDensity", n, density);
  // Read by the tiled variant only (a guest's tiles or this volume's).
  float tiling[kMaxGuests][3] = {}, dims[kMaxGuests][3] = {}, textureDims[kMaxGuests][3] = {};
  for (int g = 0; g < n; ++g)
  {
    this->Guests[g].Textures->GetTiling().GetUniforms(tiling[g], dims[g], textureDims[g]);
  }
  program->SetUniform3fv("guestTiling", n, tiling);
  program->SetUniform3fv("guestDims", n, dims);
  program->SetUniform3fv("guestTextureDims", n, textureDims);
  // Read by the bricked variant only (a guest's bricks or this volume's):
  // an unbricked guest's indirection is its own volume (a valid 3-D
  // texture on a unit of its own, never read).
  int bricks[kMaxGuests] = {}, bricked[kMaxGuests] = {};
  float brickCounts[kMaxGuests][3] = {}, atlasDims[kMaxGuests][3] = {};
  for (int g = 0; g < n; ++g)
  {
    const vtkTransmittanceMediumTextures& textures = *this->Guests[g].Textures;
    vtkTextureObject* indirection = textures.GetBrickTexture();
    bricked[g] = textures.GetBricks().IsBricked() && indirection ? 1 : 0;
    bricks[g] = (bricked[g] ? indirection : textures.GetVolumeTexture())->GetTextureUnit();
    float unused[3];
    textures.GetBricks().GetUniforms(unused, brickCounts[g], atlasDims[g]);
  }
  program->SetUniform1iv("guestBricks", n, bricks);
  program->SetUniform1iv("guestBricked", n, bricked);
  program->SetUniform3fv("guestBrickCounts", n, brickCounts);
  program->SetUniform3fv("guestAtlasDims", n, atlasDims);
  if (this->HasCameraGuests())
  {
    this->SetCameraGuestUniforms(program, false);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetCameraGuestUniforms(vtkShaderProgram* program, bool every) const
{
  const int n = static_cast<int>(this->Guests.size());
  float camera[kMaxGuests] = {};
  // Declared by the coloured-guest variant only: a coloured particle
  // cloud's scattering grid, the others their own volume (a valid 3-D
  // texture on a unit of its own, never read).
  int scattering[kMaxGuests] = {};
  float colored[kMaxGuests] = {};
  float emission[kMaxGuests] = {}; // declared by the emission variant only
  for (int g = 0; g < n; ++g)
  {
    const Guest& guest = this->Guests[g];
    camera[g] = guest.Camera ? 1.0f : 0.0f;
    const vtkTyndallMediumParameters& parameters = guest.Medium->GetParameters();
    // Its table's emission (an emission array's lights the path tracer's
    // segments instead: tyndallPathArrayEmission()).
    emission[g] = parameters.HasEmission && !guest.Medium->GetEmissionFromArray()
      ? static_cast<float>(parameters.EmissionScale)
      : 0.0f;
    vtkTextureObject* grid = guest.Textures->GetScatteringTexture();
    colored[g] = grid && (guest.Camera || every) ? 1.0f : 0.0f;
    scattering[g] = (grid ? grid : guest.Textures->GetVolumeTexture())->GetTextureUnit();
  }
  program->SetUniform1fv("guestCamera", n, camera); // declared by the ray cast only
  program->SetUniform1iv("guestScattering", n, scattering);
  program->SetUniform1fv("guestColored", n, colored);
  program->SetUniform1fv("guestEmissionScale", n, emission);
}

//------------------------------------------------------------------------------
void vtkTransmittanceFrame::SetClipUniforms(vtkShaderProgram* program) const
{
  const vtkTyndallClipRegion& clip = this->Medium->GetClipRegion();
  if (!clip.Enabled())
  {
    return; // declared only by the clipping variant (GetShaderVariant())
  }
  const auto& planes = clip.GetWorldPlanes();
  float values[4 * vtkTyndallClipRegion::MaximumPlanes] = {};
  for (size_t i = 0; i < planes.size(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      values[4 * i + c] = static_cast<float>(planes[i][c]);
    }
  }
  program->SetUniform4fv(
    "clipPlanes", vtkTyndallClipRegion::MaximumPlanes, reinterpret_cast<const float(*)[4]>(values));
  program->SetUniformi("clipPlaneCount", static_cast<int>(planes.size()));
  program->SetUniformi("cropping", clip.GetCropping() ? 1 : 0);
  float worldToData[16];
  const double* m = clip.GetWorldToData();
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      worldToData[4 * c + r] = static_cast<float>(m[4 * r + c]); // column-major
    }
  }
  program->SetUniformMatrix4x4("worldToData", worldToData);
  const double* p = clip.GetCroppingPlanes();
  const float low[3] = { float(p[0]), float(p[2]), float(p[4]) };
  const float high[3] = { float(p[1]), float(p[3]), float(p[5]) };
  program->SetUniform3f("cropLow", low);
  program->SetUniform3f("cropHigh", high);
  program->SetUniformi("cropFlags", clip.GetCroppingFlags());
}
