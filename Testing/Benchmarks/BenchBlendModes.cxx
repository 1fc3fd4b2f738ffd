// Benchmark of VTK's blend modes drawn by vtkTransmittanceVolumeMapper
// beside VTK 9.1's vtkGPUVolumeRayCastMapper on the same scene: the
// projections (maximum, minimum and average intensity, additive) and the
// unshaded composite of a plain vtkVolumeProperty, and its gradient shading
// (Shade on; Tyndall without shadows, the method None, and with the maps'
// shadows: VTK draws none), and the isosurface mode (three surfaces, Shade
// on, without and with shadows). Prints, per mode, the
// time of a frame of each mapper (the mean of N frames, each finished with
// WaitForCompletion(), the two mappers alternating frame by frame in one
// window so that both see the same load), their ratio, and the PSNR between
// their pictures. Prints figures; it is not a test.
//
//   BenchBlendModes [--voxels N] [--size N] [--frames N] [--quick] [--peeling]
//
// --peeling: two translucent spheres (one through the volume, one in front
// of it) with the renderer's depth peeling for volumes, so that both mappers
// draw the volume inside VTK's dual depth peeling (vtkTransmittancePeelingPass);
// run it beside a run without to compare a peeled frame with an unpeeled one.
//
// The volume is VTK's wavelet (vtkRTAnalyticSource, floats) over N^3 points
// (default 256), seen at an angle in an N x N window (--size, default 512),
// each mapper at its defaults (VTK's automatic sample distance; Tyndall's
// half voxel, jitter on). --quick: 32^3, 64^2, 1 frame (ctest runs it: every
// mode renders, never a timing).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestImage.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
struct Mode
{
  const char* Name;
  int BlendMode;
  double PeakOpacity;
  bool Shade = false;
  int Method = vtkTransmittanceVolumeMapper::ADAPTIVE_ETM; // Tyndall's (the default)
};

// Seconds per frame of the window's current volume, the mean of `frames`.
double FrameTime(vtkRenderWindow* window)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  return timer->GetElapsedTime();
}

// A translucent sphere at `center` (a fraction of the half-width `h` of
// the volume's box on each axis), drawn with depth peeling for volumes.
void AddTranslucentSphere(vtkRenderer* renderer, double h, double x, double y, double z, double r)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x * h, y * h, z * h);
  sphere->SetRadius(r * h);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.3, 0.8, 0.4);
  actor->GetProperty()->SetOpacity(0.4);
  renderer->AddActor(actor);
  renderer->SetUseDepthPeeling(1);
  renderer->SetUseDepthPeelingForVolumes(true);
  renderer->SetMaximumNumberOfPeels(4);
  renderer->SetOcclusionRatio(0.0);
}
}

int main(int argc, char* argv[])
{
  int voxels = 256, size = 512, frames = 5;
  bool peeling = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--quick")
    {
      voxels = 32;
      size = 64;
      frames = 1;
    }
    else if (a == "--peeling")
    {
      peeling = true;
    }
    else if (a == "--voxels" && i + 1 < argc)
    {
      voxels = std::atoi(argv[++i]);
    }
    else if (a == "--size" && i + 1 < argc)
    {
      size = std::atoi(argv[++i]);
    }
    else if (a == "--frames" && i + 1 < argc)
    {
      frames = std::atoi(argv[++i]);
    }
    else
    {
      std::printf(
        "Usage: BenchBlendModes [--voxels N] [--size N] [--frames N] [--quick] [--peeling]\n");
      return EXIT_FAILURE;
    }
  }
  if (voxels < 8 || voxels > 1024 || size < 16 || size > 4096 || frames < 1)
  {
    std::printf("BenchBlendModes: --voxels 8..1024, --size 16..4096, --frames 1 or more\n");
    return EXIT_FAILURE;
  }

  vtkNew<vtkRTAnalyticSource> wavelet;
  const int h = voxels / 2;
  wavelet->SetWholeExtent(-h + 1, h, -h + 1, h, -h + 1, h);
  wavelet->Update();
  vtkImageData* data = wavelet->GetOutput();
  double range[2];
  data->GetPointData()->GetScalars()->GetRange(range);

  vtkNew<vtkGPUVolumeRayCastMapper> vtkMapper;
  vtkNew<vtkTransmittanceVolumeMapper> tyndall;
  vtkMapper->SetInputData(data);
  tyndall->SetInputData(data);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.0, 0.0, 0.0);
  color->AddRGBPoint(range[1], 1.0, 0.9, 0.8);
  vtkNew<vtkPiecewiseFunction> opacity;
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.2, 0.3, 0.4);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(size, size);
  window->AddRenderer(renderer);
  volume->SetMapper(vtkMapper);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->ResetCamera();
  if (peeling) // after the camera: the same view as without
  {
    AddTranslucentSphere(renderer, h, 0.1, 0.0, 0.0, 0.5);
    AddTranslucentSphere(renderer, h, -0.3, -0.2, 1.6, 0.35);
  }

  std::printf("BenchBlendModes: wavelet %d^3 (floats), %d x %d, %d frame(s) each, mappers "
              "alternating%s\n",
    voxels, size, size, frames,
    peeling ? ", translucent spheres with depth peeling for volumes" : "");
  std::printf(
    "%-22s %12s %12s %14s %8s\n", "blend mode", "VTK ms", "Tyndall ms", "Tyndall / VTK", "PSNR dB");
  const Mode modes[] = { { "composite (unshaded)", vtkVolumeMapper::COMPOSITE_BLEND, 0.2 },
    { "maximum intensity", vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, 1.0 },
    { "minimum intensity", vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, 1.0 },
    { "average intensity", vtkVolumeMapper::AVERAGE_INTENSITY_BLEND, 1.0 },
    { "additive", vtkVolumeMapper::ADDITIVE_BLEND, 0.05 },
    { "shaded, no shadows", vtkVolumeMapper::COMPOSITE_BLEND, 0.2, true,
      vtkTransmittanceVolumeMapper::NONE },
    { "shaded, AdaptiveETM", vtkVolumeMapper::COMPOSITE_BLEND, 0.2, true,
      vtkTransmittanceVolumeMapper::ADAPTIVE_ETM },
    { "iso, no shadows", vtkVolumeMapper::ISOSURFACE_BLEND, 1.0, true,
      vtkTransmittanceVolumeMapper::NONE },
    { "iso, AdaptiveETM", vtkVolumeMapper::ISOSURFACE_BLEND, 1.0, true,
      vtkTransmittanceVolumeMapper::ADAPTIVE_ETM } };
  // The isosurface modes' surfaces: 45, 60 and 75 % of the range.
  for (int i = 0; i < 3; ++i)
  {
    property->GetIsoSurfaceValues()->SetValue(
      i, range[0] + (0.45 + 0.15 * i) * (range[1] - range[0]));
  }
  for (const Mode& mode : modes)
  {
    opacity->RemoveAllPoints();
    opacity->AddPoint(range[0], 0.0);
    opacity->AddPoint(range[1], mode.PeakOpacity);
    vtkMapper->SetBlendMode(mode.BlendMode);
    tyndall->SetBlendMode(mode.BlendMode);
    tyndall->SetTransmittanceMethod(mode.Method);
    property->SetShade(mode.Shade ? 1 : 0);
    // A first frame of each (shaders, textures), not timed; their pictures.
    volume->SetMapper(vtkMapper);
    FrameTime(window);
    vtkSmartPointer<vtkImageData> vtkImage = tyndall_test::Grab(window);
    volume->SetMapper(tyndall);
    FrameTime(window);
    vtkSmartPointer<vtkImageData> tyndallImage = tyndall_test::Grab(window);
    double vtkTime = 0.0, tyndallTime = 0.0;
    for (int f = 0; f < frames; ++f)
    {
      volume->SetMapper(vtkMapper);
      vtkTime += FrameTime(window);
      volume->SetMapper(tyndall);
      tyndallTime += FrameTime(window);
    }
    vtkTime /= frames;
    tyndallTime /= frames;
    std::printf("%-22s %12.1f %12.1f %14.2f %8.1f\n", mode.Name, 1e3 * vtkTime, 1e3 * tyndallTime,
      tyndallTime / vtkTime, tyndall_test::PSNR(tyndallImage, vtkImage));
  }
  return EXIT_SUCCESS;
}
