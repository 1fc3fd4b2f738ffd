// vtkVolumetricPathTracer on every scene the mapper draws, through the
// medium interface (vtkTyndallMedium) both CPU integrators share: where it
// must agree with vtkSingleScatteringReference (one bounce: the same
// expectation) and where two of its own images must converge.
//
// 1. Emission from an array (EmissionArrayName): one bounce against the
//    reference; the emission is there (the same scene without it is darker).
// 2. A coloured extinction (ExtinctionColor 0.3, 0.6, 1): one bounce against
//    the reference per channel (spectral tracking against the densest
//    channel), and the view transmittance of each channel against the
//    reference's (red sees through more than blue).
// 3. Two volumes that shadow each other (the left cloud in the sun's way of
//    the right one): the right cloud's one bounce against the reference, and
//    lit alone it is measurably brighter.
// 4. A particle cloud casting its shadow into a grid volume (a particle
//    mapper's volume as the other medium), and a coloured particle cloud
//    alone: one bounce against the reference.
// 5. Two overlapping volumes drawn as one medium (a camera group): the first
//    draws both (one bounce against the reference), the second nothing; two
//    coincident copies at half density converge at 4 bounces to the one
//    cloud at full density (paths scatter through both media).
//
// The statistics are TyndallTestStatistics.h's (as TestVolumetricPathTracer;
// the pixels clearer than 0.9, or with values below 0.001 in both images,
// get no per-pixel z: see kClear). A CPU test: no window is opened (the
// mappers only describe the volumes). 9 s (Release, 2 cores, 2026-12-07).
//
// TYNDALL_PATH_TRACER_QUICK (the sanitizer suite, as TestVolumetricPathTracer;
// TyndallTestStatistics.h): every path-traced render with a sixteenth of its
// samples, the z bounds and the other statistical checks (emission on vs off,
// the other volume's shadow, the view transmittance's means) reported, not
// checked; both renders, enough values with a z, finite radiance, red seeing
// through more than blue (the reference's) and the second volume drawing
// nothing of its own checked as before.
//
// Measured (global z, mean z^2, max |z|): emission array -0.94, 0.93, 3.5
// (on vs off z 18.7); coloured extinction -2.7, 1.30, 5.3, mean view
// transmittance within 0.0011 of the reference's per channel; two volumes
// 1.4, 1.04, 2.3 (the other's shadow: z -20.2); particles' shadow 0.39, 0.95,
// 3.2; coloured particles 0.82, 1.17, 3.7; one medium 0.65, 1.08, 2.7; the
// half-density copies at 4 bounces -0.38, 1.03, 2.9.
// Sensitivity, measured by breaking the tracer on purpose: the emission
// array left out fails test 1 at global z -29; spectral tracking's null
// weights set to 1, test 2 at -345 (and every channel's transmittance the
// blue one's); the other media left out of the shadow rays, tests 3 and 4 at
// z 27 and 93; the colour of every collision taken from the volume's own
// medium, test 5 at 180 (and 40 at 4 bounces).
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestParticles.h"
#include "TyndallTestScene.h"
#include "TyndallTestStatistics.h"

#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;
using tyndall_test::CheckPictureUnbiased;
using tyndall_test::CheckStatistic;
using tyndall_test::Compare;
using tyndall_test::Report;
using tyndall_test::Stats;
constexpr int kSize = 24;
// Pixels clearer than this (view transmittance) have no per-pixel z: fewer
// than a tenth of their paths meet the medium; nor do values below kFaint in
// both images, a quarter of an 8-bit level (TyndallTestStatistics.h).
constexpr double kClear = 0.9;
constexpr double kFaint = 0.001;
// The values with a z: about 440 of a 24 x 24 image of a cloud, 190 of a 48
// x 24 image of one of two clouds.
constexpr int kCount = 350;
constexpr int kHalfCount = 150;

Stats Against(vtkImageData* traced, vtkImageData* reference)
{
  return Compare(traced, reference, false, kClear, kFaint);
}

// One volume of the built-in cloud (24^3) under a sun, seen from the front.
struct OneCloud
{
  vtkSmartPointer<vtkImageData> Data = tyndall_test::MakeCloud(24);
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property = tyndall_test::MakeCloudProperty(0.6);
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;

  OneCloud()
  {
    this->Mapper->SetInputData(this->Data);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Property->SetAmbientIntensity(0.05);
    this->Property->SetScatteringAnisotropy(0.3);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.6, 0.4, 1.5));
    tyndall_test::SetTestCamera(this->Renderer);
  }
};

vtkImageData* Reference(
  vtkSingleScatteringReference* reference, vtkRenderer* renderer, vtkVolume* volume, int w, int h)
{
  reference->SetStepSize(0.01);
  return reference->Render(renderer, volume, w, h);
}

vtkImageData* Trace(vtkVolumetricPathTracer* tracer, vtkRenderer* renderer, vtkVolume* volume,
  int bounces, int samples, unsigned seed, int w = kSize, int h = kSize)
{
  tracer->SetDistanceSamplingToDeltaTracking();
  tracer->SetMaximumBounces(bounces);
  tracer->SetSamplesPerPixel(tyndall_test::PathTracerSamples(samples));
  tracer->SetSeed(seed);
  vtkImageData* image = tracer->Render(renderer, volume, w, h);
  std::cout << "  path tracer, " << bounces << " bounce(s), " << tracer->GetSamplesPerPixel()
            << " spp: " << tracer->GetLastRenderTime() << " s" << std::endl;
  return image;
}

// One bounce of the path tracer against the reference for `volume` (a w x h
// image, 512 samples, seed `seed`): both render, and the comparison is
// unbiased (at least `count` values with a z). The images stay with the
// renderers; false when either failed.
bool OneBounce(vtkSingleScatteringReference* reference, vtkVolumetricPathTracer* tracer,
  vtkRenderer* renderer, vtkVolume* volume, unsigned seed, const std::string& what, int count,
  int w = kSize, int h = kSize)
{
  vtkImageData* exact = Reference(reference, renderer, volume, w, h);
  vtkImageData* image = Trace(tracer, renderer, volume, 1, 512, seed, w, h);
  Check(exact && image, what + ": both render");
  if (exact && image)
  {
    CheckPictureUnbiased(Against(image, exact), what + ", 1 bounce vs reference", count);
  }
  return exact && image;
}

// The mean over the image of each channel of `array`.
void ChannelMeans(vtkImageData* image, const char* array, double mean[3])
{
  vtkDataArray* a = image->GetPointData()->GetArray(array);
  const int n = a->GetNumberOfComponents();
  for (int c = 0; c < 3; ++c)
  {
    mean[c] = 0.0;
    for (vtkIdType p = 0; p < a->GetNumberOfTuples(); ++p)
    {
      mean[c] += a->GetComponent(p, n == 3 ? c : 0);
    }
    mean[c] /= static_cast<double>(a->GetNumberOfTuples());
  }
}

// 1. Emission from an array.
void TestEmissionArray()
{
  OneCloud scene;
  vtkNew<vtkFloatArray> heat;
  heat->DeepCopy(scene.Data->GetPointData()->GetScalars());
  heat->SetName("heat");
  scene.Data->GetPointData()->AddArray(heat);
  vtkNew<vtkColorTransferFunction> glow;
  glow->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  glow->AddRGBPoint(8.0, 1.0, 0.5, 0.1);
  scene.Property->SetEmissionArrayName("heat");
  scene.Property->SetEmissionColor(glow);
  scene.Property->SetEmissionScale(0.6);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkVolumetricPathTracer> tracer;
  if (!OneBounce(reference, tracer, scene.Renderer, scene.Volume, 3, "emission array", kCount))
  {
    return;
  }
  vtkNew<vtkImageData> with;
  with->DeepCopy(tracer->GetOutput());
  scene.Property->SetEmissionScale(0.0);
  vtkImageData* without = Trace(tracer, scene.Renderer, scene.Volume, 1, 512, 4);
  const Stats s = Compare(with, without, true);
  Report(s, "emission array on vs off");
  CheckStatistic(s.Global > 5.0, "the emission array adds light");
}

// 2. A coloured extinction.
void TestChromatic()
{
  OneCloud scene;
  scene.Property->SetExtinctionColor(0.3, 0.6, 1.0);
  scene.Property->SetDensityScale(1.5);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkVolumetricPathTracer> tracer;
  if (!OneBounce(reference, tracer, scene.Renderer, scene.Volume, 5, "coloured extinction", kCount))
  {
    return;
  }
  vtkImageData* image = tracer->GetOutput();
  vtkImageData* exact = reference->GetOutput();
  double traced[3], expected[3];
  ChannelMeans(image, "Transmittance", traced);
  ChannelMeans(exact, "Transmittance", expected);
  std::cout << "coloured extinction, mean view transmittance R G B: traced " << traced[0] << " "
            << traced[1] << " " << traced[2] << ", reference " << expected[0] << " " << expected[1]
            << " " << expected[2] << std::endl;
  Check(image->GetPointData()->GetArray("Transmittance")->GetNumberOfComponents() == 3,
    "coloured extinction: a transmittance per channel");
  for (int c = 0; c < 3; ++c)
  {
    // Over 576 pixels of 512 escapes each the mean's standard error is below 0.001.
    CheckStatistic(
      std::abs(traced[c] - expected[c]) < 0.005, "coloured extinction: view transmittance");
  }
  Check(expected[0] > expected[2] + 0.05, "coloured extinction: red sees through more than blue");
}

// 3. Two volumes that shadow each other.
void TestTwoVolumes()
{
  OneCloud left, right;
  vtkNew<vtkRenderer> renderer;
  left.Volume->SetPosition(-1.1, 0.0, 0.0);
  left.Volume->SetScale(0.8);
  right.Volume->SetPosition(1.1, 0.0, 0.0);
  right.Volume->SetScale(0.8);
  left.Property->SetDensityScale(2.0);
  renderer->AddVolume(left.Volume);
  renderer->AddVolume(right.Volume);
  renderer->AddLight(tyndall_test::MakeSun(-1.0, 0.25, 0.15, 1.5)); // through the left one
  tyndall_test::SetTestCamera(renderer, 36.0);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkVolumetricPathTracer> tracer;
  if (!OneBounce(reference, tracer, renderer, right.Volume, 7, "two volumes, the right one",
        kHalfCount, 2 * kSize, kSize))
  {
    return;
  }
  vtkNew<vtkImageData> shadowed;
  shadowed->DeepCopy(tracer->GetOutput());
  right.Property->SetSceneShadows(false);
  vtkImageData* alone = Trace(tracer, renderer, right.Volume, 1, 512, 8, 2 * kSize, kSize);
  right.Property->SetSceneShadows(true);
  const Stats s = Compare(shadowed, alone, true);
  Report(s, "two volumes, the right one with the other's shadow vs lit alone");
  CheckStatistic(s.Global < -5.0, "the other volume shadows this one");
}

// 4. Particles: a particle cloud's shadow in a grid volume, and a coloured cloud alone.
void TestParticles()
{
  OneCloud grid;
  grid.Volume->SetPosition(1.1, 0.0, 0.0);
  grid.Volume->SetScale(0.8);
  vtkNew<vtkTransmittanceParticleMapper> particleMapper;
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(1500, 11, 0.7);
  particleMapper->SetInputData(particles);
  particleMapper->SetGridResolution(32);
  vtkNew<vtkVolume> cloud;
  cloud->SetMapper(particleMapper);
  vtkSmartPointer<vtkParticipatingMediumProperty> property = tyndall_test::MakeCloudProperty();
  property->SetDensityScale(3.0);
  cloud->SetProperty(property);
  cloud->SetPosition(-1.1, 0.0, 0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(cloud);
  renderer->AddVolume(grid.Volume);
  renderer->AddLight(tyndall_test::MakeSun(-1.0, 0.25, 0.15, 1.5));
  tyndall_test::SetTestCamera(renderer, 36.0);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkVolumetricPathTracer> tracer;
  OneBounce(reference, tracer, renderer, grid.Volume, 9, "grid volume in a particle cloud's shadow",
    kHalfCount, 2 * kSize, kSize);
  // The particles themselves, coloured: their exact sum and colours.
  vtkNew<vtkFloatArray> colors;
  colors->SetName("color");
  colors->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < particles->GetNumberOfPoints(); ++i)
  {
    colors->InsertNextTuple3(0.3 + 0.6 * (i % 3 == 0), 0.4 + 0.5 * (i % 3 == 1), 0.95);
  }
  particles->GetPointData()->AddArray(colors);
  particles->Modified();
  grid.Volume->VisibilityOff();
  OneBounce(reference, tracer, renderer, cloud, 10, "coloured particle cloud", kHalfCount,
    2 * kSize, kSize);
}

// 5. Overlapping volumes drawn as one medium.
void TestCameraGroup()
{
  OneCloud first, second;
  vtkNew<vtkRenderer> renderer;
  second.Volume->SetPosition(0.1, 0.05, 0.0);
  second.Volume->SetOrientation(0.0, 90.0, 0.0);
  vtkNew<vtkColorTransferFunction> red;
  red->AddRGBPoint(0.0, 0.95, 0.45, 0.3);
  red->AddRGBPoint(8.0, 0.95, 0.45, 0.3);
  second.Property->SetColor(red);
  first.Property->SetDensityScale(0.5);
  second.Property->SetDensityScale(0.5);
  renderer->AddVolume(first.Volume);
  renderer->AddVolume(second.Volume);
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.6, 0.4, 1.5));
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkSingleScatteringReference> reference;
  vtkNew<vtkVolumetricPathTracer> tracer;
  OneBounce(reference, tracer, renderer, first.Volume, 13, "two volumes drawn as one", kCount);
  // The second volume is drawn by the first: nothing of its own.
  vtkImageData* drawn = Trace(tracer, renderer, second.Volume, 1, 4, 14);
  double radiance[3], transmittance[3];
  ChannelMeans(drawn, "Radiance", radiance);
  ChannelMeans(drawn, "Transmittance", transmittance);
  Check(radiance[0] == 0.0 && radiance[1] == 0.0 && radiance[2] == 0.0 && transmittance[0] == 1.0,
    "camera group: the second volume draws nothing of its own");

  // Two coincident copies at half density against the one cloud: 4 bounces.
  second.Volume->SetPosition(0.0, 0.0, 0.0);
  second.Volume->SetOrientation(0.0, 0.0, 0.0);
  second.Property->SetColor(first.Property->GetRGBTransferFunction());
  vtkNew<vtkImageData> copies;
  copies->DeepCopy(Trace(tracer, renderer, first.Volume, 4, 256, 15));
  second.Volume->VisibilityOff();
  first.Property->SetDensityScale(1.0);
  vtkImageData* one = Trace(tracer, renderer, first.Volume, 4, 256, 16);
  if (one)
  {
    CheckPictureUnbiased(Compare(copies, one, true, kClear, kFaint),
      "two half-density copies vs the cloud, 4 bounces", kCount);
  }
}
}

int TestVolumetricPathTracerScenes(int, char*[])
{
  TestEmissionArray();
  TestChromatic();
  TestTwoVolumes();
  TestParticles();
  TestCameraGroup();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
