// The renderer's sky (vtkTyndallEnvironment) in the mapper's path-tracing
// mode and in its CPU twin, vtkVolumetricPathTracer:
// 1. the white furnace: a white, non-absorbing medium (albedo 1) under a
//    constant sky L, no light, the background L: every pixel is L exactly
//    (the paths' light and the background seen through the medium add up
//    to it), whatever the medium and the phase function (g 0.6). The CPU's
//    and the GPU's 64-spp pictures, their sums over the picture and over
//    each quadrant within 4.5 standard errors of L's. A sky counted twice (the sampled sky's and
//    the escaped paths' weights not summing to 1) or missed is off by far more.
//    And a shaded furnace: a white plain property with Shade on, Kd 1, Ks
//    0, Ka 0 (vtkTyndallSurfaceLobe's weight exactly 1), the sky L seen as
//    LightUnit L and the background LightUnit L: every pixel LightUnit L
//    (z below 0.3; the unit left out of the escapes: z -81 on both);
// 2. the GPU against the CPU: a gradient sky with the sun, and an image sky
//    (a bright patch, the only light, a dark ground), on the built-in cloud:
//    the sums of both at 64 spp, over the picture and each quadrant, within
//    4.5 standard errors, and over tiles of 4 x 4 pixels the mean z^2 below
//    2 (measured 0.17 and 0.18: the variance is overestimated; a sky
//    mirrored on the GPU 7.4, which the sums miss); and a shaded CT (a
//    plain property with Shade on, vtkTyndallSurfaceLobe) under the gradient
//    sky alone (z below 0.3, tiles 0.44; the GPU's specular density 4/3 too
//    large: z 8.7); and the ball as a medium with Shade on (its surface
//    term added to its scattering) under the sun and the gradient sky (z
//    below 0.43, tiles 0.20; the sky's next-event estimate weighed against
//    the lobe's draws, which a medium's Shade never makes: z -9);
// 3. the map-based frame's approximations: with SkyLightDirections 0 a
//    constant sky adds its radiance to the ambient term, the picture
//    identical to one with that AmbientIntensity, on the GPU and in the CPU
//    single-scattering reference; the sky's 4 lights, with no shadow and an
//    isotropic phase function, give the same picture on the GPU (50 dB or
//    more: they carry the sky's light); shadowed (brute force) the GPU's
//    picture is the CPU reference's (40 dB or more; the reference always
//    shadows), and the maps' (isotropic) darker than the mean's (unshadowed
//    lights are not); the sky's light in both modes is printed
//    (how alike); a new sky restarts the paths;
// 4. a shaded CT's map-based frame (VTK's gradient shading) under a sky
//    alone: its lights shade it as in the CPU reference (40 dB or more),
//    a medium's Shade too; its mean is diffuse light (a larger Ambient by
//    Kd 2 pi m, on the GPU and in the reference; a medium's Shade as the
//    CPU's; none where there is no gradient), and the sky's share of the
//    picture is the paths' within a factor 2.
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallSurfaceLobe.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestPathCompare.h"
#include "TyndallTestPathScene.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
using tyndall_test::Check;
using Scene = tyndall_test::PathScene;
constexpr int kSamples = 64;
// The light cache's side: the paths here track their shadows, and each of
// the sky's 4 lights would cost 1.1 s of llvmpipe at the default 256.
constexpr int kCacheSize = 64;

// 1. the white furnace; `shaded`: a shaded one (a plain property with
// Shade on, white, Kd 1, Ks 0, Ka 0: every collision scatters all it
// receives, its lobe's weight exactly 1; the sky is LightUnit L to it, the
// sky's unit for a shaded collision, and so is the background), which holds
// the paths' own loop with vtkTyndallSurfaceLobe (the lobe's weights, the
// sky's draws and the escapes weighed against each other, the unit on
// both, the offset start: one bounce does not reach them).
void Furnace(bool shaded)
{
  const int size = 32;
  Scene scene(tyndall_test::MakeCloud(32), 0.5, size);
  scene.Mapper->SetTransmittanceCacheSize(kCacheSize);
  const double L = shaded ? 0.1 : 0.6;
  const double seen = shaded ? vtkTyndallSurfaceLobe::LightUnit * L : L;
  scene.Renderer->RemoveAllLights();
  scene.Renderer->AutomaticLightCreationOff();
  scene.Renderer->SetEnvironmentalBG(L, L, L);
  scene.Renderer->SetBackground(seen, seen, seen);
  vtkColorTransferFunction* color = scene.Property->GetRGBTransferFunction();
  color->RemoveAllPoints();
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  scene.Property->SetAmbientIntensity(0.0);
  scene.Property->SetScatteringAnisotropy(0.6);
  if (shaded)
  {
    vtkNew<vtkVolumeProperty> plain;
    plain->SetScalarOpacity(scene.Property->GetScalarOpacity());
    plain->SetColor(color);
    plain->SetScalarOpacityUnitDistance(scene.Property->GetScalarOpacityUnitDistance());
    plain->SetInterpolationTypeToLinear();
    plain->ShadeOn();
    plain->SetAmbient(0.0);
    plain->SetDiffuse(1.0);
    plain->SetSpecular(0.0);
    scene.Volume->SetProperty(plain);
  }
  scene.Mapper->SetPathTraceMaximumBounces(1000);
  scene.Mapper->SetPathTraceShadowsToTracked();
  scene.Mapper->SetPathTraceSamplesPerFrame(16);
  const std::string name = shaded ? "Shaded furnace" : "Furnace";

  auto cpu = tyndall_test::MakeCpuTracer(scene, kSamples);
  vtkImageData* traced = cpu->Render(scene.Renderer, scene.Volume, size, size);
  if (!traced)
  {
    Check(false, name + ": the CPU tracer renders");
    return;
  }
  const double* bg = scene.Renderer->GetBackground();
  auto sky = [&](vtkIdType, int) { return seen; };
  const tyndall_test::PathComparison cpuPicture{ cpu->Composite(), traced, bg, kSamples, 1, sky };
  Check(cpuPicture.WorstZ(name + ", CPU", true) < 4.5,
    name + ": the CPU tracer's picture is the sky's radiance everywhere");
  Check(scene.Trace(kSamples) >= kSamples, name + ": the GPU's picture has its samples");
  vtkSmartPointer<vtkImageData> picture = scene.Picture();
  const tyndall_test::PathComparison gpuPicture{ picture, traced, bg, kSamples, 1, sky };
  Check(gpuPicture.WorstZ(name + ", GPU", true) < 4.5,
    name + ": the GPU's picture is the sky's radiance everywhere");
}

// An equirectangular sky of 32 x 16 (VTK's renderer does not prefilter a
// smaller one on llvmpipe): a bright patch (30) 22-34 degrees above the
// horizon, 22-67 degrees right of the front, a dim blue above the horizon,
// a dark ground.
vtkSmartPointer<vtkTexture> MakeSkyImage()
{
  const int W = 32, H = 16;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(W, H, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(W * H);
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const bool patch = i >= 18 && i <= 21 && j == 10;
      const double sky[3] = { 0.06, 0.09, 0.16 };
      const double ground[3] = { 0.02, 0.016, 0.012 };
      for (int c = 0; c < 3; ++c)
      {
        values->SetComponent(j * W + i, c, patch ? 30.0 : (j >= H / 2 ? sky[c] : ground[c]));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  // VTK's renderer prefilters the environment for its surfaces' PBR lighting, which wants these.
  texture->MipmapOn();
  texture->InterpolateOn();
  return texture;
}

// What AgainstCpu() draws: the cloud, a shaded CT (a plain property with
// Shade on over the dense medium's ball: vtkTyndallSurfaceLobe), or the
// ball as a medium with Shade on (its surface term added to its scattering).
enum class Drawn
{
  Cloud,
  ShadedCT,
  MediumShade
};

// 2. the GPU against the CPU under a sky (tracked shadows: unbiased).
void AgainstCpu(
  const char* name, const std::function<void(vtkRenderer*)>& sky, Drawn drawn = Drawn::Cloud)
{
  const int size = 32;
  Scene scene(
    drawn == Drawn::Cloud ? tyndall_test::MakeCloud(32) : tyndall_test::MakeDenseMedium(32), 0.5,
    size);
  if (drawn == Drawn::ShadedCT)
  {
    scene.Volume->SetProperty(tyndall_test::MakeShadedProperty(4.0, 12.0, 0.9));
  }
  else if (drawn == Drawn::MediumShade)
  {
    scene.Property->ShadeOn();
    scene.Property->SetDiffuse(0.5);
    scene.Property->SetSpecular(0.4);
    scene.Property->SetSpecularPower(15.0);
  }
  scene.Mapper->SetTransmittanceCacheSize(kCacheSize);
  // A background of exact 8-bit levels (the frame buffer rounds 0.3 x 255 =
  // 76.5 its own way: half a level in every background pixel).
  scene.Renderer->SetBackground(0.2, 0.4, 0.6);
  sky(scene.Renderer);
  tyndall_test::BothTraced both;
  if (!both.Trace(scene, kSamples, size, name))
  {
    return;
  }
  const tyndall_test::PathComparison comparison =
    both.Compare(scene.Renderer->GetBackground(), kSamples);
  const double z = comparison.WorstZ(name, true);
  const double chi = comparison.TileChiSquare(4);
  std::cout << name << ": the mean z^2 over 4 x 4 tiles " << chi << std::endl;
  Check(z < 4.5, std::string(name) + ": the GPU's mean is the CPU's within the noise");
  Check(chi < 2.0, std::string(name) + ": the GPU's picture is the CPU's tile by tile");
}

// Sums of the reference's radiance (largest difference of a and b; b's sum).
void Compare(vtkImageData* a, vtkImageData* b, double& largest, double& sum)
{
  vtkDataArray* x = a->GetPointData()->GetArray("Radiance");
  vtkDataArray* y = b->GetPointData()->GetArray("Radiance");
  largest = sum = 0.0;
  for (vtkIdType p = 0; p < x->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(x->GetComponent(p, c) - y->GetComponent(p, c)));
      sum += y->GetComponent(p, c);
    }
  }
}

// The sum of an 8-bit picture's first three channels.
double Sum(vtkImageData* image)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  double sum = 0.0;
  for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
  {
    sum += a->GetComponent(p, 0) + a->GetComponent(p, 1) + a->GetComponent(p, 2);
  }
  return sum;
}

// 3. the map-based frame: the sky's mean radiance as ambient light
// (SkyLightDirections 0), then the sky's lights.
void MapFrame()
{
  const int size = 32;
  Scene scene(tyndall_test::MakeCloud(32), 0.5, size);
  scene.Mapper->SetTransmittanceCacheSize(kCacheSize);
  scene.Mapper->PathTracingOff();
  scene.Mapper->SetSkyLightDirections(0);
  const double ambient = scene.Property->GetAmbientIntensity();
  const double sky = 0.25;
  scene.Property->SetAmbientIntensity(ambient + sky);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> asAmbient = scene.Picture();
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkImageData> referenceAmbient;
  referenceAmbient->DeepCopy(reference->Render(scene.Renderer, scene.Volume, size, size));
  scene.Property->SetAmbientIntensity(ambient);
  scene.Renderer->SetEnvironmentalBG(sky, sky, sky);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> withSky = scene.Picture();
  Check(tyndall_test::PSNR(withSky, asAmbient) == std::numeric_limits<double>::infinity(),
    "the map-based frame: a constant sky is its radiance as ambient light");
  double largest, sum;
  Compare(
    referenceAmbient, reference->Render(scene.Renderer, scene.Volume, size, size), largest, sum);
  Check(largest <= 1e-12 && sum > 0.0,
    "the single-scattering reference: a constant sky is its radiance as ambient light");

  // The sky's lights, unshadowed, isotropic: the same light as the mean.
  scene.Mapper->SetSkyLightDirections(4);
  scene.Mapper->SetTransmittanceMethodToNone();
  const double g = scene.Property->GetScatteringAnisotropy();
  scene.Property->SetScatteringAnisotropy(0.0);
  scene.Property->SetAmbientIntensity(ambient + sky);
  scene.Renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  scene.Window->Render();
  asAmbient = scene.Picture();
  scene.Property->SetAmbientIntensity(ambient);
  scene.Renderer->SetEnvironmentalBG(sky, sky, sky);
  scene.Window->Render();
  const double unshadowedPsnr = tyndall_test::PSNR(scene.Picture(), asAmbient);
  std::cout << "The sky's 4 lights unshadowed, isotropic, against its mean as ambient light: "
            << unshadowedPsnr << " dB" << std::endl;
  Check(scene.Mapper->GetNumberOfRenderedLights() == 5, "the sun and the sky's 4 lights");
  Check(unshadowedPsnr >= 50.0, "the map-based frame: the sky's lights carry its light");
  scene.Property->SetScatteringAnisotropy(g);

  // Shadowed: the GPU's brute force against the CPU reference, as without the sky.
  scene.Mapper->SetTransmittanceMethodToBruteForce();
  double psnr[2];
  for (int lit = 0; lit < 2; ++lit)
  {
    scene.Renderer->SetEnvironmentalBG(lit * sky, lit * sky, lit * sky);
    scene.Window->Render();
    reference->Render(scene.Renderer, scene.Volume, size, size);
    psnr[lit] = tyndall_test::PSNR(scene.Picture(), reference->Composite());
  }
  std::cout << "Brute force against the CPU reference: " << psnr[1]
            << " dB under the sky's lights, " << psnr[0] << " dB without the sky" << std::endl;
  Check(psnr[1] >= 40.0, "the map-based frame's sky lights: the GPU's are the CPU reference's");
  // Shadowed by the maps (isotropic): the sky's share of the picture (over
  // the one without the sky) darker than its mean's as ambient light.
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
  scene.Property->SetScatteringAnisotropy(0.0);
  scene.Renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  scene.Window->Render();
  const double base = Sum(scene.Picture());
  scene.Renderer->SetEnvironmentalBG(sky, sky, sky);
  scene.Mapper->SetSkyLightDirections(0);
  scene.Window->Render();
  const double mean = Sum(scene.Picture()) - base;
  scene.Mapper->SetSkyLightDirections(4);
  scene.Window->Render();
  const double darker = (Sum(scene.Picture()) - base) / mean;
  std::cout << "The sky's share, its lights shadowed by the maps over its mean as ambient light: "
            << darker << std::endl;
  Check(mean > 0.0 && darker < 0.8, "the sky's lights are shadowed by the medium");
  scene.Property->SetScatteringAnisotropy(g);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> shadowed = scene.Picture();

  // How alike the two modes light the sky.
  vtkSmartPointer<vtkImageData> withoutSkyPaths;
  scene.Renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  scene.Trace(64);
  withoutSkyPaths = scene.Picture();
  scene.Renderer->SetEnvironmentalBG(sky, sky, sky);
  scene.Window->Render();
  Check(scene.Mapper->GetLastPathTraceSamples() == 0,
    "a new sky restarts the paths (the map-based frame first)");
  scene.Trace(64);
  vtkSmartPointer<vtkImageData> paths = scene.Picture();
  std::cout << "The sky's light (" << sky
            << "), the built-in cloud, against 64 spp of paths: the map-based frame with the "
               "sky's lights "
            << tyndall_test::PSNR(shadowed, paths) << " dB, its mean as ambient light "
            << tyndall_test::PSNR(withSky, paths) << " dB; the paths without the sky "
            << tyndall_test::PSNR(withoutSkyPaths, paths) << " dB" << std::endl;
  Check(tyndall_test::PSNR(withoutSkyPaths, paths) < 60.0, "the paths see the sky");
}
}

// 4. a shaded CT's map-based frame (a plain property with Shade on: VTK's
// gradient shading), lit by a sky alone: the sky's lights shade it as
// they do in the CPU single-scattering reference (brute force: 40 dB or
// more), and a medium's Shade (its surface term) alike; the sky's mean
// from every direction (SkyLightDirections 0) is a grey sky m's diffuse
// light Kd c 2 pi m, the picture of an Ambient larger by Kd 2 pi m on the
// GPU and in the reference, a medium's Shade under it the CPU's too, and a
// sample without a gradient gets none of it (a block of one value: the
// picture under a black sky); and the sky's share of the picture (over the
// one under a black sky) in the map-based frame against the paths' (64
// spp), within a factor 2 of it (0.69: one bounce against all of them; 0
// before the sky lit the shading).
void ShadedMapFrame()
{
  const int size = 32;
  vtkSmartPointer<vtkImageData> data = tyndall_test::MakeDenseMedium(32);
  Scene scene(data, 0.5, size);
  vtkSmartPointer<vtkVolumeProperty> property = tyndall_test::MakeShadedProperty(4.0, 12.0, 0.9);
  scene.Volume->SetProperty(property);
  scene.Mapper->SetTransmittanceCacheSize(kCacheSize);
  scene.Mapper->PathTracingOff();
  scene.Renderer->RemoveAllLights();
  scene.Renderer->AutomaticLightCreationOff();
  scene.Renderer->SetBackground(0.2, 0.4, 0.6);
  auto gradientSky = [&](bool on)
  {
    scene.Renderer->SetGradientEnvironmentalBG(on);
    scene.Renderer->SetEnvironmentalBG(0.05 * on, 0.04 * on, 0.03 * on);
    scene.Renderer->SetEnvironmentalBG2(0.15 * on, 0.22 * on, 0.4 * on);
  };

  // The sky's lights: the GPU's brute force against the CPU reference.
  vtkNew<vtkSingleScatteringReference> reference;
  scene.Mapper->SetTransmittanceMethodToBruteForce();
  gradientSky(true);
  scene.Window->Render();
  reference->Render(scene.Renderer, scene.Volume, size, size);
  const double psnr = tyndall_test::PSNR(scene.Picture(), reference->Composite());
  std::cout << "A shaded CT under the sky's lights, brute force against the CPU reference: " << psnr
            << " dB" << std::endl;
  Check(psnr >= 40.0, "a shaded CT's map-based frame: the sky's lights as the CPU reference's");
  // A medium's Shade: its surface term lit by them too.
  scene.Volume->SetProperty(scene.Property);
  scene.Property->ShadeOn();
  scene.Window->Render();
  reference->Render(scene.Renderer, scene.Volume, size, size);
  const double additive = tyndall_test::PSNR(scene.Picture(), reference->Composite());
  std::cout << "A medium's Shade under the sky's lights, brute force against the CPU reference: "
            << additive << " dB" << std::endl;
  Check(additive >= 40.0, "a medium's Shade: the sky's lights as the CPU reference's");
  scene.Property->ShadeOff();
  scene.Volume->SetProperty(property);

  // The sky's mean: a larger Ambient. Kd 2 pi m of a grey sky m.
  scene.Mapper->SetSkyLightDirections(0);
  const double m = 0.05;
  const double ka = property->GetAmbient();
  gradientSky(false);
  scene.Renderer->SetEnvironmentalBG(m, m, m);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> withMean = scene.Picture();
  vtkNew<vtkImageData> referenceMean;
  referenceMean->DeepCopy(reference->Render(scene.Renderer, scene.Volume, size, size));
  scene.Renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  property->SetAmbient(ka + 2.0 * vtkMath::Pi() * property->GetDiffuse() * m);
  scene.Window->Render();
  const double meanPsnr = tyndall_test::PSNR(withMean, scene.Picture());
  double largest, sum;
  Compare(referenceMean, reference->Render(scene.Renderer, scene.Volume, size, size), largest, sum);
  property->SetAmbient(ka);
  std::cout << "A shaded CT under a constant sky's mean against a larger Ambient: " << meanPsnr
            << " dB on the GPU, the reference's largest difference " << largest << std::endl;
  Check(meanPsnr >= 60.0, "a shaded CT's map-based frame: the sky's mean is diffuse light");
  // (The reference's radiance is stored as floats: 1e-6 is their rounding.)
  Check(largest <= 1e-6 && sum > 0.0,
    "the single-scattering reference: a shaded CT's sky mean is diffuse light");
  // A medium's Shade under the mean: the GPU's surface term as the CPU's.
  scene.Renderer->SetEnvironmentalBG(m, m, m);
  scene.Volume->SetProperty(scene.Property);
  scene.Property->ShadeOn();
  scene.Window->Render();
  reference->Render(scene.Renderer, scene.Volume, size, size);
  const double additiveMean = tyndall_test::PSNR(scene.Picture(), reference->Composite());
  scene.Property->ShadeOff();
  // Without a gradient (a block of one value) a sample gets none of the
  // mean, as none of the lights: the picture under the sky is the one under
  // a black sky.
  vtkNew<vtkImageData> block;
  block->SetDimensions(16, 16, 16);
  block->SetOrigin(-0.5, -0.5, -0.5);
  block->SetSpacing(1.0 / 15, 1.0 / 15, 1.0 / 15);
  block->AllocateScalars(VTK_FLOAT, 1);
  block->GetPointData()->GetScalars()->Fill(8.0);
  scene.Mapper->SetInputData(block);
  scene.Volume->SetProperty(property);
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> flatUnderSky = scene.Picture();
  vtkNew<vtkImageData> flatReference;
  flatReference->DeepCopy(reference->Render(scene.Renderer, scene.Volume, size, size));
  scene.Renderer->SetEnvironmentalBG(0.0, 0.0, 0.0);
  scene.Window->Render();
  const double flatPsnr = tyndall_test::PSNR(flatUnderSky, scene.Picture());
  Compare(flatReference, reference->Render(scene.Renderer, scene.Volume, size, size), largest, sum);
  scene.Mapper->SetInputData(data);
  std::cout << "The sky's mean, a medium's Shade, brute force against the CPU reference: "
            << additiveMean
            << " dB; a block of one value under it against a black sky: " << flatPsnr
            << " dB on the GPU, the reference's largest difference " << largest << std::endl;
  Check(additiveMean >= 40.0, "a medium's Shade: the sky's mean as the CPU reference's");
  Check(flatPsnr == std::numeric_limits<double>::infinity() && largest == 0.0 && sum > 0.0,
    "no gradient, none of the sky's mean");

  // How alike the two modes light it: the sky's share of each picture.
  scene.Mapper->SetSkyLightDirections(4);
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
  double maps[2], paths[2];
  for (int lit = 0; lit < 2; ++lit)
  {
    gradientSky(lit != 0);
    scene.Mapper->PathTracingOff();
    scene.Window->Render();
    maps[lit] = Sum(scene.Picture());
    scene.Trace(64);
    paths[lit] = Sum(scene.Picture());
  }
  const double share = (maps[1] - maps[0]) / (paths[1] - paths[0]);
  std::cout << "A shaded CT, the sky's share of the map-based frame over the paths' (64 spp): "
            << share << std::endl;
  // (Single scattering against every bounce: the maps' share is the smaller.)
  Check(paths[1] > paths[0] && share > 0.5 && share < 2.0,
    "a shaded CT: the map-based frame and the paths light the sky alike");
}

int TestTransmittanceMapperSky(int, char*[])
{
  Furnace(false);
  Furnace(true);
  AgainstCpu("Gradient sky",
    [](vtkRenderer* renderer)
    {
      renderer->GradientEnvironmentalBGOn();
      renderer->SetEnvironmentalBG(0.05, 0.04, 0.03);
      renderer->SetEnvironmentalBG2(0.3, 0.45, 0.8);
    });
  AgainstCpu("Image sky",
    [](vtkRenderer* renderer)
    {
      // The sky's patch alone lights one side: a mirrored sky lights the other.
      renderer->RemoveAllLights();
      renderer->AutomaticLightCreationOff();
      renderer->SetEnvironmentTexture(MakeSkyImage());
      renderer->UseImageBasedLightingOn();
      renderer->SetEnvironmentUp(0.0, 0.0, 1.0);
      renderer->SetEnvironmentRight(1.0, 0.0, 0.0);
    });
  // A shaded CT lit by a gradient sky alone (its first bounce is VTK's
  // Kd c E: a sky dim enough not to saturate): the lobe's draws and density
  // weigh most of the picture (the paths that leave for the sky, multiple
  // importance sampling against the sky's draws).
  AgainstCpu(
    "Shaded CT, gradient sky",
    [](vtkRenderer* renderer)
    {
      renderer->RemoveAllLights();
      renderer->AutomaticLightCreationOff();
      renderer->GradientEnvironmentalBGOn();
      renderer->SetEnvironmentalBG(0.05, 0.04, 0.03);
      renderer->SetEnvironmentalBG2(0.15, 0.22, 0.4);
    },
    Drawn::ShadedCT);
  // A medium's Shade under the sun and a gradient sky: each collision's
  // surface term (the lobe's light, the sky's by next-event estimation
  // alone) added to its scattering, the paths scattered by the phase
  // function (vtkVolumetricPathTracer's AddSurfaceTerm()).
  AgainstCpu(
    "A medium's Shade, gradient sky",
    [](vtkRenderer* renderer)
    {
      renderer->GradientEnvironmentalBGOn();
      renderer->SetEnvironmentalBG(0.05, 0.04, 0.03);
      renderer->SetEnvironmentalBG2(0.15, 0.22, 0.4);
    },
    Drawn::MediumShade);
  MapFrame();
  ShadedMapFrame();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
