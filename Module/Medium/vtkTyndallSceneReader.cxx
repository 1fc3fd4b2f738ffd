#include "vtkTyndallSceneReader.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkParticipatingMediumMapper.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderer.h"
#include "vtkTyndallParticleMedium.h"
#include "vtkTyndallSkyLights.h"
#include "vtkTyndallVolumeSettings.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// Where vtkRenderer puts `light` before it renders (see the class description).
void PlaceLight(
  vtkLight* light, vtkCamera* camera, bool follow, double position[3], double focalPoint[3])
{
  if (follow && light->LightTypeIsHeadlight())
  {
    camera->GetPosition(position);
    camera->GetFocalPoint(focalPoint);
  }
  else if (follow && light->LightTypeIsCameraLight())
  {
    vtkMatrix4x4* cameraLight = camera->GetCameraLightTransformMatrix();
    double in[4] = { 0.0, 0.0, 0.0, 1.0 }, out[4];
    light->GetPosition(in);
    cameraLight->MultiplyPoint(in, out);
    std::copy(out, out + 3, position);
    light->GetFocalPoint(in);
    cameraLight->MultiplyPoint(in, out);
    std::copy(out, out + 3, focalPoint);
  }
  else
  {
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focalPoint);
  }
}

// Whether two volumes' mappers light them by the sky alike (SkyLight,
// SkyLightDirections): one of a camera group draws the others with its own.
bool SameSky(vtkVolume* a, vtkVolume* b)
{
  auto* x = vtkParticipatingMediumMapper::SafeDownCast(a->GetMapper());
  auto* y = vtkParticipatingMediumMapper::SafeDownCast(b->GetMapper());
  return x && y && x->GetSkyLight() == y->GetSkyLight() &&
    x->GetSkyLightDirections() == y->GetSkyLightDirections();
}

// Whether a Tyndall volume can be part of a camera group (see the class
// description); `medium` is its medium as read by this reader, or null when
// it is not one of the guests.
bool Groupable(vtkVolume* volume, const vtkTyndallGridMedium* medium)
{
  auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  return medium && property && property->GetSceneShadows() && property->GetSceneCompositing() &&
    !medium->GetProjection().Enabled() && !medium->GetIsosurfaces().Enabled() &&
    !property->GetDetailNoise() && !medium->HasMissingData() && !medium->GetClip() &&
    !medium->GetLabelMap().Enabled() && !medium->GetParameters().GetChromatic() &&
    !medium->GetEmissionFromArray() && !medium->GetComponents().Enabled() &&
    !medium->GetShading().Enabled() && !medium->GetGradientOpacity() && !medium->GetTable().Has2D();
}

// Whether the world boxes of two media overlap (their world-axis bounds, by
// more than a millionth of the smaller diagonal on every axis).
bool Overlap(const vtkTyndallMedium& a, const vtkTyndallMedium& b)
{
  double ca[24], cb[24];
  a.GetWorldCorners(ca);
  b.GetWorldCorners(cb);
  const double margin = 1e-6 * std::min(a.GetWorldDiagonal(), b.GetWorldDiagonal());
  for (int axis = 0; axis < 3; ++axis)
  {
    double lowA = ca[axis], highA = ca[axis], lowB = cb[axis], highB = cb[axis];
    for (int i = 1; i < 8; ++i)
    {
      lowA = std::min(lowA, ca[3 * i + axis]);
      highA = std::max(highA, ca[3 * i + axis]);
      lowB = std::min(lowB, cb[3 * i + axis]);
      highB = std::max(highB, cb[3 * i + axis]);
    }
    if (std::min(highA, highB) - std::max(lowA, lowB) <= margin)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkTyndallSceneReader::vtkTyndallSceneReader()
  : Medium(new vtkTyndallGridMedium)
{
}

//------------------------------------------------------------------------------
vtkTyndallSceneReader::~vtkTyndallSceneReader() = default;

//------------------------------------------------------------------------------
bool vtkTyndallSceneReader::IsTyndallVolume(vtkVolume* volume)
{
  return volume && vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper()) != nullptr;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::MakeMedium(
  vtkVolume* volume, std::unique_ptr<vtkTyndallGridMedium>& medium)
{
  auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper());
  const bool particles = mapper && mapper->DrawsParticles();
  const bool isParticles = dynamic_cast<vtkTyndallParticleMedium*>(medium.get()) != nullptr;
  if (!medium || particles != isParticles)
  {
    medium.reset(particles ? new vtkTyndallParticleMedium : new vtkTyndallGridMedium);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneReader::Update(vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter)
{
  this->Media.clear();
  if (!renderer || !volume)
  {
    vtkErrorWithObjectMacro(reporter, << (renderer ? "The volume" : "The renderer") << " is null.");
    return false;
  }
  if (volume->IsA("vtkMultiVolume"))
  {
    vtkErrorWithObjectMacro(reporter,
      << "A vtkMultiVolume is not drawn by Tyndall: give each volume its own vtkVolume and "
         "Tyndall mapper (their lights share one set of maps).");
    return false;
  }
  MakeMedium(volume, this->Medium);
  if (!this->Medium->Update(volume, reporter))
  {
    return false;
  }
  auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  // Isosurfaces are the grid's (vtkTyndallVolumeSettings names the detail not drawn).
  const bool detail = property && !this->Medium->GetIsosurfaces().Enabled();
  if (!this->Detail.Update(*this->Medium, detail ? property->GetDetailNoise() : nullptr, reporter,
        property ? property->GetDetailFilterWidth() : 0.0))
  {
    return false;
  }
  this->WarnNotDrawn(volume, reporter);
  this->UpdateLights(renderer, reporter);
  // A projection (vtkTyndallProjection) is lit through nothing, and lit by
  // nothing but a shaded slice (vtkTyndallShading: its surface term alone,
  // whatever the scattering model: VTK's slice).
  const bool projection = this->Medium->GetProjection().Enabled();
  this->UpdateGuests(renderer, volume, projection, reporter);
  this->UpdateCameraGroup(renderer, volume, reporter);
  const vtkTyndallMediumParameters& parameters = this->Medium->GetParameters();
  const bool lit =
    projection ? this->Medium->GetShading().Enabled() : parameters.GetSingleScattering();
  if (!lit)
  {
    this->Lights.clear();
  }
  for (vtkTyndallLight& light : this->Lights)
  {
    for (int c = 0; c < 3; ++c)
    {
      light.Irradiance[c] = parameters.LightScale * light.Color[c];
    }
  }
  // The sky (a refused environment is black: the scene renders without it);
  // its tables kept while a volume it does not light is read.
  auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper());
  this->SkyLit = !projection && parameters.GetSingleScattering() && mapper && mapper->GetSkyLight();
  if (this->SkyLit)
  {
    this->Environment.Update(renderer, reporter);
    const int slots = MaximumNumberOfLights - static_cast<int>(this->Lights.size());
    this->UpdateSkyLights(std::min(mapper->GetSkyLightDirections(), slots));
  }
  // The media: this volume's own (its detail when it has one, not in a
  // projection) first.
  this->Media.push_back(this->Detail.Enabled() && !projection
      ? static_cast<const vtkTyndallMedium*>(&this->Detail)
      : this->Medium.get());
  this->Media.insert(this->Media.end(), this->Guests.begin(), this->Guests.end());
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::UpdateSkyLights(int count)
{
  // Cut again only when the sky or the count change (an image's cut reads every texel).
  if (count != this->SkyLightCount || this->Environment.GetSerial() != this->SkyLightSerial)
  {
    this->SkyLights = vtkTyndallSkyLights::Split(this->Environment, count);
    this->SkyLightCount = count;
    this->SkyLightSerial = this->Environment.GetSerial();
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::GetMapAmbient(double ambient[3]) const
{
  this->GetShadingSkyMean(ambient); // the sky's mean where no sky light carries it
  for (int c = 0; c < 3; ++c)
  {
    ambient[c] += this->Medium->GetParameters().AmbientIntensity;
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::GetShadingSkyMean(double mean[3]) const
{
  const double* sky = this->GetEnvironment().GetMeanRadiance();
  const bool meanAsAmbient = this->GetSkyLights().empty();
  for (int c = 0; c < 3; ++c)
  {
    mean[c] = meanAsAmbient ? sky[c] : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::UpdateLights(vtkRenderer* renderer, vtkObject* reporter)
{
  this->Lights.clear();
  vtkCamera* camera = renderer->GetActiveCamera();
  const bool follow = renderer->GetLightFollowCamera() != 0;
  int ignored = 0, degenerate = 0;
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  int switchedOn = 0;
  while (vtkLight* light = lights->GetNextLight(it))
  {
    const int rendererIndex = light->GetSwitch() ? switchedOn++ : -1;
    if (!light->GetSwitch() || !(light->GetIntensity() > 0.0))
    {
      continue;
    }
    if (static_cast<int>(this->Lights.size()) == MaximumNumberOfLights)
    {
      ++ignored;
      continue;
    }
    vtkTyndallLight l;
    l.RendererIndex = rendererIndex;
    double focalPoint[3];
    PlaceLight(light, camera, follow, l.Position, focalPoint);
    for (int c = 0; c < 3; ++c)
    {
      l.Direction[c] = focalPoint[c] - l.Position[c];
      l.Color[c] = light->GetIntensity() * light->GetDiffuseColor()[c];
    }
    l.Positional = light->GetPositional() != 0;
    l.Headlight = light->LightTypeIsHeadlight() != 0;
    l.Spot = l.Positional && light->GetConeAngle() < 90.0;
    const bool directed = !l.Positional || l.Spot;
    if (!(vtkMath::Normalize(l.Direction) > 0.0))
    {
      if (directed)
      {
        ++degenerate;
        continue;
      }
      l.Direction[0] = l.Direction[1] = 0.0; // a point light: unused
      l.Direction[2] = -1.0;
    }
    if (l.Positional)
    {
      light->GetAttenuationValues(l.Attenuation);
    }
    if (l.Spot)
    {
      l.ConeCosine = std::cos(vtkMath::RadiansFromDegrees(light->GetConeAngle()));
      l.Exponent = light->GetExponent();
    }
    this->Lights.push_back(l);
  }

  std::ostringstream warning;
  if (degenerate)
  {
    warning << degenerate
            << " directional or spot light(s) whose position and focal point coincide have no "
               "direction and are ignored. ";
  }
  if (ignored)
  {
    warning << ignored << " light(s) beyond the first " << MaximumNumberOfLights << " are ignored.";
  }
  if (!warning.str().empty() && warning.str() != this->LastLightWarning)
  {
    vtkWarningWithObjectMacro(reporter, << warning.str());
  }
  this->LastLightWarning = warning.str();
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::WarnNotDrawn(vtkVolume* volume, vtkObject* reporter)
{
  const std::string warning =
    vtkTyndallVolumeSettings::Describe(vtkTyndallVolumeSettings::NotDrawn(volume));
  std::string& last = this->LastNotDrawnWarning[volume];
  if (!warning.empty() && warning != last)
  {
    vtkWarningWithObjectMacro(reporter, << warning);
  }
  last = warning;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneReader::IsDrawnVolume(vtkVolume* entry, vtkVolume* volume)
{
  if (entry == volume)
  {
    return true;
  }
  if (!entry || !volume || !entry->GetMapper() || entry->GetMapper() != volume->GetMapper() ||
    entry->GetProperty() != volume->GetProperty())
  {
    return false;
  }
  // The same placement (a level-of-detail prop copies its matrix into the
  // volume it draws): volumes that merely share a mapper are two media.
  vtkMatrix4x4* a = entry->GetMatrix();
  vtkMatrix4x4* b = volume->GetMatrix();
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      const double x = a->GetElement(i, j);
      if (std::abs(x - b->GetElement(i, j)) > 1e-9 * (1.0 + std::abs(x)))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::UpdateGuests(
  vtkRenderer* renderer, vtkVolume* volume, bool projection, vtkObject* reporter)
{
  this->Guests.clear();
  this->GuestVolumes.clear();
  if (projection)
  {
    this->LastGuestWarning.clear();
    return;
  }
  auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  std::ostringstream warning;
  int ignored = 0;
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  int index = -1;
  while (vtkVolume* other =
           (!property || property->GetSceneShadows()) ? volumes->GetNextVolume(it) : nullptr)
  {
    ++index;
    if (IsDrawnVolume(other, volume) || !other->GetVisibility() || !IsTyndallVolume(other))
    {
      continue;
    }
    if (static_cast<int>(this->Guests.size()) == MaximumNumberOfGuests)
    {
      ++ignored;
      continue;
    }
    const size_t slot = this->Guests.size();
    if (this->GuestSlots.size() <= slot)
    {
      this->GuestSlots.resize(slot + 1);
    }
    GuestSlot& g = this->GuestSlots[slot];
    if (g.Volume != other)
    {
      g.Volume = other;
      g.Medium = nullptr;
    }
    MakeMedium(other, g.Medium);
    const char* reason = nullptr;
    auto* otherProperty = vtkParticipatingMediumProperty::SafeDownCast(other->GetProperty());
    if (!g.Medium->Update(other, reporter))
    {
      reason = "cannot be read";
    }
    else if (g.Medium->GetProjection().Enabled())
    {
      continue; // a projection is not a medium: it casts no shadow (documented)
    }
    else if (g.Medium->HasMissingData())
    {
      reason = "has missing data (NaN or a mask)";
    }
    else if (g.Medium->GetLabelMap().Enabled())
    {
      reason = "has a label map";
    }
    else if (g.Medium->GetClip())
    {
      reason = "is clipped or cropped";
    }
    else if (g.Medium->GetGradientOpacity())
    {
      reason = "has gradient opacity";
    }
    else if (g.Medium->GetIsosurfaces().Enabled())
    {
      reason = "is drawn as isosurfaces";
    }
    else if (g.Medium->GetTable().Has2D())
    {
      reason = "has a 2-D transfer function";
    }
    else if (g.Medium->GetComponents().Enabled())
    {
      reason = "has several components";
    }
    else if (otherProperty && otherProperty->GetDetailNoise())
    {
      reason = "has procedural detail";
    }
    else if (g.Medium->GetParameters().GetChromatic() ||
      this->Medium->GetParameters().GetChromatic())
    {
      reason = "is in a scene with a coloured extinction";
    }
    if (reason)
    {
      warning << "Volume " << index << " of the renderer " << reason
              << ": it casts no shadow into the other volumes. ";
      continue;
    }
    this->Guests.push_back(g.Medium.get());
    this->GuestVolumes.push_back(other);
  }
  if (ignored)
  {
    warning << ignored << " volume(s) beyond the first " << MaximumNumberOfGuests
            << " others cast no shadow into this one.";
  }
  if (!warning.str().empty() && warning.str() != this->LastGuestWarning)
  {
    vtkWarningWithObjectMacro(reporter, << warning.str());
  }
  this->LastGuestWarning = warning.str();
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::UpdateCameraGroup(
  vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter)
{
  this->CameraGuests.clear();
  this->DrawnBy = nullptr;
  // The candidates: the first MaximumNumberOfGuests + 1 visible Tyndall
  // volumes in the renderer's order, each with its medium (this one's, a
  // guest's, or null for a volume that is not a guest).
  std::vector<vtkVolume*> volumes;
  std::vector<const vtkTyndallGridMedium*> read, media;
  vtkVolumeCollection* collection = renderer->GetVolumes();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkVolume* entry = static_cast<int>(volumes.size()) <= MaximumNumberOfGuests
      ? collection->GetNextVolume(it)
      : nullptr)
  {
    vtkVolume* v = IsDrawnVolume(entry, volume) ? volume : entry;
    if (!v->GetVisibility() || !IsTyndallVolume(v))
    {
      continue;
    }
    const auto guest = std::find(this->GuestVolumes.begin(), this->GuestVolumes.end(), v);
    const vtkTyndallGridMedium* medium = v == volume ? this->Medium.get()
      : guest != this->GuestVolumes.end() ? this->Guests[guest - this->GuestVolumes.begin()]
                                          : nullptr;
    volumes.push_back(v);
    read.push_back(medium);
    // A volume VTK's culler left out of this frame (render time multiplier
    // 0: its bounding sphere lies outside the view, so no camera ray meets
    // it) draws nothing and is drawn by no one: not grouped.
    media.push_back(Groupable(v, medium) && v->GetRenderTimeMultiplier() > 0.0 ? medium : nullptr);
  }
  const auto self = std::find(volumes.begin(), volumes.end(), volume);
  if (self == volumes.end())
  {
    return;
  }
  // Groups: connected components of "overlap and are lit alike" (an
  // equivalence, so every reader finds the same), labelled by their first
  // member.
  const size_t n = volumes.size();
  std::vector<size_t> group(n);
  for (size_t i = 0; i < n; ++i)
  {
    group[i] = i;
  }
  for (bool changed = true; changed;)
  {
    changed = false;
    for (size_t i = 0; i < n; ++i)
    {
      for (size_t j = i + 1; j < n; ++j)
      {
        if (media[i] && media[j] && group[i] != group[j] &&
          media[i]->GetParameters().SameLighting(media[j]->GetParameters()) &&
          SameSky(volumes[i], volumes[j]) && Overlap(*media[i], *media[j]))
        {
          group[i] = group[j] = std::min(group[i], group[j]);
          changed = true;
        }
      }
    }
  }
  const size_t me = self - volumes.begin();
  this->WarnLayers(volumes, read, group, me, reporter);
  if (!media[me])
  {
    return;
  }
  if (group[me] != me)
  {
    this->DrawnBy = volumes[group[me]];
    return;
  }
  for (size_t j = me + 1; j < n; ++j)
  {
    if (group[j] == me)
    {
      const auto guest =
        std::find(this->GuestVolumes.begin(), this->GuestVolumes.end(), volumes[j]);
      this->CameraGuests.push_back(static_cast<int>(guest - this->GuestVolumes.begin()));
    }
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneReader::WarnLayers(const std::vector<vtkVolume*>& volumes,
  const std::vector<const vtkTyndallGridMedium*>& media, const std::vector<size_t>& group,
  size_t me, vtkObject* reporter)
{
  std::ostringstream warning;
  auto compositing = [](vtkVolume* v)
  {
    auto* p = vtkParticipatingMediumProperty::SafeDownCast(v->GetProperty());
    return p && p->GetSceneShadows() && p->GetSceneCompositing() &&
      v->GetRenderTimeMultiplier() > 0.0; // culled: no group to miss
  };
  for (size_t j = 0; j < volumes.size(); ++j)
  {
    if (j != me && group[j] != group[me] && media[me] && media[j] && compositing(volumes[me]) &&
      compositing(volumes[j]) && Overlap(*media[me], *media[j]))
    {
      warning << "This volume's box overlaps that of Tyndall volume " << j
              << " (counting the renderer's visible Tyndall volumes from 0), but they cannot be "
                 "drawn as one medium (different lighting "
                 "settings, or missing data, clipping, cropping, detail, a coloured extinction, "
                 "an emission array, several components or Shade): each is drawn as a layer, "
                 "wrong "
                 "where they "
                 "interpenetrate along a camera ray. ";
    }
  }
  if (!warning.str().empty() && warning.str() != this->LastCameraWarning)
  {
    vtkWarningWithObjectMacro(reporter, << warning.str());
  }
  this->LastCameraWarning = warning.str();
}
