#include "vtkTyndallSurfaceLobe.h"

#include "vtkMath.h"
#include "vtkTyndallShading.h"

#include <algorithm>
#include <cmath>

const double vtkTyndallSurfaceLobe::LightUnit = 2.0 * vtkMath::Pi();

namespace
{
// The unit direction at the cosine mu and the angle phi about the unit axis a
// (an orthonormal basis after Duff et al. 2017).
void AboutAxis(const double a[3], double mu, double phi, double out[3])
{
  const double sign = std::copysign(1.0, a[2]);
  const double s = -1.0 / (sign + a[2]);
  const double b = a[0] * a[1] * s;
  const double u[3] = { 1.0 + sign * a[0] * a[0] * s, sign * b, -sign * a[0] };
  const double w[3] = { b, sign + a[1] * a[1] * s, -a[1] };
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  const double cu = sinTheta * std::cos(phi), cw = sinTheta * std::sin(phi);
  for (int c = 0; c < 3; ++c)
  {
    out[c] = mu * a[c] + cu * u[c] + cw * w[c];
  }
}

// The unit half vector of l and v; false where l = -v.
bool HalfVector(const double l[3], const double v[3], double h[3])
{
  for (int c = 0; c < 3; ++c)
  {
    h[c] = l[c] + v[c];
  }
  const double length = vtkMath::Norm(h);
  if (!(length > 1.0e-12))
  {
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    h[c] /= length;
  }
  return true;
}
}

//------------------------------------------------------------------------------
void vtkTyndallSurfaceLobe::Set(const vtkTyndallShading& shading, const double n[3],
  const double v[3], const double color[3], int component, double blend, double scale)
{
  this->Set(shading.GetDiffuse(component), shading.GetSpecular(component),
    shading.GetSpecularPower(component), n, v, color, blend, scale);
}

//------------------------------------------------------------------------------
void vtkTyndallSurfaceLobe::Set(double diffuse, double specular, double power, const double n[3],
  const double v[3], const double color[3], double blend, double scale)
{
  const bool normal = n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
  double mean = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    this->N[c] = n[c];
    this->V[c] = v[c];
    this->Diffuse[c] = std::max(0.0, diffuse * color[c]);
    mean += this->Diffuse[c] / 3.0;
  }
  this->Specular = std::max(0.0, specular);
  this->Power = std::max(0.0, power);
  this->Blend = blend > 0.0 ? std::min(blend, 1.0) : 0.0; // (NaN: 0)
  this->Scale = scale > 0.0 ? scale : 0.0;
  const double surface = 1.0 - this->Blend;
  const double d = normal ? surface * mean : 0.0;
  const double s =
    normal ? surface * this->Specular * std::min(1.0, 4.0 / (this->Power + 1.0)) : 0.0;
  const double u = this->Blend * 2.0 * mean;
  const double sum = d + s + u;
  this->DiffuseShare = sum > 0.0 ? d / sum : 0.0;
  this->SpecularShare = sum > 0.0 ? s / sum : 0.0;
  this->VolumeShare = sum > 0.0 ? u / sum : 0.0;
}

//------------------------------------------------------------------------------
void vtkTyndallSurfaceLobe::Evaluate(const double l[3], double f[3]) const
{
  f[0] = f[1] = f[2] = 0.0;
  if (!this->Scatters())
  {
    return;
  }
  const double inverse = this->Scale / vtkTyndallSurfaceLobe::LightUnit;
  const bool normal = this->N[0] != 0.0 || this->N[1] != 0.0 || this->N[2] != 0.0;
  const double nl = std::abs(vtkMath::Dot(this->N, l));
  double h[3];
  const double specular = normal && HalfVector(l, this->V, h)
    ? this->Specular * std::pow(std::abs(vtkMath::Dot(this->N, h)), this->Power)
    : 0.0;
  const double surface = 1.0 - this->Blend;
  for (int c = 0; c < 3; ++c)
  {
    f[c] =
      (surface * (this->Diffuse[c] * nl + specular) + this->Blend * this->Diffuse[c]) * inverse;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallSurfaceLobe::Pdf(const double l[3]) const
{
  if (!this->Scatters())
  {
    return 0.0;
  }
  const double twoPi = 2.0 * vtkMath::Pi();
  double pdf = this->DiffuseShare * std::abs(vtkMath::Dot(this->N, l)) / twoPi +
    this->VolumeShare / (2.0 * twoPi);
  double h[3];
  if (this->SpecularShare > 0.0 && HalfVector(l, this->V, h))
  {
    const double vh = std::abs(vtkMath::Dot(this->V, h));
    if (vh > 0.0)
    {
      const double nh = std::abs(vtkMath::Dot(this->N, h));
      pdf +=
        this->SpecularShare * (this->Power + 1.0) / twoPi * std::pow(nh, this->Power) / (4.0 * vh);
    }
  }
  return pdf;
}

//------------------------------------------------------------------------------
double vtkTyndallSurfaceLobe::Sample(
  double u0, double u1, double u2, double l[3], double weight[3]) const
{
  weight[0] = weight[1] = weight[2] = 0.0;
  if (!this->Scatters())
  {
    l[0] = this->V[0];
    l[1] = this->V[1];
    l[2] = this->V[2];
    return 0.0;
  }
  const double phi = 2.0 * vtkMath::Pi() * u2;
  if (u0 < this->DiffuseShare)
  {
    // The two-sided cosine lobe: a side, then cos theta = sqrt(u1) about it.
    const bool front = u0 < 0.5 * this->DiffuseShare;
    const double axis[3] = { front ? this->N[0] : -this->N[0], front ? this->N[1] : -this->N[1],
      front ? this->N[2] : -this->N[2] };
    AboutAxis(axis, std::sqrt(u1), phi, l);
  }
  else if (this->VolumeShare > 0.0 && u0 >= this->DiffuseShare + this->SpecularShare)
  {
    // The blending's part: uniformly over the sphere.
    const double axis[3] = { 0.0, 0.0, 1.0 };
    AboutAxis(axis, 1.0 - 2.0 * u1, phi, l);
  }
  else
  {
    // The half vector about n turned towards v, l the mirror of v about it.
    const double side = vtkMath::Dot(this->N, this->V) < 0.0 ? -1.0 : 1.0;
    const double axis[3] = { side * this->N[0], side * this->N[1], side * this->N[2] };
    double h[3];
    AboutAxis(axis, std::pow(u1, 1.0 / (this->Power + 1.0)), phi, h);
    const double vh = vtkMath::Dot(this->V, h);
    for (int c = 0; c < 3; ++c)
    {
      l[c] = 2.0 * vh * h[c] - this->V[c];
    }
    vtkMath::Normalize(l);
  }
  const double pdf = this->Pdf(l);
  if (!(pdf > 0.0))
  {
    return 0.0;
  }
  double f[3];
  this->Evaluate(l, f);
  for (int c = 0; c < 3; ++c)
  {
    weight[c] = f[c] / pdf;
  }
  return pdf;
}
