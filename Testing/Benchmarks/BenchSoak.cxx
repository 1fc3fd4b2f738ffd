// Soak benchmark: create-render-destroy cycles of a volume, its mapper and
// renderer in one window, for Tyndall's mapper (cycling through every
// transmittance method) and, as the yardstick, VTK's own
// vtkGPUVolumeRayCastMapper. Prints the resident memory and the number of
// live OpenGL objects (textures, buffers, framebuffers, programs, vertex
// arrays) after a warm-up and after the cycles. Prints figures; it is not a
// test (the growth it reports is judged against VTK's mapper in
// Documentation/testing.md).
//
//   BenchSoak [--cycles N] [--size N] [--resolution N]
//
// Defaults: 1000 cycles per mapper, a 128 x 128 window, the built-in cloud
// at 64^3. Run under xvfb-run.
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoiseSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDisplay.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
// Resident memory in MiB (/proc/self/statm), 0 where unavailable.
double ResidentMiB()
{
  long pages = 0, resident = 0;
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (f)
  {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
    {
      resident = 0;
    }
    std::fclose(f);
  }
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Live OpenGL objects among the first 16384 names of each kind.
struct GLObjects
{
  int Textures = 0, Buffers = 0, Framebuffers = 0, Programs = 0, VertexArrays = 0;
  int Total() const { return Textures + Buffers + Framebuffers + Programs + VertexArrays; }
};

GLObjects CountGLObjects(vtkRenderWindow* window)
{
  window->MakeCurrent();
  GLObjects n;
  for (GLuint id = 1; id <= 16384; ++id)
  {
    n.Textures += glIsTexture(id) ? 1 : 0;
    n.Buffers += glIsBuffer(id) ? 1 : 0;
    n.Framebuffers += glIsFramebuffer(id) ? 1 : 0;
    n.Programs += glIsProgram(id) ? 1 : 0;
    n.VertexArrays += glIsVertexArray(id) ? 1 : 0;
  }
  return n;
}

// One cycle: a renderer, a volume and its mapper created, rendered once,
// released and destroyed.
void Cycle(vtkRenderWindow* window, vtkImageData* cloud, bool tyndall, int method)
{
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(8.0, 0.5);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  vtkNew<vtkVolume> volume;
  vtkSmartPointer<vtkVolumeProperty> property;
  vtkSmartPointer<vtkVolumeMapper> mapper;
  if (tyndall)
  {
    auto medium = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
    property = medium;
    auto m = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
    m->SetTransmittanceMethod(method);
    m->SetTransmittanceMapSize(64);
    mapper = m;
  }
  else
  {
    property = vtkSmartPointer<vtkVolumeProperty>::New();
    property->ShadeOn();
    mapper = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(0.05);
  mapper->SetInputData(cloud);
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  renderer->ResetCamera();
  window->Render();
  renderer->RemoveVolume(volume);
  volume->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
}

struct Figures
{
  double MiB[2];
  GLObjects Objects[2];
  double Seconds;
};

Figures Soak(vtkRenderWindow* window, vtkImageData* cloud, bool tyndall, int cycles)
{
  Figures f;
  const int warmUp = 12;
  for (int c = 0; c < warmUp; ++c)
  {
    Cycle(window, cloud, tyndall, c % 6);
  }
  f.MiB[0] = ResidentMiB();
  f.Objects[0] = CountGLObjects(window);
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  for (int c = 0; c < cycles; ++c)
  {
    Cycle(window, cloud, tyndall, c % 6);
  }
  timer->StopTimer();
  f.Seconds = timer->GetElapsedTime();
  f.MiB[1] = ResidentMiB();
  f.Objects[1] = CountGLObjects(window);
  return f;
}

void Print(const char* name, int cycles, const Figures& f)
{
  const GLObjects& a = f.Objects[0];
  const GLObjects& b = f.Objects[1];
  std::cout << "| " << name << " | " << cycles << " | " << std::fixed << std::setprecision(1)
            << f.MiB[0] << " | " << f.MiB[1] << " | " << std::setprecision(2)
            << 1024.0 * (f.MiB[1] - f.MiB[0]) / cycles << " | " << a.Textures << " -> "
            << b.Textures << " | " << a.Buffers << " -> " << b.Buffers << " | " << a.Framebuffers
            << " -> " << b.Framebuffers << " | " << a.Programs << " -> " << b.Programs << " | "
            << a.VertexArrays << " -> " << b.VertexArrays << " | " << std::setprecision(1)
            << 1000.0 * f.Seconds / cycles << " |\n";
}
}

int main(int argc, char* argv[])
{
  int cycles = 1000, size = 128, resolution = 64;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 < argc && (arg == "--cycles" || arg == "--size" || arg == "--resolution"))
    {
      const int value = std::atoi(argv[++i]);
      (arg == "--cycles" ? cycles : arg == "--size" ? size : resolution) = value;
    }
    else
    {
      std::cerr << "usage: BenchSoak [--cycles N] [--size N] [--resolution N]\n";
      return 2;
    }
  }
  if (cycles < 1 || size < 16 || resolution < 8)
  {
    std::cerr << "BenchSoak: --cycles >= 1, --size >= 16, --resolution >= 8\n";
    return 2;
  }
  vtkNew<vtkTyndallDisplay> display;
  if (!display->Open())
  {
    std::cerr << "BenchSoak: " << display->GetErrorMessage() << "\n";
    return 1;
  }
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(0, resolution - 1, 0, resolution - 1, 0, resolution - 1);
  const double spacing = 1.0 / (resolution - 1);
  source->SetSpacing(spacing, spacing, spacing);
  source->Update();
  vtkImageData* cloud = source->GetOutput();

  vtkNew<vtkRenderWindow> window;
  display->Attach(window);
  window->SetOffScreenRendering(1);
  window->SetSize(size, size);
  window->Render();

  std::cout << "BenchSoak: " << cycles << " create-render-destroy cycles per mapper in one " << size
            << " x " << size << " window, cloud " << resolution << "^3 (after "
            << "12 warm-up cycles; Tyndall cycles through its 6 methods)\n\n"
            << "| mapper | cycles | RSS after warm-up (MiB) | RSS after (MiB) | growth per "
               "cycle (KiB) | textures | buffers | framebuffers | programs | vertex arrays | "
               "ms per cycle |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  const Figures vtk = Soak(window, cloud, false, cycles);
  Print("vtkGPUVolumeRayCastMapper", cycles, vtk);
  const Figures tyndall = Soak(window, cloud, true, cycles);
  Print("vtkTransmittanceVolumeMapper", cycles, tyndall);
  return 0;
}
