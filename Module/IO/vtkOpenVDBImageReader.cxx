#include "vtkOpenVDBImageReader.h"

#include "vtkOpenVDBInternals.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <openvdb/tools/LevelSetUtil.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <limits>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkOpenVDBImageReader);

namespace
{
namespace fs = std::filesystem;

enum class GridKind
{
  Unsupported,
  Float,
  Double,
  Vec3S,
  Vec3D
};

GridKind KindOf(const openvdb::GridBase& grid)
{
  if (grid.isType<openvdb::FloatGrid>())
  {
    return GridKind::Float;
  }
  if (grid.isType<openvdb::DoubleGrid>())
  {
    return GridKind::Double;
  }
  if (grid.isType<openvdb::Vec3SGrid>())
  {
    return GridKind::Vec3S;
  }
  if (grid.isType<openvdb::Vec3DGrid>())
  {
    return GridKind::Vec3D;
  }
  return GridKind::Unsupported;
}

int ComponentsOf(GridKind kind)
{
  return (kind == GridKind::Vec3S || kind == GridKind::Vec3D) ? 3 : 1;
}

int VTKTypeOf(GridKind kind)
{
  return (kind == GridKind::Float || kind == GridKind::Vec3S) ? VTK_FLOAT : VTK_DOUBLE;
}

int BytesPerValue(GridKind kind)
{
  return ComponentsOf(kind) * (VTKTypeOf(kind) == VTK_FLOAT ? 4 : 8);
}

// Floor division (index boxes of the downsampling are aligned to multiples
// of the factor, negative indices included).
int64_t FloorDiv(int64_t a, int64_t b)
{
  const int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

struct GridInfo
{
  std::string Name;
  std::string ValueType;
  std::string TreeType;
  std::string Class;
  GridKind Kind = GridKind::Unsupported;
  bool LevelSet = false;
  bool HasBBox = false;
  openvdb::CoordBBox BBox; // may be empty
  int64_t VoxelCount = -1;
  int64_t MemBytes = -1;
  bool Linear = false;
  std::string MapType;
  openvdb::Mat4d Matrix = openvdb::Mat4d::identity();
};

struct FileStamp
{
  std::string Name;
  uintmax_t Size = 0;
  fs::file_time_type Time;
  bool operator==(const FileStamp& o) const
  {
    return this->Name == o.Name && this->Size == o.Size && this->Time == o.Time;
  }
};

constexpr int64_t kMaxCoord = std::numeric_limits<int32_t>::max();

// Per value type: number of components and component access.
template <class T>
struct ValueTraits
{
  static constexpr int N = 1;
  static double Get(const T& v, int) { return static_cast<double>(v); }
};
template <class T>
struct ValueTraits<openvdb::math::Vec3<T>>
{
  static constexpr int N = 3;
  static double Get(const openvdb::math::Vec3<T>& v, int c) { return static_cast<double>(v[c]); }
};

// Densifies rows [begin, end) of the output extent; row r is (j, k) =
// (Ext[2] + r % ny, Ext[4] + r / ny). OutT is the array's value type.
template <class GridT, class OutT>
struct Densifier
{
  using ValueT = typename GridT::ValueType;
  using Traits = ValueTraits<ValueT>;
  const GridT* Grid = nullptr;
  int Ext[6];
  int Factor = 1;
  double Background[3] = { 0.0, 0.0, 0.0 }; // finite (sanitised)
  bool BackgroundFinite = true;
  OutT* Out = nullptr;
  std::atomic<vtkIdType>* NonFinite = nullptr;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    constexpr int nc = Traits::N;
    const vtkIdType nx = this->Ext[1] - this->Ext[0] + 1;
    const vtkIdType ny = this->Ext[3] - this->Ext[2] + 1;
    const int f = this->Factor;
    const double invCount = 1.0 / (double(f) * f * f);
    auto acc = this->Grid->getConstUnsafeAccessor();
    vtkIdType bad = 0;
    ValueT v;
    double value[3];
    // One voxel's value (active value or background), non-finite -> 0.
    auto sample = [&](const openvdb::Coord& ijk)
    {
      if (acc.probeValue(ijk, v))
      {
        bool finite = true;
        for (int c = 0; c < nc; ++c)
        {
          value[c] = Traits::Get(v, c);
          if (!std::isfinite(value[c]))
          {
            value[c] = 0.0;
            finite = false;
          }
        }
        bad += finite ? 0 : 1;
      }
      else
      {
        for (int c = 0; c < nc; ++c)
        {
          value[c] = this->Background[c];
        }
        bad += this->BackgroundFinite ? 0 : 1;
      }
    };
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int j = this->Ext[2] + static_cast<int>(r % ny);
      const int k = this->Ext[4] + static_cast<int>(r / ny);
      OutT* row = this->Out + r * nx * nc;
      for (vtkIdType i = 0; i < nx; ++i)
      {
        const int ii = this->Ext[0] + static_cast<int>(i);
        if (f == 1)
        {
          sample(openvdb::Coord(ii, j, k));
          for (int c = 0; c < nc; ++c)
          {
            row[i * nc + c] = static_cast<OutT>(value[c]);
          }
          continue;
        }
        double sum[3] = { 0.0, 0.0, 0.0 };
        for (int dz = 0; dz < f; ++dz)
        {
          for (int dy = 0; dy < f; ++dy)
          {
            for (int dx = 0; dx < f; ++dx)
            {
              const int64_t x = int64_t(ii) * f + dx, y = int64_t(j) * f + dy,
                            z = int64_t(k) * f + dz;
              if (x > kMaxCoord || y > kMaxCoord || z > kMaxCoord)
              {
                // Beyond OpenVDB's index range: background.
                for (int c = 0; c < nc; ++c)
                {
                  value[c] = this->Background[c];
                }
                bad += this->BackgroundFinite ? 0 : 1;
              }
              else
              {
                sample(openvdb::Coord(int(x), int(y), int(z)));
              }
              for (int c = 0; c < nc; ++c)
              {
                sum[c] += value[c];
              }
            }
          }
        }
        for (int c = 0; c < nc; ++c)
        {
          row[i * nc + c] = static_cast<OutT>(sum[c] * invCount);
        }
      }
    }
    *this->NonFinite += bad;
  }

  // True when FillActive() gives what operator() gives (no downsampling, a
  // background of 0: the zeroed array already holds it) and costs less: the
  // grid holds fewer active values than the extent has voxels (a small
  // piece of a large grid is read voxel by voxel).
  bool CanFillActive() const
  {
    if (!(this->Factor == 1 && this->BackgroundFinite && this->Background[0] == 0.0 &&
          this->Background[1] == 0.0 && this->Background[2] == 0.0))
    {
      return false;
    }
    const double voxels = (double(this->Ext[1]) - this->Ext[0] + 1.0) *
      (double(this->Ext[3]) - this->Ext[2] + 1.0) * (double(this->Ext[5]) - this->Ext[4] + 1.0);
    return double(this->Grid->activeVoxelCount()) <= voxels;
  }

  // Writes the grid's active values (voxels and tiles) that lie in the
  // extent into an output already zeroed, and nothing else: the cost of the
  // active values, not of the box (an output from calloc keeps the pages no
  // active value touches unallocated). Non-finite values become 0, counted.
  // Every 2^20 values (and every 2^20 rows of tiles) `progress(fraction of
  // the active values visited)` is called; it returns true to abort, and
  // then FillActive() returns false.
  template <class Progress>
  bool FillActive(const Progress& progress) const
  {
    const double active = std::max(double(this->Grid->activeVoxelCount()), 1.0);
    constexpr int nc = Traits::N;
    const openvdb::CoordBBox extent(openvdb::Coord(this->Ext[0], this->Ext[2], this->Ext[4]),
      openvdb::Coord(this->Ext[1], this->Ext[3], this->Ext[5]));
    const int64_t nx = int64_t(this->Ext[1]) - this->Ext[0] + 1;
    const int64_t ny = int64_t(this->Ext[3]) - this->Ext[2] + 1;
    vtkIdType bad = 0;
    int64_t visited = 0, rows = 0;
    for (auto it = this->Grid->cbeginValueOn(); it; ++it)
    {
      if ((++visited & 0xFFFFF) == 0 && progress(double(visited) / active))
      {
        return false;
      }
      openvdb::CoordBBox box;
      it.getBoundingBox(box); // one voxel, or a tile's voxels
      box.intersect(extent);
      if (box.empty())
      {
        continue;
      }
      double value[3];
      bool finite = true;
      for (int c = 0; c < nc; ++c)
      {
        value[c] = Traits::Get(*it, c);
        finite = finite && std::isfinite(value[c]);
      }
      for (int c = 0; c < nc && !finite; ++c)
      {
        value[c] = std::isfinite(value[c]) ? value[c] : 0.0;
      }
      for (int64_t k = box.min().z(); k <= box.max().z(); ++k)
      {
        for (int64_t j = box.min().y(); j <= box.max().y(); ++j)
        {
          if ((++rows & 0xFFFFF) == 0 && progress(double(visited) / active))
          {
            return false; // (tiles of many rows)
          }
          OutT* row = this->Out + ((k - this->Ext[4]) * ny + (j - this->Ext[2])) * nx * nc;
          for (int64_t i = box.min().x(); i <= box.max().x(); ++i)
          {
            for (int c = 0; c < nc; ++c)
            {
              row[(i - this->Ext[0]) * nc + c] = static_cast<OutT>(value[c]);
            }
            bad += finite ? 0 : 1;
          }
        }
      }
    }
    *this->NonFinite += bad;
    return true;
  }
};

std::string ListGrids(const std::vector<GridInfo>& grids)
{
  std::ostringstream os;
  for (size_t i = 0; i < grids.size(); ++i)
  {
    os << (i ? ", " : "") << "'" << grids[i].Name << "' (" << grids[i].ValueType << ")";
  }
  return os.str();
}

// An exception's message made fit for an error message: printable
// characters only and at most 400 of them (corrupted files can make OpenVDB
// put huge garbage strings into its messages).
std::string Shorten(const char* what)
{
  std::string out;
  for (const char* p = what ? what : ""; *p && out.size() < 400; ++p)
  {
    const unsigned char c = static_cast<unsigned char>(*p);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if (what && std::strlen(what) > out.size())
  {
    out += "...";
  }
  return out.empty() ? std::string("an exception without a message") : out;
}

// Runs f; returns "" or what went wrong. No exception escapes.
template <class F>
std::string RunGuarded(F&& f)
{
  try
  {
    f();
    return std::string();
  }
  catch (const std::ios_base::failure&)
  {
    return "the file ends early or cannot be read (truncated?)";
  }
  catch (const openvdb::Exception& e)
  {
    return Shorten(e.what());
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory (corrupted sizes in the file?)";
  }
  catch (const std::exception& e)
  {
    return Shorten(e.what());
  }
  catch (...)
  {
    return "an unknown exception";
  }
}

std::string BoxString(const openvdb::CoordBBox& box)
{
  std::ostringstream os;
  os << box;
  return os.str();
}

std::string ArrayName(const GridInfo& info, int index)
{
  return info.Name.empty() ? "grid" + std::to_string(index) : info.Name;
}
}

//------------------------------------------------------------------------------
struct vtkOpenVDBImageReader::Internals
{
  std::vector<std::string> Requested;
  std::vector<GridInfo> Grids;
  std::vector<int> Selected;
  bool Valid = false;
  openvdb::CoordBBox IndexBBox; // union of the selected grids' boxes (full resolution)
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };

  // Grids read from the file, kept for streaming.
  FileStamp CacheStamp;
  bool CacheConverted = false;
  std::map<std::string, openvdb::GridBase::Ptr> Cache;

  // Reads one grid (or takes it from the cache); throws on failure.
  openvdb::GridBase::Ptr Load(
    const char* fileName, const GridInfo& info, bool convert, std::string& warning)
  {
    auto it = this->Cache.find(info.Name);
    if (it != this->Cache.end())
    {
      return it->second;
    }
    tyndall_io::SafeFile file(fileName);
    openvdb::GridBase::Ptr grid = file.ReadGrid(info.Name);
    if (!grid || KindOf(*grid) != info.Kind)
    {
      throw std::runtime_error("grid '" + info.Name + "' changed type between reads");
    }
    if (info.LevelSet && convert)
    {
      if (info.Kind == GridKind::Float)
      {
        openvdb::tools::sdfToFogVolume(*openvdb::gridPtrCast<openvdb::FloatGrid>(grid));
      }
      else if (info.Kind == GridKind::Double)
      {
        openvdb::tools::sdfToFogVolume(*openvdb::gridPtrCast<openvdb::DoubleGrid>(grid));
      }
    }
    const openvdb::CoordBBox actual = grid->evalActiveVoxelBoundingBox();
    if (info.HasBBox && !actual.empty() && !info.BBox.isInside(actual))
    {
      std::ostringstream os;
      os << "Grid '" << info.Name << "' has active voxels in " << actual
         << ", outside the bounding box its file metadata records (" << info.BBox
         << "); the output covers only the recorded box.";
      warning = os.str();
    }
    this->Cache[info.Name] = grid;
    return grid;
  }
};

//------------------------------------------------------------------------------
vtkOpenVDBImageReader::vtkOpenVDBImageReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOpenVDBImageReader::~vtkOpenVDBImageReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::CanReadFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return 0;
  }
  std::ifstream in(fileName, std::ios::binary);
  unsigned char bytes[8];
  if (!in.read(reinterpret_cast<char*>(bytes), 8))
  {
    return 0;
  }
  // OPENVDB_MAGIC (0x56444220) as a little-endian int32 in the first 4 of
  // the 8 bytes OpenVDB writes for it.
  const uint32_t magic = uint32_t(bytes[0]) | (uint32_t(bytes[1]) << 8) |
    (uint32_t(bytes[2]) << 16) | (uint32_t(bytes[3]) << 24);
  return magic == 0x56444220u ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageReader::SetGridName(const char* name)
{
  std::vector<std::string> requested;
  if (name && *name)
  {
    requested.emplace_back(name);
  }
  if (requested != this->Internal->Requested)
  {
    this->Internal->Requested = requested;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageReader::AddGridName(const char* name)
{
  if (!name || !*name)
  {
    vtkErrorMacro(<< "AddGridName: the name cannot be empty.");
    return;
  }
  this->Internal->Requested.emplace_back(name);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageReader::RemoveAllGridNames()
{
  if (!this->Internal->Requested.empty())
  {
    this->Internal->Requested.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::GetNumberOfRequestedGridNames()
{
  return static_cast<int>(this->Internal->Requested.size());
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetRequestedGridName(int i)
{
  if (i < 0 || i >= this->GetNumberOfRequestedGridNames())
  {
    return nullptr;
  }
  return this->Internal->Requested[i].c_str();
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::GetNumberOfGrids()
{
  return static_cast<int>(this->Internal->Grids.size());
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetGridName(int i)
{
  return (i >= 0 && i < this->GetNumberOfGrids()) ? this->Internal->Grids[i].Name.c_str() : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetGridValueType(int i)
{
  return (i >= 0 && i < this->GetNumberOfGrids()) ? this->Internal->Grids[i].ValueType.c_str()
                                                  : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetGridType(int i)
{
  return (i >= 0 && i < this->GetNumberOfGrids()) ? this->Internal->Grids[i].TreeType.c_str()
                                                  : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetGridClass(int i)
{
  return (i >= 0 && i < this->GetNumberOfGrids()) ? this->Internal->Grids[i].Class.c_str()
                                                  : nullptr;
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::IsGridSupported(int i)
{
  return i >= 0 && i < this->GetNumberOfGrids() &&
    this->Internal->Grids[i].Kind != GridKind::Unsupported;
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::GetGridIndexBoundingBox(int i, int bbox[6])
{
  if (i < 0 || i >= this->GetNumberOfGrids())
  {
    return false;
  }
  const GridInfo& info = this->Internal->Grids[i];
  if (!info.HasBBox || info.BBox.empty())
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    bbox[2 * c] = info.BBox.min()[c];
    bbox[2 * c + 1] = info.BBox.max()[c];
  }
  return true;
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkOpenVDBImageReader::GetGridActiveVoxelCount(int i)
{
  return (i >= 0 && i < this->GetNumberOfGrids()) ? this->Internal->Grids[i].VoxelCount : -1;
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::GetGridIndex(const char* name)
{
  if (!name)
  {
    return -1;
  }
  for (size_t i = 0; i < this->Internal->Grids.size(); ++i)
  {
    if (this->Internal->Grids[i].Name == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::GetNumberOfSelectedGrids()
{
  return static_cast<int>(this->Internal->Selected.size());
}

//------------------------------------------------------------------------------
const char* vtkOpenVDBImageReader::GetSelectedGridName(int i)
{
  if (i < 0 || i >= this->GetNumberOfSelectedGrids())
  {
    return nullptr;
  }
  return this->Internal->Grids[this->Internal->Selected[i]].Name.c_str();
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageReader::ReleaseGrids()
{
  this->Internal->Cache.clear();
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::ReadFileInformation()
{
  Internals& in = *this->Internal;
  in.Grids.clear();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No FileName was set.");
    return false;
  }
  const fs::path path(this->FileName);
  std::error_code ec;
  if (!fs::exists(path, ec))
  {
    vtkErrorMacro(<< "The file '" << this->FileName << "' does not exist.");
    return false;
  }
  if (!fs::is_regular_file(path, ec))
  {
    vtkErrorMacro(<< "'" << this->FileName << "' is not a regular file.");
    return false;
  }
  FileStamp stamp;
  stamp.Name = this->FileName;
  stamp.Size = fs::file_size(path, ec);
  if (ec)
  {
    vtkErrorMacro(<< "Cannot determine the size of '" << this->FileName << "': " << ec.message());
    return false;
  }
  stamp.Time = fs::last_write_time(path, ec);
  if (stamp.Size == 0)
  {
    vtkErrorMacro(<< "The file '" << this->FileName
                  << "' is empty (0 bytes); it is not an OpenVDB file.");
    return false;
  }
  if (!vtkOpenVDBImageReader::CanReadFile(this->FileName))
  {
    vtkErrorMacro(<< "The file '" << this->FileName
                  << "' is not an OpenVDB file (it does not start with OpenVDB's magic number).");
    return false;
  }
  if (!(stamp == in.CacheStamp) || in.CacheConverted != this->ConvertLevelSetToFog)
  {
    in.Cache.clear();
    in.CacheStamp = stamp;
    in.CacheConverted = this->ConvertLevelSetToFog;
  }

  std::string failure;
  failure = RunGuarded(
    [&]()
    {
      tyndall_io::SafeFile file(this->FileName);
      for (int i = 0; i < file.GetNumberOfGrids(); ++i)
      {
        const openvdb::GridBase::Ptr grid = file.ReadGridMetadata(i);
        if (!grid)
        {
          continue;
        }
        GridInfo info;
        info.Name = grid->getName();
        info.ValueType = grid->valueType();
        info.TreeType = grid->type();
        info.Class = openvdb::GridBase::gridClassToString(grid->getGridClass());
        info.LevelSet = grid->getGridClass() == openvdb::GRID_LEVEL_SET;
        info.Kind = KindOf(*grid);
        auto bmin =
          grid->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
        auto bmax =
          grid->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
        if (bmin && bmax)
        {
          info.HasBBox = true;
          info.BBox =
            openvdb::CoordBBox(openvdb::Coord(bmin->value()), openvdb::Coord(bmax->value()));
        }
        auto count =
          grid->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
        info.VoxelCount = count ? count->value() : -1;
        auto bytes =
          grid->getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_MEM_BYTES);
        info.MemBytes = bytes ? bytes->value() : -1;
        const openvdb::math::Transform& transform = grid->constTransform();
        info.Linear = transform.isLinear();
        info.MapType = transform.mapType();
        if (info.Linear)
        {
          info.Matrix = tyndall_io::AffineMatrix(transform);
        }
        in.Grids.push_back(info);
      }
    });
  if (!failure.empty())
  {
    in.Grids.clear();
    vtkErrorMacro(<< "Cannot read the OpenVDB file '" << this->FileName
                  << "' (truncated, corrupted or not an OpenVDB file?): " << failure);
    return false;
  }
  if (in.Grids.empty())
  {
    vtkErrorMacro(<< "The OpenVDB file '" << this->FileName << "' contains no grids.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::SelectGrids()
{
  Internals& in = *this->Internal;
  in.Selected.clear();
  const int n = static_cast<int>(in.Grids.size());
  if (in.Requested.empty())
  {
    int pick = -1;
    for (int i = 0; i < n && pick < 0; ++i)
    {
      if (in.Grids[i].Kind == GridKind::Float && in.Grids[i].Name == "density")
      {
        pick = i;
      }
    }
    for (int i = 0; i < n && pick < 0; ++i)
    {
      if (in.Grids[i].Kind == GridKind::Float)
      {
        pick = i;
      }
    }
    for (int i = 0; i < n && pick < 0; ++i)
    {
      if (in.Grids[i].Kind != GridKind::Unsupported)
      {
        pick = i;
      }
    }
    if (pick < 0)
    {
      vtkErrorMacro(<< "The OpenVDB file '" << this->FileName
                    << "' has no grid of a supported type (float, double, vec3s, vec3d); its "
                    << "grids: " << ListGrids(in.Grids) << ".");
      return false;
    }
    in.Selected.push_back(pick);
  }
  else
  {
    for (const std::string& name : in.Requested)
    {
      const int index = this->GetGridIndex(name.c_str());
      if (index < 0)
      {
        vtkErrorMacro(<< "The OpenVDB file '" << this->FileName << "' has no grid named '" << name
                      << "'; its grids: " << ListGrids(in.Grids) << ".");
        in.Selected.clear();
        return false;
      }
      if (std::find(in.Selected.begin(), in.Selected.end(), index) == in.Selected.end())
      {
        in.Selected.push_back(index);
      }
    }
  }
  for (int index : in.Selected)
  {
    const GridInfo& info = in.Grids[index];
    if (info.Kind == GridKind::Unsupported)
    {
      vtkErrorMacro(<< "Grid '" << info.Name << "' has the unsupported grid type " << info.TreeType
                    << " (value type '" << info.ValueType
                    << "'); the reader reads float, double, vec3s and vec3d grids.");
      in.Selected.clear();
      return false;
    }
    if (info.LevelSet && !this->ConvertLevelSetToFog)
    {
      vtkErrorMacro(<< "Grid '" << info.Name
                    << "' is a level set (a signed distance field, not a density); turn "
                       "ConvertLevelSetToFog on (tyndall-render --level-set-to-fog) to read it "
                       "as a fog volume: 0 outside, 1 inside, a ramp across the narrow band.");
      in.Selected.clear();
      return false;
    }
    if (info.LevelSet && ComponentsOf(info.Kind) != 1)
    {
      vtkErrorMacro(<< "Grid '" << info.Name
                    << "' is a vector-valued level set, which cannot be converted to fog.");
      in.Selected.clear();
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::ComputeGeometry()
{
  Internals& in = *this->Internal;
  const GridInfo& first = in.Grids[in.Selected[0]];
  for (int index : in.Selected)
  {
    const GridInfo& info = in.Grids[index];
    if (!info.Linear)
    {
      vtkErrorMacro(<< "Grid '" << info.Name << "' has a non-linear transform (" << info.MapType
                    << "); vtkImageData can only represent linear (affine) transforms.");
      return false;
    }
  }

  // Axes (rows 0-2) and translation (row 3) of the affine matrix.
  const openvdb::Mat4d& m = first.Matrix;
  double maxAbs = 0.0;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      if (!std::isfinite(m(r, c)))
      {
        vtkErrorMacro(<< "Grid '" << first.Name << "' has a transform with non-finite entries.");
        return false;
      }
      maxAbs = std::max(maxAbs, std::abs(m(r, c)));
    }
  }
  if (m(0, 3) != 0.0 || m(1, 3) != 0.0 || m(2, 3) != 0.0 || m(3, 3) != 1.0)
  {
    vtkErrorMacro(<< "Grid '" << first.Name << "' has a projective transform.");
    return false;
  }
  double axis[3][3], size[3];
  for (int a = 0; a < 3; ++a)
  {
    size[a] = std::sqrt(m(a, 0) * m(a, 0) + m(a, 1) * m(a, 1) + m(a, 2) * m(a, 2));
    if (!(size[a] > 0.0) || !std::isfinite(size[a]))
    {
      vtkErrorMacro(<< "Grid '" << first.Name << "' has a degenerate transform (index axis " << a
                    << " has length " << size[a] << ").");
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      axis[a][c] = m(a, c) / size[a];
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a + 1; b < 3; ++b)
    {
      const double dot =
        axis[a][0] * axis[b][0] + axis[a][1] * axis[b][1] + axis[a][2] * axis[b][2];
      if (std::abs(dot) > 1.0e-6)
      {
        vtkErrorMacro(<< "Grid '" << first.Name << "' has a sheared transform (index axes " << a
                      << " and " << b
                      << " are not perpendicular); vtkImageData cannot represent it.");
        return false;
      }
    }
  }
  for (int index : in.Selected)
  {
    const GridInfo& info = in.Grids[index];
    double diff = 0.0;
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        diff = std::max(diff, std::abs(info.Matrix(r, c) - m(r, c)));
      }
    }
    if (diff > 1.0e-9 * std::max(1.0, maxAbs))
    {
      vtkErrorMacro(<< "Grids '" << first.Name << "' and '" << info.Name
                    << "' have different transforms; read them into separate images.");
      return false;
    }
  }

  // The index bounding box: union of the selected grids' boxes.
  in.IndexBBox = openvdb::CoordBBox();
  for (int index : in.Selected)
  {
    GridInfo& info = in.Grids[index];
    if (!info.HasBBox)
    {
      // No metadata: read the grid now (it stays in memory for RequestData).
      std::string failure, warning;
      failure = RunGuarded(
        [&]()
        {
          openvdb::GridBase::Ptr grid =
            in.Load(this->FileName, info, this->ConvertLevelSetToFog, warning);
          info.BBox = grid->evalActiveVoxelBoundingBox();
          info.HasBBox = true;
        });
      if (!failure.empty())
      {
        vtkErrorMacro(<< "Cannot read grid '" << info.Name << "' of '" << this->FileName
                      << "' (truncated or corrupted?): " << failure);
        return false;
      }
    }
    if (!info.BBox.empty())
    {
      in.IndexBBox.expand(info.BBox);
    }
  }
  if (in.IndexBBox.empty())
  {
    vtkErrorMacro(<< "The selected grid(s) of '" << this->FileName
                  << "' have no active voxels; there is nothing to read.");
    return false;
  }
  const int64_t maxDim = std::numeric_limits<int>::max();
  for (int c = 0; c < 3; ++c)
  {
    const int64_t dim = int64_t(in.IndexBBox.max()[c]) - int64_t(in.IndexBBox.min()[c]) + 1;
    if (dim > maxDim)
    {
      vtkErrorMacro(<< "The selected grid(s) of '" << this->FileName << "' have absurd dimensions: "
                    << dim << " voxels along axis " << c << " (index box "
                    << BoxString(in.IndexBBox) << "); at most " << maxDim << " are supported.");
      return false;
    }
  }

  // Extent, origin, spacing and direction (see the class documentation).
  const int f = this->DownsamplingFactor;
  const double centre = 0.5 * (f - 1);
  for (int c = 0; c < 3; ++c)
  {
    in.WholeExtent[2 * c] = static_cast<int>(FloorDiv(in.IndexBBox.min()[c], f));
    in.WholeExtent[2 * c + 1] = static_cast<int>(FloorDiv(in.IndexBBox.max()[c], f));
    in.Spacing[c] = f * size[c];
    in.Origin[c] = m(3, c) + centre * (m(0, c) + m(1, c) + m(2, c));
    for (int a = 0; a < 3; ++a)
    {
      in.Direction[3 * c + a] = axis[a][c]; // column a is index axis a
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  in.Valid = this->ReadFileInformation() && this->SelectGrids() && this->ComputeGeometry();
  if (!in.Valid)
  {
    in.Selected.clear();
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  static const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  static const double unitSpacing[3] = { 1.0, 1.0, 1.0 };
  static const double zeroOrigin[3] = { 0.0, 0.0, 0.0 };
  static const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), in.Valid ? in.WholeExtent : emptyExtent, 6);
  outInfo->Set(vtkDataObject::SPACING(), in.Valid ? in.Spacing : unitSpacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), in.Valid ? in.Origin : zeroOrigin, 3);
  outInfo->Set(vtkDataObject::DIRECTION(), in.Valid ? in.Direction : identity, 9);
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  if (in.Valid)
  {
    const GridInfo& first = in.Grids[in.Selected[0]];
    vtkDataObject::SetPointDataActiveScalarInfo(
      outInfo, VTKTypeOf(first.Kind), ComponentsOf(first.Kind));
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOpenVDBImageReader::LoadGrids()
{
  Internals& in = *this->Internal;
  // Keep only the selected grids in memory.
  std::map<std::string, openvdb::GridBase::Ptr> kept;
  for (int index : in.Selected)
  {
    auto it = in.Cache.find(in.Grids[index].Name);
    if (it != in.Cache.end())
    {
      kept.insert(*it);
    }
  }
  in.Cache.swap(kept);
  for (int index : in.Selected)
  {
    const GridInfo& info = in.Grids[index];
    std::string failure, warning;
    failure =
      RunGuarded([&]() { in.Load(this->FileName, info, this->ConvertLevelSetToFog, warning); });
    if (!failure.empty())
    {
      in.Cache.erase(info.Name);
      vtkErrorMacro(<< "Cannot read grid '" << info.Name << "' of '" << this->FileName
                    << "' (truncated or corrupted?): " << failure);
      return false;
    }
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  this->NumberOfNonFiniteValues = 0;
  this->FilledActiveOnly = false; // (until every grid is read so)
  this->LastMemoryEstimate = 0.0;
  if (!in.Valid)
  {
    return 1; // RequestInformation reported the problem
  }

  int ext[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), ext);
  for (int c = 0; c < 3; ++c)
  {
    ext[2 * c] = std::max(ext[2 * c], in.WholeExtent[2 * c]);
    ext[2 * c + 1] = std::min(ext[2 * c + 1], in.WholeExtent[2 * c + 1]);
  }
  if (ext[0] > ext[1] || ext[2] > ext[3] || ext[4] > ext[5])
  {
    return 1; // an empty request gets an empty image
  }
  const int64_t nx = int64_t(ext[1]) - ext[0] + 1;
  const int64_t ny = int64_t(ext[3]) - ext[2] + 1;
  const int64_t nz = int64_t(ext[5]) - ext[4] + 1;
  const double voxels = double(nx) * double(ny) * double(nz);

  // Memory estimate: dense arrays plus grids still to be read.
  double denseBytes = 0.0, gridBytes = 0.0;
  bool gridSizeUnknown = false;
  for (int index : in.Selected)
  {
    const GridInfo& info = in.Grids[index];
    denseBytes += voxels * BytesPerValue(info.Kind);
    if (in.Cache.find(info.Name) == in.Cache.end())
    {
      if (info.MemBytes >= 0)
      {
        gridBytes += double(info.MemBytes);
      }
      else
      {
        gridSizeUnknown = true;
      }
    }
  }
  const double mib = 1024.0 * 1024.0;
  this->LastMemoryEstimate = denseBytes + gridBytes;
  if (this->LastMemoryEstimate > this->MemoryLimit * mib ||
    voxels > double(std::numeric_limits<vtkIdType>::max() / 8))
  {
    vtkErrorMacro(<< "Reading " << nx << " x " << ny << " x " << nz << " voxels of '"
                  << this->FileName << "' needs about " << this->LastMemoryEstimate / mib
                  << " MiB (dense arrays " << denseBytes / mib << " MiB, grids to read "
                  << gridBytes / mib << " MiB" << (gridSizeUnknown ? " or more" : "")
                  << "), above the MemoryLimit of " << this->MemoryLimit
                  << " MiB. Raise MemoryLimit, request a smaller update extent (stream the "
                     "volume in pieces) or set a DownsamplingFactor.");
    return 1;
  }
  if (!this->LoadGrids())
  {
    return 1;
  }

  // Allocate the arrays, zeroed (calloc: the pages that no active value
  // touches are never allocated when the background is 0).
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(nx * ny * nz);
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  for (size_t g = 0; g < in.Selected.size(); ++g)
  {
    const GridInfo& info = in.Grids[in.Selected[g]];
    vtkSmartPointer<vtkDataArray> array;
    array.TakeReference(vtkDataArray::CreateDataArray(VTKTypeOf(info.Kind)));
    array->SetNumberOfComponents(ComponentsOf(info.Kind));
    array->SetName(ArrayName(info, in.Selected[g]).c_str());
    const vtkIdType values = numberOfPoints * ComponentsOf(info.Kind);
    void* zeroed = std::calloc(static_cast<size_t>(values),
      static_cast<size_t>(BytesPerValue(info.Kind) / ComponentsOf(info.Kind)));
    if (!zeroed)
    {
      vtkErrorMacro(<< "Cannot allocate " << nx << " x " << ny << " x " << nz
                    << " values for grid '" << info.Name
                    << "'; request a smaller extent or set a DownsamplingFactor.");
      return 1;
    }
    array->SetVoidArray(zeroed, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_FREE);
    arrays.push_back(array);
  }

  // Densify, grid by grid, in batches of rows (progress and abort checks).
  std::atomic<vtkIdType> nonFinite(0);
  const vtkIdType rows = static_cast<vtkIdType>(ny * nz);
  const vtkIdType batches = std::min<vtkIdType>(rows, 20);
  const double totalSteps = double(batches) * double(in.Selected.size());
  double step = 0.0;
  this->UpdateProgress(0.0);
  auto run = [&](auto& densifier)
  {
    std::copy(ext, ext + 6, densifier.Ext);
    densifier.Factor = this->DownsamplingFactor;
    densifier.NonFinite = &nonFinite;
    if (densifier.CanFillActive())
    {
      // A background of 0: the active values alone (the same array).
      const double first = step;
      if (densifier.FillActive(
            [&](double done)
            {
              this->UpdateProgress((first + done * double(batches)) / totalSteps);
              return this->AbortExecute != 0;
            }))
      {
        step += double(batches);
        this->UpdateProgress(step / totalSteps);
      }
      return;
    }
    this->FilledActiveOnly = false;
    for (vtkIdType b = 0; b < batches && !this->AbortExecute; ++b)
    {
      const vtkIdType begin = rows * b / batches;
      const vtkIdType end = rows * (b + 1) / batches;
      vtkSMPTools::For(begin, end, std::max<vtkIdType>(1, (end - begin) / 64), densifier);
      step += 1.0;
      this->UpdateProgress(step / totalSteps);
    }
  };
  auto setBackground = [](auto& densifier, const auto& background, int components)
  {
    using Traits = ValueTraits<std::decay_t<decltype(background)>>;
    for (int c = 0; c < components; ++c)
    {
      const double v = Traits::Get(background, c);
      densifier.Background[c] = std::isfinite(v) ? v : 0.0;
      densifier.BackgroundFinite = densifier.BackgroundFinite && std::isfinite(v);
    }
  };
  this->FilledActiveOnly = !in.Selected.empty();
  for (size_t g = 0; g < in.Selected.size() && !this->AbortExecute; ++g)
  {
    const GridInfo& info = in.Grids[in.Selected[g]];
    const openvdb::GridBase::Ptr& base = in.Cache[info.Name];
    switch (info.Kind)
    {
      case GridKind::Float:
      {
        Densifier<openvdb::FloatGrid, float> d;
        d.Grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(base).get();
        d.Out = static_cast<float*>(arrays[g]->GetVoidPointer(0));
        setBackground(d, d.Grid->background(), 1);
        run(d);
        break;
      }
      case GridKind::Double:
      {
        Densifier<openvdb::DoubleGrid, double> d;
        d.Grid = openvdb::gridConstPtrCast<openvdb::DoubleGrid>(base).get();
        d.Out = static_cast<double*>(arrays[g]->GetVoidPointer(0));
        setBackground(d, d.Grid->background(), 1);
        run(d);
        break;
      }
      case GridKind::Vec3S:
      {
        Densifier<openvdb::Vec3SGrid, float> d;
        d.Grid = openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(base).get();
        d.Out = static_cast<float*>(arrays[g]->GetVoidPointer(0));
        setBackground(d, d.Grid->background(), 3);
        run(d);
        break;
      }
      case GridKind::Vec3D:
      {
        Densifier<openvdb::Vec3DGrid, double> d;
        d.Grid = openvdb::gridConstPtrCast<openvdb::Vec3DGrid>(base).get();
        d.Out = static_cast<double*>(arrays[g]->GetVoidPointer(0));
        setBackground(d, d.Grid->background(), 3);
        run(d);
        break;
      }
      default:
        break;
    }
  }
  if (this->AbortExecute)
  {
    this->FilledActiveOnly = false;
    output->Initialize();
    return 1;
  }

  output->SetExtent(ext);
  output->SetOrigin(in.Origin);
  output->SetSpacing(in.Spacing);
  output->SetDirectionMatrix(in.Direction);
  for (size_t g = 0; g < arrays.size(); ++g)
  {
    output->GetPointData()->AddArray(arrays[g]);
  }
  output->GetPointData()->SetActiveScalars(arrays[0]->GetName());
  this->NumberOfNonFiniteValues = nonFinite.load();
  if (this->NumberOfNonFiniteValues > 0)
  {
    vtkWarningMacro(<< "Replaced " << this->NumberOfNonFiniteValues
                    << " NaN or infinite voxel value(s) by 0 while reading '" << this->FileName
                    << "'.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "RequestedGridNames:";
  for (const std::string& name : this->Internal->Requested)
  {
    os << " '" << name << "'";
  }
  os << (this->Internal->Requested.empty() ? " (automatic)\n" : "\n");
  os << indent << "NumberOfGrids: " << this->GetNumberOfGrids() << "\n";
  for (const GridInfo& info : this->Internal->Grids)
  {
    os << indent.GetNextIndent() << "'" << info.Name << "': " << info.TreeType << ", " << info.Class
       << ", index box " << info.BBox << "\n";
  }
  os << indent << "ConvertLevelSetToFog: " << (this->ConvertLevelSetToFog ? "On" : "Off") << "\n";
  os << indent << "DownsamplingFactor: " << this->DownsamplingFactor << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB\n";
  os << indent << "NumberOfNonFiniteValues: " << this->NumberOfNonFiniteValues << "\n";
  os << indent << "FilledActiveOnly: " << this->FilledActiveOnly << "\n";
  os << indent << "LastMemoryEstimate: " << this->LastMemoryEstimate << " bytes\n";
}
