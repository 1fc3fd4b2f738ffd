// The transmittance cache (vtkTransmittanceLightCachePass): every map
// light's transmittance on a lattice over the box, read by the camera rays
// with one fetch.
// 1. With two map lights (a sun and a spot light, stacked lattices) and a
//    light inside the box (brute force, not cached), every map method draws
//    with the cache what it draws without it to 45 dB PSNR and 8/255 at
//    most; a coarse 16-texel lattice differs visibly (the cache is read).
// 2. The cache is built once per map build: not for a camera move, again
//    for a light move (the maps change) and for a new size; never for None
//    or brute force, nor when it is off.
// 3. A cache over 1 GiB is refused with an error and the picture is the
//    uncached one.
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <iostream>
#include <string>

namespace
{
using M = vtkTransmittanceVolumeMapper;
using tyndall_test::Check;

struct Scene
{
  vtkNew<M> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkLight> Spot;

  Scene()
  {
    this->Mapper->SetInputData(tyndall_test::MakeCloud(40));
    this->Mapper->JitterOff();
    this->Mapper->SetLightSampleCount(96);
    this->Mapper->SetTransmittanceMapSize(128);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(tyndall_test::MakeCloudProperty(0.8));
    this->Volume->RotateY(20.0);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.6, 0.4));
    this->Spot->SetLightTypeToSceneLight();
    this->Spot->SetPositional(true);
    this->Spot->SetConeAngle(40.0);
    this->Spot->SetPosition(-2.0, 1.5, 1.0);
    this->Spot->SetFocalPoint(0.0, 0.0, 0.0);
    this->Spot->SetColor(1.0, 0.7, 0.4);
    this->Renderer->AddLight(this->Spot);
    tyndall_test::SetTestCamera(this->Renderer);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(160, 160);
    this->Window->AddRenderer(this->Renderer);
  }

  vtkSmartPointer<vtkImageData> Draw()
  {
    this->Window->Render();
    return tyndall_test::Grab(this->Window);
  }
};

// Cache on against off for every map method, with a light inside the box
// besides the two map lights.
void CompareWithMaps()
{
  Scene scene;
  vtkNew<vtkLight> inside;
  inside->SetLightTypeToSceneLight();
  inside->SetPositional(true);
  inside->SetConeAngle(180.0);
  inside->SetPosition(0.2, 0.1, 0.0);
  inside->SetIntensity(0.3);
  scene.Renderer->AddLight(inside);
  for (int m = M::TFM; m <= M::ADAPTIVE_ETM; ++m)
  {
    const std::string name = vtkTransmittanceMapMath::GetMethodName(m);
    scene.Mapper->SetTransmittanceMethod(m);
    scene.Mapper->TransmittanceCacheOff();
    vtkSmartPointer<vtkImageData> maps = scene.Draw();
    scene.Mapper->TransmittanceCacheOn();
    const int builds = scene.Mapper->GetTransmittanceCacheBuildCount();
    vtkSmartPointer<vtkImageData> cached = scene.Draw();
    const double psnr = tyndall_test::PSNR(cached, maps);
    const int worst = tyndall_test::MaxDifference(cached, maps);
    std::cout << name << ": cache (256) against maps " << psnr << " dB, at most " << worst
              << "/255; built in " << scene.Mapper->GetLastTransmittanceCacheBuildTime() << " s\n";
    Check(scene.Mapper->GetTransmittanceCacheBuildCount() == builds + 1,
      name + ": the cache is built for a map method");
    Check(psnr >= 45.0 && worst <= 8, name + ": the cache draws what the maps draw");
  }
  // A coarse lattice: visibly different, so the pictures above came from
  // the cache.
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
  scene.Mapper->SetTransmittanceCacheSize(16);
  vtkSmartPointer<vtkImageData> coarse = scene.Draw();
  scene.Mapper->TransmittanceCacheOff();
  vtkSmartPointer<vtkImageData> maps = scene.Draw();
  const int coarseWorst = tyndall_test::MaxDifference(coarse, maps);
  std::cout << "AdaptiveETM, 16-texel cache against maps: " << tyndall_test::PSNR(coarse, maps)
            << " dB, at most " << coarseWorst << "/255\n";
  Check(coarseWorst > 8, "a 16-texel cache differs visibly from the maps");
}

// When the cache is (re)built.
void CountBuilds()
{
  Scene scene;
  M* mapper = scene.Mapper;
  auto builds = [mapper]() { return mapper->GetTransmittanceCacheBuildCount(); };
  mapper->SetTransmittanceMethodToNone();
  scene.Draw();
  mapper->SetTransmittanceMethodToBruteForce();
  scene.Draw();
  Check(builds() == 0, "no cache for None or brute force");
  mapper->SetTransmittanceMethodToAdaptiveETM();
  scene.Draw();
  Check(builds() == 1, "one build for the first map frame");
  scene.Renderer->GetActiveCamera()->Azimuth(25.0);
  scene.Draw();
  scene.Draw();
  Check(builds() == 1 && mapper->GetMapBuildCount() == 1, "no rebuild for a camera move");
  scene.Spot->SetPosition(-2.0, 1.0, 1.5);
  scene.Draw();
  Check(builds() == 2 && mapper->GetMapBuildCount() == 2, "a rebuild when a light moves");
  mapper->SetTransmittanceCacheSize(100);
  scene.Draw();
  Check(builds() == 3 && mapper->GetMapBuildCount() == 2, "a rebuild for a new size alone");
  mapper->TransmittanceCacheOff();
  scene.Spot->SetPosition(-2.0, 1.5, 1.0);
  scene.Draw();
  Check(builds() == 3, "no build when the cache is off");
  mapper->SetTransmittanceCacheSize(1);
  Check(mapper->GetTransmittanceCacheSize() == 16, "the size clamps to 16");
  mapper->SetTransmittanceCacheSize(5000);
  Check(mapper->GetTransmittanceCacheSize() == 1024, "the size clamps to 1024");
}

// 1024^3 half floats (2 GiB) for one light: refused, the maps read instead.
void RefuseTooLarge()
{
  Scene scene;
  scene.Renderer->RemoveLight(scene.Spot);
  scene.Mapper->SetTransmittanceMethodToAdaptiveETM();
  scene.Mapper->TransmittanceCacheOff();
  vtkSmartPointer<vtkImageData> maps = scene.Draw();
  vtkNew<vtkTest::ErrorObserver> observer;
  scene.Mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  scene.Mapper->TransmittanceCacheOn();
  scene.Mapper->SetTransmittanceCacheSize(1024);
  vtkSmartPointer<vtkImageData> refused = scene.Draw();
  const std::string message = observer->GetErrorMessage();
  std::cout << "1024 cache refused: " << (message.find("2048 MiB") != std::string::npos) << "\n";
  Check(observer->GetError() && message.find("transmittance cache") != std::string::npos,
    "an oversized cache is refused with an error");
  Check(scene.Mapper->GetTransmittanceCacheBuildCount() == 0, "the oversized cache is not built");
  Check(tyndall_test::MaxDifference(refused, maps) == 0,
    "with the cache refused the picture is the uncached one");
}
}

int TestTransmittanceMapperTransmittanceCache(int, char*[])
{
  CompareWithMaps();
  CountBuilds();
  RefuseTooLarge();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
