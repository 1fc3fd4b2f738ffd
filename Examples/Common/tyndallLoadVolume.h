// tyndallLoadVolume: loads a volume file (or a DICOM directory) into a
// vtkImageData for Tyndall's example programs (tyndall-render, the viewer).
//
// The reader is chosen by the path's extension (case-insensitive):
//
//   .vdb               vtkOpenVDBImageReader (only when Tyndall::IO is built;
//                      the grid is chosen by name, default: the reader's)
//   .vti               vtkXMLImageDataReader
//   .mhd .mha          vtkMetaImageReader
//   .nrrd .nhdr        vtkNrrdReader
//   .nii .nii.gz       vtkNIFTIImageReader
//   .vtk               vtkDataSetReader (legacy; must hold structured points)
//   .slc               vtkSLCReader
//   a directory        vtkDICOMImageReader (a directory of DICOM Part 10
//                      slices, "DICM" at byte 128; other files are skipped)
//
// The result is a new vtkImageData, detached from the reader, with one
// active one-component numeric scalar array (point scalars, or cell scalars
// when the file has only those). When the file has no active scalars, the
// first numeric point (else cell) array is made active. The extent starts
// at 0: an image whose extent starts elsewhere (OpenVDB index boxes, cropped
// files) gets its origin moved to its first point, so world positions are
// unchanged. Multi-component
// scalars are refused unless a component is chosen. Every failure (missing
// or unreadable file, unknown extension, a reader's error, data that is not
// an image, no scalars, fewer than 2 points along an axis) returns nullptr
// and a one-line message in `error` that starts with the path.
#ifndef tyndallLoadVolume_h
#define tyndallLoadVolume_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>

struct tyndallLoadVolumeOptions
{
  // Grid of a .vdb file; empty: the reader's default (its first grid).
  std::string GridName;
  // Component of multi-component scalars to keep; -1: refuse them.
  int Component = -1;
  // Called with the reader's progress in [0, 1] (may be empty).
  std::function<void(double)> Progress;
};

/**
 * Loads `path` (see above). `gridName` selects the grid of a .vdb file
 * (empty: the first). Returns nullptr and sets `error` on failure.
 */
vtkSmartPointer<vtkImageData> tyndallLoadVolume(
  const std::string& path, const std::string& gridName, std::string& error);

/**
 * The same with all options.
 */
vtkSmartPointer<vtkImageData> tyndallLoadVolume(
  const std::string& path, const tyndallLoadVolumeOptions& options, std::string& error);

/**
 * Whether .vdb files can be read (Tyndall::IO was built).
 */
bool tyndallLoadVolumeCanReadVDB();

/**
 * A short description of the accepted inputs, one per line, for --help.
 */
std::string tyndallLoadVolumeFormats();

#endif
