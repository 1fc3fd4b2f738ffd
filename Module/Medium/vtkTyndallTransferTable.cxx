#include "vtkTyndallTransferTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

//------------------------------------------------------------------------------
bool vtkTyndallTransferTable::Build(vtkVolumeProperty* property, vtkColorTransferFunction* emission,
  double lo, double hi, std::string& error, bool linearExtinction)
{
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    std::ostringstream os;
    os << "the volume property's scalar opacity unit distance must be positive and finite; it is "
       << unitDistance << ".";
    error = os.str();
    return false;
  }
  this->Minimum = lo;
  this->Maximum = hi;
  this->EmissionFromArray = false;
  this->Scale = this->Maximum > this->Minimum ? (Size - 1) / (this->Maximum - this->Minimum) : 0.0;

  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const bool gray = property->GetColorChannels(0) == 1;
  vtkPiecewiseFunction* grayFunction = gray ? property->GetGrayTransferFunction(0) : nullptr;
  vtkColorTransferFunction* rgbFunction = gray ? nullptr : property->GetRGBTransferFunction(0);
  this->Extinction.assign(Size, 0.0);
  this->Albedo.assign(3 * Size, 0.0);
  this->Emission.assign(3 * Size, 0.0);
  this->Opacity.assign(Size, 0.0);
  for (int i = 0; i < Size; ++i)
  {
    const double s = std::min(this->Scale > 0.0 ? lo + i / this->Scale : lo, hi);
    this->Opacity[i] = opacity->GetValue(s);
    this->Extinction[i] = linearExtinction
      ? std::max(s, 0.0)
      : vtkTransmittanceMapMath::ExtinctionFromOpacity(this->Opacity[i], unitDistance, 1.0);
    double* albedo = this->Albedo.data() + 3 * i;
    if (gray)
    {
      albedo[0] = albedo[1] = albedo[2] = grayFunction->GetValue(s);
    }
    else
    {
      rgbFunction->GetColor(s, albedo);
    }
    if (emission)
    {
      emission->GetColor(s, this->Emission.data() + 3 * i);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::TabulateEmission(
  double lo, double hi, const std::function<void(double, double[3])>& color)
{
  this->EmissionFromArray = true;
  this->EmissionMinimum = lo;
  this->EmissionEntries = hi > lo ? (Size - 1) / (hi - lo) : 0.0;
  this->Emission.assign(3 * Size, 0.0);
  for (int i = 0; i < Size; ++i)
  {
    const double v =
      std::min(this->EmissionEntries > 0.0 ? lo + i / this->EmissionEntries : lo, hi);
    color(v, this->Emission.data() + 3 * i);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::TabulateGradientOpacity(vtkPiecewiseFunction* function)
{
  this->GradientOpacity.clear();
  this->GradientMaximum =
    0.25 * (this->Maximum > this->Minimum ? this->Maximum - this->Minimum : 1.0);
  if (!function)
  {
    return;
  }
  this->GradientOpacity.resize(Size);
  for (int i = 0; i < Size; ++i)
  {
    const double g = this->GradientMaximum * i / (Size - 1);
    this->GradientOpacity[i] = std::min(std::max(function->GetValue(g), 0.0), 1.0);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallTransferTable::GetTexture(std::vector<float>& rgba) const
{
  rgba.assign(4 * Rows * static_cast<size_t>(Size), 0.0f);
  float* albedo = rgba.data() + 4 * static_cast<size_t>(AlbedoRow) * Size;
  float* emission = rgba.data() + 4 * static_cast<size_t>(EmissionRow) * Size;
  float* gradient = rgba.data() + 4 * static_cast<size_t>(GradientRow) * Size;
  for (int i = 0; i < Size; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      albedo[4 * i + c] = static_cast<float>(this->Albedo[3 * i + c]);
      emission[4 * i + c] = static_cast<float>(this->Emission[3 * i + c]);
    }
    albedo[4 * i + 3] = static_cast<float>(this->Extinction[i]);
    emission[4 * i + 3] = static_cast<float>(this->Opacity[i]);
    gradient[4 * i] =
      this->GradientOpacity.empty() ? 1.0f : static_cast<float>(this->GradientOpacity[i]);
  }
}
