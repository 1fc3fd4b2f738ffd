/**
 * @class   vtkVolumeFileReader
 * @brief   reads a volume from any format Tyndall renders into one vtkImageData
 *
 * vtkVolumeFileReader chooses a reader by the path (case-insensitive
 * extension, or a directory):
 *
 * | input | format | reader |
 * |---|---|---|
 * | .vdb | OpenVDB | vtkOpenVDBImageReader (GridName picks the grid) |
 * | .vti | VTK XML image data | vtkXMLImageDataReader |
 * | .mhd .mha | MetaImage | vtkMetaImageReader |
 * | .nrrd .nhdr | NRRD | vtkNrrdReader |
 * | .nii .nii.gz | NIfTI-1 | vtkNIFTIImageReader |
 * | .vtk | legacy VTK structured points | vtkDataSetReader |
 * | .slc | SLC | vtkSLCReader |
 * | a directory | a DICOM series (Part 10 files, "DICM" at byte 128) | its own (below) |
 *
 * The output is one image with one active one-component numeric scalar
 * array: point scalars, or cell scalars when the file has only those; when
 * no array is active the first numeric one is made active; multi-component
 * scalars are refused unless Component selects one. The extent starts at 0:
 * an image whose extent starts elsewhere (OpenVDB index boxes, cropped
 * files) gets its origin moved to its first point, so world positions are
 * unchanged. An image with fewer than 2 points along an axis is refused.
 *
 * The output's field data says where the volume came from, for
 * vtkTransferFunctionPresets::GuessPreset(): a string array "TyndallFormat"
 * (one of "OpenVDB", "VTK XML", "MetaImage", "NRRD", "NIfTI", "VTK legacy",
 * "SLC", "DICOM") and, when the file names it, "TyndallModality" (the
 * MetaImage "Modality" field: "CT", "MR", ...).
 *
 * A NIfTI file with an sform (sform_code > 0) or else a qform is placed by
 * it, in the LPS patient frame of DICOM and MetaImage (NIfTI's RAS with x
 * and y negated): origin, spacing and direction matrix; without either it
 * keeps VTK's placement (origin 0, spacing pixdim).
 *
 * A DICOM series is read by this class itself, not by vtkDICOMImageReader
 * (which flips the rows, ignores the orientation tags and trusts every
 * file): uncompressed little-endian slices, one per file, sorted by their
 * position along the slice normal and evenly spaced, placed in the patient
 * frame (origin = the first slice's Image Position (Patient), direction
 * matrix = row, column and normal directions of Image Orientation
 * (Patient)), Rescale Slope and Intercept applied; the Modality tag is
 * kept as "TyndallModality".
 *
 * The header is checked before any voxel is read: each VTK reader's
 * information pass runs first, and the read stops with an error when the
 * header claims an empty or flat extent, a type that is not numeric, a zero
 * or non-finite spacing, a non-finite origin, more voxel bytes than
 * MemoryLimit, or (uncompressed MetaImage, NRRD and NIfTI data) more voxel
 * bytes than its file holds. Exceptions thrown by a reader (std::bad_alloc
 * included) are caught and reported.
 *
 * Errors (a missing or unreadable path, an unknown extension, a file that is
 * not of its extension's format, a failed header check, a reader's error,
 * data that is not an image, no scalars, a bad component) are reported with
 * vtkErrorMacro as one line that starts with the path, and the output is
 * empty. The inner reader's progress is forwarded (ProgressEvent).
 * Documentation/io.md lists the bad inputs that are tested.
 *
 * A request for part of the extent (a piece of a parallel pipeline, such
 * as ParaView's under MPI, or streaming) gets that part only: the file is
 * still read whole, once per reader.
 *
 * Usable from Python: `from tyndall import vtkVolumeFileReader`.
 *
 * @sa vtkOpenVDBImageReader vtkTransferFunctionPresets
 */

#ifndef vtkVolumeFileReader_h
#define vtkVolumeFileReader_h

#include "TyndallIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkImageData;
class vtkMatrix4x4;
class vtkTyndallErrorObserver;

class TYNDALLIO_EXPORT vtkVolumeFileReader : public vtkImageAlgorithm
{
public:
  static vtkVolumeFileReader* New();
  vtkTypeMacro(vtkVolumeFileReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file or DICOM directory to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The grid of a .vdb file (default: none, the OpenVDB reader's choice:
   * "density" if it is a float grid, else the first float grid). A grid name
   * with another format is an error.
   */
  vtkSetStringMacro(GridName);
  vtkGetStringMacro(GridName);

  /**
   * OpenVDB only: one more grid read into the same image as a further
   * point-data array (vtkOpenVDBImageReader::AddGridName()), for example
   * the "temperature" of a fire beside its "density"; default none. The
   * rendered grid stays GridName's (or the automatic choice).
   */
  vtkSetStringMacro(ExtraGridName);
  vtkGetStringMacro(ExtraGridName);
  ///@}

  ///@{
  /**
   * The component of multi-component scalars to keep, in [-1, 1024];
   * default -1: multi-component scalars are refused (unless AllComponents).
   */
  vtkSetClampMacro(Component, int, -1, 1024);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /**
   * Whether multi-component scalars are kept whole when Component is -1:
   * 2 to 4 components (what a volume mapper draws; more are refused with an
   * error naming the limit). Default off.
   */
  vtkSetMacro(AllComponents, bool);
  vtkGetMacro(AllComponents, bool);
  vtkBooleanMacro(AllComponents, bool);
  ///@}

  ///@{
  /**
   * Memory limit in MiB for the voxels a file's header claims, in [1, 1e9];
   * default 4096. Checked after the header is read and before any voxel is
   * allocated (the OpenVDB reader gets the same limit). A header that claims
   * more is an error that names its dimensions and size.
   */
  vtkSetClampMacro(MemoryLimit, double, 1.0, 1.0e9);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  ///@{
  /**
   * The time frame of a 4-D file (a NIfTI file with a time dimension), in
   * [0, 1000000]; default 0, the first. A frame the file lacks is an error;
   * the frame read and their number are noted (GetNotes()).
   */
  vtkSetClampMacro(Frame, int, 0, 1000000);
  vtkGetMacro(Frame, int);
  ///@}

  ///@{
  /**
   * Whether a NIfTI file's scaling (value = stored x scl_slope + scl_inter,
   * when scl_slope is neither 0 nor 1 or scl_inter is not 0) is applied;
   * default on. Scaled values are float (double for double data); the
   * scaling is noted (GetNotes()).
   */
  vtkSetMacro(Rescale, bool);
  vtkGetMacro(Rescale, bool);
  vtkBooleanMacro(Rescale, bool);
  ///@}

  ///@{
  /**
   * Whether an OpenVDB level set (a signed distance field) is converted to
   * a fog volume (vtkOpenVDBImageReader::ConvertLevelSetToFog, OpenVDB's
   * sdfToFogVolume); default off: a level set is refused with an error that
   * names this switch.
   */
  vtkSetMacro(ConvertLevelSetToFog, bool);
  vtkGetMacro(ConvertLevelSetToFog, bool);
  vtkBooleanMacro(ConvertLevelSetToFog, bool);
  ///@}

  /**
   * What the last read did to the data beyond reading it, one note per line
   * (NIfTI scaling applied, the frame of a 4-D file); "" if nothing. The
   * notes are also in the output's field data as the string array
   * "TyndallReadNotes", which the programs print.
   */
  const char* GetNotes();

  /**
   * The format of the last successful read ("OpenVDB", "MetaImage", ...,
   * see the class description); empty before one.
   */
  const char* GetFormatName() { return this->FormatName.c_str(); }

  /**
   * Whether `path` has an extension this reader knows, or is a directory
   * (it may still fail to read).
   */
  static bool CanReadFile(const char* path);

  /**
   * The accepted inputs, one per line, for a program's --help.
   */
  static const char* GetFormatsDescription();

protected:
  vtkVolumeFileReader();
  ~vtkVolumeFileReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;
  char* GridName = nullptr;
  char* ExtraGridName = nullptr;
  int Component = -1;
  bool AllComponents = false;
  double MemoryLimit = 4096.0;
  int Frame = 0;
  bool Rescale = true;
  bool ConvertLevelSetToFog = false;

private:
  vtkVolumeFileReader(const vtkVolumeFileReader&) = delete;
  void operator=(const vtkVolumeFileReader&) = delete;

  // Reads the file into Image; false with Error set on failure.
  bool Read();
  bool ReadDirectory(const std::string& path);
  bool ReadFile(const std::string& path);
  // True (with Error = "path: problem") when a check found a problem.
  bool Refuse(const std::string& path, const std::string& problem);
  bool NotOfFormat(const std::string& path, const char* format);
  bool ReadOpenVDB(const std::string& path);
  bool ReadMetaImage(const std::string& path);
  bool ReadNifti(const std::string& path);
  bool ReadLegacy(const std::string& path);
  bool ChooseFrame(const std::string& path, int frames);
  bool ApplyRescale(double slope, double intercept);
  bool PlaceNifti(const std::string& path, vtkMatrix4x4* placement, const char* which);
  bool RunReader(vtkAlgorithm* reader, const std::string& path, const char* format,
    const std::function<std::string(double)>& checkData = nullptr);
  bool RunPasses(vtkAlgorithm* reader, const std::string& path,
    const std::function<std::string(double)>& checkData, vtkTyndallErrorObserver* errors);
  bool Finish(const std::string& path);

  vtkSmartPointer<vtkImageData> Image;
  std::string FormatName;
  std::string Modality;
  std::string Error;
  std::vector<std::string> Notes;
  std::vector<std::string> UnobservedMessages; // output-window messages of the last inner read
  std::string NotesText;
  vtkMTimeType ReadTime = 0;
};

#endif
