// Sparse volumes on the GPU (issue 37): the scalars stored as the bricks
// that vary (vtkTransmittanceVolumeBricks), one shared slot per constant
// value, an indirection texel per brick.
//
// 1. The layout on the CPU: Plan() finds the bricks whose samples and +1
//    apron hold one value (counted here independently), gives each
//    constant one slot, and declines when the bricks would not save the
//    share asked; MapCoordinate() (the CPU twin of the shaders'
//    tyndallBrickedTexel()): trilinear and nearest samples of the atlas
//    equal the volume's at any coordinate, brick seams and faces included.
// 2. The mapper (70 x 54 x 61, sides that are no multiple of 8) with
//    bricking off against on and automatic: 8-bit data shaded with the
//    maps' shadows, floats read nearest, the maximum intensity projection,
//    and the sparse volume as another volume's guest (its shadow on it).
//    Each within 60 dB of the dense picture; the bricks take under half
//    the dense texture's bytes; one mapper switched off and on again.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeBricks.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestSampling.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

constexpr int NX = 70, NY = 54, NZ = 61;
constexpr int B = vtkTransmittanceVolumeBricks::BrickSize;

// Two soft balls in an empty box (0) and a slab of one value (90): two
// constants, and bricks that vary around the balls and the slab's faces.
double Value(int i, int j, int k)
{
  const double r1 =
    std::sqrt((i - 20.0) * (i - 20.0) + (j - 25.0) * (j - 25.0) + (k - 30.0) * (k - 30.0));
  const double r2 =
    std::sqrt((i - 48.0) * (i - 48.0) + (j - 30.0) * (j - 30.0) + (k - 24.0) * (k - 24.0));
  double v = 250.0 * std::max(0.0, 1.0 - r1 / 11.0) + 200.0 * std::max(0.0, 1.0 - r2 / 8.0);
  if (k >= 45 && k <= 56 && i < 40)
  {
    v = 90.0;
  }
  return std::floor(std::min(v, 250.0));
}

void CheckLayout()
{
  const int dims[3] = { NX, NY, NZ };
  std::vector<double> values(static_cast<size_t>(NX) * NY * NZ);
  for (int k = 0, n = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i, ++n)
      {
        values[n] = Value(i, j, k);
      }
    }
  }
  // The bricks that vary, counted here: samples b B .. b B + B (clamped).
  int counts[3], varying = 0;
  for (int a = 0; a < 3; ++a)
  {
    counts[a] = (dims[a] - 1 + B - 1) / B;
  }
  for (int bz = 0; bz < counts[2]; ++bz)
  {
    for (int by = 0; by < counts[1]; ++by)
    {
      for (int bx = 0; bx < counts[0]; ++bx)
      {
        double lo = 1e30, hi = -1e30;
        for (int k = bz * B; k <= std::min(bz * B + B, NZ - 1); ++k)
        {
          for (int j = by * B; j <= std::min(by * B + B, NY - 1); ++j)
          {
            for (int i = bx * B; i <= std::min(bx * B + B, NX - 1); ++i)
            {
              const double v = values[(static_cast<size_t>(k) * NY + j) * NX + i];
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
          }
        }
        varying += lo < hi ? 1 : 0;
      }
    }
  }
  vtkTransmittanceVolumeBricks bricks;
  Check(bricks.Plan(dims, 1, sizeof(double), values.data(), 2048, 1.0) && bricks.IsBricked(),
    "a sparse volume: bricked");
  const int* nb = bricks.GetBrickCounts();
  std::cout << "bricks " << nb[0] << " x " << nb[1] << " x " << nb[2] << ", " << varying
            << " vary, " << bricks.GetSlots() << " slots; atlas " << bricks.GetAtlasBytes()
            << " + indirection " << bricks.GetIndirectionBytes() << " bytes against "
            << bricks.GetDenseBytes() << " dense\n";
  Check(nb[0] == counts[0] && nb[1] == counts[1] && nb[2] == counts[2],
    "bricks per axis: ceil((n - 1) / 8)");
  Check(bricks.GetSlots() == varying + 2, "a slot per brick that varies, one per constant (0, 90)");
  Check(bricks.GetAtlasBytes() + bricks.GetIndirectionBytes() < bricks.GetDenseBytes() / 2,
    "the bricks take under half the dense bytes");
  vtkTransmittanceVolumeBricks declined;
  Check(!declined.Plan(dims, 1, sizeof(double), values.data(), 2048, 0.01) && !declined.IsBricked(),
    "declined where it would not save the share asked");
  std::vector<unsigned char> bytes;
  Check(bricks.BuildAtlas(values.data(), bytes), "the atlas built");
  std::vector<double> atlas(bytes.size() / sizeof(double));
  std::memcpy(atlas.data(), bytes.data(), bytes.size());
  const int* size = bricks.GetAtlasDimensions();
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  double worst[2] = { 0.0, 0.0 };
  for (int n = 0; n < 40000; ++n)
  {
    double t[3];
    for (int a = 0; a < 3; ++a)
    {
      random->Next();
      t[a] = random->GetRangeValue(-0.05, 1.05);
      if (n % 3 == 0)
      {
        // On and about a brick seam (sample b B, +- a little).
        random->Next();
        const int b = 1 + static_cast<int>(random->GetValue() * (nb[a] - 1));
        random->Next();
        t[a] = (b * B + random->GetRangeValue(-1.0, 1.0) + 0.5) / dims[a];
      }
    }
    double texel[3];
    bricks.MapCoordinate(t, texel);
    for (int nearest = 0; nearest < 2; ++nearest)
    {
      worst[nearest] = std::max(worst[nearest],
        std::abs(tyndall_test::TextureSample(values, dims, t, nearest) -
          tyndall_test::TextureSample(atlas, size, texel, nearest)));
    }
  }
  std::cout << "atlas against the volume: largest difference " << worst[0] << " (linear), "
            << worst[1] << " (nearest)\n";
  Check(worst[0] < 1.0e-9 && worst[1] == 0.0,
    "the atlas samples as the volume (MapCoordinate()), linear and nearest");
}

vtkSmartPointer<vtkImageData> Volume(int type)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->AllocateScalars(type, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int k = 0, n = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i, ++n)
      {
        scalars->SetTuple1(n, Value(i, j, k));
      }
    }
  }
  return image;
}

void SetFunctions(vtkVolumeProperty* property, bool shade, bool nearest)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.2, 0.3, 0.9);
  color->AddRGBPoint(90.0, 0.3, 0.9, 0.4);
  color->AddRGBPoint(250.0, 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(20.0, 0.0);
  opacity->AddPoint(250.0, 0.6);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationType(nearest ? VTK_NEAREST_INTERPOLATION : VTK_LINEAR_INTERPOLATION);
  property->SetShade(shade);
}
}

int TestTransmittanceMapperBricks(int, char*[])
{
  CheckLayout();

  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(90.0, 80.0, 60.0);
  light->SetFocalPoint(35.0, 27.0, 30.0);
  light->SetPositional(false);
  renderer->AddLight(light);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkTest::ErrorObserver> errors;
  renderer->GetActiveCamera()->SetFocalPoint(35.0, 27.0, 30.0);
  renderer->GetActiveCamera()->SetPosition(120.0, -60.0, 90.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera(-20.0, NX + 5.0, -25.0, NY - 1.0, 0.0, NZ - 1.0);

  // The same scene with bricking off, on and automatic (the default).
  auto compare = [&](const std::string& what, vtkImageData* data, int blend)
  {
    const int modes[3] = { vtkTransmittanceVolumeMapper::BRICKING_OFF,
      vtkTransmittanceVolumeMapper::BRICKING_ON, vtkTransmittanceVolumeMapper::BRICKING_AUTO };
    vtkSmartPointer<vtkImageData> pictures[3];
    vtkIdType bytes[3] = { 0, 0, 0 };
    for (int m = 0; m < 3; ++m)
    {
      vtkNew<vtkTransmittanceVolumeMapper> mapper;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->SetInputData(data);
      mapper->SetBlendMode(blend);
      mapper->SetTransmittanceMethodToETM();
      mapper->JitterOff();
      mapper->SetVolumeBricking(modes[m]);
      volume->SetMapper(mapper);
      window->Render();
      pictures[m] = tyndall_test::Grab(window);
      bytes[m] = mapper->GetVolumeTextureBytes();
      Check(mapper->GetVolumeBricked() == (m > 0), what + (m > 0 ? ": bricked" : ": dense"));
      volume->SetMapper(nullptr);
    }
    const double on = tyndall_test::PSNR(pictures[1], pictures[0]);
    const double automatic = tyndall_test::PSNR(pictures[2], pictures[0]);
    std::cout << what << ": bricked against dense " << on << " dB (on), " << automatic
              << " dB (automatic); " << bytes[2] << " bytes against " << bytes[0] << "\n";
    Check(on >= 60.0 && automatic >= 60.0, what + ": the bricks draw the dense picture");
    Check(bytes[2] > 0 && 2 * bytes[2] < bytes[0], what + ": under half the dense bytes");
    Check(!errors->GetError(), what + ": no error");
    errors->Clear();
  };

  SetFunctions(property, true, false);
  vtkSmartPointer<vtkImageData> bytes = Volume(VTK_UNSIGNED_CHAR);
  compare("8-bit, shaded, ETM shadows", bytes, vtkVolumeMapper::COMPOSITE_BLEND);
  SetFunctions(property, false, true);
  vtkSmartPointer<vtkImageData> floats = Volume(VTK_FLOAT);
  compare("floats, nearest", floats, vtkVolumeMapper::COMPOSITE_BLEND);
  SetFunctions(property, false, false);
  compare("floats, maximum intensity", floats, vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);

  // The sparse volume as another volume's guest: a dense cloud beside it,
  // in its shadow (both lit through the maps).
  {
    SetFunctions(property, false, false);
    auto cloud = vtkSmartPointer<vtkImageData>::New();
    cloud->SetDimensions(16, 16, 16);
    cloud->SetOrigin(4.0, -22.0, 12.0);
    cloud->AllocateScalars(VTK_FLOAT, 1);
    auto* c = static_cast<float*>(cloud->GetScalarPointer());
    for (int n = 0; n < 16 * 16 * 16; ++n)
    {
      c[n] = static_cast<float>(120.0 + 100.0 * std::sin(0.7 * n)); // varies everywhere: dense
    }
    vtkNew<vtkVolumeProperty> cloudProperty;
    SetFunctions(cloudProperty, false, false);
    vtkNew<vtkVolume> other;
    other->SetProperty(cloudProperty);
    renderer->AddVolume(other);
    vtkSmartPointer<vtkImageData> pictures[2];
    for (int bricked = 0; bricked < 2; ++bricked)
    {
      vtkNew<vtkTransmittanceVolumeMapper> mapper, cloudMapper;
      for (vtkTransmittanceVolumeMapper* m : { mapper.Get(), cloudMapper.Get() })
      {
        m->AddObserver(vtkCommand::ErrorEvent, errors);
        m->SetTransmittanceMethodToETM();
        m->JitterOff();
        m->SetVolumeBricking(bricked ? vtkTransmittanceVolumeMapper::BRICKING_AUTO
                                     : vtkTransmittanceVolumeMapper::BRICKING_OFF);
      }
      mapper->SetInputData(floats);
      cloudMapper->SetInputData(cloud);
      volume->SetMapper(mapper);
      other->SetMapper(cloudMapper);
      window->Render();
      pictures[bricked] = tyndall_test::Grab(window);
      Check(mapper->GetVolumeBricked() == (bricked == 1) && !cloudMapper->GetVolumeBricked(),
        "a guest: the sparse volume bricked, the cloud dense");
      volume->SetMapper(nullptr);
      other->SetMapper(nullptr);
    }
    renderer->RemoveVolume(other);
    const double psnr = tyndall_test::PSNR(pictures[1], pictures[0]);
    std::cout << "a bricked guest: " << psnr << " dB from the dense picture\n";
    Check(psnr >= 60.0 && !errors->GetError(), "a bricked guest: the dense picture");
    errors->Clear();
  }

  // One mapper switched off, automatic, off: uploaded again each time.
  {
    SetFunctions(property, true, false);
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    mapper->SetInputData(bytes);
    mapper->SetTransmittanceMethodToETM();
    mapper->JitterOff();
    volume->SetMapper(mapper);
    vtkSmartPointer<vtkImageData> pictures[3];
    const int modes[3] = { vtkTransmittanceVolumeMapper::BRICKING_OFF,
      vtkTransmittanceVolumeMapper::BRICKING_AUTO, vtkTransmittanceVolumeMapper::BRICKING_OFF };
    for (int i = 0; i < 3; ++i)
    {
      mapper->SetVolumeBricking(modes[i]);
      window->Render();
      pictures[i] = tyndall_test::Grab(window);
      Check(mapper->GetVolumeBricked() == (i == 1), "one mapper: bricked when automatic");
    }
    const double psnr = std::min(
      tyndall_test::PSNR(pictures[1], pictures[0]), tyndall_test::PSNR(pictures[2], pictures[0]));
    std::cout << "one mapper switched: " << psnr << " dB\n";
    Check(psnr >= 60.0, "one mapper switched: the same picture");
    volume->SetMapper(nullptr);
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
