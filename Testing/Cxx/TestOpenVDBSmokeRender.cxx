// Baseline image of the Houdini smoke sample (../shared/data/vdb/smoke.vdb)
// read by vtkOpenVDBImageReader and rendered with VTK's stock GPU ray caster
// (unshaded composite), compared with
// Testing/Data/Baseline/TestOpenVDBSmokeRender.png (VTK's comparison and a
// PSNR floor). Skips (exit code 125) when the sample is absent.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestImage.h"

#include <filesystem>
#include <iostream>
#include <string>

int TestOpenVDBSmokeRender(int argc, char* argv[])
{
  const std::string path = std::string(TYNDALL_SHARED_DATA) + "/vdb/smoke.vdb";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    std::cout << "Skipping: " << path << " not found (../shared/data is absent)." << std::endl;
    return 125;
  }
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "The smoke sample could not be read." << std::endl;
    return EXIT_FAILURE;
  }

  // Densities 0 .. 5.7; thin wisps faint, the dense core nearly opaque.
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.02, 0.0);
  opacity->AddPoint(1.0, 0.08);
  opacity->AddPoint(5.8, 0.5);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.85, 0.85, 0.85);
  color->AddRGBPoint(1.0, 0.7, 0.7, 0.7);
  color->AddRGBPoint(5.8, 1.0, 0.95, 0.85);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(0.476); // the voxel size
  property->ShadeOff();

  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  mapper->SetAutoAdjustSampleDistances(false);
  mapper->SetSampleDistance(0.2);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.1, 0.12, 0.2);
  // The smoke rises along +y; look at it from +z.
  double bounds[6];
  reader->GetOutput()->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(centre[0], centre[1] - 6.0, centre[2]);
  camera->SetPosition(centre[0], centre[1] - 6.0, centre[2] + 215.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();

  const int result = tyndall_test::RegressionTestWithPSNR(argc, argv, window, 45.0);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
