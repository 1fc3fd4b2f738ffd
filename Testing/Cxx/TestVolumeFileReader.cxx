// vtkVolumeFileReader: one small volume written in every format VTK and
// Tyndall can write (VTK XML, MetaImage, NIfTI, legacy VTK, OpenVDB) reads
// back with the same values, an extent starting at 0 (world positions kept)
// and its format in the field data; multi-component scalars need a
// component; bad paths and files give one error line starting with the path
// and an empty output; the shared sample volumes (when present) read with
// the format their extension names.
#include "TyndallTestCheck.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageWriter.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkStructuredPointsWriter.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolumeFileReader.h"
#include "vtkXMLImageDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

// A 6 x 5 x 4 image, extent starting at (2, 1, 0), values 10 i + j - k.
vtkSmartPointer<vtkImageData> MakeImage(int components = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(2, 7, 1, 5, 0, 3);
  image->SetSpacing(0.5, 0.25, 1.0);
  image->SetOrigin(1.0, -2.0, 0.5);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(6 * 5 * 4);
  for (int k = 0, n = 0; k < 4; ++k)
  {
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 6; ++i, ++n)
      {
        for (int c = 0; c < components; ++c)
        {
          values->SetComponent(n, c, 10.0 * i + j - k + 100.0 * c);
        }
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

std::string Format(vtkImageData* image)
{
  auto* array =
    vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("TyndallFormat"));
  return array && array->GetNumberOfValues() ? array->GetValue(0) : "";
}

// Reads `path` and checks it against MakeImage() (component `component`).
void CheckRead(
  const std::string& path, const std::string& format, bool keepsOrigin, int component = -1)
{
  vtkNew<vtkVolumeFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->SetComponent(component);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Check(!errors->GetError(), format + ": no error (" + errors->GetErrorMessage() + ")");
  Check(Format(image) == format && reader->GetFormatName() == format, format + ": the format");
  const int* extent = image->GetExtent();
  Check(extent[0] == 0 && extent[1] == 5 && extent[2] == 0 && extent[3] == 4 && extent[4] == 0 &&
      extent[5] == 3,
    format + ": 6 x 5 x 4 points, extent from 0");
  double first[3];
  image->TransformIndexToPhysicalPoint(0, 0, 0, first);
  // The first point of MakeImage() is at origin + spacing * (2, 1, 0).
  Check(!keepsOrigin ||
      (std::abs(first[0] - 2.0) < 1e-6 && std::abs(first[1] + 1.75) < 1e-6 &&
        std::abs(first[2] - 0.5) < 1e-6),
    format + ": the first point keeps its world position");
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  bool same =
    scalars && scalars->GetNumberOfComponents() == 1 && scalars->GetNumberOfTuples() == 120;
  const double offset = component > 0 ? 100.0 * component : 0.0;
  for (int k = 0, n = 0; same && k < 4; ++k)
  {
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 6; ++i, ++n)
      {
        same = same && std::abs(scalars->GetComponent(n, 0) - (10.0 * i + j - k + offset)) < 1e-5;
      }
    }
  }
  Check(same, format + ": the values");
}

void CheckError(const std::string& path, const std::string& text, const std::string& what,
  const char* grid = nullptr, int component = -1);

// The largest |value - (scale * (10 i + j - k + offset) + shift)| over the
// points of a 6 x 5 x 4 image read like MakeImage(); infinity if the image
// is not one.
double Deviation(vtkImageData* image, double scale, double shift, double offset)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetNumberOfComponents() != 1 || scalars->GetNumberOfTuples() != 120)
  {
    return HUGE_VAL;
  }
  double worst = 0.0;
  for (int k = 0, n = 0; k < 4; ++k)
  {
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 6; ++i, ++n)
      {
        const double expected = scale * (10.0 * i + j - k + offset) + shift;
        worst = std::max(worst, std::abs(scalars->GetComponent(n, 0) - expected));
      }
    }
  }
  return worst;
}

// Reading `path` with frame `frame` fails with `text`.
void CheckFrameError(const std::string& path, int frame, const std::string& text)
{
  vtkNew<vtkVolumeFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->SetFrame(frame);
  reader->Update();
  Check(errors->GetErrorMessage().find(text) != std::string::npos &&
      reader->GetOutput()->GetNumberOfPoints() == 0,
    "frame " + std::to_string(frame) + " of " + path + ": '" + errors->GetErrorMessage() + "'");
}

// NIfTI: scl_slope / scl_inter applied (or not), the frames of a 4-D file.
void CheckNifti(const std::string& dir)
{
  {
    vtkNew<vtkNIFTIImageWriter> w;
    w->SetInputData(MakeImage());
    w->SetRescaleSlope(2.0);
    w->SetRescaleIntercept(-10.0);
    w->SetFileName((dir + "/scaled.nii").c_str());
    w->Write();
    vtkNew<vtkNIFTIImageWriter> w4;
    w4->SetInputData(MakeImage(3));
    w4->SetTimeDimension(3);
    w4->SetFileName((dir + "/frames.nii.gz").c_str());
    w4->Write();
  }
  vtkNew<vtkVolumeFileReader> reader;
  reader->SetFileName((dir + "/scaled.nii").c_str());
  reader->Update();
  Check(Deviation(reader->GetOutput(), 2.0, -10.0, 0.0) < 1e-5 &&
      reader->GetOutput()->GetPointData()->GetScalars()->GetDataType() == VTK_FLOAT,
    "NIfTI: scl_slope 2 and scl_inter -10 applied, as float");
  Check(std::string(reader->GetNotes()).find("value = stored x 2 + -10") != std::string::npos,
    "NIfTI: the scaling is noted");
  reader->RescaleOff();
  reader->Update();
  Check(Deviation(reader->GetOutput(), 1.0, 0.0, 0.0) < 1e-5 && !*reader->GetNotes(),
    "NIfTI: RescaleOff keeps the stored values");

  reader->SetFileName((dir + "/frames.nii.gz").c_str());
  reader->Update();
  Check(Deviation(reader->GetOutput(), 1.0, 0.0, 0.0) < 1e-5 &&
      std::string(reader->GetNotes()) == "frame 0 of 3 of a 4-D file (--frame N picks another)",
    "NIfTI 4-D: frame 0 by default, noted");
  reader->SetFrame(2);
  reader->Update();
  Check(Deviation(reader->GetOutput(), 1.0, 0.0, 200.0) < 1e-5, "NIfTI 4-D: frame 2");
  CheckFrameError(dir + "/frames.nii.gz", 3, "frame 3 requested, but the file has 3 frames");
  CheckFrameError(dir + "/scaled.nii", 1, "frame 1 requested, but the file has 1 frame");
}

// NIfTI placement: a qform (or sform) turning the image 90 degrees about z
// and moving it to (10, 20, 30) in RAS comes out in the LPS frame of the
// other formats: with MakeImage()'s spacing (0.5, 0.25, 1), RAS x = 10 -
// 0.25 j, y = 20 + 0.5 i, z = 30 + k (worked out by hand), so index
// (i, j, k) is at LPS (-10 + 0.25 j, -20 - 0.5 i, 30 + k).
void CheckNiftiPlacement(const std::string& dir)
{
  for (const char* form : { "qform", "sform" })
  {
    vtkNew<vtkMatrix4x4> m;
    const double rows[3][4] = { { 0, -1, 0, 10 }, { 1, 0, 0, 20 }, { 0, 0, 1, 30 } };
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        m->SetElement(r, c, rows[r][c]);
      }
    }
    auto image = MakeImage();
    image->SetOrigin(0.0, 0.0, 0.0);
    image->SetExtent(0, 5, 0, 4, 0, 3);
    vtkNew<vtkNIFTIImageWriter> w;
    w->SetInputData(image);
    std::string(form) == "qform" ? w->SetQFormMatrix(m) : w->SetSFormMatrix(m);
    const std::string path = dir + "/placed-" + form + ".nii";
    w->SetFileName(path.c_str());
    w->Write();
    vtkNew<vtkVolumeFileReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    double worst = 0.0;
    for (int k : { 0, 3 })
    {
      for (int j : { 0, 4 })
      {
        for (int i : { 0, 5 })
        {
          double p[3];
          reader->GetOutput()->TransformIndexToPhysicalPoint(i, j, k, p);
          const double expected[3] = { -10.0 + 0.25 * j, -20.0 - 0.5 * i, 30.0 + k };
          for (int a = 0; a < 3; ++a)
          {
            worst = std::max(worst, std::abs(p[a] - expected[a]));
          }
        }
      }
    }
    Check(worst < 1e-5 && Deviation(reader->GetOutput(), 1.0, 0.0, 0.0) < 1e-5,
      std::string("NIfTI ") + form + ": placed in the LPS frame (worst " + std::to_string(worst) +
        ")");
  }
}

// Header claims checked before reading: size against the memory limit and
// against the file.
void CheckClaims(const std::string& dir)
{
  std::ofstream(dir + "/huge.mhd") << "ObjectType = Image\nNDims = 3\nDimSize = 2000 2000 2000\n"
                                      "ElementType = MET_UCHAR\nElementDataFile = huge.raw\n";
  std::ofstream(dir + "/huge.raw") << std::string(1000, 'x');
  CheckError(dir + "/huge.mhd", "8000000000 bytes (7.45 GiB), above the memory limit of 4096 MiB",
    "a header above the memory limit");
  vtkNew<vtkVolumeFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName((dir + "/huge.mhd").c_str());
  reader->SetMemoryLimit(10000.0);
  reader->Update();
  Check(errors->GetErrorMessage().find("truncated: the header claims 8000000000 bytes") !=
        std::string::npos &&
      errors->GetErrorMessage().find("which holds 1000 bytes") != std::string::npos,
    "within a larger memory limit, the short raw file is refused (" + errors->GetErrorMessage() +
      ")");
}

// Reading `path` fails with an error containing `text`, and an empty output.
void CheckError(const std::string& path, const std::string& text, const std::string& what,
  const char* grid, int component)
{
  vtkNew<vtkVolumeFileReader> reader;
  vtkNew<vtkTest::ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->SetGridName(grid);
  reader->SetComponent(component);
  reader->Update();
  const bool ok = errors->GetError() && errors->GetErrorMessage().find(text) != std::string::npos &&
    reader->GetOutput()->GetNumberOfPoints() == 0;
  if (!ok)
  {
    std::cerr << what << ": expected an error with '" << text << "', got '"
              << errors->GetErrorMessage() << "'" << std::endl;
  }
  Check(ok, what);
}

// Pieces of a parallel pipeline: piece p of 3 is a part of the extent with
// the whole image's values there, and the pieces cover the whole extent.
void CheckPieces(const std::string& path)
{
  vtkNew<vtkVolumeFileReader> whole;
  whole->SetFileName(path.c_str());
  whole->Update();
  vtkImageData* all = whole->GetOutput();
  int wholeExtent[6];
  all->GetExtent(wholeExtent);
  vtkIdType covered = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    vtkNew<vtkVolumeFileReader> reader;
    reader->SetFileName(path.c_str());
    reader->UpdatePiece(piece, 3, 0);
    vtkImageData* part = reader->GetOutput();
    int e[6];
    part->GetExtent(e);
    bool inside = true;
    for (int a = 0; a < 3; ++a)
    {
      inside = inside && e[2 * a] >= wholeExtent[2 * a] && e[2 * a + 1] <= wholeExtent[2 * a + 1];
    }
    Check(inside && part->GetNumberOfPoints() < all->GetNumberOfPoints(),
      "piece " + std::to_string(piece) + " of 3 is a part of the extent");
    bool same = part->GetPointData()->GetScalars() != nullptr;
    for (int k = e[4]; same && k <= e[5]; ++k)
    {
      for (int j = e[2]; same && j <= e[3]; ++j)
      {
        for (int i = e[0]; same && i <= e[1]; ++i)
        {
          same = part->GetScalarComponentAsDouble(i, j, k, 0) ==
            all->GetScalarComponentAsDouble(i, j, k, 0);
        }
      }
    }
    Check(same, "piece " + std::to_string(piece) + " holds the whole image's values");
    covered += (e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1);
  }
  // Pieces split by points share their boundary planes: they cover at least
  // every point.
  Check(covered >= all->GetNumberOfPoints(), "the pieces cover the whole extent");
}
}

int TestVolumeFileReader(int, char*[])
{
  const std::string dir = "TestVolumeFileReader";
  vtksys::SystemTools::MakeDirectory(dir);
  auto image = MakeImage();
  {
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(image);
    w->SetFileName((dir + "/volume.vti").c_str());
    w->Write();
  }
  {
    vtkNew<vtkMetaImageWriter> w;
    w->SetInputData(image);
    w->SetFileName((dir + "/volume.mhd").c_str());
    w->Write();
  }
  {
    vtkNew<vtkNIFTIImageWriter> w;
    w->SetInputData(image);
    w->SetFileName((dir + "/volume.nii.gz").c_str());
    w->Write();
  }
  {
    vtkNew<vtkStructuredPointsWriter> w;
    w->SetInputData(image);
    w->SetFileName((dir + "/volume.vtk").c_str());
    w->Write();
  }
  {
    vtkNew<vtkOpenVDBImageWriter> w;
    w->SetInputData(image);
    w->SetFileName((dir + "/volume.vdb").c_str());
    w->Write();
  }
  CheckRead(dir + "/volume.vti", "VTK XML", true);
  CheckRead(dir + "/volume.mhd", "MetaImage", false);
  CheckRead(dir + "/volume.nii.gz", "NIfTI", false);
  CheckRead(dir + "/volume.vtk", "VTK legacy", false);
  CheckRead(dir + "/volume.vdb", "OpenVDB", false);

  // Multi-component scalars: refused, or one component kept.
  {
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(MakeImage(3));
    w->SetFileName((dir + "/rgb.vti").c_str());
    w->Write();
  }
  CheckError(dir + "/rgb.vti", "have 3 components; choose one", "three components refused");
  CheckRead(dir + "/rgb.vti", "VTK XML", true, 2);
  CheckError(dir + "/rgb.vti", "component 3 requested", "a component out of range", nullptr, 3);
  {
    // Kept whole for a volume mapper's components (AllComponents): 2 to 4.
    vtkNew<vtkVolumeFileReader> reader;
    reader->SetFileName((dir + "/rgb.vti").c_str());
    reader->AllComponentsOn();
    reader->Update();
    vtkDataArray* scalars = reader->GetOutput()->GetPointData()->GetScalars();
    Check(scalars && scalars->GetNumberOfComponents() == 3, "AllComponents keeps 3 components");
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(MakeImage(5));
    w->SetFileName((dir + "/five.vti").c_str());
    w->Write();
    vtkNew<vtkTest::ErrorObserver> errors;
    vtkNew<vtkVolumeFileReader> five;
    five->AddObserver(vtkCommand::ErrorEvent, errors);
    five->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
    five->SetFileName((dir + "/five.vti").c_str());
    five->AllComponentsOn();
    five->Update();
    Check(errors->GetError() &&
        errors->GetErrorMessage().find("5 components; at most 4 are drawn together") !=
          std::string::npos,
      "AllComponents refuses 5 components (" + errors->GetErrorMessage() + ")");
  }

  // Bad paths and files.
  CheckError(dir + "/absent.vti", "absent.vti: no such file", "a missing file");
  CheckError("", "no input path", "no path");
  std::ofstream(dir + "/notes.txt") << "hello\n";
  CheckError(
    dir + "/notes.txt", "unknown volume format (extension '.txt')", "an unknown extension");
  std::ofstream(dir + "/fake.vti") << "not xml\n";
  CheckError(dir + "/fake.vti", "fake.vti: not a VTK XML file", "a file not of its format");
  std::ofstream(dir + "/fake.mhd") << "garbage\n";
  CheckError(dir + "/fake.mhd", "fake.mhd: ", "a bad MetaImage header");
  CheckError(dir + "/volume.vti", "only meaningful for .vdb", "a grid name for a .vti", "density");
  CheckError(dir, "none of the directory's", "a directory without DICOM files");
  {
    auto flat = vtkSmartPointer<vtkImageData>::New();
    flat->SetDimensions(6, 5, 1);
    flat->AllocateScalars(VTK_FLOAT, 1);
    flat->GetPointData()->GetScalars()->Fill(1.0);
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(flat);
    w->SetFileName((dir + "/flat.vti").c_str());
    w->Write();
  }
  CheckError(dir + "/flat.vti", "at least 2 points along each axis", "a flat image");

  CheckPieces(dir + "/volume.vti");
  CheckNifti(dir);
  CheckNiftiPlacement(dir);
  CheckClaims(dir);

  // The shared samples, when present.
  const std::string shared = TYNDALL_SHARED_DATA;
  const struct
  {
    const char* File;
    const char* Format;
  } samples[] = { { "/volumes/HeadMRVolume.mhd", "MetaImage" },
    { "/volumes/headsq/quarter.nhdr", "NRRD" }, { "/volumes/neghip.slc", "SLC" },
    { "/volumes/ironProt.vtk", "VTK legacy" }, { "/vdb/smoke.vdb", "OpenVDB" } };
  for (const auto& sample : samples)
  {
    const std::string path = shared + sample.File;
    if (!vtksys::SystemTools::FileExists(path))
    {
      std::cout << "skipped (absent): " << path << std::endl;
      continue;
    }
    vtkNew<vtkVolumeFileReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    Check(reader->GetOutput()->GetNumberOfPoints() > 1000 &&
        Format(reader->GetOutput()) == sample.Format,
      std::string(sample.File) + " reads as " + sample.Format);
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
