// The scene rules of Documentation/rendering-model.md ("What is read from the
// scene"), each on both renderers: the GPU mapper (brute force, the in-shader
// reference) and the CPU reference read the scene through the same reader,
// so for every rule they must agree with each other (PSNR floors, measured
// on Mesa llvmpipe and set a little under) and show the rule's effect:
//
// - NaN scalars are missing data: a column of NaN voxels is a hole through
//   which the background shows, on both;
// - +-Inf take the finite range's ends;
// - a direction matrix is honoured: the same picture as turning the volume;
// - the mapper's scalar selection (SelectScalarArray) picks the array;
// - a gray transfer function (one colour channel) gives grey;
// - a directional light without a direction is ignored with a warning;
// - lights beyond the eighth are ignored with a warning.
//
// Measured (llvmpipe, 96 x 96): 51.4 to 53.4 dB between the renderers.
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkSingleScatteringReference.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"
#include "TyndallTestScene.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
constexpr int kSize = 96;
using tyndall_test::Check;

// A volume, its renderer and window, and the CPU reference.
struct Scene
{
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property = tyndall_test::MakeCloudProperty(0.3);
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkSingleScatteringReference> Reference;
  vtkNew<vtkTest::ErrorObserver> MapperMessages;
  vtkNew<vtkTest::ErrorObserver> ReferenceMessages;

  Scene()
  {
    this->Mapper->SetTransmittanceMethodToBruteForce();
    this->Mapper->SetLightSampleCount(96);
    this->Mapper->JitterOff();
    this->Property->SetAmbientIntensity(0.1);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.45);
    this->Renderer->AutomaticLightCreationOff();
    this->Renderer->AddLight(tyndall_test::MakeSun(1.0, 0.5, 0.3));
    tyndall_test::SetTestCamera(this->Renderer);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(kSize, kSize);
    this->Window->AddRenderer(this->Renderer);
    this->Reference->SetLightStepSize(0.02);
    for (unsigned long event : { vtkCommand::ErrorEvent, vtkCommand::WarningEvent })
    {
      this->Mapper->AddObserver(event, this->MapperMessages);
      this->Reference->AddObserver(event, this->ReferenceMessages);
    }
  }

  // The GPU's picture.
  vtkSmartPointer<vtkImageData> GPU()
  {
    this->Window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(this->Window);
    grab->ReadFrontBufferOff();
    grab->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(grab->GetOutput());
    return image;
  }

  // The CPU reference's picture (8 bits, over the background).
  vtkSmartPointer<vtkImageData> CPU()
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    if (this->Reference->Render(this->Renderer, this->Volume, kSize, kSize))
    {
      image->DeepCopy(this->Reference->Composite());
    }
    return image;
  }
};

// Both pictures, their PSNR checked against `floor`.
void Compare(Scene& scene, const std::string& what, double floor,
  vtkSmartPointer<vtkImageData>& gpu, vtkSmartPointer<vtkImageData>& cpu)
{
  gpu = scene.GPU();
  cpu = scene.CPU();
  const double psnr = tyndall_test::PSNR(gpu, cpu);
  std::cout << what << ": GPU vs CPU " << psnr << " dB (floor " << floor << ")" << std::endl;
  Check(psnr >= floor, what + ": the GPU and the CPU reference agree");
}

const unsigned char* Pixel(vtkImageData* image, int i, int j)
{
  return static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
}

// A 24^3 medium over [-1, 1]^3: a ball of scalar 8 fading to 0.
vtkSmartPointer<vtkImageData> MakeBall()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(24, 24, 24);
  image->SetSpacing(2.0 / 23, 2.0 / 23, 2.0 / 23);
  image->SetOrigin(-1.0, -1.0, -1.0);
  vtkNew<vtkFloatArray> values;
  values->SetName("ball");
  values->SetNumberOfTuples(24 * 24 * 24);
  for (int k = 0; k < 24; ++k)
  {
    for (int j = 0; j < 24; ++j)
    {
      for (int i = 0; i < 24; ++i)
      {
        const double x = -1.0 + 2.0 * i / 23, y = -1.0 + 2.0 * j / 23, z = -1.0 + 2.0 * k / 23;
        const double r = std::sqrt(x * x + y * y + z * z);
        values->SetValue(i + 24 * (j + 24 * k), static_cast<float>(8.0 * std::max(0.0, 1.0 - r)));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}
}

int TestTransmittanceMapperSceneRules(int, char*[])
{
  Scene scene;
  vtkSmartPointer<vtkImageData> gpu, cpu;

  // NaN: a column of missing voxels along z through the ball's centre. The
  // scalars are lifted by 2, so that the smallest finite one is not empty
  // medium either: replacing NaN by the minimum would fill the hole.
  {
    auto ball = MakeBall();
    auto* values = vtkFloatArray::SafeDownCast(ball->GetPointData()->GetScalars());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetValue(i, values->GetValue(i) + 2.0f);
    }
    for (int k = 0; k < 24; ++k)
    {
      for (int j = 10; j < 14; ++j)
      {
        for (int i = 10; i < 14; ++i)
        {
          values->SetValue(i + 24 * (j + 24 * k), std::numeric_limits<float>::quiet_NaN());
        }
      }
    }
    values->SetValue(0, std::numeric_limits<float>::infinity());
    scene.Mapper->SetInputData(ball);
    Compare(scene, "NaN column and an Inf voxel", 48.0, gpu, cpu);
    Check(scene.MapperMessages->GetWarning() && scene.ReferenceMessages->GetWarning() &&
        scene.MapperMessages->GetWarningMessage().find("384 NaN scalars") != std::string::npos &&
        scene.ReferenceMessages->GetWarningMessage().find("and 1 infinite") != std::string::npos,
      "both renderers warn about the non-finite scalars");
    // The hole: the background shows through the ball's centre on both.
    const unsigned char* bg = Pixel(gpu, kSize / 2, kSize / 2);
    const unsigned char* bgCpu = Pixel(cpu, kSize / 2, kSize / 2);
    Check(std::abs(bg[2] - 115) <= 2 && std::abs(bgCpu[2] - 115) <= 2,
      "the NaN column is a hole on both renderers (background blue 0.45 = 115)");
    scene.MapperMessages->Clear();
    scene.ReferenceMessages->Clear();
  }

  // A direction matrix against the same turn of the volume.
  {
    auto ball = MakeBall();
    auto* values = vtkFloatArray::SafeDownCast(ball->GetPointData()->GetScalars());
    for (int i = 0; i < 24 * 24 * 24; ++i)
    {
      values->SetValue(
        i, values->GetValue(i) * ((i / 24) % 24 < 12 ? 1.0f : 0.4f)); // lopsided in y
    }
    ball->SetOrigin(-1.0, 1.0, 1.0);
    ball->SetDirectionMatrix(1, 0, 0, 0, -1, 0, 0, 0, -1); // 180 degrees about x
    scene.Mapper->SetInputData(ball);
    vtkSmartPointer<vtkImageData> byDirection, byDirectionCpu;
    Compare(scene, "direction matrix", 48.0, byDirection, byDirectionCpu);
    auto plain = vtkSmartPointer<vtkImageData>::New();
    plain->DeepCopy(ball);
    plain->SetOrigin(-1.0, -1.0, -1.0);
    plain->SetDirectionMatrix(1, 0, 0, 0, 1, 0, 0, 0, 1);
    scene.Mapper->SetInputData(plain);
    scene.Volume->RotateX(180.0);
    vtkSmartPointer<vtkImageData> byVolume, byVolumeCpu;
    Compare(scene, "the same turn by the volume's matrix", 48.0, byVolume, byVolumeCpu);
    scene.Volume->RotateX(-180.0);
    const double gpuSame = tyndall_test::PSNR(byDirection, byVolume);
    const double cpuSame = tyndall_test::PSNR(byDirectionCpu, byVolumeCpu);
    std::cout << "direction matrix vs volume matrix: GPU " << gpuSame << " dB, CPU " << cpuSame
              << " dB" << std::endl;
    Check(gpuSame >= 50.0 && cpuSame >= 50.0,
      "a direction matrix renders as the same turn of the volume, on both");
  }

  // The mapper's array selection.
  {
    auto ball = MakeBall();
    vtkNew<vtkFloatArray> shell;
    shell->SetName("shell");
    shell->SetNumberOfTuples(ball->GetNumberOfPoints());
    auto* values = vtkFloatArray::SafeDownCast(ball->GetPointData()->GetScalars());
    for (vtkIdType i = 0; i < shell->GetNumberOfTuples(); ++i)
    {
      const float v = values->GetValue(i);
      shell->SetValue(i, v > 1.0f && v < 3.0f ? 8.0f : 0.0f);
    }
    ball->GetPointData()->AddArray(shell);
    scene.Mapper->SetInputData(ball);
    vtkSmartPointer<vtkImageData> active, activeCpu;
    Compare(scene, "the active scalars", 48.0, active, activeCpu);
    scene.Mapper->SetScalarModeToUsePointFieldData();
    scene.Mapper->SelectScalarArray("shell");
    Compare(scene, "SelectScalarArray(\"shell\")", 48.0, gpu, cpu);
    Check(tyndall_test::PSNR(gpu, active) < 35.0 && tyndall_test::PSNR(cpu, activeCpu) < 35.0,
      "the selected array is the one rendered, on both");
    scene.Mapper->SetScalarModeToDefault();
  }

  // A gray transfer function.
  {
    scene.Mapper->SetInputData(MakeBall());
    vtkNew<vtkPiecewiseFunction> gray;
    gray->AddPoint(0.0, 0.3);
    gray->AddPoint(8.0, 0.9);
    scene.Property->SetColor(gray);
    Compare(scene, "gray transfer function", 48.0, gpu, cpu);
    // Over a black background (the blue one would tint the thin parts), with
    // a white sun: every pixel grey.
    scene.Renderer->SetBackground(0.0, 0.0, 0.0);
    gpu = scene.GPU();
    cpu = scene.CPU();
    int colourful = 0;
    for (vtkImageData* image : { gpu.Get(), cpu.Get() })
    {
      for (int j = 0; j < kSize; ++j)
      {
        for (int i = 0; i < kSize; ++i)
        {
          const unsigned char* p = Pixel(image, i, j);
          colourful += (std::abs(p[0] - p[1]) > 1 || std::abs(p[1] - p[2]) > 1) ? 1 : 0;
        }
      }
    }
    Check(colourful == 0, "a gray transfer function gives grey on both renderers");
    scene.Renderer->SetBackground(0.2, 0.3, 0.45);
    scene.Property->SetColor(tyndall_test::MakeCloudProperty()->GetRGBTransferFunction());
  }

  // A directional light without a direction, and lights beyond the eighth.
  {
    vtkSmartPointer<vtkImageData> oneLight, oneLightCpu;
    Compare(scene, "one sun", 48.0, oneLight, oneLightCpu);
    vtkNew<vtkLight> degenerate;
    degenerate->SetPositional(false);
    degenerate->SetPosition(0.3, 0.3, 0.3);
    degenerate->SetFocalPoint(0.3, 0.3, 0.3);
    scene.Renderer->AddLight(degenerate);
    Compare(scene, "with a light that has no direction", 48.0, gpu, cpu);
    Check(scene.MapperMessages->GetWarning() && scene.ReferenceMessages->GetWarning() &&
        scene.MapperMessages->GetWarningMessage().find("no direction") != std::string::npos &&
        scene.ReferenceMessages->GetWarningMessage().find("no direction") != std::string::npos,
      "both renderers warn about the light without a direction");
    Check(tyndall_test::PSNR(gpu, oneLight) == std::numeric_limits<double>::infinity() &&
        tyndall_test::PSNR(cpu, oneLightCpu) == std::numeric_limits<double>::infinity(),
      "the light without a direction is ignored, on both");
    scene.Renderer->RemoveLight(degenerate);
    scene.MapperMessages->Clear();
    scene.ReferenceMessages->Clear();
    for (int l = 0; l < 7; ++l)
    {
      scene.Renderer->AddLight(tyndall_test::MakeSun(std::cos(l), 0.5, std::sin(l), 0.1));
    }
    vtkSmartPointer<vtkImageData> eight, eightCpu;
    Compare(scene, "eight lights", 48.0, eight, eightCpu);
    scene.Renderer->AddLight(tyndall_test::MakeSun(0.0, -1.0, 0.0, 1.0));
    scene.Renderer->AddLight(tyndall_test::MakeSun(0.0, 0.0, 1.0, 1.0));
    Compare(scene, "ten lights", 48.0, gpu, cpu);
    Check(scene.MapperMessages->GetWarningMessage().find("2 light(s) beyond the first 8") !=
          std::string::npos &&
        scene.ReferenceMessages->GetWarningMessage().find("2 light(s) beyond the first 8") !=
          std::string::npos,
      "both renderers warn about the lights beyond the eighth");
    Check(tyndall_test::PSNR(gpu, eight) == std::numeric_limits<double>::infinity() &&
        tyndall_test::PSNR(cpu, eightCpu) == std::numeric_limits<double>::infinity(),
      "lights beyond the eighth are ignored, on both");
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
