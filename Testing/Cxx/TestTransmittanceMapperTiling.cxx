// Volumes past one texture (issue 37): a volume whose slices pass the GPU's
// 3-D texture size is stored as tiles of slices side by side in one texture
// (vtkTransmittanceVolumeTiling), every sample kept.
//
// 1. The layout on the CPU: Plan()'s tiles for a 512 x 512 x 3000 CT and
//    the cases it refuses, and MapCoordinate() (the CPU twin of the
//    shaders' tyndallTiledTexel()): trilinear samples of the tiled layout,
//    clamped to the edge as the GPU does, equal the volume's at any
//    coordinate, the tiles' seams and the volume's faces included.
// 2. The mapper with a small MaximumTextureSize that tiles a 20 x 18 x 131
//    volume (3 tiles in a 40 x 36 x 45 texture, the last one short) against the same mapper
//    drawing it from one texture: 8-bit data shaded with the maps' shadows
//    (uploaded from the data's memory), floats with NaN holes in the maximum
//    intensity projection (the validity texture, tiled too), a label map
//    (its texture tiled), and the tiled volume as another volume's guest
//    (its shadow on it). Each within 50 dB of the one-texture picture.
// 3. Width past the limit: still every n-th sample, with the warning.
// 4. Width past the limit with bricks that fit it: every sample, as bricks
//    (the dense texture's picture); with bricking off every n-th sample.
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTransmittanceVolumeTiling.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestSampling.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

constexpr int NX = 20, NY = 18, NZ = 131;
constexpr int TileLimit = 48; // 3 tiles 44 slices apart (the last 43 slices), 2 x 2 places

void CheckLayout()
{
  vtkTransmittanceVolumeTiling tiling;
  const int ct[3] = { 512, 512, 3000 };
  Check(tiling.Plan(ct, 2048) && tiling.GetTiles() == 2 &&
      tiling.GetTextureDimensions()[0] == 1024 && tiling.GetTextureDimensions()[1] == 512 &&
      tiling.GetTextureDimensions()[2] == 1501,
    "a 512 x 512 x 3000 CT: 2 tiles in 1024 x 512 x 1501");
  const int cube[3] = { 1024, 1024, 1024 };
  Check(tiling.Plan(cube, 2048) && !tiling.IsTiled() && tiling.GetTextureDimensions()[2] == 1024,
    "a volume that fits is one tile");
  const int wide[3] = { 3000, 10, 10 };
  Check(!tiling.Plan(wide, 2048), "a width past the limit cannot be tiled");
  const int deep[3] = { 1500, 1500, 4000 };
  Check(!tiling.Plan(deep, 2048), "tiles that do not fit beside each other");

  const int dims[3] = { NX, NY, NZ };
  Check(tiling.Plan(dims, TileLimit) && tiling.GetTiles() == 3 && tiling.GetTilesX() == 2 &&
      tiling.GetSlicesPerTile() == 44 && tiling.GetTextureDimensions()[2] == 45,
    "20 x 18 x 131 at 48: 3 tiles, 2 across, 44 slices apart, 45 deep");
  int first = 0, count = 0, origin[2];
  tiling.GetTile(2, first, count, origin);
  Check(first == 88 && count == 43 && origin[0] == 0 && origin[1] == NY,
    "the last tile: slices 88 to 130, in the second row");
  const int* size = tiling.GetTextureDimensions();
  std::cout << "tiled texture " << size[0] << " x " << size[1] << " x " << size[2] << ", overhead "
            << tiling.GetOverhead() << "\n";
  // Distinct values everywhere, and the tiled layout built from GetTile().
  std::vector<double> values(static_cast<size_t>(NX) * NY * NZ);
  for (size_t n = 0; n < values.size(); ++n)
  {
    values[n] = std::sin(0.37 * n) + 0.001 * n;
  }
  std::vector<double> tiled(static_cast<size_t>(size[0]) * size[1] * size[2], -1.0e9);
  for (int k = 0; k < tiling.GetTiles(); ++k)
  {
    int first = 0, count = 0, origin[2];
    tiling.GetTile(k, first, count, origin);
    for (int z = 0; z < count; ++z)
    {
      for (int y = 0; y < NY; ++y)
      {
        for (int x = 0; x < NX; ++x)
        {
          tiled[(static_cast<size_t>(z) * size[1] + origin[1] + y) * size[0] + origin[0] + x] =
            values[(static_cast<size_t>(first + z) * NY + y) * NX + x];
        }
      }
    }
  }
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  double worst = 0.0;
  for (int n = 0; n < 20000; ++n)
  {
    double t[3];
    for (double& c : t)
    {
      random->Next();
      c = random->GetRangeValue(-0.05, 1.05);
    }
    if (n % 4 == 0)
    {
      // On and about a seam: sample k S (+- a little) of tile k.
      const int k = 1 + (n / 4) % 2;
      random->Next();
      t[2] = (k * tiling.GetSlicesPerTile() + random->GetRangeValue(-1.0, 1.0) + 0.5) / NZ;
    }
    double texel[3];
    tiling.MapCoordinate(t, texel);
    worst = std::max(worst,
      std::abs(tyndall_test::TextureSample(values, dims, t) -
        tyndall_test::TextureSample(tiled, size, texel)));
  }
  std::cout << "tiled against whole samples: largest difference " << worst << "\n";
  Check(worst < 1.0e-9, "the tiled layout samples as the volume (MapCoordinate())");
}

// Smooth values of 0 .. 250 with detail along z, so that the tiles differ.
vtkSmartPointer<vtkImageData> Volume(int type)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  image->SetSpacing(1.0, 1.0, 0.4);
  image->AllocateScalars(type, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int k = 0, n = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i, ++n)
      {
        const double r2 = (i - 9.5) * (i - 9.5) + (j - 8.5) * (j - 8.5);
        const double v =
          250.0 * std::exp(-r2 / 30.0) * (0.55 + 0.45 * std::sin(0.21 * k + 0.05 * i));
        scalars->SetTuple1(n, std::floor(v));
      }
    }
  }
  return image;
}

void SetFunctions(vtkVolumeProperty* property, bool shade)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.2, 0.3, 0.9);
  color->AddRGBPoint(125.0, 0.9, 0.8, 0.4);
  color->AddRGBPoint(250.0, 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(60.0, 0.0);
  opacity->AddPoint(250.0, 0.5);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  property->SetShade(shade);
}

// Label 1 in the volume's lower half, 2 in a slab across the seams.
vtkSmartPointer<vtkImageData> Labels()
{
  auto labels = vtkSmartPointer<vtkImageData>::New();
  labels->SetDimensions(NX, NY, NZ);
  labels->SetSpacing(1.0, 1.0, 0.4);
  labels->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* values = static_cast<unsigned char*>(labels->GetScalarPointer());
  for (int k = 0, n = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i, ++n)
      {
        values[n] = static_cast<unsigned char>(std::abs(k - 43) < 6 ? 2 : (j < NY / 2 ? 1 : 0));
      }
    }
  }
  return labels;
}
}

int TestTransmittanceMapperTiling(int, char*[])
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
  light->SetPosition(30.0, 50.0, 10.0);
  light->SetFocalPoint(10.0, 9.0, 26.0);
  light->SetPositional(false);
  renderer->AddLight(light);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkTest::ErrorObserver> warnings;
  renderer->GetActiveCamera()->SetFocalPoint(9.5, 8.5, 25.8);
  renderer->GetActiveCamera()->SetPosition(80.0, 40.0, 60.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera(0.0, NX - 1.0, 0.0, NY - 1.0, 0.0, (NZ - 1) * 0.4);

  // One picture per texture size: the whole volume in one texture (0), and tiled.
  auto compare = [&](const std::string& what, vtkImageData* data, vtkImageData* labels, int blend,
                   const std::string& expected)
  {
    vtkSmartPointer<vtkImageData> pictures[2];
    for (int tiled = 0; tiled < 2; ++tiled)
    {
      vtkNew<vtkTransmittanceVolumeMapper> mapper;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->AddObserver(vtkCommand::WarningEvent, warnings);
      mapper->SetInputData(data);
      mapper->SetBlendMode(blend);
      mapper->SetTransmittanceMethodToETM();
      mapper->JitterOff();
      mapper->SetMaximumTextureSize(tiled ? TileLimit : 0);
      if (labels)
      {
        mapper->SetMaskInput(labels);
        mapper->SetMaskTypeToLabelMap();
      }
      volume->SetMapper(mapper);
      window->Render();
      pictures[tiled] = tyndall_test::Grab(window);
      Check(mapper->GetNumberOfVolumeTextureTiles() == (tiled ? 3 : 1),
        what + (tiled ? ": 3 tiles" : ": one texture"));
      volume->SetMapper(nullptr);
    }
    const double psnr = tyndall_test::PSNR(pictures[1], pictures[0]);
    std::cout << what << ": tiled against one texture " << psnr << " dB, "
              << tyndall_test::CountDrawn(pictures[0], renderer->GetBackground())
              << " pixels drawn\n";
    Check(psnr >= 60.0, what + ": the tiled volume draws the one-texture picture");
    Check(
      tyndall_test::CountDrawn(pictures[0], renderer->GetBackground()) > 500, what + ": a picture");
    // No warning but the `expected` one (NaN, several volumes' order).
    const std::string warning = warnings->GetWarning() ? warnings->GetWarningMessage() : "";
    std::cout << (warning.empty() ? "" : "warning: " + warning + "\n");
    Check(!errors->GetError() &&
        (warning.empty() || (!expected.empty() && warning.find(expected) != std::string::npos)),
      what + ": no error, no warning but the expected one");
    errors->Clear();
    warnings->Clear();
  };

  SetFunctions(property, true);
  vtkSmartPointer<vtkImageData> bytes = Volume(VTK_UNSIGNED_CHAR);
  compare("8-bit, shaded, ETM shadows", bytes, nullptr, vtkVolumeMapper::COMPOSITE_BLEND, "");

  // Signed 16-bit values (negative ones too), read nearest.
  SetFunctions(property, true);
  property->SetInterpolationTypeToNearest();
  vtkSmartPointer<vtkImageData> shorts = Volume(VTK_SHORT);
  auto* v = static_cast<short*>(shorts->GetScalarPointer());
  for (vtkIdType n = 0; n < shorts->GetNumberOfPoints(); ++n)
  {
    v[n] = static_cast<short>(v[n] * 100 - 3000); // the functions' 0 .. 250 as -3000 .. 22000
  }
  {
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(-3000.0, 0.2, 0.3, 0.9);
    color->AddRGBPoint(22000.0, 1.0, 0.3, 0.1);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(3000.0, 0.0);
    opacity->AddPoint(22000.0, 0.5);
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
  }
  compare("signed 16-bit, nearest, shaded", shorts, nullptr, vtkVolumeMapper::COMPOSITE_BLEND, "");

  // One mapper whose limit changes: the volume uploaded again each time.
  {
    SetFunctions(property, true);
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(bytes);
    mapper->SetTransmittanceMethodToETM();
    mapper->JitterOff();
    volume->SetMapper(mapper);
    vtkSmartPointer<vtkImageData> pictures[3];
    const int limits[3] = { 0, TileLimit, 0 }, tiles[3] = { 1, 3, 1 };
    for (int i = 0; i < 3; ++i)
    {
      mapper->SetMaximumTextureSize(limits[i]);
      window->Render();
      pictures[i] = tyndall_test::Grab(window);
      Check(mapper->GetNumberOfVolumeTextureTiles() == tiles[i],
        "one mapper, limit " + std::to_string(limits[i]) + ": " + std::to_string(tiles[i]) +
          " tile(s)");
    }
    const double tiled = tyndall_test::PSNR(pictures[1], pictures[0]);
    const double back = tyndall_test::PSNR(pictures[2], pictures[0]);
    std::cout << "one mapper whose limit changes: tiled " << tiled << " dB, back " << back
              << " dB\n";
    Check(tiled >= 60.0 && back >= 60.0, "one mapper whose limit changes: the same picture");
    Check(!errors->GetError(), "one mapper whose limit changes: no error");
    volume->SetMapper(nullptr);
  }

  SetFunctions(property, false);
  vtkSmartPointer<vtkImageData> floats = Volume(VTK_FLOAT);
  auto* f = static_cast<float*>(floats->GetScalarPointer());
  for (int k = 40; k < 48; ++k) // NaN holes across the first seam
  {
    for (int i = 4; i < 9; ++i)
    {
      f[(static_cast<size_t>(k) * NY + 9) * NX + i] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  compare("floats with NaN, maximum intensity", floats, nullptr,
    vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, "NaN scalars");

  SetFunctions(property, false);
  vtkNew<vtkColorTransferFunction> red, green;
  red->AddRGBPoint(0.0, 1.0, 0.1, 0.1);
  green->AddRGBPoint(0.0, 0.1, 1.0, 0.2);
  vtkNew<vtkPiecewiseFunction> labelOpacity;
  labelOpacity->AddPoint(0.0, 0.0);
  labelOpacity->AddPoint(250.0, 0.8);
  property->SetLabelColor(1, red);
  property->SetLabelScalarOpacity(1, labelOpacity);
  property->SetLabelColor(2, green);
  property->SetLabelScalarOpacity(2, labelOpacity);
  compare("a label map", bytes, Labels(), vtkVolumeMapper::COMPOSITE_BLEND, "");
  property->SetLabelColor(1, nullptr);
  property->SetLabelColor(2, nullptr);
  property->SetLabelScalarOpacity(1, nullptr);
  property->SetLabelScalarOpacity(2, nullptr);

  // A guest: a small cloud beside the tiled volume, in its shadow (shaded:
  // lit by the renderer's light through the maps).
  {
    SetFunctions(property, true);
    auto cloud = vtkSmartPointer<vtkImageData>::New();
    cloud->SetDimensions(16, 16, 16);
    cloud->SetOrigin(2.0, -30.0, 18.0);
    cloud->SetSpacing(1.0, 1.0, 1.0);
    cloud->AllocateScalars(VTK_FLOAT, 1);
    auto* c = static_cast<float*>(cloud->GetScalarPointer());
    for (int n = 0; n < 16 * 16 * 16; ++n)
    {
      const double x = n % 16 - 7.5, y = (n / 16) % 16 - 7.5, z = n / 256 - 7.5;
      c[n] = static_cast<float>(200.0 * std::exp(-(x * x + y * y + z * z) / 20.0));
    }
    vtkNew<vtkTransmittanceVolumeMapper> cloudMapper;
    cloudMapper->SetInputData(cloud);
    cloudMapper->SetTransmittanceMethodToETM();
    cloudMapper->JitterOff();
    vtkNew<vtkVolume> cloudVolume;
    cloudVolume->SetMapper(cloudMapper);
    cloudVolume->SetProperty(property);
    // The cloud first: its mapper builds the maps, the tiled volume a guest
    // in them (read through its tiles by the guest's code).
    renderer->RemoveVolume(volume);
    renderer->AddVolume(cloudVolume);
    renderer->AddVolume(volume);
    // The light from beyond the tiled volume, onto the cloud.
    light->SetPosition(10.0, 60.0, 26.0);
    renderer->ResetCamera(0.0, NX - 1.0, -30.0, NY - 1.0, 0.0, (NZ - 1) * 0.4);
    compare("a guest in the tiled volume's shadow", bytes, nullptr,
      vtkVolumeMapper::COMPOSITE_BLEND, "Several Tyndall volumes");
    renderer->RemoveVolume(cloudVolume);
  }

  // Wider than the limit: every n-th sample, with the warning. At 16, every
  // 2nd sample (10 x 9 x 65) would need 5 tiles of 16 slices in one 16 x 16
  // place; every 3rd (7 x 6 x 44) fits in 3 tiles.
  {
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->AddObserver(vtkCommand::WarningEvent, warnings);
    mapper->SetInputData(bytes);
    mapper->SetMaximumTextureSize(16);
    volume->SetMapper(mapper);
    window->Render();
    const std::string warning = warnings->GetWarningMessage();
    std::cout << "width past the limit: " << warning << "\n";
    Check(warning.find("exceeds the GPU's 3-D texture size 16") != std::string::npos &&
        warning.find("every 3rd sample") != std::string::npos,
      "a volume 20 wide at a limit of 16: every 3rd sample, with the warning");
    Check(!errors->GetError(), "width past the limit: no error");
    volume->SetMapper(nullptr);
  }

  // Wider than the limit but whose bricks fit it: every sample, as bricks.
  // A 100 x 12 x 12 volume (13 x 2 x 2 bricks of 8^3 that vary, 52 slots of
  // 9^3 in an atlas of at most 40 per side) at a limit of 40: the picture of
  // the one dense texture, no warning; with bricking off, every 3rd sample
  // and the warning.
  {
    auto wide = vtkSmartPointer<vtkImageData>::New();
    wide->SetDimensions(100, 12, 12);
    wide->SetSpacing(0.2, 1.0, 1.0);
    wide->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    vtkDataArray* scalars = wide->GetPointData()->GetScalars();
    for (int k = 0, n = 0; k < 12; ++k)
    {
      for (int j = 0; j < 12; ++j)
      {
        for (int i = 0; i < 100; ++i, ++n)
        {
          const double r2 = (j - 5.5) * (j - 5.5) + (k - 5.5) * (k - 5.5);
          scalars->SetTuple1(
            n, std::floor(250.0 * std::exp(-r2 / 12.0) * (0.55 + 0.45 * std::sin(0.3 * i))));
        }
      }
    }
    SetFunctions(property, true);
    renderer->ResetCamera(0.0, 19.8, 0.0, 11.0, 0.0, 11.0);
    struct Run
    {
      int Limit;
      int Bricking;
    };
    const Run runs[3] = { { 0, vtkTransmittanceVolumeMapper::BRICKING_OFF },
      { 40, vtkTransmittanceVolumeMapper::BRICKING_AUTO },
      { 40, vtkTransmittanceVolumeMapper::BRICKING_OFF } };
    vtkSmartPointer<vtkImageData> pictures[3];
    std::string said[3];
    bool bricked[3] = { false, false, false };
    for (int r = 0; r < 3; ++r)
    {
      vtkNew<vtkTransmittanceVolumeMapper> mapper;
      mapper->AddObserver(vtkCommand::ErrorEvent, errors);
      mapper->AddObserver(vtkCommand::WarningEvent, warnings);
      mapper->SetInputData(wide);
      mapper->SetTransmittanceMethodToETM();
      mapper->JitterOff();
      mapper->SetMaximumTextureSize(runs[r].Limit);
      mapper->SetVolumeBricking(runs[r].Bricking);
      volume->SetMapper(mapper);
      window->Render();
      pictures[r] = tyndall_test::Grab(window);
      bricked[r] = mapper->GetVolumeBricked();
      said[r] = warnings->GetWarning() ? warnings->GetWarningMessage() : "";
      warnings->Clear();
      volume->SetMapper(nullptr);
    }
    const double asBricks = tyndall_test::PSNR(pictures[1], pictures[0]);
    const double sampled = tyndall_test::PSNR(pictures[2], pictures[0]);
    std::cout << "wider than the limit, as bricks: " << asBricks
              << " dB against one texture; bricking off: " << sampled << " dB (" << said[2]
              << ")\n";
    Check(bricked[1] && said[1].empty() && asBricks >= 60.0 &&
        tyndall_test::CountDrawn(pictures[0], renderer->GetBackground()) > 500,
      "a volume 100 wide at a limit of 40: every sample as bricks, the one-texture picture");
    Check(!bricked[2] && said[2].find("every 3rd sample") != std::string::npos && sampled < 60.0,
      "bricking off: every 3rd sample, with the warning");
    Check(!errors->GetError(), "wider than the limit: no error");
    errors->Clear();
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
