/**
 * @file   vtkVolumeFileChecks.h
 * @brief  checks of a volume file's claims before its voxels are read (private to Tyndall::IO)
 *
 * vtkVolumeFileReader runs each VTK reader's information pass first (which
 * reads only the header), then these checks, and reads the voxels only if
 * they pass:
 *
 * - CheckInformation(): the extent is not empty, every axis has at least 2
 *   points, the scalar type is a known numeric type, the spacing and origin
 *   are finite and the spacing is not zero, and the voxels fit the memory
 *   limit (points x components x bytes per value).
 * - CheckRawData(): for uncompressed binary data (MetaImage, NRRD, NIfTI),
 *   the file that holds the voxels is at least as long as the header's
 *   offset plus the voxels' bytes. VTK's raw readers only warn about a short
 *   file and render whatever memory held.
 *
 * Every function returns "" when the check passes, else the problem as
 * text that the caller prefixes with the path. Not a VTK class: plain
 * functions in namespace tyndall_io, not wrapped, not installed.
 */

#ifndef vtkVolumeFileChecks_h
#define vtkVolumeFileChecks_h

#include <cstdint> // For std::int64_t
#include <string>  // For std::string

class vtkInformation;

namespace tyndall_io
{
/// Where the raw voxels of a file lie, as far as its header says.
struct RawData
{
  /// The file holding the voxels; empty when the check does not apply
  /// (compressed or text data, a list of files, an unknown layout).
  std::string File;
  /// Bytes before the voxels; -1: the voxels are the file's last bytes.
  std::int64_t Offset = 0;
  /// How the data is stored ("raw"; "zlib": a zlib or gzip stream at
  /// Offset, checked by inflating it; "ascii", "several files", ...: not
  /// checked, File is empty).
  std::string Encoding = "raw";
};

/// The header's claims in `info` (a reader's output information after
/// UpdateInformation()) against the rules above; `memoryLimitMiB` bounds
/// the voxels' bytes. Sets `bytes` to the voxels' size in bytes.
std::string CheckInformation(vtkInformation* info, double memoryLimitMiB, double& bytes);

/// The file of `raw` holds at least `bytes` bytes after its offset (raw),
/// or a zlib/gzip stream there that inflates without error to at least
/// `bytes` bytes (zlib: a full decompression pass, nothing kept).
std::string CheckRawData(const RawData& raw, double bytes);

/// A NIfTI-1 or NIfTI-2 header (plain or gzip-compressed file) that VTK's
/// reader can take: a known datatype code (an unknown one crashes VTK 9.1's
/// reader), 1 to 7 dimensions, finite non-zero pixdim along the first three.
std::string CheckNiftiHeader(const std::string& path);

/// Where a MetaImage header (.mhd, or the header part of a .mha) puts its
/// voxels: ElementDataFile (LOCAL: after the header in the same file),
/// HeaderSize, CompressedData, BinaryData.
RawData MetaImageRawData(const std::string& path);

/// Where an NRRD header puts its voxels: "data file" (or after the header's
/// blank line), "encoding", "byte skip".
RawData NrrdRawData(const std::string& path);

/// An NRRD header's type is one vtkNrrdReader knows and its sizes are
/// positive integers (vtkNrrdReader turns a size of 0 into 2 points).
std::string CheckNrrdHeader(const std::string& path);

/// A VTK XML image file's Spacing and Origin attributes are finite (the
/// reader silently keeps 1 for "nan") and the spacing is not zero; raw
/// appended data (compressed or not) lies inside the file (the reader
/// silently reads a short block).
std::string CheckXmlImageHeader(const std::string& path);

/// A byte count as text: "262144 bytes (256 KiB)".
std::string FormatBytes(double bytes);

/// `text` in lower case (ASCII letters).
std::string Lower(std::string text);
}

#endif
