// Bad input to vtkTransmittanceVolumeMapper: each case reports a clear error
// (or a documented warning) through VTK's error mechanism and leaves the
// rest of the render intact: an opaque actor beside the volume is still
// drawn, and a valid volume renders again afterwards.
#include "vtkActor.h"
#include "vtkContourValues.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestCheck.h"
#include "TyndallTestScene.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
using tyndall_test::Check;

// Number of pixels that differ from the background colour.
int CountForeground(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  auto* pixels = static_cast<unsigned char*>(image->GetScalarPointer());
  const int n = image->GetNumberOfPoints();
  const int c = image->GetNumberOfScalarComponents();
  int count = 0;
  for (int i = 0; i < n; ++i)
  {
    count += (pixels[c * i] != 0 || pixels[c * i + 1] != 0 || pixels[c * i + 2] != 0) ? 1 : 0;
  }
  return count;
}

vtkSmartPointer<vtkImageData> MakeImage(int nx, int ny, int nz, int components, double fill)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(0.1, 0.1, 0.1);
  image->SetOrigin(-0.5, -0.5, -0.5);
  if (components > 0)
  {
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfComponents(components);
    values->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny * nz);
    values->Fill(fill);
    image->GetPointData()->SetScalars(values);
  }
  return image;
}
}

int TestTransmittanceMapperBadInput(int, char*[])
{
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> observer;
  mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  mapper->AddObserver(vtkCommand::WarningEvent, observer);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tyndall_test::MakeCloudProperty());

  // An opaque sphere beside the volume, which must always be drawn.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-3.0, 0.0, 0.0);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->AddActor(actor);
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  renderer->GetActiveCamera()->SetPosition(-1.5, 0.0, 8.0);
  renderer->GetActiveCamera()->SetFocalPoint(-1.5, 0.0, 0.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(120, 80);
  window->AddRenderer(renderer);

  // Only the sphere: the reference count of foreground pixels.
  volume->VisibilityOff();
  window->Render();
  const int sphereOnly = CountForeground(window);
  volume->VisibilityOn();
  Check(sphereOnly > 100, "the sphere is visible");

  auto expectError =
    [&](vtkImageData* input, const std::string& text, const std::string& what, bool warning = false)
  {
    observer->Clear();
    mapper->SetInputData(input);
    window->Render();
    const bool got = warning ? observer->GetWarning() : observer->GetError();
    const std::string message =
      warning ? observer->GetWarningMessage() : observer->GetErrorMessage();
    if (!got || message.find(text) == std::string::npos)
    {
      std::cerr << what << ": expected a message containing '" << text << "', got '" << message
                << "'" << std::endl;
    }
    Check(got && message.find(text) != std::string::npos, what);
    Check(CountForeground(window) >= sphereOnly, what + ": the rest of the render is intact");
  };

  expectError(MakeImage(8, 8, 8, 0, 0.0), "no scalars", "no scalars");
  expectError(MakeImage(8, 8, 8, 5, 1.0), "5 components; 1 to 4", "five-component scalars");
  {
    // Three components are drawn independent (VTK's default), not dependent.
    volume->GetProperty()->IndependentComponentsOff();
    expectError(MakeImage(8, 8, 8, 3, 1.0), "3 dependent components", "three dependent components");
    volume->GetProperty()->IndependentComponentsOn();
    auto image = MakeImage(8, 8, 8, 2, 1.0);
    auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetComponent(i, 1, std::numeric_limits<float>::quiet_NaN());
    }
    expectError(image, "no finite value in component 1", "a component of NaN only");
    // Several components in the blend mode they are not drawn in (the
    // projections draw them: vtkTyndallProjection; the isosurfaces of
    // independent ones whose first has the largest weight are that one's).
    mapper->SetBlendModeToIsoSurface();
    volume->GetProperty()->GetIsoSurfaceValues()->SetValue(0, 0.5);
    volume->GetProperty()->SetComponentWeight(0, 0.5); // component 1 of the largest weight
    expectError(MakeImage(8, 8, 8, 2, 1.0), "isosurface blend mode", "two components, isosurfaces");
    volume->GetProperty()->SetComponentWeight(0, 1.0);
    volume->GetProperty()->GetIsoSurfaceValues()->SetNumberOfContours(0);
    mapper->SetBlendModeToComposite();
  }
  expectError(MakeImage(8, 8, 1, 1, 1.0), "at least 2", "one voxel thick");
  expectError(MakeImage(0, 0, 0, 1, 1.0), "empty", "an empty image");
  {
    auto image = MakeImage(8, 8, 8, 1, std::numeric_limits<double>::quiet_NaN());
    expectError(image, "no finite value", "only NaN scalars");
  }
  {
    auto image = MakeImage(8, 8, 8, 1, 4.0);
    auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
    values->SetValue(5, std::numeric_limits<float>::quiet_NaN());
    values->SetValue(9, std::numeric_limits<float>::infinity());
    expectError(image, "1 NaN scalars (missing data", "NaN and Inf scalars, with a warning", true);
    Check(observer->GetWarningMessage().find("and 1 infinite") != std::string::npos,
      "the warning counts the infinite scalars");
    Check(!observer->GetError(), "NaN scalars are not an error");
    Check(CountForeground(window) > sphereOnly, "the volume with NaN scalars is drawn");
  }

  // Larger than the GPU's 3-D texture limit along x: every sample as bricks
  // (its one value in one shared slot), no warning; with bricking off,
  // downsampled, with a warning.
  {
    auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
    const int limit = vtkTextureObject::GetMaximumTextureSize3D(glWindow);
    std::cout << "GL_MAX_3D_TEXTURE_SIZE " << limit << std::endl;
    auto image = MakeImage(limit + 5, 4, 4, 1, 4.0);
    image->SetSpacing(1.0 / limit, 0.2, 0.2);
    observer->Clear();
    mapper->SetInputData(image);
    window->Render();
    Check(!observer->GetError() && !observer->GetWarning() && mapper->GetVolumeBricked() &&
        CountForeground(window) > sphereOnly,
      "an oversized volume is drawn whole as bricks, without a warning");
    mapper->SetVolumeBricking(vtkTransmittanceVolumeMapper::BRICKING_OFF);
    expectError(image, "exceeds the GPU's 3-D texture size",
      "an oversized volume, bricking off, is downsampled", true);
    Check(
      !observer->GetError() && !mapper->GetVolumeBricked(), "an oversized volume is not an error");
    Check(CountForeground(window) > sphereOnly, "the downsampled volume is drawn");
    mapper->SetVolumeBricking(vtkTransmittanceVolumeMapper::BRICKING_AUTO);
  }

  // A NaN in the medium's settings (VTK's clamp macros let it through): an
  // error naming the setting, nothing of the volume drawn, the rest intact.
  {
    auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
    mapper->SetInputData(MakeImage(8, 8, 8, 1, 4.0));
    volume->VisibilityOff();
    window->Render();
    const int withoutVolume = CountForeground(window); // with the lights as they are now
    volume->VisibilityOn();
    window->Render();
    Check(CountForeground(window) > withoutVolume, "the valid volume is drawn");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::pair<std::string, std::function<void(double)>> settings[] = {
      { "ScatteringAnisotropy", [&](double v) { property->SetScatteringAnisotropy(v); } },
      { "OctaveScattering", [&](double v) { property->SetOctaveScattering(v); } },
      { "OctaveBuildUp", [&](double v) { property->SetOctaveBuildUp(v); } },
      { "LightScale", [&](double v) { property->SetLightScale(v); } }
    };
    for (const auto& s : settings)
    {
      s.second(nan);
      observer->Clear();
      window->Render();
      const std::string message = observer->GetErrorMessage();
      Check(observer->GetError() && message.find(s.first) != std::string::npos &&
          message.find("not a finite number") != std::string::npos,
        "NaN " + s.first + ": an error naming it");
      const int drawn = CountForeground(window);
      Check(drawn == withoutVolume, "NaN " + s.first + ": nothing of the volume drawn");
      vtkNew<vtkParticipatingMediumProperty> defaults;
      s.second(s.first == "ScatteringAnisotropy" ? defaults->GetScatteringAnisotropy()
          : s.first == "OctaveScattering"        ? defaults->GetOctaveScattering()
          : s.first == "OctaveBuildUp"           ? defaults->GetOctaveBuildUp()
                                                 : defaults->GetLightScale());
    }
    // A NaN iso value in the isosurface blend mode: the same.
    mapper->SetBlendModeToIsoSurface();
    property->GetIsoSurfaceValues()->SetValue(0, 2.0);
    property->GetIsoSurfaceValues()->SetValue(1, nan);
    observer->Clear();
    window->Render();
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("iso value 1") != std::string::npos &&
        observer->GetErrorMessage().find("not a finite number") != std::string::npos,
      "a NaN iso value: an error naming it");
    Check(CountForeground(window) == withoutVolume, "a NaN iso value: nothing of the volume drawn");
    property->GetIsoSurfaceValues()->SetNumberOfContours(0);
    mapper->SetBlendModeToComposite();
    // A binary mask whose dimensions differ from the volume's: the same.
    vtkSmartPointer<vtkImageData> mask = MakeImage(8, 8, 7, 1, 1.0);
    mapper->SetMaskInput(mask);
    mapper->SetMaskTypeToBinary();
    observer->Clear();
    window->Render();
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("mapper's mask") != std::string::npos &&
        observer->GetErrorMessage().find("8 x 8 x 7") != std::string::npos,
      "a mask of other dimensions: an error naming them");
    Check(
      CountForeground(window) == withoutVolume, "a mismatched mask: nothing of the volume drawn");
    // A mask with three components: the same.
    mapper->SetMaskInput(MakeImage(8, 8, 8, 3, 1.0));
    observer->Clear();
    window->Render();
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("one component") != std::string::npos,
      "a mask of three components: an error");
    // A matching mask hiding everything: no error, nothing of the volume drawn.
    mapper->SetMaskInput(MakeImage(8, 8, 8, 1, 0.0));
    observer->Clear();
    window->Render();
    Check(!observer->GetError() && CountForeground(window) == withoutVolume,
      "a mask hiding every sample: nothing drawn, no error");
    // The same as a label map: label 0 everywhere keeps the volume's
    // functions (VTK's rule), without a word.
    mapper->SetMaskTypeToLabelMap();
    observer->Clear();
    window->Render();
    Check(
      !observer->GetError() && !observer->GetWarning() && CountForeground(window) > withoutVolume,
      "a label map of label 0: the volume drawn with its own functions");
    // A label map with a NaN: an error naming it, nothing of the volume drawn.
    mapper->SetMaskInput(MakeImage(8, 8, 8, 1, nan));
    observer->Clear();
    window->Render();
    Check(observer->GetError() &&
        observer->GetErrorMessage().find("label map's values are finite") != std::string::npos &&
        CountForeground(window) == withoutVolume,
      "a label map with a NaN: an error, nothing drawn");
    mapper->SetMaskInput(nullptr);
    observer->Clear();
    window->Render();
    Check(!observer->GetError() && CountForeground(window) > withoutVolume,
      "the mask removed: the volume drawn again");

    // A plain property's 2-D transfer function that cannot be read: an
    // error naming it, nothing of the volume drawn; a valid one is drawn.
    vtkSmartPointer<vtkVolumeProperty> medium = property; // the volume's, kept while swapped
    vtkNew<vtkVolumeProperty> plain;
    plain->DeepCopy(property);
    plain->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
    volume->SetProperty(plain);
    auto expectTransfer2D =
      [&](vtkImageData* function, const std::string& text, const std::string& what)
    {
      plain->SetTransferFunction2D(function);
      observer->Clear();
      window->Render();
      Check(observer->GetError() && observer->GetErrorMessage().find(text) != std::string::npos,
        what + ": an error naming it (" + observer->GetErrorMessage() + ")");
      Check(CountForeground(window) == withoutVolume, what + ": nothing of the volume drawn");
    };
    expectTransfer2D(nullptr, "no 2-D transfer function", "TF_2D without a function");
    // (vtkVolumeProperty itself refuses, with its own error, what is not a
    // 4-component float image.)
    vtkSmartPointer<vtkImageData> function = MakeImage(8, 4, 1, 4, 1.5);
    expectTransfer2D(function, "in [0, 1]", "a 2-D function's opacity of 1.5");
    function = MakeImage(8, 4, 1, 4, std::numeric_limits<double>::quiet_NaN());
    expectTransfer2D(function, "in [0, 1]", "a NaN in a 2-D function");
    function = MakeImage(8, 4, 2, 4, 0.5);
    expectTransfer2D(function, "W x H x 1", "a 2-D function of two slices");
    function = MakeImage(4097, 2, 1, 4, 0.5);
    expectTransfer2D(function, "at most 4096", "a 2-D function 4097 pixels wide");
    plain->SetTransferFunction2D(MakeImage(8, 4, 1, 4, 0.5));
    observer->Clear();
    window->Render();
    Check(!observer->GetError() && CountForeground(window) > withoutVolume,
      "a valid 2-D function: drawn");
    volume->SetProperty(medium);
  }

  // No lights: ambient and emission only, no error; here the volume is dark.
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  observer->Clear();
  mapper->SetInputData(tyndall_test::MakeCloud(16));
  window->Render();
  Check(!observer->GetError(), "no lights is not an error");

  // A valid volume renders after all that.
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  observer->Clear();
  window->Render();
  Check(!observer->GetError() && !observer->GetWarning(), "a valid volume renders cleanly");
  Check(CountForeground(window) > sphereOnly + 50, "the valid volume is drawn");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
