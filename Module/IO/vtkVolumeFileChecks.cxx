#include "vtkVolumeFileChecks.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtk_zlib.h"
#include "vtksys/FStream.hxx"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
std::string Trim(const std::string& text)
{
  size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
  {
    ++begin;
  }
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
  {
    --end;
  }
  return text.substr(begin, end - begin);
}

// A path named in a header: relative to the header's directory.
std::string Beside(const std::string& header, const std::string& name)
{
  if (vtksys::SystemTools::FileIsFullPath(name))
  {
    return name;
  }
  const std::string dir = vtksys::SystemTools::GetFilenamePath(header);
  return dir.empty() ? name : dir + "/" + name;
}

// Whether a header's file reference is a list or a pattern of files, which
// the size check does not follow.
bool SeveralFiles(const std::string& value)
{
  return value.rfind("LIST", 0) == 0 || value.find('%') != std::string::npos ||
    value.find(' ') != std::string::npos;
}

// The voxels in `dataFile`, named by `header`, after `offset` bytes (a list
// or pattern of files is not followed: File stays empty).
tyndall_io::RawData External(const std::string& header, const std::string& dataFile,
  std::int64_t offset, const std::string& encoding)
{
  tyndall_io::RawData raw;
  if (SeveralFiles(dataFile))
  {
    raw.Encoding = "several files";
    return raw;
  }
  raw.File = Beside(header, dataFile);
  raw.Offset = offset;
  raw.Encoding = encoding;
  return raw;
}

// The "field: value" lines of an NRRD header, in order (comments and
// key:=value lines skipped). The header ends at its first empty line, whose
// end `end` receives (-1 when the file is all header: a detached one).
std::vector<std::pair<std::string, std::string>> NrrdFields(
  const std::string& path, std::int64_t& end)
{
  std::vector<std::pair<std::string, std::string>> fields;
  end = -1;
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  std::string line;
  while (std::getline(in, line) && in.tellg() < (1 << 22))
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.empty())
    {
      end = static_cast<std::int64_t>(in.tellg());
      break;
    }
    const size_t colon = line.find(": ");
    if (line[0] != '#' && colon != std::string::npos)
    {
      fields.emplace_back(line.substr(0, colon), Trim(line.substr(colon + 2)));
    }
  }
  return fields;
}

// A field of type T at byte `at` of a binary header, byte-swapped if asked.
template <class T>
T HeaderField(const unsigned char* header, size_t at, bool swap)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, header + at, sizeof(T));
  if (swap)
  {
    std::reverse(b, b + sizeof(T));
  }
  T value;
  std::memcpy(&value, b, sizeof(T));
  return value;
}

bool KnownType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
    case VTK_FLOAT:
    case VTK_DOUBLE:
      return true;
    default:
      return false;
  }
}

// The type and components of the active scalars the information announces
// (point data, else cell data); false when it announces none.
bool AnnouncedScalars(vtkInformation* info, int& type, int& components)
{
  for (int association :
    { vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataObject::FIELD_ASSOCIATION_CELLS })
  {
    vtkInformation* field =
      vtkDataObject::GetActiveFieldInformation(info, association, vtkDataSetAttributes::SCALARS);
    if (field && field->Has(vtkDataObject::FIELD_ARRAY_TYPE()))
    {
      type = field->Get(vtkDataObject::FIELD_ARRAY_TYPE());
      components = field->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        ? field->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        : 1;
      return true;
    }
  }
  return false;
}

std::string Triple(const double v[3])
{
  std::ostringstream os;
  os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return os.str();
}
}

namespace tyndall_io
{
std::string CheckCompressed(const RawData& raw, double bytes);

//------------------------------------------------------------------------------
std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

//------------------------------------------------------------------------------
std::string FormatBytes(double bytes)
{
  static const char* units[] = { "bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB" };
  int unit = 0;
  double scaled = bytes;
  while (scaled >= 1024.0 && unit < 6)
  {
    scaled /= 1024.0;
    ++unit;
  }
  std::ostringstream os;
  if (bytes < 1.0e15)
  {
    os << static_cast<long long>(bytes) << " bytes";
  }
  else
  {
    os << std::setprecision(3) << bytes << " bytes";
  }
  if (unit > 0)
  {
    os << " (" << std::setprecision(3) << scaled << " " << units[unit] << ")";
  }
  return os.str();
}

//------------------------------------------------------------------------------
std::string CheckInformation(vtkInformation* info, double memoryLimitMiB, double& bytes)
{
  bytes = 0.0;
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return "the header gives no extent";
  }
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<double>(extent[2 * a + 1]) - extent[2 * a] + 1.0;
  }
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    std::ostringstream os;
    os << "the image is " << dims[0] << " x " << dims[1] << " x " << dims[2]
       << " points; a volume needs at least 2 points along each axis";
    return os.str();
  }
  int type = VTK_FLOAT, components = 1;
  const bool announced = AnnouncedScalars(info, type, components);
  if (announced && !KnownType(type))
  {
    return "the header's voxel type (VTK type id " + std::to_string(type) +
      ") is not a numeric type";
  }
  if (components < 1)
  {
    return "the header claims " + std::to_string(components) + " components per voxel";
  }
  // Unannounced scalars (XML files announce them, raw readers too): count
  // one byte per value, the least any type needs.
  const int valueBytes = announced ? vtkDataArray::GetDataTypeSize(type) : 1;
  bytes = dims[0] * dims[1] * dims[2] * components * valueBytes;
  const double limit = memoryLimitMiB * 1024.0 * 1024.0;
  if (bytes > limit)
  {
    std::ostringstream os;
    os << "the header claims " << dims[0] << " x " << dims[1] << " x " << dims[2] << " points";
    if (announced)
    {
      os << " of " << components << " x " << vtkImageScalarTypeNameMacro(type);
    }
    os << ", " << FormatBytes(bytes) << ", above the memory limit of " << memoryLimitMiB
       << " MiB (vtkVolumeFileReader::SetMemoryLimit; tyndall-render --memory-limit)";
    return os.str();
  }
  double spacing[3] = { 1.0, 1.0, 1.0 }, origin[3] = { 0.0, 0.0, 0.0 };
  if (info->Has(vtkDataObject::SPACING()))
  {
    info->Get(vtkDataObject::SPACING(), spacing);
  }
  if (info->Has(vtkDataObject::ORIGIN()))
  {
    info->Get(vtkDataObject::ORIGIN(), origin);
  }
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(spacing[a]) || spacing[a] == 0.0)
    {
      return "the spacing " + Triple(spacing) + " is not finite and non-zero along every axis";
    }
    if (!std::isfinite(origin[a]))
    {
      return "the origin " + Triple(origin) + " is not finite";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string CheckRawData(const RawData& raw, double bytes)
{
  if (raw.File.empty())
  {
    return std::string();
  }
  if (!vtksys::SystemTools::FileExists(raw.File, true))
  {
    return "the data file '" + raw.File + "' named by the header does not exist";
  }
  if (raw.Encoding == "zlib")
  {
    return CheckCompressed(raw, bytes);
  }
  const double length = static_cast<double>(vtksys::SystemTools::FileLength(raw.File));
  const double offset = raw.Offset < 0 ? 0.0 : static_cast<double>(raw.Offset);
  if (length - offset >= bytes)
  {
    return std::string();
  }
  std::ostringstream os;
  os << "truncated: the header claims " << FormatBytes(bytes) << " of voxel data";
  if (raw.Offset > 0)
  {
    os << " after byte " << raw.Offset;
  }
  os << " of '" << raw.File << "', which holds " << FormatBytes(length);
  return os.str();
}

//------------------------------------------------------------------------------
std::string CheckCompressed(const RawData& raw, double bytes)
{
  vtksys::ifstream in(raw.File.c_str(), std::ios::binary);
  in.seekg(std::max<std::int64_t>(raw.Offset, 0));
  z_stream stream;
  std::memset(&stream, 0, sizeof(stream));
  if (inflateInit2(&stream, 32 + MAX_WBITS) != Z_OK) // zlib or gzip header
  {
    return "cannot start zlib";
  }
  std::vector<unsigned char> input(1 << 16), output(1 << 16);
  double produced = 0.0;
  int status = Z_OK;
  while (status == Z_OK && produced < bytes)
  {
    if (stream.avail_in == 0)
    {
      in.read(reinterpret_cast<char*>(input.data()), static_cast<std::streamsize>(input.size()));
      stream.next_in = input.data();
      stream.avail_in = static_cast<uInt>(in.gcount());
      if (stream.avail_in == 0)
      {
        break; // the file ends inside the stream
      }
    }
    stream.next_out = output.data();
    stream.avail_out = static_cast<uInt>(output.size());
    status = inflate(&stream, Z_NO_FLUSH);
    produced += static_cast<double>(output.size() - stream.avail_out);
  }
  inflateEnd(&stream);
  if (status != Z_OK && status != Z_STREAM_END)
  {
    return "the compressed voxel data in '" + raw.File +
      "' is corrupted (zlib: " + (stream.msg ? stream.msg : "error " + std::to_string(status)) +
      ")";
  }
  if (produced < bytes)
  {
    return "truncated: the header claims " + FormatBytes(bytes) +
      " of voxel data, the compressed data in '" + raw.File + "' holds " + FormatBytes(produced);
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string CheckNiftiHeader(const std::string& path)
{
  gzFile file = gzopen(path.c_str(), "rb"); // reads plain files too
  if (!file)
  {
    return "cannot open the file";
  }
  unsigned char header[540];
  const int got = gzread(file, header, sizeof(header));
  gzclose(file);
  if (got < 348)
  {
    return "not a NIfTI file (" + std::to_string(std::max(got, 0)) +
      " bytes, shorter than a NIfTI header)";
  }
  const std::int32_t size = HeaderField<std::int32_t>(header, 0, false);
  const bool swap = size != 348 && size != 540;
  const std::int32_t sized = HeaderField<std::int32_t>(header, 0, swap);
  if (sized != 348 && sized != 540)
  {
    return "not a NIfTI file (header size " + std::to_string(size) + ")";
  }
  const bool two = sized == 540;
  if (two && got < 540)
  {
    return "not a NIfTI-2 file (its header is cut short)";
  }
  // Field positions: NIfTI-1 (int16 dims, float pixdims), NIfTI-2 (int64, double).
  const int datatype = HeaderField<std::int16_t>(header, two ? 12 : 70, swap);
  static const int known[] = { 2, 4, 8, 16, 32, 64, 128, 256, 512, 768, 1024, 1280, 1792, 2304 };
  if (std::find(std::begin(known), std::end(known), datatype) == std::end(known))
  {
    return "unknown NIfTI datatype code " + std::to_string(datatype);
  }
  const double rank = two ? static_cast<double>(HeaderField<std::int64_t>(header, 16, swap))
                          : HeaderField<std::int16_t>(header, 40, swap);
  if (rank < 1 || rank > 7)
  {
    return "impossible NIfTI header: " + std::to_string(static_cast<long long>(rank)) +
      " dimensions (dim[0] must be 1 to 7)";
  }
  double pixdim[3];
  for (int a = 0; a < 3; ++a)
  {
    pixdim[a] = two ? HeaderField<double>(header, 104 + 8 * (a + 1), swap)
                    : HeaderField<float>(header, 76 + 4 * (a + 1), swap);
  }
  for (int a = 0; a < std::min(3, static_cast<int>(rank)); ++a)
  {
    if (!std::isfinite(pixdim[a]) || pixdim[a] == 0.0)
    {
      return "the spacing (pixdim) " + Triple(pixdim) +
        " is not finite and non-zero along every axis";
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
RawData MetaImageRawData(const std::string& path)
{
  RawData raw;
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  std::string line, dataFile;
  std::int64_t headerSize = 0;
  bool compressed = false, binary = true;
  // The header is "Key = Value" lines; ElementDataFile ends it.
  while (std::getline(in, line) && in.tellg() < (1 << 20))
  {
    const size_t equals = line.find('=');
    if (equals == std::string::npos)
    {
      continue;
    }
    const std::string key = Trim(line.substr(0, equals));
    const std::string value = Trim(line.substr(equals + 1));
    if (key == "CompressedData")
    {
      compressed = Lower(value) == "true";
    }
    else if (key == "BinaryData")
    {
      binary = Lower(value) != "false";
    }
    else if (key == "HeaderSize")
    {
      headerSize = std::atoll(value.c_str());
    }
    else if (key == "ElementDataFile")
    {
      dataFile = value;
      break;
    }
  }
  if (dataFile.empty())
  {
    raw.Encoding = "unknown"; // metaio reports the missing field
    return raw;
  }
  if (!binary)
  {
    raw.Encoding = "ascii";
    return raw;
  }
  raw.Encoding = compressed ? "zlib" : "raw";
  if (dataFile == "LOCAL")
  {
    raw.File = path;
    raw.Offset = static_cast<std::int64_t>(in.tellg()) + std::max<std::int64_t>(headerSize, 0);
    return raw;
  }
  return External(path, dataFile, headerSize, raw.Encoding);
}

//------------------------------------------------------------------------------
RawData NrrdRawData(const std::string& path)
{
  RawData raw;
  std::string dataFile;
  std::string encoding = "raw";
  std::int64_t byteSkip = 0, end = -1;
  for (const auto& f : NrrdFields(path, end))
  {
    if (f.first == "encoding")
    {
      encoding = Lower(f.second);
    }
    else if (f.first == "data file" || f.first == "datafile")
    {
      dataFile = f.second;
    }
    else if (f.first == "byte skip" || f.first == "byteskip")
    {
      byteSkip = std::atoll(f.second.c_str());
    }
  }
  const bool blank = end >= 0;
  if (encoding == "gzip" || encoding == "gz")
  {
    encoding = "zlib";
  }
  else if (encoding != "raw")
  {
    raw.Encoding = encoding;
    return raw;
  }
  raw.Encoding = encoding;
  if (dataFile.empty())
  {
    if (!blank)
    {
      raw.Encoding = "unknown"; // no data: the reader reports it
      return raw;
    }
    raw.File = path;
    raw.Offset = end;
    return raw;
  }
  return External(path, dataFile, byteSkip, raw.Encoding);
}
}

namespace
{
// The value of attribute `name` in `tag` ("" if absent).
std::string Attribute(const std::string& tag, const std::string& name)
{
  const std::string key = " " + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos)
  {
    return std::string();
  }
  const size_t begin = at + key.size();
  const size_t end = tag.find('"', begin);
  return end == std::string::npos ? std::string() : tag.substr(begin, end - begin);
}

// The XML tag that starts at `at` ("<Name ... >").
std::string TagAt(const std::string& text, size_t at)
{
  const size_t end = text.find('>', at);
  return end == std::string::npos ? text.substr(at) : text.substr(at, end - at + 1);
}

// Three numbers (strtod: "nan" and "inf" parse too); false if fewer.
bool Three(const std::string& text, double v[3])
{
  const char* p = text.c_str();
  for (int i = 0; i < 3; ++i)
  {
    char* end = nullptr;
    v[i] = std::strtod(p, &end);
    if (end == p)
    {
      return false;
    }
    p = end;
  }
  return true;
}

// Reads an unsigned integer of `size` bytes (4 or 8, little endian) at `at`.
bool ReadUnsigned(vtksys::ifstream& in, double at, int size, double& value)
{
  unsigned char b[8] = { 0 };
  in.clear();
  in.seekg(static_cast<std::streamoff>(at));
  in.read(reinterpret_cast<char*>(b), size);
  if (in.gcount() != size)
  {
    return false;
  }
  value = 0.0;
  for (int i = size - 1; i >= 0; --i)
  {
    value = value * 256.0 + b[i];
  }
  return true;
}

// The bytes array `tag`'s appended block needs from its offset on (header
// included); -1 if its header lies outside the file.
double AppendedBlockBytes(vtksys::ifstream& in, double start, int header, bool compressed)
{
  double count = 0.0;
  if (!ReadUnsigned(in, start, header, count))
  {
    return -1.0;
  }
  if (!compressed)
  {
    return header + count; // one number: the array's bytes
  }
  // Compressed: block count, block size, last block size, compressed sizes.
  if (count > 1.0e7)
  {
    return 1.0e300;
  }
  double total = header * (3.0 + count);
  for (int b = 0; b < static_cast<int>(count); ++b)
  {
    double size = 0.0;
    if (!ReadUnsigned(in, start + header * (3.0 + b), header, size))
    {
      return -1.0;
    }
    total += size;
  }
  return total;
}
}

namespace tyndall_io
{
//------------------------------------------------------------------------------
std::string CheckNrrdHeader(const std::string& path)
{
  static const char* types[] = { "signed char", "int8", "int8_t", "uchar", "unsigned char", "uint8",
    "uint8_t", "short", "short int", "signed short", "signed short int", "int16", "int16_t",
    "ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t", "int", "signed int",
    "int32", "int32_t", "uint", "unsigned int", "uint32", "uint32_t", "longlong", "long long",
    "long long int", "signed long long", "signed long long int", "int64", "int64_t", "ulonglong",
    "unsigned long long", "unsigned long long int", "uint64", "uint64_t", "float", "double" };
  std::int64_t headerEnd = -1;
  for (const auto& f : NrrdFields(path, headerEnd))
  {
    const std::string& field = f.first;
    const std::string& value = f.second;
    if (field == "type" && std::find(std::begin(types), std::end(types), value) == std::end(types))
    {
      return "unknown NRRD type '" + value + "'";
    }
    if (field == "sizes")
    {
      std::istringstream sizes(value);
      for (std::string size; sizes >> size;)
      {
        char* end = nullptr;
        const long long n = std::strtoll(size.c_str(), &end, 10);
        if (*end != '\0' || n < 1)
        {
          return "impossible NRRD sizes '" + value + "' (each must be a positive integer)";
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string CheckXmlImageHeader(const std::string& path)
{
  vtksys::ifstream in(path.c_str(), std::ios::binary);
  std::string head(1 << 20, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  const size_t image = head.find("<ImageData");
  if (image == std::string::npos)
  {
    return std::string(); // the XML reader says what is wrong
  }
  const std::string imageTag = TagAt(head, image);
  double v[3];
  for (const char* name : { "Spacing", "Origin" })
  {
    const std::string text = Attribute(imageTag, name);
    if (text.empty())
    {
      continue;
    }
    const bool spacing = std::string(name) == "Spacing";
    if (!Three(text, v) || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
      (spacing && (v[0] == 0.0 || v[1] == 0.0 || v[2] == 0.0)))
    {
      return std::string("the ") + (spacing ? "spacing" : "origin") + " \"" + text + "\" is not " +
        (spacing ? "finite and non-zero along every axis" : "finite");
    }
  }
  // Raw appended data: every array's block must lie inside the file.
  const size_t appended = head.find("<AppendedData");
  if (appended == std::string::npos || Attribute(TagAt(head, appended), "encoding") != "raw")
  {
    return std::string();
  }
  const size_t underscore = head.find('_', head.find('>', appended));
  if (underscore == std::string::npos)
  {
    return "the appended data has no '_' marker";
  }
  const std::string fileTag = TagAt(head, head.find("<VTKFile"));
  const int header = Attribute(fileTag, "header_type") == "UInt64" ? 8 : 4;
  const bool compressed = !Attribute(fileTag, "compressor").empty();
  const double base = static_cast<double>(underscore) + 1.0;
  const double length = static_cast<double>(vtksys::SystemTools::FileLength(path));
  for (size_t at = head.find("<DataArray"); at < appended; at = head.find("<DataArray", at + 1))
  {
    const std::string tag = TagAt(head, at);
    if (Attribute(tag, "format") != "appended")
    {
      continue;
    }
    const double start = base + std::atof(Attribute(tag, "offset").c_str());
    const double needed = AppendedBlockBytes(in, start, header, compressed);
    if (needed < 0.0 || start + needed > length)
    {
      std::ostringstream os;
      os << "truncated: the appended data of array '" << Attribute(tag, "Name")
         << "' runs past the "
         << "end of the file (" << FormatBytes(length) << ")";
      return os.str();
    }
  }
  return std::string();
}
}
