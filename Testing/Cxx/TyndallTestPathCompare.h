// The path-tracing tests' comparison of the GPU's 8-bit picture with the CPU
// tracer's (TestTransmittanceMapperPathTrace, TestTransmittanceMapperSky):
// MakeCpuTracer() is a PathScene's CPU twin (the mapper's distance sampling
// and bounce limit); PathComparison scores the picture's sums against expected
// values, each pixel's variance the CPU tracer's noise, `Pictures` of them
// (its radiance's standard error squared plus bg^2 T (1 - T) / n for the
// view transmittance's escapes; their negative covariance left out: a
// larger variance) and an 8-bit rounding's 1/12 level^2, per picture.
// Header only; not part of the library.
#ifndef TyndallTestPathCompare_h
#define TyndallTestPathCompare_h

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumetricPathTracer.h"

#include "TyndallTestCheck.h"
#include "TyndallTestPathScene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace tyndall_test
{
inline vtkSmartPointer<vtkVolumetricPathTracer> MakeCpuTracer(PathScene& scene, int samples)
{
  auto tracer = vtkSmartPointer<vtkVolumetricPathTracer>::New();
  // The mapper's distance sampling: procedural detail in closed form or
  // tracked; a grid (no closed form) tracked.
  const bool closedForm = scene.Property->GetDetailNoise() &&
    scene.Mapper->GetPathTraceDistanceSampling() ==
      vtkTransmittanceVolumeMapper::PATH_DISTANCE_CLOSED_FORM;
  tracer->SetDistanceSampling(
    closedForm ? vtkVolumetricPathTracer::CLOSED_FORM : vtkVolumetricPathTracer::DELTA_TRACKING);
  tracer->SetSamplesPerPixel(samples);
  tracer->SetMaximumBounces(scene.Mapper->GetPathTraceMaximumBounces());
  return tracer;
}

struct PathComparison
{
  vtkImageData* Picture;                          // the GPU's, 8-bit
  vtkImageData* Traced;                           // the CPU tracer's output
  const double* Background;                       // the renderer's
  int Samples;                                    // the CPU tracer's per pixel
  int Pictures;                                   // the pictures whose noise counts (1 or 2)
  std::function<double(vtkIdType, int)> Expected; // pixel p's channel c
  std::function<bool(vtkIdType)> Selected;        // the pixels compared (null: all)

  // The z score of the sum of channel c over the pixels [x0, x1) x [y0, y1)
  // (those Selected).
  double Z(int x0, int y0, int x1, int y1, int c, double* difference = nullptr) const
  {
    int dims[3];
    this->Picture->GetDimensions(dims);
    vtkDataArray* E = this->Traced->GetPointData()->GetArray("RadianceStandardError");
    vtkDataArray* T = this->Traced->GetPointData()->GetArray("Transmittance");
    const auto* pixels = static_cast<unsigned char*>(this->Picture->GetScalarPointer());
    const int components = this->Picture->GetNumberOfScalarComponents();
    const double rounding = 1.0 / (12.0 * 255.0 * 255.0);
    const double* bg = this->Background;
    const int tc = T->GetNumberOfComponents() == 3 ? c : 0; // per channel: a coloured extinction
    double sum = 0.0, variance = 0.0;
    for (int y = y0; y < y1; ++y)
    {
      for (int x = x0; x < x1; ++x)
      {
        const vtkIdType p = static_cast<vtkIdType>(y) * dims[0] + x;
        if (this->Selected && !this->Selected(p))
        {
          continue;
        }
        const double t = T->GetComponent(p, tc);
        sum += pixels[p * components + c] / 255.0 - this->Expected(p, c);
        variance += this->Pictures *
          (std::pow(E->GetComponent(p, c), 2) + bg[c] * bg[c] * t * (1.0 - t) / this->Samples +
            rounding);
      }
    }
    if (difference)
    {
      *difference = sum;
    }
    return sum / std::sqrt(variance);
  }

  // The worst |z| of the channels' sums over the whole picture (printed,
  // with `name`), and with `quadrants` over each quadrant too (light moved
  // within the picture keeps the whole sum).
  double WorstZ(const std::string& name, bool quadrants) const
  {
    int dims[3];
    this->Picture->GetDimensions(dims);
    const int w = dims[0], h = dims[1];
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      double difference = 0.0;
      const double z = this->Z(0, 0, w, h, c, &difference);
      std::cout << name << ", channel " << c << ": sums differ by " << difference << ", z " << z
                << std::endl;
      worst = std::max(worst, std::abs(z));
      for (int q = 0; quadrants && q < 4; ++q)
      {
        const int x0 = q % 2 ? w / 2 : 0, y0 = q / 2 ? h / 2 : 0;
        worst = std::max(worst, std::abs(this->Z(x0, y0, x0 + w / 2, y0 + h / 2, c)));
      }
    }
    return worst;
  }

  // The mean of z^2 over tiles of `tile` x `tile` pixels and the channels:
  // about 1 where the pictures agree (less where the variance is
  // overestimated), more where light moved within the picture.
  double TileChiSquare(int tile) const
  {
    int dims[3];
    this->Picture->GetDimensions(dims);
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y + tile <= dims[1]; y += tile)
    {
      for (int x = 0; x + tile <= dims[0]; x += tile)
      {
        for (int c = 0; c < 3; ++c)
        {
          sum += std::pow(this->Z(x, y, x + tile, y + tile, c), 2);
          ++count;
        }
      }
    }
    return count ? sum / count : 0.0;
  }
};

// Both tracers' pictures of a scene: the CPU tracer's output and the GPU's
// 8-bit picture, its shadows ratio tracked (the CPU's estimator), 16 paths
// per frame.
struct BothTraced
{
  vtkSmartPointer<vtkVolumetricPathTracer> Cpu; // owns Traced
  vtkImageData* Traced = nullptr;
  vtkSmartPointer<vtkImageData> Gpu;

  // Traces `scene` (size x size) at `samples` per pixel on both; false
  // (with a failed check naming `name`) when either does not render them.
  bool Trace(PathScene& scene, int samples, int size, const std::string& name)
  {
    // The map-based frame drawn before the paths is not compared: every
    // Tyndall volume's transmittance cache at its smallest lattice (a
    // shaded CT in a fog under a sun and a sky's four directions built a
    // 256^3 one for five lights in 3.8 s per mapper on llvmpipe; the
    // tracked paths read no map and no cache).
    vtkVolumeCollection* volumes = scene.Renderer->GetVolumes();
    volumes->InitTraversal();
    while (vtkVolume* volume = volumes->GetNextVolume())
    {
      if (auto* mapper = vtkTransmittanceVolumeMapper::SafeDownCast(volume->GetMapper()))
      {
        mapper->SetTransmittanceCacheSize(16);
      }
    }
    this->Cpu = MakeCpuTracer(scene, samples);
    this->Traced = this->Cpu->Render(scene.Renderer, scene.Volume, size, size);
    if (!this->Traced)
    {
      Check(false, name + ": the CPU tracer renders");
      return false;
    }
    scene.Mapper->SetPathTraceShadowsToTracked();
    scene.Mapper->SetPathTraceSamplesPerFrame(16);
    const bool traced = scene.Trace(samples) >= samples;
    Check(traced, name + ": the GPU's picture has its samples");
    this->Gpu = scene.Picture();
    return traced;
  }

  // The GPU's picture against the CPU's composite over `bg`, min(1, L + T
  // bg), both pictures' noise counted.
  PathComparison Compare(const double* bg, int samples) const
  {
    vtkDataArray* L = this->Traced->GetPointData()->GetArray("Radiance");
    vtkDataArray* T = this->Traced->GetPointData()->GetArray("Transmittance");
    return PathComparison{ this->Gpu, this->Traced, bg, samples, 2,
      [L, T, bg](vtkIdType p, int c)
      {
        const int tc = T->GetNumberOfComponents() == 3 ? c : 0; // a coloured extinction's
        return std::min(1.0, L->GetComponent(p, c) + T->GetComponent(p, tc) * bg[c]);
      } };
  }
};
}

#endif
