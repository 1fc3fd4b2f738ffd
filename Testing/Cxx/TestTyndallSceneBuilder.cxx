// vtkTyndallSceneBuilder, the scene of every Tyndall program: the default
// scene (the cloud, its transfer function, the sun, the sky, the camera),
// a data volume (the guessed preset, the key light, a camera fitted to the
// data), the options applied to the medium and the mapper (also again after
// a viewer key), a transfer-function file with emission, given lights, and
// the errors (a missing volume, a bad transfer-function file, a degenerate
// camera). Nothing is rendered: no display is needed.
#include "TyndallTestCheck.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCosineNoise.h"
#include "vtkCullerCollection.h"
#include "vtkFloatArray.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallOptions.h"
#include "vtkTyndallSceneBuilder.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkXMLImageDataWriter.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

// Builds a renderer from a command line; nullptr (and the errors) on failure.
vtkSmartPointer<vtkRenderer> Build(vtkTyndallSceneBuilder* builder, std::vector<std::string> args,
  vtkTest::ErrorObserver* errors = nullptr)
{
  vtkNew<vtkTyndallOptions> options;
  args.insert(args.begin(), "program");
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  if (!options->Parse(static_cast<int>(argv.size()), argv.data()))
  {
    std::cerr << "bad command line: " << options->GetErrorMessage() << std::endl;
    return nullptr;
  }
  builder->SetOptions(options);
  if (errors)
  {
    builder->AddObserver(vtkCommand::ErrorEvent, errors);
  }
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  return builder->Build(renderer) ? renderer : nullptr;
}
}

int TestTyndallSceneBuilder(int, char*[])
{
  // The default scene.
  {
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder, { "-r", "16" });
    Check(renderer != nullptr, "the default scene builds");
    if (renderer)
    {
      vtkParticipatingMediumProperty* p = builder->GetProperty();
      vtkTransmittanceVolumeMapper* m = builder->GetMapper();
      Check(builder->GetDefaultScene() &&
          std::string(builder->GetTransferFunctionDescription()) == "white cloud",
        "the white cloud");
      Check(builder->GetImage()->GetNumberOfPoints() == 16 * 16 * 16, "-r 16: a 16^3 cloud");
      Check(p->GetScatteringAnisotropy() == 0.3 && p->GetAmbientIntensity() == 0.25 &&
          p->GetScatteringModel() == vtkParticipatingMediumProperty::SINGLE_SCATTERING &&
          p->GetScalarOpacityUnitDistance() == 0.05,
        "the default scene's medium (g 0.3, ambient 0.25)");
      vtkNew<vtkParticipatingMediumProperty> fresh;
      Check(p->GetScatteringOctaves() == fresh->GetScatteringOctaves() &&
          p->GetOctaveScattering() == fresh->GetOctaveScattering() &&
          p->GetOctaveExtinction() == fresh->GetOctaveExtinction() &&
          p->GetOctaveAnisotropy() == fresh->GetOctaveAnisotropy() &&
          p->GetOctaveBuildUp() == fresh->GetOctaveBuildUp(),
        "the options' octave defaults are the property's");
      Check(m->GetTransmittanceMethod() == vtkTransmittanceVolumeMapper::ADAPTIVE_ETM &&
          m->GetNumberOfCoefficients() == 8 && m->GetTransmittanceMapSize() == 256 &&
          m->GetJitter(),
        "adaptive ETM, 8 coefficients, 256^2 maps, jitter");
      Check(renderer->GetLights()->GetNumberOfItems() == 1 && builder->GetKeyLight() &&
          builder->GetKeyLight()->GetIntensity() == 0.85 && renderer->GetGradientBackground(),
        "the low sun and the sky");
      double position[3];
      renderer->GetActiveCamera()->GetPosition(position);
      Check(position[1] == -0.6 && position[2] == 4.2, "the fixed view of the cloud");
      vtkCosineNoise* detail = p->GetDetailNoise();
      Check(detail && detail->GetNumberOfOctaves() == 4 && detail->GetOffset() == 1.0 &&
          std::abs(detail->GetStandardDeviation() - 0.5) < 1e-12,
        "the default scene is procedural: 4 octaves of detail, mean 1, contrast 0.5");
    }
  }

  // --no-detail: the voxelised cloud alone.
  {
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder, { "-r", "16", "--no-detail" });
    Check(renderer && !builder->GetProperty()->GetDetailNoise(), "--no-detail: no detail");
  }

  // The options reach the medium and the mapper; a viewer key is applied again.
  {
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder,
      { "-r", "16", "--method", "tfm", "--coefficients", "5", "--map-size", "64", "--density-scale",
        "2", "--anisotropy", "-0.3", "--ambient", "0.1", "--light-scale", "3", "--no-jitter",
        "--octaves", "3", "--octave-scattering", "0.7", "--octave-extinction", "0.2",
        "--octave-anisotropy", "0.1", "--octave-build-up", "2.5", "--model", "emission-absorption",
        "--light-direction", "0", "-1", "0", "--light-position", "2", "2", "2", "--light-intensity",
        "0.5", "--background", "1", "0", "0", "--view-angle", "45" });
    Check(renderer != nullptr, "a scene with every kind of option");
    if (renderer)
    {
      vtkParticipatingMediumProperty* p = builder->GetProperty();
      vtkTransmittanceVolumeMapper* m = builder->GetMapper();
      Check(m->GetTransmittanceMethod() == vtkTransmittanceVolumeMapper::TFM &&
          m->GetNumberOfCoefficients() == 5 && m->GetTransmittanceMapSize() == 64 &&
          !m->GetJitter(),
        "the mapper's options");
      Check(p->GetDensityScale() == 2.0 && p->GetScatteringAnisotropy() == -0.3 &&
          p->GetAmbientIntensity() == 0.1 && p->GetLightScale() == 3.0 &&
          p->GetScatteringOctaves() == 3 && p->GetOctaveScattering() == 0.7 &&
          p->GetOctaveExtinction() == 0.2 && p->GetOctaveAnisotropy() == 0.1 &&
          p->GetOctaveBuildUp() == 2.5 &&
          p->GetScatteringModel() == vtkParticipatingMediumProperty::EMISSION_ABSORPTION,
        "the medium's options");
      Check(renderer->GetLights()->GetNumberOfItems() == 2 && !renderer->GetGradientBackground() &&
          renderer->GetBackground()[0] == 1.0 &&
          renderer->GetActiveCamera()->GetViewAngle() == 45.0,
        "the lights, the background and the view angle given");
      vtkNew<vtkLightCollection> lights;
      renderer->GetLights()->InitTraversal();
      vtkLight* sun = renderer->GetLights()->GetNextItem();
      vtkLight* point = renderer->GetLights()->GetNextItem();
      double from[3];
      sun->GetPosition(from);
      Check(!sun->GetPositional() && from[1] == 1.0 && point->GetPositional() &&
          point->GetIntensity() == 0.5 && point->GetConeAngle() == 90.0,
        "a directional light travelling along -y, a point light");
      // What a viewer key does (vtkTyndallOptions::ApplyKey), then ApplyOptions().
      builder->GetOptions()->SetNumber("coefficients", 6);
      builder->GetOptions()->SetNumber("density-scale", 2.5);
      builder->ApplyOptions();
      Check(m->GetNumberOfCoefficients() == 6 && p->GetDensityScale() == 2.5,
        "changed options reach the mapper and the medium");
    }
  }

  // Clipping and cropping reach the mapper; the viewer's key moves the plane.
  {
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder,
      { "-r", "16", "--clip-normal", "0", "0", "2", "--clip-origin", "0", "0", "0.1",
        "--clip-offset", "0.1", "--crop-low", "-1", "-0.5", "-1", "--crop-high", "1", "0.5",
        "0.25" });
    Check(renderer != nullptr, "a clipped and cropped scene");
    if (renderer)
    {
      vtkTransmittanceVolumeMapper* m = builder->GetMapper();
      vtkPlaneCollection* planes = m->GetClippingPlanes();
      const double diagonal = 2.0 * std::sqrt(3.0); // the cloud fills [-1, 1]^3
      bool plane = planes && planes->GetNumberOfItems() == 1;
      if (plane)
      {
        const double* n = planes->GetItem(0)->GetNormal();
        const double* o = planes->GetItem(0)->GetOrigin();
        plane = n[0] == 0.0 && n[1] == 0.0 && n[2] == 1.0 && o[0] == 0.0 &&
          std::abs(o[2] - (0.1 + 0.1 * diagonal)) < 1e-12;
      }
      Check(plane, "--clip-normal, --clip-origin, --clip-offset: one unit-normal plane, offset");
      double crop[6];
      m->GetCroppingRegionPlanes(crop);
      Check(m->GetCropping() && crop[0] == -1.0 && crop[1] == 1.0 && crop[2] == -0.5 &&
          crop[3] == 0.5 && crop[4] == -1.0 && crop[5] == 0.25 &&
          m->GetCroppingRegionFlags() == VTK_CROP_SUBVOLUME,
        "--crop-low, --crop-high: the subvolume");
      // What the viewer's 'o' key does (vtkTyndallOptions::ApplyKey: 0.1 - 0.05).
      builder->GetOptions()->SetNumber("clip-offset", 0.05);
      builder->ApplyOptions();
      Check(planes->GetNumberOfItems() == 1 &&
          std::abs(planes->GetItem(0)->GetOrigin()[2] - (0.1 + 0.05 * diagonal)) < 1e-12,
        "a new --clip-offset moves the plane (ApplyOptions)");
    }
  }

  // The viewer's clip keys without --clip-normal: a plane of normal +x
  // through the centre, moved by the offset; none before a key is pressed.
  {
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder, { "-r", "16" });
    Check(renderer != nullptr, "a scene without clipping");
    if (renderer)
    {
      vtkTransmittanceVolumeMapper* m = builder->GetMapper();
      Check(!m->GetClippingPlanes() || m->GetClippingPlanes()->GetNumberOfItems() == 0,
        "no clipping plane before a key");
      // What the viewer's 'p' key does (vtkTyndallOptions::ApplyKey: 0 + 0.05;
      // TestTyndallOptions checks the key itself).
      builder->GetOptions()->SetNumber("clip-offset", 0.05);
      builder->ApplyOptions();
      vtkPlaneCollection* planes = m->GetClippingPlanes();
      const double diagonal = 2.0 * std::sqrt(3.0);
      bool plane = planes && planes->GetNumberOfItems() == 1;
      if (plane)
      {
        const double* n = planes->GetItem(0)->GetNormal();
        const double* o = planes->GetItem(0)->GetOrigin();
        plane = n[0] == 1.0 && n[1] == 0.0 && n[2] == 0.0 &&
          std::abs(o[0] - 0.05 * diagonal) < 1e-12 && o[1] == 0.0 && o[2] == 0.0;
      }
      Check(plane, "'p' alone: a plane of normal +x, 5 % of the diagonal past the centre");
    }
  }

  // A data volume: the guessed preset, the key light, a fitted camera.
  {
    vtkNew<vtkImageData> blob;
    blob->SetDimensions(10, 12, 8);
    blob->SetSpacing(1.0, 1.0, 2.0);
    blob->SetOrigin(5.0, 0.0, 0.0);
    vtkNew<vtkFloatArray> density;
    density->SetName("density");
    density->SetNumberOfTuples(960);
    for (int i = 0; i < 960; ++i)
    {
      density->SetValue(i, static_cast<float>((i * 37) % 50) / 10.0f);
    }
    blob->GetPointData()->SetScalars(density);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName("TestTyndallSceneBuilder-blob.vti");
    writer->Write();
    vtkNew<vtkTyndallSceneBuilder> builder;
    auto renderer = Build(builder, { "TestTyndallSceneBuilder-blob.vti" });
    Check(renderer != nullptr, "a data volume builds");
    if (renderer)
    {
      vtkParticipatingMediumProperty* p = builder->GetProperty();
      Check(!builder->GetDefaultScene() &&
          std::string(builder->GetTransferFunctionDescription()) == "preset Cloud (guessed)",
        "a float density: the Cloud preset, guessed");
      Check(std::abs(p->GetScalarOpacityUnitDistance() - 4.0 / 3.0) < 1e-12,
        "the preset's unit distance is the mean spacing");
      Check(p->GetScatteringAnisotropy() == 0.0 && p->GetAmbientIntensity() == 0.2 &&
          !renderer->GetGradientBackground() && renderer->GetBackground()[0] == 0.0 &&
          builder->GetKeyLight()->GetIntensity() == 0.7,
        "data: g 0, ambient 0.2, a key light of 0.7, black");
      double focal[3], light[3];
      renderer->GetActiveCamera()->GetFocalPoint(focal);
      builder->GetKeyLight()->GetFocalPoint(light);
      Check(std::abs(focal[0] - 9.5) < 1e-9 && std::abs(focal[2] - 7.0) < 1e-9 &&
          std::abs(light[0] - 9.5) < 1e-9,
        "the camera and the key light aim at the data's centre");
    }
    vtkNew<vtkTyndallSceneBuilder> preset;
    Check(Build(preset, { "--preset", "mr", "TestTyndallSceneBuilder-blob.vti" }) != nullptr &&
        std::string(preset->GetTransferFunctionDescription()) == "preset mr",
      "--preset names the preset");

    // A transfer-function file with emission, and --emission-scale.
    std::ofstream("TestTyndallSceneBuilder.tf")
      << "opacity 0 0\nopacity 5 0.5\ncolor 0 1 0 0\nemission 0 0 0 1\nunit-distance 2\n";
    vtkNew<vtkTyndallSceneBuilder> file;
    auto withFile = Build(file,
      { "--transfer-function", "TestTyndallSceneBuilder.tf", "--emission-scale", "3",
        "TestTyndallSceneBuilder-blob.vti" });
    Check(withFile != nullptr && file->GetProperty()->GetScalarOpacityUnitDistance() == 2.0 &&
        file->GetProperty()->GetEmissionScale() == 3.0 && file->GetProperty()->GetEmissionColor(),
      "a transfer-function file with emission");
    if (withFile)
    {
      double emission[3];
      file->GetProperty()->GetEmissionColor()->GetColor(1.0, emission);
      Check(emission[2] == 1.0 && emission[0] == 0.0, "the file's emission colour, not its colour");
    }

    // Several volumes: the cloud moved by --position, the blob twice beside
    // it, each with its placement, transfer function and density; the same
    // mapper settings; sorted back to front; the camera fits all of them.
    vtkNew<vtkTyndallSceneBuilder> several;
    auto scene = Build(several,
      { "-r", "16", "--position", "-1", "0", "0", "--method", "tfm", "--add-volume",
        "TestTyndallSceneBuilder-blob.vti", "--volume-position", "2", "0", "0", "--volume-scale",
        "0.1", "--volume-density-scale", "3", "--volume-transfer-function",
        "TestTyndallSceneBuilder.tf", "--add-volume", "TestTyndallSceneBuilder-blob.vti",
        "--volume-preset", "mr", "--no-scene-shadows", "--no-scene-compositing" });
    Check(scene != nullptr && several->GetNumberOfAddedVolumes() == 2 &&
        scene->GetVolumes()->GetNumberOfItems() == 3,
      "two added volumes beside the cloud");
    if (scene && several->GetNumberOfAddedVolumes() == 2)
    {
      vtkVolume* added = several->GetAddedVolume(0);
      auto* property = vtkParticipatingMediumProperty::SafeDownCast(added->GetProperty());
      auto* mapper = vtkTransmittanceVolumeMapper::SafeDownCast(added->GetMapper());
      Check(several->GetVolume()->GetPosition()[0] == -1.0 && added->GetPosition()[0] == 2.0 &&
          added->GetScale()[0] == 0.1 && property && property->GetDensityScale() == 3.0 &&
          property->GetScalarOpacityUnitDistance() == 2.0 && !property->GetSceneShadows() &&
          !property->GetSceneCompositing() && mapper &&
          mapper->GetTransmittanceMethod() == vtkTransmittanceVolumeMapper::TFM,
        "the added volume's placement, density, transfer function and settings");
      scene->GetCullers()->InitTraversal();
      auto* culler = vtkFrustumCoverageCuller::SafeDownCast(scene->GetCullers()->GetNextItem());
      Check(culler && culler->GetSortingStyle() == VTK_CULLER_SORT_BACK_TO_FRONT,
        "several volumes are drawn back to front");
      double focal[3];
      scene->GetActiveCamera()->GetFocalPoint(focal);
      Check(focal[0] > 0.0, "the camera fits every volume (its focus moves towards the blobs)");
    }
  }

  // Errors.
  {
    vtkNew<vtkTest::ErrorObserver> errors;
    vtkNew<vtkTyndallSceneBuilder> builder;
    Check(!Build(builder, { "no-such-volume.vti" }, errors) &&
        errors->GetErrorMessage().find("no-such-volume.vti: no such file") != std::string::npos,
      "a missing volume: an error naming it");
    errors->Clear();
    std::ofstream("TestTyndallSceneBuilder-bad.tf") << "opacity 0 2\n";
    vtkNew<vtkTyndallSceneBuilder> bad;
    Check(!Build(bad, { "--transfer-function", "TestTyndallSceneBuilder-bad.tf" }, errors) &&
        errors->GetErrorMessage().find("TestTyndallSceneBuilder-bad.tf:1: alpha must be") !=
          std::string::npos,
      "a bad transfer-function file: the file and line");
    errors->Clear();
    vtkNew<vtkTyndallSceneBuilder> camera;
    Check(!Build(camera,
            { "-r", "8", "--camera-position", "0", "0", "0", "--focal-point", "0", "0", "0" },
            errors) &&
        errors->GetErrorMessage().find("the camera position and the focal point coincide") !=
          std::string::npos,
      "a degenerate camera");
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
