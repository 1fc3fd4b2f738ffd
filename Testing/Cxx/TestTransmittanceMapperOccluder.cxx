// Opaque geometry blocks light entering the medium, for every method: a
// plate above the left half of a homogeneous slab, lit from above, leaves
// that half with ambient light only; without the plate both halves match.
#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestScene.h"

#include <iostream>

namespace
{
// Mean red value of a 9 x 9 pixel patch around (x, y).
double Patch(vtkImageData* image, int x, int y)
{
  double sum = 0.0;
  for (int j = -4; j <= 4; ++j)
  {
    for (int i = -4; i <= 4; ++i)
    {
      sum += *static_cast<unsigned char*>(image->GetScalarPointer(x + i, y + j, 0));
    }
  }
  return sum / 81.0;
}
}

int TestTransmittanceMapperOccluder(int, char*[])
{
  // A homogeneous slab [-1,1] x [-0.5,0.5] x [-1,1].
  vtkNew<vtkImageData> slab;
  slab->SetDimensions(21, 11, 21);
  slab->SetOrigin(-1.0, -0.5, -1.0);
  slab->SetSpacing(0.1, 0.1, 0.1);
  vtkNew<vtkFloatArray> density;
  density->SetNumberOfTuples(21 * 11 * 21);
  density->Fill(8.0);
  slab->GetPointData()->SetScalars(density);

  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputData(slab);
  mapper->JitterOff();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  auto medium = tyndall_test::MakeCloudProperty(0.05);
  medium->SetAmbientIntensity(0.05);
  volume->SetProperty(medium);

  // The plate: above the left half of the slab, between it and the light.
  vtkNew<vtkCubeSource> plate;
  plate->SetBounds(-1.2, 0.0, 0.8, 0.85, -1.2, 1.2);
  vtkNew<vtkPolyDataMapper> plateMapper;
  plateMapper->SetInputConnection(plate->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(plateMapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->AddActor(actor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  auto sun = tyndall_test::MakeSun(0.0, 1.0, 0.0);
  renderer->AddLight(sun);
  // Orthographic camera looking along -z at the slab.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(1.0);
  camera->SetPosition(0.0, 0.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(200, 200);
  window->AddRenderer(renderer);
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();

  // Pixel (50, 90) sees the slab's left half, (150, 90) its right half.
  int status = EXIT_SUCCESS;
  using M = vtkTransmittanceVolumeMapper;
  for (int method : { M::NONE, M::BRUTE_FORCE, M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
  {
    mapper->SetTransmittanceMethod(method);
    for (bool withPlate : { true, false })
    {
      actor->SetVisibility(withPlate);
      window->Render();
      grab->Modified();
      grab->Update();
      const double left = Patch(grab->GetOutput(), 50, 90);
      const double right = Patch(grab->GetOutput(), 150, 90);
      std::cout << vtkTransmittanceMapMath::GetMethodName(method)
                << (withPlate ? " with the plate" : " without the plate") << ": left " << left
                << ", right " << right << std::endl;
      const bool ok =
        right > 40.0 && (withPlate ? left < 0.35 * right : std::abs(left - right) < 0.05 * right);
      if (!ok)
      {
        std::cerr << "FAILED: " << vtkTransmittanceMapMath::GetMethodName(method)
                  << (withPlate ? ": the plate's shadow is missing"
                                : ": the halves differ without the plate")
                  << std::endl;
        status = EXIT_FAILURE;
      }
    }
  }
  return status;
}
