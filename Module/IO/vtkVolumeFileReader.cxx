#include "vtkVolumeFileReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDICOMImageReader.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSetReader.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPointData.h"
#include "vtkSLCReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkVolumeFileReader);

namespace
{
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

// The extensions and their formats (directories are DICOM).
struct Format
{
  const char* Extension;
  const char* Name;
};
const Format kFormats[] = { { ".vdb", "OpenVDB" }, { ".vti", "VTK XML" }, { ".mhd", "MetaImage" },
  { ".mha", "MetaImage" }, { ".nrrd", "NRRD" }, { ".nhdr", "NRRD" }, { ".nii", "NIfTI" },
  { ".nii.gz", "NIfTI" }, { ".vtk", "VTK legacy" }, { ".slc", "SLC" } };

const char* FormatOf(const std::string& lowerPath)
{
  for (const Format& f : kFormats)
  {
    if (EndsWith(lowerPath, f.Extension))
    {
      return f.Name;
    }
  }
  return nullptr;
}

void AddString(vtkFieldData* data, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  data->AddArray(array);
}
}

//------------------------------------------------------------------------------
vtkVolumeFileReader::vtkVolumeFileReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkVolumeFileReader::~vtkVolumeFileReader()
{
  this->SetFileName(nullptr);
  this->SetGridName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::CanReadFile(const char* path)
{
  return path && *path &&
    (vtksys::SystemTools::FileIsDirectory(path) || FormatOf(Lower(path)) != nullptr);
}

//------------------------------------------------------------------------------
const char* vtkVolumeFileReader::GetFormatsDescription()
{
  return "  .vdb           OpenVDB (--grid NAME picks the grid)\n"
         "  .vti           VTK XML image data\n"
         "  .mhd .mha      MetaImage\n"
         "  .nrrd .nhdr    NRRD\n"
         "  .nii .nii.gz   NIfTI-1\n"
         "  .vtk           legacy VTK structured points\n"
         "  .slc           SLC\n"
         "  DIRECTORY      DICOM series, one slice per file\n";
}

//------------------------------------------------------------------------------
int vtkVolumeFileReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (this->ReadTime < this->GetMTime() || !this->Image)
  {
    this->Image = nullptr;
    this->FormatName.clear();
    this->Modality.clear();
    this->Error.clear();
    const bool ok = this->Read();
    this->ReadTime = this->GetMTime();
    if (!ok)
    {
      this->Image = nullptr;
    }
  }
  if (!this->Image)
  {
    vtkErrorMacro(<< this->Error);
    return 0;
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Image->GetExtent(), 6);
  info->Set(vtkDataObject::SPACING(), this->Image->GetSpacing(), 3);
  info->Set(vtkDataObject::ORIGIN(), this->Image->GetOrigin(), 3);
  info->Set(vtkDataObject::DIRECTION(), this->Image->GetDirectionMatrix()->GetData(), 9);
  return 1;
}

//------------------------------------------------------------------------------
int vtkVolumeFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!this->Image || !output)
  {
    return 0;
  }
  output->ShallowCopy(this->Image);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::Read()
{
  const std::string path = this->FileName ? this->FileName : "";
  if (path.empty())
  {
    this->Error = "no input path given";
    return false;
  }
  if (!vtksys::SystemTools::PathExists(path))
  {
    this->Error = path + ": no such file or directory";
    return false;
  }
  const bool directory = vtksys::SystemTools::FileIsDirectory(path);
  if (this->GridName && *this->GridName && (directory || !EndsWith(Lower(path), ".vdb")))
  {
    this->Error = path + ": a grid name is only meaningful for .vdb files";
    return false;
  }
  if (!(directory ? this->ReadDirectory(path) : this->ReadFile(path)))
  {
    if (this->Error.empty())
    {
      this->Error = path + ": the file could not be read";
    }
    return false;
  }
  return this->Finish(path);
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadDirectory(const std::string& path)
{
  int files = 0, dicomFiles = 0;
  CountFiles(path, files, dicomFiles);
  if (files == 0)
  {
    this->Error = path + ": the directory holds no files (expected a DICOM series)";
    return false;
  }
  if (dicomFiles == 0)
  {
    this->Error = path + ": none of the directory's " + std::to_string(files) +
      " files is a DICOM file (no 'DICM' marker at byte 128)";
    return false;
  }
  vtkNew<vtkDICOMImageReader> reader;
  // Files that are not DICOM (a DICOMDIR, notes) are skipped with a warning
  // each: keep them quiet.
  vtkNew<vtkTyndallErrorObserver> quiet;
  reader->AddObserver(vtkCommand::WarningEvent, quiet);
  reader->SetDirectoryName(path.c_str());
  if (!this->RunReader(reader, path, "DICOM"))
  {
    return false;
  }
  if (this->Image->GetNumberOfPoints() <= 0)
  {
    this->Error = path + ": no DICOM images found in the directory";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadFile(const std::string& path)
{
  // A file: it must be readable.
  FILE* file = vtksys::SystemTools::Fopen(path, "rb");
  if (!file)
  {
    this->Error = path + ": cannot open the file";
    return false;
  }
  fclose(file);
  const std::string lower = Lower(path);
  const char* format = FormatOf(lower);
  if (!format)
  {
    this->Error = path + ": unknown volume format (extension '" +
      vtksys::SystemTools::GetFilenameLastExtension(path) +
      "'); known: .vdb .vti .mhd .mha .nrrd .nhdr .nii .nii.gz .vtk .slc or a DICOM directory";
    return false;
  }
  const std::string name = format;
  auto notOfFormat = [&]()
  {
    this->Error = path + ": not a " + name + " file";
    return false;
  };
  if (name == "OpenVDB")
  {
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->SetFileName(path.c_str());
    if (this->GridName && *this->GridName)
    {
      reader->SetGridName(this->GridName);
    }
    return this->RunReader(reader, path, format);
  }
  if (name == "VTK XML")
  {
    vtkNew<vtkXMLImageDataReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return notOfFormat();
    }
    reader->SetFileName(path.c_str());
    return this->RunReader(reader, path, format);
  }
  if (name == "MetaImage")
  {
    vtkNew<vtkMetaImageReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return notOfFormat();
    }
    reader->SetFileName(path.c_str());
    const bool ok = this->RunReader(reader, path, format);
    this->Modality = reader->GetModality() ? reader->GetModality() : "";
    // MetaImage names modalities MET_MOD_CT, MET_MOD_MR, ...
    if (this->Modality.rfind("MET_MOD_", 0) == 0)
    {
      this->Modality = this->Modality.substr(8);
    }
    if (this->Modality == "UNKNOWN")
    {
      this->Modality.clear();
    }
    return ok;
  }
  if (name == "NRRD")
  {
    vtkNew<vtkNrrdReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return notOfFormat();
    }
    reader->SetFileName(path.c_str());
    return this->RunReader(reader, path, format);
  }
  if (name == "NIfTI")
  {
    vtkNew<vtkNIFTIImageReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return notOfFormat();
    }
    reader->SetFileName(path.c_str());
    return this->RunReader(reader, path, format);
  }
  if (name == "VTK legacy")
  {
    vtkNew<vtkDataSetReader> reader;
    reader->SetFileName(path.c_str());
    vtkNew<vtkTyndallErrorObserver> quiet; // ReadOutputType reports errors of its own
    quiet->Watch(reader);
    const int type = reader->ReadOutputType();
    reader->RemoveObserver(quiet);
    if (type < 0)
    {
      this->Error = path + ": not a legacy VTK data file" +
        (quiet->HasErrors() ? " (" + quiet->GetMessages().front() + ")" : std::string());
      return false;
    }
    if (type != VTK_STRUCTURED_POINTS && type != VTK_IMAGE_DATA)
    {
      this->Error = path + ": not image data (the legacy file holds a " +
        std::string(vtkDataObjectTypes::GetClassNameFromTypeId(type)) + ", not structured points)";
      return false;
    }
    return this->RunReader(reader, path, format);
  }
  vtkNew<vtkSLCReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return notOfFormat();
  }
  reader->SetFileName(path.c_str());
  return this->RunReader(reader, path, format);
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::RunReader(
  vtkAlgorithm* reader, const std::string& path, const char* format)
{
  // The inner reader's errors become this reader's one line; its progress is ours.
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(reader);
  errors->Watch(reader->GetExecutive());
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback([](vtkObject*, unsigned long, void* self, void* fraction)
    { static_cast<vtkVolumeFileReader*>(self)->UpdateProgress(*static_cast<double*>(fraction)); });
  reader->AddObserver(vtkCommand::ProgressEvent, progress);
  reader->Update();
  reader->RemoveObserver(errors);
  reader->RemoveObserver(progress);
  reader->GetExecutive()->RemoveObserver(errors);

  vtkDataObject* output = reader->GetOutputDataObject(0);
  if (errors->HasErrors())
  {
    this->Error = path + ": " + errors->GetMessages().front();
    return false;
  }
  auto* image = vtkImageData::SafeDownCast(output);
  if (!image)
  {
    this->Error = path + ": not image data (the file holds " +
      (output ? std::string(output->GetClassName()) : std::string("nothing")) + ")";
    return false;
  }
  this->Image = vtkSmartPointer<vtkImageData>::New();
  this->Image->ShallowCopy(image);
  this->FormatName = format;
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::Finish(const std::string& path)
{
  vtkImageData* image = this->Image;
  int dims[3];
  image->GetDimensions(dims);
  if (image->GetNumberOfPoints() <= 0 || dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    this->Error = path + ": the file could not be read (empty image)";
    return false;
  }
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    std::ostringstream os;
    os << path << ": the image is " << dims[0] << " x " << dims[1] << " x " << dims[2]
       << " points; a volume needs at least 2 points along each axis";
    this->Error = os.str();
    return false;
  }
  // Extent starting at 0, origin moved to the first point (with the
  // direction matrix): the same world positions.
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
    this->Error = path + ": the image has no numeric scalars";
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  const std::string arrayName = scalars->GetName() ? scalars->GetName() : "";
  if (this->Component >= components)
  {
    std::ostringstream os;
    os << path << ": component " << this->Component << " requested, but the scalars ('" << arrayName
       << "') have " << components << " component" << (components == 1 ? "" : "s");
    this->Error = os.str();
    return false;
  }
  if (components > 1 && this->Component < 0)
  {
    std::ostringstream os;
    os << path << ": the scalars ('" << arrayName << "') have " << components
       << " components; choose one (--component 0.." << components - 1 << ")";
    this->Error = os.str();
    return false;
  }
  if (components > 1 && cellScalars)
  {
    // vtkImageExtractComponents works on point scalars only.
    vtkSmartPointer<vtkDataArray> one;
    one.TakeReference(scalars->NewInstance());
    one->SetNumberOfComponents(1);
    one->SetNumberOfTuples(scalars->GetNumberOfTuples());
    one->CopyComponent(0, scalars, this->Component);
    one->SetName(scalars->GetName());
    auto result = vtkSmartPointer<vtkImageData>::New();
    result->CopyStructure(image);
    result->GetCellData()->SetScalars(one);
    this->Image = result;
  }
  else if (components > 1)
  {
    vtkNew<vtkImageExtractComponents> extract;
    extract->SetInputData(image);
    extract->SetComponents(this->Component);
    extract->Update();
    auto result = vtkSmartPointer<vtkImageData>::New();
    result->ShallowCopy(extract->GetOutput());
    this->Image = result;
  }
  AddString(this->Image->GetFieldData(), "TyndallFormat", this->FormatName);
  if (!this->Modality.empty())
  {
    AddString(this->Image->GetFieldData(), "TyndallModality", this->Modality);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkVolumeFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "GridName: " << (this->GridName ? this->GridName : "(none)") << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "FormatName: " << this->FormatName << "\n";
}
