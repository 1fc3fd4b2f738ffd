// Particle clouds for the tests and benchmarks of vtkTransmittanceParticleMapper:
// a random cloud, and the exact ETM map of a cloud (the closed-form sum of
// vtkParticleKernel::AddExtinctionCoefficients along every texel's light ray),
// the CPU twin of the GPU's splatting.
#ifndef TyndallTestParticles_h
#define TyndallTestParticles_h

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTransmittanceLightFrustum.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallSceneReader.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace tyndall_test
{
// `n` particles in a ball of radius `ball` (a fixed seed): radius in
// [rMin, rMax], density in [dMin, dMax] per world unit.
inline vtkSmartPointer<vtkPolyData> MakeParticles(int n, unsigned seed = 7, double ball = 0.8,
  double rMin = 0.06, double rMax = 0.16, double dMin = 0.5, double dMax = 3.0)
{
  std::mt19937 random(seed);
  auto uniform = [&random]() { return (random() + 0.5) / 4294967296.0; };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius, density;
  radius->SetName("radius");
  density->SetName("density");
  while (points->GetNumberOfPoints() < n)
  {
    const double x = (2.0 * uniform() - 1.0) * ball, y = (2.0 * uniform() - 1.0) * ball,
                 z = (2.0 * uniform() - 1.0) * ball;
    if (x * x + y * y + z * z > ball * ball)
    {
      continue;
    }
    points->InsertNextPoint(x, y, z);
    radius->InsertNextValue(rMin + (rMax - rMin) * uniform());
    density->InsertNextValue(dMin + (dMax - dMin) * uniform());
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->GetPointData()->AddArray(radius);
  cloud->GetPointData()->AddArray(density);
  return cloud;
}

// The exact ETM coefficients of every `stride`-th texel (in both directions)
// of light 0's map of `map`'s size.
struct ExactMap
{
  int Size = 0;
  int Stride = 1;
  int Count = 0;
  std::vector<int> Texels;          // the texels computed
  std::vector<double> Coefficients; // Count per texel, in Texels' order
  double Scale = 0.0;               // the largest |coefficient|

  // The largest |GPU - exact| over the texels, relative to Scale.
  double LargestError(vtkImageData* map) const
  {
    vtkDataArray* gpu = map->GetPointData()->GetArray("Coefficients");
    double error = 0.0;
    for (size_t i = 0; i < this->Texels.size(); ++i)
    {
      for (int k = 0; k < this->Count; ++k)
      {
        error = std::max(error,
          std::abs(
            gpu->GetComponent(this->Texels[i], k) - this->Coefficients[i * this->Count + k]));
      }
    }
    return this->Scale > 0.0 ? error / this->Scale : error;
  }

  // PSNR (peak 1) of the transmittance the GPU's map reconstructs at s =
  // 0.05, 0.15, ..., 0.95 of each texel against the exact map's.
  double TransmittancePSNR(vtkImageData* map) const
  {
    vtkDataArray* gpu = map->GetPointData()->GetArray("Coefficients");
    const double bounds[3] = { 0.0, 1.0, 1.0 };
    double sum = 0.0;
    long long n = 0;
    std::vector<double> c(this->Count);
    for (size_t i = 0; i < this->Texels.size(); ++i)
    {
      for (int k = 0; k < this->Count; ++k)
      {
        c[k] = gpu->GetComponent(this->Texels[i], k);
      }
      for (int q = 0; q < 10; ++q)
      {
        const double s = 0.05 + 0.1 * q;
        using M = vtkTransmittanceMapMath;
        const double a = M::Reconstruct(M::ETM, c.data(), this->Count, bounds, s);
        const double b =
          M::Reconstruct(M::ETM, &this->Coefficients[i * this->Count], this->Count, bounds, s);
        sum += (a - b) * (a - b);
        ++n;
      }
    }
    const double mse = n ? sum / n : 0.0;
    return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : 999.0;
  }
};

inline ExactMap ExactEtmMap(vtkTransmittanceVolumeMapper* mapper, vtkRenderer* renderer,
  vtkVolume* volume, vtkPolyData* particles, vtkImageData* map, int stride)
{
  ExactMap exact;
  exact.Size = map->GetDimensions()[0];
  exact.Stride = stride;
  exact.Count = map->GetPointData()->GetArray("Coefficients")->GetNumberOfComponents();
  vtkTyndallSceneReader reader;
  reader.Update(renderer, volume, nullptr);
  const vtkTyndallGridMedium& medium = reader.GetMedium();
  // World -> data: the index -> data map after world -> index.
  double worldToData[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      double v = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        v += medium.GetIndexToData()[4 * r + k] * medium.GetWorldToIndex()[4 * k + c];
      }
      worldToData[4 * r + c] = v;
    }
  }
  const double* w2i = medium.GetWorldToIndex();
  vtkTransmittanceLightFrustum* frustum = mapper->GetLightFrustum(0);
  const int size = exact.Size;
  for (int j = 0; j < size; j += stride)
  {
    for (int i = 0; i < size; i += stride)
    {
      exact.Texels.push_back(j * size + i);
    }
  }
  const int count = exact.Count;
  exact.Coefficients.assign(exact.Texels.size() * count, 0.0);
  vtkDataArray* radius = particles->GetPointData()->GetArray("radius");
  vtkDataArray* density = particles->GetPointData()->GetArray("density");
  const vtkIdType n = particles->GetNumberOfPoints();
  std::vector<double> centres(3 * n), radii(n), densities(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    particles->GetPoint(p, &centres[3 * p]);
    radii[p] = radius->GetTuple1(p);
    densities[p] = density->GetTuple1(p);
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(exact.Texels.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const int t = exact.Texels[e];
        double o[3], d[3];
        frustum->GetRay((t % size + 0.5) / size, (t / size + 0.5) / size, o, d);
        // The ray's part in the medium's box (field index space; t a world distance).
        double t0 = -1e300, t1 = 1e300;
        for (int a = 0; a < 3; ++a)
        {
          const double po =
            w2i[4 * a] * o[0] + w2i[4 * a + 1] * o[1] + w2i[4 * a + 2] * o[2] + w2i[4 * a + 3];
          const double pd = w2i[4 * a] * d[0] + w2i[4 * a + 1] * d[1] + w2i[4 * a + 2] * d[2];
          const double ta = (medium.GetBoxLow()[a] - po) / pd;
          const double tb = (medium.GetBoxHigh()[a] - po) / pd;
          t0 = std::max(t0, std::min(ta, tb));
          t1 = std::min(t1, std::max(ta, tb));
        }
        if (!(t0 < t1))
        {
          continue;
        }
        // In data space: the entry point, the unit direction and lambda.
        double od[3], dd[3];
        for (int r = 0; r < 3; ++r)
        {
          const double* row = worldToData + 4 * r;
          od[r] = row[0] * (o[0] + t0 * d[0]) + row[1] * (o[1] + t0 * d[1]) +
            row[2] * (o[2] + t0 * d[2]) + row[3];
          dd[r] = row[0] * d[0] + row[1] * d[1] + row[2] * d[2];
        }
        const double lambda = std::sqrt(dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2]);
        for (double& v : dd)
        {
          v /= lambda;
        }
        double* c = &exact.Coefficients[e * count];
        for (vtkIdType p = 0; p < n; ++p)
        {
          const double* x = &centres[3 * p];
          const double v[3] = { x[0] - od[0], x[1] - od[1], x[2] - od[2] };
          const double sc = v[0] * dd[0] + v[1] * dd[1] + v[2] * dd[2];
          const double w[3] = { v[0] - sc * dd[0], v[1] - sc * dd[1], v[2] - sc * dd[2] };
          const double b2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
          if (b2 >= radii[p] * radii[p])
          {
            continue;
          }
          double add[16] = {};
          vtkParticleKernel::AddExtinctionCoefficients(
            std::sqrt(b2), sc, lambda * (t1 - t0), radii[p], densities[p], count, add);
          for (int k = 0; k < count; ++k)
          {
            c[k] += add[k] / lambda;
          }
        }
      }
    });
  for (double v : exact.Coefficients)
  {
    exact.Scale = std::max(exact.Scale, std::abs(v));
  }
  return exact;
}
}

#endif
