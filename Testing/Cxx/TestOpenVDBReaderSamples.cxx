// vtkOpenVDBImageReader on the real samples of ../shared/data/vdb: grid
// information, extent, geometry, every voxel value, value ranges and sums
// against OpenVDB's own API (computed here, independently of the reader,
// with OpenVDB's value iterators), plus the sizes vdb_print -l reports.
// Skips (exit code 125) when the samples are absent.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPointData.h"

#include "TyndallTestOpenVDB.h"

#include <openvdb/io/File.h>

#include <cstdint>

using namespace tyndall_vdb_test;

namespace
{
// What `vdb_print -l` reports for the samples (dimensions of the active
// voxels and the number of active voxels), as a cross-check of OpenVDB's
// numbers below.
struct Printed
{
  const char* File;
  int Dims[3];
  int64_t ActiveVoxels;
};
const Printed kPrinted[] = {
  { "fog_small.vdb", { 21, 36, 7 }, 818 },
  { "smoke.vdb", { 111, 222, 112 }, 1049275 },
  { "torus.vdb", { 31, 11, 31 }, 4808 },
  { "wdas_cloud_sixteenth.vdb", { 126, 86, 154 }, 415642 },
};

void CheckSample(const Printed& printed, const std::string& path)
{
  const std::string tag = std::string(printed.File) + ": ";
  // OpenVDB's view of the file.
  openvdb::io::File file(path);
  file.open(false);
  openvdb::GridPtrVecPtr metadata = file.readAllGridMetadata();
  std::string gridName;
  for (const auto& g : *metadata)
  {
    if (g->isType<openvdb::FloatGrid>() && gridName.empty())
    {
      gridName = g->getName();
    }
  }
  openvdb::FloatGrid::Ptr grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(gridName));
  file.close();
  Check(grid != nullptr, tag + "OpenVDB reads a float grid");
  if (!grid)
  {
    return;
  }
  const DenseStats expected = ComputeDenseStats(*grid);
  const openvdb::Coord dim = expected.BBox.dim();

  // vdb_print's numbers agree with OpenVDB's API.
  Check(dim[0] == printed.Dims[0] && dim[1] == printed.Dims[1] && dim[2] == printed.Dims[2],
    tag + "active dimensions as vdb_print reports");
  Check(int64_t(grid->activeVoxelCount()) == printed.ActiveVoxels,
    tag + "active voxel count as vdb_print reports");

  // Information without reading voxels.
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  Check(reader->GetNumberOfGrids() == int(metadata->size()), tag + "number of grids");
  for (int i = 0; i < reader->GetNumberOfGrids() && i < int(metadata->size()); ++i)
  {
    Check(
      (*metadata)[i]->getName() == reader->GetGridName(i), tag + "grid name " + std::to_string(i));
    Check((*metadata)[i]->valueType() == reader->GetGridValueType(i), tag + "value type");
    Check(openvdb::GridBase::gridClassToString((*metadata)[i]->getGridClass()) ==
        reader->GetGridClass(i),
      tag + "grid class");
  }
  const int index = reader->GetGridIndex(gridName.c_str());
  Check(index >= 0, tag + "GetGridIndex finds the grid");
  Check(reader->GetNumberOfSelectedGrids() == 1 && gridName == reader->GetSelectedGridName(0),
    tag + "the automatic choice is the float grid");
  int box[6];
  Check(reader->GetGridIndexBoundingBox(index, box), tag + "bounding box known");
  for (int c = 0; c < 3; ++c)
  {
    Check(box[2 * c] == expected.BBox.min()[c] && box[2 * c + 1] == expected.BBox.max()[c],
      tag + "bounding box axis " + std::to_string(c));
  }
  Check(reader->GetGridActiveVoxelCount(index) == int64_t(expected.Active),
    tag + "active voxel count from the metadata");
  Check(std::string(reader->GetGridClass(index)) == "fog volume", tag + "fog volume class");

  // The image.
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int ext[6];
  image->GetExtent(ext);
  for (int c = 0; c < 3; ++c)
  {
    Check(ext[2 * c] == expected.BBox.min()[c] && ext[2 * c + 1] == expected.BBox.max()[c],
      tag + "extent is the index box, axis " + std::to_string(c));
  }
  const openvdb::Vec3d voxelSize = grid->voxelSize();
  double spacing[3];
  image->GetSpacing(spacing);
  for (int c = 0; c < 3; ++c)
  {
    Check(Near(spacing[c], voxelSize[c], 1e-12), tag + "spacing is the voxel size");
  }
  // World positions of a few voxels: image points are voxel centres.
  const openvdb::Coord corners[3] = { expected.BBox.min(), expected.BBox.max(),
    openvdb::Coord((expected.BBox.min().asVec3i() + expected.BBox.max().asVec3i()) / 2) };
  for (const openvdb::Coord& ijk : corners)
  {
    double p[3];
    image->TransformIndexToPhysicalPoint(ijk[0], ijk[1], ijk[2], p);
    const openvdb::Vec3d w = grid->indexToWorld(ijk);
    Check(Near(p[0], w[0], 1e-9) && Near(p[1], w[1], 1e-9) && Near(p[2], w[2], 1e-9),
      tag + "point (i, j, k) is the world position of voxel (i, j, k)");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  Check(scalars != nullptr && scalars->GetDataType() == VTK_FLOAT &&
      scalars->GetNumberOfComponents() == 1 && gridName == scalars->GetName(),
    tag + "one float array named after the grid");
  if (!scalars)
  {
    return;
  }
  Check(scalars->GetNumberOfTuples() == vtkIdType(expected.BBox.volume()),
    tag + "one value per voxel of the box");
  double sum, mn, mx;
  ArrayStats(scalars, 0, sum, mn, mx);
  std::cout << tag << "sum " << sum << " (OpenVDB " << expected.Sum << "), range [" << mn << ", "
            << mx << "] (OpenVDB [" << expected.Min << ", " << expected.Max << "])" << std::endl;
  Check(Near(sum, expected.Sum, 1e-9), tag + "voxel sum");
  Check(mn == expected.Min && mx == expected.Max, tag + "value range");

  // Every voxel: the active value, or the background.
  auto acc = grid->getConstAccessor();
  vtkIdType mismatches = 0;
  const float* values = static_cast<float*>(scalars->GetVoidPointer(0));
  vtkIdType id = 0;
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      for (int i = ext[0]; i <= ext[1]; ++i, ++id)
      {
        const openvdb::Coord ijk(i, j, k);
        const float want = acc.isValueOn(ijk) ? acc.getValue(ijk) : grid->background();
        mismatches += (values[id] == want) ? 0 : 1;
      }
    }
  }
  Check(mismatches == 0, tag + std::to_string(mismatches) + " voxels differ from OpenVDB's");
  Check(reader->GetNumberOfNonFiniteValues() == 0, tag + "no non-finite values");
}
}

int TestOpenVDBReaderSamples(int, char*[])
{
  openvdb::initialize();
  int found = 0;
  for (const Printed& p : kPrinted)
  {
    const std::string path = SharedVDB(p.File);
    if (path.empty())
    {
      std::cout << "sample " << p.File << " not found; not checked" << std::endl;
      continue;
    }
    ++found;
    CheckSample(p, path);
  }
  if (found == 0)
  {
    std::cout << "Skipping: no OpenVDB samples in ../shared/data/vdb (TYNDALL_SHARED_DATA)."
              << std::endl;
    return 125;
  }
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
