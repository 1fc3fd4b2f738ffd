#include "vtkTyndallSceneReader.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderer.h"
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
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneReader::Update(vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter)
{
  if (!renderer || !volume)
  {
    vtkErrorWithObjectMacro(reporter, << (renderer ? "The volume" : "The renderer") << " is null.");
    return false;
  }
  if (!this->Medium.Update(volume, reporter))
  {
    return false;
  }
  auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  if (!this->Detail.Update(this->Medium, property ? property->GetDetailNoise() : nullptr, reporter))
  {
    return false;
  }
  this->UpdateLights(renderer, reporter);
  this->UpdateGuests(renderer, volume, reporter);
  if (!this->Medium.GetSingleScattering())
  {
    this->Lights.clear();
  }
  for (vtkTyndallLight& light : this->Lights)
  {
    for (int c = 0; c < 3; ++c)
    {
      light.Irradiance[c] = this->Medium.GetLightScale() * light.Color[c];
    }
  }
  return true;
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
void vtkTyndallSceneReader::UpdateGuests(
  vtkRenderer* renderer, vtkVolume* volume, vtkObject* reporter)
{
  this->Guests.clear();
  this->GuestVolumes.clear();
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
    if (other == volume || !other->GetVisibility() || !other->GetMapper() ||
      !other->GetMapper()->IsA("vtkTransmittanceVolumeMapper"))
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
    if (g.Volume != other || !g.Medium)
    {
      g.Volume = other;
      g.Medium.reset(new vtkTyndallGridMedium);
    }
    const char* reason = nullptr;
    auto* otherProperty = vtkParticipatingMediumProperty::SafeDownCast(other->GetProperty());
    if (!g.Medium->Update(other, reporter))
    {
      reason = "cannot be read";
    }
    else if (g.Medium->GetNumberOfNaNScalars() > 0)
    {
      reason = "has missing data (NaN)";
    }
    else if (g.Medium->GetClip().Enabled())
    {
      reason = "is clipped or cropped";
    }
    else if (otherProperty && otherProperty->GetDetailNoise())
    {
      reason = "has procedural detail";
    }
    else if (g.Medium->GetChromatic() || this->Medium.GetChromatic())
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
