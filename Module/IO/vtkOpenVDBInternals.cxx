#include "vtkOpenVDBInternals.h"

#include "vtk_zlib.h"

#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/io.h>

#ifdef TYNDALL_HAVE_BLOSC
#include <blosc.h>
#endif

#include <cstring>

#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
// Walks the parts of a .vdb file that hold variable-length fields (strings,
// metadata values, the delayed-load metadata's arrays) before OpenVDB reads
// them, and refuses lengths that run past the end of their block. OpenVDB
// allocates (and fills) a buffer of the length it reads before reading the
// bytes, so a corrupted 32-bit length would otherwise cost up to 4 GiB of
// memory. The walk mirrors OpenVDB 10's readers (MetaMap::readMeta,
// Metadata::read, DelayedLoadMetadata::readValue, GridDescriptor::read,
// Transform::read); it consumes exactly what they consume for every file
// OpenVDB writes.
class Scanner
{
public:
  Scanner(std::istream& is, uint64_t limit, uint64_t fileSize)
    : Is(is)
    , Limit(limit)
    , FileSize(fileSize)
  {
  }

  uint64_t Pos() { return static_cast<uint64_t>(this->Is.tellg()); }

  void Need(uint64_t n, const char* what)
  {
    const uint64_t pos = this->Pos();
    if (pos > this->Limit || n > this->Limit - pos)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: " << what << " of " << n << " bytes at byte " << pos
                           << " runs past the end of its block (byte " << this->Limit << ")");
    }
  }

  uint32_t U32(const char* what)
  {
    this->Need(4, what);
    uint32_t v = 0;
    this->Is.read(reinterpret_cast<char*>(&v), 4);
    return v;
  }

  void Skip(uint64_t n, const char* what)
  {
    this->Need(n, what);
    this->Is.seekg(static_cast<std::streamoff>(n), std::ios_base::cur);
  }

  std::string String(const char* what)
  {
    const uint32_t n = this->U32(what);
    this->Need(n, what);
    std::string s(n, '\0');
    if (n > 0)
    {
      this->Is.read(&s[0], n);
    }
    return s;
  }

  void MetaMap()
  {
    const uint32_t count = this->U32("a metadata count");
    // Every entry takes at least 12 bytes (two lengths and a size).
    this->Need(uint64_t(count) * 12, "a metadata table");
    for (uint32_t i = 0; i < count; ++i)
    {
      this->String("a metadata name");
      const std::string type = this->String("a metadata type name");
      const uint32_t numBytes = this->U32("a metadata size");
      if (type == openvdb::StringMetadata::staticTypeName() ||
        !openvdb::Metadata::isRegisteredType(type))
      {
        this->Skip(numBytes, "a metadata value");
      }
      else if (type == openvdb::BoolMetadata::staticTypeName())
      {
        // OpenVDB reads the byte straight into a bool.
        this->Need(1, "a boolean metadata value");
        uint8_t value = 0;
        this->Is.read(reinterpret_cast<char*>(&value), 1);
        if (value > 1 || numBytes != 1)
        {
          OPENVDB_THROW(openvdb::IoError,
            "corrupted file: a boolean metadata value is " << int(value) << " (" << numBytes
                                                           << " bytes), not 0 or 1");
        }
      }
      else if (type == openvdb::io::DelayedLoadMetadata::staticTypeName())
      {
        this->DelayedLoad(numBytes);
      }
      else
      {
        const openvdb::Metadata::Ptr meta = openvdb::Metadata::createMetadata(type);
        this->Skip(meta ? meta->size() : numBytes, "a metadata value");
      }
    }
  }

  void DelayedLoad(uint32_t numBytes)
  {
    if (numBytes == 0)
    {
      return;
    }
    const uint64_t start = this->Pos();
    const uint32_t count = this->U32("delayed-load metadata");
    // One entry per leaf node: a file holds fewer leaves than 8 per byte.
    if (uint64_t(count) > 8 * this->FileSize + 1024)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: delayed-load metadata claims " << count << " leaf nodes");
    }
    for (int part = 0; part < 2; ++part)
    {
      const uint32_t bytes = this->U32("delayed-load metadata");
      if (part == 1 && bytes == std::numeric_limits<uint32_t>::max())
      {
        break;
      }
      const uint64_t elementSize = part == 0 ? 1 : 8;
      if (bytes > 0)
      {
        // A Blosc buffer: its header's bytes 4-7 hold the uncompressed size,
        // which OpenVDB reserves.
        // (OpenVDB pads small arrays to 128 bytes before compressing them.)
        this->BloscChunk(bytes, uint64_t(count) * elementSize + 1024, "delayed-load metadata");
      }
      else
      {
        this->Skip(uint64_t(count) * elementSize, "delayed-load metadata");
      }
    }
    const uint64_t consumed = this->Pos() - start;
    if (consumed < numBytes)
    {
      this->Skip(numBytes - consumed, "delayed-load metadata");
    }
  }

  // A Blosc chunk of chunkBytes bytes at the current position, whose
  // uncompressed size may be at most maxBytes. Blosc 1.x decompresses
  // without knowing the chunk's length: it trusts the sizes and block
  // offsets in the chunk's header, so a corrupted header makes it read past
  // the chunk. The header must agree with the chunk: compressed size within
  // it, block offsets inside it. Leaves the stream after the chunk.
  void BloscChunk(uint64_t chunkBytes, uint64_t maxBytes, const char* what)
  {
    this->Need(chunkBytes, what);
    if (chunkBytes < 16)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: a Blosc chunk of " << chunkBytes << " bytes in " << what);
    }
    unsigned char header[16];
    this->Is.read(reinterpret_cast<char*>(header), 16);
    uint32_t nbytes = 0, blocksize = 0, cbytes = 0;
    std::memcpy(&nbytes, header + 4, 4);
    std::memcpy(&blocksize, header + 8, 4);
    std::memcpy(&cbytes, header + 12, 4);
    const bool memcpyed = (header[2] & 0x02) != 0; // BLOSC_MEMCPYED: stored, not compressed
    bool ok = cbytes >= 16 && cbytes <= chunkBytes && nbytes <= maxBytes;
    uint64_t consumed = 16;
    if (ok && memcpyed)
    {
      ok = uint64_t(nbytes) + 16 <= cbytes;
    }
    else if (ok && nbytes > 0)
    {
      ok = blocksize > 0;
      const uint64_t nblocks = ok ? (uint64_t(nbytes) + blocksize - 1) / blocksize : 0;
      ok = ok && 16 + 4 * nblocks <= cbytes;
      for (uint64_t b = 0; ok && b < nblocks; ++b)
      {
        int32_t start = 0;
        this->Is.read(reinterpret_cast<char*>(&start), 4);
        consumed += 4;
        ok = start >= int64_t(16 + 4 * nblocks) && uint64_t(start) < cbytes;
      }
    }
    if (!ok)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: a Blosc chunk in " << what << " has an inconsistent header (" << cbytes
                                            << " compressed bytes in a chunk of " << chunkBytes
                                            << ", " << nbytes << " bytes uncompressed)");
    }
    this->Skip(chunkBytes - consumed, what);
  }

private:
  std::istream& Is;
  uint64_t Limit;
  uint64_t FileSize;
};

// Checks the keys of a grid's root table. OpenVDB keys a root tile by the
// origin the file states (it aligns only a child's own origin), so a damaged
// file can hold a key off the root's grid; one near 2^31 overflows every
// bounding box OpenVDB computes later (origin + 4095).
template <class GridT>
bool CheckRootKeysOf(const openvdb::GridBase& base)
{
  const GridT* grid = dynamic_cast<const GridT*>(&base);
  if (!grid)
  {
    return false;
  }
  using RootT = typename GridT::TreeType::RootNodeType;
  constexpr int32_t mask = int32_t(RootT::ChildNodeType::DIM) - 1;
  for (auto it = grid->tree().root().cbeginChildAll(); it; ++it)
  {
    const openvdb::Coord key = it.getCoord();
    if ((key.x() & mask) || (key.y() & mask) || (key.z() & mask))
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: a root " << (it.isChildNode() ? "child" : "tile") << " at " << key
                                  << " is off the root's " << (mask + 1) << "-voxel grid");
    }
  }
  return true;
}

void CheckRootKeys(const openvdb::GridBase& grid)
{
  CheckRootKeysOf<openvdb::FloatGrid>(grid) || CheckRootKeysOf<openvdb::DoubleGrid>(grid) ||
    CheckRootKeysOf<openvdb::Vec3SGrid>(grid) || CheckRootKeysOf<openvdb::Vec3DGrid>(grid);
}

// Walks a grid's tree (topology, then buffers) as OpenVDB 10 reads it, for
// files of format version 222 or later and trees of the standard 5-4-3
// configuration, checking every length against the end of the grid's block
// before OpenVDB reads it. It exists because OpenVDB 10's bloscFromStream()
// and unzipFromStream() copy an "uncompressed" chunk of the length the file
// states into a buffer sized for the expected length and only then compare
// the two (a heap overflow on crafted files; later OpenVDB versions check
// first). The walk mirrors RootNode/InternalNode/LeafNode::readTopology and
// readBuffers and io::readCompressedValues.
class TreeWalker
{
public:
  TreeWalker(std::istream& is, uint64_t limit, uint32_t compression, int valueSize, int storedSize)
    : S(is, limit, limit)
    , Is(is)
    , Compression(compression)
    , ValueSize(valueSize)
    , StoredSize(storedSize)
  {
  }

  void Walk()
  {
    this->S.Skip(4, "the tree's buffer count");
    this->S.Skip(this->ValueSize, "the background value");
    const uint32_t numTiles = this->S.U32("the root's tile count");
    const uint32_t numChildren = this->S.U32("the root's child count");
    // Each tile: origin, value, active flag.
    this->S.Need(uint64_t(numTiles) * (12 + this->ValueSize + 1), "the root's tiles");
    for (uint32_t n = 0; n < numTiles; ++n)
    {
      this->S.Skip(12 + this->ValueSize, "a root tile's origin and value");
      uint8_t active = 0;
      this->Is.read(reinterpret_cast<char*>(&active), 1);
      if (active > 1)
      {
        // OpenVDB reads the byte straight into a bool.
        OPENVDB_THROW(openvdb::IoError,
          "corrupted file: a root tile's active flag is " << int(active) << ", not 0 or 1");
      }
    }
    // The smallest child (two 4096-byte masks) bounds the count.
    this->S.Need(uint64_t(numChildren) * 8204, "the root's children");
    std::map<openvdb::Coord, Upper> children; // the root's table, by origin
    for (uint32_t n = 0; n < numChildren; ++n)
    {
      int32_t origin[3];
      this->S.Need(12, "a child origin");
      this->Is.read(reinterpret_cast<char*>(origin), 12);
      Upper upper;
      this->ReadInternal(32768,
        [&]()
        {
          Lower lower;
          this->ReadInternal(4096, [&]() { lower.Leaves.push_back(this->ReadLeafTopology()); });
          upper.Children.push_back(std::move(lower));
        });
      const openvdb::Coord key(origin[0], origin[1], origin[2]);
      if (children.count(key))
      {
        // RootNode::readTopology would overwrite the first child's table
        // entry and leak it (with its subtree, about 270 KB).
        OPENVDB_THROW(openvdb::IoError, "corrupted file: two root children at " << key);
      }
      children[key] = std::move(upper);
    }
    for (const auto& child : children)
    {
      for (const Lower& lower : child.second.Children)
      {
        for (uint32_t activeCount : lower.Leaves)
        {
          this->S.Skip(64, "a leaf's value mask");
          this->Values(512, 64, activeCount);
        }
      }
    }
  }

private:
  struct Lower
  {
    std::vector<uint32_t> Leaves; // active voxels of each leaf, in file order
  };
  struct Upper
  {
    std::vector<Lower> Children;
  };

  // An internal node with `size` entries: child mask, value mask, values,
  // then each child (readChild) in index order.
  template <class F>
  void ReadInternal(uint32_t size, F&& readChild)
  {
    const uint32_t maskBytes = size / 8;
    std::vector<uint64_t> childMask(size / 64), valueMask(size / 64);
    this->S.Need(2 * uint64_t(maskBytes), "an internal node's masks");
    this->Is.read(reinterpret_cast<char*>(childMask.data()), maskBytes);
    this->Is.read(reinterpret_cast<char*>(valueMask.data()), maskBytes);
    uint32_t activeCount = 0;
    for (uint64_t word : valueMask)
    {
      activeCount += static_cast<uint32_t>(__builtin_popcountll(word));
    }
    this->Values(size, maskBytes, activeCount, true);
    for (uint64_t word : childMask)
    {
      for (int bit = 0; bit < 64; ++bit)
      {
        if (word & (uint64_t(1) << bit))
        {
          readChild();
        }
      }
    }
  }

  uint32_t ReadLeafTopology()
  {
    uint64_t mask[8];
    this->S.Need(64, "a leaf's value mask");
    this->Is.read(reinterpret_cast<char*>(mask), 64);
    uint32_t activeCount = 0;
    for (uint64_t word : mask)
    {
      activeCount += static_cast<uint32_t>(__builtin_popcountll(word));
    }
    return activeCount;
  }

  // io::readCompressedValues for `count` values of a node whose masks take
  // maskBytes and whose value mask has activeCount bits on. With `decode`
  // (an internal node's values, which OpenVDB reads inside readTopology),
  // a compressed chunk is also decompressed, as OpenVDB will: a failure
  // there throws out of RootNode::readTopology and leaks the child node it
  // was reading (about 270 KB), so it must be found first. Leaf values are
  // read later, into nodes the tree already owns.
  void Values(uint32_t count, uint32_t maskBytes, uint32_t activeCount, bool decode = false)
  {
    this->S.Need(1, "a value block's flag");
    int8_t flag = 0;
    this->Is.read(reinterpret_cast<char*>(&flag), 1);
    if (flag == 2 || flag == 4 || flag == 5) // one or two inactive values
    {
      this->S.Skip(uint64_t(this->ValueSize) * (flag == 5 ? 2 : 1), "inactive values");
    }
    if (flag == 3 || flag == 4 || flag == 5) // a selection mask
    {
      this->S.Skip(maskBytes, "a selection mask");
    }
    uint64_t values = count;
    if ((this->Compression & openvdb::io::COMPRESS_ACTIVE_MASK) && flag != 6)
    {
      values = activeCount;
    }
    const bool half = this->StoredSize != this->ValueSize;
    if (half && values == 0)
    {
      return; // HalfReader reads nothing for no values
    }
    const uint64_t bytes = values * uint64_t(this->StoredSize);
    if (this->Compression & (openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ZIP))
    {
      this->S.Need(8, "a compressed chunk's size");
      int64_t stated = 0;
      this->Is.read(reinterpret_cast<char*>(&stated), 8);
      if (stated <= 0)
      {
        // |stated| computed unsigned: -INT64_MIN does not fit in int64_t.
        const uint64_t magnitude = uint64_t(0) - uint64_t(stated);
        if (magnitude != bytes)
        {
          OPENVDB_THROW(openvdb::IoError,
            "corrupted file: an uncompressed chunk states " << magnitude << " bytes where " << bytes
                                                            << " are expected");
        }
        this->S.Skip(bytes, "an uncompressed chunk");
      }
      else if (this->Compression & openvdb::io::COMPRESS_BLOSC)
      {
        const std::streampos chunk = this->Is.tellg();
        this->S.BloscChunk(uint64_t(stated), bytes, "a compressed value block");
        if (decode)
        {
          this->Decode(chunk, uint64_t(stated), bytes, true);
        }
      }
      else if (decode)
      {
        this->S.Need(uint64_t(stated), "a compressed chunk");
        this->Decode(this->Is.tellg(), uint64_t(stated), bytes, false);
      }
      else
      {
        this->S.Skip(uint64_t(stated), "a compressed chunk"); // zlib is given its length
      }
    }
    else
    {
      this->S.Skip(bytes, "uncompressed values");
    }
  }

  // Decompresses the chunk of chunkBytes at `chunk` (Blosc or zlib) as
  // io::bloscFromStream / unzipFromStream will, and throws unless it gives
  // exactly `bytes` bytes. Leaves the stream after the chunk.
  void Decode(std::streampos chunk, uint64_t chunkBytes, uint64_t bytes, bool blosc)
  {
    std::vector<char> in(chunkBytes), out(bytes + 1);
    this->Is.seekg(chunk);
    this->Is.read(in.data(), static_cast<std::streamsize>(chunkBytes));
    bool ok = false;
    if (blosc)
    {
#ifdef TYNDALL_HAVE_BLOSC
      const int got = blosc_decompress_ctx(in.data(), out.data(), out.size(), 1);
      ok = got >= 0 && uint64_t(got) == bytes;
#else
      ok = true; // without Blosc's header, only the lengths were checked
#endif
    }
    else
    {
      uLongf length = static_cast<uLongf>(out.size());
      ok = uncompress(reinterpret_cast<Bytef*>(out.data()), &length,
             reinterpret_cast<const Bytef*>(in.data()), static_cast<uLong>(chunkBytes)) == Z_OK &&
        uint64_t(length) == bytes;
    }
    if (!ok)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupted file: a " << (blosc ? "Blosc" : "zlib") << " chunk of an internal node does "
                             << "not decompress to its " << bytes << " bytes");
    }
  }

  Scanner S;
  std::istream& Is;
  uint32_t Compression;
  int ValueSize;
  int StoredSize;
};

// Runs f with the stream's position restored afterwards.
template <class F>
void Scan(std::istream& is, F&& f)
{
  const std::streampos pos = is.tellg();
  f();
  is.seekg(pos);
}
}

namespace tyndall_io
{
//------------------------------------------------------------------------------
void InitializeOpenVDB()
{
  static std::once_flag once;
  std::call_once(once, []() { openvdb::initialize(); });
}

//------------------------------------------------------------------------------
openvdb::Mat4d AffineMatrix(const openvdb::math::Transform& transform)
{
  return transform.baseMap()->getAffineMap()->getMat4();
}

//------------------------------------------------------------------------------
SafeFile::SafeFile(const std::string& fileName)
  : FileName(fileName)
{
  InitializeOpenVDB();
  this->Stream.open(fileName, std::ios_base::in | std::ios_base::binary);
  if (!this->Stream)
  {
    OPENVDB_THROW(openvdb::IoError, "could not open " << fileName);
  }
  this->Stream.seekg(0, std::ios_base::end);
  const std::streamoff size = this->Stream.tellg();
  this->Stream.seekg(0, std::ios_base::beg);
  if (size < 0 || !this->Stream)
  {
    OPENVDB_THROW(openvdb::IoError, "could not determine the size of " << fileName);
  }
  this->FileSize = static_cast<uint64_t>(size);
  // From here on every short read throws std::ios_base::failure.
  this->Stream.exceptions(std::ios_base::failbit | std::ios_base::badbit);

  this->readHeader(this->Stream);
  if (this->fileVersion() > openvdb::OPENVDB_FILE_VERSION)
  {
    OPENVDB_THROW(openvdb::IoError,
      "file format version " << this->fileVersion() << " is newer than this OpenVDB ("
                             << openvdb::OPENVDB_FILE_VERSION << ") reads");
  }
  if (this->fileVersion() < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
  {
    OPENVDB_THROW(openvdb::IoError,
      "file format version " << this->fileVersion() << " (before OpenVDB 3.0, format "
                             << openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION
                             << ") is not supported");
  }
  this->StreamMeta.reset(new openvdb::io::StreamMetadata);
  this->StreamMeta->setSeekable(true);
  openvdb::io::setStreamMetadataPtr(this->Stream, this->StreamMeta, /*transfer=*/false);
  this->setFormatVersion(this->Stream);
  this->setLibraryVersion(this->Stream);
  this->setDataCompression(this->Stream);

  Scan(this->Stream, [&]() { Scanner(this->Stream, this->FileSize, this->FileSize).MetaMap(); });
  openvdb::MetaMap fileMeta;
  fileMeta.readMeta(this->Stream);
  const int32_t count = readGridCount(this->Stream);
  // Each grid needs far more than 16 bytes; a larger count is garbage.
  if (count < 0 || uint64_t(count) > this->FileSize / 16)
  {
    OPENVDB_THROW(openvdb::IoError, "corrupted file: it claims " << count << " grids");
  }
  openvdb::io::Archive::NamedGridMap named;
  for (int32_t i = 0; i < count; ++i)
  {
    Scan(this->Stream,
      [&]()
      {
        Scanner scanner(this->Stream, this->FileSize, this->FileSize);
        const int strings = openvdb::io::getFormatVersion(this->Stream) >=
            openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING
          ? 3
          : 2;
        for (int s = 0; s < strings; ++s)
        {
          scanner.String("a grid descriptor string");
        }
      });
    openvdb::io::GridDescriptor gd;
    gd.read(this->Stream);
    if (!this->inputHasGridOffsets())
    {
      openvdb::GridBase::Ptr grid = this->CreateGrid(gd);
      Scan(this->Stream,
        [&]()
        {
          Scanner scanner(this->Stream, this->FileSize, this->FileSize);
          scanner.Skip(4, "the grid compression flags");
          scanner.MetaMap();
          scanner.String("the transform type");
        });
      this->ValidateTree(gd, this->FileSize);
      openvdb::io::Archive::readGrid(grid, gd, this->Stream);
      named[gd.uniqueName()] = grid;
      this->StreamedGrids.push_back(grid);
      this->Descriptors.push_back(gd);
      continue;
    }
    const int64_t here = static_cast<int64_t>(this->Stream.tellg());
    if (gd.getGridPos() < here || gd.getEndPos() < gd.getGridPos() ||
      uint64_t(gd.getEndPos()) > this->FileSize)
    {
      OPENVDB_THROW(openvdb::IoError,
        "truncated or corrupted file: grid \""
          << openvdb::io::GridDescriptor::nameAsString(gd.uniqueName()) << "\" claims bytes "
          << gd.getGridPos() << " to " << gd.getEndPos() << " of a file of " << this->FileSize
          << " bytes");
    }
    this->Descriptors.push_back(gd);
    gd.seekToEnd(this->Stream);
  }
  for (const auto& gd : this->Descriptors)
  {
    this->connectInstance(gd, named);
  }
}

//------------------------------------------------------------------------------
SafeFile::~SafeFile() = default;

//------------------------------------------------------------------------------
openvdb::GridBase::Ptr SafeFile::CreateGrid(const openvdb::io::GridDescriptor& gd) const
{
  if (!openvdb::GridBase::isRegistered(gd.gridType()))
  {
    OPENVDB_THROW(openvdb::KeyError, "grid type " << gd.gridType() << " is not registered");
  }
  openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(gd.gridType());
  if (grid)
  {
    grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
  }
  return grid;
}

//------------------------------------------------------------------------------
void SafeFile::CheckEnd(const openvdb::io::GridDescriptor& gd)
{
  const int64_t pos = static_cast<int64_t>(this->Stream.tellg());
  if (pos > gd.getEndPos())
  {
    OPENVDB_THROW(openvdb::IoError,
      "corrupted file: reading grid \""
        << openvdb::io::GridDescriptor::nameAsString(gd.uniqueName()) << "\" went past its end ("
        << pos << " > " << gd.getEndPos() << ")");
  }
}

//------------------------------------------------------------------------------
void SafeFile::ScanGrid(const openvdb::io::GridDescriptor& gd)
{
  gd.seekToGrid(this->Stream);
  Scan(this->Stream,
    [&]()
    {
      Scanner scanner(this->Stream, uint64_t(gd.getEndPos()), this->FileSize);
      const uint32_t version = openvdb::io::getFormatVersion(this->Stream);
      if (version >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
      {
        scanner.Skip(4, "the grid compression flags");
      }
      scanner.MetaMap();
      if (version >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
      {
        scanner.String("the transform type");
      }
    });
}

//------------------------------------------------------------------------------
void SafeFile::ValidateTree(const openvdb::io::GridDescriptor& gd, uint64_t limit)
{
  const std::streampos start = this->Stream.tellg();
  openvdb::GridBase::Ptr probe = this->CreateGrid(gd);
  int valueSize = 0, halfSize = 0;
  if (probe->isType<openvdb::FloatGrid>())
  {
    valueSize = 4;
    halfSize = 2;
  }
  else if (probe->isType<openvdb::DoubleGrid>())
  {
    valueSize = 8;
    halfSize = 2;
  }
  else if (probe->isType<openvdb::Vec3SGrid>())
  {
    valueSize = 12;
    halfSize = 6;
  }
  else if (probe->isType<openvdb::Vec3DGrid>())
  {
    valueSize = 24;
    halfSize = 6;
  }
  else
  {
    OPENVDB_THROW(openvdb::TypeError,
      "reading the voxels of grid type " << gd.gridType() << " is not supported");
  }
  readGridCompression(this->Stream);
  const uint32_t compression = openvdb::io::getDataCompression(this->Stream);
  probe->readMeta(this->Stream);
  probe->readTransform(this->Stream);
  if (!gd.isInstance())
  {
    TreeWalker(
      this->Stream, limit, compression, valueSize, probe->saveFloatAsHalf() ? halfSize : valueSize)
      .Walk();
  }
  this->Stream.seekg(start);
}

//------------------------------------------------------------------------------
openvdb::GridBase::Ptr SafeFile::ReadGridMetadata(int i)
{
  const openvdb::io::GridDescriptor& gd = this->Descriptors.at(i);
  if (!this->inputHasGridOffsets())
  {
    return this->StreamedGrids.at(i)->copyGridWithNewTree();
  }
  openvdb::GridBase::Ptr grid = this->CreateGrid(gd);
  this->ScanGrid(gd);
  if (openvdb::io::getFormatVersion(this->Stream) < openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
  {
    // Old layout (topology before transform): read the whole grid.
    openvdb::io::Archive::readGrid(grid, gd, this->Stream);
    this->CheckEnd(gd);
    return grid->copyGridWithNewTree();
  }
  // As openvdb::io::File::readGridPartial without topology.
  readGridCompression(this->Stream);
  grid->readMeta(this->Stream);
  if ((*grid)[openvdb::GridBase::META_FILE_DELAYED_LOAD])
  {
    grid->removeMeta(openvdb::GridBase::META_FILE_DELAYED_LOAD);
  }
  grid->readTransform(this->Stream);
  this->CheckEnd(gd);
  return grid;
}

//------------------------------------------------------------------------------
openvdb::GridBase::Ptr SafeFile::ReadGrid(int i)
{
  if (!this->inputHasGridOffsets())
  {
    return this->StreamedGrids.at(i);
  }
  const openvdb::io::GridDescriptor& gd = this->Descriptors.at(i);
  openvdb::GridBase::Ptr grid = this->CreateGrid(gd);
  this->ScanGrid(gd);
  this->ValidateTree(gd, uint64_t(gd.getEndPos()));
  openvdb::io::Archive::readGrid(grid, gd, this->Stream);
  this->CheckEnd(gd);
  if (gd.isInstance())
  {
    int parent = -1;
    for (size_t j = 0; j < this->Descriptors.size() && parent < 0; ++j)
    {
      if (this->Descriptors[j].uniqueName() == gd.instanceParentName() && int(j) != i)
      {
        parent = static_cast<int>(j);
      }
    }
    if (parent < 0 || this->Descriptors[parent].isInstance())
    {
      OPENVDB_THROW(openvdb::KeyError,
        "missing instance parent \""
          << openvdb::io::GridDescriptor::nameAsString(gd.instanceParentName()) << "\"");
    }
    grid->setTree(this->ReadGrid(parent)->baseTreePtr());
  }
  return grid;
}

//------------------------------------------------------------------------------
openvdb::GridBase::Ptr SafeFile::ReadGrid(const std::string& name)
{
  for (size_t i = 0; i < this->Descriptors.size(); ++i)
  {
    if (this->Descriptors[i].gridName() == name)
    {
      openvdb::GridBase::Ptr grid = this->ReadGrid(static_cast<int>(i));
      CheckRootKeys(*grid);
      return grid;
    }
  }
  OPENVDB_THROW(openvdb::KeyError, "no grid named \"" << name << "\"");
}
}
