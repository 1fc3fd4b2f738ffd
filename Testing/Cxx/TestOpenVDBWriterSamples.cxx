// vtkOpenVDBImageWriter on the real samples of ../shared/data/vdb: read ->
// write -> read gives back every value exactly (the writer's tolerance is
// 0, so only exact zeros become inactive and they read back as 0) on the
// same points. Skips (exit code 125) when the samples are absent.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenVDBImageReader.h"
#include "vtkOpenVDBImageWriter.h"
#include "vtkPointData.h"

#include "TyndallTestOpenVDB.h"

using namespace tyndall_vdb_test;

int TestOpenVDBWriterSamples(int argc, char* argv[])
{
  openvdb::initialize();
  const std::string dir = ScratchDir(argc, argv, "TestOpenVDBWriterSamples");
  int found = 0;
  for (const char* sample :
    { "fog_small.vdb", "smoke.vdb", "torus.vdb", "wdas_cloud_sixteenth.vdb" })
  {
    const std::string path = SharedVDB(sample);
    if (path.empty())
    {
      std::cout << "sample " << sample << " not found; not checked" << std::endl;
      continue;
    }
    ++found;
    const std::string tag = sample;
    vtkNew<vtkOpenVDBImageReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkImageData* first = reader->GetOutput();
    Check(first->GetNumberOfPoints() > 0, tag + ": reads");

    const std::string copy = dir + "/" + sample;
    vtkNew<vtkOpenVDBImageWriter> writer;
    writer->SetInputData(first);
    writer->SetFileName(copy.c_str());
    writer->SetGridName(reader->GetSelectedGridName(0));
    Check(writer->Write() == 1, tag + ": writes");

    vtkNew<vtkOpenVDBImageReader> again;
    again->SetFileName(copy.c_str());
    again->Update();
    vtkImageData* second = again->GetOutput();
    vtkDataArray* a = first->GetPointData()->GetScalars();
    vtkDataArray* b = second->GetPointData()->GetScalars();
    Check(a && b && std::string(a->GetName()) == b->GetName(), tag + ": same array name");
    if (!a || !b)
    {
      continue;
    }
    int ext[6], ext2[6];
    first->GetExtent(ext);
    second->GetExtent(ext2);
    vtkIdType bad = 0, nonZero = 0;
    double sum1 = 0.0, sum2 = 0.0;
    for (int k = ext[4]; k <= ext[5]; ++k)
    {
      for (int j = ext[2]; j <= ext[3]; ++j)
      {
        for (int i = ext[0]; i <= ext[1]; ++i)
        {
          int ijk[3] = { i, j, k };
          const double v = a->GetComponent(first->ComputePointId(ijk), 0);
          const bool inside = i >= ext2[0] && i <= ext2[1] && j >= ext2[2] && j <= ext2[3] &&
            k >= ext2[4] && k <= ext2[5];
          const double w = inside ? b->GetComponent(second->ComputePointId(ijk), 0) : 0.0;
          bad += (v == w) ? 0 : 1;
          nonZero += v != 0.0 ? 1 : 0;
          sum1 += v;
          sum2 += w;
        }
      }
    }
    std::cout << tag << ": " << nonZero << " non-zero voxels, sums " << sum1 << " / " << sum2
              << std::endl;
    Check(bad == 0, tag + ": " + std::to_string(bad) + " values changed in the round trip");
    Check(writer->GetNumberOfActiveVoxels() == nonZero, tag + ": one active voxel per non-zero");
    double o1[3], o2[3], s1[3], s2[3];
    first->GetOrigin(o1);
    second->GetOrigin(o2);
    first->GetSpacing(s1);
    second->GetSpacing(s2);
    for (int c = 0; c < 3; ++c)
    {
      Check(Near(o1[c], o2[c], 1e-12) && Near(s1[c], s2[c], 1e-12),
        tag + ": origin and spacing preserved");
    }
  }
  if (found == 0)
  {
    std::cout << "Skipping: no OpenVDB samples in ../shared/data/vdb (TYNDALL_SHARED_DATA)."
              << std::endl;
    return 125;
  }
  return Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
