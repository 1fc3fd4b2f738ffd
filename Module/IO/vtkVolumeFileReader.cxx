#include "vtkVolumeFileReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTypes.h"
#include "vtkDataSetReader.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageExtractComponents.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkSLCReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkStructuredPointsReader.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkVolumeFileChecks.h"
#include "vtkVolumeFileDicom.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkVolumeFileReader);

namespace
{
bool EndsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Counts a directory's regular files and lists those that look like DICOM
// Part 10 files ("DICM" at byte 128).
void ListFiles(const std::string& directory, int& files, std::vector<std::string>& dicomFiles)
{
  files = 0;
  dicomFiles.clear();
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
        dicomFiles.push_back(path);
      }
      fclose(file);
    }
  }
  std::sort(dicomFiles.begin(), dicomFiles.end());
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
  this->SetExtraGridName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::CanReadFile(const char* path)
{
  return path && *path &&
    (vtksys::SystemTools::FileIsDirectory(path) || FormatOf(tyndall_io::Lower(path)) != nullptr);
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
    this->Notes.clear();
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
  // Pieces are parts of the extent (RequestData crops to them).
  info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
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
  // A piece of a parallel pipeline (ParaView under MPI, streaming): the
  // requested extent only. The file is read whole, once, by every piece.
  vtkInformation* info = outputVector->GetInformationObject(0);
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    int extent[6];
    info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    output->Crop(extent);
  }
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
  if (this->GridName && *this->GridName &&
    (directory || !EndsWith(tyndall_io::Lower(path), ".vdb")))
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
  int files = 0;
  std::vector<std::string> dicomFiles;
  ListFiles(path, files, dicomFiles);
  if (files == 0)
  {
    this->Error = path + ": the directory holds no files (expected a DICOM series)";
    return false;
  }
  if (dicomFiles.empty())
  {
    this->Error = path + ": none of the directory's " + std::to_string(files) +
      " files is a DICOM file (no 'DICM' marker at byte 128)";
    return false;
  }
  // VTK's reader trusts every file's pixel data: check them first.
  std::vector<tyndall_io::DicomSlice> slices(dicomFiles.size());
  std::string problem;
  for (size_t i = 0; i < dicomFiles.size() && problem.empty(); ++i)
  {
    problem = tyndall_io::ScanDicomFile(dicomFiles[i], slices[i]);
  }
  if (problem.empty())
  {
    problem = tyndall_io::CheckDicomSeries(slices);
  }
  if (this->Refuse(path, problem))
  {
    return false;
  }
  // Read here rather than by vtkDICOMImageReader, which flips the rows, ignores
  // the orientation tags and trusts every file: the patient frame.
  auto image = vtkSmartPointer<vtkImageData>::New();
  try
  {
    problem = tyndall_io::ReadDicomSeries(slices, this->MemoryLimit, image, this->Notes);
  }
  catch (const std::bad_alloc&)
  {
    problem = "out of memory while reading the series";
  }
  if (this->Refuse(path, problem))
  {
    return false;
  }
  this->Image = image;
  this->FormatName = "DICOM";
  this->Modality = slices.front().Modality;
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
  const char* format = FormatOf(tyndall_io::Lower(path));
  if (!format)
  {
    this->Error = path + ": unknown volume format (extension '" +
      vtksys::SystemTools::GetFilenameLastExtension(path) +
      "'); known: .vdb .vti .mhd .mha .nrrd .nhdr .nii .nii.gz .vtk .slc or a DICOM directory";
    return false;
  }
  const std::string name = format;
  if (name == "OpenVDB")
  {
    return this->ReadOpenVDB(path);
  }
  if (name == "MetaImage")
  {
    return this->ReadMetaImage(path);
  }
  if (name == "NIfTI")
  {
    return this->ReadNifti(path);
  }
  if (name == "VTK legacy")
  {
    return this->ReadLegacy(path);
  }
  if (name == "VTK XML")
  {
    vtkNew<vtkXMLImageDataReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return this->NotOfFormat(path, format);
    }
    if (this->Refuse(path, tyndall_io::CheckXmlImageHeader(path)))
    {
      return false;
    }
    reader->SetFileName(path.c_str());
    return this->RunReader(reader, path, format);
  }
  if (name == "NRRD")
  {
    vtkNew<vtkNrrdReader> reader;
    if (!reader->CanReadFile(path.c_str()))
    {
      return this->NotOfFormat(path, format);
    }
    if (this->Refuse(path, tyndall_io::CheckNrrdHeader(path)))
    {
      return false;
    }
    reader->SetFileName(path.c_str());
    return this->RunReader(reader, path, format,
      [&](double bytes) { return tyndall_io::CheckRawData(tyndall_io::NrrdRawData(path), bytes); });
  }
  vtkNew<vtkSLCReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return this->NotOfFormat(path, format);
  }
  reader->SetFileName(path.c_str());
  return this->RunReader(reader, path, format);
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::Refuse(const std::string& path, const std::string& problem)
{
  if (problem.empty())
  {
    return false;
  }
  this->Error = path + ": " + problem;
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::NotOfFormat(const std::string& path, const char* format)
{
  this->Error = path + ": not a " + format + " file";
  return false;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadOpenVDB(const std::string& path)
{
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetMemoryLimit(this->MemoryLimit);
  reader->SetConvertLevelSetToFog(this->ConvertLevelSetToFog);
  if (this->GridName && *this->GridName)
  {
    reader->SetGridName(this->GridName);
  }
  if (this->ExtraGridName && *this->ExtraGridName)
  {
    if (!(this->GridName && *this->GridName))
    {
      // The automatic choice, made explicit so that the extra grid follows it.
      reader->UpdateInformation();
      std::string chosen;
      for (int i = 0; i < reader->GetNumberOfGrids() && chosen.empty(); ++i)
      {
        if (std::string(reader->GetGridName(i)) == "density" &&
          std::string(reader->GetGridValueType(i)) == "float")
        {
          chosen = "density";
        }
      }
      for (int i = 0; i < reader->GetNumberOfGrids() && chosen.empty(); ++i)
      {
        if (std::string(reader->GetGridValueType(i)) == "float" &&
          std::string(reader->GetGridName(i)) != this->ExtraGridName)
        {
          chosen = reader->GetGridName(i);
        }
      }
      if (!chosen.empty())
      {
        reader->SetGridName(chosen.c_str());
      }
    }
    reader->AddGridName(this->ExtraGridName);
  }
  return this->RunReader(reader, path, "OpenVDB");
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadMetaImage(const std::string& path)
{
  vtkNew<vtkMetaImageReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return this->NotOfFormat(path, "MetaImage");
  }
  reader->SetFileName(path.c_str());
  const bool ok = this->RunReader(reader, path, "MetaImage",
    [&](double bytes)
    { return tyndall_io::CheckRawData(tyndall_io::MetaImageRawData(path), bytes); });
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

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadNifti(const std::string& path)
{
  vtkNew<vtkNIFTIImageReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return this->NotOfFormat(path, "NIfTI");
  }
  // VTK 9.1's reader crashes on an unknown datatype code: the header first.
  if (this->Refuse(path, tyndall_io::CheckNiftiHeader(path)))
  {
    return false;
  }
  reader->SetFileName(path.c_str());
  reader->TimeAsVectorOn(); // every frame, then Frame picks one
  const bool gzip = EndsWith(tyndall_io::Lower(path), ".gz");
  const bool ok = this->RunReader(reader, path, "NIfTI",
    [&](double bytes)
    {
      tyndall_io::RawData raw; // .nii: the voxels follow the header in the file
      raw.File = gzip ? std::string() : path;
      raw.Offset = reader->GetNIFTIHeader()->GetVoxOffset();
      return tyndall_io::CheckRawData(raw, bytes);
    });
  if (!ok || !this->ChooseFrame(path, std::max(1, reader->GetTimeDimension())) ||
    !this->ApplyRescale(reader->GetRescaleSlope(), reader->GetRescaleIntercept()))
  {
    return false;
  }
  // The placement: the sform when its code says it is set, else the qform.
  vtkNIFTIImageHeader* header = reader->GetNIFTIHeader();
  vtkMatrix4x4* placement = header->GetSFormCode() > 0 ? reader->GetSFormMatrix()
    : header->GetQFormCode() > 0                       ? reader->GetQFormMatrix()
                                                       : nullptr;
  if (placement)
  {
    return this->PlaceNifti(path, placement, header->GetSFormCode() > 0 ? "sform" : "qform");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::PlaceNifti(
  const std::string& path, vtkMatrix4x4* placement, const char* which)
{
  // VTK's NIfTI reader gives the image in index x pixdim coordinates and a
  // matrix from those to NIfTI's RAS millimetres; the other formats (DICOM,
  // ITK's MetaImage) are in the LPS patient frame: x and y change sign.
  double spacing[3], axes[3][3], origin[3], first[3];
  this->Image->GetSpacing(spacing);
  this->Image->GetOrigin(first);
  for (int r = 0; r < 3; ++r)
  {
    const double sign = r < 2 ? -1.0 : 1.0;
    origin[r] = sign *
      (placement->GetElement(r, 0) * first[0] + placement->GetElement(r, 1) * first[1] +
        placement->GetElement(r, 2) * first[2] + placement->GetElement(r, 3));
    for (int a = 0; a < 3; ++a)
    {
      axes[a][r] = sign * placement->GetElement(r, a) * spacing[a];
    }
  }
  double direction[9];
  for (int a = 0; a < 3; ++a)
  {
    spacing[a] = vtkMath::Norm(axes[a]);
    if (!std::isfinite(spacing[a]) || spacing[a] == 0.0)
    {
      this->Error = path + ": the " + std::string(which) + " matrix is degenerate";
      return false;
    }
    for (int r = 0; r < 3; ++r)
    {
      direction[3 * r + a] = axes[a][r] / spacing[a];
    }
  }
  this->Image->SetOrigin(origin);
  this->Image->SetSpacing(spacing);
  this->Image->SetDirectionMatrix(direction);
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ChooseFrame(const std::string& path, int frames)
{
  if (this->Frame >= frames)
  {
    this->Error = path + ": frame " + std::to_string(this->Frame) +
      " requested, but the file has " + std::to_string(frames) +
      (frames == 1 ? " frame (it is not 4-D)" : " frames");
    return false;
  }
  if (frames == 1)
  {
    return true;
  }
  vtkDataArray* scalars = this->Image->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfComponents() % frames != 0)
  {
    this->Error = path + ": the time frames do not match the scalars' components";
    return false;
  }
  // The frames are the components, frame after frame.
  const int perFrame = scalars->GetNumberOfComponents() / frames;
  vtkSmartPointer<vtkDataArray> one;
  one.TakeReference(scalars->NewInstance());
  one->SetName(scalars->GetName());
  one->SetNumberOfComponents(perFrame);
  one->SetNumberOfTuples(scalars->GetNumberOfTuples());
  for (int c = 0; c < perFrame; ++c)
  {
    one->CopyComponent(c, scalars, this->Frame * perFrame + c);
  }
  this->Image->GetPointData()->SetScalars(one);
  this->Notes.push_back("frame " + std::to_string(this->Frame) + " of " + std::to_string(frames) +
    " of a 4-D file (--frame N picks another)");
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ApplyRescale(double slope, double intercept)
{
  // NIfTI: scl_slope 0 (or not finite) means "no scaling".
  if (!this->Rescale || slope == 0.0 || !std::isfinite(slope) || !std::isfinite(intercept) ||
    (slope == 1.0 && intercept == 0.0))
  {
    return true;
  }
  vtkDataArray* scalars = this->Image->GetPointData()->GetScalars();
  vtkSmartPointer<vtkDataArray> scaled;
  if (scalars->GetDataType() == VTK_DOUBLE)
  {
    scaled = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    scaled = vtkSmartPointer<vtkFloatArray>::New();
  }
  scaled->SetName(scalars->GetName());
  scaled->SetNumberOfComponents(scalars->GetNumberOfComponents());
  scaled->SetNumberOfTuples(scalars->GetNumberOfTuples());
  const int components = scalars->GetNumberOfComponents();
  std::vector<double> tuple(components);
  for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t)
  {
    scalars->GetTuple(t, tuple.data());
    for (double& v : tuple)
    {
      v = v * slope + intercept;
    }
    scaled->SetTuple(t, tuple.data());
  }
  this->Image->GetPointData()->SetScalars(scaled);
  std::ostringstream note;
  note << "NIfTI scaling applied: value = stored x " << slope << " + " << intercept
       << " (scl_slope, scl_inter; --no-rescale keeps the stored values)";
  this->Notes.push_back(note.str());
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::ReadLegacy(const std::string& path)
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
  // The structured points reader itself, so that its messages reach us: it
  // only warns about data shorter than declared ("Error reading ... data").
  vtkNew<vtkStructuredPointsReader> points;
  points->SetFileName(path.c_str());
  vtkNew<vtkTyndallErrorObserver> warnings;
  points->AddObserver(vtkCommand::WarningEvent, warnings);
  if (!this->RunReader(points, path, "VTK legacy"))
  {
    return false;
  }
  std::vector<std::string> messages = warnings->GetMessages();
  messages.insert(messages.end(), this->UnobservedMessages.begin(), this->UnobservedMessages.end());
  for (const std::string& warning : messages)
  {
    if (warning.find("Error reading") != std::string::npos)
    {
      this->Error = path + ": the data is shorter than the header declares (" + warning + ")";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVolumeFileReader::RunReader(vtkAlgorithm* reader, const std::string& path,
  const char* format, const std::function<std::string(double)>& checkData)
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
  // Messages of objects nobody observes (vtkGenericWarningMacro in the
  // readers' helpers, inner objects) reach the output window: keep them.
  vtkNew<vtkTyndallErrorObserver> unobserved;
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  const unsigned long warningTag = window->AddObserver(vtkCommand::WarningEvent, unobserved);
  const unsigned long errorTag = window->AddObserver(vtkCommand::ErrorEvent, unobserved);
  std::string thrown;
  bool read = false;
  try
  {
    read = this->RunPasses(reader, path, checkData, errors);
  }
  catch (const std::bad_alloc&)
  {
    thrown = "out of memory while reading (do the header's sizes fit the file?)";
  }
  catch (const std::exception& e)
  {
    thrown = std::string("the reader threw an exception: ") + e.what();
  }
  catch (...)
  {
    thrown = "the reader threw an unknown exception";
  }
  reader->RemoveObserver(errors);
  reader->RemoveObserver(progress);
  reader->GetExecutive()->RemoveObserver(errors);
  window->RemoveObserver(warningTag);
  window->RemoveObserver(errorTag);
  this->UnobservedMessages = unobserved->GetMessages();
  if (!thrown.empty() || errors->HasErrors())
  {
    std::string message = thrown.empty() ? errors->GetMessages().front() : thrown;
    // The executive's "Algorithm X returned failure for request" says less
    // than what the reader told the output window.
    if (message.rfind("Algorithm ", 0) == 0 && !this->UnobservedMessages.empty())
    {
      message = this->UnobservedMessages.front();
    }
    this->Error = path + ": " + message.substr(0, 400);
    return false;
  }
  if (!read)
  {
    return false; // a header check failed: Error says which
  }
  vtkDataObject* output = reader->GetOutputDataObject(0);
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
bool vtkVolumeFileReader::RunPasses(vtkAlgorithm* reader, const std::string& path,
  const std::function<std::string(double)>& checkData, vtkTyndallErrorObserver* errors)
{
  // The header first: its claims are checked before any voxel is allocated.
  reader->UpdateInformation();
  if (errors->HasErrors())
  {
    return false;
  }
  if (!vtkImageData::SafeDownCast(reader->GetOutputDataObject(0)))
  {
    return true; // not image data: RunReader says what it is
  }
  double bytes = 0.0;
  std::string problem =
    tyndall_io::CheckInformation(reader->GetOutputInformation(0), this->MemoryLimit, bytes);
  if (problem.empty() && checkData)
  {
    problem = checkData(bytes);
  }
  if (this->Refuse(path, problem))
  {
    return false;
  }
  reader->Update();
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
  if (components > 1 && this->Component < 0 && (!this->AllComponents || components > 4))
  {
    std::ostringstream os;
    os << path << ": the scalars ('" << arrayName << "') have " << components << " components; "
       << (this->AllComponents ? "at most 4 are drawn together: " : "")
       << "choose one (--component 0.." << components - 1 << ")"
       << (this->AllComponents ? "" : " or draw them together (--components)");
    this->Error = os.str();
    return false;
  }
  if (components > 1 && this->Component < 0)
  {
    // Every component kept (AllComponents).
  }
  else if (components > 1 && cellScalars)
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
  if (!this->Notes.empty())
  {
    vtkNew<vtkStringArray> notes;
    notes->SetName("TyndallReadNotes");
    for (const std::string& note : this->Notes)
    {
      notes->InsertNextValue(note);
    }
    this->Image->GetFieldData()->AddArray(notes);
  }
  if (!this->Modality.empty())
  {
    AddString(this->Image->GetFieldData(), "TyndallModality", this->Modality);
  }
  return true;
}

//------------------------------------------------------------------------------
const char* vtkVolumeFileReader::GetNotes()
{
  this->NotesText.clear();
  for (const std::string& note : this->Notes)
  {
    this->NotesText += (this->NotesText.empty() ? "" : "\n") + note;
  }
  return this->NotesText.c_str();
}

//------------------------------------------------------------------------------
void vtkVolumeFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "GridName: " << (this->GridName ? this->GridName : "(none)") << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "AllComponents: " << this->AllComponents << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "Frame: " << this->Frame << "\n";
  os << indent << "Rescale: " << (this->Rescale ? "on" : "off") << "\n";
  os << indent << "ConvertLevelSetToFog: " << (this->ConvertLevelSetToFog ? "on" : "off") << "\n";
  os << indent << "FormatName: " << this->FormatName << "\n";
}
