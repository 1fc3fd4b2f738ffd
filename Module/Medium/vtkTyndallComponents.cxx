#include "vtkTyndallComponents.h"

#include "vtkVolumeProperty.h"

#include <algorithm>
#include <sstream>

//------------------------------------------------------------------------------
bool vtkTyndallComponents::Read(
  vtkVolumeProperty* property, int count, bool additive, std::string& error)
{
  this->Count = 1;
  this->ComponentMode = Single;
  this->Additive = false;
  std::fill(this->Weights, this->Weights + MaximumCount, 1.0);
  if (count < 1 || count > MaximumCount)
  {
    std::ostringstream os;
    os << "the scalars have " << count << " components; 1 to " << MaximumCount
       << " are drawn (VTK's mappers draw at most 4).";
    error = os.str();
    return false;
  }
  const bool independent = property && property->GetIndependentComponents();
  if (count == 3 && !independent)
  {
    error = "the scalars have 3 dependent components; dependent components are drawn as 2 "
            "(colour, opacity) or 4 (RGBA), as VTK draws them: turn the property's "
            "IndependentComponents on.";
    return false;
  }
  this->Count = count;
  if (count == 1)
  {
    return true;
  }
  this->ComponentMode = independent ? Independent : (count == 2 ? DependentLA : DependentRGBA);
  this->Additive = independent && additive;
  for (int i = 0; i < count && independent; ++i)
  {
    this->Weights[i] = property->GetComponentWeight(i);
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkTyndallComponents::GetTableCount() const
{
  switch (this->ComponentMode)
  {
    case Independent:
      return this->Count;
    case DependentLA:
      return 2;
    default:
      return 1;
  }
}

//------------------------------------------------------------------------------
int vtkTyndallComponents::TableFunction(int t) const
{
  return this->ComponentMode == Independent ? t : 0;
}

//------------------------------------------------------------------------------
int vtkTyndallComponents::TableComponent(int t) const
{
  switch (this->ComponentMode)
  {
    case Independent:
    case DependentLA:
      return t;
    case DependentRGBA:
      return 3;
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallComponents::Mix(const double sigma[MaximumCount],
  const double color[MaximumCount][3], const double unit[MaximumCount], double rgb[3]) const
{
  double extinction = 0.0;
  switch (this->ComponentMode)
  {
    case Single:
      extinction = sigma[0];
      std::copy(color[0], color[0] + 3, rgb);
      break;
    case DependentLA:
      extinction = sigma[1];
      std::copy(color[0], color[0] + 3, rgb);
      break;
    case DependentRGBA:
      extinction = sigma[0];
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = std::min(std::max(unit[c], 0.0), 1.0);
      }
      break;
    case Independent:
    {
      double weighted = 0.0, squares = 0.0, emission[3] = { 0.0, 0.0, 0.0 };
      for (int i = 0; i < this->Count; ++i)
      {
        const double w = this->Weights[i];
        if (w > 0.0)
        {
          weighted += w * sigma[i];
          squares += sigma[i] * sigma[i];
          for (int c = 0; c < 3; ++c)
          {
            emission[c] += w * sigma[i] * color[i][c];
          }
        }
      }
      extinction = this->Additive ? weighted : (weighted > 0.0 ? squares / weighted : 0.0);
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = extinction > 0.0 ? emission[c] / extinction : 0.0;
      }
      break;
    }
  }
  if (!(extinction > 0.0))
  {
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    return 0.0;
  }
  return extinction;
}

//------------------------------------------------------------------------------
void vtkTyndallComponents::Parts(
  const double sigma[MaximumCount], double weights[MaximumCount]) const
{
  const double color[MaximumCount][3] = {};
  const double unit[MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
  double rgb[3];
  const double extinction = this->Mix(sigma, color, unit, rgb);
  for (int i = 0; i < MaximumCount; ++i)
  {
    const double w = i < this->Count ? this->Weights[i] : 0.0;
    weights[i] = w > 0.0 && extinction > 0.0 ? w * sigma[i] / extinction : 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallComponents::Majorant(const double sigmaMax[MaximumCount]) const
{
  switch (this->ComponentMode)
  {
    case DependentLA:
      return sigmaMax[1];
    case Independent:
    {
      // Additive: sum w_i sigma_i. VTK's: sum sigma_i^2 / sum w_i sigma_i is
      // at most max sigma_i / w_i (sum sigma_i^2 = sum (sigma_i / w_i) w_i
      // sigma_i).
      double bound = 0.0;
      for (int i = 0; i < this->Count; ++i)
      {
        const double w = this->Weights[i];
        if (w > 0.0)
        {
          bound = this->Additive ? bound + w * sigmaMax[i] : std::max(bound, sigmaMax[i] / w);
        }
      }
      return bound;
    }
    default:
      return sigmaMax[0];
  }
}

//------------------------------------------------------------------------------
std::string vtkTyndallComponents::Describe() const
{
  std::ostringstream os;
  os << this->Count << (this->ComponentMode == Independent ? " independent" : " dependent")
     << " components";
  return os.str();
}
