// tyndall-render: Tyndall's main job. Renders the built-in default scene, a
// cosine-noise cloud lit by a low sun with single scattering and adaptive
// ETM shadows (vtkTransmittanceVolumeMapper), to a PNG and prints where it is.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoiseSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
void Usage(std::ostream& os)
{
  os << "Usage: tyndall-render [options]\n"
        "Renders Tyndall's built-in default scene (a cosine-noise cloud lit by a low\n"
        "sun: single scattering, adaptive ETM shadows) to an 8-bit PNG and prints\n"
        "the PNG's path. Timings go to stderr.\n\n"
        "Options:\n"
        "  -o, --output FILE    PNG to write (default: tyndall-cloud.png)\n"
        "  -s, --size W H       image size in pixels, 16..8192 (default: 512 512)\n"
        "  -r, --resolution N   voxels per axis of the cloud, 8..512 (default: 128)\n"
        "  -h, --help           show this help\n";
}

bool ParseInt(const char* text, int lo, int hi, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (!text[0] || *end || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}
}

int main(int argc, char* argv[])
{
  std::string output = "tyndall-cloud.png";
  int size[2] = { 512, 512 };
  int resolution = 128;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      Usage(std::cout);
      return EXIT_SUCCESS;
    }
    else if ((arg == "-o" || arg == "--output") && i + 1 < argc)
    {
      output = argv[++i];
    }
    else if ((arg == "-s" || arg == "--size") && i + 2 < argc)
    {
      if (!ParseInt(argv[i + 1], 16, 8192, size[0]) || !ParseInt(argv[i + 2], 16, 8192, size[1]))
      {
        std::cerr << "tyndall-render: --size needs two integers in 16..8192\n";
        return 2;
      }
      i += 2;
    }
    else if ((arg == "-r" || arg == "--resolution") && i + 1 < argc)
    {
      if (!ParseInt(argv[++i], 8, 512, resolution))
      {
        std::cerr << "tyndall-render: --resolution needs an integer in 8..512\n";
        return 2;
      }
    }
    else
    {
      std::cerr << "tyndall-render: unknown or incomplete option '" << arg << "'\n";
      Usage(std::cerr);
      return 2;
    }
  }

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkNew<vtkCosineNoiseSource> cloud;
  const int n = resolution - 1;
  cloud->SetWholeExtent(0, n, 0, n, 0, n);
  cloud->SetSpacing(2.0 / n, 2.0 / n, 2.0 / n);
  cloud->Update();
  timer->StopTimer();
  std::cerr << "cloud: " << resolution << "^3 voxels in " << timer->GetElapsedTime() << " s\n";

  // A white cloud: VTK opacity semantics (0.5 per 0.05 units at density 8),
  // albedo 0.95.
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(8.0, 0.5);
  vtkNew<vtkColorTransferFunction> albedo;
  albedo->AddRGBPoint(0.0, 0.95, 0.95, 0.95);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(albedo);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(0.05);

  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputConnection(cloud->GetOutputPort());
  mapper->SetScatteringModelToSingleScattering();
  mapper->SetTransmittanceMethodToAdaptiveETM();
  mapper->SetNumberOfCoefficients(8);
  mapper->SetTransmittanceMapSize(256);
  mapper->SetScatteringAnisotropy(0.3);
  mapper->SetAmbientIntensity(0.45);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->GradientBackgroundOn();
  renderer->SetBackground(0.55, 0.68, 0.82);
  renderer->SetBackground2(0.16, 0.32, 0.58);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> sun; // a low sun from the front right
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(1.0, 0.3, 0.5);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetColor(1.0, 0.9, 0.75);
  sun->SetIntensity(1.2);
  renderer->AddLight(sun);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -0.6, 4.2);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(size[0], size[1]);
  window->AddRenderer(renderer);
  timer->StartTimer();
  window->Render();
  timer->StopTimer();
  std::cerr << "first frame (maps built in " << mapper->GetLastMapBuildTime()
            << " s): " << size[0] << " x " << size[1] << " in " << timer->GetElapsedTime()
            << " s\n";

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(output.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << "tyndall-render: cannot write " << output << "\n";
    return 1;
  }
  std::cout << vtksys::SystemTools::CollapseFullPath(output) << std::endl;
  return EXIT_SUCCESS;
}
