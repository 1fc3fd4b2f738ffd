// vtkCosineNoiseSource: values equal the noise times the envelope, a
// streamed image assembled from pieces equals the whole bit for bit, the
// same seed gives the same output, progress is reported, a Transform on the
// noise is honoured.
#include "TyndallTestCheck.h"
#include "vtkCallbackCommand.h"
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using tyndall_test::Check;

float ValueAt(vtkImageData* image, int i, int j, int k)
{
  return *static_cast<float*>(image->GetScalarPointer(i, j, k));
}

void OnProgress(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* values = static_cast<std::vector<double>*>(clientData);
  values->push_back(static_cast<vtkAlgorithm*>(caller)->GetProgress());
}
}

int TestCosineNoiseSource(int, char*[])
{
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(-3, 40, 0, 30, 2, 25); // x rows cross several 16-voxel blocks
  source->SetOrigin(-1.1, -0.9, -0.8);
  source->SetSpacing(0.05, 0.06, 0.07);
  source->Update();
  vtkImageData* whole = source->GetOutput();
  int dims[3];
  whole->GetDimensions(dims);
  Check(dims[0] == 44 && dims[1] == 31 && dims[2] == 24, "dimensions follow the extent");
  auto* scalars = vtkFloatArray::SafeDownCast(whole->GetPointData()->GetScalars());
  Check(scalars && std::string(scalars->GetName()) == "density", "float scalars named density");
  if (!scalars)
  {
    return EXIT_FAILURE;
  }
  double range[2];
  scalars->GetRange(range);
  std::cout << "density range " << range[0] << " .. " << range[1] << "\n";
  Check(range[0] >= 0.0 && range[1] > 0.5, "non-negative density with a visible cloud");

  // 1. Values: envelope * max(0, noise), against direct evaluation.
  vtkCosineNoise* noise = source->GetNoise();
  double worst = 0.0;
  const int* e = whole->GetExtent();
  for (int k = e[4]; k <= e[5]; ++k)
  {
    for (int j = e[2]; j <= e[3]; ++j)
    {
      for (int i = e[0]; i <= e[1]; ++i)
      {
        double x[3] = { -1.1 + 0.05 * i, -0.9 + 0.06 * j, -0.8 + 0.07 * k };
        const double expected =
          source->EvaluateEnvelope(x) * std::max(0.0, noise->EvaluateFunction(x));
        worst = std::max(worst, std::abs(ValueAt(whole, i, j, k) - expected));
      }
    }
  }
  std::cout << "max abs difference to direct evaluation " << worst << "\n";
  Check(worst < 1e-5 * std::max(1.0, range[1]), "voxel values equal the noise times the envelope");

  // 2. Streaming: pieces (split inside x blocks too) equal the whole exactly.
  vtkNew<vtkImageData> copy;
  copy->DeepCopy(whole);
  const int pieces[][6] = { { -3, 5, 0, 30, 2, 25 }, { 6, 21, 0, 12, 2, 25 },
    { 6, 21, 13, 30, 2, 10 }, { 6, 21, 13, 30, 11, 25 }, { 22, 40, 0, 30, 2, 25 } };
  size_t mismatches = 0, compared = 0;
  for (const auto& piece : pieces)
  {
    source->Modified(); // otherwise the executive reuses the whole image
    source->UpdateExtent(piece);
    vtkImageData* out = source->GetOutput();
    const int* pe = out->GetExtent();
    Check(std::equal(pe, pe + 6, piece), "the output covers exactly the requested piece");
    for (int k = piece[4]; k <= piece[5]; ++k)
    {
      for (int j = piece[2]; j <= piece[3]; ++j)
      {
        for (int i = piece[0]; i <= piece[1]; ++i)
        {
          ++compared;
          mismatches += ValueAt(out, i, j, k) != ValueAt(copy, i, j, k) ? 1 : 0;
        }
      }
    }
  }
  Check(compared == static_cast<size_t>(44 * 31 * 24), "pieces tile the whole extent");
  Check(mismatches == 0, "streamed pieces are bit-identical to the whole image");

  // 3. Same seed, same output; another seed, another output.
  {
    vtkNew<vtkCosineNoiseSource> a, b;
    a->SetWholeExtent(54, 74, 54, 74, 54, 74); // the centre of the default cloud
    b->SetWholeExtent(54, 74, 54, 74, 54, 74);
    a->Update();
    b->Update();
    auto* va = vtkFloatArray::SafeDownCast(a->GetOutput()->GetPointData()->GetScalars());
    Check(va->GetRange()[1] > 0.0, "the centre of the default cloud is not empty");
    auto* vb = vtkFloatArray::SafeDownCast(b->GetOutput()->GetPointData()->GetScalars());
    Check(
      std::equal(va->GetPointer(0), va->GetPointer(0) + va->GetNumberOfValues(), vb->GetPointer(0)),
      "same seed, same image");
    b->GetNoise()->SetSeed(99);
    b->Update();
    vb = vtkFloatArray::SafeDownCast(b->GetOutput()->GetPointData()->GetScalars());
    Check(!std::equal(
            va->GetPointer(0), va->GetPointer(0) + va->GetNumberOfValues(), vb->GetPointer(0)),
      "changing the noise's seed re-executes the source with other values");
  }

  // 4. Progress events, ending at 1.
  {
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(OnProgress);
    callback->SetClientData(&progress);
    vtkNew<vtkCosineNoiseSource> s;
    s->SetWholeExtent(0, 31, 0, 31, 0, 31);
    s->AddObserver(vtkCommand::ProgressEvent, callback);
    s->Update();
    Check(progress.size() >= 5 && progress.back() == 1.0, "progress reported up to 1");
    Check(std::is_sorted(progress.begin(), progress.end()), "progress never decreases");
  }

  // 5. A Transform on the noise is honoured; no envelope, signed values.
  {
    vtkNew<vtkCosineNoiseSource> s;
    s->SetWholeExtent(0, 9, 0, 7, 0, 5);
    s->SetEnvelopeTypeToNone();
    s->ClampNegativeOff();
    s->GetNoise()->SetOffset(0.0);
    vtkNew<vtkTransform> transform;
    transform->RotateZ(30.0);
    transform->Translate(0.2, 0.0, -0.1);
    s->GetNoise()->SetTransform(transform);
    s->Update();
    double err = 0.0, minimum = 1e30;
    for (int k = 0; k <= 5; ++k)
    {
      for (int j = 0; j <= 7; ++j)
      {
        for (int i = 0; i <= 9; ++i)
        {
          double x[3] = { -1.0 + 2.0 / 127.0 * i, -1.0 + 2.0 / 127.0 * j, -1.0 + 2.0 / 127.0 * k };
          const double expected = s->GetNoise()->FunctionValue(x);
          const float v = ValueAt(s->GetOutput(), i, j, k);
          err = std::max(err, std::abs(v - expected));
          minimum = std::min<double>(minimum, v);
        }
      }
    }
    Check(err < 1e-5 * std::max(1.0, std::abs(minimum)), "the noise's Transform is applied");
    Check(minimum < 0.0, "ClampNegative off keeps negative values");
  }

  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
