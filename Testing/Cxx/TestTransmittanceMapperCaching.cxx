// vtkTransmittanceVolumeMapper rebuilds its maps only when something they
// depend on changes, never for a camera move; parameters clamp to their
// documented ranges; releasing graphics resources and destroying the window
// leave no OpenGL error.
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include "TyndallTestCheck.h"
#include "TyndallTestScene.h"

#include <iostream>

namespace
{
using tyndall_test::Check;
}

int TestTransmittanceMapperCaching(int, char*[])
{
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  // The maps' builds are counted; the transmittance cache (on by default) follows
  // them and has its own counts in TestTransmittanceMapperTransmittanceCache.
  mapper->TransmittanceCacheOff();
  // Parameter clamping to the documented ranges.
  mapper->SetNumberOfCoefficients(100);
  Check(mapper->GetNumberOfCoefficients() == 16, "coefficients clamp to 16");
  mapper->SetNumberOfCoefficients(0);
  Check(mapper->GetNumberOfCoefficients() == 1, "coefficients clamp to 1");
  mapper->SetTransmittanceMapSize(1);
  Check(mapper->GetTransmittanceMapSize() == 16, "map size clamps to 16");
  mapper->SetTransmittanceMethod(42);
  Check(mapper->GetTransmittanceMethod() == vtkTransmittanceVolumeMapper::ADAPTIVE_ETM,
    "method clamps into the enumeration");
  mapper->SetAdaptiveThreshold(2.0);
  Check(mapper->GetAdaptiveThreshold() == 0.5, "adaptive threshold clamps to 0.5");
  mapper->SetLightSampleCount(0);
  Check(mapper->GetLightSampleCount() == 1, "light samples clamp to 1");

  mapper->SetNumberOfCoefficients(8);
  mapper->SetAdaptiveThreshold(0.01);
  mapper->SetLightSampleCount(64);
  mapper->SetTransmittanceMapSize(64);
  mapper->SetInputData(tyndall_test::MakeCloud(32));
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);

  // The medium's settings clamp to their documented ranges too.
  auto property = tyndall_test::MakeCloudProperty();
  property->SetScatteringAnisotropy(2.0);
  Check(property->GetScatteringAnisotropy() == 0.99, "anisotropy clamps to 0.99");
  property->SetScatteringAnisotropy(-5.0);
  Check(property->GetScatteringAnisotropy() == -0.99, "anisotropy clamps to -0.99");
  property->SetDensityScale(-1.0);
  Check(property->GetDensityScale() == 0.0, "density scale clamps to 0");
  property->SetScatteringAnisotropy(0.3);
  property->SetDensityScale(1.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  auto sun = tyndall_test::MakeSun(1.0, 0.5, 0.2);
  renderer->AddLight(sun);
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(64, 64);
  window->AddRenderer(renderer);

  window->Render();
  Check(mapper->GetMapBuildCount() == 1, "the first frame builds the maps");
  int builds = mapper->GetMapBuildCount();
  auto expect = [&](bool rebuilt, const char* what)
  {
    window->Render();
    const int now = mapper->GetMapBuildCount();
    if (now != builds + (rebuilt ? 1 : 0))
    {
      std::cerr << what << ": " << now - builds << " rebuilds" << std::endl;
    }
    Check(now == builds + (rebuilt ? 1 : 0), what);
    builds = now;
  };

  renderer->GetActiveCamera()->Azimuth(40.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->ResetCameraClippingRange();
  expect(false, "a camera move reuses the maps");
  renderer->GetActiveCamera()->Zoom(1.3);
  expect(false, "a zoom reuses the maps");
  property->SetScatteringAnisotropy(-0.2);
  property->SetAmbientIntensity(0.1);
  property->SetLightScale(10.0);
  expect(false, "anisotropy, ambient and light scale do not touch the maps");
  property->SetScatteringOctaves(3);
  expect(true, "more octaves extend the adaptive maps' range (rebuild)");
  property->SetOctaveExtinction(0.6);
  expect(true, "the octaves' extinction moves the adaptive maps' range (rebuild)");
  property->SetOctaveScattering(0.7);
  expect(true,
    "the octaves' scattering from 1.3 to 0.7 narrows the adaptive maps' range "
    "(their weight above 1 widens it; rebuild)");
  property->SetOctaveScattering(0.5);
  property->SetOctaveAnisotropy(0.2);
  property->SetOctaveBuildUp(2.0);
  expect(false,
    "the octaves' scattering (at most 1), anisotropy and build-up do not touch the "
    "maps");
  sun->SetPosition(-1.0, 0.5, 0.2);
  expect(true, "moving the light rebuilds");
  sun->SetIntensity(2.0);
  expect(false, "the light's intensity does not touch the maps");
  property->SetDensityScale(2.0);
  expect(true, "the density scale rebuilds");
  mapper->SetNumberOfCoefficients(12);
  expect(true, "the coefficient count rebuilds");
  mapper->SetTransmittanceMapSize(32);
  expect(true, "the map size rebuilds");
  mapper->SetTransmittanceMethodToTFM();
  expect(true, "the method rebuilds");
  property->GetScalarOpacity()->AddPoint(4.0, 0.1);
  expect(true, "the opacity transfer function rebuilds");
  property->GetRGBTransferFunction()->AddRGBPoint(4.0, 1.0, 0.2, 0.1);
  expect(false, "the colour transfer function does not touch the maps");
  mapper->SetBlendModeToIsoSurface();
  property->GetIsoSurfaceValues()->SetValue(0, 0.5);
  expect(true, "the isosurface blend mode rebuilds (the light meets the surfaces)");
  property->GetIsoSurfaceValues()->SetValue(0, 0.6);
  expect(true, "an iso value rebuilds");
  property->GetRGBTransferFunction()->AddRGBPoint(3.0, 0.2, 1.0, 0.1);
  expect(false, "the colour transfer function does not touch the isosurfaces' maps");
  mapper->SetBlendModeToComposite();
  expect(true, "back to composite rebuilds");
  volume->RotateZ(30.0);
  expect(true, "the volume's matrix rebuilds");
  mapper->SetInputData(tyndall_test::MakeCloud(24));
  expect(true, "new data rebuilds");
  auto second = tyndall_test::MakeSun(0.0, 1.0, 0.0);
  renderer->AddLight(second);
  expect(true, "a new light rebuilds");
  renderer->GetActiveCamera()->Azimuth(-60.0);
  renderer->ResetCameraClippingRange();
  expect(false, "a camera move with two lights reuses the maps");
  mapper->GetLightFrustum(0)->SetPadding(0.2);
  expect(true, "a light frustum's padding rebuilds");
  mapper->SetTransmittanceMethodToBruteForce();
  expect(false, "brute force builds no map");
  Check(!errors->GetError(), "no errors while rendering");

  // Release, render again, destroy: no OpenGL error.
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  mapper->SetTransmittanceMethodToAdaptiveETM();
  window->Render();
  mapper->ReleaseGraphicsResources(window);
  window->Render();
  Check(mapper->GetMapBuildCount() == builds + 2, "released maps are rebuilt once");
  glWindow->MakeCurrent();
  const GLenum glError = glGetError();
  Check(glError == GL_NO_ERROR, "no OpenGL error after release and re-render");
  window->Finalize();
  Check(!errors->GetError(), "no errors after finalizing the window");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
