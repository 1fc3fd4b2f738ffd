// The scene of the path-tracing mode's test and benchmark
// (TestTransmittanceMapperPathTrace, BenchCinematic): a medium lit by a sun of
// intensity 1.5, ambient 0.05, g 0.4, in its own window; Trace() renders
// from a new start until the picture has its samples. Header only; not part
// of the library.
#ifndef TyndallTestPathScene_h
#define TyndallTestPathScene_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestScene.h"

#include <chrono>
#include <string>

namespace tyndall_test
{
struct PathScene
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  int Frames = 0; // frames of paths the last Trace() rendered
  // When the last Trace()'s first frame of paths began (after the map-based frame).
  std::chrono::steady_clock::time_point PathsStart;

  PathScene(vtkImageData* data, double peakOpacity, int size)
    : Property(MakeCloudProperty(peakOpacity))
  {
    this->Mapper->SetInputData(data);
    this->Mapper->JitterOff();
    this->Mapper->InteractiveAdjustmentOff();
    this->Mapper->PathTracingOn();
    this->Property->SetScatteringAnisotropy(0.4);
    this->Property->SetAmbientIntensity(0.05);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Volume->RotateY(15.0);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    this->Renderer->AddLight(MakeSun(1.0, 0.5, 0.3, 1.5));
    SetTestCamera(this->Renderer);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
  }

  // Renders from a new start (the map-based frame, then frames of paths)
  // until the picture has `samples` samples per pixel, or `stop(samples so
  // far)` returns true after a frame of paths, or the picture stops growing
  // (refused); the samples it has.
  template <typename Stop>
  int Trace(int samples, Stop stop)
  {
    this->Mapper->PathTracingOn();
    this->Mapper->SetPathTraceSamplesPerPixel(samples);
    this->Mapper->ResetAccumulation();
    this->Window->Render(); // the map-based frame
    this->PathsStart = std::chrono::steady_clock::now();
    for (this->Frames = 1; this->Frames <= 2 * samples + 2; ++this->Frames)
    {
      this->Window->Render();
      const int n = this->Mapper->GetLastPathTraceSamples();
      if (stop(n) || n >= samples || n == 0)
      {
        break;
      }
    }
    return this->Mapper->GetLastPathTraceSamples();
  }

  int Trace(int samples)
  {
    return this->Trace(samples, [](int) { return false; });
  }

  // The picture as the last Render() left it (vtkWindowToImageFilter
  // renders again by default: a still frame would add paths).
  vtkSmartPointer<vtkImageData> Picture()
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOff();
    grab->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(grab->GetOutput());
    return image;
  }
};
}

#endif
