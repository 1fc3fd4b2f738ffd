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
//    Also: slots in rows and layers (a small texture size), at most 256
//    along an axis (the 8-bit indirection), more constant
//    values than shared slots, volumes of one brick, the share at which a
//    plan is declined.
// 2. The mapper (70 x 57 x 61: n - 1 a multiple of 8 or not) with bricking
//    off against on, automatic and automatic at a texture size of 72 (8
//    slots a side): 8- and 16-bit data shaded with the maps' shadows, floats
//    read nearest, the maximum intensity projection, two independent
//    components, and the sparse volume as the guest of a cloud beside it
//    (its shadow on it; the cloud's mapper builds the maps the two share
//    through the guest's bricks: read as dense, 35.3 dB). Each within 60 dB of the dense picture,
//    with something drawn; the bricks take under half the dense texture's bytes; one mapper
//    switched off and on again.
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

constexpr int NX = 70, NY = 57, NZ = 61; // (57 - 1: a multiple of 8)
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

// Plans `values` (dims) at `maximumSize` and `share`, builds the atlas and
// holds 40,000 linear and nearest samples of it (MapCoordinate(), the CPU
// twin of the shaders' tyndallBrickedTexel()) to the volume's, a third of
// them about brick seams; false when the plan declined.
bool CheckAtlas(const std::string& what, const std::vector<double>& values, const int dims[3],
  int maximumSize, double share, vtkTransmittanceVolumeBricks& bricks)
{
  if (!bricks.Plan(dims, 1, sizeof(double), values.data(), maximumSize, share))
  {
    return false;
  }
  std::vector<unsigned char> bytes;
  Check(bricks.BuildAtlas(values.data(), bytes), what + ": the atlas built");
  std::vector<double> atlas(bytes.size() / sizeof(double));
  std::memcpy(atlas.data(), bytes.data(), bytes.size());
  const int* size = bricks.GetAtlasDimensions();
  const int* nb = bricks.GetBrickCounts();
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
      if (n % 3 == 0 && nb[a] > 1)
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
  const int* slots = bricks.GetSlotCounts();
  std::cout << what << ": " << bricks.GetSlots() << " slots in " << slots[0] << " x " << slots[1]
            << " x " << slots[2] << "; the atlas against the volume: largest difference "
            << worst[0] << " (linear), " << worst[1] << " (nearest)\n";
  Check(worst[0] < 1.0e-9 && worst[1] == 0.0,
    what + ": the atlas samples as the volume (MapCoordinate()), linear and nearest");
  return true;
}

// `dims` samples of value(i, j, k).
std::vector<double> Fill(const int dims[3], double (*value)(int, int, int))
{
  std::vector<double> values(static_cast<size_t>(dims[0]) * dims[1] * dims[2]);
  for (int k = 0, n = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i, ++n)
      {
        values[n] = value(i, j, k);
      }
    }
  }
  return values;
}

// Along x, 48 bricks: the even ones of one value each (1 .. 12, twice
// over: more values than get a shared slot), the odd ones a ramp from the
// value before to the value after (so each even brick's apron holds its
// own value).
double Strip(int i, int, int)
{
  const auto constant = [](int brick) { return 1.0 + (brick / 2) % 12; };
  const int brick = std::min(i / B, 47);
  if (brick % 2 == 0)
  {
    return constant(brick);
  }
  const double f = (i - brick * B) / static_cast<double>(B);
  return (1.0 - f) * constant(brick - 1) + f * constant(brick + 1);
}

void CheckLayout()
{
  const int dims[3] = { NX, NY, NZ };
  const std::vector<double> values = Fill(dims, Value);
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
  Check(CheckAtlas("the sparse volume", values, dims, 2048, 1.0, bricks) && bricks.IsBricked(),
    "a sparse volume: bricked");
  const int* nb = bricks.GetBrickCounts();
  std::cout << "bricks " << nb[0] << " x " << nb[1] << " x " << nb[2] << ", " << varying
            << " vary; atlas " << bricks.GetAtlasBytes() << " + indirection "
            << bricks.GetIndirectionBytes() << " bytes against " << bricks.GetDenseBytes()
            << " dense\n";
  Check(nb[0] == counts[0] && nb[1] == counts[1] && nb[2] == counts[2],
    "bricks per axis: ceil((n - 1) / 8)");
  Check(bricks.GetSlots() == varying + 2, "a slot per brick that varies, one per constant (0, 90)");
  const double ratio = static_cast<double>(bricks.GetAtlasBytes() + bricks.GetIndirectionBytes()) /
    bricks.GetDenseBytes();
  Check(ratio < 0.5, "the bricks take under half the dense bytes");
  vtkTransmittanceVolumeBricks other;
  Check(!other.Plan(dims, 1, sizeof(double), values.data(), 2048, 0.99 * ratio) &&
      !other.IsBricked() && other.Plan(dims, 1, sizeof(double), values.data(), 2048, 1.01 * ratio),
    "declined just below the share the bricks take, taken just above");
  // Rows and layers of slots (at most 5 per axis here).
  Check(CheckAtlas("5 slots a side", values, dims, 45, 1.0, other) &&
      other.GetSlotCounts()[1] > 1 && other.GetSlotCounts()[2] > 1 &&
      other.GetSlotCounts()[0] <= 5 && other.GetSlotCounts()[2] <= 5,
    "slots in rows and layers");
  Check(!other.Plan(dims, 1, sizeof(double), values.data(), 36, 1.0),
    "more slots than the texture size holds: declined");
  // At most 256 slots along an axis (the 8-bit indirection), whatever the
  // texture size: 300 bricks that vary in a row take two rows of slots.
  const int row[3] = { 300 * B + 1, 9, 9 };
  std::vector<double> wave(static_cast<size_t>(row[0]) * row[1] * row[2]);
  for (size_t n = 0; n < wave.size(); ++n)
  {
    wave[n] = std::sin(0.37 * n);
  }
  Check(CheckAtlas("300 bricks in a row", wave, row, 16384, 1.0e9, other) &&
      other.GetSlots() == 300 &&
      other.GetSlotCounts()[0] == vtkTransmittanceVolumeBricks::MaximumSlotsPerAxis &&
      other.GetSlotCounts()[1] == 2 && other.GetSlotCounts()[2] == 1,
    "at most 256 slots along an axis (a texture size of 16384)");
  // More constant values than shared slots: the first 8 values share a
  // slot each, the other 4 values' bricks have their own.
  const int strip[3] = { 48 * B + 1, 9, 9 };
  Check(CheckAtlas("12 constants", Fill(strip, Strip), strip, 2048, 1.0, other) &&
      other.GetSlots() == 24 + 8 + 8,
    "12 constants: 8 shared slots, the rest their own (40 slots)");
  // The smallest volumes (one brick, its apron past the end repeated).
  const int tiny[2][3] = { { 2, 1, 9 }, { 1, 1, 1 } };
  for (const auto& d : tiny)
  {
    std::vector<double> small(static_cast<size_t>(d[0]) * d[1] * d[2]);
    for (size_t n = 0; n < small.size(); ++n)
    {
      small[n] = std::sin(1.7 * n);
    }
    Check(CheckAtlas("tiny", small, d, 2048, 1.0e9, other) && other.GetSlots() == 1,
      "a volume of one brick");
  }
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
  // (The fourth: automatic with a texture size of 72, 8 slots a side: the
  // slots in rows and layers.)
  auto compare = [&](const std::string& what, vtkImageData* data, int blend)
  {
    const int modes[4] = { vtkTransmittanceVolumeMapper::BRICKING_OFF,
      vtkTransmittanceVolumeMapper::BRICKING_ON, vtkTransmittanceVolumeMapper::BRICKING_AUTO,
      vtkTransmittanceVolumeMapper::BRICKING_AUTO };
    vtkSmartPointer<vtkImageData> pictures[4];
    vtkIdType bytes[4] = { 0, 0, 0, 0 };
    for (int m = 0; m < 4; ++m)
    {
      vtkNew<vtkTransmittanceVolumeMapper> mapper;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->SetInputData(data);
      mapper->SetBlendMode(blend);
      mapper->SetTransmittanceMethodToETM();
      mapper->JitterOff();
      mapper->SetVolumeBricking(modes[m]);
      mapper->SetMaximumTextureSize(m == 3 ? 72 : 0);
      volume->SetMapper(mapper);
      window->Render();
      pictures[m] = tyndall_test::Grab(window);
      bytes[m] = mapper->GetVolumeTextureBytes();
      Check(mapper->GetVolumeBricked() == (m > 0), what + (m > 0 ? ": bricked" : ": dense"));
      volume->SetMapper(nullptr);
    }
    const double on = tyndall_test::PSNR(pictures[1], pictures[0]);
    const double automatic = tyndall_test::PSNR(pictures[2], pictures[0]);
    const double layers = tyndall_test::PSNR(pictures[3], pictures[0]);
    const int drawn = tyndall_test::CountDrawn(pictures[0], renderer->GetBackground());
    std::cout << what << ": bricked against dense " << on << " dB (on), " << automatic
              << " dB (automatic), " << layers << " dB (8 slots a side); " << bytes[2]
              << " bytes against " << bytes[0] << "; " << drawn << " pixels drawn\n";
    Check(on >= 60.0 && automatic >= 60.0 && layers >= 60.0,
      what + ": the bricks draw the dense picture");
    Check(bytes[2] > 0 && 2 * bytes[2] < bytes[0], what + ": under half the dense bytes");
    Check(drawn > 300, what + ": a picture");
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
  SetFunctions(property, true, false);
  compare("16-bit, shaded", Volume(VTK_UNSIGNED_SHORT), vtkVolumeMapper::COMPOSITE_BLEND);
  // Two independent components (the second half the first): tuples of two
  // compared, an atlas of two channels.
  {
    SetFunctions(property, false, false);
    property->SetColor(1, property->GetRGBTransferFunction(0));
    property->SetScalarOpacity(1, property->GetScalarOpacity(0));
    auto two = vtkSmartPointer<vtkImageData>::New();
    two->SetDimensions(NX, NY, NZ);
    two->AllocateScalars(VTK_FLOAT, 2);
    auto* v = static_cast<float*>(two->GetScalarPointer());
    const auto* f = static_cast<const float*>(floats->GetScalarPointer());
    for (vtkIdType n = 0; n < floats->GetNumberOfPoints(); ++n)
    {
      v[2 * n] = f[n];
      v[2 * n + 1] = 0.5f * f[n];
    }
    compare("two independent components", two, vtkVolumeMapper::COMPOSITE_BLEND);
    property->IndependentComponentsOn();
  }

  // The sparse volume as another volume's guest: a dense cloud beside its
  // box in the first ball's shadow (the light's ray to the cloud's middle
  // crosses the ball's middle; both lit through the maps).
  {
    SetFunctions(property, true, false); // (shaded: lit, so shadowed)
    auto cloud = vtkSmartPointer<vtkImageData>::New();
    cloud->SetDimensions(16, 16, 16);
    cloud->SetOrigin(-18.0, -12.0, 6.0);
    cloud->AllocateScalars(VTK_FLOAT, 1);
    auto* c = static_cast<float*>(cloud->GetScalarPointer());
    for (int n = 0; n < 16 * 16 * 16; ++n)
    {
      c[n] = static_cast<float>(120.0 + 100.0 * std::sin(0.7 * n)); // varies everywhere: dense
    }
    vtkNew<vtkVolumeProperty> cloudProperty;
    SetFunctions(cloudProperty, true, false);
    vtkNew<vtkVolume> other;
    other->SetProperty(cloudProperty);
    // The cloud first: its mapper builds the maps the two share, through
    // its guest's bricks.
    renderer->RemoveVolume(volume);
    renderer->AddVolume(other);
    renderer->AddVolume(volume);
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
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
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
    Check(psnr >= 60.0 && !errors->GetError(), "one mapper switched: the same picture, no error");
    volume->SetMapper(nullptr);
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
