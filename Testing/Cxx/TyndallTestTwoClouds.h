// The scene of several-volume tests and benchmarks: two clouds (the
// built-in cloud, 48^3 unless asked, scaled 0.8) side by side at x = -1 and x = +1, the
// left one denser, under a low sun from the left (its light crosses the
// left cloud, then the right one), seen from the front; volumes sorted back
// to front. The picture of Documentation/scripts/scene_shadows_picture.py.
// Header only; not part of the library.
#ifndef TyndallTestTwoClouds_h
#define TyndallTestTwoClouds_h

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCullerCollection.h"
#include "vtkFrustumCoverageCuller.h"
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
struct TwoClouds
{
  /// One cloud: its own mapper (16 coefficients, jitter off, no transmittance
  /// cache: see SetCache()), property and placement.
  struct Cloud
  {
    vtkNew<vtkTransmittanceVolumeMapper> Mapper;
    vtkSmartPointer<vtkParticipatingMediumProperty> Property;
    vtkNew<vtkVolume> Volume;

    Cloud(vtkImageData* data, double peakOpacity, double x)
      : Property(tyndall_test::MakeCloudProperty(peakOpacity))
    {
      this->Mapper->SetInputData(data);
      this->Mapper->JitterOff();
      this->Mapper->SetNumberOfCoefficients(16);
      this->Mapper->TransmittanceCacheOff();
      this->Volume->SetMapper(this->Mapper);
      this->Volume->SetProperty(this->Property);
      this->Volume->SetScale(0.8);
      this->Volume->SetPosition(x, 0.0, 0.0);
    }
  };

  vtkSmartPointer<vtkImageData> Data;
  Cloud Left{ Data, 0.9, -1.0 };
  Cloud Right{ Data, 0.5, 1.0 };
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  /// A width x height window; the cloud at resolution^3.
  TwoClouds(int width, int height, int resolution = 48)
    : Data(tyndall_test::MakeCloud(resolution))
  {
    this->Renderer->AddVolume(this->Left.Volume);
    this->Renderer->AddVolume(this->Right.Volume);
    this->Renderer->AddLight(tyndall_test::MakeSun(-1.0, 0.3, 0.2, 1.0));
    this->Renderer->SetBackground(0.1, 0.12, 0.18);
    tyndall_test::SetTestCamera(this->Renderer, 24.0);
    this->Renderer->GetActiveCamera()->SetPosition(0.0, -0.5, 4.6); // both clouds in view
    this->Renderer->ResetCameraClippingRange();
    // Volumes drawn back to front (VTK's way for several volumes).
    this->Renderer->GetCullers()->InitTraversal();
    vtkFrustumCoverageCuller::SafeDownCast(this->Renderer->GetCullers()->GetNextItem())
      ->SetSortingStyleToBackToFront();
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
  }

  void SetMethod(int method)
  {
    this->Left.Mapper->SetTransmittanceMethod(method);
    this->Right.Mapper->SetTransmittanceMethod(method);
  }

  /// The camera rays' transmittance cache of both (on by default in the
  /// mapper, off here): the tests check it where they ask for it (the
  /// other's shadow and the group's box read through it, against the CPU);
  /// its 256^3 lattice per light and map build was most of their time (with
  /// it throughout -SceneShadows took 91 s instead of 32, -SceneCompositing
  /// 119 s instead of 77), and every PSNR moved by 0.05 dB at most without it.
  void SetCache(bool on)
  {
    this->Left.Mapper->SetTransmittanceCache(on);
    this->Right.Mapper->SetTransmittanceCache(on);
  }

  void SetSceneShadows(bool on)
  {
    this->Left.Property->SetSceneShadows(on);
    this->Right.Property->SetSceneShadows(on);
  }

  void SetSceneCompositing(bool on)
  {
    this->Left.Property->SetSceneCompositing(on);
    this->Right.Property->SetSceneCompositing(on);
  }

  /**
   * The overlapping scene: the two clouds through the same space, the
   * right one red, turned a quarter turn about y and moved by 0.05 in x
   * and y, both at half density, the camera closer (the picture of
   * Documentation/scripts/scene_compositing_picture.py).
   */
  void Interpenetrate()
  {
    this->Left.Volume->SetPosition(0.0, 0.0, 0.0);
    this->Right.Volume->SetPosition(0.05, 0.05, 0.0);
    this->Right.Volume->SetOrientation(0.0, 90.0, 0.0);
    vtkNew<vtkColorTransferFunction> red;
    red->AddRGBPoint(0.0, 0.95, 0.45, 0.3);
    red->AddRGBPoint(8.0, 0.95, 0.45, 0.3);
    this->Right.Property->SetColor(red);
    this->Left.Property->SetDensityScale(0.5);
    this->Right.Property->SetDensityScale(0.5);
    this->Renderer->GetActiveCamera()->SetPosition(0.0, -0.3, 2.8);
    this->Renderer->ResetCameraClippingRange();
  }

  vtkSmartPointer<vtkImageData> Gpu()
  {
    this->Window->Render();
    return tyndall_test::Grab(this->Window);
  }

  /**
   * The CPU reference's picture: each cloud rendered (lit through the
   * other), composited over the background (their pixels do not overlap,
   * so the order is exact either way).
   */
  vtkSmartPointer<vtkImageData> Cpu()
  {
    const int w = this->Window->GetSize()[0], h = this->Window->GetSize()[1];
    vtkNew<vtkSingleScatteringReference> left, right;
    left->Render(this->Renderer, this->Left.Volume, w, h);
    right->Render(this->Renderer, this->Right.Volume, w, h);
    return tyndall_test::CompositeFrontToBack(
      { left->GetOutput(), right->GetOutput() }, this->Renderer->GetBackground());
  }
};
}

#endif
