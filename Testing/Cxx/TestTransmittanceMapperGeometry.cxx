// The volume's placement is honoured exactly: an extent that does not start
// at 0 (as OpenVDB grids give) with the origin moved back renders the same
// picture; a rotation through the image's direction matrix renders the same
// picture as the same rotation through the vtkVolume's matrix.
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <iostream>

int TestTransmittanceMapperGeometry(int, char*[])
{
  auto cloud = tyndall_test::MakeCloud(40);
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputData(cloud);
  mapper->JitterOff();
  mapper->SetTransmittanceMapSize(64);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tyndall_test::MakeCloudProperty());
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(128, 128);
  window->AddRenderer(renderer);
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  auto capture = [&]()
  {
    window->Render();
    grab->Modified();
    grab->Update();
    vtkNew<vtkImageData> image;
    image->DeepCopy(grab->GetOutput());
    return vtkSmartPointer<vtkImageData>(image);
  };
  int status = EXIT_SUCCESS;
  auto same = [&](vtkImageData* a, vtkImageData* b, const char* what)
  {
    const double psnr = tyndall_test::PSNR(a, b);
    std::cout << what << ": " << psnr << " dB" << std::endl;
    if (!(psnr >= 55.0))
    {
      std::cerr << "FAILED: " << what << std::endl;
      status = EXIT_FAILURE;
    }
  };

  auto reference = capture();

  // The same samples, indexed from (7, 3, -4), origin moved back.
  vtkNew<vtkImageData> shifted;
  shifted->DeepCopy(cloud);
  const int* e = cloud->GetExtent();
  shifted->SetExtent(e[0] + 7, e[1] + 7, e[2] + 3, e[3] + 3, e[4] - 4, e[5] - 4);
  const double* o = cloud->GetOrigin();
  const double* d = cloud->GetSpacing();
  shifted->SetOrigin(o[0] - 7 * d[0], o[1] - 3 * d[1], o[2] + 4 * d[2]);
  mapper->SetInputData(shifted);
  same(reference, capture(), "extent starting at (7, 3, -4)");

  // A quarter turn about z through the direction matrix, about the image's
  // centre (0, 0, 0), vs the same turn through the volume's matrix.
  volume->RotateZ(90.0);
  mapper->SetInputData(cloud);
  auto turnedByVolume = capture();
  volume->SetOrientation(0.0, 0.0, 0.0);
  vtkNew<vtkImageData> turned;
  turned->DeepCopy(cloud);
  const double quarter[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
  turned->SetDirectionMatrix(quarter);
  // The origin (-1, -1, -1) turns to (1, -1, -1) about the z axis.
  turned->SetOrigin(1.0, -1.0, -1.0);
  mapper->SetInputData(turned);
  same(turnedByVolume, capture(), "direction matrix vs volume matrix");
  if (!(tyndall_test::PSNR(reference, turnedByVolume) < 40.0))
  {
    std::cerr << "FAILED: the quarter turn should change the picture" << std::endl;
    status = EXIT_FAILURE;
  }
  return status;
}
