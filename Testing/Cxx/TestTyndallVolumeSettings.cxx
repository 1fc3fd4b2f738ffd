// The settings Tyndall draws otherwise than VTK 9.1's volume mappers
// (vtkTyndallVolumeSettings, issue 36): an application that swaps
// vtkGPUVolumeRayCastMapper for a Tyndall mapper gets a warning naming each,
// never a silently different picture. Read through vtkTyndallSceneReader,
// which both renderers use (no OpenGL):
//
// 0. VTK's projection blend modes (vtkTyndallProjection) and its
//    isosurface mode (vtkTyndallIsosurfaces) are drawn: not named, nor the
//    slice mode with a vtkPlane, nor its shading and gradient opacity (of one
//    component, as VTK draws them); without a plane it is, and procedural
//    detail in a projection, gradient shading in the slice of several
//    components (VTK shades no other projection), gradient opacity in the
//    maximum or minimum intensity or the isosurface mode (VTK ignores it in
//    the others);
// 1. a plain vtkVolumeProperty at VTK's defaults (composite, shade off, no
//    gradient opacity, TF_1D, nearest) gives no warning, nor linear, nor does a
//    vtkParticipatingMediumProperty with Shade on and nearest interpolation (Tyndall's meaning);
// 2. each setting alone: one warning that names it, not repeated while the
//    setting stays, none once it is back to its default;
// 3. gradient opacity is drawn (read) in composite, named in a projection;
//    a function of 1 everywhere, or disabled: not read, no warning;
// 4. two settings at once: one warning naming both; a change of the set
//    warns again;
// 5. one mapper drawing two volumes of different settings: each said once,
//    not every frame; a vtkMultiVolume: an error;
// 6. several components in the projections are drawn; where VTK 9.1 draws
//    otherwise than it means (the minimum of independent components, the
//    maximum or minimum of 2 dependent ones), named.
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContourValues.h"
#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMultiVolume.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTestErrorObserver.h"
#include "vtkTyndallSceneReader.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

// Collects the warnings of the object it observes.
class WarningLog : public vtkCommand
{
public:
  static WarningLog* New() { return new WarningLog; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Messages.emplace_back(data ? static_cast<const char*>(data) : "");
  }
  std::vector<std::string> Messages;
};

struct Scene
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkSmartVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Reporter; // any vtkObject: where the warnings go
  vtkNew<WarningLog> Log;
  vtkTyndallSceneReader Reader;

  explicit Scene(vtkVolumeProperty* property)
  {
    this->Image->SetDimensions(6, 6, 6);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(this->Image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetValue(i, static_cast<float>(i % 7));
    }
    this->Image->GetPointData()->SetScalars(values);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(6.0, 0.5);
    property->SetScalarOpacity(opacity);
    this->Mapper->SetInputData(this->Image);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Reporter->AddObserver(vtkCommand::WarningEvent, this->Log);
  }

  // Reads the scene; the warnings it gave that mention `what` (all: "").
  int Read(const std::string& what = "")
  {
    this->Log->Messages.clear();
    const bool read = this->Reader.Update(this->Renderer, this->Volume, this->Reporter);
    Check(read, "the scene is read");
    int count = 0;
    for (const std::string& m : this->Log->Messages)
    {
      count += m.find(what) != std::string::npos ? 1 : 0;
    }
    return count;
  }
};

// One setting: warned once while it holds, named, and not after `reset`.
void CheckSetting(Scene& scene, const std::string& name, const std::function<void()>& set,
  const std::function<void()>& reset)
{
  set();
  const int first = scene.Read(name);
  const std::string said = scene.Log->Messages.empty() ? "" : scene.Log->Messages.front();
  const int again = scene.Read();
  reset();
  const int after = scene.Read();
  std::cout << name << ": " << said << "\n";
  Check(first == 1 && said.find("otherwise than VTK 9.1's volume mappers") != std::string::npos,
    name + ": one warning names it");
  Check(again == 0, name + ": not repeated while it holds");
  Check(after == 0, name + ": none once it is back to its default");
}
}

int TestTyndallVolumeSettings(int, char*[])
{
  vtkNew<vtkVolumeProperty> plain;
  Scene scene(plain);
  // vtkVolumeProperty's default interpolation, nearest, is drawn.
  Check(scene.Read() == 0, "composite, shade off, no gradient opacity, TF_1D, nearest: no warning");
  plain->SetInterpolationTypeToLinear();
  Check(scene.Read() == 0, "composite, shade off, no gradient opacity, TF_1D, linear: no warning");

  vtkSmartVolumeMapper* mapper = scene.Mapper;
  // The projections (vtkTyndallProjection) and isosurfaces
  // (vtkTyndallIsosurfaces) are drawn: nothing said.
  for (int mode : { vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND,
         vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, vtkVolumeMapper::AVERAGE_INTENSITY_BLEND,
         vtkVolumeMapper::ADDITIVE_BLEND, vtkVolumeMapper::ISOSURFACE_BLEND })
  {
    mapper->SetBlendMode(mode);
    Check(scene.Read() == 0, "a projection or the isosurface blend mode is drawn: no warning");
  }
  CheckSetting(
    scene, "slice blend mode", [&] { mapper->SetBlendModeToSlice(); },
    [&] { mapper->SetBlendModeToComposite(); });
  // With a vtkPlane as its slice function the slice is drawn (vtkTyndallProjection).
  vtkNew<vtkPlane> slicePlane;
  plain->SetSliceFunction(slicePlane);
  mapper->SetBlendModeToSlice();
  Check(scene.Read() == 0 &&
      scene.Reader.GetMedium().GetProjection().GetMode() == vtkTyndallProjection::SLICE,
    "the slice blend mode with a vtkPlane: drawn, no warning");
  plain->SetSliceFunction(nullptr);
  mapper->SetBlendModeToComposite();
  // Shading in a projection: VTK 9.1 shades the slice alone (its
  // maximum, minimum, average and additive are unshaded, as Tyndall's).
  plain->ShadeOn();
  for (int mode :
    { vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, vtkVolumeMapper::MINIMUM_INTENSITY_BLEND,
      vtkVolumeMapper::AVERAGE_INTENSITY_BLEND, vtkVolumeMapper::ADDITIVE_BLEND })
  {
    mapper->SetBlendMode(mode);
    Check(
      scene.Read() == 0, "gradient shading in a projection but the slice: as VTK's, no warning");
  }
  plain->ShadeOff();
  // The slice of one component is shaded, and its alpha multiplied by the
  // gradient opacity, as VTK 9.1 does (vtkTyndallVolumeSettings::SliceReadsGradient()).
  plain->SetSliceFunction(slicePlane);
  mapper->SetBlendModeToSlice();
  plain->ShadeOn();
  vtkNew<vtkLight> light; // (the renderer makes its headlight when it renders)
  scene.Renderer->AddLight(light);
  Check(scene.Read() == 0 && scene.Reader.GetMedium().GetShading().Enabled() &&
      !scene.Reader.GetLights().empty(),
    "gradient shading in the slice: drawn (shaded, lit), no warning");
  plain->ShadeOff();
  Check(scene.Read() == 0 && !scene.Reader.GetMedium().GetShading().Enabled() &&
      scene.Reader.GetLights().empty(),
    "the slice unshaded: not shaded, not lit");
  scene.Renderer->RemoveLight(light);
  mapper->SetBlendModeToComposite();
  // Shading in the composite blend mode is drawn (vtkTyndallShading).
  plain->ShadeOn();
  Check(scene.Read() == 0, "gradient shading in composite: drawn, no warning");
  plain->ShadeOff();
  vtkNew<vtkPiecewiseFunction> gradient;
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(10.0, 1.0);
  // Gradient opacity is drawn (vtkTyndallGridMedium), but in a projection.
  plain->SetGradientOpacity(gradient);
  Check(scene.Read() == 0, "gradient opacity in composite: drawn, no warning");
  Check(scene.Reader.GetMedium().GetGradientOpacity(), "gradient opacity in composite: read");
  // VTK 9.1 ignores it in the average intensity and additive modes too.
  for (int mode : { vtkVolumeMapper::AVERAGE_INTENSITY_BLEND, vtkVolumeMapper::ADDITIVE_BLEND })
  {
    mapper->SetBlendMode(mode);
    Check(scene.Read() == 0, "gradient opacity in the average or additive mode: no warning");
  }
  mapper->SetBlendModeToSlice();
  Check(scene.Read() == 0 && scene.Reader.GetMedium().GetGradientOpacity(),
    "gradient opacity in the slice: read, no warning");
  mapper->SetBlendModeToMaximumIntensity();
  CheckSetting(
    scene, "gradient opacity in the maximum intensity blend mode", [] {},
    [&] { plain->DisableGradientOpacityOn(); });
  plain->DisableGradientOpacityOff();
  Check(scene.Read() == 1, "gradient opacity in a projection enabled again: warned again");
  plain->DisableGradientOpacityOn();
  Check(scene.Read() == 0 && !scene.Reader.GetMedium().GetGradientOpacity(),
    "gradient opacity disabled: no warning, not read");
  // Nor is it read for isosurfaces.
  mapper->SetBlendModeToIsoSurface();
  CheckSetting(
    scene, "gradient opacity in the isosurface blend mode",
    [&] { plain->DisableGradientOpacityOff(); }, [&] { plain->DisableGradientOpacityOn(); });
  mapper->SetBlendModeToComposite();
  plain->DisableGradientOpacityOff();
  Check(scene.Read() == 0 && scene.Reader.GetMedium().GetGradientOpacity(),
    "gradient opacity back in composite: read");
  plain->DisableGradientOpacityOn();
  gradient->RemoveAllPoints();
  gradient->AddPoint(0.0, 1.0);
  gradient->AddPoint(10.0, 1.0);
  plain->DisableGradientOpacityOff();
  Check(scene.Read() == 0 && !scene.Reader.GetMedium().GetGradientOpacity(),
    "a gradient opacity of 1 everywhere changes nothing: no warning, not read");
  // 2-D transfer functions are drawn (vtkTyndallTransferTable::Has2D()), but
  // in a projection or for isosurfaces.
  vtkNew<vtkImageData> transfer2D;
  transfer2D->SetDimensions(4, 3, 1);
  transfer2D->AllocateScalars(VTK_FLOAT, 4);
  auto* tf = static_cast<float*>(transfer2D->GetScalarPointer());
  std::fill(tf, tf + 4 * 4 * 3, 0.5f);
  plain->SetTransferFunction2D(transfer2D);
  plain->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  Check(scene.Read() == 0 && scene.Reader.GetMedium().GetTable().Has2D(),
    "2-D transfer functions in composite: drawn, no warning");
  plain->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  Check(scene.Read() == 0 && !scene.Reader.GetMedium().GetTable().Has2D(),
    "back to TF_1D: the 2-D function dropped");
  mapper->SetBlendModeToMaximumIntensity();
  CheckSetting(
    scene, "2-D transfer functions in the maximum intensity blend mode",
    [&] { plain->SetTransferFunctionMode(vtkVolumeProperty::TF_2D); },
    [&] { plain->SetTransferFunctionMode(vtkVolumeProperty::TF_1D); });
  mapper->SetBlendModeToComposite();
  // Depth peeling for volumes is drawn (vtkTransmittancePeelingPass;
  // TestTransmittanceMapperDepthPeeling): NotDrawn() does not read the
  // renderer.

  // Two at once: one warning naming both (the slice's shading with a 2-D
  // function); a change of the set warns again.
  mapper->SetBlendModeToSlice();
  plain->ShadeOn();
  plain->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  Check(scene.Read("gradient shading") == 1 &&
      scene.Log->Messages.front().find("2-D transfer functions") != std::string::npos &&
      scene.Log->Messages.size() == 1,
    "two settings: one warning naming both");
  plain->ShadeOff();
  Check(scene.Read("2-D transfer functions") == 1 &&
      scene.Log->Messages.front().find("gradient shading") == std::string::npos,
    "one of them back to its default: warned again, naming the other");
  plain->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  plain->SetSliceFunction(nullptr);
  // Shading in the slice without a plane (drawn as composite) and isosurface
  // blend modes is drawn.
  mapper->SetBlendModeToSlice();
  plain->ShadeOn();
  Check(scene.Read("gradient shading") == 0, "gradient shading in the slice mode: drawn");
  mapper->SetBlendModeToIsoSurface();
  Check(scene.Read("gradient shading") == 0, "gradient shading in the isosurface mode: drawn");
  plain->ShadeOff();
  mapper->SetBlendModeToComposite();

  // One mapper drawing two volumes whose settings differ: each is said
  // once, not every frame.
  vtkNew<vtkVolume> other;
  other->SetMapper(mapper);
  vtkNew<vtkVolumeProperty> otherProperty; // (its gradient opacity is what is said)
  otherProperty->DeepCopy(plain);
  vtkNew<vtkPiecewiseFunction> ramp;
  ramp->AddPoint(0.0, 0.0);
  ramp->AddPoint(10.0, 1.0);
  otherProperty->SetGradientOpacity(ramp);
  otherProperty->DisableGradientOpacityOff();
  other->SetProperty(otherProperty);
  scene.Renderer->AddVolume(other);
  mapper->SetBlendModeToMaximumIntensity();
  int said = 0;
  for (int frame = 0; frame < 3; ++frame)
  {
    said += scene.Read();
    scene.Log->Messages.clear();
    Check(scene.Reader.Update(scene.Renderer, other, scene.Reporter), "the other volume is read");
    said += static_cast<int>(scene.Log->Messages.size());
  }
  Check(said == 1, "two volumes of one mapper: the other's setting said once over three frames");
  scene.Renderer->RemoveVolume(other);
  mapper->SetBlendModeToComposite();

  // A vtkMultiVolume: an error, nothing read.
  vtkNew<vtkMultiVolume> multi;
  multi->SetMapper(mapper);
  vtkNew<vtkTest::ErrorObserver> errors;
  scene.Reporter->AddObserver(vtkCommand::ErrorEvent, errors);
  Check(!scene.Reader.Update(scene.Renderer, multi, scene.Reporter) && errors->GetError() &&
      errors->GetErrorMessage().find("vtkMultiVolume") != std::string::npos,
    "a vtkMultiVolume: an error that names it");

  // Tyndall's own property: its Shade is documented (a surface term added to its
  // scattering), its interpolation as ignored: neither is named. Its
  // classification (2-D functions, gradient opacity) is VTK's.
  vtkNew<vtkParticipatingMediumProperty> medium;
  medium->ShadeOn();
  medium->SetInterpolationTypeToNearest();
  Scene tyndall(medium);
  Check(tyndall.Read() == 0,
    "a vtkParticipatingMediumProperty with Shade on and nearest interpolation: no warning");
  tyndall.Mapper->SetBlendModeToSlice();
  Check(tyndall.Read("slice blend mode") == 1,
    "a vtkParticipatingMediumProperty: a blend mode is named");
  // Procedural detail is not projected: named.
  vtkNew<vtkCosineNoise> detail;
  medium->SetDetailNoise(detail);
  tyndall.Mapper->SetBlendModeToMinimumIntensity();
  Check(tyndall.Read("procedural detail in the minimum intensity blend mode") == 1,
    "procedural detail in a projection: named");
  tyndall.Mapper->SetBlendModeToIsoSurface();
  Check(tyndall.Read("procedural detail in the isosurface blend mode") == 1 &&
      !tyndall.Reader.GetDetail().Enabled(),
    "procedural detail with isosurfaces: named, not read");
  tyndall.Mapper->SetBlendModeToComposite();
  Check(tyndall.Read() == 0, "procedural detail in composite: no warning");
  // Its classification is VTK's (ParaView's 2-D transfer functions): a 2-D
  // function and gradient opacity are read, but with procedural detail,
  // which multiplies the 1-D extinction: named there, not read.
  medium->SetTransferFunction2D(transfer2D);
  CheckSetting(
    tyndall, "a 2-D transfer function or gradient opacity with procedural detail",
    [&] { medium->SetTransferFunctionMode(vtkVolumeProperty::TF_2D); },
    [&] { medium->SetTransferFunctionMode(vtkVolumeProperty::TF_1D); });
  medium->SetDetailNoise(nullptr);
  medium->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  Check(tyndall.Read() == 0 && tyndall.Reader.GetMedium().GetTable().Has2D(),
    "a vtkParticipatingMediumProperty's 2-D transfer function: read, no warning");
  vtkNew<vtkColorTransferFunction> glow;
  glow->AddRGBPoint(0.0, 1.0, 0.5, 0.2);
  medium->SetEmissionColor(glow);
  CheckSetting(
    tyndall, "emission with a 2-D transfer function", [&] { medium->SetEmissionScale(2.0); },
    [&] { medium->SetEmissionScale(0.0); });
  medium->SetEmissionColor(nullptr);
  tyndall.Mapper->SetBlendModeToMaximumIntensity();
  Check(tyndall.Read("2-D transfer functions in the maximum intensity") == 1,
    "a vtkParticipatingMediumProperty's 2-D transfer function in a projection: named");
  tyndall.Mapper->SetBlendModeToComposite();
  medium->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  gradient->RemoveAllPoints();
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(10.0, 1.0);
  medium->SetGradientOpacity(gradient);
  Check(tyndall.Read() == 0 && tyndall.Reader.GetMedium().GetGradientOpacity(),
    "a vtkParticipatingMediumProperty's gradient opacity: read, no warning");
  medium->SetDetailNoise(detail);
  Check(
    tyndall.Read("with procedural detail") == 1 && !tyndall.Reader.GetMedium().GetGradientOpacity(),
    "gradient opacity with procedural detail: named, not read");

  // 6. Several components in a projection are drawn (vtkTyndallProjection);
  // where VTK 9.1's shader draws other than it means, named.
  vtkNew<vtkVolumeProperty> componentProperty;
  Scene components(componentProperty);
  for (const int count : { 3, 2 })
  {
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfComponents(count);
    values->SetNumberOfTuples(components.Image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < count; ++c)
      {
        values->SetComponent(i, c, static_cast<float>((i + c) % 7));
      }
    }
    components.Image->GetPointData()->SetScalars(values);
    componentProperty->SetIndependentComponents(count == 3);
    const std::string named = count == 3 ? "minimum intensity of independent components"
                                         : "maximum intensity of 2 dependent components";
    const auto mode = [&](int blend) { components.Mapper->SetBlendMode(blend); };
    CheckSetting(
      components, named,
      [&]()
      {
        mode(count == 3 ? vtkVolumeMapper::MINIMUM_INTENSITY_BLEND
                        : vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);
      },
      [&]() { mode(vtkVolumeMapper::AVERAGE_INTENSITY_BLEND); });
    Check(
      components.Read() == 0 && components.Reader.GetMedium().GetComponents().GetCount() == count,
      std::to_string(count) + " components in the average intensity: drawn, no warning");
    if (count == 3)
    {
      // Gradient opacity: ignored by VTK 9.1 too in the average intensity
      // (no warning); in the maximum named once.
      vtkNew<vtkPiecewiseFunction> fade;
      fade->AddPoint(0.0, 0.0);
      fade->AddPoint(10.0, 1.0);
      componentProperty->SetGradientOpacity(0, fade);
      Check(components.Read("gradient opacity") == 0,
        "gradient opacity of components in the average intensity: as VTK's, no warning");
      mode(vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);
      components.Read();
      const std::string said =
        components.Log->Messages.empty() ? "" : components.Log->Messages.front();
      Check(said.find("gradient opacity") != std::string::npos &&
          said.find("gradient opacity") == said.rfind("gradient opacity"),
        "gradient opacity of components in the maximum intensity: named once (" + said + ")");
      // Their isosurfaces are component 0's (vtkTyndallGridMedium): its
      // gradient opacity named once, as the isosurfaces'.
      componentProperty->GetIsoSurfaceValues()->SetValue(0, 3.0);
      mode(vtkVolumeMapper::ISOSURFACE_BLEND);
      components.Read();
      const std::string iso =
        components.Log->Messages.empty() ? "" : components.Log->Messages.front();
      Check(iso.find("gradient opacity in the isosurface blend mode") != std::string::npos &&
          iso.find("gradient opacity") == iso.rfind("gradient opacity"),
        "gradient opacity of components in the isosurface mode: named once (" + iso + ")");
      componentProperty->GetIsoSurfaceValues()->SetNumberOfContours(0);
      componentProperty->DisableGradientOpacityOn(0);
      mode(vtkVolumeMapper::AVERAGE_INTENSITY_BLEND);
    }
    if (count == 2)
    {
      CheckSetting(
        components, "minimum intensity of 2 dependent components",
        [&]() { mode(vtkVolumeMapper::MINIMUM_INTENSITY_BLEND); },
        [&]() { mode(vtkVolumeMapper::ADDITIVE_BLEND); });
      // The slice of several components is drawn unshaded: named.
      vtkNew<vtkPlane> plane;
      componentProperty->SetSliceFunction(plane);
      mode(vtkVolumeMapper::SLICE_BLEND);
      CheckSetting(
        components, "gradient shading in the slice blend mode",
        [&]() { componentProperty->ShadeOn(); }, [&]() { componentProperty->ShadeOff(); });
      componentProperty->ShadeOn();
      components.Read();
      Check(!components.Reader.GetMedium().GetShading().Enabled(),
        "the slice of 2 components: not shaded");
      componentProperty->ShadeOff();
      componentProperty->SetSliceFunction(nullptr);
    }
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
