#include "vtkSingleScatteringReference.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallReferenceScene.h"
#include "vtkTyndallSceneReader.h"
#include "vtkTyndallShading.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkSingleScatteringReference);

namespace
{
// The most steps one ray may take across the volume's box.
constexpr double kMaxStepsPerRay = 1.0e7;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Everything the rendering loop reads; read only inside the loop.
struct Scene : public vtkTyndallReferenceScene
{
  double Step = 1.0;
  double LightStep = 1.0;
  double Threshold = 0.0;
  double MaxOpticalDepth = kInfinity;
  bool LightIgnoresClipping = false;
};

using Point = vtkTyndallMedium::Point;
using LocalRays = vtkTyndallReferenceScene::LocalRays;

class RowRenderer
{
public:
  explicit RowRenderer(const Scene& scene)
    : S(&scene)
  {
  }

  // The light transmittance from the world point x to `light`, per channel.
  void PointTransmittance(
    const Scene::LightSource& light, const double x[3], double transmittance[3]) const
  {
    double l[3], factor, tMax;
    this->S->LightGeometry(light, x, l, factor, tMax);
    this->S->ChannelTransmittances(
      this->LightTransmittance(x, nullptr, 0.0, l, tMax), transmittance);
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    for (vtkIdType j = begin; j < end; ++j)
    {
      for (int i = 0; i < this->S->Width; ++i)
      {
        const vtkIdType pixel = j * this->S->Width + i;
        double transmittance[3];
        this->RenderPixel(i, static_cast<int>(j), this->S->Radiance + 3 * pixel, transmittance);
        if (this->S->GetChromatic())
        {
          std::copy(transmittance, transmittance + 3, this->S->Transmittance + 3 * pixel);
        }
        else
        {
          this->S->Transmittance[pixel] = transmittance[0];
        }
      }
    }
  }

private:
  const Scene* S;

  // T_l from the world point x along the unit world direction l, up to the
  // world distance tMax: through every medium of the scene (each up to its
  // box's exit). `camera` (unless null) holds the camera ray's images, whose
  // points at the distance t are x's in the camera media's frames.
  double LightTransmittance(
    const double x[3], const LocalRays* camera, double t, const double l[3], double tMax) const
  {
    const Scene& s = *this->S;
    double own = 0.0, guests = 0.0;
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      if (k > 0 && guests > s.MaxOpticalDepth)
      {
        break; // the guests have darkened the light past the threshold already
      }
      const vtkTyndallMedium& medium = *s.Media[k].Medium;
      double p[3], d[3];
      if (camera && s.Media[k].Camera)
      {
        camera->At(static_cast<int>(k), t, p);
      }
      else
      {
        medium.ToLocalPoint(x, p);
      }
      medium.ToLocalDirection(l, d);
      if (k == 0)
      {
        own = medium.OpticalDepth(
          p, d, 0.0, tMax, s.LightStep, s.MaxOpticalDepth, !s.LightIgnoresClipping);
      }
      else
      {
        guests += medium.OpticalDepth(p, d, 0.0, tMax, s.LightStep, s.MaxOpticalDepth - guests);
      }
    }
    return std::exp(-guests) * std::exp(-own);
  }

  // The pixel's radiance and view transmittance per channel (equal
  // channels without a coloured extinction).
  void RenderPixel(int i, int j, double* radiance, double transmittance[3]) const
  {
    const Scene& s = *this->S;
    radiance[0] = radiance[1] = radiance[2] = 0.0;
    transmittance[0] = transmittance[1] = transmittance[2] = 1.0;
    // Unproject the pixel centre at the near and far planes.
    double origin[3], w[3], rayLength;
    if (s.DrawnByAnother || !s.CameraRay(i, j, origin, w, rayLength))
    {
      return; // nothing, or drawn by the first volume of its camera group
    }
    LocalRays rays;
    double t0 = 0.0, t1 = rayLength;
    if (!s.ClipToCameraMedia(origin, w, rays, t0, t1))
    {
      return;
    }
    if (s.Projected)
    {
      this->ProjectPixel(origin, w, rays, t0, t1, radiance, transmittance);
      return;
    }
    const double steps = std::max(1.0, std::ceil((t1 - t0) / s.Step));
    const int n = static_cast<int>(steps);
    const double dt = (t1 - t0) / n;
    const vtkTyndallMedium& own = *s.Media[0].Medium;
    const bool arrayEmission = own.GetArrayEmission();
    const double* extinctionColor = s.Parameters->ExtinctionColor;

    double* Tv = transmittance;
    double* L = radiance;
    for (int m = 0; m < n; ++m)
    {
      // The step's middle; for isosurfaces where its first surface lies, their
      // normal at the step's end (where VTK shades them).
      double t = t0 + (m + 0.5) * dt;
      double tNormal = t;
      Point point;
      bool dense;
      if (s.Isosurfaced)
      {
        dense = this->IsoSample(rays, t0 + m * dt, dt, point, t);
        tNormal = t0 + (m + 1) * dt;
      }
      else
      {
        const double x[3] = { origin[0] + t * w[0], origin[1] + t * w[1], origin[2] + t * w[2] };
        dense = this->CameraMedium(rays, t, s.Footprint.At(x), point);
      }
      double sigmaC[3]; // per channel
      for (int c = 0; c < 3; ++c)
      {
        sigmaC[c] = dense ? point.Extinction * extinctionColor[c] : 0.0;
      }
      if (arrayEmission)
      {
        // Emission per unit length, attenuated within the step.
        double p[3], e[3];
        rays.At(0, t, p);
        own.ArrayEmission(p, e);
        for (int c = 0; c < 3; ++c)
        {
          const double weight =
            Tv[c] * (sigmaC[c] > 0.0 ? -std::expm1(-sigmaC[c] * dt) / sigmaC[c] : dt);
          L[c] += weight * s.Parameters->EmissionScale * e[c];
        }
      }
      if (!dense)
      {
        continue;
      }
      double J[3];
      this->Source(point, origin, w, t, tNormal, rays, J);
      // The step's medium is constant: integrate it exactly.
      for (int c = 0; c < 3; ++c)
      {
        const double a = -std::expm1(-sigmaC[c] * dt);
        L[c] += Tv[c] * J[c] * a;
        Tv[c] *= 1.0 - a;
      }
      if (std::max(std::max(Tv[0], Tv[1]), Tv[2]) < s.Threshold)
      {
        break;
      }
    }
  }

  // A plain property's gradient shading (vtkTyndallShading; GPU twin:
  // tyndallSurfaceShading()) of the sample `point` at the world point x, its
  // normal taken at the distance tNormal along the camera ray (direction w,
  // images `rays`): each light shadowed by its transmittance through the media.
  void Shade(const Point& point, const double x[3], const double w[3], double tNormal,
    const LocalRays& rays, double J[3]) const
  {
    const Scene& s = *this->S;
    const vtkTyndallGridMedium& grid = *s.Shaded;
    const vtkTyndallShading& shading = grid.GetShading();
    // A medium's Shade: the surface term alone, of the mixture's colour.
    const bool additive = shading.GetAdditive();
    double p[3];
    rays.At(0, tNormal, p);
    // One part (the sample's colour), or independent components' each
    // (vtkTyndallGridMedium::ComponentParts()) with its own gradient.
    constexpr int most = vtkTyndallComponents::MaximumCount;
    double weights[most] = { 1.0, 0.0, 0.0, 0.0 }, colors[most][3] = {};
    double sigma[most] = { point.Extinction, 0.0, 0.0, 0.0 };
    std::copy(point.Albedo, point.Albedo + 3, colors[0]);
    const bool independent =
      !additive && grid.GetComponents().GetMode() == vtkTyndallComponents::Independent;
    const int parts = independent ? grid.GetComponents().GetCount() : 1;
    if (independent && !grid.ComponentParts(p, weights, colors, sigma))
    {
      J[0] = J[1] = J[2] = 0.0;
      return;
    }
    // Each part's unit normal and blending weight (vtkTyndallShading).
    double n[most][3], blend[most];
    vtkTyndallShading::Sums sums[most];
    for (int i = 0; i < parts; ++i)
    {
      grid.FieldGradient(p, n[i], i);
      const double length = vtkMath::Norm(n[i]);
      for (int c = 0; c < 3; ++c)
      {
        n[i][c] = length > 0.0 ? n[i][c] / length : 0.0;
      }
      const double* range = grid.GetComponentRange(i);
      blend[i] =
        shading.BlendWeight(length, sigma[i], range[1] - range[0], grid.GetMinimumWorldSpacing());
      shading.Start(colors[i], sums[i], i);
      if (additive)
      {
        std::fill(sums[i].Surface, sums[i].Surface + 3, 0.0);
      }
    }
    const double v[3] = { -w[0], -w[1], -w[2] };
    // The renderer's lights, then the sky's (its directional lights, or its
    // mean from every direction).
    auto addLight = [&](const Scene::LightSource& light)
    {
      double l[3], factor, tMax;
      if (!s.LightGeometry(light, x, l, factor, tMax))
      {
        return;
      }
      double T[3];
      this->SurfaceTransmittance(grid, x, l, tMax, T);
      const double E[3] = { factor * light.Color[0], factor * light.Color[1],
        factor * light.Color[2] };
      for (int i = 0; i < parts; ++i)
      {
        shading.AddLight(n[i], light.Headlight ? v : l, v, colors[i], E, T, sums[i], i);
      }
    };
    std::for_each(s.Lights.begin(), s.Lights.end(), addLight);
    std::for_each(s.SkyLights.begin(), s.SkyLights.end(), addLight);
    J[0] = J[1] = J[2] = 0.0;
    for (int i = 0; i < parts; ++i)
    {
      shading.AddSkyMean(n[i], colors[i], s.ShadingSkyMean, sums[i], i);
      double rgb[3] = { sums[i].Surface[0], sums[i].Surface[1], sums[i].Surface[2] };
      if (!additive)
      {
        vtkTyndallShading::Finish(sums[i], blend[i], rgb);
      }
      for (int c = 0; c < 3; ++c)
      {
        J[c] += weights[i] * rgb[c];
      }
    }
  }

  // T_l of a surface at the world point x towards l (up to tMax) on `grid`
  // (shaded samples, isosurfaces): a surface does not shadow itself, T_l is
  // taken ShadowOffset voxels towards the light (the camera media's frames:
  // the offset point's own images, not the ray's).
  void SurfaceTransmittance(const vtkTyndallGridMedium& grid, const double x[3], const double l[3],
    double tMax, double T[3]) const
  {
    const double offset = vtkTyndallShading::ShadowOffset * grid.GetMinimumWorldSpacing();
    const double y[3] = { x[0] + offset * l[0], x[1] + offset * l[1], x[2] + offset * l[2] };
    this->S->ChannelTransmittances(
      this->LightTransmittance(y, nullptr, 0.0, l, std::max(tMax - offset, 0.0)), T);
  }

  // A projection blend mode (vtkTyndallProjection; GPU twin:
  // vtkTransmittanceProjectionFS.glsl): the grid's scalars at the middles of
  // n equal steps of [t0, t1], gathered by vtkTyndallProjection::Ray; the
  // premultiplied pixel, its transmittance 1 - alpha.
  void ProjectPixel(const double origin[3], const double w[3], const LocalRays& rays, double t0,
    double t1, double* radiance, double transmittance[3]) const
  {
    const vtkTyndallGridMedium& grid = *this->S->Projected;
    const vtkTyndallProjection& projection = grid.GetProjection();
    const bool components = grid.GetComponents().Enabled();
    vtkTyndallProjection::Ray ray = components
      ? vtkTyndallProjection::Ray(projection, this->S->ProjectionClasses)
      : vtkTyndallProjection::Ray(projection, grid.GetTable());
    // The scalar (or every component) at the distance t, to the ray (kept,
    // not missing).
    auto add = [&](double t, double dt)
    {
      double p[3], values[vtkTyndallComponents::MaximumCount];
      rays.At(0, t, p);
      if (components ? grid.KeptComponents(p, true, values) : grid.KeptScalar(p, true, values[0]))
      {
        if (components)
        {
          ray.AddComponents(values, dt);
        }
        else
        {
          ray.Add(values[0], dt);
        }
      }
    };
    double t = 0.0;
    if (projection.GetMode() == vtkTyndallProjection::SLICE)
    {
      // The one sample where the ray meets the plane, on its part in the box.
      if (projection.SliceDistance(origin, w, t) && t >= t0 && t <= t1)
      {
        add(t, 0.0);
      }
    }
    else
    {
      const int n = static_cast<int>(std::max(1.0, std::ceil((t1 - t0) / this->S->Step)));
      const double dt = (t1 - t0) / n;
      for (int m = 0; m < n; ++m)
      {
        add(t0 + (m + 0.5) * dt, dt);
      }
    }
    double rgba[4];
    if (ray.Pixel(rgba))
    {
      if (projection.GetMode() == vtkTyndallProjection::SLICE && !components)
      {
        this->SliceSurface(origin, w, rays, t, rgba);
      }
      std::copy(rgba, rgba + 3, radiance);
      std::fill(transmittance, transmittance + 3, 1.0 - rgba[3]);
    }
  }

  // The slice's pixel rgba (premultiplied) at the distance t as VTK 9.1
  // draws a slice of one component (GPU twin: tyndallProjectionSurface()): with
  // Shade its colour shaded as a surface by the lights, unshadowed (a
  // projection has no maps), and with gradient opacity its alpha (not the
  // colour's weight) multiplied by it.
  void SliceSurface(const double origin[3], const double w[3], const LocalRays& rays, double t,
    double rgba[4]) const
  {
    const Scene& s = *this->S;
    const vtkTyndallGridMedium& grid = *s.Projected;
    double p[3];
    rays.At(0, t, p);
    const double alpha = rgba[3];
    if (s.Shaded && alpha > 0.0)
    {
      const double x[3] = { origin[0] + t * w[0], origin[1] + t * w[1], origin[2] + t * w[2] };
      const double color[3] = { rgba[0] / alpha, rgba[1] / alpha, rgba[2] / alpha };
      double n[3];
      grid.FieldGradient(p, n, 0);
      const double length = vtkMath::Norm(n);
      for (double& c : n)
      {
        c = length > 0.0 ? c / length : 0.0;
      }
      const vtkTyndallShading& shading = grid.GetShading();
      vtkTyndallShading::Sums sums;
      shading.Start(color, sums);
      const double v[3] = { -w[0], -w[1], -w[2] };
      const double unshadowed[3] = { 1.0, 1.0, 1.0 };
      for (const Scene::LightSource& light : s.Lights)
      {
        double l[3], factor, tMax;
        if (s.LightGeometry(light, x, l, factor, tMax))
        {
          const double E[3] = { factor * light.Color[0], factor * light.Color[1],
            factor * light.Color[2] };
          shading.AddLight(n, light.Headlight ? v : l, v, color, E, unshadowed, sums);
        }
      }
      double rgb[3];
      vtkTyndallShading::Finish(sums, 0.0, rgb);
      for (int c = 0; c < 3; ++c)
      {
        rgba[c] = rgb[c] * alpha;
      }
    }
    if (grid.GetGradientOpacity())
    {
      rgba[3] = alpha * grid.GradientOpacityAt(p);
    }
  }

  // The isosurfaces (vtkTyndallIsosurfaces; GPU twin: tyndallIsoCameraSample())
  // the camera ray's step from the distance t0, of length dt, crosses; `t`:
  // where the first lies.
  bool IsoSample(const LocalRays& rays, double t0, double dt, Point& point, double& t) const
  {
    double p0[3], p1[3], first;
    rays.At(0, t0, p0);
    rays.At(0, t0 + dt, p1);
    const bool crossed = this->S->Isosurfaced->IsoSample(p0, p1, dt, point, first);
    t = t0 + first * dt;
    return crossed;
  }

  // What the camera rays see at the distance t: the extinction of the
  // camera media summed, with their colours and emission colours (per unit
  // extinction) mixed in proportion to their extinctions (GPU twin:
  // tyndallCameraMedium()); procedural detail filtered by `pixel`, the
  // world width of a pixel there (vtkTyndallFootprint). False for empty medium.
  bool CameraMedium(const LocalRays& rays, double t, double pixel, Point& mixed) const
  {
    const Scene& s = *this->S;
    mixed = Point();
    for (size_t k = 0; k < s.Media.size(); ++k)
    {
      Point point;
      double p[3];
      rays.At(static_cast<int>(k), t, p);
      if (s.Media[k].Camera && s.Media[k].Medium->Sample(p, point, pixel))
      {
        mixed.Extinction += point.Extinction;
        for (int c = 0; c < 3; ++c)
        {
          mixed.Albedo[c] += point.Extinction * point.Albedo[c];
          mixed.Emission[c] += point.Extinction * point.Emission[c];
        }
      }
    }
    if (!(mixed.Extinction > 0.0))
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      mixed.Albedo[c] /= mixed.Extinction;
      mixed.Emission[c] /= mixed.Extinction;
    }
    return true;
  }

  // The source term J of a sample `point` at the distance t along the camera
  // ray origin + t w (its images `rays`); a shaded sample's normal at tNormal.
  void Source(const Point& point, const double origin[3], const double w[3], double t,
    double tNormal, const LocalRays& rays, double J[3]) const
  {
    const Scene& s = *this->S;
    const double* color = point.Albedo;
    if (!s.Parameters->GetSingleScattering())
    {
      std::copy(color, color + 3, J);
      return;
    }
    const double x[3] = { origin[0] + t * w[0], origin[1] + t * w[1], origin[2] + t * w[2] };
    if (s.Shaded && !s.Shaded->GetShading().GetAdditive())
    {
      this->Shade(point, x, w, tNormal, rays, J);
      return;
    }
    s.Source(
      point, x, w, *s.Parameters, // (the camera media are lit alike)
      [&](const double l[3], double tMax, double T[3])
      {
        if (s.Isosurfaced)
        {
          this->SurfaceTransmittance(*s.Isosurfaced, x, l, tMax, T);
        }
        else
        {
          s.ChannelTransmittances(this->LightTransmittance(x, &rays, t, l, tMax), T);
        }
      },
      J);
    if (s.Shaded)
    {
      // A vtkParticipatingMediumProperty's Shade: its surface term added.
      double surface[3];
      this->Shade(point, x, w, tNormal, rays, surface);
      for (int c = 0; c < 3; ++c)
      {
        J[c] += surface[c];
      }
    }
  }
};
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::vtkSingleScatteringReference() = default;

//------------------------------------------------------------------------------
vtkSingleScatteringReference::~vtkSingleScatteringReference() = default;

//------------------------------------------------------------------------------
namespace
{
// The steps (by default a quarter of the camera media's finest feature: a
// voxel along the shortest axis, or half the detail's shortest wavelength)
// and early termination; false (with an error through `reporter`) for steps
// too small.
bool SetUpSteps(
  double stepSize, double lightStepSize, double threshold, Scene& scene, vtkObject* reporter)
{
  scene.Step = stepSize > 0.0 ? stepSize : scene.GetCameraFinestFeature() / 4.0;
  scene.LightStep = lightStepSize > 0.0 ? lightStepSize : scene.Step;
  if (!(scene.Step > 0.0) || !(scene.LightStep > 0.0) ||
    scene.GetDiagonals() / std::min(scene.Step, scene.LightStep) > kMaxStepsPerRay)
  {
    vtkErrorWithObjectMacro(reporter, << "Render: the step " << scene.Step << " (light step "
                                      << scene.LightStep << ") would take more than "
                                      << kMaxStepsPerRay
                                      << " steps across the volume and its guests; set a larger "
                                         "StepSize / "
                                         "LightStepSize.");
    return false;
  }
  scene.Threshold = threshold;
  // March the light until the faintest octave and channel cannot see it.
  scene.MaxOpticalDepth = scene.Parameters->LightDepthLimit(threshold);
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkSingleScatteringReference::RenderImage(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  vtkTyndallSceneReader& tyndall = *this->SceneReader;
  Scene scene;
  if (!scene.ReadScene(tyndall, renderer, volume, width, height, this) ||
    !SetUpSteps(
      this->StepSize, this->LightStepSize, this->EarlyTerminationThreshold, scene, this) ||
    !scene.SetUpView(tyndall, renderer, this))
  {
    return false;
  }
  scene.LightIgnoresClipping = this->LightIgnoresClipping;

  // The output.
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkNew<vtkDoubleArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> transmittance;
  transmittance->SetName("Transmittance");
  transmittance->SetNumberOfComponents(scene.GetChromatic() ? 3 : 1);
  if (!radiance->Allocate(3 * pixels) ||
    !transmittance->Allocate(transmittance->GetNumberOfComponents() * pixels))
  {
    vtkErrorMacro(<< "Render: cannot allocate a " << width << " x " << height << " image.");
    return false;
  }
  radiance->SetNumberOfTuples(pixels);
  transmittance->SetNumberOfTuples(pixels);
  scene.Radiance = radiance->GetPointer(0);
  scene.Transmittance = transmittance->GetPointer(0);

  const auto rows = [&](vtkIdType begin, vtkIdType end)
  {
    RowRenderer renderer(scene);
    vtkSMPTools::For(begin, end, 1, renderer);
  };
  if (!scene.RenderRowBatches(
        this->AbortExecute, [this](double progress) { this->UpdateProgress(progress); }, rows))
  {
    return false;
  }

  scene.SetOutput(this->Output, radiance, transmittance);
  this->LastStepSize = scene.Step;
  this->LastLightStepSize = scene.LightStep;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSingleScatteringReference::ComputeLightTransmittance(vtkRenderer* renderer,
  vtkVolume* volume, int light, const double point[3], double transmittance[3])
{
  transmittance[0] = transmittance[1] = transmittance[2] = 1.0;
  vtkTyndallSceneReader& tyndall = *this->SceneReader;
  Scene scene;
  if (!point || !scene.ReadScene(tyndall, renderer, volume, 1, 1, this) ||
    !SetUpSteps(
      this->StepSize, this->LightStepSize, this->EarlyTerminationThreshold, scene, this) ||
    !scene.SetUpView(tyndall, renderer, this))
  {
    return false;
  }
  if (light < 0 || light >= static_cast<int>(scene.Lights.size()))
  {
    vtkErrorMacro(<< "ComputeLightTransmittance: light " << light << " is not one of the scene's "
                  << scene.Lights.size() << " lights.");
    return false;
  }
  scene.LightIgnoresClipping = this->LightIgnoresClipping;
  RowRenderer(scene).PointTransmittance(scene.Lights[light], point, transmittance);
  return true;
}

//------------------------------------------------------------------------------
void vtkSingleScatteringReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "LightStepSize: " << this->LightStepSize << "\n";
  os << indent << "EarlyTerminationThreshold: " << this->EarlyTerminationThreshold << "\n";
  os << indent << "LightIgnoresClipping: " << this->LightIgnoresClipping << "\n";
  os << indent << "LastStepSize: " << this->LastStepSize << "\n";
  os << indent << "LastLightStepSize: " << this->LastLightStepSize << "\n";
}
