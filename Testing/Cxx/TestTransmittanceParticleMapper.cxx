// vtkTransmittanceParticleMapper: a particle cloud rendered as a medium.
// 1. The splatted extinction maps against their CPU twin: every texel of the
//    GPU's ETM map (a directional and a positional light, the volume turned
//    and stretched so that the particles are ellipsoids in the world) against
//    vtkParticleKernel::AddExtinctionCoefficients summed over the particles
//    along the same light ray (vtkTransmittanceLightFrustum::GetRay); the
//    march of the particles' grid is printed beside it, and is far less exact;
// 2. the picture against the CPU reference, which integrates the particles'
//    exact sum (no grid): every method above its floor, ETM splatted and
//    marched;
// 3. particles and an image volume shadow each other: a particle cloud between
//    the sun and a cloud volume, GPU (ETM: splatted into the maps the volume
//    is lit by) against the CPU reference; the same without scene shadows is
//    measurably different;
// 4. coloured particles: the exact albedo (the colours weighted by the
//    particles' extinctions) against a sum over every particle, and the
//    picture against the CPU reference, which the same cloud without its
//    colours misses by far;
//    coloured particles inside a cloud volume drawn as one medium, either
//    drawing the group, against the CPU reference;
// 5. bad particle clouds are errors and draw nothing.
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCullerCollection.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkParticleKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSingleScatteringReference.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallParticles.h"
#include "vtkTyndallSceneReader.h"
#include "vtkVolume.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestParticles.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace
{
using tyndall_test::Check;
using M = vtkTransmittanceVolumeMapper;

struct ParticleScene
{
  vtkNew<vtkTransmittanceParticleMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  ParticleScene(vtkPolyData* particles, int size)
  {
    this->Mapper->SetInputData(particles);
    this->Mapper->JitterOff();
    this->Mapper->SetTransmittanceMapSize(128);
    this->Mapper->SetNumberOfCoefficients(8);
    // The particles' maps and pictures against the CPU, not the camera
    // rays' transmittance cache (on by default; TestTransmittanceMapper-
    // TransmittanceCache checks it): its 256^3 lattices were 25 of the
    // test's 127 s. ColouredGroup() turns it on (coloured particles drawing
    // the group, and as the cloud's guests, read with it against the CPU:
    // 15 s more). Without it every PSNR moved by 0.03 dB at most.
    this->Mapper->TransmittanceCacheOff();
    auto property = tyndall_test::MakeCloudProperty();
    property->SetAmbientIntensity(0.1);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    tyndall_test::SetTestCamera(this->Renderer);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
  }

  // The CPU reference's picture (the particles' exact sum).
  vtkSmartPointer<vtkImageData> Cpu()
  {
    vtkNew<vtkSingleScatteringReference> reference;
    const int* size = this->Window->GetSize();
    if (!reference->Render(this->Renderer, this->Volume, size[0], size[1]))
    {
      return nullptr;
    }
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(reference->Composite());
    return image;
  }

  double Psnr(vtkImageData* cpu)
  {
    this->Window->Render();
    vtkSmartPointer<vtkImageData> gpu = tyndall_test::Grab(this->Window);
    return cpu ? tyndall_test::PSNR(gpu, cpu) : -1.0;
  }
};

// The 64^3 test cloud as a volume of scale `scale` (AdaptiveETM, maps 128^2).
struct CloudVolume
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property = tyndall_test::MakeCloudProperty();

  explicit CloudVolume(double scale)
  {
    this->Mapper->SetInputData(tyndall_test::MakeCloud(64));
    this->Mapper->JitterOff();
    this->Mapper->SetTransmittanceMapSize(128);
    this->Mapper->TransmittanceCacheOff(); // as ParticleScene's
    this->Property->SetAmbientIntensity(0.1);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Volume->SetScale(scale);
  }
};

// The largest difference between light 0's ETM map and the closed-form sum,
// relative to the map's largest coefficient.
double MapError(ParticleScene& scene, vtkPolyData* particles)
{
  vtkNew<vtkImageData> map;
  if (!scene.Mapper->GetTransmittanceMap(0, map))
  {
    return std::numeric_limits<double>::infinity();
  }
  const tyndall_test::ExactMap exact =
    tyndall_test::ExactEtmMap(scene.Mapper, scene.Renderer, scene.Volume, particles, map, 1);
  return exact.LargestError(map);
}

// 1. The splatted maps against the closed form.
void SplattedMaps()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(1500);
  ParticleScene scene(particles, 96);
  scene.Volume->RotateX(20.0);
  scene.Volume->RotateY(35.0);
  scene.Volume->SetScale(1.0, 0.8, 1.25);
  scene.Mapper->SetTransmittanceMethodToETM();
  scene.Mapper->SetLightSampleCount(256);
  vtkSmartPointer<vtkLight> sun = tyndall_test::MakeSun(1.0, 0.5, 0.3);
  scene.Renderer->AddLight(sun);
  for (int positional = 0; positional < 2; ++positional)
  {
    if (positional)
    {
      sun->SetPositional(true);
      sun->SetConeAngle(90.0);
      sun->SetPosition(2.5, 1.5, 1.0);
    }
    scene.Mapper->SplattingOn();
    scene.Window->Render();
    const double splatted = MapError(scene, particles);
    scene.Mapper->SplattingOff();
    scene.Window->Render();
    const double marched = MapError(scene, particles);
    std::cout << (positional ? "positional" : "directional")
              << " light: ETM map against the closed form, splatted " << splatted
              << ", marched on the 128^3 grid " << marched << " (of the largest coefficient)\n";
    Check(splatted < 2e-5, "the splatted map equals the closed form");
    Check(marched > 10.0 * splatted, "the marched grid is measurably less exact");
  }
}

// 2. The picture against the CPU reference.
void Pictures()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(3000);
  ParticleScene scene(particles, 96);
  scene.Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  scene.Mapper->SetGridResolution(64);
  scene.Mapper->SetLightSampleCount(128);
  struct Case
  {
    const char* Name;
    int Method;
    bool Splatting;
    double Floor;
  };
  // Floors a little under what llvmpipe measured (48.8, 40.3, 40.3, 44.3, 40.3 dB).
  const Case cases[] = { { "BruteForce", M::BRUTE_FORCE, true, 47.5 },
    { "ETM, splatted", M::ETM, true, 39.5 }, { "ETM, grid marched", M::ETM, false, 39.5 },
    { "AdaptiveETM", M::ADAPTIVE_ETM, true, 43.5 }, { "TFM", M::TFM, true, 39.5 } };
  scene.Window->Render();
  const vtkSmartPointer<vtkImageData> cpu = scene.Cpu();
  for (const Case& c : cases)
  {
    scene.Mapper->SetTransmittanceMethod(c.Method);
    scene.Mapper->SetSplatting(c.Splatting);
    const double psnr = scene.Psnr(cpu);
    std::cout << "3000 particles, " << c.Name << ": GPU vs CPU " << psnr << " dB (floor " << c.Floor
              << ")\n";
    Check(psnr >= c.Floor, std::string(c.Name) + " above its floor");
  }
}

// Colours for `particles`: red-orange on one side of x = 0, blue on the other.
void AddColors(vtkPolyData* particles)
{
  vtkNew<vtkDoubleArray> colors;
  colors->SetName("color");
  colors->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < particles->GetNumberOfPoints(); ++i)
  {
    const bool left = particles->GetPoint(i)[0] < 0.0;
    colors->InsertNextTuple3(left ? 0.95 : 0.2, left ? 0.4 : 0.45, left ? 0.2 : 0.95);
  }
  particles->GetPointData()->AddArray(colors);
}

// The path tracer's one bounce against the single-scattering reference:
// both sample the particles exactly (delta tracking needs a majorant above
// the particles' sum, vtkTyndallParticles::GetDensityBound()).
void PathTracer()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(3000);
  AddColors(particles); // both renderers read the particles' colours
  ParticleScene scene(particles, 32);
  scene.Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  scene.Mapper->SetGridResolution(64);
  vtkNew<vtkSingleScatteringReference> reference;
  reference->Render(scene.Renderer, scene.Volume, 32, 32);
  vtkNew<vtkVolumetricPathTracer> tracer;
  tracer->SetDistanceSamplingToDeltaTracking();
  tracer->SetMaximumBounces(1);
  tracer->SetSamplesPerPixel(256);
  vtkImageData* traced = tracer->Render(scene.Renderer, scene.Volume, 32, 32);
  // Per channel (the colours tint them differently): Radiance is RGB.
  double sums[2][3] = { { 0.0, 0.0, 0.0 }, { 0.0, 0.0, 0.0 } };
  vtkImageData* images[2] = { reference->GetOutput(), traced };
  for (int k = 0; k < 2; ++k)
  {
    const std::vector<double> values = tyndall_test::RadianceValues(images[k]);
    for (size_t i = 0; i < values.size(); ++i)
    {
      sums[k][i % 3] += values[i];
    }
  }
  double ratio[3];
  for (int c = 0; c < 3; ++c)
  {
    ratio[c] = sums[0][c] > 0.0 ? sums[1][c] / sums[0][c] : 0.0;
  }
  std::cout << "path tracer (1 bounce, delta tracking, majorant " << tracer->GetLastMajorant()
            << ") / single-scattering reference, coloured particles, mean radiance R G B: "
            << ratio[0] << " " << ratio[1] << " " << ratio[2] << " (reference red / blue "
            << sums[0][0] / sums[0][2] << ")\n";
  Check(std::abs(ratio[0] - 1.0) < 0.02 && std::abs(ratio[1] - 1.0) < 0.02 &&
      std::abs(ratio[2] - 1.0) < 0.02,
    "the path tracer's one bounce equals single scattering, channel by channel");
}

// 3. A particle cloud above a cloud volume, the sun above both.
void SharedShadows()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(2000, 11);
  ParticleScene scene(particles, 96);
  scene.Mapper->SetGridResolution(64);
  scene.Volume->SetPosition(0.0, 0.9, 0.0);
  CloudVolume cloudVolume(0.7);
  vtkVolume* cloud = cloudVolume.Volume;
  vtkTransmittanceVolumeMapper* cloudMapper = cloudVolume.Mapper;
  vtkParticipatingMediumProperty* cloudProperty = cloudVolume.Property;
  cloud->SetPosition(0.0, -1.0, 0.0);
  scene.Renderer->AddVolume(cloud);
  scene.Renderer->GetCullers()->InitTraversal();
  vtkFrustumCoverageCuller::SafeDownCast(scene.Renderer->GetCullers()->GetNextItem())
    ->SetSortingStyleToBackToFront();
  scene.Renderer->AddLight(tyndall_test::MakeSun(0.2, 1.0, 0.3));
  scene.Renderer->GetActiveCamera()->SetViewAngle(45.0);
  scene.Renderer->ResetCameraClippingRange();
  vtkSmartPointer<vtkImageData> withShadows[2];
  vtkSmartPointer<vtkImageData> cpu;
  for (int method : { M::ETM, M::ADAPTIVE_ETM })
  {
    scene.Mapper->SetTransmittanceMethod(method);
    cloudMapper->SetTransmittanceMethod(method);
    scene.Window->Render();
    withShadows[method == M::ETM ? 0 : 1] = tyndall_test::Grab(scene.Window);
  }
  // The CPU reference: each volume's picture (lit through the other), composited.
  vtkNew<vtkSingleScatteringReference> top, bottom;
  top->Render(scene.Renderer, scene.Volume, 96, 96);
  bottom->Render(scene.Renderer, cloud, 96, 96);
  cpu = tyndall_test::CompositeFrontToBack(
    { top->GetOutput(), bottom->GetOutput() }, scene.Renderer->GetBackground());
  const double etm = tyndall_test::PSNR(withShadows[0], cpu);
  const double adaptive = tyndall_test::PSNR(withShadows[1], cpu);
  cloudProperty->SceneShadowsOff();
  vtkParticipatingMediumProperty::SafeDownCast(scene.Volume->GetProperty())->SceneShadowsOff();
  scene.Window->Render();
  vtkSmartPointer<vtkImageData> alone = tyndall_test::Grab(scene.Window);
  const double wrong = tyndall_test::PSNR(alone, cpu);
  std::cout << "particles over a cloud volume, GPU vs CPU: ETM (splatted) " << etm
            << " dB, AdaptiveETM " << adaptive << " dB; each lit alone " << wrong
            << " dB (largest difference " << tyndall_test::MaxDifference(alone, cpu) << ")\n";
  // Floors a little under what llvmpipe measured (37.9 and 41.8 dB).
  Check(etm >= 37.0, "ETM: the particles' shadow on the volume");
  Check(adaptive >= 40.5, "AdaptiveETM: the particles' shadow on the volume");
  Check(wrong < etm - 5.0, "without shared shadows the picture is measurably wrong");
}

// 4. Coloured particles.
void Colors()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(3000);
  AddColors(particles);
  // The exact albedo against a sum over every particle, at random points.
  vtkTyndallParticles medium;
  std::string error;
  Check(medium.Update(particles, error) && medium.HasColors(), "coloured particles are read");
  vtkDataArray* radius = particles->GetPointData()->GetArray("radius");
  vtkDataArray* density = particles->GetPointData()->GetArray("density");
  vtkDataArray* colors = particles->GetPointData()->GetArray("color");
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.9, 0.9);
  double largest = 0.0;
  int inside = 0;
  for (int n = 0; n < 500; ++n)
  {
    const double x[3] = { coordinate(random), coordinate(random), coordinate(random) };
    double sum = 0.0, weighted[3] = { 0.0, 0.0, 0.0 }, color[3];
    for (vtkIdType i = 0; i < particles->GetNumberOfPoints(); ++i)
    {
      const double* c = particles->GetPoint(i);
      const double k =
        vtkParticleKernel::Extinction(std::sqrt(vtkMath::Distance2BetweenPoints(x, c)),
          radius->GetTuple1(i), density->GetTuple1(i));
      sum += k;
      for (int a = 0; a < 3; ++a)
      {
        weighted[a] += k * colors->GetComponent(i, a);
      }
    }
    const double d = medium.Density(x, color);
    largest = std::max(largest, std::abs(d - sum) / std::max(sum, 1.0));
    if (sum > 0.0)
    {
      ++inside;
      for (int a = 0; a < 3; ++a)
      {
        largest = std::max(largest, std::abs(color[a] - weighted[a] / sum));
      }
    }
  }
  std::cout << "coloured particles: density and albedo against the sum over every particle, "
            << inside << " of 500 points in the medium, largest error " << largest << "\n";
  Check(inside > 100 && largest < 1e-12, "the albedo is the extinction-weighted colour");

  // The picture against the CPU reference (exact colours); the same cloud
  // without colours against it.
  ParticleScene scene(particles, 96);
  scene.Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
  scene.Mapper->SetGridResolution(64);
  scene.Window->Render();
  const vtkSmartPointer<vtkImageData> cpu = scene.Cpu();
  const double etm = scene.Psnr(cpu);
  scene.Mapper->SetTransmittanceMethod(M::ADAPTIVE_ETM);
  const double adaptive = scene.Psnr(cpu);
  auto plain = vtkSmartPointer<vtkPolyData>::New();
  plain->DeepCopy(particles);
  plain->GetPointData()->RemoveArray("color");
  scene.Mapper->SetInputData(plain);
  const double uncoloured = scene.Psnr(cpu);
  scene.Mapper->SetInputData(particles); // and back: the colours' texture again
  const double again = scene.Psnr(cpu);
  std::cout << "3000 coloured particles, GPU vs CPU: ETM (splatted) " << etm << " dB, AdaptiveETM "
            << adaptive << " dB; without the colours " << uncoloured << " dB, coloured again "
            << again << " dB\n";
  // Floors a little under what llvmpipe measured.
  Check(again == adaptive, "the colours come back with the coloured input");
  Check(etm >= 39.5, "ETM: coloured particles against the CPU reference");
  Check(adaptive >= 43.0, "AdaptiveETM: coloured particles against the CPU reference");
  Check(uncoloured < etm - 10.0, "the colours show");
}

// 4b. Coloured particles inside a cloud volume, drawn as one medium with it
// (SceneCompositing): the group's camera rays read the particles' colours
// as a guest's or as their own, whichever volume draws the group.
void ColouredGroup()
{
  vtkSmartPointer<vtkPolyData> particles = tyndall_test::MakeParticles(2000, 5, 0.6);
  AddColors(particles);
  ParticleScene scene(particles, 96);
  scene.Mapper->SetGridResolution(64);
  scene.Mapper->SetTransmittanceMethod(M::ADAPTIVE_ETM);
  scene.Mapper->TransmittanceCacheOn(); // the default, as a user's: the guests' colours with it
  CloudVolume cloudVolume(0.8);
  cloudVolume.Mapper->TransmittanceCacheOn();
  vtkVolume* cloud = cloudVolume.Volume;
  vtkParticipatingMediumProperty* cloudProperty = cloudVolume.Property;
  scene.Renderer->AddLight(tyndall_test::MakeSun(0.6, 1.0, 0.4));
  auto* particleProperty =
    vtkParticipatingMediumProperty::SafeDownCast(scene.Volume->GetProperty());
  double psnr[2] = { 0.0, 0.0 };
  vtkSmartPointer<vtkImageData> cpu;
  for (int order = 0; order < 2; ++order)
  {
    // The particles drawing the group (first in the renderer), then the cloud.
    scene.Renderer->RemoveAllViewProps();
    scene.Renderer->AddVolume(order == 0 ? scene.Volume.Get() : cloud);
    scene.Renderer->AddVolume(order == 0 ? cloud : scene.Volume.Get());
    scene.Window->Render();
    vtkSmartPointer<vtkImageData> gpu = tyndall_test::Grab(scene.Window);
    if (!cpu)
    {
      // The CPU reference draws each volume with the other in its shadows,
      // whichever is first: one picture for both orders.
      vtkNew<vtkSingleScatteringReference> a, b;
      a->Render(scene.Renderer, scene.Volume, 96, 96);
      b->Render(scene.Renderer, cloud, 96, 96);
      cpu = tyndall_test::CompositeFrontToBack(
        { a->GetOutput(), b->GetOutput() }, scene.Renderer->GetBackground());
    }
    psnr[order] = tyndall_test::PSNR(gpu, cpu);
    if (order == 1)
    {
      // Drawn as layers instead: wrong where they interpenetrate.
      particleProperty->SceneCompositingOff();
      cloudProperty->SceneCompositingOff();
      scene.Window->Render();
      const double layers = tyndall_test::PSNR(tyndall_test::Grab(scene.Window), cpu);
      std::cout << "coloured particles inside a cloud volume, one medium, GPU vs CPU: the "
                   "particles draw "
                << psnr[0] << " dB, the cloud draws " << psnr[1] << " dB; as layers " << layers
                << " dB\n";
      Check(layers < psnr[1] - 5.0, "as layers the picture is measurably wrong");
    }
  }
  // Floors a little under what llvmpipe measured.
  Check(psnr[0] >= 40.0, "coloured particles drawing the group");
  Check(psnr[1] >= 40.0, "the cloud drawing the group with coloured particles as its guest");
}

// 5. Bad particle clouds.
void BadInput()
{
  vtkSmartPointer<vtkPolyData> good = tyndall_test::MakeParticles(10);
  auto noRadius = vtkSmartPointer<vtkPolyData>::New();
  noRadius->DeepCopy(good);
  noRadius->GetPointData()->RemoveArray("radius");
  auto nanDensity = vtkSmartPointer<vtkPolyData>::New();
  nanDensity->DeepCopy(good);
  vtkDataArray::SafeDownCast(nanDensity->GetPointData()->GetArray("density"))
    ->SetTuple1(3, std::nan(""));
  auto zeroRadius = vtkSmartPointer<vtkPolyData>::New();
  zeroRadius->DeepCopy(good);
  vtkDataArray::SafeDownCast(zeroRadius->GetPointData()->GetArray("radius"))->SetTuple1(0, 0.0);
  auto twoComponents = vtkSmartPointer<vtkPolyData>::New();
  twoComponents->DeepCopy(good);
  vtkNew<vtkDoubleArray> rg;
  rg->SetName("color");
  rg->SetNumberOfComponents(2);
  rg->SetNumberOfTuples(good->GetNumberOfPoints());
  rg->Fill(0.5);
  twoComponents->GetPointData()->AddArray(rg);
  auto tooBright = vtkSmartPointer<vtkPolyData>::New();
  tooBright->DeepCopy(good);
  AddColors(tooBright);
  vtkDataArray::SafeDownCast(tooBright->GetPointData()->GetArray("color"))->SetComponent(4, 1, 1.5);
  vtkNew<vtkPolyData> empty;
  for (vtkPolyData* bad : { noRadius.Get(), nanDensity.Get(), zeroRadius.Get(), twoComponents.Get(),
         tooBright.Get(), static_cast<vtkPolyData*>(empty.Get()) })
  {
    ParticleScene scene(bad, 64);
    scene.Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
    vtkNew<vtkTest::ErrorObserver> errors;
    scene.Mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    scene.Window->Render();
    vtkSmartPointer<vtkImageData> picture = tyndall_test::Grab(scene.Window);
    scene.Volume->VisibilityOff();
    scene.Window->Render();
    vtkSmartPointer<vtkImageData> background = tyndall_test::Grab(scene.Window);
    // The first message's text, after "vtkTransmittanceParticleMapper (0x...): "
    // (the observer appends every error: one per render).
    const std::string message = errors->GetErrorMessage();
    const size_t at = message.find("): ");
    const size_t begin = at == std::string::npos ? 0 : at + 3;
    std::cout << "bad cloud: " << message.substr(begin, message.find('\n', begin) - begin) << "\n";
    Check(errors->GetError(), "a bad particle cloud is an error");
    Check(tyndall_test::MaxDifference(picture, background) == 0, "and draws nothing");
  }
}
}

int TestTransmittanceParticleMapper(int, char*[])
{
  // One X connection open throughout: Xvfb resets when its last client
  // leaves, and a window opened during the reset fails ("bad X server
  // connection"); each scene's window opens and closes its own.
  vtkNew<vtkRenderWindow> keeper;
  keeper->SetSize(8, 8);
  keeper->Render();
  auto time = [](const char* what, void (*f)())
  {
    const auto start = std::chrono::steady_clock::now();
    f();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    std::cout << what << ": " << seconds.count() << " s\n";
  };
  time("maps", SplattedMaps);
  time("pictures", Pictures);
  time("shared shadows", SharedShadows);
  time("path tracer", PathTracer);
  time("colours", Colors);
  time("coloured group", ColouredGroup);
  BadInput();
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
