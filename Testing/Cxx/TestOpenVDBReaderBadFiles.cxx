// Bad input to vtkOpenVDBImageReader: missing, empty, foreign, truncated and
// corrupted files, files without grids or with unsupported grids, transforms
// vtkImageData cannot represent, absurd or too large dimensions, level sets,
// empty grids and lying metadata. Every case gives a clear error (checked by
// its wording) and an empty output; no exception reaches the test and
// nothing crashes. The files are made here, in the test's scratch directory.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"

#include "TyndallTestOpenVDB.h"

#include <openvdb/io/File.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace tyndall_vdb_test;

namespace
{
vtkNew<vtkTest::ErrorObserver> observer;

// Reads `path` with a fresh reader (plus optional grid name) and expects an
// error containing `text` and an empty output.
void ExpectFailure(const std::string& path, const std::string& text, const std::string& what,
  const char* gridName = nullptr, bool convertLevelSets = false)
{
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);
  reader->SetFileName(path.empty() ? nullptr : path.c_str());
  reader->SetGridName(gridName);
  reader->SetConvertLevelSetToFog(convertLevelSets);
  reader->Update();
  ExpectError(observer, text, what + " (error)");
  Check(IsEmpty(reader->GetOutput()), what + " (empty output)");
}

// A valid dense-ish float grid: 40^3 voxels of varying values.
openvdb::FloatGrid::Ptr MakeGrid(const std::string& name)
{
  openvdb::FloatGrid::Ptr grid = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
  grid->setName(name);
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto acc = grid->getAccessor();
  for (int k = 0; k < 40; ++k)
  {
    for (int j = 0; j < 40; ++j)
    {
      for (int i = 0; i < 40; ++i)
      {
        acc.setValue(openvdb::Coord(i, j, k), float((i * 7 + j * 13 + k * 3) % 17) / 17.0f + 0.01f);
      }
    }
  }
  return grid;
}

void WriteUncompressed(const std::string& path, const openvdb::GridPtrVec& grids)
{
  openvdb::io::File file(path);
  file.setCompression(openvdb::io::COMPRESS_NONE);
  file.write(grids);
  file.close();
}

// Byte offset of the first grid descriptor: the grid name as OpenVDB writes
// strings (a 32-bit length, then the characters).
size_t FindDescriptor(const std::vector<char>& bytes, const std::string& name)
{
  std::string pattern(4, '\0');
  const uint32_t n = static_cast<uint32_t>(name.size());
  std::memcpy(&pattern[0], &n, 4);
  pattern += name;
  const std::string all(bytes.begin(), bytes.end());
  return all.find(pattern);
}

// A truncated copy of `source` must fail at every length.
void CheckTruncations(const std::string& source, const std::string& dir, const std::string& tag)
{
  const size_t size = ReadBytes(source).size();
  const size_t lengths[] = { 4, 8, 12, 16, 20, 40, 57, 61, 64, 100, 200, 300, 500, 1000, size / 4,
    size / 2, 3 * size / 4, size - 100, size - 8, size - 1 };
  for (size_t length : lengths)
  {
    if (length >= size)
    {
      continue;
    }
    const std::string path = dir + "/truncated.vdb";
    CopyFile(source, path, length);
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, observer);
    reader->SetFileName(path.c_str());
    reader->Update();
    const std::string what =
      tag + " truncated to " + std::to_string(length) + " of " + std::to_string(size) + " bytes";
    Check(observer->GetError(), what + " gives an error");
    if (observer->GetError())
    {
      std::cout << what << ": "
                << observer->GetErrorMessage().substr(
                     observer->GetErrorMessage().find(": ") + 2, 300)
                << std::endl;
    }
    observer->Clear();
    Check(IsEmpty(reader->GetOutput()), what + " gives an empty output");
  }
}
}

int TestOpenVDBReaderBadFiles(int argc, char* argv[])
{
  openvdb::initialize();
  const std::string dir = ScratchDir(argc, argv, "TestOpenVDBReaderBadFiles");

  // No file name, a missing file, a directory, an empty and a foreign file.
  ExpectFailure("", "No FileName", "no file name");
  ExpectFailure(dir + "/missing.vdb", "does not exist", "a missing file");
  ExpectFailure(dir, "not a regular file", "a directory");
  WriteBytes(dir + "/empty.vdb", {});
  ExpectFailure(dir + "/empty.vdb", "is empty", "an empty file");
  const std::string text = "This is not a VDB file, just some text.\n";
  WriteBytes(dir + "/text.vdb", std::vector<char>(text.begin(), text.end()));
  ExpectFailure(dir + "/text.vdb", "not an OpenVDB file", "a text file");
  Check(vtkOpenVDBImageReader::CanReadFile((dir + "/text.vdb").c_str()) == 0,
    "CanReadFile refuses a text file");

  // Truncated files: compressed (OpenVDB's default), uncompressed, and the
  // real samples when present.
  const std::string good = dir + "/good.vdb";
  WriteGrids(good, { MakeGrid("density") });
  Check(vtkOpenVDBImageReader::CanReadFile(good.c_str()) == 1, "CanReadFile accepts a .vdb");
  {
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->SetFileName(good.c_str());
    reader->Update();
    Check(reader->GetOutput()->GetNumberOfPoints() == 40 * 40 * 40, "the intact file reads");
  }
  CheckTruncations(good, dir, "compressed file");
  const std::string raw = dir + "/uncompressed.vdb";
  WriteUncompressed(raw, { MakeGrid("density") });
  CheckTruncations(raw, dir, "uncompressed file");
  for (const char* sample : { "fog_small.vdb", "smoke.vdb" })
  {
    const std::string path = SharedVDB(sample);
    if (!path.empty())
    {
      CheckTruncations(path, dir, sample);
    }
  }

  // Corrupted files. The magic number:
  std::vector<char> bytes = ReadBytes(good);
  std::vector<char> corrupt = bytes;
  corrupt[1] = 'X';
  WriteBytes(dir + "/magic.vdb", corrupt);
  ExpectFailure(dir + "/magic.vdb", "not an OpenVDB file", "a corrupted magic number");
  // The grid count (the 4 bytes before the first descriptor) and the
  // descriptor's end position (after name, type and instance-parent strings).
  const size_t descriptor = FindDescriptor(bytes, "density");
  Check(descriptor != std::string::npos && descriptor >= 4, "found the grid descriptor");
  if (descriptor != std::string::npos && descriptor >= 4)
  {
    corrupt = bytes;
    const int32_t manyGrids = 0x7fffffff;
    std::memcpy(&corrupt[descriptor - 4], &manyGrids, 4);
    WriteBytes(dir + "/count.vdb", corrupt);
    ExpectFailure(dir + "/count.vdb", "claims", "an absurd grid count");

    size_t pos = descriptor + 4 + 7; // past the name
    uint32_t typeLength = 0;
    std::memcpy(&typeLength, &bytes[pos], 4);
    pos += 4 + typeLength + 4 + 16; // type, empty instance parent, grid and block positions
    corrupt = bytes;
    const int64_t farEnd = int64_t(1) << 40;
    std::memcpy(&corrupt[pos], &farEnd, 8);
    WriteBytes(dir + "/endpos.vdb", corrupt);
    ExpectFailure(dir + "/endpos.vdb", "truncated or corrupted", "an end position past the file");

    corrupt = bytes;
    const uint32_t hugeName = 0xfffffff0u;
    std::memcpy(&corrupt[descriptor], &hugeName, 4);
    WriteBytes(dir + "/name.vdb", corrupt);
    ExpectFailure(dir + "/name.vdb", "runs past the end", "a garbage name length");
  }
  // Regression cases of the fuzzer's findings in OpenVDB 10 itself, which the
  // reader must catch before OpenVDB reads the data.
  // (1) An "uncompressed" zlib chunk that states more bytes than its buffer
  // holds: OpenVDB 10 copies the stated length first (a heap overflow).
  // Incompressible leaf values make OpenVDB store the leaf raw, with the
  // size -2048 (512 floats).
  {
    openvdb::FloatGrid::Ptr noisy = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    noisy->setName("density");
    // Random bit patterns (finite ones) do not compress.
    std::mt19937 values(7u);
    auto uniform = [](std::mt19937& rng)
    {
      const uint32_t bits = static_cast<uint32_t>(rng());
      float v = 0.0f;
      std::memcpy(&v, &bits, 4);
      return std::isfinite(v) ? v : 1.0f;
    };
    for (int k = 0; k < 8; ++k)
    {
      for (int j = 0; j < 8; ++j)
      {
        for (int i = 0; i < 8; ++i)
        {
          noisy->tree().setValue(openvdb::Coord(i, j, k), uniform(values));
        }
      }
    }
    openvdb::io::File file(dir + "/zip.vdb");
    file.setCompression(openvdb::io::COMPRESS_ZIP);
    file.write(openvdb::GridPtrVec{ noisy });
    file.close();
    std::vector<char> zip = ReadBytes(dir + "/zip.vdb");
    const int64_t raw = -2048;
    const std::string all(zip.begin(), zip.end());
    const size_t at = all.rfind(std::string(reinterpret_cast<const char*>(&raw), 8));
    Check(at != std::string::npos, "found the raw leaf chunk");
    if (at != std::string::npos)
    {
      const int64_t longer = -4096;
      std::memcpy(&zip[at], &longer, 8);
      WriteBytes(dir + "/zip-overflow.vdb", zip);
      ExpectFailure(dir + "/zip-overflow.vdb", "states 4096 bytes where 2048 are expected",
        "a raw chunk longer than its buffer");
      // The most negative size (the fuzzer's; its negation overflows int64).
      const int64_t lowest = std::numeric_limits<int64_t>::min();
      std::memcpy(&zip[at], &lowest, 8);
      WriteBytes(dir + "/zip-lowest.vdb", zip);
      ExpectFailure(dir + "/zip-lowest.vdb", "states 9223372036854775808 bytes where 2048",
        "a raw chunk stating -2^63 bytes");
    }
  }
  // (2) A Blosc chunk whose header claims more compressed bytes than the
  // chunk has: Blosc trusts the header and reads past the chunk.
  {
    openvdb::FloatGrid::Ptr smooth = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    smooth->setName("density");
    for (int k = 0; k < 8; ++k)
    {
      for (int j = 0; j < 8; ++j)
      {
        for (int i = 0; i < 8; ++i)
        {
          smooth->tree().setValue(openvdb::Coord(i, j, k), 0.25f * float(i + j));
        }
      }
    }
    openvdb::io::File file(dir + "/blosc.vdb");
    file.setCompression(openvdb::io::COMPRESS_BLOSC);
    file.write(openvdb::GridPtrVec{ smooth });
    file.close();
    std::vector<char> blosc = ReadBytes(dir + "/blosc.vdb");
    // The leaf's chunk: a positive int64 size n, then a Blosc header with
    // type size 4, 2048 uncompressed bytes and n compressed bytes.
    size_t header = std::string::npos;
    for (size_t p = 0; p + 24 <= blosc.size() && header == std::string::npos; ++p)
    {
      int64_t n = 0;
      uint32_t nbytes = 0, cbytes = 0;
      std::memcpy(&n, &blosc[p], 8);
      std::memcpy(&nbytes, &blosc[p + 12], 4);
      std::memcpy(&cbytes, &blosc[p + 20], 4);
      if (n > 16 && n < 2048 && blosc[p + 11] == 4 && nbytes == 2048 && cbytes == uint32_t(n))
      {
        header = p + 8;
      }
    }
    Check(header != std::string::npos, "found the leaf's Blosc chunk");
    if (header != std::string::npos)
    {
      const uint32_t claimed = 100000;
      std::memcpy(&blosc[header + 12], &claimed, 4);
      WriteBytes(dir + "/blosc-header.vdb", blosc);
      ExpectFailure(dir + "/blosc-header.vdb", "inconsistent header",
        "a Blosc header claiming more bytes than its chunk");
    }
  }

  // Random corruption anywhere after the magic number: either an error and an
  // empty output, or a consistent image; never a crash or an exception.
  const std::vector<char> sources[] = { bytes, ReadBytes(raw) };
  std::mt19937 rng(20240611u);
  int errors = 0, images = 0;
  for (const std::vector<char>& source : sources)
  {
    for (int trial = 0; trial < 60; ++trial)
    {
      corrupt = source;
      std::uniform_int_distribution<size_t> where(8, corrupt.size() - 1);
      std::uniform_int_distribution<int> value(0, 255), count(1, 8);
      const int n = count(rng);
      for (int b = 0; b < n; ++b)
      {
        corrupt[where(rng)] = static_cast<char>(value(rng));
      }
      WriteBytes(dir + "/random.vdb", corrupt);
      vtkNew<vtkOpenVDBImageReader> reader;
      reader->AddObserver(vtkCommand::ErrorEvent, observer);
      reader->AddObserver(vtkCommand::WarningEvent, observer);
      reader->SetFileName((dir + "/random.vdb").c_str());
      reader->SetMemoryLimit(512);
      reader->Update();
      vtkImageData* image = reader->GetOutput();
      if (observer->GetError())
      {
        ++errors;
        Check(IsEmpty(image), "a corrupted file that fails gives an empty output");
      }
      else
      {
        ++images;
        vtkDataArray* scalars = image->GetPointData()->GetScalars();
        Check(scalars && scalars->GetNumberOfTuples() == image->GetNumberOfPoints() &&
            image->GetNumberOfPoints() > 0,
          "a corrupted file that reads gives a consistent image");
      }
      observer->Clear();
    }
  }
  std::cout << "random corruption: " << errors << " errors, " << images << " images" << std::endl;

  // A file without grids.
  WriteGrids(dir + "/nogrids.vdb", openvdb::GridPtrVec());
  ExpectFailure(dir + "/nogrids.vdb", "contains no grids", "a file without grids");

  // Unsupported grid types, and a missing grid name.
  {
    openvdb::Int32Grid::Ptr ints = tyndall_io::NewGrid<openvdb::Int32Grid>(0);
    ints->setName("ints");
    ints->tree().setValue(openvdb::Coord(1, 2, 3), 7);
    openvdb::BoolGrid::Ptr mask = tyndall_io::NewGrid<openvdb::BoolGrid>(false);
    mask->setName("mask");
    mask->tree().setValue(openvdb::Coord(0, 0, 0), true);
    openvdb::Vec3IGrid::Ptr vec3i = tyndall_io::NewGrid<openvdb::Vec3IGrid>();
    vec3i->setName("vec3i");
    vec3i->tree().setValue(openvdb::Coord(0, 0, 0), openvdb::Vec3i(1, 2, 3));
    WriteGrids(dir + "/unsupported.vdb", { ints, mask, vec3i });
  }
  ExpectFailure(
    dir + "/unsupported.vdb", "no grid of a supported type", "a file with only unsupported grids");
  ExpectFailure(dir + "/unsupported.vdb", "unsupported grid type", "an int32 grid", "ints");
  ExpectFailure(dir + "/unsupported.vdb", "unsupported grid type", "a bool grid", "mask");
  ExpectFailure(dir + "/unsupported.vdb", "unsupported grid type", "a vec3i grid", "vec3i");
  ExpectFailure(good, "no grid named 'temperature'", "a missing grid name", "temperature");
  {
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->SetFileName((dir + "/unsupported.vdb").c_str());
    reader->AddObserver(vtkCommand::ErrorEvent, observer);
    reader->UpdateInformation();
    observer->Clear();
    Check(reader->GetNumberOfGrids() == 3 && !reader->IsGridSupported(0) &&
        std::string(reader->GetGridValueType(0)) == "int32",
      "unsupported grids are listed with their types");
  }

  // Transforms vtkImageData cannot represent.
  {
    openvdb::FloatGrid::Ptr frustum = MakeGrid("density");
    frustum->setTransform(openvdb::math::Transform::createFrustumTransform(
      openvdb::BBoxd(openvdb::Vec3d(0, 0, 0), openvdb::Vec3d(39, 39, 39)), 0.5, 2.0, 0.1));
    WriteGrids(dir + "/frustum.vdb", { frustum });
    ExpectFailure(dir + "/frustum.vdb", "non-linear transform", "a frustum transform");

    openvdb::FloatGrid::Ptr sheared = MakeGrid("density");
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    m(1, 0) = 0.5; // index axis j leans towards x
    sheared->setTransform(openvdb::math::Transform::createLinearTransform(m));
    WriteGrids(dir + "/sheared.vdb", { sheared });
    ExpectFailure(dir + "/sheared.vdb", "sheared transform", "a sheared transform");
  }

  // Damage OpenVDB itself does not notice (the fuzzer's findings): a root
  // tile keyed off the root's 4096-voxel grid near 2^31 (OpenVDB's bounding
  // boxes then overflow int32), a tile's active flag and a boolean metadata
  // value of 3 (OpenVDB reads the byte straight into a bool).
  {
    openvdb::FloatGrid::Ptr grid = MakeGrid("density");
    grid->tree().addTile(3, openvdb::Coord(12288, 8192, -4096), 0.5f, false);
    grid->insertMeta("tyndall_flag", openvdb::BoolMetadata(true));
    WriteGrids(dir + "/keys.vdb", { grid });
    const std::vector<char> bytes = ReadBytes(dir + "/keys.vdb");
    const std::string all(bytes.begin(), bytes.end());
    const int32_t key[3] = { 12288, 8192, -4096 };
    const size_t at = all.find(std::string(reinterpret_cast<const char*>(key), 12));
    Check(at != std::string::npos, "found the root tile");
    if (at != std::string::npos)
    {
      std::vector<char> corrupt = bytes;
      const int32_t top = std::numeric_limits<int32_t>::max();
      std::memcpy(&corrupt[at], &top, 4);
      WriteBytes(dir + "/key-top.vdb", corrupt);
      ExpectFailure(dir + "/key-top.vdb", "is off the root's 4096-voxel grid",
        "a root tile keyed at x = 2^31 - 1");
      corrupt = bytes;
      corrupt[at + 12 + 4] = 3; // after the origin and the float value
      WriteBytes(dir + "/tile-flag.vdb", corrupt);
      ExpectFailure(dir + "/tile-flag.vdb", "active flag is 3", "a tile's active flag of 3");
    }
    const std::string name = "tyndall_flag";
    const size_t meta = all.find(name + std::string("\x04\0\0\0bool\x01\0\0\0\x01", 13));
    Check(meta != std::string::npos, "found the boolean metadata");
    if (meta != std::string::npos)
    {
      std::vector<char> corrupt = bytes;
      corrupt[meta + name.size() + 12] = 3;
      WriteBytes(dir + "/meta-flag.vdb", corrupt);
      ExpectFailure(
        dir + "/meta-flag.vdb", "boolean metadata value is 3", "a boolean metadata value of 3");
    }
  }

  // Two root children at one origin: OpenVDB would overwrite the first
  // child's table entry and leak it (with its subtree).
  {
    openvdb::FloatGrid::Ptr grid = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    grid->setName("density");
    grid->tree().setValue(openvdb::Coord(1, 1, 1), 1.0f);
    grid->tree().setValue(openvdb::Coord(4100, 1, 1), 1.0f);
    {
      openvdb::io::File file(dir + "/twins.vdb");
      file.setCompression(openvdb::io::COMPRESS_NONE); // no codec bytes to mistake for an origin
      file.write({ grid });
      file.close();
    }
    const std::vector<char> bytes = ReadBytes(dir + "/twins.vdb");
    const std::string all(bytes.begin(), bytes.end());
    const int32_t second[3] = { 4096, 0, 0 }; // the second root child's origin
    const size_t at = all.find(std::string(reinterpret_cast<const char*>(second), 12));
    Check(at != std::string::npos, "found the second root child");
    if (at != std::string::npos)
    {
      std::vector<char> corrupt = bytes;
      std::memset(&corrupt[at], 0, 12); // now also at (0, 0, 0)
      WriteBytes(dir + "/twins-corrupt.vdb", corrupt);
      ExpectFailure(dir + "/twins-corrupt.vdb", "two root children at [0, 0, 0]",
        "two root children at one origin");
    }
  }

  // Absurd dimensions, and dimensions too large for the memory limit (an
  // active root tile of 4096^3 voxels): refused before any allocation.
  {
    openvdb::FloatGrid::Ptr absurd = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    absurd->setName("density");
    absurd->tree().setValue(openvdb::Coord(-2000000000, 0, 0), 1.0f);
    absurd->tree().setValue(openvdb::Coord(2000000000, 0, 0), 1.0f);
    WriteGrids(dir + "/absurd.vdb", { absurd });
    ExpectFailure(dir + "/absurd.vdb", "absurd dimensions", "4e9 voxels along x");

    openvdb::FloatGrid::Ptr tile = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    tile->setName("density");
    tile->tree().addTile(3, openvdb::Coord(0, 0, 0), 1.0f, true);
    WriteGrids(dir + "/tile.vdb", { tile });
    ExpectFailure(dir + "/tile.vdb", "above the MemoryLimit", "a 4096^3 active tile");
  }

  // A level set without conversion, and an empty grid.
  {
    openvdb::FloatGrid::Ptr sphere =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(5.0f, openvdb::Vec3f(0.0f), 0.5f);
    sphere->setName("surface");
    WriteGrids(dir + "/levelset.vdb", { sphere });
    ExpectFailure(dir + "/levelset.vdb", "is a level set", "a level set without conversion");

    openvdb::FloatGrid::Ptr empty = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    empty->setName("density");
    WriteGrids(dir + "/emptygrid.vdb", { empty });
    ExpectFailure(dir + "/emptygrid.vdb", "no active voxels", "a grid without active voxels");
  }

  // No statistics metadata: the reader reads the grid for its bounding box.
  // Lying metadata (a box smaller than the active voxels): a warning.
  {
    openvdb::io::File file(dir + "/nostats.vdb");
    file.setGridStatsMetadataEnabled(false);
    file.write(openvdb::GridPtrVec{ MakeGrid("density") });
    file.close();
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, observer);
    reader->SetFileName((dir + "/nostats.vdb").c_str());
    reader->Update();
    Check(!observer->GetError() && reader->GetOutput()->GetNumberOfPoints() == 40 * 40 * 40,
      "a file without bounding-box metadata reads whole");
    observer->Clear();

    openvdb::FloatGrid::Ptr lying = MakeGrid("density");
    lying->insertMeta(
      openvdb::GridBase::META_FILE_BBOX_MIN, openvdb::Vec3IMetadata(openvdb::Vec3i(0, 0, 0)));
    lying->insertMeta(
      openvdb::GridBase::META_FILE_BBOX_MAX, openvdb::Vec3IMetadata(openvdb::Vec3i(9, 9, 9)));
    openvdb::io::File lie(dir + "/lying.vdb");
    lie.setGridStatsMetadataEnabled(false);
    lie.write(openvdb::GridPtrVec{ lying });
    lie.close();
    vtkNew<vtkOpenVDBImageReader> liar;
    liar->AddObserver(vtkCommand::ErrorEvent, observer);
    liar->AddObserver(vtkCommand::WarningEvent, observer);
    liar->SetFileName((dir + "/lying.vdb").c_str());
    liar->Update();
    Check(!observer->GetError() && observer->GetWarning() &&
        observer->GetWarningMessage().find("outside the bounding box") != std::string::npos,
      "lying bounding-box metadata gives a warning");
    Check(liar->GetOutput()->GetNumberOfPoints() == 10 * 10 * 10,
      "lying metadata: the recorded box is read");
    observer->Clear();
  }

  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
