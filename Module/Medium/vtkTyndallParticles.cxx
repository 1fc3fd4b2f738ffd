#include "vtkTyndallParticles.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// A one-component array of `name` with one value per point, or null with `error` set.
vtkDataArray* PerParticleArray(vtkPolyData* particles, const char* name, std::string& error)
{
  vtkDataArray* array = particles->GetPointData()->GetArray(name);
  std::ostringstream os;
  if (!array)
  {
    os << "The particles have no point-data array named \"" << name << "\".";
  }
  else if (array->GetNumberOfComponents() != 1)
  {
    os << "The particles' array \"" << name << "\" has " << array->GetNumberOfComponents()
       << " components (one is needed).";
  }
  else if (array->GetNumberOfTuples() != particles->GetNumberOfPoints())
  {
    os << "The particles' array \"" << name << "\" has " << array->GetNumberOfTuples()
       << " values for " << particles->GetNumberOfPoints() << " particles.";
  }
  error = os.str();
  return error.empty() ? array : nullptr;
}

// The particles' optional "color" array into `colors` (3 per particle);
// false with `error` set when it is there but unusable.
bool ReadColors(vtkPolyData* particles, std::vector<double>& colors, std::string& error)
{
  vtkDataArray* array = particles->GetPointData()->GetArray("color");
  if (!array)
  {
    return true;
  }
  const vtkIdType n = particles->GetNumberOfPoints();
  std::ostringstream os;
  if (array->GetNumberOfComponents() != 3 || array->GetNumberOfTuples() != n)
  {
    os << "The particles' array \"color\" has " << array->GetNumberOfTuples() << " values of "
       << array->GetNumberOfComponents() << " components for " << n
       << " particles (three components per particle are needed).";
    error = os.str();
    return false;
  }
  colors.resize(3 * static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = array->GetComponent(i, c);
      if (!(v >= 0.0 && v <= 1.0))
      {
        os << "Particle " << i << " has the colour component " << v
           << "; colours must lie in [0, 1].";
        error = os.str();
        return false;
      }
      colors[3 * i + c] = v;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkTyndallParticles::Update(vtkPolyData* particles, std::string& error)
{
  *this = vtkTyndallParticles();
  const vtkIdType n = particles ? particles->GetNumberOfPoints() : 0;
  if (n < 1 || n > MaximumNumberOfParticles)
  {
    std::ostringstream os;
    os << "The particle cloud has " << n << " particles (between 1 and " << MaximumNumberOfParticles
       << " are rendered).";
    error = os.str();
    return false;
  }
  vtkDataArray* radius = PerParticleArray(particles, "radius", error);
  vtkDataArray* density = radius ? PerParticleArray(particles, "density", error) : nullptr;
  if (!density || !ReadColors(particles, this->Colors, error))
  {
    *this = vtkTyndallParticles();
    return false;
  }
  this->Kernels.resize(KernelSize * n);
  this->Radius.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double* c = this->Kernels.data() + KernelSize * i;
    particles->GetPoint(i, c);
    const double r = radius->GetTuple1(i);
    const double rho = density->GetTuple1(i);
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]) || !std::isfinite(r) ||
      !(r > 0.0) || !std::isfinite(rho) || !(rho >= 0.0))
    {
      std::ostringstream os;
      os << "Particle " << i << " cannot be rendered (centre " << c[0] << " " << c[1] << " " << c[2]
         << ", radius " << r << ", density " << rho
         << "): the centre must be finite, the radius finite and > 0, the density finite and "
            ">= 0.";
      error = os.str();
      *this = vtkTyndallParticles();
      return false;
    }
    this->Radius[i] = r;
    c[3] = r * r;
    c[4] = 1.0 / c[3];
    c[5] = rho;
    for (int a = 0; a < 3; ++a)
    {
      this->Bounds[2 * a] = i == 0 ? c[a] - r : std::min(this->Bounds[2 * a], c[a] - r);
      this->Bounds[2 * a + 1] = i == 0 ? c[a] + r : std::max(this->Bounds[2 * a + 1], c[a] + r);
    }
    this->MaximumRadius = std::max(this->MaximumRadius, r);
  }
  this->SplatVertices.resize(5 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    float* v = this->SplatVertices.data() + 5 * i;
    const double* k = this->Kernels.data() + KernelSize * i;
    for (int a = 0; a < 3; ++a)
    {
      v[a] = static_cast<float>(k[a]);
    }
    v[3] = static_cast<float>(this->Radius[i]);
    v[4] = static_cast<float>(k[5]);
  }
  this->BuildCells();
  this->ReadTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallParticles::BuildCells()
{
  // Cells of half the mean radius (a point's candidates are the particles
  // whose box overlaps its cell: about density x (cell + 2R)^3 of them), at
  // most 2^22 cells and about 2^25 listings (125 per particle at this size).
  const vtkIdType n = this->GetNumberOfParticles();
  double extent[3], meanRadius = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = this->Bounds[2 * a + 1] - this->Bounds[2 * a];
  }
  for (double r : this->Radius)
  {
    meanRadius += r / n;
  }
  const double volume = extent[0] * extent[1] * extent[2];
  const double listings = std::max(1.0, std::min(125.0, std::ldexp(1.0, 25) / n));
  // (2R / c + 1)^3 listings per particle of radius R: c from the budget.
  const double fromListings = 2.0 * meanRadius / std::max(std::cbrt(listings) - 1.0, 1e-3);
  this->CellSize =
    std::max({ 0.5 * meanRadius, fromListings, std::cbrt(volume / std::ldexp(1.0, 22)), 1e-300 });
  vtkIdType total = 1;
  for (int a = 0; a < 3; ++a)
  {
    this->CellDims[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / this->CellSize)));
    total *= this->CellDims[a];
  }
  // Two passes: count, then fill (compressed rows).
  std::vector<vtkIdType> count(total + 1, 0);
  auto forCells = [this](vtkIdType i, const auto& visit)
  {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const double c = this->Kernels[KernelSize * i + a];
      lo[a] = this->CellIndex(a, c - this->Radius[i]);
      hi[a] = this->CellIndex(a, c + this->Radius[i]);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
    {
      for (int y = lo[1]; y <= hi[1]; ++y)
      {
        for (int x = lo[0]; x <= hi[0]; ++x)
        {
          visit((static_cast<vtkIdType>(z) * this->CellDims[1] + y) * this->CellDims[0] + x);
        }
      }
    }
  };
  for (vtkIdType i = 0; i < n; ++i)
  {
    forCells(i, [&count](vtkIdType c) { ++count[c + 1]; });
  }
  for (vtkIdType c = 0; c < total; ++c)
  {
    count[c + 1] += count[c];
  }
  this->CellStart = count;
  this->CellParticles.resize(count[total]);
  for (vtkIdType i = 0; i < n; ++i)
  {
    forCells(i, [this, &count, i](vtkIdType c) { this->CellParticles[count[c]++] = i; });
  }
  for (vtkIdType c = 0; c < total; ++c)
  {
    double sum = 0.0;
    for (vtkIdType k = this->CellStart[c]; k < this->CellStart[c + 1]; ++k)
    {
      sum += this->Kernels[KernelSize * this->CellParticles[k] + 5];
    }
    this->DensityBound = std::max(this->DensityBound, sum);
  }
}

//------------------------------------------------------------------------------
int vtkTyndallParticles::CellIndex(int a, double x) const
{
  const double f = std::floor((x - this->Bounds[2 * a]) / this->CellSize);
  return static_cast<int>(std::min(std::max(f, 0.0), this->CellDims[a] - 1.0));
}

//------------------------------------------------------------------------------
double vtkTyndallParticles::Density(const double x[3]) const
{
  return this->Sum(x, nullptr);
}

//------------------------------------------------------------------------------
double vtkTyndallParticles::Density(const double x[3], double color[3]) const
{
  double scattering[3] = { 0.0, 0.0, 0.0 };
  const double density = this->Sum(x, this->HasColors() ? scattering : nullptr);
  for (int c = 0; c < 3; ++c)
  {
    color[c] = this->HasColors() && density > 0.0 ? scattering[c] / density : 1.0;
  }
  return density;
}

//------------------------------------------------------------------------------
double vtkTyndallParticles::Sum(const double x[3], double* color) const
{
  if (color)
  {
    std::fill(color, color + 3, 0.0);
  }
  if (this->CellStart.empty())
  {
    return 0.0;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (!(x[a] >= this->Bounds[2 * a] && x[a] <= this->Bounds[2 * a + 1]))
    {
      return 0.0;
    }
  }
  const vtkIdType cell = (static_cast<vtkIdType>(this->CellIndex(2, x[2])) * this->CellDims[1] +
                           this->CellIndex(1, x[1])) *
      this->CellDims[0] +
    this->CellIndex(0, x[0]);
  double sum = 0.0;
  for (vtkIdType k = this->CellStart[cell]; k < this->CellStart[cell + 1]; ++k)
  {
    const vtkIdType i = this->CellParticles[k];
    const double* c = this->Kernels.data() + KernelSize * i;
    const double dx = x[0] - c[0], dy = x[1] - c[1], dz = x[2] - c[2];
    // Inside the sphere: r^2 below R^2, the same product (0 on the sphere,
    // exactly). Update() checked every radius and density.
    const double r2 = dx * dx + dy * dy + dz * dz;
    const double e = r2 < c[3] ? vtkParticleKernel::ExtinctionOfSquaredRatio(r2 * c[4], c[5]) : 0.0;
    sum += e;
    if (color && e > 0.0)
    {
      for (int a = 0; a < 3; ++a)
      {
        color[a] += e * this->Colors[3 * i + a];
      }
    }
  }
  return sum;
}

//------------------------------------------------------------------------------
void vtkTyndallParticles::Voxelize(int longestSide, vtkImageData* image) const
{
  longestSide = std::max(2, longestSide);
  double extent[3];
  for (int a = 0; a < 3; ++a)
  {
    extent[a] = this->Bounds[2 * a + 1] - this->Bounds[2 * a];
  }
  const double longest = std::max({ extent[0], extent[1], extent[2] });
  const double spacing = longest > 0.0 ? longest / (longestSide - 1) : 1.0;
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = std::max(2, static_cast<int>(std::ceil(extent[a] / spacing - 1e-9)) + 1);
  }
  image->Initialize();
  image->SetDimensions(dims);
  image->SetSpacing(spacing, spacing, spacing);
  // Centred on the bounds (a side's last node may pass its bound by less than a spacing).
  double origin[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] =
      0.5 * (this->Bounds[2 * a] + this->Bounds[2 * a + 1]) - 0.5 * (dims[a] - 1) * spacing;
  }
  image->SetOrigin(origin);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2]);
  float* out = values->GetPointer(0);
  vtkNew<vtkFloatArray> scattering;
  scattering->SetName("scattering");
  scattering->SetNumberOfComponents(3);
  scattering->SetNumberOfTuples(this->HasColors() ? values->GetNumberOfTuples() : 0);
  float* rgb = this->HasColors() ? scattering->GetPointer(0) : nullptr;
  vtkSMPTools::For(0, dims[2],
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType z = begin; z < end; ++z)
      {
        for (int y = 0; y < dims[1]; ++y)
        {
          for (int x = 0; x < dims[0]; ++x)
          {
            const double p[3] = { origin[0] + x * spacing, origin[1] + y * spacing,
              origin[2] + z * spacing };
            const vtkIdType i = (z * dims[1] + y) * dims[0] + x;
            double c[3];
            out[i] = static_cast<float>(this->Sum(p, rgb ? c : nullptr));
            for (int a = 0; rgb && a < 3; ++a)
            {
              rgb[3 * i + a] = static_cast<float>(c[a]);
            }
          }
        }
      }
    });
  image->GetPointData()->SetScalars(values);
  if (this->HasColors())
  {
    image->GetPointData()->AddArray(scattering);
  }
}
