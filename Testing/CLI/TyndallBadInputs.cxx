// The files of the bad-input matrix (Documentation/bad-inputs.md): one damaged
// or impossible file per row, per format. Testing/CLI/CMakeLists.txt holds
// the rows (file, expected message) and runs tyndall-render on each: exit
// status 1, a message naming the file and the problem, no picture written.
#include "TyndallTestData.h"

#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkStructuredPointsWriter.h"
#include "vtkXMLImageDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <cstring>
#include <iostream>
#include <limits>
#include <string>

namespace tyndall_test_data
{
namespace
{
// 16^3 bytes of a ramp: the voxels of the small raw files.
std::string Voxels(size_t count = 16 * 16 * 16)
{
  std::string bytes(count, '\0');
  for (size_t i = 0; i < count; ++i)
  {
    bytes[i] = static_cast<char>(i % 251);
  }
  return bytes;
}

std::string MetaHeader(const std::string& dims, const std::string& type, const std::string& extra,
  const std::string& dataFile)
{
  return "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
         "DimSize = " +
    dims + "\nElementType = " + type + "\n" + extra + "ElementDataFile = " + dataFile + "\n";
}

void WriteMetaImage(const std::string& dir)
{
  const std::string ok = "ElementSpacing = 1 1 1\n";
  auto mhd = [&](const std::string& name, const std::string& dims, const std::string& type,
               const std::string& extra, size_t rawBytes)
  {
    WriteText(dir + "/" + name + ".mhd", MetaHeader(dims, type, extra, name + ".raw"));
    WriteText(dir + "/" + name + ".raw", Voxels(rawBytes));
  };
  // The two cases: 100000^3 voxels; 1,000 bytes of a 262,144-byte volume.
  mhd("mhd-huge", "100000 100000 100000", "MET_UCHAR", ok, 4096);
  mhd("mhd-truncated", "64 64 64", "MET_UCHAR", ok, 1000);
  mhd("mhd-truncated-float", "16 16 16", "MET_FLOAT", ok, 4096 * 3);
  mhd("mhd-zero-dim", "0 16 16", "MET_UCHAR", ok, 4096);
  mhd("mhd-negative-dim", "16 -16 16", "MET_UCHAR", ok, 4096);
  mhd("mhd-zero-spacing", "16 16 16", "MET_UCHAR", "ElementSpacing = 1 0 1\n", 4096);
  mhd("mhd-nan-spacing", "16 16 16", "MET_UCHAR", "ElementSpacing = nan 1 1\n", 4096);
  mhd("mhd-inf-origin", "16 16 16", "MET_UCHAR", ok + "Offset = inf 0 0\n", 4096);
  mhd("mhd-unknown-type", "16 16 16", "MET_QUATERNION", ok, 4096);
  mhd("mhd-zero-channels", "16 16 16", "MET_UCHAR", ok + "ElementNumberOfChannels = 0\n", 4096);
  WriteText(dir + "/mhd-bad-zlib.mhd",
    MetaHeader("16 16 16", "MET_UCHAR", ok + "CompressedData = True\nCompressedDataSize = 500\n",
      "mhd-bad-zlib.raw"));
  WriteText(dir + "/mhd-bad-zlib.raw", std::string(500, 'z'));
  WriteText(dir + "/mhd-empty.mhd", "");
  WriteText(dir + "/mhd-no-data-file.mhd",
    "ObjectType = Image\nNDims = 3\nDimSize = 16 16 16\nElementType = MET_UCHAR\n");
  // A .mha: header and voxels in one file, the voxels cut short.
  WriteText(
    dir + "/mha-truncated.mha", MetaHeader("16 16 16", "MET_UCHAR", ok, "LOCAL") + Voxels(2000));
}

std::string NrrdHeader(const std::string& fields)
{
  return "NRRD0004\ntype: uint8\ndimension: 3\nendian: little\n" + fields;
}

void WriteNrrd(const std::string& dir)
{
  const std::string sizes = "sizes: 16 16 16\nspacings: 1 1 1\n";
  auto nrrd = [&](const std::string& name, const std::string& fields, const std::string& data)
  { WriteText(dir + "/" + name + ".nrrd", NrrdHeader(fields) + "\n" + data); };
  nrrd("nrrd-truncated", sizes + "encoding: raw\n", Voxels(1000));
  nrrd("nrrd-huge", "sizes: 100000 100000 100000\nspacings: 1 1 1\nencoding: raw\n", Voxels());
  nrrd("nrrd-zero-size", "sizes: 16 0 16\nspacings: 1 1 1\nencoding: raw\n", Voxels());
  nrrd("nrrd-zero-spacing", "sizes: 16 16 16\nspacings: 1 1 0\nencoding: raw\n", Voxels());
  nrrd("nrrd-nan-spacing", "sizes: 16 16 16\nspacings: 1 nan 1\nencoding: raw\n", Voxels());
  nrrd("nrrd-bzip2", sizes + "encoding: bzip2\n", Voxels());
  nrrd("nrrd-bad-gzip", sizes + "encoding: gzip\n", std::string(300, 'g'));
  nrrd("nrrd-time", sizes + "space: right-anterior-superior-time\nencoding: raw\n", Voxels());
  WriteText(dir + "/nrrd-unknown-type.nrrd",
    "NRRD0004\ntype: quaternion\ndimension: 3\n" + sizes + "encoding: raw\n\n" + Voxels());
  WriteText(dir + "/nrrd-garbage.nrrd", std::string(1000, 'n'));
  // Detached headers: the voxels in another file, cut short or missing.
  WriteText(dir + "/nhdr-truncated.nhdr",
    NrrdHeader(sizes + "encoding: raw\ndata file: nhdr-truncated.raw\n"));
  WriteText(dir + "/nhdr-truncated.raw", Voxels(3000));
  WriteText(dir + "/nhdr-missing-data.nhdr",
    NrrdHeader(sizes + "encoding: raw\ndata file: no-such-data.raw\n"));
}

// NIfTI-1 header fields patched into a valid file.
void PutInt16(std::string& bytes, size_t offset, int16_t v)
{
  std::memcpy(&bytes[offset], &v, sizeof(v));
}
void PutFloat(std::string& bytes, size_t offset, float v)
{
  std::memcpy(&bytes[offset], &v, sizeof(v));
}
constexpr size_t NiftiDim = 40, NiftiDataType = 70, NiftiPixDim = 76;

void WriteNifti(const std::string& dir)
{
  for (const char* name : { "/nifti-base.nii", "/nifti-base.nii.gz" })
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(Blob(1));
    writer->SetFileName((dir + name).c_str());
    writer->Write();
  }
  const std::string base = ReadBytes(dir + "/nifti-base.nii");
  const std::string gz = ReadBytes(dir + "/nifti-base.nii.gz");
  if (base.size() < 352 || gz.size() < 100)
  {
    std::cerr << "make-bad-inputs: vtkNIFTIImageWriter failed in " << dir << "\n";
    return;
  }
  auto patched = [&](const std::string& name, auto patch)
  {
    std::string bytes = base;
    patch(bytes);
    WriteText(dir + "/" + name + ".nii", bytes);
  };
  WriteText(dir + "/nii-truncated.nii", base.substr(0, 352 + 4 * 1000));
  WriteText(dir + "/nii-header-only.nii", base.substr(0, 200));
  patched("nii-huge",
    [](std::string& b)
    {
      for (int a = 1; a <= 3; ++a)
      {
        PutInt16(b, NiftiDim + 2 * a, 30000);
      }
    });
  patched("nii-zero-dim", [](std::string& b) { PutInt16(b, NiftiDim + 4, 0); });
  patched("nii-zero-spacing", [](std::string& b) { PutFloat(b, NiftiPixDim + 8, 0.0f); });
  patched("nii-nan-spacing",
    [](std::string& b) { PutFloat(b, NiftiPixDim + 4, std::numeric_limits<float>::quiet_NaN()); });
  patched("nii-unknown-type", [](std::string& b) { PutInt16(b, NiftiDataType, 1234); });
  patched("nii-bad-rank", [](std::string& b) { PutInt16(b, NiftiDim, 9); });
  WriteText(dir + "/niigz-truncated.nii.gz", gz.substr(0, gz.size() / 2));
  WriteText(dir + "/niigz-garbage.nii.gz", std::string("\x1f\x8b", 2) + std::string(500, 'q'));
}

std::string LegacyHeader(const std::string& format, const std::string& dims,
  const std::string& spacing, const std::string& type)
{
  return "# vtk DataFile Version 3.0\nbad input\n" + format +
    "\nDATASET STRUCTURED_POINTS\nDIMENSIONS " + dims + "\nSPACING " + spacing +
    "\nORIGIN 0 0 0\nPOINT_DATA 4096\nSCALARS s " + type + " 1\nLOOKUP_TABLE default\n";
}

std::string AsciiValues(int count)
{
  std::string text;
  for (int i = 0; i < count; ++i)
  {
    text += std::to_string(i % 97) + (i % 16 == 15 ? "\n" : " ");
  }
  return text;
}

void WriteLegacy(const std::string& dir)
{
  const std::string dims = "16 16 16", spacing = "1 1 1";
  WriteText(dir + "/vtk-truncated-ascii.vtk",
    LegacyHeader("ASCII", dims, spacing, "float") + AsciiValues(1000));
  WriteText(dir + "/vtk-truncated-binary.vtk",
    LegacyHeader("BINARY", dims, spacing, "unsigned_char") + Voxels(1000));
  WriteText(dir + "/vtk-huge.vtk",
    LegacyHeader("BINARY", "100000 100000 100000", spacing, "unsigned_char") + Voxels());
  WriteText(dir + "/vtk-zero-spacing.vtk",
    LegacyHeader("ASCII", dims, "1 0 1", "float") + AsciiValues(4096));
  WriteText(dir + "/vtk-unknown-type.vtk",
    LegacyHeader("ASCII", dims, spacing, "quaternion") + AsciiValues(4096));
  WriteText(dir + "/vtk-garbage.vtk", std::string(1000, 'v'));
}

std::string VtiFile(const std::string& extent, const std::string& spacing, const std::string& type,
  const std::string& values)
{
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<ImageData WholeExtent=\"" +
    extent + "\" Origin=\"0 0 0\" Spacing=\"" + spacing + "\">\n<Piece Extent=\"" + extent +
    "\">\n<PointData Scalars=\"s\">\n<DataArray type=\"" + type +
    "\" Name=\"s\" format=\"ascii\">\n" + values +
    "</DataArray>\n</PointData>\n<CellData/>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

void WriteVti(const std::string& dir)
{
  const std::string extent = "0 15 0 15 0 15";
  WriteText(dir + "/vti-huge.vti",
    VtiFile("0 99999 0 99999 0 99999", "1 1 1", "Float32", AsciiValues(4096)));
  WriteText(dir + "/vti-nan-spacing.vti", VtiFile(extent, "1 nan 1", "Float32", AsciiValues(4096)));
  WriteText(dir + "/vti-zero-spacing.vti", VtiFile(extent, "0 1 1", "Float32", AsciiValues(4096)));
  WriteText(
    dir + "/vti-unknown-type.vti", VtiFile(extent, "1 1 1", "Quaternion", AsciiValues(4096)));
  WriteText(dir + "/vti-short-ascii.vti", VtiFile(extent, "1 1 1", "Float32", AsciiValues(1000)));
  WriteText(dir + "/vti-garbage.vti", std::string(1000, 'x'));
  // Raw appended data (no compression, no base64), cut in the middle.
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(Blob(1));
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToNone();
  writer->SetFileName((dir + "/vti-appended-base.vti").c_str());
  writer->Write();
  const std::string appended = ReadBytes(dir + "/vti-appended-base.vti");
  WriteText(dir + "/vti-appended-truncated.vti", appended.substr(0, appended.size() - 20000));
}

std::vector<int16_t> Slab(int columns, int rows)
{
  std::vector<int16_t> pixels(static_cast<size_t>(columns) * rows);
  for (size_t i = 0; i < pixels.size(); ++i)
  {
    pixels[i] = static_cast<int16_t>(i % 2000 - 1000);
  }
  return pixels;
}

void WriteDicom(const std::string& dir)
{
  // Each series: 4 slices of 32 x 28, one of them damaged.
  auto series = [&](const std::string& name, int damaged, auto damage)
  {
    const std::string path = dir + "/" + name;
    vtksys::SystemTools::MakeDirectory(path);
    for (int k = 0; k < 4; ++k)
    {
      DicomSlice slice;
      slice.Index = k;
      slice.Pixels = Slab(32, 28);
      if (k == damaged)
      {
        damage(slice);
      }
      WriteDicomSlice(path + "/slice" + std::to_string(k) + ".dcm", slice);
    }
  };
  series("dicom-truncated", 2, [](DicomSlice& s) { s.KeepBytes = 900; });
  series("dicom-zero-spacing", 0, [](DicomSlice& s) { s.PixelSpacing = "0\\0"; });
  series("dicom-huge", 0,
    [](DicomSlice& s)
    {
      s.Rows = 65535;
      s.Columns = 65535;
    });
  series("dicom-mixed-sizes", 3,
    [](DicomSlice& s)
    {
      s.Rows = 64;
      s.Columns = 64;
      s.Pixels = Slab(64, 64);
    });
}
}

//------------------------------------------------------------------------------
int MakeBadInputs(const std::string& dir, const std::string& vdb)
{
  vtksys::SystemTools::MakeDirectory(dir);
  WriteMetaImage(dir);
  WriteNrrd(dir);
  WriteNifti(dir);
  WriteLegacy(dir);
  WriteVti(dir);
  WriteDicom(dir);
  WriteText(dir + "/slc-garbage.slc", std::string(1000, 's'));
  if (!vdb.empty())
  {
    // A real OpenVDB file cut in the middle of its voxels.
    const std::string bytes = ReadBytes(vdb);
    WriteText(dir + "/vdb-truncated.vdb", bytes.substr(0, bytes.size() / 2));
  }
  std::cout << "wrote the bad inputs into " << dir << "\n";
  return 0;
}
}
