// Baseline image of vtkTransmittanceVolumeMapper in six scenes, one per
// viewport: a directional light; a point light; a spot light; two coloured
// lights; a rotated and scaled volume; an opaque sphere inside the medium
// (view rays stop at its depth) with a point light inside the volume's
// bounds (that light falls back to brute force).
#include "vtkActor.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkSphereSource.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

int TestTransmittanceMapperScenes(int argc, char* argv[])
{
  auto cloud = tyndall_test::MakeCloud(48);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(480, 320);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);

  vtkSmartPointer<vtkRenderer> renderers[6];
  vtkSmartPointer<vtkVolume> volumes[6];
  for (int i = 0; i < 6; ++i)
  {
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    mapper->SetInputData(cloud);
    mapper->JitterOff();
    mapper->SetTransmittanceMapSize(128);
    volumes[i] = vtkSmartPointer<vtkVolume>::New();
    volumes[i]->SetMapper(mapper);
    auto medium = tyndall_test::MakeCloudProperty(0.4);
    medium->SetAmbientIntensity(0.15);
    volumes[i]->SetProperty(medium);
    renderers[i] = vtkSmartPointer<vtkRenderer>::New();
    renderers[i]->SetViewport((i % 3) / 3.0, (i / 3) / 2.0, (i % 3 + 1) / 3.0, (i / 3 + 1) / 2.0);
    renderers[i]->SetBackground(0.2, 0.3, 0.45);
    renderers[i]->AddVolume(volumes[i]);
    window->AddRenderer(renderers[i]);
  }

  // Bottom row: directional, point, spot.
  renderers[0]->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  {
    vtkNew<vtkLight> point;
    point->SetLightTypeToSceneLight();
    point->PositionalOn();
    point->SetConeAngle(180.0);
    point->SetPosition(1.6, 1.2, 0.6);
    point->SetFocalPoint(0.0, 0.0, 0.0);
    point->SetAttenuationValues(0.0, 0.0, 0.35);
    renderers[1]->AddLight(point);
  }
  {
    vtkNew<vtkLight> spot;
    spot->SetLightTypeToSceneLight();
    spot->PositionalOn();
    spot->SetPosition(0.0, 2.5, 0.5);
    spot->SetFocalPoint(0.3, 0.0, 0.0);
    spot->SetConeAngle(20.0);
    spot->SetExponent(2.0);
    spot->SetIntensity(1.5);
    renderers[2]->AddLight(spot);
  }
  // Top row: two lights; a rotated, scaled volume; an opaque sphere.
  {
    auto warm = tyndall_test::MakeSun(1.0, 0.2, 0.2, 0.8);
    warm->SetColor(1.0, 0.6, 0.3);
    auto cool = tyndall_test::MakeSun(-1.0, 0.6, -0.2, 0.8);
    cool->SetColor(0.3, 0.5, 1.0);
    renderers[3]->AddLight(warm);
    renderers[3]->AddLight(cool);
  }
  renderers[4]->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  volumes[4]->RotateZ(35.0);
  volumes[4]->RotateX(-20.0);
  volumes[4]->SetScale(0.7, 1.3, 1.0);
  {
    renderers[5]->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
    vtkNew<vtkLight> inside; // inside the bounds: brute-force fallback
    inside->SetLightTypeToSceneLight();
    inside->PositionalOn();
    inside->SetConeAngle(180.0);
    inside->SetPosition(-0.5, 0.0, 0.0);
    inside->SetColor(1.0, 0.5, 0.2);
    inside->SetIntensity(0.05);
    renderers[5]->AddLight(inside);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.35, 0.0, 0.3);
    sphere->SetRadius(0.3);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(sphereMapper);
    actor->GetProperty()->SetColor(0.8, 0.2, 0.2);
    renderers[5]->AddActor(actor);
  }
  for (auto& renderer : renderers)
  {
    tyndall_test::SetTestCamera(renderer, 40.0);
  }
  window->Render();

  const int result = tyndall_test::RegressionTestWithPSNR(argc, argv, window, 45.0);
  if (result == vtkTesting::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkTesting::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
