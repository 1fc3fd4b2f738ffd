// Baseline image of every transmittance method on the built-in cloud, one
// viewport each: None, BruteForce, TFM (bottom row); AdaptiveTFM, ETM,
// AdaptiveETM (top row).
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

int TestTransmittanceMapperMethods(int argc, char* argv[])
{
  auto cloud = tyndall_test::MakeCloud(48);
  auto property = tyndall_test::MakeCloudProperty(0.5);
  property->SetAmbientIntensity(0.1);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(480, 320);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  for (int method = vtkTransmittanceVolumeMapper::NONE;
       method <= vtkTransmittanceVolumeMapper::ADAPTIVE_ETM; ++method)
  {
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    mapper->SetInputData(cloud);
    mapper->SetTransmittanceMethod(method);
    mapper->SetTransmittanceMapSize(128);
    mapper->JitterOff();
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(
      (method % 3) / 3.0, (method / 3) / 2.0, (method % 3 + 1) / 3.0, (method / 3 + 1) / 2.0);
    renderer->SetBackground(0.2, 0.3, 0.45);
    renderer->AddVolume(volume);
    renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
    tyndall_test::SetTestCamera(renderer, 36.0);
    window->AddRenderer(renderer);
  }
  window->Render();
  const int result = tyndall_test::RegressionTestWithPSNR(argc, argv, window, 45.0);
  if (result == vtkTesting::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkTesting::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
