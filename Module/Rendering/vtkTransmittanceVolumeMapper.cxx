#include "vtkTransmittanceVolumeMapper.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceDepthPass.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceMapPass.h"
#include "vtkTransmittanceMediumTextures.h"
#include "vtkTransmittanceOcclusionPass.h"
#include "vtkTransmittanceRayCastPass.h"
#include "vtkTransmittanceScopedTextures.h"
#include "vtkTyndallSceneReader.h"
#include "vtkWeakPointer.h"

vtkStandardNewMacro(vtkTransmittanceVolumeMapper);

//------------------------------------------------------------------------------
class vtkTransmittanceVolumeMapper::vtkInternals
{
public:
  vtkTyndallSceneReader Scene;
  vtkTransmittanceFrame Frame;
  vtkNew<vtkTransmittanceMediumTextures> Textures;
  vtkNew<vtkTransmittanceOcclusionPass> Occlusion;
  vtkNew<vtkTransmittanceMapPass> Maps;
  vtkNew<vtkTransmittanceDepthPass> Depth;
  vtkNew<vtkTransmittanceRayCastPass> RayCast;
  // The window the resources live in (weak: it may go before the mapper).
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  // Whether the last Render() went through every pass: the lights, methods,
  // frusta and maps it reports describe that render, or nothing.
  bool Complete = false;
};

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
  in.Textures->ReleaseGraphicsResources(window);
  in.Occlusion->ReleaseGraphicsResources(window);
  in.Maps->ReleaseGraphicsResources(window);
  in.Depth->ReleaseGraphicsResources(window);
  in.RayCast->ReleaseGraphicsResources(window);
  in.Window = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
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
  in.Complete = false;
  if (in.Window && in.Window != window)
  {
    // Released in their own context, then back to this one.
    in.Window->MakeCurrent();
    this->ReleaseGraphicsResources(in.Window);
    window->MakeCurrent();
  }
  in.Window = window;
  if (!in.Scene.Update(renderer, volume, this) ||
    !in.Textures->Update(window, in.Scene.GetMedium(), this))
  {
    return;
  }
  vtkTransmittanceFrame::Settings settings;
  settings.Method = this->TransmittanceMethod;
  settings.Coefficients = this->NumberOfCoefficients;
  settings.MapSize = this->TransmittanceMapSize;
  settings.LightSampleCount = this->LightSampleCount;
  settings.AdaptiveThreshold = this->AdaptiveThreshold;
  settings.SampleDistance = this->SampleDistance;
  settings.Jitter = this->Jitter;
  settings.SkipEmptySpace = this->EmptySpaceSkipping;
  in.Frame.Prepare(renderer, window, in.Scene, *in.Textures, settings);

  vtkTransmittanceScopedTextures medium(
    { in.Textures->GetVolumeTexture(), in.Textures->GetValidityTexture(),
      in.Textures->GetTransferTexture(), in.Textures->GetBlockTexture() });
  vtkTransmittanceRayCastPass::Inputs inputs;
  if (in.Occlusion->Render(in.Frame, this))
  {
    inputs.Occlusion = in.Occlusion->GetTexture();
    inputs.OcclusionSlices = in.Occlusion->GetSlices();
  }
  if (!in.Maps->Render(in.Frame, this) || !in.Depth->Render(in.Frame, this))
  {
    return;
  }
  inputs.Depth = in.Depth->GetTexture();
  if (in.Frame.NeedsMaps())
  {
    inputs.Maps = in.Maps->GetTexture();
    inputs.MapSlices = in.Maps->GetSlices();
  }
  in.Complete = in.RayCast->Render(in.Frame, inputs, this);
}

//------------------------------------------------------------------------------
int vtkTransmittanceVolumeMapper::GetNumberOfRenderedLights()
{
  const vtkInternals& in = *this->Internals;
  return in.Complete ? static_cast<int>(in.Frame.Lights.size()) : 0;
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
  if (!in.Maps->GetMap(
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
  os << indent << "Jitter: " << (this->Jitter ? "On" : "Off") << "\n";
  os << indent << "EmptySpaceSkipping: " << (this->EmptySpaceSkipping ? "On" : "Off") << "\n";
  os << indent << "MapBuildCount: " << this->GetMapBuildCount() << "\n";
  os << indent << "LastMapBuildTime: " << this->GetLastMapBuildTime() << "\n";
}
