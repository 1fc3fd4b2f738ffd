#include "vtkVolumeFileDicom.h"

#include "vtksys/FStream.hxx"
#include "vtksys/SystemTools.hxx"

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
