// vtkOpenVDBImageReader's streaming, downsampling, memory limit and progress:
// - pieces (sub-extents) equal the whole image, each densifies only its own
//   extent (its extent, point count and memory estimate), and
//   vtkImageDataStreamer reassembles the whole exactly;
// - DownsamplingFactor f averages f^3 boxes aligned to multiples of f in
//   index space (checked against box averages of the full-resolution image,
//   with the background outside the active box), with points at the box
//   centres (checked with OpenVDB's indexToWorld);
// - an update above MemoryLimit fails cleanly before allocating;
// - progress events rise to 1;
// - a grid of background 0 gets its active values alone written, whole and
//   in pieces that cut its active tile (GetFilledActiveOnly()).
#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageDataStreamer.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"

#include "TyndallTestOpenVDB.h"

#include <algorithm>
#include <vector>

using namespace tyndall_vdb_test;

namespace
{
vtkNew<vtkTest::ErrorObserver> observer;
const float kBackground = 0.125f;

// Floor division, independent of the reader's.
int FloorDiv(int a, int b)
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

bool SameValues(vtkImageData* piece, vtkImageData* whole)
{
  int ext[6];
  piece->GetExtent(ext);
  vtkDataArray* a = piece->GetPointData()->GetScalars();
  vtkDataArray* b = whole->GetPointData()->GetScalars();
  if (!a || !b)
  {
    return false;
  }
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      for (int i = ext[0]; i <= ext[1]; ++i)
      {
        int ijk[3] = { i, j, k };
        const vtkIdType pa = piece->ComputePointId(ijk);
        const vtkIdType pb = whole->ComputePointId(ijk);
        if (pa < 0 || pb < 0 || a->GetComponent(pa, 0) != b->GetComponent(pb, 0))
        {
          return false;
        }
      }
    }
  }
  return true;
}

// The full-resolution value at (i, j, k): the image's value inside its
// extent, the background outside.
double FullValue(vtkImageData* full, int i, int j, int k)
{
  int ext[6];
  full->GetExtent(ext);
  if (i < ext[0] || i > ext[1] || j < ext[2] || j > ext[3] || k < ext[4] || k > ext[5])
  {
    return kBackground;
  }
  int ijk[3] = { i, j, k };
  return full->GetPointData()->GetScalars()->GetComponent(full->ComputePointId(ijk), 0);
}

void CheckDownsampled(vtkImageData* down, vtkImageData* full, const openvdb::GridBase& grid, int f,
  const std::string& tag)
{
  int fe[6], de[6];
  full->GetExtent(fe);
  down->GetExtent(de);
  for (int c = 0; c < 3; ++c)
  {
    Check(de[2 * c] == FloorDiv(fe[2 * c], f) && de[2 * c + 1] == FloorDiv(fe[2 * c + 1], f),
      tag + ": extent is the full extent divided by f (rounded down), axis " + std::to_string(c));
  }
  vtkDataArray* values = down->GetPointData()->GetScalars();
  vtkIdType bad = 0, badPosition = 0;
  const double offset = 0.5 * (f - 1);
  for (int K = de[4]; K <= de[5]; ++K)
  {
    for (int J = de[2]; J <= de[3]; ++J)
    {
      for (int I = de[0]; I <= de[1]; ++I)
      {
        double sum = 0.0;
        for (int z = 0; z < f; ++z)
        {
          for (int y = 0; y < f; ++y)
          {
            for (int x = 0; x < f; ++x)
            {
              sum += FullValue(full, I * f + x, J * f + y, K * f + z);
            }
          }
        }
        const float want = static_cast<float>(sum * (1.0 / (double(f) * f * f)));
        int ijk[3] = { I, J, K };
        const vtkIdType id = down->ComputePointId(ijk);
        bad += (values->GetComponent(id, 0) == want) ? 0 : 1;
        double p[3];
        down->TransformIndexToPhysicalPoint(I, J, K, p);
        const openvdb::Vec3d w =
          grid.indexToWorld(openvdb::Vec3d(I * f + offset, J * f + offset, K * f + offset));
        badPosition +=
          (Near(p[0], w[0], 1e-9) && Near(p[1], w[1], 1e-9) && Near(p[2], w[2], 1e-9)) ? 0 : 1;
      }
    }
  }
  Check(bad == 0, tag + ": " + std::to_string(bad) + " box averages differ");
  Check(badPosition == 0, tag + ": " + std::to_string(badPosition) + " points off the box centres");
}
}

int TestOpenVDBReaderStreaming(int argc, char* argv[])
{
  openvdb::initialize();
  const std::string dir = ScratchDir(argc, argv, "TestOpenVDBReaderStreaming");

  // A grid with a non-zero background, varying values, an active tile and
  // an index box that is neither aligned nor a multiple of 2 or 3.
  openvdb::FloatGrid::Ptr grid = tyndall_io::NewGrid<openvdb::FloatGrid>(kBackground);
  grid->setName("density");
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(0.3);
  transform->postTranslate(openvdb::Vec3d(-2.0, 0.5, 7.0));
  grid->setTransform(transform);
  {
    auto acc = grid->getAccessor();
    for (int k = -9; k <= 6; ++k)
    {
      for (int j = 3; j <= 17; ++j)
      {
        for (int i = -5; i <= 20; ++i)
        {
          if ((i * 31 + j * 17 + k * 7) % 5 != 0) // leave some voxels inactive
          {
            acc.setValue(openvdb::Coord(i, j, k),
              float((i * 7 + j * 13 + k * 3 + 600) % 23) / 23.0f + 0.015625f);
          }
        }
      }
    }
    grid->tree().addTile(1, openvdb::Coord(8, 8, -8), 0.75f, true); // voxels 8..15, 8..15, -8..-1
  }
  const std::string path = dir + "/grid.vdb";
  WriteGrids(path, { grid });

  vtkNew<vtkOpenVDBImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());

  // Progress events.
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> progressCallback;
  progressCallback->SetClientData(&progress);
  progressCallback->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
    { static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(call)); });
  reader->AddObserver(vtkCommand::ProgressEvent, progressCallback);

  reader->Update();
  Check(!observer->GetError(), "whole: no error");
  vtkNew<vtkImageData> whole;
  whole->DeepCopy(reader->GetOutput());
  int wholeExt[6];
  whole->GetExtent(wholeExt);
  Check(wholeExt[0] == -5 && wholeExt[1] == 20 && wholeExt[2] == 3 && wholeExt[3] == 17 &&
      wholeExt[4] == -9 && wholeExt[5] == 6,
    "whole: the index box");
  bool rising = !progress.empty() && progress.front() == 0.0 && progress.back() == 1.0;
  for (size_t p = 1; p < progress.size(); ++p)
  {
    rising = rising && progress[p] >= progress[p - 1];
  }
  Check(rising && progress.size() >= 3, "progress events rise from 0 to 1");
  const double wholeEstimate = reader->GetLastMemoryEstimate();

  // Pieces: 2 x 2 x 3 blocks of the whole extent.
  int pieces = 0;
  for (int bz = 0; bz < 3; ++bz)
  {
    for (int by = 0; by < 2; ++by)
    {
      for (int bx = 0; bx < 2; ++bx)
      {
        const int b[3] = { bx, by, bz }, n[3] = { 2, 2, 3 };
        int sub[6];
        for (int c = 0; c < 3; ++c)
        {
          const int lo = wholeExt[2 * c], len = wholeExt[2 * c + 1] - lo + 1;
          sub[2 * c] = lo + len * b[c] / n[c];
          sub[2 * c + 1] = lo + len * (b[c] + 1) / n[c] - 1;
        }
        reader->Modified(); // else the executive keeps the larger image it has
        reader->UpdateExtent(sub);
        vtkImageData* piece = reader->GetOutput();
        int got[6];
        piece->GetExtent(got);
        const vtkIdType points =
          vtkIdType(sub[1] - sub[0] + 1) * (sub[3] - sub[2] + 1) * (sub[5] - sub[4] + 1);
        Check(std::equal(got, got + 6, sub) && piece->GetNumberOfPoints() == points,
          "piece " + std::to_string(pieces) + ": only the requested extent");
        Check(reader->GetLastMemoryEstimate() == 4.0 * points,
          "piece " + std::to_string(pieces) + ": estimate of its own dense array");
        Check(SameValues(piece, whole), "piece " + std::to_string(pieces) + " equals the whole");
        ++pieces;
      }
    }
  }
  Check(reader->GetLastMemoryEstimate() < wholeEstimate, "a piece needs less memory");

  // vtkImageDataStreamer: the reader computes several pieces, reassembled.
  {
    vtkNew<vtkOpenVDBImageReader> streamed;
    streamed->SetFileName(path.c_str());
    std::vector<double> starts;
    vtkNew<vtkCallbackCommand> counter;
    counter->SetClientData(&starts);
    counter->SetCallback(
      [](vtkObject*, unsigned long, void* client, void* call)
      {
        if (*static_cast<double*>(call) == 0.0)
        {
          static_cast<std::vector<double>*>(client)->push_back(0.0);
        }
      });
    streamed->AddObserver(vtkCommand::ProgressEvent, counter);
    vtkNew<vtkImageDataStreamer> streamer;
    streamer->SetInputConnection(streamed->GetOutputPort());
    streamer->SetNumberOfStreamDivisions(5);
    streamer->Update();
    Check(starts.size() >= 5,
      "the streamer made the reader run once per piece (" + std::to_string(starts.size()) +
        " runs)");
    vtkImageData* out = streamer->GetOutput();
    int ext[6];
    out->GetExtent(ext);
    Check(std::equal(ext, ext + 6, wholeExt) && SameValues(out, whole) && SameValues(whole, out),
      "streamed pieces equal the whole");
  }

  // Downsampling, whole and in pieces.
  for (int f : { 2, 3 })
  {
    const std::string tag = "downsampling by " + std::to_string(f);
    reader->SetDownsamplingFactor(f);
    reader->UpdateWholeExtent();
    Check(!observer->GetError(), tag + ": no error");
    vtkNew<vtkImageData> down;
    down->DeepCopy(reader->GetOutput());
    CheckDownsampled(down, whole, *grid, f, tag);
    int de[6];
    down->GetExtent(de);
    const int half = (de[1] + de[0]) / 2;
    int left[6] = { de[0], half, de[2], de[3], de[4], de[5] };
    int right[6] = { half + 1, de[1], de[2], de[3], de[4], de[5] };
    reader->Modified();
    reader->UpdateExtent(left);
    Check(SameValues(reader->GetOutput(), down), tag + ": left piece equals the whole");
    reader->Modified();
    reader->UpdateExtent(right);
    Check(SameValues(reader->GetOutput(), down), tag + ": right piece equals the whole");
  }
  reader->SetDownsamplingFactor(1);

  // The memory limit: a 200^3 box (two voxels at its corners) is 30.5 MiB
  // of floats.
  {
    openvdb::FloatGrid::Ptr big = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    big->setName("density");
    big->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
    big->tree().setValue(openvdb::Coord(199, 199, 199), 2.0f);
    WriteGrids(dir + "/big.vdb", { big });
    vtkNew<vtkOpenVDBImageReader> limited;
    limited->AddObserver(vtkCommand::ErrorEvent, observer);
    limited->SetFileName((dir + "/big.vdb").c_str());
    limited->SetMemoryLimit(16);
    limited->Update();
    ExpectError(observer, "above the MemoryLimit of 16 MiB", "30.5 MiB above a 16 MiB limit");
    Check(IsEmpty(limited->GetOutput()), "above the limit: empty output");
    Check(
      limited->GetLastMemoryEstimate() >= 200.0 * 200 * 200 * 4, "the estimate covers the array");

    limited->SetDownsamplingFactor(2);
    limited->UpdateWholeExtent();
    Check(!observer->GetError() && limited->GetOutput()->GetNumberOfPoints() == 100 * 100 * 100,
      "downsampled by 2 it fits");
    observer->Clear();
    limited->SetDownsamplingFactor(1);
    int slab[6] = { 0, 199, 0, 199, 0, 39 };
    limited->UpdateExtent(slab);
    Check(!observer->GetError() && limited->GetOutput()->GetNumberOfPoints() == 200 * 200 * 40,
      "a 6 MiB slab fits");
    observer->Clear();
    limited->SetMemoryLimit(64);
    limited->UpdateWholeExtent();
    Check(!observer->GetError() && limited->GetOutput()->GetNumberOfPoints() == 200 * 200 * 200,
      "the whole fits under 64 MiB");
    observer->Clear();
  }

  // A background of 0 (a fog volume: every 8th of the grid's voxels and its
  // tile, 1071 active values): the active values alone are written
  // (GetFilledActiveOnly()), whole and in pieces of more voxels than that
  // which cut the active tile, every point checked against the grid (its
  // inactive voxels, one holding 9, read as 0); a piece of fewer voxels and
  // a downsampled read go voxel by voxel, as before.
  {
    openvdb::FloatGrid::Ptr fog = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    fog->setName("density");
    fog->setTransform(transform);
    for (auto it = grid->cbeginValueOn(); it; ++it)
    {
      const openvdb::Coord c = it.getCoord();
      if (it.isVoxelValue() && (c.x() + c.y() + c.z()) % 8 == 0)
      {
        fog->tree().setValue(c, *it);
      }
    }
    fog->tree().addTile(1, openvdb::Coord(8, 8, -8), 0.75f, true);
    fog->tree().setValueOff(openvdb::Coord(0, 5, 0), 9.0f);
    WriteGrids(dir + "/fog.vdb", { fog });
    vtkNew<vtkOpenVDBImageReader> sparse;
    sparse->AddObserver(vtkCommand::ErrorEvent, observer);
    sparse->SetFileName((dir + "/fog.vdb").c_str());
    auto acc = fog->getConstAccessor();
    auto matches = [&acc](vtkImageData* image)
    {
      int ext[6];
      image->GetExtent(ext);
      vtkDataArray* values = image->GetPointData()->GetScalars();
      vtkIdType bad = values ? 0 : 1;
      for (int k = ext[4]; values && k <= ext[5]; ++k)
      {
        for (int j = ext[2]; j <= ext[3]; ++j)
        {
          for (int i = ext[0]; i <= ext[1]; ++i)
          {
            const openvdb::Coord ijk(i, j, k);
            const float want = acc.isValueOn(ijk) ? acc.getValue(ijk) : 0.0f;
            int p[3] = { i, j, k };
            bad += values->GetComponent(image->ComputePointId(p), 0) == want ? 0 : 1;
          }
        }
      }
      return bad == 0;
    };
    sparse->Update();
    Check(!observer->GetError() && sparse->GetFilledActiveOnly() && matches(sparse->GetOutput()),
      "fog: its active values alone, every point the grid's");
    const double active = double(fog->activeVoxelCount());
    std::cout << "fog: " << active << " active values\n";
    // 26 x 10 x 6 and 15 x 8 x 11 voxels, each across the tile; 4 x 4 x 4.
    const int cuts[3][6] = { { -5, 20, 3, 12, -9, -4 }, { 6, 20, 10, 17, -4, 6 },
      { 0, 3, 4, 7, 0, 3 } };
    for (const int* cut : cuts)
    {
      int sub[6];
      std::copy(cut, cut + 6, sub);
      sparse->Modified();
      sparse->UpdateExtent(sub);
      int got[6];
      sparse->GetOutput()->GetExtent(got);
      const bool large = double(sparse->GetOutput()->GetNumberOfPoints()) >= active;
      Check(std::equal(got, got + 6, sub) && sparse->GetFilledActiveOnly() == large &&
          matches(sparse->GetOutput()),
        large ? "fog: a piece across the tile, its active values alone, every point the grid's"
              : "fog: a piece of fewer voxels than active values, voxel by voxel, every point "
                "the grid's");
    }
    sparse->SetDownsamplingFactor(2);
    sparse->UpdateWholeExtent();
    Check(!observer->GetError() && !sparse->GetFilledActiveOnly(),
      "fog downsampled: every voxel read (the box filter)");
    observer->Clear();
  }

  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
