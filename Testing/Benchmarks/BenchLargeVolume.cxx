// Benchmark of a large volume (issue 37): one frame of a smooth volume of
// X x Y x Z samples of an integer or float type, drawn by
// vtkTransmittanceVolumeMapper or by VTK 9.1's vtkGPUVolumeRayCastMapper, in
// a process of its own so that its peak resident memory is its own. Prints
// the data's size, the first frame's time, a second frame's time and the
// process's peak resident memory (getrusage), and writes the picture.
// Prints figures; it is not a test.
//
//   BenchLargeVolume [--dims X Y Z] [--type uchar|char|schar|ushort|short|float]
//                    [--mapper tyndall|vtk] [--size N] [--output FILE.png]
//                    [--sparse [--blob-width W]] [--bricking off|on|auto]
//                    [--write-vdb FILE.vdb]
//   BenchLargeVolume --compare [--voxels N] [--size N] [--output-dir DIR]
//
// --sparse: the blobs a tenth as wide and 0 where their level is below 1
// (a sparse cache: about 0.5 % of the samples are not 0, OpenVDB's active
// voxels), and Tyndall's figures add the bytes its volume texture takes on
// the GPU (vtkTransmittanceVolumeMapper::GetVolumeTextureBytes(); bricked
// or dense: --bricking, the mapper's SetVolumeBricking(), default auto)
// against a dense grid of the samples that are not 0. --blob-width W: the
// sparse blobs W times as wide as the dense ones (default 0.1: about 0.2 %
// of the box not 0; 0.17: about 1 %, the 10^7 active voxels in a
// 10^9-voxel box at --voxels 1000). --write-vdb: writes the volume (float)
// as an OpenVDB fog volume (its samples not 0 the active voxels, and its two
// corners, so that the file's box is the volume's; vtkOpenVDBImageWriter)
// instead of drawing it, for tyndall-render and vtkOpenVDBImageReader.
//
// The volume: four Gaussian blobs over [-1, 1]^3 (a level of 200 at a
// blob's centre, clamped to [0, 255], mapped into each type's range: see
// Types; the transfer functions mapped alike), a plain
// vtkVolumeProperty (shade off: VTK's unlit picture, drawn alike by both
// mappers), the camera at an angle. --compare runs this program three times
// (Tyndall at N^3, Tyndall at (N/2)^3, VTK at N^3; N default 1024, unsigned
// char) and prints Tyndall's peak resident memory and first frame over
// VTK's and the PSNR of the N^3 picture against the (N/2)^3 one and against
// VTK's (failing below 30 and 35 dB). A volume the GPU cannot hold ends
// with the mapper's error, never a black picture.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageWriter.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestImage.h"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
struct Options
{
  int Dims[3] = { 1024, 1024, 1024 };
  std::string Type = "uchar";
  std::string Mapper = "tyndall";
  int Size = 400;
  std::string Output = "BenchLargeVolume.png";
  bool Compare = false;
  std::string OutputDir = ".";
  bool Sparse = false;
  double BlobWidth = 0.1; // the sparse blobs' width over the dense ones'
  std::string WriteVdb;
  int Bricking = vtkTransmittanceVolumeMapper::BRICKING_AUTO;
};

// Peak resident memory of this process in MiB.
double PeakResidentMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// The blobs' level at every sample, a sum of separable Gaussians (each blob
// a product of three per-axis tables) clamped to [0, 255], as T: level *
// scale + offset (within T: see Types).
template <typename T>
void FillBlobs(
  T* out, const int dims[3], double scale, double offset, bool sparse, double sparseWidth)
{
  double blobs[4][4] = { { -0.4, -0.3, -0.2, 0.5 }, { 0.35, 0.3, 0.1, 0.45 },
    { 0.0, 0.1, 0.45, 0.4 }, { 0.2, -0.45, -0.4, 0.35 } };
  for (auto& blob : blobs)
  {
    blob[3] *= sparse ? sparseWidth : 1.0;
  }
  std::vector<float> axis[4][3];
  for (int b = 0; b < 4; ++b)
  {
    for (int a = 0; a < 3; ++a)
    {
      axis[b][a].resize(dims[a]);
      for (int i = 0; i < dims[a]; ++i)
      {
        const double x = dims[a] > 1 ? -1.0 + 2.0 * i / (dims[a] - 1) : 0.0;
        const double d = (x - blobs[b][a]) / blobs[b][3];
        axis[b][a][i] = static_cast<float>(std::exp(-d * d));
      }
    }
  }
  vtkSMPTools::For(0, dims[2],
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType z = first; z < last; ++z)
      {
        T* slice = out + static_cast<size_t>(z) * dims[0] * dims[1];
        for (int y = 0; y < dims[1]; ++y)
        {
          for (int x = 0; x < dims[0]; ++x)
          {
            float v = 0.0f;
            for (int b = 0; b < 4; ++b)
            {
              v += axis[b][0][x] * axis[b][1][y] * axis[b][2][z];
            }
            double level = std::min(std::max(200.0 * v, 0.0), 255.0);
            level = sparse && level < 1.0 ? 0.0 : level;
            slice[static_cast<size_t>(y) * dims[0] + x] = static_cast<T>(level * scale + offset);
          }
        }
      }
    });
}

// A scalar type of --type: the blobs' level L (0..255) is stored as
// L * Scale + Offset, so that each type's range is used (negative values
// in the signed ones, large ones in the 16-bit ones) within the type.
struct Type
{
  const char* Name;
  int Id;
  double Scale;
  double Offset;
};
const Type Types[] = { { "uchar", VTK_UNSIGNED_CHAR, 1.0, 0.0 }, { "char", VTK_CHAR, 0.5, -64.0 },
  { "schar", VTK_SIGNED_CHAR, 0.5, -64.0 }, { "ushort", VTK_UNSIGNED_SHORT, 200.0, 0.0 },
  { "short", VTK_SHORT, 100.0, -12000.0 }, { "float", VTK_FLOAT, 1.0, 0.0 } };

const Type* FindType(const std::string& name)
{
  for (const Type& type : Types)
  {
    if (name == type.Name)
    {
      return &type;
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkImageData> MakeVolume(const Options& o, const Type& type)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(o.Dims);
  image->SetOrigin(-1.0, -1.0, -1.0);
  image->SetSpacing(2.0 / std::max(o.Dims[0] - 1, 1), 2.0 / std::max(o.Dims[1] - 1, 1),
    2.0 / std::max(o.Dims[2] - 1, 1));
  image->AllocateScalars(type.Id, 1);
  void* data = image->GetScalarPointer();
  switch (type.Id)
  {
    vtkTemplateMacro(FillBlobs(
      static_cast<VTK_TT*>(data), o.Dims, type.Scale, type.Offset, o.Sparse, o.BlobWidth));
  }
  return image;
}

// --write-vdb: the volume as an OpenVDB file.
int WriteVdb(const Options& o)
{
  const Type* type = FindType("float");
  vtkSmartPointer<vtkImageData> data = MakeVolume(o, *type);
  // The box's two corners active (a level of 0.5, where the opacity is 0):
  // the file's box is the whole volume, not the blobs' box.
  vtkDataArray* values = data->GetPointData()->GetScalars();
  values->SetTuple1(0, 0.5);
  values->SetTuple1(values->GetNumberOfTuples() - 1, 0.5);
  vtkNew<vtkOpenVDBImageWriter> writer;
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(writer);
  writer->SetInputData(data);
  writer->SetFileName(o.WriteVdb.c_str());
  writer->SetGridName("density");
  writer->Write();
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  vtkIdType active = 0;
  for (vtkIdType n = 0; n < scalars->GetNumberOfTuples(); ++n)
  {
    active += scalars->GetTuple1(n) != 0.0 ? 1 : 0;
  }
  std::printf("wrote %s: %d x %d x %d float, %lld samples not 0 (active voxels)%s\n",
    o.WriteVdb.c_str(), o.Dims[0], o.Dims[1], o.Dims[2], static_cast<long long>(active),
    errors->HasErrors() ? "  (error)" : "");
  return errors->HasErrors() ? EXIT_FAILURE : EXIT_SUCCESS;
}

// One volume, one mapper: the figures and the picture.
int RenderOne(const Options& o)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const Type* type = FindType(o.Type);
  if (!type)
  {
    std::printf("BenchLargeVolume: unknown --type %s\n", o.Type.c_str());
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkImageData> data = MakeVolume(o, *type);
  timer->StopTimer();
  // The functions over the levels, mapped as the values are.
  auto at = [type](double level) { return level * type->Scale + type->Offset; };
  const double mib = data->GetPointData()->GetScalars()->GetDataSize() *
    data->GetPointData()->GetScalars()->GetDataTypeSize() / (1024.0 * 1024.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(at(0.0), 0.2, 0.3, 0.9);
  color->AddRGBPoint(at(100.0), 0.9, 0.8, 0.3);
  color->AddRGBPoint(at(255.0), 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(at(0.0), 0.0);
  opacity->AddPoint(at(20.0), 0.0);
  opacity->AddPoint(at(255.0), 0.6);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.05);
  property->SetInterpolationTypeToLinear();
  vtkSmartPointer<vtkVolumeMapper> mapper;
  if (o.Mapper == "vtk")
  {
    mapper = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
  }
  else
  {
    mapper = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
  }
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(mapper);
  mapper->SetInputData(data);
  auto* tyndall = vtkTransmittanceVolumeMapper::SafeDownCast(mapper);
  if (tyndall)
  {
    tyndall->SetVolumeBricking(o.Bricking);
  }
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(o.Size, o.Size);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.4);
  double times[2];
  for (double& t : times)
  {
    timer->StartTimer();
    window->Render();
    window->WaitForCompletion();
    timer->StopTimer();
    t = timer->GetElapsedTime();
  }
  vtkSmartPointer<vtkImageData> picture = tyndall_test::Grab(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(o.Output.c_str());
  writer->SetInputData(picture);
  writer->Write();
  std::printf("%-8s %5d x %5d x %5d %-6s %9.1f MiB  first frame %7.2f s  second %7.2f s  peak "
              "resident %8.1f MiB  %s%s\n",
    o.Mapper.c_str(), o.Dims[0], o.Dims[1], o.Dims[2], o.Type.c_str(), mib, times[0], times[1],
    PeakResidentMiB(), o.Output.c_str(), errors->HasErrors() ? "  (error)" : "");
  if (tyndall && o.Sparse)
  {
    // The samples that are not 0 (the blobs' level of 0 is `Offset`).
    vtkDataArray* scalars = data->GetPointData()->GetScalars();
    vtkIdType active = 0;
    for (vtkIdType n = 0; n < scalars->GetNumberOfTuples(); ++n)
    {
      active += scalars->GetTuple1(n) != type->Offset ? 1 : 0;
    }
    const double texture = tyndall->GetVolumeTextureBytes() / (1024.0 * 1024.0);
    const double activeMiB = active * scalars->GetDataTypeSize() / (1024.0 * 1024.0);
    std::printf(
      "         GPU volume texture %.1f MiB (%s), %lld samples not 0 (%.3f %% of the box; "
      "a dense grid of them %.1f MiB): %.2fx\n",
      texture, tyndall->GetVolumeBricked() ? "bricked" : "dense", static_cast<long long>(active),
      100.0 * active / scalars->GetNumberOfTuples(), activeMiB, texture / activeMiB);
  }
  // The figures for --compare, beside the picture.
  if (FILE* figures = std::fopen((o.Output + ".txt").c_str(), "w"))
  {
    std::fprintf(figures, "%f %f\n", PeakResidentMiB(), times[0]);
    std::fclose(figures);
  }
  if (errors->HasErrors())
  {
    std::printf("  error: %s\n", errors->GetMessages().front().c_str());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

vtkSmartPointer<vtkImageData> ReadPNG(const std::string& name)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(name.c_str());
  reader->Update();
  return reader->GetOutput();
}

// Three runs of this program (each its own process) and their comparison.
int Compare(const char* self, const Options& o)
{
  const int n = o.Dims[0];
  struct Run
  {
    const char* Mapper;
    int Voxels;
    std::string Picture;
  };
  std::vector<Run> runs = { { "tyndall", n, "" }, { "tyndall", n / 2, "" }, { "vtk", n, "" } };
  for (Run& run : runs)
  {
    // The type is in the name: ctest runs one comparison per type at once,
    // into one folder (a shared name let one run read another's half-written
    // picture).
    run.Picture = o.OutputDir + "/large-" + o.Type + "-" + run.Mapper + "-" +
      std::to_string(run.Voxels) + ".png";
    // (VTK's mapper refuses VTK_CHAR, whose sign depends on the platform:
    // it draws the same values as signed char.)
    const std::string type =
      o.Type == "char" && run.Mapper == std::string("vtk") ? "schar" : o.Type;
    const std::string command = std::string(self) + " --mapper " + run.Mapper + " --type " + type +
      " --size " + std::to_string(o.Size) + " --dims " + std::to_string(run.Voxels) + " " +
      std::to_string(run.Voxels) + " " + std::to_string(run.Voxels) + " --output " + run.Picture;
    std::fflush(stdout);
    if (std::system(command.c_str()) != 0)
    {
      std::printf("BenchLargeVolume: the %s run at %d^3 failed\n", run.Mapper, run.Voxels);
      return EXIT_FAILURE;
    }
  }
  double figures[3][2] = {};
  for (int r = 0; r < 3; ++r)
  {
    if (FILE* f = std::fopen((runs[r].Picture + ".txt").c_str(), "r"))
    {
      if (std::fscanf(f, "%lf %lf", &figures[r][0], &figures[r][1]) != 2)
      {
        figures[r][0] = figures[r][1] = 0.0;
      }
      std::fclose(f);
    }
  }
  std::printf("Tyndall / VTK at %d^3: peak resident memory %.2f, first frame %.2f\n", n,
    figures[0][0] / figures[2][0], figures[0][1] / figures[2][1]);
  vtkSmartPointer<vtkImageData> full = ReadPNG(runs[0].Picture);
  const double half = tyndall_test::PSNR(full, ReadPNG(runs[1].Picture));
  const double vtk = tyndall_test::PSNR(full, ReadPNG(runs[2].Picture));
  std::printf("PSNR: Tyndall %d^3 against Tyndall %d^3 %.1f dB, against VTK %d^3 %.1f dB\n", n,
    n / 2, half, n, vtk);
  // The bar for the half resolution; VTK's unlit picture is the
  // same scene: a volume stored or read wrong is far from both.
  if (half < 30.0 || vtk < 35.0)
  {
    std::printf("BenchLargeVolume: the pictures disagree (floors: 30 dB at half the resolution, "
                "35 dB against VTK): failed\n");
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--dims" && i + 3 < argc)
    {
      for (int d = 0; d < 3; ++d)
      {
        o.Dims[d] = std::atoi(argv[++i]);
      }
    }
    else if (a == "--voxels" && i + 1 < argc)
    {
      o.Dims[0] = o.Dims[1] = o.Dims[2] = std::atoi(argv[++i]);
    }
    else if (a == "--type" && i + 1 < argc)
    {
      o.Type = argv[++i];
    }
    else if (a == "--mapper" && i + 1 < argc)
    {
      o.Mapper = argv[++i];
    }
    else if (a == "--size" && i + 1 < argc)
    {
      o.Size = std::atoi(argv[++i]);
    }
    else if (a == "--output" && i + 1 < argc)
    {
      o.Output = argv[++i];
    }
    else if (a == "--output-dir" && i + 1 < argc)
    {
      o.OutputDir = argv[++i];
    }
    else if (a == "--compare")
    {
      o.Compare = true;
    }
    else if (a == "--sparse")
    {
      o.Sparse = true;
    }
    else if (a == "--write-vdb" && i + 1 < argc)
    {
      o.WriteVdb = argv[++i];
    }
    else if (a == "--blob-width" && i + 1 < argc)
    {
      o.BlobWidth = std::atof(argv[++i]);
    }
    else if (a == "--bricking" && i + 1 < argc)
    {
      const std::string m = argv[++i];
      o.Bricking = m == "off" ? vtkTransmittanceVolumeMapper::BRICKING_OFF
                              : (m == "on" ? vtkTransmittanceVolumeMapper::BRICKING_ON
                                           : vtkTransmittanceVolumeMapper::BRICKING_AUTO);
    }
    else
    {
      std::printf(
        "Usage: BenchLargeVolume [--dims X Y Z | --voxels N] [--type "
        "uchar|char|schar|ushort|short|float] [--mapper tyndall|vtk] [--size N] [--output "
        "FILE.png] [--sparse [--blob-width W]] [--write-vdb FILE.vdb] [--bricking off|on|auto] "
        "[--compare [--output-dir "
        "DIR]]\n");
      return EXIT_FAILURE;
    }
  }
  if (o.Dims[0] < 2 || o.Dims[1] < 2 || o.Dims[2] < 2 || o.Size < 16 || o.Size > 4096 ||
    (o.Mapper != "tyndall" && o.Mapper != "vtk") || !(o.BlobWidth > 0.0 && o.BlobWidth <= 1.0))
  {
    std::printf("BenchLargeVolume: --dims of 2 or more, --size 16..4096, --mapper tyndall|vtk, "
                "--blob-width in (0, 1]\n");
    return EXIT_FAILURE;
  }
  if (!o.WriteVdb.empty())
  {
    return WriteVdb(o);
  }
  return o.Compare ? Compare(argv[0], o) : RenderOne(o);
}
