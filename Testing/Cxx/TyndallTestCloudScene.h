// The scene of the tests that compare vtkTransmittanceVolumeMapper with the
// CPU reference on the built-in cloud: the cloud at 48^3 drawn by the mapper
// (jitter off) with a cloud property, the tests' camera, a size x size
// window. Each test adds its lights, background and settings. Header only;
// not part of the library.
#ifndef TyndallTestCloudScene_h
#define TyndallTestCloudScene_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

namespace tyndall_test
{
struct CloudScene
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  /// The cloud with MakeCloudProperty(peakOpacity) in a size x size window.
  CloudScene(int size, double peakOpacity)
    : Property(MakeCloudProperty(peakOpacity))
  {
    this->Mapper->SetInputData(MakeCloud(48));
    this->Mapper->JitterOff();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    SetTestCamera(this->Renderer);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
  }

  /// The mapper's picture.
  vtkSmartPointer<vtkImageData> Gpu()
  {
    this->Window->Render();
    return Grab(this->Window);
  }

  /// `reference`'s picture of the scene (with `raw`, its radiance and transmittance).
  vtkSmartPointer<vtkImageData> Cpu(vtkSingleScatteringReference* reference, bool raw = false)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    if (reference->Render(
          this->Renderer, this->Volume, this->Window->GetSize()[0], this->Window->GetSize()[1]))
    {
      image->DeepCopy(raw ? reference->GetOutput() : reference->Composite());
    }
    return image;
  }
};
}

#endif
