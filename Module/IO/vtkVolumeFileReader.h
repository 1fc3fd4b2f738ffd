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
 * | a directory | a DICOM series (Part 10 files, "DICM" at byte 128) | vtkDICOMImageReader |
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
 * Errors (a missing or unreadable path, an unknown extension, a file that is
 * not of its extension's format, a reader's error, data that is not an
 * image, no scalars, a flat image, a bad component) are reported with
 * vtkErrorMacro as one line that starts with the path, and the output is
 * empty. The inner reader's progress is forwarded (ProgressEvent).
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

#include <string> // For std::string

class vtkImageData;

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
  ///@}

  ///@{
  /**
   * The component of multi-component scalars to keep, in [-1, 1024];
   * default -1: multi-component scalars are refused.
   */
  vtkSetClampMacro(Component, int, -1, 1024);
  vtkGetMacro(Component, int);
  ///@}

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
  int Component = -1;

private:
  vtkVolumeFileReader(const vtkVolumeFileReader&) = delete;
  void operator=(const vtkVolumeFileReader&) = delete;

  // Reads the file into Image; false with Error set on failure.
  bool Read();
  bool ReadDirectory(const std::string& path);
  bool ReadFile(const std::string& path);
  bool RunReader(vtkAlgorithm* reader, const std::string& path, const char* format);
  bool Finish(const std::string& path);

  vtkSmartPointer<vtkImageData> Image;
  std::string FormatName;
  std::string Modality;
  std::string Error;
  vtkMTimeType ReadTime = 0;
};

#endif
