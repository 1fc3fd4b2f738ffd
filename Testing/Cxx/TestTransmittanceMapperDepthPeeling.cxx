// Depth peeling for volumes (vtkRenderer's UseDepthPeelingForVolumes, which
// ParaView turns on) with translucent geometry: VTK draws the volume inside
// its dual depth peeling, a stage at a time (vtkTransmittancePeelingPass).
// A lit cloud with the maps' shadows (AdaptiveETM) and a translucent sphere:
// 1. the sphere behind the cloud: the picture equals the one drawn without
//    peeling for volumes (then VTK draws the translucent geometry first and
//    the volume over it, which is right for a sphere behind), and the stages
//    rebuild no map;
// 2. the sphere in front of the cloud: the picture equals the sphere drawn
//    over the cloud's own picture (the cloud alone, as the renderer's
//    background texture), and differs from the one drawn without peeling
//    for volumes (the cloud over the sphere);
// 3. the interactive frame (a reduced image) in peeling, by a mapper that
//    has drawn in peeling only: reduced, close to the still one;
// 4. a maximum intensity projection in peeling, the sphere behind: the
//    picture drawn without peeling for volumes, and no warning;
// 5. a coloured extinction in peeling: drawn with the channels' mean
//    opacity, and said;
// 6. emission with next to no extinction (an 8-bit opacity of 0) between
//    two nested, nearly clear spheres: kept;
// 7. an opaque ball between the sun and the cloud, with the nested spheres:
//    its shadow in every stage (the later ones read the occluders' depth the
//    first drew);
// 8. a renderer viewport away from the window's origin;
// 9. a particle cloud (ETM, splatted) behind which the light moves while
//    peeling: its maps are rebuilt inside a stage (whose MAX blending the
//    splats must not inherit) and the picture equals the unpeeled one.
// VTK's own scene against vtkGPUVolumeRayCastMapper is in
// TestTransmittanceMapperVTKScenes (Geometry-DepthPeeling*).
#include "vtkActor.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkTexture.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestParticles.h"
#include "TyndallTestScene.h"

#include <cstdlib>
#include <iostream>
#include <string>

using tyndall_test::Check;

namespace
{
// The window's picture with the renderer's depth peeling for volumes, and
// without it; PSNR() between them. Peeling is left on.
struct PeeledAndUnpeeled
{
  vtkSmartPointer<vtkImageData> Peeled;
  vtkSmartPointer<vtkImageData> Unpeeled;
  double PSNR() const { return tyndall_test::PSNR(this->Peeled, this->Unpeeled); }
};

PeeledAndUnpeeled DrawBothWays(vtkRenderWindow* window, vtkRenderer* renderer)
{
  PeeledAndUnpeeled pictures;
  renderer->SetUseDepthPeelingForVolumes(true);
  window->Render();
  pictures.Peeled = tyndall_test::Grab(window);
  renderer->SetUseDepthPeelingForVolumes(false);
  window->Render();
  pictures.Unpeeled = tyndall_test::Grab(window);
  renderer->SetUseDepthPeelingForVolumes(true);
  return pictures;
}

// The renderer's picture with only the sphere drawn, over `background`.
vtkSmartPointer<vtkImageData> SphereOver(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkVolume* volume, vtkImageData* background)
{
  vtkNew<vtkTexture> texture;
  texture->SetInputData(background);
  texture->InterpolateOff();
  renderer->SetBackgroundTexture(texture);
  renderer->TexturedBackgroundOn();
  volume->VisibilityOff();
  window->Render();
  vtkSmartPointer<vtkImageData> picture = tyndall_test::Grab(window);
  volume->VisibilityOn();
  renderer->TexturedBackgroundOff();
  renderer->SetBackgroundTexture(nullptr);
  return picture;
}
}

int TestTransmittanceMapperDepthPeeling(int, char*[])
{
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  mapper->SetInputData(tyndall_test::MakeCloud(64));
  mapper->SetTransmittanceMethodToAdaptiveETM();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(tyndall_test::MakeCloudProperty(0.6));
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.2, 0.1, -2.2); // behind the cloud's box [-1, 1]^3
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  actor->GetProperty()->SetColor(0.2, 0.9, 0.3);
  actor->GetProperty()->SetOpacity(0.5);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->AddActor(actor);
  renderer->SetBackground(0.2, 0.3, 0.45);
  renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(8);
  renderer->SetOcclusionRatio(0.0);
  tyndall_test::SetTestCamera(renderer);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(200, 200);
  window->AddRenderer(renderer);

  // 1. The sphere behind.
  renderer->SetUseDepthPeelingForVolumes(false);
  window->Render();
  vtkSmartPointer<vtkImageData> unpeeled = tyndall_test::Grab(window);
  const int builds = mapper->GetMapBuildCount();
  renderer->SetUseDepthPeelingForVolumes(true);
  window->Render();
  vtkSmartPointer<vtkImageData> peeled = tyndall_test::Grab(window);
  const double behind = tyndall_test::PSNR(peeled, unpeeled);
  std::cout << "sphere behind: peeled against unpeeled " << behind << " dB\n";
  Check(behind >= 45.0, "the sphere behind: peeling draws the picture drawn without it");
  Check(mapper->GetMapBuildCount() == builds, "the peeling stages rebuild no map");
  Check(mapper->GetLightTransmittanceMethod(0) == vtkTransmittanceVolumeMapper::ADAPTIVE_ETM,
    "the maps' shadows in peeling");

  // 2. The sphere in front: over the cloud's own picture.
  actor->SetPosition(0.0, 0.0, 3.9); // centre at z = 1.7, the box ends at 1
  renderer->SetUseDepthPeelingForVolumes(false);
  actor->VisibilityOff();
  window->Render();
  vtkSmartPointer<vtkImageData> cloud = tyndall_test::Grab(window);
  actor->VisibilityOn();
  window->Render();
  unpeeled = tyndall_test::Grab(window);
  vtkSmartPointer<vtkImageData> expected = SphereOver(window, renderer, volume, cloud);
  renderer->SetUseDepthPeelingForVolumes(true);
  window->Render();
  peeled = tyndall_test::Grab(window);
  const double front = tyndall_test::PSNR(peeled, expected);
  const double wrong = tyndall_test::PSNR(unpeeled, expected);
  std::cout << "sphere in front: peeled against the sphere over the cloud " << front
            << " dB; unpeeled (the cloud over the sphere) " << wrong << " dB\n";
  Check(front >= 40.0, "the sphere in front: drawn over the cloud");
  Check(wrong < front - 6.0, "without peeling for volumes the picture differs");

  // 3. An interactive (reduced) frame in peeling, by a mapper that has
  //    drawn in peeling only: its cost is measured over a frame's stages.
  vtkNew<vtkTransmittanceVolumeMapper> fresh;
  fresh->SetInputData(mapper->GetInput());
  fresh->SetTransmittanceMethodToAdaptiveETM();
  volume->SetMapper(fresh);
  window->Render();
  window->Render(); // the first frame's stages, summed, are measured now
  vtkSmartPointer<vtkImageData> still = tyndall_test::Grab(window);
  window->SetDesiredUpdateRate(1000.0);
  window->Render();
  const int reduction = fresh->GetLastImageReduction();
  const double moving = tyndall_test::PSNR(tyndall_test::Grab(window), still);
  std::cout << "interactive frame in peeling: reduction " << reduction << ", " << moving
            << " dB against the still one; still against the first mapper's "
            << tyndall_test::PSNR(still, peeled) << " dB\n";
  Check(reduction > 1 && moving >= 25.0, "the reduced frame in peeling resembles the still one");
  Check(fresh->GetLastRayCastTime() > 0.0, "a peeled frame's camera rays are timed");
  window->SetDesiredUpdateRate(0.0001);
  volume->SetMapper(mapper);

  // 4. A maximum intensity projection in peeling, the sphere behind.
  actor->SetPosition(0.0, 0.0, 0.0);
  mapper->SetBlendModeToMaximumIntensity();
  vtkNew<vtkTest::ErrorObserver> messages;
  mapper->AddObserver(vtkCommand::WarningEvent, messages);
  const double projected = DrawBothWays(window, renderer).PSNR();
  std::cout << "maximum intensity, sphere behind: peeled against unpeeled " << projected << " dB\n";
  Check(projected >= 45.0, "a projection in peeling draws the picture drawn without it");
  Check(!messages->GetWarning(), "a projection in peeling: no warning");
  mapper->SetBlendModeToComposite();

  // 5. A coloured extinction in peeling: one warning, and the picture close
  //    to the unpeeled one (the sphere behind sees the channels' mean).
  auto* property = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  property->SetExtinctionColor(1.0, 0.5, 0.25);
  messages->Clear();
  window->Render();
  window->Render(); // said once
  const std::string said = messages->GetWarningMessage();
  const size_t first = said.find("coloured extinction");
  Check(
    first != std::string::npos && said.find("coloured extinction", first + 1) == std::string::npos,
    "a coloured extinction in peeling: one warning");
  const double chromatic = DrawBothWays(window, renderer).PSNR();
  std::cout << "coloured extinction, sphere behind: peeled against unpeeled " << chromatic
            << " dB\n";
  Check(chromatic >= 30.0, "a coloured extinction in peeling: close to the unpeeled picture");
  property->SetExtinctionColor(1.0, 1.0, 1.0);

  // 6. Emission with next to no extinction inside two nested, nearly clear
  //    spheres in the cloud: the light between them at the back reaches the
  //    pass's 8-bit back peels with an opacity under 1/510, which the pass
  //    drops unless raised; the nearly clear layers dim it by about 1 % each,
  //    so the picture is the unpeeled one (the cloud drawn over them).
  vtkNew<vtkColorTransferFunction> fire;
  fire->AddRGBPoint(0.0, 1.0, 0.5, 0.1);
  fire->AddRGBPoint(8.0, 1.0, 0.5, 0.1);
  property->SetEmissionColor(fire);
  property->SetEmissionScale(1.0e5);
  property->SetScalarOpacityUnitDistance(1.0e4);
  vtkNew<vtkActor> inner;
  inner->SetMapper(sphereMapper);
  for (vtkActor* shell : { actor.Get(), inner.Get() })
  {
    const double scale = shell == actor.Get() ? 0.7 : 0.35;
    shell->SetScale(scale); // about the origin: the centre moves with it
    shell->SetPosition(-0.2 * scale, -0.1 * scale, 2.2 * scale);
    shell->GetProperty()->SetOpacity(0.01);
  }
  renderer->AddActor(inner);
  const PeeledAndUnpeeled glow = DrawBothWays(window, renderer);
  const double emitted = glow.PSNR();
  volume->VisibilityOff();
  window->Render();
  const double glowing = tyndall_test::PSNR(glow.Unpeeled, tyndall_test::Grab(window));
  volume->VisibilityOn();
  std::cout << "emission, next to no extinction, in nested spheres: peeled against unpeeled "
            << emitted << " dB (the picture without the volume: " << glowing << " dB)\n";
  Check(glowing < 30.0, "the emission shows");
  Check(emitted >= 40.0, "emission without extinction in peeling");
  property->SetEmissionColor(nullptr);
  property->SetEmissionScale(0.0);
  property->SetScalarOpacityUnitDistance(0.05);

  // 7. An opaque ball between the sun and the cloud: its shadow falls on the
  //    cloud inside the nested spheres too, drawn in the later stages, which
  //    read the occluders' depth the first stage drew.
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0.95, 0.5, 0.3);
  ball->SetRadius(0.3);
  vtkNew<vtkPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(ball->GetOutputPort());
  vtkNew<vtkActor> blocker;
  blocker->SetMapper(ballMapper);
  renderer->AddActor(blocker);
  const PeeledAndUnpeeled shadowed = DrawBothWays(window, renderer);
  const double occluded = shadowed.PSNR();
  blocker->VisibilityOff();
  renderer->SetUseDepthPeelingForVolumes(false);
  window->Render();
  const double shadow = tyndall_test::PSNR(shadowed.Unpeeled, tyndall_test::Grab(window));
  std::cout << "an opaque occluder, nested spheres: peeled against unpeeled " << occluded
            << " dB (the picture without the occluder: " << shadow << " dB)\n";
  Check(shadow < 30.0, "the occluder's shadow shows");
  Check(occluded >= 40.0, "the occluders' shadow in every peeling stage");
  renderer->RemoveActor(blocker);
  renderer->RemoveActor(inner);
  actor->SetScale(1.0);
  actor->SetPosition(0.0, 0.0, 0.0);
  actor->GetProperty()->SetOpacity(0.5);
  renderer->SetUseDepthPeelingForVolumes(true);

  // 8. A viewport away from the window's origin, the sphere behind.
  renderer->SetViewport(0.35, 0.2, 1.0, 0.9);
  const double offset = DrawBothWays(window, renderer).PSNR();
  std::cout << "viewport away from the origin: peeled against unpeeled " << offset << " dB\n";
  Check(offset >= 45.0, "a viewport away from the window's origin in peeling");
  renderer->SetViewport(0.0, 0.0, 1.0, 1.0);

  // 9. Particles' maps rebuilt in a peeling stage.
  vtkNew<vtkTransmittanceParticleMapper> particles;
  particles->SetInputData(tyndall_test::MakeParticles(1500));
  particles->SetTransmittanceMethodToETM();
  particles->SetSplatting(true);
  volume->SetMapper(particles);
  vtkLight* sun = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
  window->Render(); // peeling on
  const int splatted = particles->GetMapBuildCount();
  sun->SetPosition(-1.0, 0.8, 0.5); // the maps are rebuilt in the first stage
  window->Render();
  Check(particles->GetMapBuildCount() == splatted + 1, "the light's move rebuilds the maps once");
  const double rebuilt = DrawBothWays(window, renderer).PSNR(); // the maps built in peeling
  std::cout << "particles, maps rebuilt in peeling: against unpeeled " << rebuilt << " dB\n";
  Check(rebuilt >= 45.0, "particles' maps splatted in a peeling stage are right");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
