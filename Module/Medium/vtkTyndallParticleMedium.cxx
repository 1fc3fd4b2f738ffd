#include "vtkTyndallParticleMedium.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkParticipatingMediumMapper.h"
#include "vtkPointData.h"
#include "vtkTyndallParticles.h"
#include "vtkVolume.h"

//------------------------------------------------------------------------------
vtkTyndallParticleMedium::vtkTyndallParticleMedium() = default;

//------------------------------------------------------------------------------
vtkTyndallParticleMedium::~vtkTyndallParticleMedium() = default;

//------------------------------------------------------------------------------
vtkDataSet* vtkTyndallParticleMedium::ReadInput(vtkVolume* volume, vtkObject* reporter)
{
  this->Particles = nullptr;
  this->Splat = false;
  this->Scattering = nullptr;
  auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume ? volume->GetMapper() : nullptr);
  if (!mapper || !mapper->DrawsParticles())
  {
    return this->vtkTyndallGridMedium::ReadInput(volume, reporter);
  }
  // The grid of the particles, read from the (updated) input when it
  // changed; the mapper reports why it cannot be.
  vtkImageData* image = mapper->GetMediumImage();
  if (!image || !mapper->GetParticles())
  {
    return nullptr;
  }
  this->Particles = mapper->GetParticles();
  this->Splat = mapper->GetSplatsParticles();
  // A coloured particle cloud's scattering density, voxelised beside the
  // density (vtkTyndallParticles::Voxelize()): it changes with the image.
  if (this->Particles->HasColors())
  {
    this->Scattering = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("scattering"));
  }
  return image;
}

//------------------------------------------------------------------------------
void vtkTyndallParticleMedium::ToData(const double p[3], double x[3]) const
{
  const double* m = this->GetIndexToData();
  for (int r = 0; r < 3; ++r)
  {
    const double* row = m + 4 * r;
    x[r] = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
  }
}

//------------------------------------------------------------------------------
double vtkTyndallParticleMedium::FieldScalar(const double p[3]) const
{
  double x[3];
  this->ToData(p, x);
  return this->Particles->Density(x);
}

//------------------------------------------------------------------------------
bool vtkTyndallParticleMedium::FieldAlbedo(const double p[3], double color[3]) const
{
  if (!this->Particles->HasColors())
  {
    return false;
  }
  double x[3];
  this->ToData(p, x);
  this->Particles->Density(x, color);
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallParticleMedium::GetMajorant() const
{
  return this->GetParameters().DensityScale * this->Particles->GetDensityBound();
}
