#include "vtkSingleScatteringReference.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallReferenceScene.h"
#include "vtkTyndallSceneReader.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkSingleScatteringReference);

class vtkSingleScatteringReference::vtkInternals
{
public:
  vtkTyndallSceneReader Scene;
};

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

template <typename T>
class RowRenderer
{
public:
  RowRenderer(const Scene& scene, const vtkTyndallGridMedium& medium)
    : S(&scene)
    , Field(medium)
  {
  }

  const Scene* S;
  vtkTyndallGridMedium::Sampler<T> Field;

  // The light transmittance from the world point x to `light`, per channel.
  void PointTransmittance(
    const Scene::LightSource& light, const double x[3], double transmittance[3]) const
  {
    double l[3], dl[3], factor, tMax;
    this->S->LightGeometry(light, x, l, dl, factor, tMax);
    double p[3];
    this->S->ToIndexPoint(x, p);
    const double grey = this->LightTransmittance(p, dl, tMax);
    for (int c = 0; c < 3; ++c)
    {
      transmittance[c] = this->S->Chromatic ? this->S->ChannelTransmittance(grey, c) : grey;
    }
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
        if (this->S->Chromatic)
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
  // The extinction at a field index point and its table position; false
  // for empty medium (missing data included: a NaN scalar).
  bool Extinction(const double p[3], double& sigma, int& k, double& f, bool clip = true) const
  {
    if (clip && !this->S->Inside(p))
    {
      return false;
    }
    const double s = this->Field.ReferenceScalar(p);
    if (std::isnan(s))
    {
      return false;
    }
    this->S->Table->Locate(s, k, f);
    sigma = this->S->Detail ? this->S->Detail->Extinction(p)
                            : this->S->DensityScale * this->S->Table->ExtinctionAt(k, f);
    return sigma > 0.0;
  }

  // T_l from the index-space point p along the index-space image d of a unit
  // world direction, up to the world distance tMax: through this medium and
  // the guests (the other volumes the light crosses).
  double LightTransmittance(const double p[3], const double d[3], double tMax) const
  {
    const double guests = this->S->Guests.empty()
      ? 0.0
      : this->S->GuestOpticalDepth(p, d, tMax, this->S->LightStep, this->S->MaxOpticalDepth);
    return std::exp(-guests) * this->OwnTransmittance(p, d, tMax);
  }

  // T_l through this medium alone, up to its box's exit or tMax.
  double OwnTransmittance(const double p[3], const double d[3], double tMax) const
  {
    double t0 = 0.0, t1 = tMax;
    if (!Scene::ClipToBox(p, d, this->S->BoxLow, this->S->BoxHigh, t0, t1))
    {
      return 1.0;
    }
    // [t0, t1]: the part of the ray in the box (t0 = 0 for a point inside
    // it; a point outside, such as a surface receiving the shadow, samples
    // no clamped voxels on its way in).
    const bool clip = this->S->Clip && !this->S->LightIgnoresClipping;
    if (this->S->Detail && !clip)
    {
      return std::exp(-this->S->Detail->OpticalDepth(p, d, t0, t1)); // closed form
    }
    const double length = t1 - t0;
    const double steps = std::max(1.0, std::ceil(length / this->S->LightStep));
    const int n = static_cast<int>(steps);
    const double dt = length / n;
    double tau = 0.0;
    for (int m = 0; m < n; ++m)
    {
      const double t = t0 + (m + 0.5) * dt;
      const double q[3] = { p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2] };
      double sigma;
      int k;
      double f;
      if (this->Extinction(q, sigma, k, f, clip))
      {
        tau += sigma * dt;
        if (tau > this->S->MaxOpticalDepth)
        {
          break;
        }
      }
    }
    return std::exp(-tau);
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
    double o[3], d[3];
    s.ToIndexPoint(origin, o);
    s.ToIndexDirection(w, d);
    double t0 = 0.0, t1 = rayLength;
    if (!s.ClipToCameraBoxes(o, d, t0, t1))
    {
      return;
    }
    const double steps = std::max(1.0, std::ceil((t1 - t0) / s.Step));
    const int n = static_cast<int>(steps);
    const double dt = (t1 - t0) / n;

    double* Tv = transmittance;
    double* L = radiance;
    for (int m = 0; m < n; ++m)
    {
      const double t = t0 + (m + 0.5) * dt;
      const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
      double sigma = 0.0, color[3], emission[3];
      const bool dense = this->CameraMedium(p, sigma, color, emission);
      double sigmaC[3]; // per channel
      for (int c = 0; c < 3; ++c)
      {
        sigmaC[c] = dense ? sigma * s.ExtinctionColor[c] : 0.0;
      }
      if (s.EmissionArray && s.Inside(p))
      {
        // Emission per unit length, attenuated within the step.
        double weight[3];
        for (int c = 0; c < 3; ++c)
        {
          weight[c] = Tv[c] * (sigmaC[c] > 0.0 ? -std::expm1(-sigmaC[c] * dt) / sigmaC[c] : dt);
        }
        this->AddArrayEmission(p, weight, L);
      }
      if (!dense)
      {
        continue;
      }
      double J[3];
      this->Source(color, emission, origin, w, t, p, J);
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

  // L += weight * EmissionScale * the emission array's colour at index point p (per channel).
  void AddArrayEmission(const double p[3], const double weight[3], double L[3]) const
  {
    const Scene& s = *this->S;
    int k;
    double f;
    s.Table->LocateEmission(s.Medium->EmissionValue(p), k, f);
    double e[3];
    vtkTyndallTransferTable::RGBAt(s.Table->Emission, k, f, e);
    for (int c = 0; c < 3; ++c)
    {
      L[c] += weight[c] * s.EmissionScale * e[c];
    }
  }

  // What the camera rays see at the index point p: the extinction of this
  // medium (inside its box) plus its camera guests', with their colours and
  // emission colours (per unit extinction; zero without emission) mixed in
  // proportion to their extinctions (GPU twin: tyndallCameraMedium()).
  // False for empty medium.
  bool CameraMedium(const double p[3], double& sigma, double color[3], double emission[3]) const
  {
    const Scene& s = *this->S;
    std::fill(color, color + 3, 0.0);
    std::fill(emission, emission + 3, 0.0);
    const bool emits = s.HasEmission && !s.EmissionArray;
    sigma = 0.0;
    int k;
    double f;
    // Alone, the ray was clipped to the box: its samples lie inside.
    const bool own = (!s.CameraGuests || Scene::InsideBox(p, s.BoxLow, s.BoxHigh)) &&
      this->Extinction(p, sigma, k, f);
    double albedo[3]; // a coloured particle cloud's, else the table's
    if (own)
    {
      const bool coloured = this->Field.ReferenceColor(p, albedo);
      AddColors(*s.Table, k, f, sigma, emits, coloured ? albedo : nullptr, color, emission);
    }
    else
    {
      sigma = 0.0;
    }
    for (const Scene::Guest& g : s.Guests)
    {
      double q[3], sg;
      if (g.Camera && (g.ToGuest(p, q), g.Sample(q, sg, k, f)) && sg > 0.0)
      {
        sigma += sg;
        const bool coloured = g.Medium->ParticleColor(q, albedo);
        AddColors(*g.Table, k, f, sg, emits, coloured ? albedo : nullptr, color, emission);
      }
    }
    if (!(sigma > 0.0))
    {
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      color[c] /= sigma;
      emission[c] /= sigma;
    }
    return true;
  }

  // Adds weight x the colour (`albedo`, or without it the table's) and
  // the emission colour when `emits` at the table position (k, f) of `table`.
  static void AddColors(const vtkTyndallTransferTable& table, int k, double f, double weight,
    bool emits, const double* albedo, double color[3], double emission[3])
  {
    double c[3];
    vtkTyndallTransferTable::RGBAt(table.Albedo, k, f, c);
    if (albedo)
    {
      std::copy(albedo, albedo + 3, c);
    }
    double e[3] = { 0.0, 0.0, 0.0 };
    if (emits)
    {
      vtkTyndallTransferTable::RGBAt(table.Emission, k, f, e);
    }
    for (int i = 0; i < 3; ++i)
    {
      color[i] += weight * c[i];
      emission[i] += weight * e[i];
    }
  }

  // The source term J of a sample of colour (or albedo) `color` and emission
  // colour `emission` at the distance t along the camera ray origin + t w
  // (index point p).
  void Source(const double color[3], const double emission[3], const double origin[3],
    const double w[3], double t, const double p[3], double J[3]) const
  {
    const Scene& s = *this->S;
    if (!s.SingleScattering)
    {
      std::copy(color, color + 3, J);
      return;
    }
    double in[3] = { s.Ambient, s.Ambient, s.Ambient };
    if (color[0] != 0.0 || color[1] != 0.0 || color[2] != 0.0)
    {
      const double x[3] = { origin[0] + t * w[0], origin[1] + t * w[1], origin[2] + t * w[2] };
      s.AddInScattering(
        x, w, color,
        [&](const double dl[3], double tMax) { return this->LightTransmittance(p, dl, tMax); }, in);
    }
    for (int c = 0; c < 3; ++c)
    {
      J[c] = color[c] * in[c] + s.EmissionScale * emission[c];
    }
  }
};

template <typename T>
void RenderRows(
  const Scene& scene, const vtkTyndallGridMedium& medium, vtkIdType begin, vtkIdType end)
{
  RowRenderer<T> renderer(scene, medium);
  vtkSMPTools::For(begin, end, 1, renderer);
}
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::vtkSingleScatteringReference()
  : Internals(new vtkInternals)
{
  this->Output = vtkImageData::New();
  this->CompositeOutput = vtkImageData::New();
}

//------------------------------------------------------------------------------
vtkSingleScatteringReference::~vtkSingleScatteringReference()
{
  this->Output->Delete();
  this->CompositeOutput->Delete();
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
void vtkSingleScatteringReference::UpdateProgress(double progress)
{
  this->Progress = progress;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Render(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  this->AbortExecute = false;
  this->Progress = 0.0;
  return vtkTyndallReferenceScene::TimedRender(
    this, this->Output, this->CompositeOutput,
    [&] { return this->RenderInternal(renderer, volume, width, height); }, this->LastRenderTime);
}

//------------------------------------------------------------------------------
namespace
{
// The steps (by default a quarter of the world length of one field index
// step along the shortest axis, or of half the detail's shortest
// wavelength) and early termination; false (with an error through
// `reporter`) for steps too small.
bool SetUpSteps(const vtkTyndallSceneReader& tyndall, double stepSize, double lightStepSize,
  double threshold, Scene& scene, vtkObject* reporter)
{
  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  const double minVoxel = std::min(medium.GetMinimumWorldSpacing(),
    scene.CameraGuests ? scene.CameraGuestSpacing : medium.GetMinimumWorldSpacing());
  const double wavelength =
    scene.Detail ? scene.Detail->GetShortestWavelength(medium.GetWorldToIndex()) : 1e30;
  scene.Step = stepSize > 0.0 ? stepSize : std::min(minVoxel, wavelength / 2.0) / 4.0;
  scene.LightStep = lightStepSize > 0.0 ? lightStepSize : scene.Step;
  if (!(scene.Step > 0.0) || !(scene.LightStep > 0.0) ||
    (medium.GetWorldDiagonal() + scene.GuestDiagonals) / std::min(scene.Step, scene.LightStep) >
      kMaxStepsPerRay)
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
  scene.MaxOpticalDepth = threshold > 0.0 ? -std::log(threshold) : kInfinity;
  if (scene.Octaves > 1)
  {
    // The last octave sees w T^(b^(N-1)), w = max(1, a)^(N-1) at most: march
    // until that falls below the threshold (b = 0: it never does).
    const double exponent = std::pow(scene.OctaveFactors[1], scene.Octaves - 1);
    const double weight = std::pow(std::max(1.0, scene.OctaveFactors[0]), scene.Octaves - 1);
    scene.MaxOpticalDepth = exponent > 0.0 && threshold > 0.0
      ? (scene.MaxOpticalDepth + std::log(weight)) / exponent
      : kInfinity;
  }
  // The faintest channel of a coloured extinction sees T^e.
  scene.MaxOpticalDepth /= medium.GetFaintestChannel();
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkSingleScatteringReference::RenderInternal(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  vtkTyndallSceneReader& tyndall = this->Internals->Scene;
  Scene scene;
  if (!scene.ReadScene(tyndall, renderer, volume, width, height, this) ||
    !SetUpSteps(
      tyndall, this->StepSize, this->LightStepSize, this->EarlyTerminationThreshold, scene, this) ||
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
  transmittance->SetNumberOfComponents(scene.Chromatic ? 3 : 1);
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

  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  const auto rows = [&](vtkIdType begin, vtkIdType end)
  {
    switch (medium.GetScalars()->GetDataType())
    {
      vtkTemplateMacro(RenderRows<VTK_TT>(scene, medium, begin, end));
    }
  };
  if (!scene.RenderRowBatches(
        this->AbortExecute, [this](double progress) { this->UpdateProgress(progress); }, rows))
  {
    return false;
  }

  scene.SetOutput(this->Output, radiance, transmittance);
  this->LastStepSize = scene.Step;
  this->LastLightStepSize = scene.LightStep;
  renderer->GetBackground(this->LastBackground);
  return true;
}

//------------------------------------------------------------------------------
bool vtkSingleScatteringReference::ComputeLightTransmittance(vtkRenderer* renderer,
  vtkVolume* volume, int light, const double point[3], double transmittance[3])
{
  transmittance[0] = transmittance[1] = transmittance[2] = 1.0;
  vtkTyndallSceneReader& tyndall = this->Internals->Scene;
  Scene scene;
  if (!point || !scene.ReadScene(tyndall, renderer, volume, 1, 1, this) ||
    !SetUpSteps(
      tyndall, this->StepSize, this->LightStepSize, this->EarlyTerminationThreshold, scene, this) ||
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
  const vtkTyndallGridMedium& medium = tyndall.GetMedium();
  switch (medium.GetScalars()->GetDataType())
  {
    vtkTemplateMacro(RowRenderer<VTK_TT>(scene, medium)
                       .PointTransmittance(scene.Lights[light], point, transmittance));
  }
  return true;
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Composite()
{
  return this->Composite(this->LastBackground);
}

//------------------------------------------------------------------------------
vtkImageData* vtkSingleScatteringReference::Composite(const double background[3])
{
  vtkDoubleArray* radiance =
    vtkDoubleArray::SafeDownCast(this->Output->GetPointData()->GetArray("Radiance"));
  vtkDoubleArray* transmittance =
    vtkDoubleArray::SafeDownCast(this->Output->GetPointData()->GetArray("Transmittance"));
  this->CompositeOutput->Initialize();
  if (!radiance || !transmittance)
  {
    vtkErrorMacro(<< "Composite: there is no rendered image; call Render() first.");
    return nullptr;
  }
  if (!background)
  {
    vtkErrorMacro(<< "Composite: the background colour is null.");
    return nullptr;
  }
  vtkTyndallReferenceScene::Composite(
    this->Output, radiance, transmittance, background, this->CompositeOutput);
  return this->CompositeOutput;
}

//------------------------------------------------------------------------------
void vtkSingleScatteringReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "LightStepSize: " << this->LightStepSize << "\n";
  os << indent << "EarlyTerminationThreshold: " << this->EarlyTerminationThreshold << "\n";
  os << indent << "LightIgnoresClipping: " << this->LightIgnoresClipping << "\n";
  os << indent << "AbortExecute: " << (this->AbortExecute ? "On" : "Off") << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "LastStepSize: " << this->LastStepSize << "\n";
  os << indent << "LastLightStepSize: " << this->LastLightStepSize << "\n";
  os << indent << "LastBackground: (" << this->LastBackground[0] << ", " << this->LastBackground[1]
     << ", " << this->LastBackground[2] << ")\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
}
