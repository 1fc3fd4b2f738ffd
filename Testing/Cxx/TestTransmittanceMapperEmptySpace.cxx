// Empty-space skipping (vtkTyndallMajorantGrid and the shaders'
// tyndallSkipEmpty):
// 1. CPU: every block's majorant bounds the extinction at every point the
//    renderers can sample in it (trilinear interpolation of the samples,
//    then the transfer table, as vtkTyndallTransferTable documents), and a
//    block with extinction somewhere is not empty; on the sparse blobs most
//    blocks are empty (else nothing is tested below).
// 2. GPU: with skipping on and off, every method draws the same picture
//    (at most 1/255 apart in any channel) and the maps hold the same
//    coefficients (1e-4 of their largest), on the sparse blobs and the
//    cloud; a light inside the box, a jittered camera and missing data (a
//    NaN voxel) included.
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallMajorantGrid.h"
#include "vtkTyndallTransferTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
using M = vtkTransmittanceVolumeMapper;

// Trilinear interpolation at sample coordinate v (sample i at v = i),
// clamped to the edge samples as the GPU's clamp-to-edge does.
double Trilinear(const float* s, const int dims[3], const double v[3])
{
  int i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = std::min(std::max(v[a], 0.0), dims[a] - 1.0);
    i0[a] = std::min(static_cast<int>(x), dims[a] - 2);
    f[a] = x - i0[a];
  }
  double sum = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    double w = 1.0;
    size_t index = 0;
    size_t stride = 1;
    for (int a = 0; a < 3; ++a)
    {
      const int bit = (c >> a) & 1;
      w *= bit ? f[a] : 1.0 - f[a];
      index += (i0[a] + bit) * stride;
      stride *= dims[a];
    }
    sum += w * s[index];
  }
  return sum;
}

bool CheckMajorants(vtkImageData* data)
{
  int dims[3];
  data->GetDimensions(dims);
  const float* values = static_cast<const float*>(data->GetScalarPointer());
  double range[2];
  data->GetScalarRange(range);
  vtkTyndallTransferTable table;
  std::string error;
  if (!table.Build(tyndall_test::MakeCloudProperty(0.5), nullptr, range[0], range[1], error))
  {
    std::cerr << "FAILED: the table: " << error << std::endl;
    return false;
  }
  vtkTyndallMajorantGrid grid;
  const double rangeTime = grid.BuildRanges(values, 1, nullptr, dims);
  const double majorantTime = grid.BuildMajorants(table);
  std::cout << "Grid " << grid.GetBlockCounts()[0] << "^3 blocks: " << rangeTime << " s ranges, "
            << majorantTime << " s majorants, " << 100.0 * grid.GetEmptyFraction() << " % empty\n";
  bool ok = grid.GetEmptyFraction() > 0.5;
  if (!ok)
  {
    std::cerr << "FAILED: the sparse blobs should leave most blocks empty" << std::endl;
  }
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  const int* counts = grid.GetBlockCounts();
  int violations = 0;
  for (int n = 0; n < 200000 && violations < 5; ++n)
  {
    double v[3];
    for (int a = 0; a < 3; ++a)
    {
      v[a] = random->GetNextRangeValue(-0.5, dims[a] - 0.5);
    }
    int k;
    double f;
    table.Locate(Trilinear(values, dims, v), k, f);
    const double sigma = table.ExtinctionAt(k, f);
    const size_t block =
      (static_cast<size_t>(grid.BlockOf(2, v[2])) * counts[1] + grid.BlockOf(1, v[1])) * counts[0] +
      grid.BlockOf(0, v[0]);
    const double majorant = grid.GetMajorants()[block];
    if (sigma > majorant * (1.0 + 1e-6) || (sigma > 0.0 && !(majorant > 0.0)))
    {
      std::cerr << "FAILED: extinction " << sigma << " at sample coordinate (" << v[0] << ", "
                << v[1] << ", " << v[2] << ") above its block's majorant " << majorant << std::endl;
      ++violations;
    }
  }
  return ok && violations == 0;
}

double MaxCoefficientDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* ca = a->GetPointData()->GetArray("Coefficients");
  vtkDataArray* cb = b->GetPointData()->GetArray("Coefficients");
  double worst = 0.0, largest = 0.0;
  for (vtkIdType t = 0; t < ca->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < ca->GetNumberOfComponents(); ++c)
    {
      largest = std::max(largest, std::abs(ca->GetComponent(t, c)));
      worst = std::max(worst, std::abs(ca->GetComponent(t, c) - cb->GetComponent(t, c)));
    }
  }
  return worst / std::max(largest, 1e-30);
}

// Skipping on against off on one scene; false on a difference.
bool CompareScene(const char* name, vtkImageData* data, bool lightInside, bool jitter)
{
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetJitter(jitter);
  // Skipping changes the camera and map marches; the transmittance cache (on by
  // default) reads the maps alike either way and is not what this test checks
  // (TestTransmittanceMapperTransmittanceCache and -Reference do): off, the test
  // takes half the time.
  mapper->TransmittanceCacheOff();
  mapper->SetLightSampleCount(96);
  mapper->SetTransmittanceMapSize(96);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tyndall_test::MakeCloudProperty(0.8));
  volume->RotateY(20.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.2, 0.3, 0.45);
  if (lightInside)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetConeAngle(180.0);
    light->SetPosition(0.3, 0.2, 0.1);
    light->SetFocalPoint(0.0, -1.0, 0.0);
    renderer->AddLight(light);
  }
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.6, 0.4));
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(160, 160);
  window->AddRenderer(renderer);
  bool ok = true;
  for (int m = M::NONE; m <= M::ADAPTIVE_ETM; ++m)
  {
    mapper->SetTransmittanceMethod(m);
    vtkSmartPointer<vtkImageData> images[2];
    vtkNew<vtkImageData> maps[2];
    for (int skip = 0; skip < 2; ++skip)
    {
      mapper->SetEmptySpaceSkipping(skip != 0);
      window->Render();
      images[skip] = tyndall_test::Grab(window);
      if (vtkTransmittanceMapMath::IsMapMethod(m) &&
        !mapper->GetTransmittanceMap(lightInside ? 1 : 0, maps[skip]))
      {
        std::cerr << "FAILED: " << name << ": no map to read back" << std::endl;
        return false;
      }
    }
    const int difference = tyndall_test::MaxDifference(images[0], images[1]);
    const double coefficients =
      vtkTransmittanceMapMath::IsMapMethod(m) ? MaxCoefficientDifference(maps[0], maps[1]) : 0.0;
    std::cout << name << ", " << vtkTransmittanceMapMath::GetMethodName(m)
              << ": pixels differ by at most " << difference << "/255, coefficients by "
              << coefficients << " of the largest\n";
    if (difference > 1 || coefficients > 1e-4)
    {
      std::cerr << "FAILED: " << name << ", " << vtkTransmittanceMapMath::GetMethodName(m)
                << ": skipping changed the result" << std::endl;
      ok = false;
    }
  }
  return ok;
}
}

int TestTransmittanceMapperEmptySpace(int, char*[])
{
  bool ok = CheckMajorants(tyndall_test::MakeSparseBlobs(64));
  ok = CompareScene("sparse blobs", tyndall_test::MakeSparseBlobs(64), false, false) && ok;
  ok = CompareScene("cloud, light inside, jitter", tyndall_test::MakeCloud(40), true, true) && ok;
  // Missing data: a NaN voxel in a blob.
  vtkSmartPointer<vtkImageData> holed = tyndall_test::MakeSparseBlobs(48);
  static_cast<float*>(holed->GetScalarPointer(24, 23, 24))[0] = vtkMath::Nan();
  ok = CompareScene("sparse blobs with a NaN voxel", holed, false, false) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
