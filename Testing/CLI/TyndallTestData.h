// Synthetic inputs of the tyndall-render tests (Testing/CLI): a small blob
// volume, text files, DICOM slices written byte by byte (VTK 9.1 reads DICOM
// but cannot write it), and the files of the bad-input matrix
// (Documentation/bad-inputs.md). Used by TyndallCLICheck's make-data and
// make-bad-inputs subcommands.
#ifndef TyndallTestData_h
#define TyndallTestData_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tyndall_test_data
{
/// A 24 x 20 x 16 float Gaussian blob (spacing 1, 1, 1.5), optionally with
/// `components` components (component c is (c + 1) times the first).
vtkSmartPointer<vtkImageData> Blob(int components);

/// Writes `text` (any bytes) to `path`; false on failure.
bool WriteText(const std::string& path, const std::string& text);

/// The bytes of a file ("" if it cannot be read).
std::string ReadBytes(const std::string& path);

/// One slice of a DICOM CT series (explicit VR little endian, int16 pixels).
struct DicomSlice
{
  int Index = 0; ///< instance number - 1
  int Columns = 32;
  int Rows = 28;
  std::vector<int16_t> Pixels; ///< Rows x Columns, row by row, first row first
  std::string Position;        ///< Image Position (Patient); default "0\0\<2 Index>"
  std::string Orientation = "1\\0\\0\\0\\1\\0";
  std::string PixelSpacing = "1.5\\1.5"; ///< row spacing \ column spacing
  std::string Intercept = "0";
  std::string Slope = "1";
  /// Keep only this many bytes of the file (a truncated file); 0: all.
  size_t KeepBytes = 0;
};

/// Writes `slice` as a DICOM Part 10 file; false on failure.
bool WriteDicomSlice(const std::string& path, const DicomSlice& slice);

/// Writes an OpenVDB level set (a sphere of radius 0.5, voxels of 0.05) to
/// `path`; false on failure. (TyndallLevelSet.cxx, the only OpenVDB user.)
bool WriteLevelSetSphere(const std::string& path);

/// A fog volume "density": a Gaussian blob of peak 100 in a 24 x 20 x 16
/// box, its centre `shift` voxels along x from (8.5, 9.5, 7.5).
bool WriteDensityBlob(const std::string& path, double shift);

/// Writes a 64 x 32 equirectangular sky (Radiance RGBE, uncompressed rows,
/// top first) to `path`: blue above the horizon, a dark ground, and a sun
/// of 40 (4 x 2 texels) 22-34 degrees above the horizon; false on failure.
bool WriteSkyHdr(const std::string& path);

/// Writes the bad inputs of Documentation/bad-inputs.md into `dir` (with
/// `vdb`, an OpenVDB file, cut in half); returns 0.
int MakeBadInputs(const std::string& dir, const std::string& vdb);
}

#endif
