// vtkOpenVDBImageWriter on generated data: write -> read round trips are
// exact for float input (to float precision for other types, to half
// precision with SaveFloatAsHalf), values with |v| <= Tolerance come back as
// 0, geometry (origin, anisotropic spacing, direction) is preserved, the
// file is a sparse fog volume as OpenVDB sees it, non-finite input is
// skipped with a counted warning, and bad input is refused with an error.
#include "vtkCosineNoiseSource.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkOpenVDBImageWriter.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include "TyndallTestOpenVDB.h"

#include <cmath>
#include <limits>
#include <sstream>

using namespace tyndall_vdb_test;

namespace
{
vtkNew<vtkTest::ErrorObserver> observer;

// Reads `path` back and compares it with `original`: every point of the
// original must read back as float(v), or 0 when |v| <= tolerance (or
// non-finite); points outside the read-back extent must be such zeros.
// `halfPrecision` allows half-float rounding.
void CheckRoundTrip(vtkImageData* original, const std::string& path, double tolerance,
  const std::string& tag, bool halfPrecision = false)
{
  vtkNew<vtkOpenVDBImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->SetFileName(path.c_str());
  reader->Update();
  Check(!observer->GetError(), tag + ": reads back");
  observer->Clear();
  vtkImageData* back = reader->GetOutput();
  vtkDataArray* in = original->GetPointData()->GetScalars();
  vtkDataArray* out = back->GetPointData()->GetScalars();
  if (!out)
  {
    Check(false, tag + ": scalars read back");
    return;
  }
  int ext[6], backExt[6];
  original->GetExtent(ext);
  back->GetExtent(backExt);
  vtkIdType bad = 0, badPosition = 0;
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      for (int i = ext[0]; i <= ext[1]; ++i)
      {
        int ijk[3] = { i, j, k };
        const double v = in->GetComponent(original->ComputePointId(ijk), 0);
        const bool dropped = !std::isfinite(v) || std::abs(v) <= tolerance;
        const double want = dropped ? 0.0 : double(static_cast<float>(v));
        const bool inside = i >= backExt[0] && i <= backExt[1] && j >= backExt[2] &&
          j <= backExt[3] && k >= backExt[4] && k <= backExt[5];
        const double got = inside ? out->GetComponent(back->ComputePointId(ijk), 0) : 0.0;
        // Half floats: 11 significant bits (relative rounding error 2^-11),
        // subnormal spacing 2^-24 (absolute rounding error 2^-25).
        const bool ok = halfPrecision
          ? std::abs(got - want) <= std::abs(want) * std::ldexp(1.0, -11) + std::ldexp(1.0, -25)
          : got == want;
        bad += ok ? 0 : 1;
        if (inside && (i == ext[0] || i == ext[1]))
        {
          double p[3], q[3];
          original->TransformIndexToPhysicalPoint(i, j, k, p);
          back->TransformIndexToPhysicalPoint(i, j, k, q);
          badPosition +=
            (Near(p[0], q[0], 1e-12) && Near(p[1], q[1], 1e-12) && Near(p[2], q[2], 1e-12)) ? 0 : 1;
        }
      }
    }
  }
  Check(bad == 0, tag + ": " + std::to_string(bad) + " values differ after the round trip");
  Check(badPosition == 0, tag + ": " + std::to_string(badPosition) + " points moved");
}

bool Write(vtkOpenVDBImageWriter* writer, vtkImageData* image, const std::string& path)
{
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  const int ok = writer->Write();
  const bool clean = ok == 1 && !observer->GetError();
  if (!clean)
  {
    std::cerr << "write failed: " << observer->GetErrorMessage() << std::endl;
  }
  observer->Clear();
  return clean;
}

vtkIdType CountAbove(vtkDataArray* a, double tolerance)
{
  vtkIdType n = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    const double v = a->GetComponent(i, 0);
    n += (std::isfinite(v) && std::abs(v) > tolerance) ? 1 : 0;
  }
  return n;
}

template <class ArrayT>
vtkSmartPointer<vtkImageData> MakeImage(const int ext[6], double (*f)(int, int, int))
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(const_cast<int*>(ext));
  image->SetOrigin(0.5, -1.0, 2.0);
  image->SetSpacing(0.1, 0.1, 0.1);
  vtkNew<ArrayT> values;
  values->SetName("values");
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  vtkIdType id = 0;
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      for (int i = ext[0]; i <= ext[1]; ++i, ++id)
      {
        values->SetComponent(id, 0, f(i, j, k));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}
}

int TestOpenVDBWriterRoundTrip(int argc, char* argv[])
{
  openvdb::initialize();
  const std::string dir = ScratchDir(argc, argv, "TestOpenVDBWriterRoundTrip");
  vtkNew<vtkOpenVDBImageWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->AddObserver(vtkCommand::WarningEvent, observer);

  // A cosine-noise cloud on an offset extent with anisotropic spacing.
  vtkNew<vtkCosineNoiseSource> cloud;
  cloud->SetWholeExtent(10, 73, -5, 58, 0, 47);
  cloud->SetOrigin(-1.3, -0.9, -0.7);
  cloud->SetSpacing(0.03, 0.02, 0.04);
  cloud->SetEnvelopeCenter(0.2, 0.1, 0.5);
  cloud->Update();
  vtkImageData* noise = cloud->GetOutput();
  double range[2];
  noise->GetPointData()->GetScalars()->GetRange(range);
  std::cout << "cloud range [" << range[0] << ", " << range[1] << "]" << std::endl;
  Check(range[1] > 1.0 &&
      CountAbove(noise->GetPointData()->GetScalars(), 0.0) < noise->GetNumberOfPoints(),
    "the cloud has dense and empty parts");

  for (double tolerance : { 0.0, 0.5 })
  {
    const std::string tag = "cloud, tolerance " + std::to_string(tolerance);
    const std::string path = dir + "/cloud.vdb";
    writer->SetTolerance(tolerance);
    Check(Write(writer, noise, path), tag + ": writes");
    CheckRoundTrip(noise, path, tolerance, tag);
    // OpenVDB's view of the file: a sparse fog volume named density.
    openvdb::FloatGrid::Ptr grid =
      openvdb::gridPtrCast<openvdb::FloatGrid>(ReadGrid(path, "density"));
    Check(grid != nullptr, tag + ": OpenVDB reads a float grid named density");
    if (grid)
    {
      Check(grid->getGridClass() == openvdb::GRID_FOG_VOLUME && grid->background() == 0.0f,
        tag + ": fog volume, background 0");
      const vtkIdType active = CountAbove(noise->GetPointData()->GetScalars(), tolerance);
      Check(vtkIdType(grid->activeVoxelCount()) == active &&
          writer->GetNumberOfActiveVoxels() == active,
        tag + ": one active voxel per value above the tolerance");
      const openvdb::Vec3d w = grid->indexToWorld(openvdb::Coord(10, -5, 0));
      double p[3];
      noise->TransformIndexToPhysicalPoint(10, -5, 0, p);
      Check(Near(w[0], p[0], 1e-12) && Near(w[1], p[1], 1e-12) && Near(w[2], p[2], 1e-12),
        tag + ": OpenVDB places voxel (i, j, k) at image point (i, j, k)");
    }
  }
  writer->SetTolerance(0.0);

  // Signed values (ClampNegative off): the tolerance applies to |v|.
  cloud->ClampNegativeOff();
  cloud->Update();
  writer->SetTolerance(1.0);
  Check(Write(writer, cloud->GetOutput(), dir + "/signed.vdb"), "signed cloud writes");
  CheckRoundTrip(cloud->GetOutput(), dir + "/signed.vdb", 1.0, "signed cloud, tolerance 1");
  writer->SetTolerance(0.0);

  // Other scalar types.
  const int ext[6] = { -3, 12, 0, 9, 4, 11 };
  auto uchar = MakeImage<vtkUnsignedCharArray>(
    ext, [](int i, int j, int k) { return double(((i + 3) * 37 + j * 11 + k * 5) % 256); });
  Check(Write(writer, uchar, dir + "/uchar.vdb"), "unsigned char writes");
  CheckRoundTrip(uchar, dir + "/uchar.vdb", 0.0, "unsigned char");
  auto shorts = MakeImage<vtkShortArray>(
    ext, [](int i, int j, int k) { return double((i * 997 + j * 31 - k * 1013) % 30000); });
  Check(Write(writer, shorts, dir + "/short.vdb"), "short writes");
  CheckRoundTrip(shorts, dir + "/short.vdb", 0.0, "short");
  auto doubles = MakeImage<vtkDoubleArray>(
    ext, [](int i, int j, int k) { return std::sin(0.3 * i) * std::cos(0.2 * j + 0.1 * k) * 1e3; });
  Check(Write(writer, doubles, dir + "/double.vdb"), "double writes");
  CheckRoundTrip(doubles, dir + "/double.vdb", 0.0, "double (to float precision)");

  // A direction matrix.
  {
    auto rotated = MakeImage<vtkFloatArray>(
      ext, [](int i, int j, int k) { return 1.0 + 0.01 * (i * i + j - k); });
    double axis[3] = { 1.0, 2.0, 0.5 };
    vtkMath::Normalize(axis);
    const double angle = 0.7, c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    const double x = axis[0], y = axis[1], z = axis[2];
    rotated->SetDirectionMatrix(t * x * x + c, t * x * y - s * z, t * x * z + s * y,
      t * x * y + s * z, t * y * y + c, t * y * z - s * x, t * x * z - s * y, t * y * z + s * x,
      t * z * z + c);
    rotated->SetSpacing(0.2, 0.3, 0.5);
    Check(Write(writer, rotated, dir + "/rotated.vdb"), "rotated image writes");
    CheckRoundTrip(rotated, dir + "/rotated.vdb", 0.0, "rotated image");
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->SetFileName((dir + "/rotated.vdb").c_str());
    reader->Update();
    vtkMatrix3x3* a = rotated->GetDirectionMatrix();
    vtkMatrix3x3* b = reader->GetOutput()->GetDirectionMatrix();
    double diff = 0.0;
    for (int r = 0; r < 3; ++r)
    {
      for (int col = 0; col < 3; ++col)
      {
        diff = std::max(diff, std::abs(a->GetElement(r, col) - b->GetElement(r, col)));
      }
    }
    Check(diff < 1e-12, "rotated image: direction matrix preserved");
  }

  // Half precision.
  writer->SaveFloatAsHalfOn();
  Check(Write(writer, noise, dir + "/half.vdb"), "half-precision writes");
  CheckRoundTrip(noise, dir + "/half.vdb", 0.0, "half precision", true);
  writer->SaveFloatAsHalfOff();

  // Non-finite input: skipped, counted, reported; they read back as 0.
  {
    auto finite = MakeImage<vtkFloatArray>(ext, [](int i, int, int) { return 2.0 + i; });
    vtkDataArray* values = finite->GetPointData()->GetScalars();
    values->SetComponent(3, 0, std::numeric_limits<double>::quiet_NaN());
    values->SetComponent(50, 0, std::numeric_limits<double>::infinity());
    values->SetComponent(77, 0, -std::numeric_limits<double>::infinity());
    writer->SetInputData(finite);
    writer->SetFileName((dir + "/nonfinite.vdb").c_str());
    Check(writer->Write() == 1, "non-finite input: still writes");
    Check(observer->GetWarning() &&
        observer->GetWarningMessage().find("Skipped 3 NaN") != std::string::npos,
      "non-finite input: a warning with the count");
    observer->Clear();
    Check(writer->GetNumberOfNonFiniteValues() == 3, "non-finite input: counted");
    CheckRoundTrip(finite, dir + "/nonfinite.vdb", 0.0, "non-finite input");
  }

  // Bad input.
  auto expectFailure = [&](vtkImageData* image, const std::string& path, const std::string& text,
                         const std::string& what)
  {
    writer->SetInputData(image);
    writer->SetFileName(path.empty() ? nullptr : path.c_str());
    Check(writer->Write() == 0, what + ": Write() returns 0");
    ExpectError(observer, text, what);
  };
  expectFailure(uchar, "", "No FileName", "no file name");
  expectFailure(uchar, "/nonexistent-directory/x.vdb", "Cannot write", "an unwritable path");
  writer->SetGridName("");
  expectFailure(uchar, dir + "/x.vdb", "GridName", "an empty grid name");
  writer->SetGridName("density");
  vtkNew<vtkImageData> noScalars;
  noScalars->SetExtent(0, 3, 0, 3, 0, 3);
  expectFailure(noScalars, dir + "/x.vdb", "no point scalars", "no scalars");
  vtkNew<vtkImageData> empty;
  expectFailure(empty, dir + "/x.vdb", "empty", "an empty image");
  {
    vtkNew<vtkImageData> vectors;
    vectors->SetExtent(0, 3, 0, 3, 0, 3);
    vtkNew<vtkFloatArray> v;
    v->SetNumberOfComponents(3);
    v->SetNumberOfTuples(64);
    v->Fill(1.0);
    vectors->GetPointData()->SetScalars(v);
    expectFailure(vectors, dir + "/x.vdb", "3 components", "three-component scalars");
  }
  {
    auto negative = MakeImage<vtkFloatArray>(ext, [](int, int, int) { return 1.0; });
    negative->SetSpacing(0.1, -0.1, 0.1);
    expectFailure(negative, dir + "/x.vdb", "spacing must be positive", "a negative spacing");
  }

  // The writer's grid name is the reader's array name.
  writer->SetGridName("temperature");
  Check(Write(writer, uchar, dir + "/named.vdb"), "a named grid writes");
  vtkNew<vtkOpenVDBImageReader> named;
  named->SetFileName((dir + "/named.vdb").c_str());
  named->UpdateInformation();
  Check(named->GetNumberOfGrids() == 1 && std::string(named->GetGridName(0)) == "temperature" &&
      std::string(named->GetGridClass(0)) == "fog volume",
    "the grid is named by GridName");

  std::ostringstream printed;
  writer->Print(printed);
  Check(printed.str().find("GridName: temperature") != std::string::npos &&
      printed.str().find("Tolerance: 0") != std::string::npos,
    "PrintSelf shows the settings");

  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
