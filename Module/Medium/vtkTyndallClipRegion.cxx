#include "vtkTyndallClipRegion.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"

#include <algorithm>

//------------------------------------------------------------------------------
bool vtkTyndallClipRegion::Update(vtkVolume* volume, const double indexToWorld[16],
  const double indexToData[16], vtkObject* reporter)
{
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  std::vector<double> key;
  this->WorldPlanes.clear();
  this->IndexPlanes.clear();
  vtkPlaneCollection* planes = mapper->GetClippingPlanes();
  const int count = planes ? planes->GetNumberOfItems() : 0;
  if (count > MaximumPlanes)
  {
    vtkWarningWithObjectMacro(reporter, << "The mapper has " << count
                                        << " clipping planes; the first " << MaximumPlanes
                                        << " are used.");
  }
  for (int i = 0; i < std::min(count, MaximumPlanes); ++i)
  {
    vtkPlane* plane = planes->GetItem(i);
    double n[3], o[3];
    plane->GetNormal(n);
    plane->GetOrigin(o);
    const std::array<double, 4> world = { n[0], n[1], n[2],
      -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]) };
    // n . (M p + t) + d = (M^T n) . p + (n . t + d), M = indexToWorld.
    std::array<double, 4> index = { 0.0, 0.0, 0.0, world[3] };
    for (int c = 0; c < 3; ++c)
    {
      for (int r = 0; r < 3; ++r)
      {
        index[c] += indexToWorld[4 * r + c] * n[r];
      }
      index[3] += n[c] * indexToWorld[4 * c + 3];
    }
    this->WorldPlanes.push_back(world);
    this->IndexPlanes.push_back(index);
    key.insert(key.end(), world.begin(), world.end());
  }
  auto* volumeMapper = vtkVolumeMapper::SafeDownCast(mapper);
  this->Cropping = volumeMapper && volumeMapper->GetCropping();
  key.push_back(this->Cropping ? 1.0 : 0.0);
  if (this->Cropping)
  {
    volumeMapper->GetCroppingRegionPlanes(this->CroppingPlanes);
    this->CroppingFlags = volumeMapper->GetCroppingRegionFlags();
    key.insert(key.end(), this->CroppingPlanes, this->CroppingPlanes + 6);
    key.push_back(static_cast<double>(this->CroppingFlags));
  }
  std::copy(indexToData, indexToData + 16, this->IndexToData);
  double worldToIndex[16];
  vtkMatrix4x4::Invert(indexToWorld, worldToIndex);
  vtkMatrix4x4::Multiply4x4(indexToData, worldToIndex, this->WorldToData);
  if (this->Enabled())
  {
    key.insert(key.end(), indexToWorld, indexToWorld + 16);
    key.insert(key.end(), indexToData, indexToData + 16);
  }
  const bool changed = key != this->Key;
  this->Key = key;
  return changed;
}

//------------------------------------------------------------------------------
bool vtkTyndallClipRegion::InsideIndex(const double p[3]) const
{
  for (const std::array<double, 4>& plane : this->IndexPlanes)
  {
    if (plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] < 0.0)
    {
      return false;
    }
  }
  if (!this->Cropping)
  {
    return true;
  }
  int region = 0;
  for (int a = 0, stride = 1; a < 3; ++a, stride *= 3)
  {
    const double* m = this->IndexToData + 4 * a;
    const double x = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    region += stride *
      ((x < this->CroppingPlanes[2 * a] ? 0 : 1) + (x < this->CroppingPlanes[2 * a + 1] ? 0 : 1));
  }
  return ((this->CroppingFlags >> region) & 1) != 0;
}
