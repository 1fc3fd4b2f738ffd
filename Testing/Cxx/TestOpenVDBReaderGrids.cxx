// vtkOpenVDBImageReader on grids made here with OpenVDB: grid selection
// (automatic and by name), several grids as arrays of one image (union of
// the index boxes, each padded with its own background), double and vec3
// grids, active tiles, rotated and anisotropic transforms, level sets
// converted to fog, and NaN/Inf values replaced by 0 with a counted warning.
// Expected values come from OpenVDB's API (accessors, indexToWorld) and from
// the closed form of sdfToFogVolume's ramp.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolumeFileReader.h"

#include "TyndallTestOpenVDB.h"

#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <limits>
#include <sstream>

using namespace tyndall_vdb_test;

namespace
{
vtkNew<vtkTest::ErrorObserver> observer;

template <class T>
double Component(const T& v, int)
{
  return static_cast<double>(v);
}
template <class T>
double Component(const openvdb::math::Vec3<T>& v, int c)
{
  return static_cast<double>(v[c]);
}

// Checks every point of `array` against grid values (background where
// inactive), over the image's extent; component c of vector grids.
template <class GridT>
void CheckAgainstGrid(
  vtkImageData* image, const char* arrayName, const GridT& grid, const std::string& what)
{
  vtkDataArray* array = image->GetPointData()->GetArray(arrayName);
  Check(array != nullptr, what + ": array present");
  if (!array)
  {
    return;
  }
  using ValueT = typename GridT::ValueType;
  constexpr int nc = openvdb::VecTraits<ValueT>::Size;
  Check(array->GetNumberOfComponents() == nc, what + ": components");
  int ext[6];
  image->GetExtent(ext);
  auto acc = grid.getConstAccessor();
  vtkIdType id = 0, bad = 0;
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      for (int i = ext[0]; i <= ext[1]; ++i, ++id)
      {
        const openvdb::Coord ijk(i, j, k);
        const ValueT want = acc.isValueOn(ijk) ? acc.getValue(ijk) : grid.background();
        for (int c = 0; c < nc; ++c)
        {
          const double w = Component(want, c);
          bad += (array->GetComponent(id, c) == w) ? 0 : 1;
        }
      }
    }
  }
  Check(bad == 0, what + ": " + std::to_string(bad) + " values differ from the grid's");
}

void CheckGeometry(vtkImageData* image, const openvdb::GridBase& grid, const std::string& what)
{
  int ext[6];
  image->GetExtent(ext);
  for (int k : { ext[4], ext[5] })
  {
    for (int j : { ext[2], ext[3] })
    {
      for (int i : { ext[0], ext[1] })
      {
        double p[3];
        image->TransformIndexToPhysicalPoint(i, j, k, p);
        const openvdb::Vec3d w = grid.indexToWorld(openvdb::Vec3d(i, j, k));
        Check(Near(p[0], w[0], 1e-9) && Near(p[1], w[1], 1e-9) && Near(p[2], w[2], 1e-9),
          what + ": point (i, j, k) lies at OpenVDB's indexToWorld(i, j, k)");
      }
    }
  }
}

vtkImageData* Read(vtkOpenVDBImageReader* reader, const std::string& path,
  std::initializer_list<const char*> names, const std::string& what)
{
  reader->SetFileName(path.c_str());
  reader->RemoveAllGridNames();
  for (const char* name : names)
  {
    reader->AddGridName(name);
  }
  reader->Update();
  Check(!observer->GetError(),
    what + ": no error" + (observer->GetError() ? " (" + observer->GetErrorMessage() + ")" : ""));
  observer->Clear();
  return reader->GetOutput();
}
}

int TestOpenVDBReaderGrids(int argc, char* argv[])
{
  openvdb::initialize();
  const std::string dir = ScratchDir(argc, argv, "TestOpenVDBReaderGrids");
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);

  // Four grids sharing one transform, with different boxes and backgrounds,
  // and a fifth with another transform.
  openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(0.5);
  transform->postTranslate(openvdb::Vec3d(1.0, 2.0, 3.0));
  openvdb::FloatGrid::Ptr density = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
  density->setName("density");
  density->setTransform(transform);
  density->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  density->tree().setValue(openvdb::Coord(4, 5, 6), 2.0f);
  density->tree().addTile(1, openvdb::Coord(8, 8, 8), 0.25f, true); // voxels 8..15
  density->tree().setValueOff(openvdb::Coord(2, 2, 2), 7.0f);       // inactive: read as 0
  openvdb::DoubleGrid::Ptr temperature = tyndall_io::NewGrid<openvdb::DoubleGrid>(300.0);
  temperature->setName("temperature");
  temperature->setTransform(transform);
  temperature->tree().setValue(openvdb::Coord(-3, -2, -1), 400.0);
  temperature->tree().setValue(openvdb::Coord(2, 2, 2), 500.0);
  openvdb::Vec3SGrid::Ptr velocity =
    tyndall_io::NewGrid<openvdb::Vec3SGrid>(openvdb::Vec3s(0.0f, 0.0f, 0.5f));
  velocity->setName("velocity");
  velocity->setTransform(transform);
  velocity->tree().setValue(openvdb::Coord(1, 1, 1), openvdb::Vec3s(1.0f, 2.0f, 3.0f));
  openvdb::Vec3DGrid::Ptr flow = tyndall_io::NewGrid<openvdb::Vec3DGrid>();
  flow->setName("flow");
  flow->setTransform(transform);
  flow->tree().setValue(openvdb::Coord(3, 3, 3), openvdb::Vec3d(-1.0, 0.5, 0.25));
  openvdb::FloatGrid::Ptr other = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
  other->setName("other");
  other->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
  const std::string multi = dir + "/multi.vdb";
  // "density" is not first: the automatic choice must still find it.
  WriteGrids(multi, { temperature, other, density, velocity, flow });

  // vtkVolumeFileReader::ExtraGridName (tyndall-render --emission-array):
  // the automatic choice rendered, the extra grid beside it in one image.
  {
    vtkNew<vtkVolumeFileReader> files;
    files->SetFileName(multi.c_str());
    files->SetExtraGridName("temperature");
    files->Update();
    vtkPointData* data = files->GetOutput()->GetPointData();
    vtkDataArray* scalars = data->GetScalars();
    vtkDataArray* heat = data->GetArray("temperature");
    double range[2] = { 0.0, 0.0 };
    if (heat)
    {
      heat->GetRange(range);
    }
    Check(scalars && scalars->GetName() && std::string(scalars->GetName()) == "density" && heat &&
        range[1] == 500.0,
      "ExtraGridName: density rendered, temperature (up to 500) beside it");
  }

  // Information and the automatic choice.
  reader->SetFileName(multi.c_str());
  reader->UpdateInformation();
  Check(reader->GetNumberOfGrids() == 5, "five grids listed");
  Check(std::string(reader->GetGridName(0)) == "temperature" &&
      std::string(reader->GetGridName(2)) == "density",
    "grids listed in file order");
  Check(std::string(reader->GetGridValueType(0)) == "double" &&
      std::string(reader->GetGridValueType(3)) == "vec3s" &&
      std::string(reader->GetGridValueType(4)) == "vec3d",
    "value types listed");
  Check(reader->GetNumberOfSelectedGrids() == 1 &&
      std::string(reader->GetSelectedGridName(0)) == "density",
    "the automatic choice is the float grid named density");
  int box[6];
  Check(reader->GetGridIndexBoundingBox(2, box) && box[0] == 0 && box[1] == 15 && box[2] == 0 &&
      box[3] == 15 && box[4] == 0 && box[5] == 15,
    "density's index box (voxels and the 8^3 tile)");
  Check(reader->GetGridActiveVoxelCount(2) == 2 + 512, "density's active voxel count");

  vtkImageData* image = Read(reader, multi, {}, "density alone");
  CheckAgainstGrid(image, "density", *density, "density alone");
  Check(reader->GetFilledActiveOnly(), "density (background 0): its active values alone");
  CheckGeometry(image, *density, "density alone");
  Check(image->GetPointData()->GetNumberOfArrays() == 1, "one array");
  Check(image->GetPointData()->GetScalars() &&
      std::string(image->GetPointData()->GetScalars()->GetName()) == "density",
    "density is the active scalars");

  image = Read(reader, multi, { "temperature" }, "temperature");
  Check(image->GetPointData()->GetScalars()->GetDataType() == VTK_DOUBLE, "double grid -> double");
  CheckAgainstGrid(image, "temperature", *temperature, "temperature (background 300)");
  Check(!reader->GetFilledActiveOnly(), "temperature (background 300): every voxel written");

  // Several grids: the union of the boxes, each padded with its background.
  image = Read(reader, multi, { "density", "temperature", "velocity", "flow" }, "four grids");
  int ext[6];
  image->GetExtent(ext);
  Check(
    ext[0] == -3 && ext[1] == 15 && ext[2] == -2 && ext[3] == 15 && ext[4] == -1 && ext[5] == 15,
    "the extent is the union of the grids' boxes");
  Check(image->GetPointData()->GetNumberOfArrays() == 4, "four arrays");
  CheckAgainstGrid(image, "density", *density, "density of four");
  CheckAgainstGrid(image, "temperature", *temperature, "temperature of four");
  CheckAgainstGrid(image, "velocity", *velocity, "velocity of four");
  CheckAgainstGrid(image, "flow", *flow, "flow of four");
  Check(image->GetPointData()->GetArray("velocity")->GetDataType() == VTK_FLOAT &&
      image->GetPointData()->GetArray("flow")->GetDataType() == VTK_DOUBLE,
    "vec3s -> float, vec3d -> double");
  Check(std::string(image->GetPointData()->GetScalars()->GetName()) == "density",
    "the first requested grid is the active scalars");

  // Grids with different transforms cannot share an image.
  reader->SetGridName("density");
  reader->AddGridName("other");
  reader->Update();
  ExpectError(observer, "different transforms", "grids with different transforms");
  Check(IsEmpty(reader->GetOutput()), "different transforms: empty output");

  // Without a "density" grid: the first float grid; without float grids, the
  // first supported one.
  {
    openvdb::FloatGrid::Ptr a = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f),
                            b = openvdb::deepCopyTypedGrid<openvdb::FloatGrid>(*a);
    a->setName("smoke");
    a->tree().setValue(openvdb::Coord(1, 1, 1), 1.0f);
    b->setName("heat");
    b->tree().setValue(openvdb::Coord(2, 2, 2), 1.0f);
    WriteGrids(dir + "/nodensity.vdb", { temperature, a, b });
    reader->SetFileName((dir + "/nodensity.vdb").c_str());
    reader->RemoveAllGridNames();
    reader->UpdateInformation();
    Check(reader->GetNumberOfSelectedGrids() == 1 &&
        std::string(reader->GetSelectedGridName(0)) == "smoke",
      "without density: the first float grid");
    WriteGrids(dir + "/onlydouble.vdb", { velocity, temperature });
    reader->SetFileName((dir + "/onlydouble.vdb").c_str());
    reader->UpdateInformation();
    Check(reader->GetNumberOfSelectedGrids() == 1 &&
        std::string(reader->GetSelectedGridName(0)) == "velocity",
      "without float grids: the first supported grid");
  }

  // A rotated, scaled and translated grid: the direction matrix.
  {
    openvdb::FloatGrid::Ptr rotated = openvdb::deepCopyTypedGrid<openvdb::FloatGrid>(*density);
    const double a = 30.0 * M_PI / 180.0, b = 20.0 * M_PI / 180.0;
    openvdb::Mat4d m = openvdb::Mat4d::identity();
    m.setToRotation(openvdb::math::Z_AXIS, a);
    m.preRotate(openvdb::math::X_AXIS, b);
    m.preScale(openvdb::Vec3d(0.5, 0.75, 2.0));
    m.postTranslate(openvdb::Vec3d(-1.0, 4.0, 0.5));
    rotated->setTransform(openvdb::math::Transform::createLinearTransform(m));
    WriteGrids(dir + "/rotated.vdb", { rotated });
    image = Read(reader, dir + "/rotated.vdb", {}, "rotated grid");
    CheckGeometry(image, *rotated, "rotated grid");
    CheckAgainstGrid(image, "density", *rotated, "rotated grid values");
    vtkMatrix3x3* d = image->GetDirectionMatrix();
    Check(!d->IsIdentity() && std::abs(d->Determinant() - 1.0) < 1e-12,
      "rotation: a proper rotation in the direction matrix");
    double spacing[3];
    image->GetSpacing(spacing);
    Check(
      Near(spacing[0], 0.5, 1e-12) && Near(spacing[1], 0.75, 1e-12) && Near(spacing[2], 2.0, 1e-12),
      "rotation: spacing is the scale along each index axis");
  }

  // Anisotropic axis-aligned scale.
  {
    openvdb::FloatGrid::Ptr scaled = openvdb::deepCopyTypedGrid<openvdb::FloatGrid>(*density);
    openvdb::math::MapBase::Ptr map(new openvdb::math::ScaleTranslateMap(
      openvdb::Vec3d(0.25, 1.0, 3.0), openvdb::Vec3d(5.0, -2.0, 1.0)));
    scaled->setTransform(openvdb::math::Transform::Ptr(new openvdb::math::Transform(map)));
    WriteGrids(dir + "/scaled.vdb", { scaled });
    image = Read(reader, dir + "/scaled.vdb", {}, "anisotropic grid");
    CheckGeometry(image, *scaled, "anisotropic grid");
    Check(image->GetDirectionMatrix()->IsIdentity(), "anisotropic: identity direction");
  }

  // A level set: converted to fog on request. sdfToFogVolume's fog is 0
  // outside (phi > 0), -phi / w inside the band of width w (the level set's
  // background) and 1 deeper inside.
  {
    openvdb::FloatGrid::Ptr sphere =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(4.0f, openvdb::Vec3f(0.0f), 0.5f);
    sphere->setName("surface");
    WriteGrids(dir + "/sphere.vdb", { sphere });
    reader->SetConvertLevelSetToFog(true);
    image = Read(reader, dir + "/sphere.vdb", {}, "level set as fog");
    reader->SetConvertLevelSetToFog(false);
    vtkDataArray* fog = image->GetPointData()->GetScalars();
    Check(fog != nullptr && fog->GetNumberOfTuples() > 0, "level set as fog: values");
    if (fog)
    {
      const float w = sphere->background();
      auto acc = sphere->getConstAccessor();
      image->GetExtent(ext);
      vtkIdType id = 0, bad = 0, inside = 0;
      for (int k = ext[4]; k <= ext[5]; ++k)
      {
        for (int j = ext[2]; j <= ext[3]; ++j)
        {
          for (int i = ext[0]; i <= ext[1]; ++i, ++id)
          {
            // The level set's value; inactive voxels hold +-w (sign = side).
            const float phi = acc.getValue(openvdb::Coord(i, j, k));
            const double want = phi > 0.0f ? 0.0 : (phi <= -w ? 1.0 : -double(phi) / w);
            bad += std::abs(fog->GetComponent(id, 0) - want) <= 1e-6 ? 0 : 1;
            inside += phi <= -w ? 1 : 0;
          }
        }
      }
      Check(bad == 0, "level set as fog: " + std::to_string(bad) + " values off the ramp");
      Check(inside > 0, "level set as fog: a fully inside core exists");
    }
  }

  // NaN and Inf: replaced by 0, counted and reported.
  {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    openvdb::FloatGrid::Ptr bad = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    bad->setName("density");
    auto acc = bad->getAccessor();
    for (int i = 0; i < 10; ++i)
    {
      acc.setValue(openvdb::Coord(i, 0, 0), float(i + 1));
    }
    acc.setValue(openvdb::Coord(1, 0, 0), nan);
    acc.setValue(openvdb::Coord(3, 0, 0), nan);
    acc.setValue(openvdb::Coord(5, 0, 0), nan);
    acc.setValue(openvdb::Coord(7, 0, 0), inf);
    acc.setValue(openvdb::Coord(8, 0, 0), inf);
    acc.setValue(openvdb::Coord(9, 0, 0), -inf);
    WriteGrids(dir + "/nan.vdb", { bad });
    reader->SetFileName((dir + "/nan.vdb").c_str());
    reader->RemoveAllGridNames();
    reader->Update();
    Check(!observer->GetError(), "NaN: no error");
    Check(observer->GetWarning() &&
        observer->GetWarningMessage().find("Replaced 6 NaN or infinite") != std::string::npos,
      "NaN: a warning with the count (6)");
    observer->Clear();
    Check(reader->GetNumberOfNonFiniteValues() == 6 && reader->GetFilledActiveOnly(),
      "NaN: GetNumberOfNonFiniteValues() is 6 (the active values alone written)");
    vtkDataArray* values = reader->GetOutput()->GetPointData()->GetScalars();
    const double want[10] = { 1, 0, 3, 0, 5, 0, 7, 0, 0, 0 };
    bool ok = values && values->GetNumberOfTuples() == 10;
    for (int i = 0; ok && i < 10; ++i)
    {
      ok = values->GetComponent(i, 0) == want[i];
    }
    Check(ok, "NaN: non-finite values read as 0, the others unchanged");

    // A NaN background: every inactive voxel of the box counts.
    openvdb::FloatGrid::Ptr nanBackground = tyndall_io::NewGrid<openvdb::FloatGrid>(nan);
    nanBackground->setName("density");
    nanBackground->tree().setValue(openvdb::Coord(0, 0, 0), 1.0f);
    nanBackground->tree().setValue(openvdb::Coord(3, 3, 3), 2.0f);
    WriteGrids(dir + "/nanbackground.vdb", { nanBackground });
    reader->SetFileName((dir + "/nanbackground.vdb").c_str());
    reader->Update();
    Check(reader->GetNumberOfNonFiniteValues() == 64 - 2, "NaN background: 62 voxels replaced");
    Check(observer->GetWarning(), "NaN background: a warning");
    observer->Clear();
    double sum, mn, mx;
    ArrayStats(reader->GetOutput()->GetPointData()->GetScalars(), 0, sum, mn, mx);
    Check(sum == 3.0 && mn == 0.0 && mx == 2.0, "NaN background: zeros and the two values");
  }

  // PrintSelf lists the settings and the file's grids.
  std::ostringstream printed;
  reader->Print(printed);
  Check(printed.str().find("DownsamplingFactor: 1") != std::string::npos &&
      printed.str().find("MemoryLimit: 4096 MiB") != std::string::npos &&
      printed.str().find("'density'") != std::string::npos,
    "PrintSelf shows the settings and the grids");

  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
