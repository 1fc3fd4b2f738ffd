// The transmittance maps the GPU builds against their CPU twin. For every map
// method (TFM, adaptive TFM, ETM, adaptive ETM), a directional and a
// positional light, and three media with known profiles (a homogeneous box:
// constant extinction along every ray; a linear ramp; the built-in cloud),
// the mapper's maps are read back (GetTransmittanceMap) and every texel is
// compared with vtkTransmittanceMapMath::Project() run on the CPU along the
// same light ray (vtkTransmittanceLightFrustum::GetRay, the CPU twin of the
// shader's tyndallLightRay) through the same medium (vtkTyndallGridMedium's
// Extinction, the twin of tyndallExtinction): the coefficients, the adaptive
// bounds and the transmittance they reconstruct.
//
// The test can fail: the CPU twin with a half-sample slip in the march
// (what a GLSL slip of the kind that costs 1-2 dB would do) must exceed the
// tolerances, and does (the slip's error is printed beside the real one).
//
// Every texel is compared. A texel whose adaptive decisions sit within float
// rounding of a threshold (the first march's transmittance within 1e-4 of
// AdaptiveThreshold, or the first extinct sample's extinction below 1e-6 of
// the medium's maximum) may be decided differently by float and double: such
// a texel may differ (it is counted, and must stay rare); any other may not.
//
// Measured on Mesa llvmpipe: coefficients within 7e-6 of the map's largest
// coefficient, bounds identical, T_beyond and T(s) within 1.4e-5; no texel
// differs; a half-sample slip exceeds the tolerances below 100 times or more.
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallSceneReader.h"
#include "vtkVolume.h"

#include "TyndallTestCheck.h"
#include "TyndallTestScene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using M = vtkTransmittanceMapMath;
using tyndall_test::Check;

// The texel ray's segment inside the medium's box: kIn and D (0 if it misses).
void Segment(const vtkTyndallGridMedium& medium, const double o[3], const double d[3],
  double kIn[3], double& length)
{
  const double* w2i = medium.GetWorldToIndex();
  double po[3], pd[3];
  for (int r = 0; r < 3; ++r)
  {
    po[r] = w2i[4 * r] * o[0] + w2i[4 * r + 1] * o[1] + w2i[4 * r + 2] * o[2] + w2i[4 * r + 3];
    pd[r] = w2i[4 * r] * d[0] + w2i[4 * r + 1] * d[1] + w2i[4 * r + 2] * d[2];
  }
  double t0 = -VTK_DOUBLE_MAX, t1 = VTK_DOUBLE_MAX;
  for (int a = 0; a < 3; ++a)
  {
    const double lo = medium.GetBoxLow()[a], hi = medium.GetBoxHigh()[a];
    if (pd[a] == 0.0)
    {
      if (po[a] < lo || po[a] > hi)
      {
        t1 = -VTK_DOUBLE_MAX;
      }
      continue;
    }
    double ta = (lo - po[a]) / pd[a], tb = (hi - po[a]) / pd[a];
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  length = t1 > t0 ? t1 - t0 : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    kIn[k] = o[k] + t0 * d[k];
  }
}

// The maps' size (texels per side).
constexpr int kMapSize = 40;

struct Errors
{
  double Coefficients = 0.0;  // max |GPU - CPU| / the map's largest |coefficient|
  double Bounds = 0.0;        // max |s_min|, |s_max| difference (compared texels)
  double TBeyond = 0.0;       // max |T_beyond| difference
  double Transmittance = 0.0; // max |T_GPU(s) - T_CPU(s)| at s = 0.05, 0.15, ..., 0.95
  int Skipped = 0;            // texels on a threshold that differ
  int Texels = 0;
  // The first texel over a tolerance, if any, with its errors (what a rare
  // failure of earlier sessions left no trace of).
  int Failed = -1;
  double FailedErrors[4] = { 0.0, 0.0, 0.0, 0.0 };
};

// Compares light 0's map with the CPU twin; `slip` shifts the CPU's samples
// by that fraction of a step (0: the true twin).
Errors Compare(vtkTransmittanceVolumeMapper* mapper, const vtkTyndallGridMedium& medium,
  double maxExtinction, double slip, const Errors& tolerances)
{
  Errors e;
  vtkNew<vtkImageData> map;
  if (!mapper->GetTransmittanceMap(0, map))
  {
    e.Coefficients = VTK_DOUBLE_MAX;
    return e;
  }
  const int method = mapper->GetTransmittanceMethod();
  const bool adaptive = M::IsAdaptiveMethod(method);
  const int count = mapper->GetNumberOfCoefficients();
  const int samples = mapper->GetLightSampleCount();
  const double threshold = mapper->GetAdaptiveThreshold();
  vtkDataArray* gpu = map->GetPointData()->GetArray("Coefficients");
  vtkDataArray* gpuBounds = map->GetPointData()->GetArray("Bounds");
  vtkTransmittanceLightFrustum* frustum = mapper->GetLightFrustum(0);
  const int size = map->GetDimensions()[0];
  std::vector<double> cpu(static_cast<size_t>(size) * size * count);
  std::vector<double> cpuBounds(static_cast<size_t>(size) * size * 3);
  std::vector<char> skip(static_cast<size_t>(size) * size, 0);
  double scale = 0.0;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const int t = j * size + i;
      double o[3], d[3], kIn[3], length;
      frustum->GetRay((i + 0.5) / size, (j + 0.5) / size, o, d);
      Segment(medium, o, d, kIn, length);
      std::function<double(double)> sigma = [&](double s)
      {
        const double u = std::min(1.0, s + slip / samples);
        const double x[3] = { kIn[0] + u * length * d[0], kIn[1] + u * length * d[1],
          kIn[2] + u * length * d[2] };
        return length > 0.0 ? medium.WorldExtinction(x) : 0.0;
      };
      const double D = length > 0.0 ? length : 1.0; // a missed ray: T = 1
      M::Project(method, sigma, D, samples, count, threshold, &cpu[t * count], &cpuBounds[3 * t]);
      if (adaptive)
      {
        // Decisions within float rounding of a threshold are not compared.
        double a[16], b[3], c[16], dd[3], f[16], g[3];
        std::function<double(double)> clipped = [&](double s)
        {
          const double v = sigma(s);
          return v > 1e-6 * maxExtinction ? v : 0.0;
        };
        M::Project(method, sigma, D, samples, count, threshold * (1.0 + 1e-4), a, b);
        M::Project(method, sigma, D, samples, count, threshold * (1.0 - 1e-4), c, dd);
        M::Project(method, clipped, D, samples, count, threshold, f, g);
        skip[t] = b[0] != dd[0] || b[1] != dd[1] || g[0] != cpuBounds[3 * t] ||
          g[1] != cpuBounds[3 * t + 1];
      }
      for (int k = 0; k < count; ++k)
      {
        scale = std::max(scale, std::abs(cpu[t * count + k]));
      }
    }
  }
  for (int t = 0; t < size * size; ++t)
  {
    ++e.Texels;
    Errors texel;
    double g[16], bounds[3] = { 0.0, 1.0, 1.0 };
    for (int k = 0; k < count; ++k)
    {
      g[k] = gpu->GetComponent(t, k);
      texel.Coefficients =
        std::max(texel.Coefficients, std::abs(g[k] - cpu[t * count + k]) / scale);
    }
    if (adaptive)
    {
      for (int c = 0; c < 3; ++c)
      {
        bounds[c] = gpuBounds->GetComponent(t, c);
      }
      texel.Bounds = std::max(
        std::abs(bounds[0] - cpuBounds[3 * t]), std::abs(bounds[1] - cpuBounds[3 * t + 1]));
      texel.TBeyond = std::abs(bounds[2] - cpuBounds[3 * t + 2]);
    }
    for (int k = 0; k < 10; ++k)
    {
      const double s = 0.05 + 0.1 * k;
      texel.Transmittance = std::max(texel.Transmittance,
        std::abs(M::Reconstruct(method, g, count, bounds, s) -
          M::Reconstruct(method, &cpu[t * count], count, &cpuBounds[3 * t], s)));
    }
    const bool differs = texel.Coefficients > tolerances.Coefficients ||
      texel.Bounds > tolerances.Bounds || texel.TBeyond > tolerances.TBeyond ||
      texel.Transmittance > tolerances.Transmittance;
    if (differs && skip[t])
    {
      ++e.Skipped;
      continue;
    }
    if (differs && e.Failed < 0)
    {
      e.Failed = t;
      const double errors[4] = { texel.Coefficients, texel.Bounds, texel.TBeyond,
        texel.Transmittance };
      std::copy(errors, errors + 4, e.FailedErrors);
    }
    e.Coefficients = std::max(e.Coefficients, texel.Coefficients);
    e.Bounds = std::max(e.Bounds, texel.Bounds);
    e.TBeyond = std::max(e.TBeyond, texel.TBeyond);
    e.Transmittance = std::max(e.Transmittance, texel.Transmittance);
  }
  return e;
}

// A homogeneous box: constant scalars over [-1, 1]^3.
vtkSmartPointer<vtkImageData> MakeBox()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(16, 16, 16);
  image->SetSpacing(2.0 / 15, 2.0 / 15, 2.0 / 15);
  image->SetOrigin(-1.0, -1.0, -1.0);
  image->AllocateScalars(VTK_FLOAT, 1);
  image->GetPointData()->GetScalars()->Fill(6.0);
  return image;
}

// A linear ramp in x: the scalar is 4 (x + 1).
vtkSmartPointer<vtkImageData> MakeRamp()
{
  auto image = MakeBox();
  for (int k = 0; k < 16; ++k)
  {
    for (int j = 0; j < 16; ++j)
    {
      for (int i = 0; i < 16; ++i)
      {
        image->SetScalarComponentFromDouble(i, j, k, 0, 8.0 * i / 15.0);
      }
    }
  }
  return image;
}
}

int TestTransmittanceMapperMaps(int, char*[])
{
  struct Medium
  {
    const char* Name;
    vtkSmartPointer<vtkImageData> Data;
    double PeakOpacity;
  };
  const Medium media[] = { { "box", MakeBox(), 0.3 }, { "ramp", MakeRamp(), 0.5 },
    { "cloud", tyndall_test::MakeCloud(32), 0.5 } };
  Errors tolerances;
  tolerances.Coefficients = 5e-5;
  tolerances.Bounds = 1e-6;
  tolerances.TBeyond = tolerances.Transmittance = 5e-5;
  const double tolCoefficients = tolerances.Coefficients, tolBounds = tolerances.Bounds,
               tolT = tolerances.Transmittance;
  double worst[4] = { 0.0, 0.0, 0.0, 0.0 }, slipBest = VTK_DOUBLE_MAX;
  int skipped = 0, texels = 0;

  for (const Medium& medium : media)
  {
    vtkNew<vtkTransmittanceVolumeMapper> mapper;
    // The maps are read back; the transmittance cache (on by default) drawn from
    // them is not what this test checks, and its 256^3 lattice was most of its time.
    mapper->TransmittanceCacheOff();
    mapper->SetInputData(medium.Data);
    mapper->SetTransmittanceMapSize(kMapSize);
    mapper->SetLightSampleCount(64);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(tyndall_test::MakeCloudProperty(medium.PeakOpacity));
    volume->RotateY(10.0);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    tyndall_test::SetTestCamera(renderer);
    vtkNew<vtkRenderWindow> window;
    window->SetMultiSamples(0);
    window->SetSize(32, 32);
    window->AddRenderer(renderer);

    // The CPU twin of the medium, read as the mapper reads it.
    vtkTyndallSceneReader scene;
    if (!scene.Update(renderer, volume, mapper))
    {
      std::cerr << "FAILED: the scene reader refused " << medium.Name << std::endl;
      return EXIT_FAILURE;
    }
    double maxExtinction = 0.0;
    for (double v : scene.GetMedium().GetTable().Extinction)
    {
      maxExtinction = std::max(maxExtinction, v * scene.GetMedium().GetParameters().DensityScale);
    }

    for (int positional = 0; positional < 2; ++positional)
    {
      renderer->RemoveAllLights();
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->SetPositional(positional);
      light->SetConeAngle(90.0);
      light->SetPosition(positional ? 3.0 : 1.0, positional ? 2.0 : 0.5, positional ? 2.5 : 0.3);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      renderer->AddLight(light);
      for (int method : { M::TFM, M::ADAPTIVE_TFM, M::ETM, M::ADAPTIVE_ETM })
      {
        mapper->SetTransmittanceMethod(method);
        // 8 coefficients fill two layers; 7 leave the last one partial.
        mapper->SetNumberOfCoefficients(method == M::ETM ? 7 : 8);
        window->Render();
        Check(mapper->GetLightTransmittanceMethod(0) == method, "the light has a map");
        const Errors e = Compare(mapper, scene.GetMedium(), maxExtinction, 0.0, tolerances);
        Errors lenient; // the slip's errors, every texel counted
        lenient.Coefficients = lenient.Bounds = lenient.TBeyond = lenient.Transmittance =
          VTK_DOUBLE_MAX;
        const Errors slipped = Compare(mapper, scene.GetMedium(), maxExtinction, 0.5, lenient);
        std::cout << medium.Name << (positional ? ", point light, " : ", directional light, ")
                  << M::GetMethodName(method) << ": coefficients " << e.Coefficients << ", bounds "
                  << e.Bounds << ", T_beyond " << e.TBeyond << ", T(s) " << e.Transmittance
                  << ", texels on a threshold that differ " << e.Skipped << "/" << e.Texels
                  << "; half-sample slip: coefficients " << slipped.Coefficients << ", T(s) "
                  << slipped.Transmittance << std::endl;
        if (e.Failed >= 0)
        {
          std::cout << "  FAILED texel " << e.Failed % kMapSize << ", " << e.Failed / kMapSize
                    << ": coefficients " << e.FailedErrors[0] << ", bounds " << e.FailedErrors[1]
                    << ", T_beyond " << e.FailedErrors[2] << ", T(s) " << e.FailedErrors[3]
                    << " (tolerances " << tolerances.Coefficients << ", " << tolerances.Bounds
                    << ", " << tolerances.TBeyond << ", " << tolerances.Transmittance << ")"
                    << std::endl;
        }
        worst[0] = std::max(worst[0], e.Coefficients);
        worst[1] = std::max(worst[1], e.Bounds);
        worst[2] = std::max(worst[2], e.TBeyond);
        worst[3] = std::max(worst[3], e.Transmittance);
        if (std::string(medium.Name) != "box") // a slip changes nothing in a constant medium
        {
          slipBest = std::min(slipBest,
            std::max(slipped.Coefficients / tolCoefficients, slipped.Transmittance / tolT));
        }
        skipped += e.Skipped;
        texels += e.Texels;
      }
    }
  }
  std::cout << "worst: coefficients " << worst[0] << " (tolerance " << tolCoefficients
            << "), bounds " << worst[1] << " (" << tolBounds << "), T_beyond " << worst[2] << " ("
            << tolT << "), T(s) " << worst[3] << " (" << tolT
            << "); texels on a threshold that differ " << skipped << " of " << texels
            << "; the smallest slip exceeds the tolerances " << slipBest << "x" << std::endl;
  Check(worst[0] <= tolCoefficients, "GPU coefficients match the CPU twin");
  Check(worst[1] <= tolBounds, "GPU adaptive bounds match the CPU twin");
  Check(worst[2] <= tolT, "GPU T_beyond matches the CPU twin");
  Check(worst[3] <= tolT, "GPU maps reconstruct the CPU twin's transmittance");
  Check(skipped <= texels / 100, "texels on a threshold are rare (at most 1%)");
  Check(slipBest > 10.0, "a half-sample slip of the march would fail this test");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
