#include "vtkVolumeShadowReceiverPass.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkWeakPointer.h"

#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVolumeShadowReceiverPass);
vtkCxxSetObjectMacro(vtkVolumeShadowReceiverPass, DelegatePass, vtkRenderPass);

namespace
{
// Where the per-light factors go in the fragment shader (before VTK's light code).
const char* const kFactorsTag = "//TYNDALL::SurfaceFactors";
// What VTK's polydata shader defines when the fragment has a view position.
const char* const kViewPosition = "vec4 vertexVC = vertexVCVSOutput;";
}

//------------------------------------------------------------------------------
class vtkVolumeShadowReceiverPass::vtkInternals
{
public:
  vtkWeakPointer<vtkVolume> Caster;
  // Valid during Render(): the caster's frame and maps.
  const vtkTransmittanceFrame* Frame = nullptr;
  vtkTextureObject* Maps = nullptr;
  int Slices = 0;
  float ViewToWorld[16];
  // GLSL declarations (after //VTK::Light::Dec), and per switched-on
  // renderer light the Tyndall light whose map shadows it (-1: none).
  std::string Declarations;
  std::vector<int> Lights;
  vtkTimeStamp CodeTime;
  bool WarnedCasters = false;

  /// The renderer's first visible Tyndall volume; `count` of them in all.
  vtkVolume* FindCaster(vtkRenderer* renderer, int& count)
  {
    vtkVolume* first = nullptr;
    count = 0;
    vtkVolumeCollection* volumes = renderer->GetVolumes();
    vtkCollectionSimpleIterator it;
    volumes->InitTraversal(it);
    while (vtkVolume* volume = volumes->GetNextVolume(it))
    {
      if (volume->GetVisibility() &&
        vtkTransmittanceVolumeMapper::SafeDownCast(volume->GetMapper()))
      {
        first = first ? first : volume;
        ++count;
      }
    }
    return first;
  }

  /**
   * The caster's maps hold its medium and its guests (the other volumes its
   * light crosses: vtkParticipatingMediumProperty::SceneShadows): a warning,
   * once, when some of the `count` Tyndall volumes are in neither.
   */
  void WarnCasters(int count, const vtkTransmittanceFrame& frame, vtkObject* self)
  {
    const int missing = count - 1 - static_cast<int>(frame.Guests.size());
    if (missing > 0 && !this->WarnedCasters)
    {
      vtkWarningWithObjectMacro(self, << missing << " of the " << count
                                      << " volumes drawn by vtkTransmittanceVolumeMapper cast no "
                                         "shadow on the surfaces: the first one's maps hold it "
                                         "and the volumes its light crosses (SceneShadows).");
    }
    this->WarnedCasters = missing > 0;
  }

  /// The declarations and the light table for this frame; CodeTime moves when they change.
  void UpdateCode(vtkRenderer* renderer)
  {
    int switchedOn = 0;
    vtkLightCollection* lights = renderer->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      switchedOn += light->GetSwitch() ? 1 : 0;
    }
    std::vector<int> table(switchedOn, -1);
    for (size_t l = 0; l < this->Frame->Lights.size(); ++l)
    {
      const vtkTransmittanceFrame::Light& light = this->Frame->Lights[l];
      const int index = light.Source.RendererIndex;
      if (index >= 0 && index < switchedOn && light.HasFrustum &&
        vtkTransmittanceMapMath::IsMapMethod(light.Method))
      {
        table[index] = static_cast<int>(l);
      }
    }
    const std::string declarations =
      vtkTransmittanceShaderSource::GetSurfaceLookup(this->Frame->GetMapVariant());
    if (declarations != this->Declarations || table != this->Lights)
    {
      this->Declarations = declarations;
      this->Lights = table;
      this->CodeTime.Modified();
    }
  }

  /// The inverse of the camera's view transform, column-major for glUniformMatrix.
  void UpdateViewToWorld(vtkRenderer* renderer)
  {
    auto* camera = vtkOpenGLCamera::SafeDownCast(renderer->GetActiveCamera());
    vtkMatrix4x4 *worldToView, *viewToDisplay, *worldToDisplay;
    vtkMatrix3x3* normals;
    camera->GetKeyMatrices(renderer, worldToView, normals, viewToDisplay, worldToDisplay);
    // VTK keeps the key matrices transposed (OpenGL's order): the inverse of
    // the transposed matrix, read row by row, is the inverse column by column.
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(worldToView, inverse);
    for (int i = 0; i < 16; ++i)
    {
      this->ViewToWorld[i] = static_cast<float>(inverse->GetElement(i / 4, i % 4));
    }
  }

  /// The GLSL that computes each light's factor tyndallT<i> at vertexVC.
  std::string Factors() const
  {
    std::ostringstream os;
    for (size_t i = 0; i < this->Lights.size(); ++i)
    {
      if (this->Lights[i] >= 0)
      {
        os << "  TyndallTransmittance tyndallT" << i << " = tyndallSurfaceTransmittance("
           << this->Lights[i] << ", vertexVC);\n";
      }
      else
      {
        os << "  float tyndallT" << i << " = 1.0;\n";
      }
    }
    return os.str();
  }
};

//------------------------------------------------------------------------------
vtkVolumeShadowReceiverPass::vtkVolumeShadowReceiverPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkVolumeShadowReceiverPass::~vtkVolumeShadowReceiverPass()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
bool vtkVolumeShadowReceiverPass::Install(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro(<< "Install: the renderer is null.");
    return false;
  }
  vtkRenderPass* current = renderer->GetPass();
  vtkRenderStepsPass* steps = vtkRenderStepsPass::SafeDownCast(current);
  if (current && !steps)
  {
    vtkErrorMacro(<< "Install: the renderer already draws with a " << current->GetClassName()
                  << "; set this pass as the delegate of its opaque step instead.");
    return false;
  }
  if (!steps)
  {
    vtkNew<vtkRenderStepsPass> created;
    renderer->SetPass(created);
    steps = created;
  }
  if (steps->GetOpaquePass() != this)
  {
    this->SetDelegatePass(steps->GetOpaquePass());
    steps->SetOpaquePass(this);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkVolume* vtkVolumeShadowReceiverPass::GetLastCaster()
{
  return this->Internals->Caster;
}

//------------------------------------------------------------------------------
void vtkVolumeShadowReceiverPass::Render(const vtkRenderState* s)
{
  vtkInternals& in = *this->Internals;
  this->NumberOfRenderedProps = 0;
  in.Caster = nullptr;
  in.Frame = nullptr;
  in.Maps = nullptr;
  if (!this->DelegatePass)
  {
    vtkErrorMacro(<< "No DelegatePass: the opaque geometry is not drawn.");
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  int casters = 0;
  vtkVolume* caster = in.FindCaster(renderer, casters);
  auto* mapper = caster ? vtkTransmittanceVolumeMapper::SafeDownCast(caster->GetMapper()) : nullptr;
  if (mapper && mapper->UpdateShadowMaps(renderer, caster))
  {
    in.Frame = &mapper->GetShadowFrame(in.Maps, in.Slices);
    in.WarnCasters(casters, *in.Frame, this);
  }
  if (!in.Frame || !in.Maps)
  {
    in.Frame = nullptr;
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  in.Caster = caster;
  in.UpdateCode(renderer);
  in.UpdateViewToWorld(renderer);
  in.Maps->Activate();
  this->PreRender(s);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->PostRender(s);
  in.Maps->Deactivate();
  in.Frame = nullptr;
  in.Maps = nullptr;
}

//------------------------------------------------------------------------------
bool vtkVolumeShadowReceiverPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  const vtkInternals& in = *this->Internals;
  if (!in.Frame)
  {
    return true;
  }
  // Before VTK's light code (which replaces //VTK::Light::Dec without
  // keeping it, and ends its //VTK::Light::Impl with the tag).
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + in.Declarations, false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Impl", std::string(kFactorsTag) + "\n//VTK::Light::Impl", false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeShadowReceiverPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  const vtkInternals& in = *this->Internals;
  if (!in.Frame)
  {
    return true;
  }
  // Lighting off: no view position, no light terms, nothing to shadow.
  const bool lit = fragmentShader.find(kViewPosition) != std::string::npos;
  vtkShaderProgram::Substitute(fragmentShader, kFactorsTag, lit ? in.Factors() : "", false);
  if (!lit)
  {
    return true;
  }
  // VTK 9.1's per-light terms (vtkOpenGLPolyDataMapper::ReplaceShaderLight):
  // Phong for scene lights (complexity 2 and 3) and the headlight
  // (complexity 1), and the PBR radiance.
  for (size_t i = 0; i < in.Lights.size(); ++i)
  {
    const std::string n = std::to_string(i);
    const std::string T = "tyndallT" + n;
    const std::pair<std::string, std::string> terms[] = {
      { "diffuse += (df * lightColor" + n + ");",
        "diffuse += (df * " + T + " * lightColor" + n + ");" },
      { "specular += (sf * lightColor" + n + ");",
        "specular += (sf * " + T + " * lightColor" + n + ");" },
      { "radiance = lightColor" + n + ";", "radiance = " + T + " * lightColor" + n + ";" },
      { "radiance = lightColor" + n + " * attenuation;",
        "radiance = " + T + " * lightColor" + n + " * attenuation;" },
    };
    for (const auto& term : terms)
    {
      vtkShaderProgram::Substitute(fragmentShader, term.first, term.second, true);
    }
  }
  if (!in.Lights.empty())
  {
    vtkShaderProgram::Substitute(fragmentShader, "vec3 diffuse = df * diffuseColor * lightColor0;",
      "vec3 diffuse = df * tyndallT0 * diffuseColor * lightColor0;", false);
    vtkShaderProgram::Substitute(fragmentShader,
      "vec3 specular = sf * specularColor * lightColor0;",
      "vec3 specular = sf * tyndallT0 * specularColor * lightColor0;", false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeShadowReceiverPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  vtkInternals& in = *this->Internals;
  if (!in.Frame || !program->IsUniformUsed("tyndallViewToWorld"))
  {
    return true;
  }
  program->SetUniformMatrix4x4("tyndallViewToWorld", in.ViewToWorld);
  in.Frame->SetLightMapUniforms(program);
  in.Frame->SetMapUniforms(program, in.Maps, in.Slices);
  return true;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkVolumeShadowReceiverPass::GetShaderStageMTime()
{
  return this->Internals->CodeTime.GetMTime();
}

//------------------------------------------------------------------------------
void vtkVolumeShadowReceiverPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkVolumeShadowReceiverPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "LastCaster: " << this->Internals->Caster.GetPointer() << "\n";
}
