// Helpers of the OpenVDB reader and writer tests. Header only; not part of
// the library. The tests link OpenVDB themselves so that they can compute
// expected values with OpenVDB's own API, independently of the reader.
#ifndef TyndallTestOpenVDB_h
#define TyndallTestOpenVDB_h

#include "vtkImageData.h"
#include "vtkOpenVDBInternals.h" // tyndall_io::NewGrid: the tests make their grids with it
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"

#include "TyndallTestCheck.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace tyndall_vdb_test
{
using tyndall_test::Check;
using tyndall_test::Failures;

// The test's scratch directory: <-T dir>/<name>, created empty.
inline std::string ScratchDir(int argc, char* argv[], const std::string& name)
{
  std::string base = ".";
  for (int i = 0; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-T")
    {
      base = argv[i + 1];
    }
  }
  const std::filesystem::path dir = std::filesystem::path(base) / name;
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir, ec);
  return dir.string();
}

// A sample of ../shared/data/vdb, or "" when absent.
inline std::string SharedVDB(const std::string& name)
{
#ifdef TYNDALL_SHARED_DATA
  const std::string path = std::string(TYNDALL_SHARED_DATA) + "/vdb/" + name;
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec))
  {
    return path;
  }
#endif
  return "";
}

inline void WriteGrids(const std::string& path, const openvdb::GridPtrVec& grids)
{
  openvdb::io::File file(path);
  file.write(grids);
  file.close();
}

inline openvdb::GridBase::Ptr ReadGrid(const std::string& path, const std::string& name)
{
  openvdb::io::File file(path);
  file.open(false);
  openvdb::GridBase::Ptr grid = file.readGrid(name);
  file.close();
  return grid;
}

// Statistics of the dense block a reader should produce from a scalar grid:
// the active voxels (tiles counted voxel by voxel, through OpenVDB's value
// iterators) plus the background in every inactive voxel of the active
// bounding box.
struct DenseStats
{
  openvdb::CoordBBox BBox;
  double Sum = 0.0;
  double Min = std::numeric_limits<double>::infinity();
  double Max = -std::numeric_limits<double>::infinity();
  openvdb::Index64 Active = 0;
};

template <class GridT>
DenseStats ComputeDenseStats(const GridT& grid)
{
  DenseStats s;
  s.BBox = grid.evalActiveVoxelBoundingBox();
  for (auto it = grid.cbeginValueOn(); it; ++it)
  {
    const double v = static_cast<double>(*it);
    const openvdb::Index64 n = it.getVoxelCount();
    s.Sum += v * double(n);
    s.Active += n;
    s.Min = std::min(s.Min, v);
    s.Max = std::max(s.Max, v);
  }
  const openvdb::Index64 inactive = s.BBox.volume() - s.Active;
  if (inactive > 0)
  {
    const double b = static_cast<double>(grid.background());
    s.Sum += b * double(inactive);
    s.Min = std::min(s.Min, b);
    s.Max = std::max(s.Max, b);
  }
  return s;
}

// Sum, minimum and maximum of one component of an array.
inline void ArrayStats(vtkDataArray* a, int comp, double& sum, double& mn, double& mx)
{
  sum = 0.0;
  mn = std::numeric_limits<double>::infinity();
  mx = -mn;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const double v = a->GetComponent(i, comp);
    sum += v;
    mn = std::min(mn, v);
    mx = std::max(mx, v);
  }
}

inline bool Near(double a, double b, double relTol)
{
  return std::abs(a - b) <= relTol * std::max({ 1.0, std::abs(a), std::abs(b) });
}

// Expects an error containing `text` (and clears the observer).
inline void ExpectError(
  vtkTest::ErrorObserver* observer, const std::string& text, const std::string& what)
{
  const bool ok =
    observer->GetError() && observer->GetErrorMessage().find(text) != std::string::npos;
  if (!ok)
  {
    std::cerr << "expected an error containing '" << text << "', got '"
              << (observer->GetError() ? observer->GetErrorMessage() : std::string("none")) << "'"
              << std::endl;
  }
  Check(ok, what);
  observer->Clear();
}

inline bool IsEmpty(vtkImageData* image)
{
  return image->GetNumberOfPoints() == 0 && image->GetPointData()->GetNumberOfArrays() == 0;
}

inline void CopyFile(const std::string& from, const std::string& to, size_t length)
{
  std::ifstream in(from, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes.resize(std::min(length, bytes.size()));
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::vector<char> ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline void WriteBytes(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}
}

#endif
