// Scenes shared by Tyndall's rendering tests and benchmarks. Header only;
// not part of the library.
#ifndef TyndallTestScene_h
#define TyndallTestScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <cmath>

namespace tyndall_test
{
// The built-in cloud (vtkCosineNoiseSource's defaults) at n^3 over [-1, 1]^3.
inline vtkSmartPointer<vtkImageData> MakeCloud(int n)
{
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1);
  source->SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1));
  source->Update();
  return source->GetOutput();
}

// The built-in cloud with a "temperature" array: 400 K plus a hot blob of
// 1900 K around (0, -0.3, 0), broader than the cloud's lower part.
inline vtkSmartPointer<vtkImageData> MakeFire(int n)
{
  vtkSmartPointer<vtkImageData> image = MakeCloud(n);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    const double r2 = x[0] * x[0] + (x[1] + 0.3) * (x[1] + 0.3) + x[2] * x[2];
    temperature->SetValue(
      i, static_cast<float>(400.0 + 1900.0 * std::exp(-r2 / (2.0 * 0.35 * 0.35))));
  }
  image->GetPointData()->AddArray(temperature);
  return image;
}

// A fog: 4^3 samples of the value 8 (the cloud's transfer functions at
// their peak) filling the box from (x, y, z) of the sides (sx, sy, sz).
inline vtkSmartPointer<vtkImageData> MakeFog(
  double x, double y, double z, double sx, double sy, double sz)
{
  auto fog = vtkSmartPointer<vtkImageData>::New();
  fog->SetDimensions(4, 4, 4);
  fog->SetOrigin(x, y, z);
  fog->SetSpacing(sx / 3.0, sy / 3.0, sz / 3.0);
  fog->AllocateScalars(VTK_FLOAT, 1);
  fog->GetPointData()->GetScalars()->Fill(8.0);
  return fog;
}

// Adds to a grid a "temperature" point array that rises from 1000 to 2000
// along its x index (an emission array: EmissionArrayName).
inline void AddTemperature(vtkImageData* grid)
{
  int dims[3];
  grid->GetDimensions(dims);
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("temperature");
  temperature->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const double x = dims[0] > 1 ? static_cast<double>(i % dims[0]) / (dims[0] - 1) : 0.0;
    temperature->SetValue(i, static_cast<float>(1000.0 + 1000.0 * x));
  }
  grid->GetPointData()->AddArray(temperature);
}

// Makes a property glow from AddTemperature()'s array through a colour
// function (orange at 1000, pale yellow at 2000), EmissionScale `scale`.
inline void GlowFromTemperature(vtkParticipatingMediumProperty* property, double scale)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(1000.0, 0.9, 0.4, 0.1);
  color->AddRGBPoint(2000.0, 1.0, 0.7, 0.3);
  property->SetEmissionColor(color);
  property->SetEmissionArrayName("temperature");
  property->SetEmissionScale(scale);
}

// A hot fog out of the test camera's view: MakeFog() over x in [x, x + 1.6],
// y and z in [-1, 1], with AddTemperature()'s array.
inline vtkSmartPointer<vtkImageData> MakeHotFog(double x)
{
  vtkSmartPointer<vtkImageData> fog = MakeFog(x, -1.0, -1.0, 1.6, 2.0, 2.0);
  AddTemperature(fog);
  return fog;
}

// A dense medium: a slab of high constant density with a noisy top, so that
// light rays cross optical depths of several tens.
inline vtkSmartPointer<vtkImageData> MakeDenseMedium(int n)
{
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1);
  source->SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1));
  source->SetEnvelopeTypeToSphere();
  source->SetEnvelopeRadius(0.85);
  source->SetEnvelopeFalloff(0.15);
  source->GetNoise()->SetNumberOfOctaves(3);
  source->GetNoise()->SetOffset(12.0);
  source->Update();
  return source->GetOutput();
}

// A sparse medium: six Gaussian blobs (peak 8, standard deviation 0.08,
// cut to exactly 0 below 1 % of the peak) at n^3 over [-1, 1]^3, most of the
// box empty: the case empty-space skipping is for.
inline vtkSmartPointer<vtkImageData> MakeSparseBlobs(int n)
{
  const double centres[6][3] = { { -0.6, -0.5, -0.4 }, { 0.5, -0.6, 0.1 }, { -0.2, 0.55, 0.5 },
    { 0.6, 0.4, -0.55 }, { 0.05, -0.05, 0.0 }, { -0.55, 0.2, 0.6 } };
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetOrigin(-1.0, -1.0, -1.0);
  const double h = 2.0 / (n - 1);
  image->SetSpacing(h, h, h);
  image->AllocateScalars(VTK_FLOAT, 1);
  float* v = static_cast<float*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x[3] = { -1.0 + i * h, -1.0 + j * h, -1.0 + k * h };
        double value = 0.0;
        for (const auto& c : centres)
        {
          const double r2 = (x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
            (x[2] - c[2]) * (x[2] - c[2]);
          value += 8.0 * std::exp(-r2 / (2.0 * 0.08 * 0.08));
        }
        *v++ = static_cast<float>(value < 0.08 ? 0.0 : value);
      }
    }
  }
  return image;
}

// A white cloud medium: opacity up to `peakOpacity` per 0.05 world units at
// density 8, albedo 0.9, single scattering alone (one octave: the tests of the
// integrators and the maps compare single scattering; the multiple-scattering
// octaves have their own test), the property's other settings at their
// defaults.
// The geometry the detail medium's tests take their waves through: a 9x7x6
// image, spacing (0.3, 0.25, 0.4), rotated about z by 30 degrees.
inline void SetSkewedGeometry(vtkImageData* image)
{
  image->SetDimensions(9, 7, 6);
  image->SetSpacing(0.3, 0.25, 0.4);
  image->SetOrigin(-1.2, -0.7, -0.9);
  vtkNew<vtkMatrix3x3> direction;
  const double a = vtkMath::RadiansFromDegrees(30.0);
  direction->SetElement(0, 0, std::cos(a));
  direction->SetElement(0, 1, -std::sin(a));
  direction->SetElement(1, 0, std::sin(a));
  direction->SetElement(1, 1, std::cos(a));
  image->SetDirectionMatrix(direction);
}

inline vtkSmartPointer<vtkParticipatingMediumProperty> MakeCloudProperty(double peakOpacity = 0.5)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(8.0, peakOpacity);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
  color->AddRGBPoint(8.0, 0.9, 0.9, 0.9);
  auto property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(0.05);
  property->SetScatteringOctaves(1);
  return property;
}

// A CT's look: a plain vtkVolumeProperty with Shade on (VTK's gradient
// shading; path traced as vtkTyndallSurfaceLobe), an opacity ramp from 0
// at the scalar `low` to `peakOpacity` at `high`, a bone colour, Ka 0.1,
// Kd 0.6, Ks 0.3, p 15.
inline vtkSmartPointer<vtkVolumeProperty> MakeShadedProperty(
  double low, double high, double peakOpacity)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(low, 0.0);
  opacity->AddPoint(high, peakOpacity);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(low, 0.85, 0.6, 0.45);
  color->AddRGBPoint(high, 0.95, 0.9, 0.8);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(0.05);
  property->ShadeOn();
  property->SetAmbient(0.1);
  property->SetDiffuse(0.6);
  property->SetSpecular(0.3);
  property->SetSpecularPower(15.0);
  return property;
}

// A directional scene light travelling from `from` towards the origin.
inline vtkSmartPointer<vtkLight> MakeSun(double x, double y, double z, double intensity = 1.0)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPositional(false);
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetIntensity(intensity);
  return light;
}

// The camera of the tests: looking at the origin from +z, slightly below.
inline void SetTestCamera(vtkRenderer* renderer, double viewAngle = 30.0)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -0.6, 4.2);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(viewAngle);
  renderer->ResetCameraClippingRange();
}

// A white, purely diffuse ground facing up (+y) that receives a medium's
// shadow: the square [Low, High]^2 in x and z at y = Height.
struct Ground
{
  double Height;
  double Low;
  double High;

  vtkSmartPointer<vtkActor> MakeActor() const
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(this->Low, this->Height, this->Low);
    plane->SetPoint1(this->Low, this->Height, this->High);
    plane->SetPoint2(this->High, this->Height, this->Low);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(plane->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* p = actor->GetProperty();
    p->SetColor(1.0, 1.0, 1.0);
    p->SetAmbient(0.0);
    p->SetDiffuse(1.0);
    p->SetSpecular(0.0);
    return actor;
  }

  // The ground point x that pixel (i, j) of a size x size picture of
  // `renderer` sees: false where the pixel's ray, between the near and far
  // planes, goes up or misses the ground.
  bool PixelPoint(vtkRenderer* renderer, int size, int i, int j, double x[3]) const
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0), inverse);
    double ends[2][4];
    for (int e = 0; e < 2; ++e)
    {
      const double ndc[4] = { 2.0 * (i + 0.5) / size - 1.0, 2.0 * (j + 0.5) / size - 1.0,
        e == 0 ? -1.0 : 1.0, 1.0 };
      inverse->MultiplyPoint(ndc, ends[e]);
      for (int c = 0; c < 3; ++c)
      {
        ends[e][c] /= ends[e][3];
      }
    }
    const double dy = ends[1][1] - ends[0][1];
    if (!(dy < 0.0))
    {
      return false;
    }
    const double t = (this->Height - ends[0][1]) / dy;
    for (int c = 0; c < 3; ++c)
    {
      x[c] = ends[0][c] + t * (ends[1][c] - ends[0][c]);
    }
    return t > 0.0 && t < 1.0 && x[0] > this->Low && x[0] < this->High && x[2] > this->Low &&
      x[2] < this->High;
  }
};
}

#endif
