// Clipping planes and cropping respected by the light: a cloud clipped in
// half by a plane, lit from the clipped side, so that the half that remains
// would lie in the removed half's shadow if the light ignored the clipping.
// 1. Every method (BruteForce, TFM, AdaptiveTFM, ETM, AdaptiveETM) against the
//    CPU reference, which clips the same way: >= 40 dB (the target);
// 2. the picture with the light ignoring the clipping (the CPU reference's
//    LightIgnoresClipping, what VTK's shadow rays do) differs visibly: the
//    GPU is much closer to the clipped light than to it;
// 3. moving the plane rebuilds the maps and changes the picture;
// 4. cropping (a non-convex region: the octant x, y, z >= 0 removed) against
//    the CPU reference, brute force and adaptive ETM.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkRenderWindow.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestCloudScene.h"
#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

double Mean(vtkImageData* image)
{
  if (!image)
  {
    return -1.0;
  }
  const std::vector<double> values = tyndall_test::RadianceValues(image);
  double sum = 0.0;
  for (double v : values)
  {
    sum += v;
  }
  return sum / static_cast<double>(values.size());
}
using M = vtkTransmittanceVolumeMapper;

struct Scene : tyndall_test::CloudScene
{
  explicit Scene(int size)
    : CloudScene(size, 0.6)
  {
    this->Mapper->SetTransmittanceMapSize(256);
    this->Mapper->SetNumberOfCoefficients(12);
    this->Property->SetAmbientIntensity(0.05);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    // The sun comes from +x: the clipped half (x > 0) stood between it and
    // the half that remains.
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.25, 0.15, 1.2));
  }

  vtkSmartPointer<vtkImageData> Cpu(bool lightIgnoresClipping = false)
  {
    vtkNew<vtkSingleScatteringReference> reference;
    reference->SetLightIgnoresClipping(lightIgnoresClipping);
    return this->CloudScene::Cpu(reference);
  }
};

void Methods(Scene& scene, vtkImageData* expected, const int* methods, int count,
  const double* floors, const std::string& what)
{
  for (int i = 0; i < count; ++i)
  {
    scene.Mapper->SetTransmittanceMethod(methods[i]);
    const double psnr = tyndall_test::PSNR(scene.Gpu(), expected);
    std::cout << "  " << what << ", " << scene.Mapper->GetTransmittanceMethodAsString() << ": "
              << psnr << " dB against the CPU reference\n";
    Check(psnr >= floors[i],
      what + ": " + scene.Mapper->GetTransmittanceMethodAsString() + " against the CPU reference");
  }
}
}

int TestTransmittanceMapperClipping(int, char*[])
{
  const int all[5] = { M::BRUTE_FORCE, M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM };
  {
    Scene scene(160);
    vtkNew<vtkPlane> plane; // keeps x <= 0.05
    plane->SetOrigin(0.05, 0.0, 0.0);
    plane->SetNormal(-1.0, 0.0, 0.0);
    scene.Mapper->AddClippingPlane(plane);
    vtkSmartPointer<vtkImageData> expected = scene.Cpu();
    vtkSmartPointer<vtkImageData> ignored = scene.Cpu(true);
    std::cout << "Half-clipped cloud lit from the clipped side (160^2):\n";
    // Measured on llvmpipe (12 coefficients), dB: BruteForce 50.9, TFM 43.9,
    // AdaptiveTFM 47.9, ETM 44.9, AdaptiveETM 50.1 (with 8 coefficients TFM
    // 40.0 and ETM 38.7, their accuracy on this cloud unclipped too). The
    // issue's bar is 40 dB for every method; the floors sit under the values.
    const double floors[5] = { 49.5, 42.5, 46.5, 43.5, 49.0 };
    Methods(scene, expected, all, 5, floors, "clipped");
    // 2. The light ignoring the clipping.
    const double apart = tyndall_test::PSNR(expected, ignored);
    scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
    const double gpuToIgnored = tyndall_test::PSNR(scene.Gpu(), ignored);
    std::cout << "  the light ignoring the clipping (CPU): " << apart
              << " dB against the clipped light, largest difference "
              << tyndall_test::MaxDifference(expected, ignored) << "/255; the GPU against it "
              << gpuToIgnored << " dB\n";
    Check(apart < 30.0, "the light ignoring the clipping differs visibly");
    Check(gpuToIgnored < apart + 3.0, "the GPU's light does not ignore the clipping");
    // The path tracer (one bounce: single scattering) clips like the
    // reference: its mean radiance within 5 % of the reference's (measured
    // 2.7 %: the reference's midpoint steps straddle the cut face, the path
    // tracer's delta tracking meets it exactly), while the light ignoring
    // the clipping gives a third of it.
    {
      vtkNew<vtkVolumetricPathTracer> tracer;
      tracer->SetMaximumBounces(1);
      tracer->SetSamplesPerPixel(16);
      vtkNew<vtkSingleScatteringReference> reference;
      const double traced = Mean(tracer->Render(scene.Renderer, scene.Volume, 40, 40));
      const double exact = Mean(reference->Render(scene.Renderer, scene.Volume, 40, 40));
      reference->LightIgnoresClippingOn();
      const double unclipped = Mean(reference->Render(scene.Renderer, scene.Volume, 40, 40));
      std::cout << "  mean radiance, 40^2: path tracer " << traced << ", CPU reference " << exact
                << ", the light ignoring the clipping " << unclipped << "\n";
      Check(std::abs(traced / exact - 1.0) < 0.05 && unclipped < 0.8 * exact,
        "the path tracer clips the light too");
    }
    // 3. Moving the plane rebuilds the maps and changes the picture.
    vtkSmartPointer<vtkImageData> before = scene.Gpu();
    const int builds = scene.Mapper->GetMapBuildCount();
    plane->SetOrigin(-0.3, 0.0, 0.0);
    vtkSmartPointer<vtkImageData> after = scene.Gpu();
    Check(scene.Mapper->GetMapBuildCount() == builds + 1, "moving the plane rebuilds the maps");
    Check(tyndall_test::PSNR(before, after) < 35.0, "moving the plane changes the picture");
    scene.Mapper->RemoveAllClippingPlanes();
    vtkSmartPointer<vtkImageData> whole = scene.Gpu();
    Check(scene.Mapper->GetMapBuildCount() == builds + 2, "removing the plane rebuilds the maps");
    Check(tyndall_test::PSNR(whole, after) < 35.0, "without the plane the cloud is whole again");
  }
  {
    // 4. Cropping: regions per axis split at -2 and 0 (data coordinates);
    // every region kept but the octant x, y, z >= 0 (region 26).
    Scene scene(128);
    scene.Mapper->CroppingOn();
    scene.Mapper->SetCroppingRegionPlanes(-2.0, 0.0, -2.0, 0.0, -2.0, 0.0);
    scene.Mapper->SetCroppingRegionFlags(((1 << 27) - 1) & ~(1 << 26));
    vtkSmartPointer<vtkImageData> expected = scene.Cpu();
    std::cout << "Cloud cropped (the octant x, y, z >= 0 removed, 128^2):\n";
    // Measured 43.2 and 43.3 dB (the cut's hard faces cross camera steps).
    const int two[2] = { M::BRUTE_FORCE, M::ADAPTIVE_ETM };
    const double floors[2] = { 42.0, 42.0 };
    Methods(scene, expected, two, 2, floors, "cropped");
    scene.Mapper->CroppingOff();
    const double uncropped = tyndall_test::PSNR(scene.Gpu(), expected);
    std::cout << "  uncropped against the cropped reference: " << uncropped << " dB\n";
    Check(uncropped < 30.0, "cropping changes the picture");
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
