// Interactive level of detail (vtkTransmittanceVolumeMapper's
// InteractiveAdjustment): with a desired update rate the full-size frame
// cannot meet, the camera rays are cast at a reduced size with longer
// steps, shadows on (the
// same cached maps, no rebuild), the picture close to the full-size one and
// nearer to it than to the unshadowed picture; back at the still rate, the
// frame equals the full-size picture exactly. With the adjustment off, or
// its maximum at 1, nothing is reduced.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

int TestTransmittanceMapperInteractive(int, char*[])
{
  int status = EXIT_SUCCESS;
  auto check = [&status](bool ok, const char* what)
  {
    if (!ok)
    {
      std::cerr << "FAILED: " << what << std::endl;
      status = EXIT_FAILURE;
    }
  };
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputData(tyndall_test::MakeCloud(64));
  mapper->SetTransmittanceMethodToAdaptiveETM();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tyndall_test::MakeCloudProperty(0.6));
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.2, 0.3, 0.45);
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(256, 256);
  window->AddRenderer(renderer);

  // The still frame (VTK's default desired update rate: 0.0001 per second).
  window->Render();
  vtkSmartPointer<vtkImageData> still = tyndall_test::Grab(window);
  check(mapper->GetLastImageReduction() == 1, "the still frame is full size");
  const int builds = mapper->GetMapBuildCount();

  // Interacting: 1000 frames per second asked, which no frame here meets.
  window->SetDesiredUpdateRate(1000.0);
  window->Render();
  vtkSmartPointer<vtkImageData> moving = tyndall_test::Grab(window);
  const int reduction = mapper->GetLastImageReduction();
  std::cout << "interactive frame: reduction " << reduction << ", camera rays "
            << mapper->GetLastRayCastTime() << " s, PSNR against the still frame "
            << tyndall_test::PSNR(moving, still) << " dB\n";
  check(reduction == mapper->GetMaximumImageReduction(), "the interactive frame is reduced");
  check(mapper->GetLastStepScale() == 2.0, "far too slow: the steps are lengthened too");
  check(mapper->GetMapBuildCount() == builds, "interacting rebuilds no map");
  check(mapper->GetLightTransmittanceMethod(0) == vtkTransmittanceVolumeMapper::ADAPTIVE_ETM,
    "shadows stay on while interacting");
  check(tyndall_test::PSNR(moving, still) >= 25.0, "the reduced frame resembles the still one");
  check(tyndall_test::MaxDifference(moving, still) > 0, "the reduced frame is a different picture");

  // The unshadowed picture is further from the still frame than the
  // reduced, shadowed one.
  mapper->SetTransmittanceMethodToNone();
  window->SetDesiredUpdateRate(0.0001);
  window->Render();
  vtkSmartPointer<vtkImageData> unshadowed = tyndall_test::Grab(window);
  std::cout << "unshadowed against still: " << tyndall_test::PSNR(unshadowed, still) << " dB\n";
  check(tyndall_test::PSNR(moving, still) > tyndall_test::PSNR(unshadowed, still) + 3.0,
    "the reduced frame keeps the shadows");

  // Back to still: the full-size picture, exactly.
  mapper->SetTransmittanceMethodToAdaptiveETM();
  window->Render();
  check(mapper->GetLastImageReduction() == 1 && mapper->GetLastStepScale() == 1.0,
    "the still frame after interaction is full size, full detail");
  check(tyndall_test::MaxDifference(tyndall_test::Grab(window), still) == 0,
    "the still frame equals the first one");

  // The adjustment off, or capped at 1.
  window->SetDesiredUpdateRate(1000.0);
  mapper->SetMaximumImageReduction(2);
  window->Render();
  check(mapper->GetLastImageReduction() == 2, "MaximumImageReduction caps the reduction");
  mapper->InteractiveAdjustmentOff();
  window->Render();
  check(mapper->GetLastImageReduction() == 1, "InteractiveAdjustment off: full size");
  check(tyndall_test::MaxDifference(tyndall_test::Grab(window), still) == 0,
    "InteractiveAdjustment off: the still picture");
  return status;
}
