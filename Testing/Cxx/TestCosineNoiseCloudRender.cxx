// Baseline image of a cosine-noise cloud from vtkCosineNoiseSource, rendered
// with VTK's stock GPU ray caster (unshaded composite), compared with
// Testing/Data/Baseline/TestCosineNoiseCloudRender.png (VTK's comparison and
// a PSNR floor).
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoiseSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestImage.h"

int TestCosineNoiseCloudRender(int argc, char* argv[])
{
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(0, 79, 0, 79, 0, 79);
  source->SetSpacing(2.0 / 79, 2.0 / 79, 2.0 / 79);
  source->Update();

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.5, 0.008);
  opacity->AddPoint(8.0, 0.16);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.75, 0.8, 0.9);
  color->AddRGBPoint(8.0, 1.0, 1.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(0.05);
  property->ShadeOff(); // VTK's gradient shading darkens noise

  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  mapper->SetAutoAdjustSampleDistances(false);
  mapper->SetSampleDistance(0.01);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.32, 0.45, 0.62);
  renderer->GetActiveCamera()->SetPosition(0.0, -0.6, 4.2);
  renderer->GetActiveCamera()->SetViewAngle(24.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();

  // Same machine kind, same Mesa: the image should match to 45 dB or better
  // (a 12% change of the peak opacity measured 41 dB).
  const int result = tyndall_test::RegressionTestWithPSNR(argc, argv, window, 45.0);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
