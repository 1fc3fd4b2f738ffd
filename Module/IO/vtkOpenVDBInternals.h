// Private helpers of Tyndall::IO shared by the OpenVDB reader and writer.
// Not installed and not wrapped: it is the only header of the module that
// includes OpenVDB. The OpenVDB test drivers, the CLI check and the fuzz
// target include it for NewGrid() alone.
#ifndef vtkOpenVDBInternals_h
#define vtkOpenVDBInternals_h

#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace tyndall_io
{
// Calls openvdb::initialize() exactly once per process (thread-safe).
void InitializeOpenVDB();

// The 4x4 affine matrix of a linear OpenVDB transform (OpenVDB's row-vector
// convention: world = [i j k 1] * M, so rows 0-2 are the index axes scaled by
// the voxel size and row 3 is the translation).
openvdb::Mat4d AffineMatrix(const openvdb::math::Transform& transform);

// Reads a .vdb file as openvdb::io::File does without delayed loading, but
// defensively:
// - through a std::ifstream that throws at the first short read, so a
//   truncated file fails at once instead of leaving zeros in the grids (which
//   openvdb::io::File does for uncompressed data) or looping over garbage
//   counts;
// - with every grid's byte range [grid, end) checked against the file's size
//   before anything is read from it, and the read position checked against
//   the grid's end after reading it;
// - with every variable-length field before the trees (strings, metadata
//   values) checked against the end of its block before OpenVDB reads it,
//   since OpenVDB allocates a buffer of whatever length it reads;
// - with the whole tree of a grid (node masks, value blocks, compressed
//   chunk sizes) walked and checked before OpenVDB reads its voxels, because
//   OpenVDB 10 copies an "uncompressed" chunk of whatever length the file
//   states into a buffer of the expected length before comparing the two;
// - refusing file format versions before 222 (OpenVDB 3.0, 2014);
// - keeping the grids in file order (io::File sorts them by name).
// Every failure is an exception (openvdb::Exception or std::exception).
class SafeFile : public openvdb::io::Archive
{
public:
  // Opens the file and reads its header, metadata and grid descriptors.
  explicit SafeFile(const std::string& fileName);
  ~SafeFile() override;

  int GetNumberOfGrids() const { return static_cast<int>(this->Descriptors.size()); }

  // Grid i with its metadata and transform but an empty tree.
  openvdb::GridBase::Ptr ReadGridMetadata(int i);

  // The first grid named `name`, fully read (instances get their parent's tree).
  openvdb::GridBase::Ptr ReadGrid(const std::string& name);

  uint64_t GetFileSize() const { return this->FileSize; }

private:
  openvdb::GridBase::Ptr CreateGrid(const openvdb::io::GridDescriptor& gd) const;
  openvdb::GridBase::Ptr ReadGrid(int i);
  void CheckEnd(const openvdb::io::GridDescriptor& gd);
  // Checks the lengths in the grid's metadata and transform, then leaves the
  // stream at the grid's start.
  void ScanGrid(const openvdb::io::GridDescriptor& gd);
  // Walks the tree of the grid that starts at the stream's position (which
  // it restores), checking every length against `limit` before OpenVDB
  // reads the grid; supported: float, double, vec3s and vec3d trees.
  void ValidateTree(const openvdb::io::GridDescriptor& gd, uint64_t limit);

  std::string FileName;
  uint64_t FileSize = 0;
  std::ifstream Stream;
  openvdb::io::StreamMetadata::Ptr StreamMeta;
  std::vector<openvdb::io::GridDescriptor> Descriptors;
  // Files without grid offsets (old streams) are read whole on opening.
  std::vector<openvdb::GridBase::Ptr> StreamedGrids;
};

// A new, empty grid of type GridT (one of the types openvdb::initialize()
// registers: FloatGrid, DoubleGrid, Int32Grid, BoolGrid, Vec3SGrid, ...)
// with the given background, made by OpenVDB's library through its grid
// registry instead of GridT::create(). Use it wherever a source makes a grid:
// the source that constructs a grid type compiles that type's virtual
// functions (all of Grid<T>'s and Tree<T>'s: file IO with every compression,
// merging, copying), 4-8 s of compile per type and per source, which
// libopenvdb already holds. Made by the library, they are not compiled again
// (TestOpenVDBReaderGrids.cxx, four grid types: 42 s -> 9 s at -O1); a
// source that still constructs one compiles them, slower but correct.
// Throws openvdb::LookupError before openvdb::initialize() (or
// tyndall_io::InitializeOpenVDB()). A copy is openvdb::deepCopyTypedGrid(),
// for the same reason not GridT::deepCopy().
template <class GridT>
typename GridT::Ptr NewGrid(
  const typename GridT::ValueType& background = openvdb::zeroVal<typename GridT::ValueType>())
{
  typename GridT::Ptr grid =
    openvdb::gridPtrCast<GridT>(openvdb::GridBase::createGrid(GridT::gridType()));
  if (!grid)
  {
    OPENVDB_THROW(
      openvdb::TypeError, "the grid registry made another type than " + GridT::gridType());
  }
  grid->tree().root().setBackground(background, /*updateChildNodes=*/false);
  return grid;
}
}

#endif
