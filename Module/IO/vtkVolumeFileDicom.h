/**
 * @file   vtkVolumeFileDicom.h
 * @brief  what a DICOM series' files say about their pixels, checked before VTK reads them
 *         (private to Tyndall::IO)
 *
 * vtkDICOMImageReader (VTK 9.1) sizes the volume from the first slice and
 * reads every file's pixel data into it without checking: a truncated file
 * or a slice of another size gives a picture of whatever memory held, and
 * a compressed transfer syntax gives noise. ScanDicomFile() walks a Part 10
 * file's elements (explicit or implicit VR little endian, sequences of
 * defined or undefined length) up to its pixel data and records what the
 * checks and the placement of the volume need; CheckDicomSeries() compares
 * the slices. Plain functions in namespace tyndall_io, not wrapped, not
 * installed.
 */

#ifndef vtkVolumeFileDicom_h
#define vtkVolumeFileDicom_h

#include <cstdint> // For std::int64_t
#include <string>  // For std::string
#include <vector>  // For std::vector

class vtkImageData;

namespace tyndall_io
{
/// One DICOM file as far as the checks need it.
struct DicomSlice
{
  std::string File;
  std::string TransferSyntax;
  int Rows = 0;
  int Columns = 0;
  int BitsAllocated = 0;
  int SamplesPerPixel = 1;
  std::vector<double> Position;     ///< Image Position (Patient), 3 values when present
  std::vector<double> Orientation;  ///< Image Orientation (Patient), 6 values when present
  std::vector<double> PixelSpacing; ///< row spacing, column spacing
  int PixelRepresentation = 0;      ///< 1: signed pixels
  int NumberOfFrames = 1;
  std::string Modality;
  std::string SeriesUID;
  double Slope = 1.0;
  double Intercept = 0.0;
  std::int64_t PixelOffset = -1; ///< where the pixel data's value starts
  std::int64_t PixelLength = -1; ///< its length in bytes
};

/// Reads `path` into `slice`; "" when its pixel data is present, whole and
/// uncompressed, else the problem.
std::string ScanDicomFile(const std::string& path, DicomSlice& slice);

/// The slices agree in size, bits, samples and series, and hold one frame
/// each; "" or the problem (naming two files that differ).
std::string CheckDicomSeries(const std::vector<DicomSlice>& slices);

/**
 * Reads the series' pixels into `image`, in the patient frame (DICOM's LPS
 * millimetres, the frame MetaImage files written by ITK use): the slices
 * sorted by their position along the slice normal (row direction x column
 * direction of Image Orientation (Patient)), evenly spaced; index i runs
 * along the rows (the column spacing), j down the columns (the row
 * spacing), k along the normal; the origin is the first slice's Image
 * Position (Patient) and the direction matrix holds the row, column and
 * normal directions. Rescale Slope and Intercept are applied per slice
 * (short or int when they keep integers, float otherwise). A missing
 * orientation or position falls back to the axes and the file order, said
 * in `notes`. `memoryLimitMiB` bounds the voxels. "" or the problem.
 */
std::string ReadDicomSeries(std::vector<DicomSlice> slices, double memoryLimitMiB,
  vtkImageData* image, std::vector<std::string>& notes);
}

#endif
