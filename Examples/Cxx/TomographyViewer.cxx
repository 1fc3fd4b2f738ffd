// tyndall-tomography-viewer: loads a volume in any format VTK (or Tyndall::IO)
// reads and renders it with a transfer-function preset, on screen or into a
// PNG.
//
//   tyndall-tomography-viewer [options] INPUT
//
// INPUT: a DICOM directory (or one .dcm file), .nii / .nii.gz (NIfTI),
// .mhd / .mha (MetaImage), .nrrd / .nhdr (NRRD), .vti (VTK XML image data),
// .vtk (legacy structured points), .slc (SLC) or .vdb (OpenVDB).
//
// Options:
//   --preset NAME     a vtkTransferFunctionPresets preset (CT, MR, Cloud,
//                     Smoke, DenseSmoke); default: Cloud for .vdb, CT when the
//                     data reach below -500 (Hounsfield units), else MR
//   --grid NAME       the OpenVDB grid to read (default: the reader's choice)
//   --output FILE     render once off screen and write a PNG (else interactive)
//   --size W H        window size (default 512 512)
//   --check           with --output: fail (exit 1) when the image shows nothing
//                     but background
//   --skip-missing    exit with 125 (CTest's skip code) when INPUT is absent
//
// Exit status: 0 on success, 1 when reading or rendering fails, 2 for bad
// arguments, 125 with --skip-missing and a missing INPUT.
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDICOMImageReader.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSLCReader.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredPointsReader.h"
#include "vtkTransferFunctionPresets.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLImageDataReader.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace
{
void Usage()
{
  std::cerr << "usage: tyndall-tomography-viewer [--preset NAME] [--grid NAME] [--output FILE.png]"
               " [--size W H] [--check] [--skip-missing] INPUT\n"
               "INPUT: DICOM directory or .dcm, .nii, .nii.gz, .mhd, .mha, .nrrd, .nhdr, .vti, "
               ".vtk, .slc, .vdb\npresets:";
  for (int i = 0; i < vtkTransferFunctionPresets::GetNumberOfPresets(); ++i)
  {
    std::cerr << "\n  " << vtkTransferFunctionPresets::GetPresetName(i) << ": "
              << vtkTransferFunctionPresets::GetPresetDescription(i);
  }
  std::cerr << std::endl;
}

bool EndsWith(const std::string& s, const std::string& tail)
{
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The reader for a path, or null for an unknown kind of file.
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path, const std::string& grid)
{
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    auto reader = vtkSmartPointer<vtkDICOMImageReader>::New();
    reader->SetDirectoryName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".dcm"))
  {
    auto reader = vtkSmartPointer<vtkDICOMImageReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
  {
    auto reader = vtkSmartPointer<vtkNIFTIImageReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".mhd") || EndsWith(lower, ".mha"))
  {
    auto reader = vtkSmartPointer<vtkMetaImageReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    auto reader = vtkSmartPointer<vtkNrrdReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".vti"))
  {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".vtk"))
  {
    auto reader = vtkSmartPointer<vtkStructuredPointsReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".slc"))
  {
    auto reader = vtkSmartPointer<vtkSLCReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (EndsWith(lower, ".vdb"))
  {
    auto reader = vtkSmartPointer<vtkOpenVDBImageReader>::New();
    reader->SetFileName(path.c_str());
    if (!grid.empty())
    {
      reader->SetGridName(grid.c_str());
    }
    return reader;
  }
  return nullptr;
}
}

int main(int argc, char* argv[])
{
  std::string input, preset, grid, output;
  int size[2] = { 512, 512 };
  bool check = false, skipMissing = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--preset" && i + 1 < argc)
    {
      preset = argv[++i];
    }
    else if (arg == "--grid" && i + 1 < argc)
    {
      grid = argv[++i];
    }
    else if (arg == "--output" && i + 1 < argc)
    {
      output = argv[++i];
    }
    else if (arg == "--size" && i + 2 < argc)
    {
      size[0] = std::atoi(argv[++i]);
      size[1] = std::atoi(argv[++i]);
    }
    else if (arg == "--check")
    {
      check = true;
    }
    else if (arg == "--skip-missing")
    {
      skipMissing = true;
    }
    else if (arg == "-h" || arg == "--help")
    {
      Usage();
      return 0;
    }
    else if (!arg.empty() && arg[0] != '-' && input.empty())
    {
      input = arg;
    }
    else
    {
      std::cerr << "unknown or incomplete argument: " << arg << std::endl;
      Usage();
      return 2;
    }
  }
  if (input.empty() || size[0] < 16 || size[1] < 16 || size[0] > 8192 || size[1] > 8192)
  {
    Usage();
    return 2;
  }
  if (!preset.empty() && vtkTransferFunctionPresets::GetPresetIndex(preset.c_str()) < 0)
  {
    std::cerr << "unknown preset: " << preset << std::endl;
    Usage();
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::exists(input, ec))
  {
    std::cerr << input << ": no such file or directory" << std::endl;
    return skipMissing ? 125 : 1;
  }
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(input, grid);
  if (!reader)
  {
    std::cerr << input << ": unknown kind of file" << std::endl;
    Usage();
    return 2;
  }
  reader->Update();
  vtkImageData* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    std::cerr << input << ": could not be read (see the errors above)" << std::endl;
    return 1;
  }
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range, 0);
  if (!(range[0] < range[1]))
  {
    range[1] = range[0] + 1.0; // a constant volume still gets a valid range
  }
  if (preset.empty())
  {
    preset = EndsWith(input, ".vdb") ? "Cloud" : (range[0] < -500.0 ? "CT" : "MR");
  }
  int dims[3];
  double spacing[3];
  image->GetDimensions(dims);
  image->GetSpacing(spacing);
  std::cout << input << ": " << dims[0] << " x " << dims[1] << " x " << dims[2] << ", spacing "
            << spacing[0] << " " << spacing[1] << " " << spacing[2] << ", values " << range[0]
            << " .. " << range[1] << ", preset " << preset << std::endl;

  vtkNew<vtkVolumeProperty> property;
  if (!vtkTransferFunctionPresets::Apply(preset.c_str(), property, range))
  {
    return 1;
  }
  property->SetScalarOpacityUnitDistance((spacing[0] + spacing[1] + spacing[2]) / 3.0);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.1, 0.1, 0.14);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->GetActiveCamera()->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(size[0], size[1]);
  window->AddRenderer(renderer);
  window->SetWindowName("Tyndall tomography viewer");
  if (output.empty())
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    window->Render();
    interactor->Start();
    return 0;
  }
  window->SetOffScreenRendering(1);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(output.c_str());
  writer->Write();
  std::cout << "wrote " << output << std::endl;
  if (check)
  {
    // Something other than the background must show: 0.5% of the pixels.
    vtkUnsignedCharArray* rgb =
      vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
    const unsigned char bg[3] = { 26, 26, 36 }; // the background, 0.1 0.1 0.14, in 8 bits
    vtkIdType lit = 0;
    const int nc = rgb ? rgb->GetNumberOfComponents() : 0;
    for (vtkIdType p = 0; rgb && p < rgb->GetNumberOfTuples(); ++p)
    {
      int diff = 0;
      for (int c = 0; c < 3; ++c)
      {
        diff = std::max(diff, std::abs(int(rgb->GetValue(p * nc + c)) - int(bg[c])));
      }
      lit += diff > 8 ? 1 : 0;
    }
    const vtkIdType total = rgb ? rgb->GetNumberOfTuples() : 0;
    std::cout << lit << " of " << total << " pixels show the volume" << std::endl;
    if (total == 0 || lit < total / 200)
    {
      std::cerr << "the image shows (almost) nothing but the background" << std::endl;
      return 1;
    }
  }
  return 0;
}
