#include "tyndallLoadVolume.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDICOMImageReader.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSetReader.h"
#include "vtkExecutive.h"
#include "vtkImageExtractComponents.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"
#include "vtkSLCReader.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

#ifdef TYNDALL_HAVE_IO
#include "vtkOpenVDBImageReader.h"
#endif

#include <algorithm>
#include <cctype>
#include <cstring>
#include <sstream>
#include <vector>

namespace
{
// Collects the error messages of a reader and its executive (instead of
// printing them) and forwards progress.
class ReaderObserver : public vtkCommand
{
public:
  static ReaderObserver* New() { return new ReaderObserver; }
  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    if (event == vtkCommand::ProgressEvent)
    {
      if (this->Progress && callData)
      {
        this->Progress(*static_cast<double*>(callData));
      }
      return;
    }
    if (event == vtkCommand::ErrorEvent && callData)
    {
      this->Errors.push_back(Simplify(static_cast<const char*>(callData)));
    }
  }

  // VTK's messages read "ERROR: In file, line N\nclass (0x...): text\n\n":
  // keep "text".
  static std::string Simplify(std::string message)
  {
    const auto newline = message.find('\n');
    if (message.rfind("ERROR: In ", 0) == 0 && newline != std::string::npos)
    {
      message = message.substr(newline + 1);
      const auto colon = message.find("): ");
      if (colon != std::string::npos)
      {
        message = message.substr(colon + 3);
      }
    }
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    std::replace(message.begin(), message.end(), '\n', ' ');
    return message;
  }

  std::vector<std::string> Errors;
  std::function<void(double)> Progress;
};

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool EndsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Counts a directory's regular files and those that look like DICOM Part 10
// files ("DICM" at byte 128).
void CountFiles(const std::string& directory, int& files, int& dicomFiles)
{
  files = dicomFiles = 0;
  vtksys::Directory dir;
  if (!dir.Load(directory))
  {
    return;
  }
  for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
  {
    const std::string name = dir.GetFile(i);
    const std::string path = directory + "/" + name;
    if (name == "." || name == ".." || vtksys::SystemTools::FileIsDirectory(path))
    {
      continue;
    }
    ++files;
    if (FILE* file = vtksys::SystemTools::Fopen(path, "rb"))
    {
      char header[132];
      if (fread(header, 1, sizeof(header), file) == sizeof(header) &&
        std::memcmp(header + 128, "DICM", 4) == 0)
      {
        ++dicomFiles;
      }
      fclose(file);
    }
  }
}

// The first numeric array of `data` when none is active; nullptr if none.
vtkDataArray* ScalarsOf(vtkDataSetAttributes* data)
{
  if (vtkDataArray* scalars = data->GetScalars())
  {
    return scalars;
  }
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    if (vtkDataArray* array = data->GetArray(i))
    {
      if (array->GetName())
      {
        data->SetActiveScalars(array->GetName());
      }
      else
      {
        data->SetScalars(array);
      }
      return array;
    }
  }
  return nullptr;
}

// Runs `reader` and returns its output as a detached vtkImageData (or
// nullptr with `error` set).
vtkSmartPointer<vtkImageData> Run(vtkAlgorithm* reader, const std::string& path,
  const tyndallLoadVolumeOptions& options, std::string& error)
{
  vtkNew<ReaderObserver> observer;
  observer->Progress = options.Progress;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::ProgressEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->Update();
  reader->RemoveObserver(observer);
  reader->GetExecutive()->RemoveObserver(observer);

  vtkDataObject* output = reader->GetOutputDataObject(0);
  if (!observer->Errors.empty())
  {
    error = path + ": " + observer->Errors.front();
    return nullptr;
  }
  auto* image = vtkImageData::SafeDownCast(output);
  if (!image)
  {
    error = path + ": not image data (the file holds " +
      (output ? std::string(output->GetClassName()) : std::string("nothing")) + ")";
    return nullptr;
  }
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->ShallowCopy(image);
  return result;
}

// Checks the image and keeps one component; nullptr with `error` on failure.
vtkSmartPointer<vtkImageData> Finish(vtkSmartPointer<vtkImageData> image, const std::string& path,
  const tyndallLoadVolumeOptions& options, std::string& error)
{
  int dims[3];
  image->GetDimensions(dims);
  if (image->GetNumberOfPoints() <= 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    error = path + ": the file could not be read (empty image)";
    return nullptr;
  }
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    std::ostringstream os;
    os << path << ": the image is " << dims[0] << " x " << dims[1] << " x " << dims[2]
       << " points; a volume needs at least 2 points along each axis";
    error = os.str();
    return nullptr;
  }
  // Extent starting at 0, origin moved to the first point (with the
  // direction matrix): the same world positions, and the form every mapper
  // handles (vtkTransmittanceVolumeMapper and others take the origin as the
  // first point's position).
  const int* extent = image->GetExtent();
  if (extent[0] != 0 || extent[2] != 0 || extent[4] != 0)
  {
    double first[3];
    image->TransformIndexToPhysicalPoint(extent[0], extent[2], extent[4], first);
    image->SetExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1);
    image->SetOrigin(first);
  }
  bool cellScalars = false;
  vtkDataArray* scalars = ScalarsOf(image->GetPointData());
  if (!scalars)
  {
    scalars = ScalarsOf(image->GetCellData());
    cellScalars = scalars != nullptr;
  }
  if (!scalars)
  {
    error = path + ": the image has no numeric scalars";
    return nullptr;
  }
  const int components = scalars->GetNumberOfComponents();
  if (options.Component >= components)
  {
    std::ostringstream os;
    os << path << ": component " << options.Component << " requested, but the scalars ('"
       << (scalars->GetName() ? scalars->GetName() : "") << "') have " << components << " component"
       << (components == 1 ? "" : "s");
    error = os.str();
    return nullptr;
  }
  if (components == 1)
  {
    return image;
  }
  if (options.Component < 0)
  {
    std::ostringstream os;
    os << path << ": the scalars ('" << (scalars->GetName() ? scalars->GetName() : "") << "') have "
       << components << " components; choose one (--component 0.." << components - 1 << ")";
    error = os.str();
    return nullptr;
  }
  if (cellScalars)
  {
    // vtkImageExtractComponents works on point scalars only.
    vtkSmartPointer<vtkDataArray> one;
    one.TakeReference(scalars->NewInstance());
    one->SetNumberOfComponents(1);
    one->SetNumberOfTuples(scalars->GetNumberOfTuples());
    one->CopyComponent(0, scalars, options.Component);
    one->SetName(scalars->GetName());
    auto result = vtkSmartPointer<vtkImageData>::New();
    result->CopyStructure(image);
    result->GetCellData()->SetScalars(one);
    return result;
  }
  vtkNew<vtkImageExtractComponents> extract;
  extract->SetInputData(image);
  extract->SetComponents(options.Component);
  extract->Update();
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->ShallowCopy(extract->GetOutput());
  return result;
}
}

bool tyndallLoadVolumeCanReadVDB()
{
#ifdef TYNDALL_HAVE_IO
  return true;
#else
  return false;
#endif
}

std::string tyndallLoadVolumeFormats()
{
  std::string formats;
  formats += tyndallLoadVolumeCanReadVDB()
    ? "  .vdb           OpenVDB (vtkOpenVDBImageReader; --grid NAME picks the grid)\n"
    : "  .vdb           OpenVDB (not available: this build has no Tyndall::IO)\n";
  formats += "  .vti           VTK XML image data (vtkXMLImageDataReader)\n"
             "  .mhd .mha      MetaImage (vtkMetaImageReader)\n"
             "  .nrrd .nhdr    NRRD (vtkNrrdReader)\n"
             "  .nii .nii.gz   NIfTI-1 (vtkNIFTIImageReader)\n"
             "  .vtk           legacy VTK structured points (vtkDataSetReader)\n"
             "  .slc           SLC (vtkSLCReader)\n"
             "  DIRECTORY      DICOM series, one slice per file (vtkDICOMImageReader)\n";
  return formats;
}

vtkSmartPointer<vtkImageData> tyndallLoadVolume(
  const std::string& path, const std::string& gridName, std::string& error)
{
  tyndallLoadVolumeOptions options;
  options.GridName = gridName;
  return tyndallLoadVolume(path, options, error);
}

vtkSmartPointer<vtkImageData> tyndallLoadVolume(
  const std::string& path, const tyndallLoadVolumeOptions& options, std::string& error)
{
  error.clear();
  if (path.empty())
  {
    error = "no input path given";
    return nullptr;
  }
  if (!vtksys::SystemTools::PathExists(path))
  {
    error = path + ": no such file or directory";
    return nullptr;
  }
  const std::string lower = Lower(path);
  if (!options.GridName.empty() && !EndsWith(lower, ".vdb"))
  {
    error = path + ": a grid name is only meaningful for .vdb files";
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image;
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    int files = 0, dicomFiles = 0;
    CountFiles(path, files, dicomFiles);
    if (files == 0)
    {
      error = path + ": the directory holds no files (expected a DICOM series)";
      return nullptr;
    }
    if (dicomFiles == 0)
    {
      error = path + ": none of the directory's " + std::to_string(files) +
        " files is a DICOM file (no 'DICM' marker at byte 128)";
      return nullptr;
    }
    vtkNew<vtkDICOMImageReader> reader;
    // Files that are not DICOM (a DICOMDIR, notes) are skipped with a
    // warning each: keep them quiet.
    vtkNew<ReaderObserver> quiet;
    reader->AddObserver(vtkCommand::WarningEvent, quiet);
    reader->SetDirectoryName(path.c_str());
    image = Run(reader, path, options, error);
    if (image && image->GetNumberOfPoints() <= 0)
    {
      error = path + ": no DICOM images found in the directory";
      return nullptr;
    }
  }
  else
  {
    // A file: it must be readable.
    FILE* file = vtksys::SystemTools::Fopen(path, "rb");
    if (!file)
    {
      error = path + ": cannot open the file";
      return nullptr;
    }
    fclose(file);

    if (EndsWith(lower, ".vdb"))
    {
#ifdef TYNDALL_HAVE_IO
      vtkNew<vtkOpenVDBImageReader> reader;
      reader->SetFileName(path.c_str());
      if (!options.GridName.empty())
      {
        reader->SetGridName(options.GridName.c_str());
      }
      image = Run(reader, path, options, error);
#else
      error = path + ": .vdb files need Tyndall::IO, which this build does not have";
      return nullptr;
#endif
    }
    else if (EndsWith(lower, ".vti"))
    {
      vtkNew<vtkXMLImageDataReader> reader;
      if (!reader->CanReadFile(path.c_str()))
      {
        error = path + ": not a VTK XML image data file";
        return nullptr;
      }
      reader->SetFileName(path.c_str());
      image = Run(reader, path, options, error);
    }
    else if (EndsWith(lower, ".mhd") || EndsWith(lower, ".mha"))
    {
      vtkNew<vtkMetaImageReader> reader;
      if (!reader->CanReadFile(path.c_str()))
      {
        error = path + ": not a MetaImage file";
        return nullptr;
      }
      reader->SetFileName(path.c_str());
      image = Run(reader, path, options, error);
    }
    else if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
    {
      vtkNew<vtkNrrdReader> reader;
      if (!reader->CanReadFile(path.c_str()))
      {
        error = path + ": not a NRRD file";
        return nullptr;
      }
      reader->SetFileName(path.c_str());
      image = Run(reader, path, options, error);
    }
    else if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
    {
      vtkNew<vtkNIFTIImageReader> reader;
      if (!reader->CanReadFile(path.c_str()))
      {
        error = path + ": not a NIfTI file";
        return nullptr;
      }
      reader->SetFileName(path.c_str());
      image = Run(reader, path, options, error);
    }
    else if (EndsWith(lower, ".vtk"))
    {
      vtkNew<vtkDataSetReader> reader;
      reader->SetFileName(path.c_str());
      vtkNew<ReaderObserver> quiet; // ReadOutputType reports errors of its own
      reader->AddObserver(vtkCommand::ErrorEvent, quiet);
      const int type = reader->ReadOutputType();
      reader->RemoveObserver(quiet);
      if (type < 0)
      {
        error = path + ": not a legacy VTK data file" +
          (quiet->Errors.empty() ? std::string() : " (" + quiet->Errors.front() + ")");
        return nullptr;
      }
      if (type != VTK_STRUCTURED_POINTS && type != VTK_IMAGE_DATA)
      {
        error = path + ": not image data (the legacy file holds a " +
          std::string(vtkDataObjectTypes::GetClassNameFromTypeId(type)) +
          ", not structured points)";
        return nullptr;
      }
      image = Run(reader, path, options, error);
    }
    else if (EndsWith(lower, ".slc"))
    {
      vtkNew<vtkSLCReader> reader;
      if (!reader->CanReadFile(path.c_str()))
      {
        error = path + ": not an SLC file";
        return nullptr;
      }
      reader->SetFileName(path.c_str());
      image = Run(reader, path, options, error);
    }
    else
    {
      error = path + ": unknown volume format (extension '" +
        vtksys::SystemTools::GetFilenameLastExtension(path) +
        "'); known: .vdb .vti .mhd .mha .nrrd .nhdr .nii .nii.gz .vtk .slc or a DICOM directory";
      return nullptr;
    }
  }
  if (!image)
  {
    if (error.empty())
    {
      error = path + ": the file could not be read";
    }
    return nullptr;
  }
  return Finish(image, path, options, error);
}
