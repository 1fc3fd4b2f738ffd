// libFuzzer target for vtkOpenVDBImageReader: every input is written to a
// scratch file and read like a .vdb (information, then the whole image, a
// downsampled image and a sub-extent). A crash, a sanitizer report, a hang
// (libFuzzer's -timeout) or an exception escaping the reader is a finding;
// errors reported through vtkErrorMacro are the expected outcome for most
// inputs.
//
// The target runs on one thread (VTK's SMP tools and oneTBB, which OpenVDB
// uses): coverage gathered on worker threads varies from run to run, and
// with it the inputs libFuzzer derives, so a fixed -seed would not give the
// same test twice. The reader's memory limit is 8 MiB: large enough for every
// seed and for the limit's own refusal path, small enough that an input
// describing a 60 MB box does not take the instrumented build half a minute
// (libFuzzer would report that as a hang; the release reader takes 0.05 s).
//
// With TYNDALL_FUZZ_WRITE_SEEDS=DIR in the environment, the target first
// writes a few small valid .vdb files into DIR (fog, uncompressed, several
// grid types, a level set, half precision) to seed the corpus.
#include "vtkImageData.h"
#include "vtkObject.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkOpenVDBInternals.h" // tyndall_io::NewGrid
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <tbb/global_control.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <unistd.h>

// Global operator new and delete for the fuzz target. OpenVDB allocates
// buffers of sizes read from the file (a compressed block's size, a
// string's length); on corrupted input these can be anything up to 2^64.
// In a normal process such a request fails with std::bad_alloc, which the
// reader reports as an error, but AddressSanitizer aborts on any failing
// `new`. These replacements keep the production behaviour: a request above
// 2 GiB (or one malloc cannot satisfy) throws std::bad_alloc. The memory
// comes from malloc, so AddressSanitizer still checks every access to it.
namespace
{
constexpr std::size_t kMaxAllocation = std::size_t(1) << 31;

void* Allocate(std::size_t n, std::size_t alignment)
{
  if (n > kMaxAllocation)
  {
    throw std::bad_alloc();
  }
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t))
  {
    p = std::malloc(n ? n : 1);
  }
  else if (posix_memalign(&p, alignment, n ? n : 1) != 0)
  {
    p = nullptr;
  }
  if (!p)
  {
    throw std::bad_alloc();
  }
  return p;
}

void* AllocateNoThrow(std::size_t n, std::size_t alignment) noexcept
{
  try
  {
    return Allocate(n, alignment);
  }
  catch (...)
  {
    return nullptr;
  }
}
}

void* operator new(std::size_t n)
{
  return Allocate(n, 0);
}
void* operator new[](std::size_t n)
{
  return Allocate(n, 0);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  return AllocateNoThrow(n, 0);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
  return AllocateNoThrow(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a)
{
  return Allocate(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a)
{
  return Allocate(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept
{
  return AllocateNoThrow(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept
{
  return AllocateNoThrow(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete[](void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept
{
  std::free(p);
}

namespace
{
std::string scratch;

void RemoveScratch()
{
  std::remove(scratch.c_str());
}

// OpenVDB writes a random UUID into every file header (21 bytes in, 36
// characters); a fixed one makes the seeds, and so the whole run, the same
// every time.
void FixUuid(const std::string& path)
{
  std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
  char header[57] = {};
  if (file.read(header, sizeof(header)) && header[21 + 8] == '-' && header[21 + 35] != '-')
  {
    file.seekp(21);
    file.write("00000000-0000-4000-8000-000000000000", 36);
  }
}

void WriteSeeds(const std::string& dir)
{
  openvdb::FloatGrid::Ptr fog = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
  fog->setName("density");
  fog->setGridClass(openvdb::GRID_FOG_VOLUME);
  auto acc = fog->getAccessor();
  for (int k = 0; k < 10; ++k)
  {
    for (int j = 0; j < 10; ++j)
    {
      for (int i = 0; i < 10; ++i)
      {
        if ((i + j + k) % 3 != 0)
        {
          acc.setValue(openvdb::Coord(i, j, k), 0.1f * float((i * j + k) % 7));
        }
      }
    }
  }
  fog->tree().addTile(1, openvdb::Coord(16, 0, 0), 0.5f, true);
  {
    openvdb::io::File file(dir + "/seed-fog.vdb");
    file.write(openvdb::GridPtrVec{ fog });
  }
  {
    openvdb::io::File file(dir + "/seed-uncompressed.vdb");
    file.setCompression(openvdb::io::COMPRESS_NONE);
    file.write(openvdb::GridPtrVec{ fog });
  }
  {
    openvdb::DoubleGrid::Ptr temperature = tyndall_io::NewGrid<openvdb::DoubleGrid>(300.0);
    temperature->setName("temperature");
    temperature->tree().setValue(openvdb::Coord(1, 2, 3), 400.0);
    openvdb::Vec3SGrid::Ptr velocity = tyndall_io::NewGrid<openvdb::Vec3SGrid>();
    velocity->setName("velocity");
    velocity->tree().setValue(openvdb::Coord(0, 0, 0), openvdb::Vec3s(1, 2, 3));
    openvdb::Int32Grid::Ptr ints = tyndall_io::NewGrid<openvdb::Int32Grid>(0);
    ints->setName("ints");
    ints->tree().setValue(openvdb::Coord(0, 0, 0), 5);
    openvdb::io::File file(dir + "/seed-multi.vdb");
    file.write(openvdb::GridPtrVec{ temperature, velocity, ints, fog });
  }
  {
    openvdb::FloatGrid::Ptr sphere =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(3.0f, openvdb::Vec3f(0.0f), 0.5f);
    sphere->setName("surface");
    openvdb::io::File file(dir + "/seed-levelset.vdb");
    file.write(openvdb::GridPtrVec{ sphere });
  }
  {
    openvdb::FloatGrid::Ptr half = openvdb::deepCopyTypedGrid<openvdb::FloatGrid>(*fog);
    half->setSaveFloatAsHalf(true);
    openvdb::io::File file(dir + "/seed-half.vdb");
    file.write(openvdb::GridPtrVec{ half });
  }
  for (const char* name : { "fog", "uncompressed", "multi", "levelset", "half" })
  {
    FixUuid(dir + "/seed-" + name + ".vdb");
  }
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  static tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  vtkSMPTools::SetBackend("Sequential");
  openvdb::initialize();
  vtkObject::GlobalWarningDisplayOff(); // errors are expected; keep the log short
  // TYNDALL_FUZZ_SCRATCH names the scratch file (the test gives one of its
  // own, the same every run: the name appears in the reader's messages, and a
  // name that changes changes the coverage); otherwise one in TMPDIR.
  const char* fixed = std::getenv("TYNDALL_FUZZ_SCRATCH");
  const char* tmp = std::getenv("TMPDIR");
  scratch = fixed && *fixed ? std::string(fixed)
                            : std::string(tmp && *tmp ? tmp : "/tmp") + "/tyndall-fuzz-openvdb-" +
      std::to_string(static_cast<long>(getpid())) + ".vdb";
  std::atexit(RemoveScratch);
  if (const char* seeds = std::getenv("TYNDALL_FUZZ_WRITE_SEEDS"))
  {
    WriteSeeds(seeds);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  {
    std::ofstream out(scratch, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  vtkOpenVDBImageReader* reader = vtkOpenVDBImageReader::New();
  reader->SetFileName(scratch.c_str());
  reader->SetMemoryLimit(8); // absurd boxes must be refused, not allocated
  reader->SetConvertLevelSetToFog(size > 8 && (data[8] & 1));
  reader->UpdateInformation();
  for (int i = 0; i < reader->GetNumberOfGrids(); ++i)
  {
    int box[6];
    reader->GetGridIndexBoundingBox(i, box);
  }
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (image->GetNumberOfPoints() > 0)
  {
    // The whole image was produced: downsample it, and read a corner.
    int extent[6];
    image->GetExtent(extent);
    reader->SetDownsamplingFactor(2);
    reader->UpdateWholeExtent();
    reader->SetDownsamplingFactor(1);
    reader->Modified();
    int corner[6] = { extent[0], extent[0] + (extent[1] - extent[0]) / 2, extent[2], extent[3],
      extent[4], extent[4] };
    reader->UpdateExtent(corner);
  }
  reader->Delete();
  return 0;
}
