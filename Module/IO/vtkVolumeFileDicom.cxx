#include "vtkVolumeFileDicom.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkSmartPointer.h"
#include "vtksys/FStream.hxx"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iterator>
#include <sstream>

namespace
{
constexpr std::uint32_t Undefined = 0xFFFFFFFFu;
constexpr std::uint32_t Tag(std::uint16_t group, std::uint16_t element)
{
  return (static_cast<std::uint32_t>(group) << 16) | element;
}
constexpr std::uint32_t ItemTag = Tag(0xFFFE, 0xE000);
constexpr std::uint32_t ItemEnd = Tag(0xFFFE, 0xE00D);
constexpr std::uint32_t SequenceEnd = Tag(0xFFFE, 0xE0DD);
constexpr std::uint32_t PixelData = Tag(0x7FE0, 0x0010);

// Little-endian reads from a file's bytes; the walker checks bounds first.
struct Bytes
{
  const std::string& Data;
  std::uint16_t U16(size_t at) const
  {
    return static_cast<std::uint16_t>(
      static_cast<unsigned char>(Data[at]) | (static_cast<unsigned char>(Data[at + 1]) << 8));
  }
  std::uint32_t U32(size_t at) const
  {
    return static_cast<std::uint32_t>(U16(at)) | (static_cast<std::uint32_t>(U16(at + 2)) << 16);
  }
};

// One element's header: tag, VR (explicit syntax) and value length.
struct Element
{
  std::uint32_t Tag = 0;
  std::string VR;
  std::uint32_t Length = 0;
  size_t Value = 0; // offset of the value
};

bool LongLength(const std::string& vr)
{
  static const char* longs[] = { "OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR",
    "UT", "UV" };
  for (const char* l : longs)
  {
    if (vr == l)
    {
      return true;
    }
  }
  return false;
}

// Reads the element header at `pos`; false if it runs past the end.
bool ReadElement(const Bytes& b, size_t pos, bool explicitVR, Element& e)
{
  const size_t size = b.Data.size();
  if (pos + 8 > size)
  {
    return false;
  }
  e.Tag = Tag(b.U16(pos), b.U16(pos + 2));
  e.VR.clear();
  if (!explicitVR || (e.Tag >> 16) == 0xFFFE)
  {
    e.Length = b.U32(pos + 4);
    e.Value = pos + 8;
    return true;
  }
  e.VR = b.Data.substr(pos + 4, 2);
  if (LongLength(e.VR))
  {
    if (pos + 12 > size)
    {
      return false;
    }
    e.Length = b.U32(pos + 8);
    e.Value = pos + 12;
  }
  else
  {
    e.Length = b.U16(pos + 6);
    e.Value = pos + 8;
  }
  return true;
}

// Walks elements from `pos` until `stop` (an item or sequence end tag at
// this level, or 0 for the top level), calling `visit` on top-level ones.
// Returns "" or a problem; `pos` ends after the stop tag or at the pixel data.
std::string Walk(const Bytes& b, size_t& pos, bool explicitVR, std::uint32_t stop, int depth,
  const std::function<void(const Element&)>& visit)
{
  if (depth > 16)
  {
    return "sequences nested too deeply";
  }
  Element e;
  while (pos < b.Data.size())
  {
    if (!ReadElement(b, pos, explicitVR, e))
    {
      return "the file ends inside an element header at byte " + std::to_string(pos);
    }
    if (stop && e.Tag == stop)
    {
      pos = e.Value;
      return std::string();
    }
    if (depth == 0 && e.Tag == PixelData)
    {
      visit(e);
      return std::string();
    }
    if (e.Tag == ItemTag && e.Length != Undefined && e.Value + e.Length <= b.Data.size())
    {
      pos = e.Value + e.Length; // an item of known length inside a sequence
      continue;
    }
    if (e.Length == Undefined)
    {
      // A sequence (or item) of undefined length: walk it to its end.
      pos = e.Value;
      const bool item = e.Tag == ItemTag;
      const std::string problem =
        Walk(b, pos, explicitVR, item ? ItemEnd : SequenceEnd, depth + 1, nullptr);
      if (!problem.empty())
      {
        return problem;
      }
      continue;
    }
    if (e.Value + e.Length > b.Data.size())
    {
      return "the file ends inside element (" + std::to_string(e.Tag >> 16) + "," +
        std::to_string(e.Tag & 0xFFFF) + ")";
    }
    if (depth == 0)
    {
      visit(e);
    }
    pos = e.Value + e.Length;
  }
  return stop ? "the file ends inside a sequence" : std::string();
}

std::vector<double> Numbers(const std::string& text)
{
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, '\\');)
  {
    values.push_back(std::atof(item.c_str()));
  }
  return values;
}

std::string Text(const Bytes& b, const Element& e)
{
  std::string text = b.Data.substr(e.Value, e.Length);
  while (!text.empty() && (text.back() == '\0' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

// Records the fields of `e` that the checks and the placement need.
void Record(const Bytes& b, const Element& e, tyndall_io::DicomSlice& slice)
{
  const bool us = e.Length >= 2;
  switch (e.Tag)
  {
    case Tag(0x0028, 0x0010):
      slice.Rows = us ? b.U16(e.Value) : 0;
      break;
    case Tag(0x0028, 0x0011):
      slice.Columns = us ? b.U16(e.Value) : 0;
      break;
    case Tag(0x0028, 0x0100):
      slice.BitsAllocated = us ? b.U16(e.Value) : 0;
      break;
    case Tag(0x0028, 0x0002):
      slice.SamplesPerPixel = us ? b.U16(e.Value) : 0;
      break;
    case Tag(0x0020, 0x0032):
      slice.Position = Numbers(Text(b, e));
      break;
    case Tag(0x0020, 0x0037):
      slice.Orientation = Numbers(Text(b, e));
      break;
    case Tag(0x0028, 0x0030):
      slice.PixelSpacing = Numbers(Text(b, e));
      break;
    case Tag(0x0028, 0x0103):
      slice.PixelRepresentation = us ? b.U16(e.Value) : 0;
      break;
    case Tag(0x0028, 0x0008):
      slice.NumberOfFrames = std::atoi(Text(b, e).c_str());
      break;
    case Tag(0x0008, 0x0060):
      slice.Modality = Text(b, e);
      break;
    case Tag(0x0020, 0x000E):
      slice.SeriesUID = Text(b, e);
      break;
    case Tag(0x0028, 0x1052):
      slice.Intercept = std::atof(Text(b, e).c_str());
      break;
    case Tag(0x0028, 0x1053):
      slice.Slope = std::atof(Text(b, e).c_str());
      break;
    case PixelData:
      slice.PixelOffset = static_cast<std::int64_t>(e.Value);
      slice.PixelLength = e.Length == Undefined ? -1 : static_cast<std::int64_t>(e.Length);
      break;
    default:
      break;
  }
}

std::string Size(const tyndall_io::DicomSlice& s)
{
  return std::to_string(s.Columns) + " x " + std::to_string(s.Rows) + " pixels of " +
    std::to_string(s.BitsAllocated) + " bits x " + std::to_string(s.SamplesPerPixel);
}
}

namespace tyndall_io
{
//------------------------------------------------------------------------------
std::string ScanDicomFile(const std::string& path, DicomSlice& slice)
{
  slice = DicomSlice();
  slice.File = path;
  const std::string name = vtksys::SystemTools::GetFilenameName(path);
  if (vtksys::SystemTools::FileLength(path) > (1ull << 31))
  {
    return name + " is larger than 2 GiB";
  }
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Bytes b{ data };
  // The file meta information: group 2, explicit VR little endian, after
  // the 128-byte preamble and "DICM".
  size_t pos = 132;
  Element e;
  while (ReadElement(b, pos, true, e) && (e.Tag >> 16) == 0x0002 && e.Length != Undefined &&
    e.Value + e.Length <= data.size())
  {
    if (e.Tag == Tag(0x0002, 0x0010))
    {
      slice.TransferSyntax = Text(b, e);
    }
    pos = e.Value + e.Length;
  }
  const std::string& syntax = slice.TransferSyntax;
  const bool implicitVR = syntax == "1.2.840.10008.1.2";
  if (!implicitVR && syntax != "1.2.840.10008.1.2.1" && !syntax.empty())
  {
    return name + ": transfer syntax " + syntax +
      " (compressed or big endian) is not read by VTK's DICOM reader; convert the series to "
      "uncompressed little endian first (for example with dcmtk's dcmdjpeg or gdcmconv --raw)";
  }
  const std::string problem =
    Walk(b, pos, !implicitVR, 0, 0, [&](const Element& element) { Record(b, element, slice); });
  if (!problem.empty())
  {
    return name + ": " + problem;
  }
  if (slice.PixelOffset < 0)
  {
    return name + ": no pixel data";
  }
  if (slice.PixelLength < 0)
  {
    return name + ": encapsulated (compressed) pixel data, which VTK's DICOM reader does not read";
  }
  if (slice.Rows <= 0 || slice.Columns <= 0 || slice.SamplesPerPixel <= 0 ||
    (slice.BitsAllocated != 8 && slice.BitsAllocated != 16 && slice.BitsAllocated != 32))
  {
    return name + ": impossible image size (" + Size(slice) + ")";
  }
  const std::int64_t needed = static_cast<std::int64_t>(slice.Rows) * slice.Columns *
    slice.SamplesPerPixel * (slice.BitsAllocated / 8);
  const std::int64_t held = static_cast<std::int64_t>(data.size()) - slice.PixelOffset;
  if (std::min(slice.PixelLength, held) < needed)
  {
    return name + ": truncated: its " + Size(slice) + " need " + std::to_string(needed) +
      " bytes of pixel data, the file holds " + std::to_string(std::min(slice.PixelLength, held));
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string CheckDicomSeries(const std::vector<DicomSlice>& slices)
{
  for (const DicomSlice& s : slices)
  {
    const DicomSlice& first = slices.front();
    if (s.NumberOfFrames > 1)
    {
      return vtksys::SystemTools::GetFilenameName(s.File) + " holds " +
        std::to_string(s.NumberOfFrames) + " frames; multi-frame files are not read";
    }
    if (s.SeriesUID != first.SeriesUID)
    {
      return "the directory mixes two series (" + vtksys::SystemTools::GetFilenameName(first.File) +
        " and " + vtksys::SystemTools::GetFilenameName(s.File) +
        " have different Series Instance UIDs); give a directory that holds one";
    }
    if (s.Rows != first.Rows || s.Columns != first.Columns ||
      s.BitsAllocated != first.BitsAllocated || s.SamplesPerPixel != first.SamplesPerPixel)
    {
      return "the slices differ: " + vtksys::SystemTools::GetFilenameName(first.File) + " has " +
        Size(first) + ", " + vtksys::SystemTools::GetFilenameName(s.File) + " has " + Size(s);
    }
  }
  return std::string();
}
}

namespace
{
std::string Vector(const double v[3])
{
  std::ostringstream os;
  os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return os.str();
}

// Row and column directions (unit) from the orientation tag; false if the
// tag is missing or degenerate.
bool Directions(const tyndall_io::DicomSlice& s, double row[3], double column[3])
{
  if (s.Orientation.size() != 6)
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    row[a] = s.Orientation[a];
    column[a] = s.Orientation[3 + a];
  }
  const double nr = vtkMath::Normalize(row), nc = vtkMath::Normalize(column);
  return nr > 1e-6 && nc > 1e-6 && std::abs(vtkMath::Dot(row, column)) < 1e-3;
}

// A stored pixel value (little endian, `bytes` wide, signed or not).
double Stored(const unsigned char* p, int bytes, bool isSigned)
{
  if (bytes == 1)
  {
    return isSigned ? static_cast<signed char>(p[0]) : p[0];
  }
  if (bytes == 2)
  {
    const std::uint16_t u = static_cast<std::uint16_t>(p[0] | (p[1] << 8));
    return isSigned ? static_cast<std::int16_t>(u) : u;
  }
  const std::uint32_t u = static_cast<std::uint32_t>(p[0]) |
    (static_cast<std::uint32_t>(p[1]) << 8) | (static_cast<std::uint32_t>(p[2]) << 16) |
    (static_cast<std::uint32_t>(p[3]) << 24);
  return isSigned ? static_cast<double>(static_cast<std::int32_t>(u)) : static_cast<double>(u);
}

// The array type that holds every rescaled value exactly (short, int) or
// float.
vtkSmartPointer<vtkDataArray> ValueArray(const std::vector<tyndall_io::DicomSlice>& slices)
{
  const tyndall_io::DicomSlice& first = slices.front();
  bool integral = true;
  double low = 0.0, high = 0.0;
  const int bytes = first.BitsAllocated / 8;
  const bool isSigned = first.PixelRepresentation == 1;
  const double storedLow = isSigned ? -std::ldexp(1.0, 8 * bytes - 1) : 0.0;
  const double storedHigh =
    isSigned ? std::ldexp(1.0, 8 * bytes - 1) - 1 : std::ldexp(1.0, 8 * bytes) - 1;
  for (size_t k = 0; k < slices.size(); ++k)
  {
    const auto& s = slices[k];
    integral = integral && s.Slope == std::floor(s.Slope) && s.Intercept == std::floor(s.Intercept);
    const double a = storedLow * s.Slope + s.Intercept, b = storedHigh * s.Slope + s.Intercept;
    low = k ? std::min({ low, a, b }) : std::min(a, b);
    high = k ? std::max({ high, a, b }) : std::max(a, b);
  }
  if (integral && low >= VTK_SHORT_MIN && high <= VTK_SHORT_MAX)
  {
    return vtkSmartPointer<vtkShortArray>::New();
  }
  if (integral && low >= VTK_INT_MIN && high <= VTK_INT_MAX)
  {
    return vtkSmartPointer<vtkIntArray>::New();
  }
  return vtkSmartPointer<vtkFloatArray>::New();
}

// Fills slice k of `values` from its file's pixel data.
bool ReadPixels(const tyndall_io::DicomSlice& s, vtkIdType first, vtkDataArray* values)
{
  const int bytes = s.BitsAllocated / 8;
  const vtkIdType count = static_cast<vtkIdType>(s.Rows) * s.Columns;
  std::vector<unsigned char> raw(static_cast<size_t>(count) * bytes);
  vtksys::ifstream in(s.File.c_str(), std::ios::binary);
  in.seekg(static_cast<std::streamoff>(s.PixelOffset));
  in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size()));
  if (in.gcount() != static_cast<std::streamsize>(raw.size()))
  {
    return false;
  }
  const bool isSigned = s.PixelRepresentation == 1;
  for (vtkIdType p = 0; p < count; ++p)
  {
    values->SetTuple1(first + p, Stored(&raw[p * bytes], bytes, isSigned) * s.Slope + s.Intercept);
  }
  return true;
}
}

namespace tyndall_io
{
//------------------------------------------------------------------------------
std::string ReadDicomSeries(std::vector<DicomSlice> slices, double memoryLimitMiB,
  vtkImageData* image, std::vector<std::string>& notes)
{
  DicomSlice& first = slices.front();
  if (first.SamplesPerPixel != 1)
  {
    return "colour DICOM images (" + std::to_string(first.SamplesPerPixel) +
      " samples per pixel) are not volumes";
  }
  double row[3] = { 1, 0, 0 }, column[3] = { 0, 1, 0 }, normal[3];
  if (!Directions(first, row, column))
  {
    row[0] = column[1] = 1.0;
    row[1] = row[2] = column[0] = column[2] = 0.0;
    notes.push_back("DICOM: no usable Image Orientation (Patient); the image axes are used");
  }
  vtkMath::Cross(row, column, normal);
  // Slices sorted by their position along the normal.
  const bool positioned = std::all_of(
    slices.begin(), slices.end(), [](const DicomSlice& s) { return s.Position.size() == 3; });
  std::vector<double> depth(slices.size());
  for (size_t k = 0; k < slices.size(); ++k)
  {
    depth[k] =
      positioned ? vtkMath::Dot(slices[k].Position.data(), normal) : static_cast<double>(k);
  }
  std::vector<size_t> order(slices.size());
  for (size_t k = 0; k < order.size(); ++k)
  {
    order[k] = k;
  }
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return depth[a] < depth[b]; });
  if (!positioned)
  {
    notes.push_back("DICOM: no Image Position (Patient) in some files; slices in file-name order, "
                    "1 apart");
  }
  const size_t n = slices.size();
  const double gap = n > 1 ? (depth[order[n - 1]] - depth[order[0]]) / (n - 1) : 1.0;
  for (size_t k = 1; k < n; ++k)
  {
    const double step = depth[order[k]] - depth[order[k - 1]];
    if (!(std::abs(step - gap) <= 0.01 * std::abs(gap)) || gap <= 0.0)
    {
      return "the slices are not evenly spaced along the normal " + Vector(normal) + ": " +
        vtksys::SystemTools::GetFilenameName(slices[order[k - 1]].File) + " and " +
        vtksys::SystemTools::GetFilenameName(slices[order[k]].File) + " are " +
        std::to_string(step) + " mm apart, the mean gap is " + std::to_string(gap) +
        " mm (a missing slice, two series, or a tilted gantry?)";
    }
  }
  double spacing[3] = { 1.0, 1.0, gap };
  if (first.PixelSpacing.size() == 2)
  {
    spacing[0] = first.PixelSpacing[1]; // between columns: along the row direction
    spacing[1] = first.PixelSpacing[0]; // between rows: along the column direction
  }
  for (double v : spacing)
  {
    if (!std::isfinite(v) || v <= 0.0)
    {
      return "the spacing " + Vector(spacing) + " is not finite and non-zero along every axis";
    }
  }
  std::vector<DicomSlice> sorted;
  for (size_t k : order)
  {
    sorted.push_back(slices[k]);
  }
  vtkSmartPointer<vtkDataArray> values = ValueArray(sorted);
  const double points = static_cast<double>(first.Columns) * first.Rows * n;
  if (points * values->GetDataTypeSize() > memoryLimitMiB * 1024.0 * 1024.0)
  {
    return "the series claims " + std::to_string(first.Columns) + " x " +
      std::to_string(first.Rows) + " x " + std::to_string(n) +
      " points, above the memory limit of " +
      std::to_string(static_cast<long long>(memoryLimitMiB)) + " MiB";
  }
  values->SetName("DICOM");
  values->SetNumberOfTuples(static_cast<vtkIdType>(points));
  const vtkIdType perSlice = static_cast<vtkIdType>(first.Columns) * first.Rows;
  for (size_t k = 0; k < n; ++k)
  {
    if (!ReadPixels(sorted[k], static_cast<vtkIdType>(k) * perSlice, values))
    {
      return vtksys::SystemTools::GetFilenameName(sorted[k].File) + ": cannot read its pixel data";
    }
  }
  image->SetDimensions(first.Columns, first.Rows, static_cast<int>(n));
  image->SetSpacing(spacing);
  image->SetOrigin(
    positioned ? sorted.front().Position.data() : std::vector<double>(3, 0.0).data());
  const double direction[9] = { row[0], column[0], normal[0], row[1], column[1], normal[1], row[2],
    column[2], normal[2] };
  image->SetDirectionMatrix(direction);
  image->GetPointData()->SetScalars(values);
  if (first.Slope != 1.0 || first.Intercept != 0.0)
  {
    std::ostringstream note;
    note << "DICOM rescale applied: value = stored x " << first.Slope << " + " << first.Intercept
         << " (Rescale Slope, Rescale Intercept)";
    notes.push_back(note.str());
  }
  return std::string();
}
}
