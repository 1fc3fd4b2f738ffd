#include "vtkTransmittanceVolumeMapper.h"

#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCullerCollection.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceDepthPass.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceLightCachePass.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceMapPass.h"
#include "vtkTransmittanceMapReducer.h"
#include "vtkTransmittanceMediumAdapter.h"
#include "vtkTransmittanceMediumAdapters.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTransmittanceOcclusionPass.h"
#include "vtkTransmittancePathTracePass.h"
#include "vtkTransmittancePeelingPass.h"
#include "vtkTransmittanceProjectionPass.h"
#include "vtkTransmittanceRayCastPass.h"
#include "vtkTransmittanceScopedPeelingState.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallToneMapping.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransmittanceVolumeMapper);

namespace
{
// The adaptive maps' threshold: the faintest transmittance a sample reads
// (vtkTyndallMediumParameters::LightTransmittanceLimit(): the last octave and
// the faintest channel; not where each channel has its own maps:
// `channelMaps`), at least 1e-30 (b = 0: the octave sees only whether T > 0,
// and the maps keep their whole range).
double LightThreshold(double threshold, const vtkTyndallGridMedium& medium, bool channelMaps)
{
  return std::max(medium.GetParameters().LightTransmittanceLimit(threshold, channelMaps), 1.0e-30);
}
}

//------------------------------------------------------------------------------
class vtkTransmittanceVolumeMapper::vtkInternals
{
public:
  vtkTyndallSceneReader Scene;
  bool WarnedClippedDetail = false;

  // Procedural detail's closed forms (brute-force light, sampled camera
  // rays) integrate the unclipped medium: said once per clipped scene.
  void WarnClippedDetail(vtkTransmittanceVolumeMapper* self, bool closedForm)
  {
    const bool affected =
      closedForm && this->Scene.GetDetail().Enabled() && this->Scene.GetMedium().GetClip();
    if (affected && !this->WarnedClippedDetail)
    {
      vtkWarningWithObjectMacro(self,
        << "Clipping planes and cropping cut the procedural detail's marched samples and maps, but "
           "not its closed forms (brute-force light, sampled camera rays): use a map method and "
           "marched camera rays to clip it.");
    }
    this->WarnedClippedDetail = affected;
  }
  // Several Tyndall volumes are composited in the order VTK draws them:
  // said once while the renderer does not sort its volumes back to front.
  bool WarnedDrawOrder = false;
  void WarnDrawOrder(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume)
  {
    bool others = false;
    vtkVolumeCollection* volumes = renderer->GetVolumes();
    vtkCollectionSimpleIterator it;
    volumes->InitTraversal(it);
    while (vtkVolume* other = volumes->GetNextVolume(it))
    {
      others = others ||
        (!vtkTyndallSceneReader::IsDrawnVolume(other, volume) && other->GetVisibility() &&
          other->GetMapper() && other->GetMapper()->IsA("vtkTransmittanceVolumeMapper"));
    }
    bool sorted = false;
    vtkCullerCollection* cullers = renderer->GetCullers();
    cullers->InitTraversal(it);
    while (vtkCuller* culler = cullers->GetNextCuller(it))
    {
      auto* coverage = vtkFrustumCoverageCuller::SafeDownCast(culler);
      sorted = sorted || (coverage && coverage->GetSortingStyle() == VTK_CULLER_SORT_BACK_TO_FRONT);
    }
    const bool warn = others && !sorted;
    if (warn && !this->WarnedDrawOrder)
    {
      vtkWarningWithObjectMacro(self,
        << "Several Tyndall volumes are composited in the order the renderer draws them: where "
           "their pictures overlap, set the renderer's vtkFrustumCoverageCuller to sort back to "
           "front (SetSortingStyleToBackToFront()).");
    }
    this->WarnedDrawOrder = warn;
  }
  // Several processes (vtkTransmittanceMapReducer): the reducer, the whole
  // medium's world box agreed at the start of each frame, and whether the
  // method change was said.
  vtkSmartPointer<vtkTransmittanceMapReducer> Reducer;
  bool HasWholeBounds = false;
  double WholeBounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  bool WarnedDistributedMethod = false;
  vtkTransmittanceMapReducer* Distributed() const
  {
    return this->Reducer && this->Reducer->GetNumberOfProcesses() > 1 ? this->Reducer.Get()
                                                                      : nullptr;
  }
  // Collective: the box around every process's pieces of every Tyndall
  // volume of the renderer (the drawn one and the guests its light crosses;
  // an empty piece adds nothing). False on a communication error.
  bool AgreeWholeBounds(vtkRenderer* renderer, vtkVolume* volume)
  {
    vtkBoundingBox box;
    auto add = [&box](vtkVolume* v)
    {
      const double* b = v ? v->GetBounds() : nullptr;
      if (b && b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5])
      {
        box.AddBounds(b);
      }
    };
    add(volume);
    if (vtkVolumeCollection* volumes = renderer ? renderer->GetVolumes() : nullptr)
    {
      vtkCollectionSimpleIterator it;
      volumes->InitTraversal(it);
      while (vtkVolume* v = volumes->GetNextVolume(it))
      {
        if (v->GetVisibility() && vtkTransmittanceVolumeMapper::SafeDownCast(v->GetMapper()))
        {
          add(v);
        }
      }
    }
    double values[6];
    for (int a = 0; a < 3; ++a)
    {
      values[a] = box.IsValid() ? -box.GetMinPoint()[a] : -VTK_DOUBLE_MAX;
      values[3 + a] = box.IsValid() ? box.GetMaxPoint()[a] : -VTK_DOUBLE_MAX;
    }
    const bool agreed = this->Reducer->AllReduceMax(values, 6);
    this->HasWholeBounds = agreed && values[3] >= -values[0];
    for (int a = 0; a < 3; ++a)
    {
      this->WholeBounds[2 * a] = -values[a];
      this->WholeBounds[2 * a + 1] = values[3 + a];
    }
    return agreed;
  }
  // A projection drawn by several processes: each projects its own piece
  // and the compositor blends the pieces "over", which is not a maximum,
  // minimum, average or sum across them: said once.
  bool WarnedDistributedProjection = false;
  void WarnDistributedProjection(vtkTransmittanceVolumeMapper* self)
  {
    const bool warn = this->Distributed() != nullptr;
    if (warn && !this->WarnedDistributedProjection)
    {
      vtkWarningWithObjectMacro(self,
        << "Several processes draw this picture: each projects its own piece of the volume in the "
        << vtkTyndallProjection::GetModeName(this->Scene.GetMedium().GetProjection().GetMode())
        << " blend mode and the pieces are blended over each other, not projected across them.");
    }
    this->WarnedDistributedProjection = warn;
  }
  // A coloured extinction in depth peeling: VTK's peels keep one opacity
  // per pixel, the mean of the three channels'; said once.
  bool WarnedChromaticPeeling = false;
  void WarnChromaticPeeling(vtkTransmittanceVolumeMapper* self, bool peeling)
  {
    const bool warn = peeling && this->Frame.Medium->GetParameters().GetChromatic();
    if (warn && !this->WarnedChromaticPeeling)
    {
      vtkWarningWithObjectMacro(self,
        << "A coloured extinction (ExtinctionColor) in depth peeling for volumes: VTK's peels "
           "keep one opacity per pixel, so the translucent geometry behind the medium is dimmed "
           "by the mean of its three channels' transmittance, not by each channel's.");
    }
    this->WarnedChromaticPeeling = warn;
  }
  // A light that falls back to marching (a positional light inside the
  // box) sees this process's piece alone: said once.
  bool WarnedDistributedLight = false;
  void WarnDistributedLights(vtkTransmittanceVolumeMapper* self)
  {
    for (const vtkTransmittanceFrame::Light& light : this->Frame.Lights)
    {
      if (light.Method == BRUTE_FORCE && !this->WarnedDistributedLight)
      {
        vtkWarningWithObjectMacro(
          self, << "Several processes draw this picture, but a light inside the medium's box is "
                   "marched (brute force): its shadows see this process's piece alone.");
        this->WarnedDistributedLight = true;
      }
    }
  }
  // While PrepareDistributedMaps() builds: the frame carries the reducer.
  bool Reducing = false;
  bool WarnedUnreducedMaps = false;
  // The maps of a frame drawn by several processes. Collective while
  // reducing; in Render() (where ParaView's compositor may skip a process)
  // the maps PrepareDistributedMaps() added, or this piece's alone, said once.
  vtkTransmittanceMapPass* UpdateDistributedMaps(vtkTransmittanceVolumeMapper* self)
  {
    if (this->Reducing || !this->Frame.NeedsMaps() || this->Maps->IsBuiltFor(this->Frame))
    {
      return this->Maps->Render(this->Frame, self) ? this->Maps.GetPointer() : nullptr;
    }
    if (!this->WarnedUnreducedMaps)
    {
      vtkWarningWithObjectMacro(self,
        << "Several processes draw this picture, but its maps were not added over them before "
           "the render (PrepareDistributedMaps()): the light sees this process's piece alone.");
      this->WarnedUnreducedMaps = true;
    }
    return this->Maps->Render(this->Frame, self) ? this->Maps.GetPointer() : nullptr;
  }
  // With several processes only ETM adds across them: the others are drawn
  // as ETM, said once.
  int DistributedMethod(vtkTransmittanceVolumeMapper* self, int method)
  {
    if (method == NONE || method == ETM)
    {
      return method;
    }
    if (!this->WarnedDistributedMethod)
    {
      vtkWarningWithObjectMacro(
        self, << "Several processes draw this picture: " << self->GetTransmittanceMethodAsString()
              << " is drawn as ETM, whose maps add across the processes (see "
                 "vtkTransmittanceMapReducer).");
      this->WarnedDistributedMethod = true;
    }
    return ETM;
  }
  vtkTransmittanceFrame Frame;
  vtkNew<vtkTransmittanceMediumTextures> Textures;
  vtkNew<vtkTransmittanceOcclusionPass> Occlusion;
  vtkNew<vtkTransmittanceMapPass> Maps;
  vtkNew<vtkTransmittanceLightCachePass> Cache;
  vtkNew<vtkTransmittanceDepthPass> Depth;
  vtkNew<vtkTransmittanceRayCastPass> RayCast;
  vtkNew<vtkTransmittancePathTracePass> PathTracer;
  vtkNew<vtkTransmittanceProjectionPass> Projection;
  // The window the resources live in (weak: it may go before the mapper).
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  // Whether the last Render() went through every pass: the lights, methods,
  // frusta and maps it reports describe that render, or nothing.
  bool Complete = false;
  // Whether the last Render() drew a projection blend mode (vtkTyndallProjection).
  bool Projected = false;
  /// The last Render() or UpdateShadowMaps() read the scene and has its maps
  /// (also when another volume drew it).
  bool Lit = false;
  // Interactive level of detail: the last camera-ray cost per full-size
  // pixel (0: not measured yet), time and reduction.
  double SecondsPerPixel = 0.0;
  double RayCastTime = 0.0;
  int Reduction = 0;
  double StepScale = 1.0;

  // Progressive detail sampling: what the last picture depended on; a
  // frame whose key equals it adds to the average (empty: start anew).
  std::vector<double> StillKey;

  // A 3-D prop's redraw time as StillFrameKey() counts it.
  static vtkMTimeType SceneRedrawMTime(vtkProp* prop);
  // What a still frame depends on; UpdateStillFrame() compares it with
  // StillKey and sets the inputs' history; after the render, StillKey
  // takes the key as the render left it (VTK updates some MTimes while
  // rendering, once).
  std::vector<double> StillFrameKey(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer,
    vtkVolume* volume, const vtkTransmittanceRayCastPass::Inputs& inputs) const;
  void UpdateStillFrame(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer,
    vtkVolume* volume, vtkTransmittanceRayCastPass::Inputs& inputs);
  /// Whether two still-frame keys are equal (within a move no pixel shows).
  static bool SameStillKey(const std::vector<double>& a, const std::vector<double>& b);

  // Path tracing (PathTracing on): the key of the picture the running mean
  // belongs to (empty: the next frame is the map-based one), the frames in
  // it, the samples per pixel of the last picture (0: the map-based frame)
  // and the refusal last said (vtkTransmittancePathTracePass::Refusal()).
  std::vector<double> PathKey;
  int PathFrames = 0;
  int PathSamples = 0;
  std::string PathRefusal;
  bool WarnedCutPaths = false;
  bool WarnedPathGeometry = false;
  /**
   * Draws the frame of path-tracing mode and returns true, or returns
   * false (the mode is off, or refused: said once) and draws nothing: the
   * map-based frame when the picture's key changed since the last frame
   * (something moves), else a frame of paths added to the running mean
   * (or the mean redrawn once it has PathTraceSamplesPerPixel). Sets Complete.
   */
  bool TracePaths(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
    const vtkTransmittanceRayCastPass::Inputs& inputs, bool peeling);
  /// Whether the frame cannot be path traced; says why once (a warning).
  bool RefusePaths(vtkTransmittanceVolumeMapper* self, bool peeling);
  void ChooseDetail(vtkRenderer* renderer, vtkVolume* volume, bool adjust, int maximum,
    vtkTransmittanceRayCastPass::Inputs& inputs) const;
  // The camera rays of `inputs`; with `guide`, drawn as the path tracer's
  // denoising guide (vtkTransmittancePathTracePass::DrawGuide(): the same picture).
  bool CastRays(const vtkTransmittanceRayCastPass::Inputs& inputs, bool timed, vtkObject* reporter,
    bool guide = false);
  // The pass whose camera rays CastRays() drew last: the ray cast, or the
  // path tracer's guide (what the GetLast...() queries read).
  vtkTransmittanceRayCastPass* DrawnBy = nullptr;
  const vtkTransmittanceRayCastPass& LastCast() const
  {
    return this->DrawnBy ? *this->DrawnBy : *this->RayCast.Get();
  }
  // The camera rays' cost per full-size pixel of `seconds` for a frame at
  // the last Reduction and StepScale.
  double CostPerPixel(double seconds) const;

  /// A stage of VTK's depth peeling the volume is drawn in (vtkTransmittancePeelingPass).
  struct Peel
  {
    vtkOpenGLRenderPass* Pass = nullptr;
    int Stage = vtkTransmittancePeelingPass::NoStage;
    vtkTextureObject* Images[2] = { nullptr, nullptr }; // the front and back parts' ray casts
  };
  vtkNew<vtkTransmittancePeelingPass> Peeling;
  // A frame's stages share what its first stage (PeelInitializing) made:
  // the opaque occluders' depth from the lights (whether there were any),
  // and the camera rays' time, summed over the stages (the frame's cost, from
  // which the next frame's first stage chooses the interactive reduction all
  // its stages draw at).
  bool PeelOccluders = false;
  double PeelRayTime = 0.0;
  void StartPeelFrame(const Peel* peel);

  /**
   * Render()'s work: the frame, the maps and the camera rays; in a
   * depth-peeling stage (`peel` not null) the rays of its parts, into
   * peel->Images. Sets Complete.
   */
  void RenderVolume(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
    vtkOpenGLRenderWindow* window, Peel* peel);
  /// Where the camera rays end: the opaque depth, or a peeling stage's ranges.
  bool CaptureDepth(vtkTransmittanceVolumeMapper* self, vtkVolume* volume, const Peel* peel,
    vtkTransmittanceRayCastPass::Inputs& inputs);
  /// The camera rays of a peeling stage's parts, each into its own image.
  bool CastPeelRays(
    vtkTransmittanceRayCastPass::Inputs inputs, Peel& peel, bool timed, vtkObject* reporter);
  // The camera rays of VTK's projection blend modes (vtkTyndallProjection):
  // no light, map or occluder; timed as CastRays() times its rays (not in
  // a depth-peeling stage: `peel`).
  bool Project(vtkTransmittanceVolumeMapper* self, vtkVolume* volume, bool timed, Peel* peel);

  /**
   * Reads the scene, uploads what changed and fills Frame for (renderer,
   * volume), the first steps of every Render(); false (reported) on error.
   */
  bool PrepareFrame(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
    vtkOpenGLRenderWindow* window);

  /**
   * Reads the scene and uploads the medium's textures when they changed
   * (PrepareFrame()'s first steps; also called by a mapper whose light
   * crosses this one's medium, for its textures); false (reported) on error.
   */
  bool UpdateMedium(vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
    vtkOpenGLRenderWindow* window);

  /**
   * The textures of the scene's guests (the other volumes the light
   * crosses), brought up to date by their own mappers; false (reported) on error.
   */
  bool UpdateGuests(
    vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
  std::vector<const vtkTransmittanceMediumTextures*> GuestTextures;

  /**
   * The maps of the frame: a guest's mapper's when they hold what the frame
   * needs (the same media, settings and lights: one set shared by the
   * renderer's volumes), else this mapper's own, built when something
   * changed; null (reported) on error. UsedMaps keeps it for the queries.
   */
  vtkTransmittanceMapPass* UpdateMaps(vtkTransmittanceVolumeMapper* self);
  vtkWeakPointer<vtkTransmittanceMapPass> UsedMaps;
  vtkTransmittanceMapPass* GetUsedMaps() const
  {
    return this->UsedMaps ? this->UsedMaps.GetPointer() : this->Maps.GetPointer();
  }

  /// The medium's textures and the guests', bound for the scope of the returned object.
  vtkTransmittanceScopedTextures BindMedium() const
  {
    std::vector<vtkTextureObject*> textures = { this->Textures->GetVolumeTexture(),
      this->Textures->GetValidityTexture(), this->Textures->GetTransferTexture(),
      this->Textures->GetTransfer2DTexture(), this->Textures->GetBlockTexture(),
      this->Textures->GetDetailTexture(), this->Textures->GetEmissionTexture(),
      this->Textures->GetScatteringTexture(), this->Textures->GetComponentTexture(),
      this->Textures->GetLabelTexture(), this->Textures->GetLabelRowsTexture(),
      this->Textures->GetBrickTexture() };
    for (const vtkTransmittanceMediumTextures* guest : this->GuestTextures)
    {
      textures.push_back(guest->GetVolumeTexture());
      textures.push_back(guest->GetBrickTexture()); // null but for bricks
      textures.push_back(guest->GetTransferTexture());
      textures.push_back(guest->GetScatteringTexture()); // null but for a coloured cloud
      textures.push_back(guest->GetEmissionTexture());   // null but for an emission array
    }
    return vtkTransmittanceScopedTextures(textures);
  }
};

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::vtkInternals::ChooseDetail(vtkRenderer* renderer,
  vtkVolume* volume, bool adjust, int maximum, vtkTransmittanceRayCastPass::Inputs& inputs) const
{
  inputs.Reduction = 1;
  inputs.StepScale = 1.0;
  const double allocated = volume->GetAllocatedRenderTime();
  if (!adjust || !(this->SecondsPerPixel > 0.0) || !(allocated > 0.0))
  {
    return;
  }
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  // How many times too slow the full frame would be: up to 4x, fewer
  // pixels; beyond, also steps twice as long (the cost goes as pixels x
  // steps).
  const double need = this->SecondsPerPixel * size[0] * size[1] / allocated;
  if (need <= 1.0)
  {
    return;
  }
  inputs.StepScale = need > 4.0 ? 2.0 : 1.0;
  const double r = std::ceil(std::sqrt(need / inputs.StepScale) - 1e-9);
  inputs.Reduction = static_cast<int>(std::min(std::max(r, 1.0), static_cast<double>(maximum)));
}

//------------------------------------------------------------------------------
// A 3-D prop's redraw time as the still key counts it: VTK's
// GetRedrawMTime(), except that another Tyndall volume's leaves out its
// mapper's display settings (GetSceneMTime(): vtkTyndallSceneBuilder sets
// every mapper's, and they change only how that volume is shown).
vtkMTimeType vtkTransmittanceVolumeMapper::vtkInternals::SceneRedrawMTime(vtkProp* prop)
{
  vtkVolume* volume = vtkVolume::SafeDownCast(prop);
  auto* tyndall =
    volume ? vtkTransmittanceVolumeMapper::SafeDownCast(volume->GetMapper()) : nullptr;
  if (!tyndall)
  {
    return prop->GetRedrawMTime();
  }
  vtkDataObject* data = tyndall->GetInputDataObject(0, 0);
  return std::max({ volume->GetMTime(), tyndall->GetSceneMTime(),
    volume->GetProperty() ? volume->GetProperty()->GetMTime() : vtkMTimeType(0),
    data ? data->GetMTime() : vtkMTimeType(0) });
}

//------------------------------------------------------------------------------
std::vector<double> vtkTransmittanceVolumeMapper::vtkInternals::StillFrameKey(
  vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
  const vtkTransmittanceRayCastPass::Inputs& inputs) const
{
  vtkDataObject* input = self->GetInputDataObject(0, 0);
  std::vector<double> key;
  vtkMatrix4x4* projection = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1, 1);
  key.insert(key.end(), projection->GetData(), projection->GetData() + 16);
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  key.insert(key.end(),
    { double(size[0]), double(size[1]), double(origin[0]), double(origin[1]),
      double(inputs.Reduction), inputs.StepScale });
  // The volume's placement by its matrix, not its MTime: ParaView's LOD
  // volume (vtkPVLODVolume) sets its inner volume's state every render.
  vtkMatrix4x4* placement = volume->GetMatrix();
  key.insert(key.end(), placement->GetData(), placement->GetData() + 16);
  key.insert(key.end(),
    { double(self->GetSceneMTime()), double(volume->GetProperty()->GetMTime()),
      double(input ? input->GetMTime() : 0), double(this->GetUsedMaps()->GetBuildSerial()),
      double(this->Cache->GetBuildCount()) });
  const std::vector<double>& clip = this->Scene.GetMedium().GetClipRegion().GetKey();
  key.insert(key.end(), clip.begin(), clip.end());
  key.push_back(double(this->Scene.GetEnvironment().GetSerial())); // the renderer's sky
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator lit;
  lights->InitTraversal(lit);
  while (vtkLight* light = lights->GetNextLight(lit))
  {
    key.push_back(double(light->GetMTime()));
  }
  // The 3-D props (opaque geometry hides the medium); 2-D overlays such as
  // a frame counter's text change every frame and do not touch the medium.
  // The volume itself is in the key above (its redraw time has the mapper's
  // whole MTime, which a change of the display transform moves).
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator pit;
  props->InitTraversal(pit);
  while (vtkProp* prop = props->GetNextProp(pit))
  {
    if (!vtkProp3D::SafeDownCast(prop) || prop == volume)
    {
      continue;
    }
    key.push_back(prop->GetVisibility() ? double(SceneRedrawMTime(prop)) : -1.0);
  }
  return key;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::vtkInternals::UpdateStillFrame(
  vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkVolume* volume,
  vtkTransmittanceRayCastPass::Inputs& inputs)
{
  inputs.DetailSamples = self->GetDetailSamplesPerPixel();
  inputs.HistoryFrames = 0;
  if (vtkTransmittanceRayCastPass::DetailSamplesFor(this->Frame, inputs.DetailSamples) == 0)
  {
    this->StillKey.clear();
    return;
  }
  const std::vector<double> key = this->StillFrameKey(self, renderer, volume, inputs);
  inputs.HistoryFrames =
    SameStillKey(key, this->StillKey) ? this->RayCast->GetLastHistoryFrames() : 0;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::SameStillKey(
  const std::vector<double>& a, const std::vector<double>& b)
{
  // The camera's matrix is recomputed each frame and differs in its last
  // float bits between renders (measured 3e-8 relative, alternating):
  // equal within 1e-6, relative, a move no pixel shows.
  bool same = a.size() == b.size();
  for (size_t i = 0; same && i < a.size(); ++i)
  {
    same = std::abs(a[i] - b[i]) <= 1e-6 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) });
  }
  return same;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::RefusePaths(
  vtkTransmittanceVolumeMapper* self, bool peeling)
{
  const std::string refusal =
    vtkTransmittancePathTracePass::Refusal(this->Frame, peeling, this->Distributed() != nullptr);
  if (!refusal.empty() && refusal != this->PathRefusal)
  {
    vtkWarningWithObjectMacro(
      self, << "Path tracing: " << refusal << "; the map-based frame is drawn instead.");
  }
  this->PathRefusal = refusal;
  return !refusal.empty();
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::TracePaths(vtkTransmittanceVolumeMapper* self,
  vtkRenderer* renderer, vtkVolume* volume, const vtkTransmittanceRayCastPass::Inputs& inputs,
  bool peeling)
{
  this->PathSamples = 0;
  if (!self->GetPathTracing())
  {
    this->PathKey.clear();
    this->PathRefusal.clear();
    return false;
  }
  if (this->RefusePaths(self, peeling))
  {
    this->PathKey.clear();
    return false;
  }
  this->StillKey.clear();
  // The paths' picture is full size, whatever the interactive reduction.
  vtkTransmittanceRayCastPass::Inputs still = inputs;
  still.Reduction = 1;
  still.StepScale = 1.0;
  if (!SameStillKey(this->StillFrameKey(self, renderer, volume, still), this->PathKey))
  {
    // Something moved: the map-based frame; the paths start at the next
    // still one. Drawn full size for the denoiser, it is their guide too.
    this->PathKey.clear();
    this->PathFrames = 0;
    const bool guide =
      self->GetPathTraceDenoise() && vtkTransmittancePathTracePass::CanGuide(inputs);
    if (!guide)
    {
      this->PathTracer->DropGuide();
    }
    this->Complete = this->CastRays(inputs, self->InteractiveAdjustment, self, guide);
    if (this->Complete)
    {
      this->PathKey = this->StillFrameKey(self, renderer, volume, still);
    }
    return true;
  }
  vtkTransmittancePathTracePass::Settings settings;
  settings.SamplesPerFrame = self->GetPathTraceSamplesPerFrame();
  settings.MaximumBounces = self->GetPathTraceMaximumBounces();
  settings.TrackedShadows = self->GetPathTraceShadows() == PATH_SHADOWS_TRACKED;
  settings.ClosedForm = self->GetPathTraceDistanceSampling() == PATH_DISTANCE_CLOSED_FORM;
  settings.Seed = self->GetPathTraceSeed();
  settings.Denoise = self->GetPathTraceDenoise();
  const bool cut = vtkTransmittancePathTracePass::MayCutPaths(this->Frame, settings);
  if (cut && !this->WarnedCutPaths)
  {
    vtkWarningWithObjectMacro(
      self, << "Path tracing: delta tracking across the medium's box at its largest extinction "
               "(optical depth "
            << this->Frame.OwnMedium->GetMajorant() * this->Frame.Diagonal
            << ") can take a path past a fragment's loop budget; a path cut short loses its later "
               "bounces, or the rest of its first flight (a darker or more transparent picture). "
               "Fewer bounces (PathTraceMaximumBounces), shadows from the maps or a lower "
               "DensityScale shorten the paths.");
  }
  this->WarnedCutPaths = cut;
  if (inputs.Occlusion && !this->WarnedPathGeometry)
  {
    vtkWarningWithObjectMacro(self,
      << "Path tracing: opaque geometry stops the camera rays and shadows the lights, but the "
         "scattered paths cross it.");
  }
  this->WarnedPathGeometry = inputs.Occlusion != nullptr;
  const int wanted = self->GetPathTraceSamplesPerPixel() -
    (this->PathFrames > 0 ? this->PathTracer->GetSamples() : 0);
  if (this->PathFrames > 0 && wanted <= 0)
  {
    this->Complete = this->PathTracer->Redraw(this->Frame, still, settings, self);
  }
  else
  {
    const int samples =
      vtkTransmittancePathTracePass::NextSamples(this->Frame, settings, this->PathFrames, wanted);
    this->Complete =
      this->PathTracer->Render(this->Frame, still, settings, this->PathFrames, samples, self);
    this->PathFrames = this->Complete ? this->PathTracer->GetHistoryFrames() : 0;
  }
  this->PathKey.clear();
  if (this->Complete)
  {
    this->PathSamples = this->PathTracer->GetSamples();
    this->Reduction = 1; // the paths' picture is full size
    this->StepScale = 1.0;
    this->PathKey = this->StillFrameKey(self, renderer, volume, still);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::CastRays(
  const vtkTransmittanceRayCastPass::Inputs& inputs, bool timed, vtkObject* reporter, bool guide)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->DrawnBy = guide ? this->PathTracer->GetGuideCast() : this->RayCast.Get();
  if (guide ? !this->PathTracer->DrawGuide(this->Frame, inputs, reporter)
            : !this->RayCast->Render(this->Frame, inputs, reporter))
  {
    return false;
  }
  this->Reduction = inputs.Reduction;
  this->StepScale = inputs.StepScale;
  this->RayCastTime = 0.0;
  if (timed)
  {
    glFinish();
    timer->StopTimer();
    this->RayCastTime = timer->GetElapsedTime();
    this->SecondsPerPixel = this->CostPerPixel(this->RayCastTime);
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::vtkInternals::CostPerPixel(double seconds) const
{
  // The cost per full-size pixel: the reduced image has 1 / r^2 of them.
  int size[2], origin[2];
  this->Frame.Renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  const double pixels = std::max(1.0, double(size[0]) * size[1]);
  return seconds * this->StepScale / (pixels / (double(this->Reduction) * this->Reduction));
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::Project(
  vtkTransmittanceVolumeMapper* self, vtkVolume* volume, bool timed, Peel* peel)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkTransmittanceRayCastPass::Inputs inputs;
  if (!this->CaptureDepth(self, volume, peel, inputs))
  {
    return false;
  }
  if (!peel)
  {
    if (!this->Projection->Render(this->Frame, inputs.Depth, self))
    {
      return false;
    }
  }
  else
  {
    // A stage projects each of its parts, as VTK's ray caster does.
    const int parts = peel->Stage == vtkTransmittanceShaderSource::PeelBlending ? 1 : 2;
    for (int part = 0; part < parts; ++part)
    {
      if (!this->Projection->Render(this->Frame, inputs.Depth, self, part))
      {
        return false;
      }
      peel->Images[part] = this->Projection->GetImage(part);
    }
  }
  this->Reduction = 1;
  this->StepScale = 1.0;
  this->RayCastTime = 0.0;
  if (timed && !peel)
  {
    glFinish();
    timer->StopTimer();
    this->RayCastTime = timer->GetElapsedTime();
  }
  return true;
}

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper::vtkTransmittanceVolumeMapper()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper::~vtkTransmittanceVolumeMapper() = default;

//------------------------------------------------------------------------------
const char* vtkTransmittanceVolumeMapper::GetTransmittanceMethodAsString()
{
  return vtkTransmittanceMapMath::GetMethodName(this->TransmittanceMethod);
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetMaximumNumberOfLights()
{
  return vtkTyndallSceneReader::MaximumNumberOfLights;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetMapBuildCount()
{
  return this->Internals->Maps->GetBuildCount();
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastMapBuildTime()
{
  return this->Internals->Maps->GetLastBuildTime();
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetTransmittanceCacheBuildCount()
{
  return this->Internals->Cache->GetBuildCount();
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetPathTraceGuideRenderCount()
{
  return this->Internals->PathTracer->GetGuideRenders();
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastTransmittanceCacheBuildTime()
{
  return this->Internals->Cache->GetLastBuildTime();
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastEmptySpaceGridTime()
{
  const vtkTransmittanceMediumTextures& t = *this->Internals->Textures;
  return t.GetLastBlockRangeTime() + t.GetLastMajorantTime();
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetEmptyBlockFraction()
{
  return this->Internals->Textures->GetMajorantGrid().GetEmptyFraction();
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& in = *this->Internals;
  in.Complete = false;
  in.Lit = false;
  in.Textures->ReleaseGraphicsResources(window);
  in.Occlusion->ReleaseGraphicsResources(window);
  in.Maps->ReleaseGraphicsResources(window);
  in.Cache->ReleaseGraphicsResources(window);
  in.Depth->ReleaseGraphicsResources(window);
  in.RayCast->ReleaseGraphicsResources(window);
  in.PathTracer->ReleaseGraphicsResources(window);
  in.PathKey.clear();
  in.PathFrames = 0;
  in.PathSamples = 0;
  in.Projection->ReleaseGraphicsResources(window);
  in.Peeling->ReleaseGraphicsResources(window);
  in.Window = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::UpdateMedium(vtkTransmittanceVolumeMapper* self,
  vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window)
{
  if (this->Window && this->Window != window)
  {
    // Released in their own context, then back to this one.
    this->Window->MakeCurrent();
    self->ReleaseGraphicsResources(this->Window);
    window->MakeCurrent();
  }
  this->Window = window;
  if (!this->Scene.Update(renderer, volume, self))
  {
    return false;
  }
  const vtkTyndallMedium& medium = *this->Scene.GetMedia().front();
  this->Textures->SetMaximumTextureSize(self->MaximumTextureSize);
  this->Textures->SetBricking(self->VolumeBricking);
  return vtkTransmittanceMediumAdapters::For(medium).Upload(window, medium, *this->Textures, self);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::UpdateGuests(
  vtkTransmittanceVolumeMapper* self, vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  this->GuestTextures.clear();
  for (vtkVolume* guest : this->Scene.GetGuestVolumes())
  {
    // The scene reader took only volumes drawn by this class.
    auto* mapper = static_cast<vtkTransmittanceVolumeMapper*>(guest->GetMapper());
    if (!mapper->Internals->UpdateMedium(mapper, renderer, guest, window))
    {
      return false;
    }
    this->GuestTextures.push_back(mapper->Internals->Textures.Get());
  }
  return true;
}

//------------------------------------------------------------------------------
vtkTransmittanceMapPass* vtkTransmittanceVolumeMapper::vtkInternals::UpdateMaps(
  vtkTransmittanceVolumeMapper* self)
{
  this->UsedMaps = this->Maps.GetPointer();
  if (this->Distributed())
  {
    return this->UpdateDistributedMaps(self);
  }
  if (!this->Frame.NeedsMaps())
  {
    return this->Maps;
  }
  for (vtkVolume* guest : this->Scene.GetGuestVolumes())
  {
    auto* mapper = static_cast<vtkTransmittanceVolumeMapper*>(guest->GetMapper());
    vtkTransmittanceMapPass* maps = mapper->Internals->Maps;
    if (mapper->Internals->Window == this->Window && maps->IsBuiltFor(this->Frame))
    {
      this->UsedMaps = maps;
      return maps;
    }
  }
  return this->Maps->Render(this->Frame, self) ? this->Maps.GetPointer() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::PrepareFrame(vtkTransmittanceVolumeMapper* self,
  vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window)
{
  if (!this->UpdateMedium(self, renderer, volume, window) ||
    !this->UpdateGuests(self, renderer, window))
  {
    return false;
  }
  // A projection draws no detail (vtkTyndallVolumeSettings names it).
  this->WarnClippedDetail(self,
    !this->Scene.GetMedium().GetProjection().Enabled() &&
      (self->TransmittanceMethod == BRUTE_FORCE || self->DetailSamplesPerPixel > 0));
  this->WarnDrawOrder(self, renderer, volume);
  vtkTransmittanceFrame::Settings settings;
  settings.Method = self->TransmittanceMethod;
  settings.Coefficients = self->NumberOfCoefficients;
  settings.MapSize = self->TransmittanceMapSize;
  settings.LightSampleCount = self->LightSampleCount;
  const bool channelMaps =
    self->TransmittanceMethod == TFM || self->TransmittanceMethod == ADAPTIVE_TFM;
  settings.AdaptiveThreshold =
    LightThreshold(self->AdaptiveThreshold, this->Scene.GetMedium(), channelMaps);
  settings.SampleDistance = self->SampleDistance;
  settings.Jitter = self->Jitter;
  settings.SkipEmptySpace = self->EmptySpaceSkipping;
  settings.CacheSize = self->TransmittanceCache ? self->TransmittanceCacheSize : 0;
  settings.Exposure = self->Exposure;
  settings.ToneCurve = self->ToneCurve;
  settings.EncodeSRGB = self->EncodeSRGB;
  if (vtkTransmittanceMapReducer* reducer = this->Distributed())
  {
    settings.Reducer = this->Reducing ? reducer : nullptr;
    settings.Method = this->DistributedMethod(self, settings.Method);
    settings.HasMapBounds = this->HasWholeBounds;
    settings.OpacityCoversRadiance = true; // IceT blends 8-bit colours unclamped
    std::copy(this->WholeBounds, this->WholeBounds + 6, settings.MapBounds);
  }
  this->Frame.Prepare(
    renderer, window, this->Scene, *this->Textures, this->GuestTextures, settings);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::UpdateShadowMaps(vtkRenderer* renderer, vtkVolume* volume)
{
  vtkInternals& in = *this->Internals;
  // The lights and maps are reported (GetTransmittanceMap()) as this frame
  // leaves them, also when the volume itself is out of view and only its
  // shadow is drawn; none when the frame fails.
  in.Lit = false;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window || !in.PrepareFrame(this, renderer, volume, window))
  {
    return false;
  }
  if (!in.Frame.NeedsMaps())
  {
    in.Lit = true; // the lights are read, none of them has a map
    return false;
  }
  vtkTransmittanceScopedTextures medium = in.BindMedium();
  in.Lit = in.UpdateMaps(this) != nullptr;
  return in.Lit;
}

//------------------------------------------------------------------------------
const vtkTransmittanceFrame& vtkTransmittanceVolumeMapper::GetShadowFrame(
  vtkTextureObject*& maps, int& slices)
{
  maps = this->Internals->GetUsedMaps()->GetTexture();
  slices = this->Internals->GetUsedMaps()->GetSlices();
  return this->Internals->Frame;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  vtkInternals& in = *this->Internals;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro(<< "vtkTransmittanceVolumeMapper needs an OpenGL render window.");
    return;
  }
  // Translucent geometry with depth peeling for volumes: VTK draws the
  // volume in its peeling pass, a stage at a time (vtkTransmittancePeelingPass).
  vtkInternals::Peel peel;
  peel.Stage = vtkTransmittancePeelingPass::FindStage(volume, this, peel.Pass);
  if (!peel.Pass)
  {
    in.RenderVolume(this, renderer, volume, window, nullptr);
    return;
  }
  if (peel.Stage == vtkTransmittancePeelingPass::UnknownStage)
  {
    in.Complete = false;
    vtkErrorMacro(<< "VTK's depth peeling for volumes is in a stage Tyndall does not know (not "
                     "VTK 9.1's): the volume is not drawn. Turn the renderer's "
                     "UseDepthPeelingForVolumes off.");
    return;
  }
  {
    vtkTransmittanceScopedPeelingState defaults(window->GetState());
    in.RenderVolume(this, renderer, volume, window, &peel);
  }
  if (in.Complete && peel.Images[0])
  {
    in.Complete = in.Peeling->Composite(in.Frame, peel.Pass, peel.Stage, peel.Images[0],
      peel.Images[1], this, volume, in.Frame.Integrator.OpacityCoversRadiance, this);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::vtkInternals::RenderVolume(vtkTransmittanceVolumeMapper* self,
  vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window, Peel* peel)
{
  this->Complete = false;
  this->Lit = false;
  this->Projected = false;
  if (!this->PrepareFrame(self, renderer, volume, window))
  {
    return;
  }
  vtkTransmittanceScopedTextures medium = this->BindMedium();
  if (this->Frame.Medium->GetProjection().Enabled())
  {
    this->Lit = true; // no map: a projection is unshadowed (its lights' method None)
    this->Projected = true;
    this->StillKey.clear();
    this->PathKey.clear();
    this->PathSamples = 0;
    if (self->GetPathTracing())
    {
      this->RefusePaths(self, peel != nullptr);
    }
    this->WarnDistributedProjection(self);
    this->Complete = this->Project(self, volume, self->InteractiveAdjustment, peel);
    return;
  }
  this->StartPeelFrame(peel);
  vtkTransmittanceRayCastPass::Inputs inputs;
  const bool laterStage = peel && peel->Stage != vtkTransmittanceShaderSource::PeelInitializing;
  const bool occluders =
    laterStage ? this->PeelOccluders : this->Occlusion->Render(this->Frame, self);
  this->PeelOccluders = peel && occluders;
  if (occluders)
  {
    inputs.Occlusion = this->Occlusion->GetTexture();
    inputs.OcclusionSlices = this->Occlusion->GetSlices();
  }
  vtkTransmittanceMapPass* maps = this->UpdateMaps(self);
  this->Lit = maps != nullptr;
  if (maps && this->Scene.GetDrawnBy())
  {
    return; // drawn by the first volume of its camera group, maps shared
  }
  if (!maps || !this->CaptureDepth(self, volume, peel, inputs))
  {
    return;
  }
  if (this->Frame.NeedsMaps())
  {
    inputs.Maps = maps->GetTexture();
    inputs.MapSlices = maps->GetSlices();
    if (this->Cache->Render(
          this->Frame, inputs.Maps, inputs.MapSlices, maps->GetBuildSerial(), self))
    {
      inputs.Cache = this->Cache->GetTexture();
      std::copy(this->Cache->GetSize(), this->Cache->GetSize() + 3, inputs.CacheSize);
      inputs.CacheLights = this->Cache->GetLights();
    }
  }
  this->ChooseDetail(
    renderer, volume, self->InteractiveAdjustment, self->MaximumImageReduction, inputs);
  this->WarnChromaticPeeling(self, peel != nullptr);
  if (this->TracePaths(self, renderer, volume, inputs, peel != nullptr))
  {
    return;
  }
  if (peel)
  {
    this->StillKey.clear();
    this->Complete = this->CastPeelRays(inputs, *peel, self->InteractiveAdjustment, self);
    return;
  }
  this->UpdateStillFrame(self, renderer, volume, inputs);
  this->Complete = this->CastRays(inputs, self->InteractiveAdjustment, self);
  this->StillKey.clear();
  if (this->Complete && this->RayCast->GetLastDetailSamples() > 0)
  {
    this->StillKey = this->StillFrameKey(self, renderer, volume, inputs);
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::CaptureDepth(vtkTransmittanceVolumeMapper* self,
  vtkVolume* volume, const Peel* peel, vtkTransmittanceRayCastPass::Inputs& inputs)
{
  if (peel)
  {
    // The stage's depth ranges stand for the opaque depth.
    if (!this->Peeling->RenderRanges(this->Frame, peel->Pass, peel->Stage, self, volume, self))
    {
      return false;
    }
    inputs.Depth = this->Peeling->GetRanges();
    inputs.DepthRanges = true;
    return true;
  }
  if (!this->Depth->Render(this->Frame, self))
  {
    return false;
  }
  inputs.Depth = this->Depth->GetTexture();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::vtkInternals::CastPeelRays(
  vtkTransmittanceRayCastPass::Inputs inputs, Peel& peel, bool timed, vtkObject* reporter)
{
  // A stage draws its parts once: no still-frame history (the parts differ;
  // detail is marched, not sampled); timed into the frame's sum.
  inputs.DetailSamples = 0;
  inputs.HistoryFrames = 0;
  const double perPixel = this->SecondsPerPixel; // the frame's, from its first stage
  const int parts = peel.Stage == vtkTransmittanceShaderSource::PeelBlending ? 1 : 2;
  for (int part = 0; part < parts; ++part)
  {
    inputs.Segment = part;
    if (!this->CastRays(inputs, timed, reporter))
    {
      return false;
    }
    this->PeelRayTime += this->RayCastTime;
    peel.Images[part] = this->RayCast->GetImage(part);
  }
  this->SecondsPerPixel = perPixel;
  this->RayCastTime = this->PeelRayTime; // the frame's so far
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::vtkInternals::StartPeelFrame(const Peel* peel)
{
  if (!peel)
  {
    this->PeelRayTime = 0.0;
    return;
  }
  if (peel->Stage != vtkTransmittanceShaderSource::PeelInitializing)
  {
    return;
  }
  // A new frame: the last one's stages, summed, are its cost.
  if (this->PeelRayTime > 0.0)
  {
    this->SecondsPerPixel = this->CostPerPixel(this->PeelRayTime);
  }
  this->PeelRayTime = 0.0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::SetMapReducer(vtkTransmittanceMapReducer* reducer)
{
  if (this->Internals->Reducer != reducer)
  {
    this->Internals->Reducer = reducer;
    this->Internals->WarnedDistributedMethod = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkTransmittanceMapReducer* vtkTransmittanceVolumeMapper::GetMapReducer()
{
  return this->Internals->Reducer;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::PrepareDistributedMaps(vtkRenderer* renderer, vtkVolume* volume)
{
  vtkInternals& in = *this->Internals;
  vtkTransmittanceMapReducer* reducer = in.Distributed();
  if (!reducer)
  {
    return true;
  }
  auto* window =
    renderer ? vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) : nullptr;
  if (window)
  {
    window->Initialize(); // before the first render: makes the context
    window->MakeCurrent();
    renderer->UpdateLightsGeometryToFollowCamera();
  }
  if (!in.AgreeWholeBounds(renderer, volume)) // collective
  {
    vtkErrorMacro(<< "The processes could not agree on the medium's box.");
  }
  in.Reducing = true;
  bool built = false;
  if (window && window->IsCurrent() && volume && in.PrepareFrame(this, renderer, volume, window))
  {
    vtkTransmittanceScopedTextures medium = in.BindMedium();
    built = in.UpdateMaps(this) != nullptr;
    in.WarnDistributedLights(this);
  }
  else
  {
    if (!window || !volume)
    {
      vtkErrorMacro(<< "PrepareDistributedMaps() needs a renderer with an OpenGL render window "
                       "and a volume.");
    }
    in.Maps->SkipReduction(reducer, this); // the others still reduce
  }
  in.Reducing = false;
  return built;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLastDetailSamplesPerPixel()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete && !in.Projected ? in.LastCast().GetLastDetailSamples() : 0;
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastCameraStep()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete && !in.Projected ? in.LastCast().GetLastStepLength() : 0.0;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::GetLastDetailStepMeans()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete && !in.Projected && in.LastCast().GetLastDetailStepMeans();
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLastDetailCameraWaves()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete && !in.Projected ? in.LastCast().GetLastDetailCameraWaves() : 0;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetAccumulatedFrames()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete && !in.Projected && in.LastCast().GetLastDetailSamples() > 0
    ? in.LastCast().GetLastHistoryFrames()
    : 0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::ResetAccumulation()
{
  this->Internals->StillKey.clear();
  this->Internals->PathKey.clear();
}

//------------------------------------------------------------------------------
template <typename T>
void vtkTransmittanceVolumeMapper::SetDisplayValue(T& member, T value)
{
  if (member == value)
  {
    return;
  }
  const vtkMTimeType before = this->GetSceneMTime();
  member = value;
  this->Modified();
  this->DisplayMTime = this->GetMTime();
  this->MTimeBeforeDisplay = before;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkTransmittanceVolumeMapper::GetSceneMTime()
{
  const vtkMTimeType now = this->GetMTime();
  return now == this->DisplayMTime ? this->MTimeBeforeDisplay : now;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::SetExposure(double stops)
{
  const double limit = vtkTyndallToneMapping::MaximumExposure;
  this->SetDisplayValue(
    this->Exposure, std::isnan(stops) ? 0.0 : std::min(std::max(stops, -limit), limit));
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::SetToneCurve(int curve)
{
  this->SetDisplayValue(
    this->ToneCurve, std::min(std::max(curve, int(TONE_CURVE_LINEAR)), int(TONE_CURVE_ACES)));
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::SetEncodeSRGB(bool encode)
{
  this->SetDisplayValue(this->EncodeSRGB, encode);
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::SetPathTraceDenoise(bool denoise)
{
  this->SetDisplayValue(this->PathTraceDenoise, denoise);
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLastPathTraceSamples()
{
  return this->Internals->Complete ? this->Internals->PathSamples : 0;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLastImageReduction()
{
  return this->Internals->Complete ? this->Internals->Reduction : 0;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::GetVolumeBricked()
{
  return this->Internals->Textures->GetVolumeTexture() &&
    this->Internals->Textures->GetBricks().IsBricked();
}

//------------------------------------------------------------------------------
vtkIdType vtkTransmittanceVolumeMapper::GetVolumeTextureBytes()
{
  return static_cast<vtkIdType>(this->Internals->Textures->GetVolumeTextureBytes());
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetNumberOfVolumeTextureTiles()
{
  return this->Internals->Textures->GetVolumeTexture()
    ? this->Internals->Textures->GetTiling().GetTiles()
    : 0;
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastStepScale()
{
  return this->Internals->Complete ? this->Internals->StepScale : 0.0;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLastRayCastPassCount()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete ? (in.Projected ? 1 : in.LastCast().GetLastPassCount()) : 0;
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeMapper::GetLastRayCastTime()
{
  return this->Internals->Complete ? this->Internals->RayCastTime : 0.0;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetNumberOfRenderedLights()
{
  const vtkInternals& in = *this->Internals;
  return in.Lit ? static_cast<int>(in.Frame.Lights.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetLightTransmittanceMethod(int light)
{
  const auto& lights = this->Internals->Frame.Lights;
  return light >= 0 && light < this->GetNumberOfRenderedLights() ? lights[light].Method : -1;
}

//------------------------------------------------------------------------------
vtkTransmittanceLightFrustum* vtkTransmittanceVolumeMapper::GetLightFrustum(int light)
{
  const auto& lights = this->Internals->Frame.Lights;
  return light >= 0 && light < this->GetNumberOfRenderedLights() ? lights[light].Frustum.Get()
                                                                 : nullptr;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeMapper::GetTransmittanceMap(int light, vtkImageData* map)
{
  vtkInternals& in = *this->Internals;
  if (!map || !in.Window)
  {
    vtkErrorMacro(<< "GetTransmittanceMap: " << (map ? "nothing was rendered yet." : "null map."));
    return false;
  }
  if (!vtkTransmittanceMapMath::IsMapMethod(this->GetLightTransmittanceMethod(light)))
  {
    vtkErrorMacro(<< "GetTransmittanceMap: light " << light
                  << " has no transmittance map in the last render.");
    return false;
  }
  in.Window->MakeCurrent();
  if (!in.GetUsedMaps()->GetMap(
        light, in.Frame.Layers, in.Frame.BoundsLayer, in.Frame.Integrator.Coefficients, map))
  {
    vtkErrorMacro(<< "GetTransmittanceMap: the maps could not be read back.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TransmittanceMethod: " << this->GetTransmittanceMethodAsString() << "\n";
  os << indent << "NumberOfCoefficients: " << this->NumberOfCoefficients << "\n";
  os << indent << "TransmittanceMapSize: " << this->TransmittanceMapSize << "\n";
  os << indent << "AdaptiveThreshold: " << this->AdaptiveThreshold << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "LightSampleCount: " << this->LightSampleCount << "\n";
  os << indent << "MapReducer: " << this->Internals->Reducer.Get() << "\n";
  os << indent << "Jitter: " << (this->Jitter ? "On" : "Off") << "\n";
  os << indent << "EmptySpaceSkipping: " << (this->EmptySpaceSkipping ? "On" : "Off") << "\n";
  os << indent << "InteractiveAdjustment: " << (this->InteractiveAdjustment ? "On" : "Off") << "\n";
  os << indent << "MaximumImageReduction: " << this->MaximumImageReduction << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "VolumeBricking: " << this->VolumeBricking << "\n";
  os << indent << "DetailSamplesPerPixel: " << this->DetailSamplesPerPixel << "\n";
  os << indent << "PathTracing: " << (this->PathTracing ? "On" : "Off") << "\n";
  os << indent << "PathTraceSamplesPerPixel: " << this->PathTraceSamplesPerPixel << "\n";
  os << indent << "PathTraceSamplesPerFrame: " << this->PathTraceSamplesPerFrame << "\n";
  os << indent << "PathTraceMaximumBounces: " << this->PathTraceMaximumBounces << "\n";
  os << indent << "PathTraceShadows: "
     << (this->PathTraceShadows == PATH_SHADOWS_TRACKED ? "Tracked" : "FromMaps") << "\n";
  os << indent << "PathTraceDistanceSampling: "
     << (this->PathTraceDistanceSampling == PATH_DISTANCE_CLOSED_FORM ? "ClosedForm"
                                                                      : "DeltaTracking")
     << "\n";
  os << indent << "PathTraceSeed: " << this->PathTraceSeed << "\n";
  os << indent << "PathTraceDenoise: " << (this->PathTraceDenoise ? "On" : "Off") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneCurve: " << vtkTyndallToneMapping::GetCurveName(this->ToneCurve) << "\n";
  os << indent << "EncodeSRGB: " << (this->EncodeSRGB ? "On" : "Off") << "\n";
  os << indent << "TransmittanceCache: " << (this->TransmittanceCache ? "On" : "Off") << "\n";
  os << indent << "TransmittanceCacheSize: " << this->TransmittanceCacheSize << "\n";
  os << indent << "TransmittanceCacheBuildCount: " << this->GetTransmittanceCacheBuildCount()
     << "\n";
  os << indent << "PathTraceGuideRenderCount: " << this->GetPathTraceGuideRenderCount() << "\n";
  os << indent << "MapBuildCount: " << this->GetMapBuildCount() << "\n";
  os << indent << "LastMapBuildTime: " << this->GetLastMapBuildTime() << "\n";
}
