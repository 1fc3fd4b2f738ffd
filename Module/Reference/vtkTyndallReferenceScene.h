/**
 * @class   vtkTyndallReferenceScene
 * @brief   what Tyndall's CPU integrators share: the scene's media, camera rays, lights, the row
 * loop and compositing
 *
 * vtkTyndallReferenceScene is the offline renderers' common base: the
 * single-scattering reference (vtkSingleScatteringReference) and the Monte
 * Carlo path tracer (vtkVolumetricPathTracer) set up and read a frame the
 * same way, and each renderer's own scene derives from it and adds its
 * integrator's settings.
 *
 * - Set-up: ReadScene() checks the image size and reads (renderer, volume)
 *   through a vtkTyndallSceneReader into the list of media (Media: the
 *   volume's own first, then the other volumes the light crosses, each a
 *   vtkTyndallMedium, marked when the camera rays sample it too); SetUpView()
 *   inverts the camera's composite projection and copies the lights.
 * - Geometry: a camera ray of a pixel (CameraRay(), pixel centres
 *   unprojected from the near to the far plane) and its image in every
 *   medium's frame (LocalRays: one world distance t serves them all), the
 *   direction, attenuation, spot cone and distance of a light seen from a
 *   point (LightGeometry()).
 * - Light: AddInScattering() sums E_l f_l p(mu_l) T_l over the lights (the
 *   octaves' sum with several), with the light transmittance T_l left to the
 *   integrator.
 * - The frame: TimedRender() wraps a render in its events and timing,
 *   RenderRowBatches() renders rows in batches with progress and abort
 *   checks between them, SetOutput() assembles the image and Composite()
 *   blends it over a background.
 *
 * The lighting (phase function, light scale, ambient, octaves, emission
 * scale) is the lit medium's, passed to Source() (`lit`): the camera rays'
 * is the volume's own medium's (Parameters; the media a camera ray samples
 * together are lit alike, vtkTyndallMediumParameters::SameLighting()), the
 * path tracer's collision in another medium that medium's. The coloured
 * extinction is the volume's own medium's.
 *
 * Internal to Tyndall::Reference; not wrapped.
 */

#ifndef vtkTyndallReferenceScene_h
#define vtkTyndallReferenceScene_h

#include "TyndallReferenceModule.h"  // For export macro
#include "vtkMath.h"                 // For vtkMath::Dot
#include "vtkTransmittanceMapMath.h" // For the phase function
#include "vtkTyndallEnvironment.h"   // For the sky
#include "vtkTyndallFootprint.h"     // For vtkTyndallFootprint
#include "vtkTyndallMedium.h"        // For the media
#include "vtkTyndallProjection.h"    // For vtkTyndallProjection::Classes
#include "vtkTyndallSceneReader.h"   // For MaximumNumberOfGuests
#include "vtkType.h"                 // For vtkIdType

#include <algorithm>  // For std::min
#include <cmath>      // For std::pow
#include <functional> // For std::function
#include <vector>     // For std::vector

class vtkDataArray;
class vtkImageData;
class vtkObject;
class vtkRenderer;
class vtkVolume;

class TYNDALLREFERENCE_EXPORT vtkTyndallReferenceScene
{
public:
  /// One light, as the integrators read it.
  struct LightSource
  {
    bool Positional = false;
    double ToLight[3] = { 0.0, 0.0, 1.0 };        // directional: unit, world
    double Position[3] = { 0.0, 0.0, 0.0 };       // positional, world
    double SpotDirection[3] = { 0.0, 0.0, -1.0 }; // unit, from the light to its focal point
    bool Spot = false;
    double CosCone = -1.0;
    double Exponent = 0.0;
    double Attenuation[3] = { 1.0, 0.0, 0.0 };
    double Color[3] = { 0.0, 0.0, 0.0 }; // Intensity * DiffuseColor (gradient shading)
    /// A renderer's light, which a medium sees its LightScale times brighter
    /// (AddLight()); a sky light is not scaled.
    bool Scaled = false;
    bool Headlight = false; // shades along the camera ray (vtkTyndallShading)
  };

  /// The most media a scene holds (the volume's own and its guests).
  static constexpr int MaximumNumberOfMedia = vtkTyndallSceneReader::MaximumNumberOfGuests + 1;

  /// A medium of the scene.
  struct Medium
  {
    const vtkTyndallMedium* Medium = nullptr;
    /// Whether the camera rays sample it (the volume's own, and the guests it draws as one medium).
    bool Camera = false;
  };

  int Width = 1;
  int Height = 1;
  double InverseProjection[16]; // world <- normalised device coordinates
  /// The world width of a pixel along the camera rays (what camera samples filter detail by).
  vtkTyndallFootprint Footprint;
  /// The media: the volume's own first, then the others the light crosses.
  std::vector<Medium> Media;
  /// The lighting of the camera rays: the volume's own medium's.
  const vtkTyndallMediumParameters* Parameters = nullptr;
  /// The renderer's lights (vtkTyndallSceneReader::GetLights()).
  std::vector<LightSource> Lights;
  /**
   * The renderer's environment (vtkTyndallSceneReader::GetEnvironment()):
   * the path tracer samples it (SampleSky).
   */
  const vtkTyndallEnvironment* Environment = nullptr;
  /**
   * Set before SetUpView(): whether the integrator samples the sky (the
   * path tracer) or, as the map-based frame does, has it as SkyLights and
   * MapAmbient (vtkSingleScatteringReference, the default).
   */
  bool SampleSky = false;
  /**
   * The sky's directional lights (vtkTyndallSceneReader::GetSkyLights();
   * none with SampleSky): AddInScattering() adds them after Lights, and
   * gradient shading lights with them too.
   */
  std::vector<LightSource> SkyLights;
  /**
   * The sky's mean radiance per channel that gradient shading takes as light
   * from every direction (vtkTyndallSceneReader::GetShadingSkyMean(): where
   * no sky light carries the sky); 0 with SampleSky.
   */
  double ShadingSkyMean[3] = { 0.0, 0.0, 0.0 };
  /**
   * The ambient radiance per channel Source() adds: the map-based frame's
   * (vtkTyndallSceneReader::GetMapAmbient()), or with SampleSky the
   * volume's own medium's AmbientIntensity alone (Source() takes the lit
   * medium's).
   */
  double Ambient[3] = { 0.0, 0.0, 0.0 };
  /**
   * The volume's grid when it is drawn in a projection blend mode
   * (vtkTyndallProjection; Media's first then), else null.
   */
  const vtkTyndallGridMedium* Projected = nullptr;
  /// Projected's classification of several components (set with it).
  vtkTyndallProjection::Classes ProjectionClasses;
  /**
   * The volume's grid when a plain property's gradient shading shades it
   * (vtkTyndallShading; Media's first then), else null.
   */
  const vtkTyndallGridMedium* Shaded = nullptr;
  /// The volume's grid when its mapper draws isosurfaces (vtkTyndallIsosurfaces), else null.
  const vtkTyndallGridMedium* Isosurfaced = nullptr;
  /// Whether this medium is drawn by another volume's camera rays
  /// (vtkTyndallSceneReader::GetDrawnBy()): it draws nothing itself.
  bool DrawnByAnother = false;
  double* Radiance = nullptr;
  double* Transmittance = nullptr;

  /**
   * A ray's image in every medium's frame: o + t d in medium k's frame for
   * the world ray x + t w (t a world distance in each).
   */
  struct LocalRays
  {
    double O[MaximumNumberOfMedia][3];
    double D[MaximumNumberOfMedia][3];

    /// Sets the images of the world ray x + t w (w a unit vector).
    void Set(const vtkTyndallReferenceScene& scene, const double x[3], const double w[3]);
    /// Medium k's point at the world distance t.
    void At(int k, double t, double p[3]) const
    {
      for (int c = 0; c < 3; ++c)
      {
        p[c] = this->O[k][c] + t * this->D[k][c];
      }
    }
  };

  /**
   * The part [t0, t1] (narrowed) of the world ray x + t w that the camera
   * media's boxes hold: from the first entry into any of them to the last
   * exit; `rays` receives the ray's images. False when it misses them all.
   */
  bool ClipToCameraMedia(
    const double x[3], const double w[3], LocalRays& rays, double& t0, double& t1) const;

  /// The smallest GetFinestFeature() of the camera media (world units).
  double GetCameraFinestFeature() const;

  /// The sum of the media's world diagonals (how far a ray may march through the scene).
  double GetDiagonals() const;

  /**
   * Checks the image size (each side in [1, 16384]), updates
   * `reader` from (renderer, volume) and sets the image size and the
   * media. Errors go through `reporter`; false on error.
   */
  bool ReadScene(vtkTyndallSceneReader& reader, vtkRenderer* renderer, vtkVolume* volume, int width,
    int height, vtkObject* reporter);

  /**
   * Inverts the active camera's composite projection (aspect Width /
   * Height) into InverseProjection and copies `reader`'s lights; call after
   * ReadScene(). False (with an error through `reporter`) for a singular
   * projection.
   */
  bool SetUpView(const vtkTyndallSceneReader& reader, vtkRenderer* renderer, vtkObject* reporter);

  /// Whether the channels' extinctions differ (the volume's own medium's).
  bool GetChromatic() const { return this->Parameters->GetChromatic(); }

  /**
   * Channel k's transmittance where the densest channel's is T:
   * T^ExtinctionColor[k] (1 for a channel without extinction).
   */
  double ChannelTransmittance(double T, int k) const
  {
    const double e = this->Parameters->ExtinctionColor[k];
    return e == 0.0 ? 1.0 : (T > 0.0 ? std::pow(std::min(T, 1.0), e) : 0.0);
  }

  /**
   * Every channel's transmittance where the densest channel's is `grey`
   * (ChannelTransmittance(); `grey` itself without a coloured extinction).
   */
  void ChannelTransmittances(double grey, double T[3]) const
  {
    for (int c = 0; c < 3; ++c)
    {
      T[c] = this->GetChromatic() ? this->ChannelTransmittance(grey, c) : grey;
    }
  }

  /// The phase function at the cosine mu (Henyey-Greenstein, the lit medium's anisotropy).
  static double Phase(const vtkTyndallMediumParameters& lit, double mu)
  {
    return vtkTransmittanceMapMath::HenyeyGreenstein(lit.ScatteringAnisotropy, mu);
  }

  /**
   * The camera ray of pixel (i, j): its world origin on the near plane, the
   * unit world direction w towards the far plane and the world length
   * between the planes. False for a degenerate ray.
   */
  bool CameraRay(int i, int j, double origin[3], double w[3], double& length) const;

  /**
   * Towards `light` from the world point x: the unit world direction l, the
   * attenuation and spot cone factor and the world distance tMax to a
   * positional light (infinity for a directional one). False when the light
   * does not reach x.
   */
  bool LightGeometry(
    const LightSource& light, const double x[3], double l[3], double& factor, double& tMax) const;

  /**
   * Adds E_l * f_l * p(mu_l) * T_l of every light to `in`, at the world
   * point x of the medium lit as `lit` says, seen along the unit world
   * direction w; `transmittance(l, tMax,
   * T)` sets T_l per channel along the world direction l (see
   * LightGeometry(); with a coloured extinction each channel's own, equal
   * channels without). With several octaves, p(mu_l) T_l becomes the
   * octaves' sum at the albedo `albedo` (vtkTransmittanceMapMath::OctaveScattering()).
   */
  template <typename LightTransmittance>
  void AddInScattering(const double x[3], const double w[3], const double albedo[3],
    const vtkTyndallMediumParameters& lit, LightTransmittance&& transmittance, double in[3]) const
  {
    for (const LightSource& light : this->Lights)
    {
      this->AddLight(light, x, w, albedo, lit, transmittance, in);
    }
    for (const LightSource& light : this->SkyLights)
    {
      this->AddLight(light, x, w, albedo, lit, transmittance, in);
    }
  }

  /**
   * AddInScattering()'s term of one light: E_l its colour, times the lit
   * medium's LightScale for a renderer's light (LightSource::Scaled).
   */
  template <typename LightTransmittance>
  void AddLight(const LightSource& light, const double x[3], const double w[3],
    const double albedo[3], const vtkTyndallMediumParameters& lit,
    LightTransmittance&& transmittance, double in[3]) const
  {
    const bool chromatic = this->GetChromatic();
    double l[3], factor, tMax;
    if (!this->LightGeometry(light, x, l, factor, tMax))
    {
      return;
    }
    // mu = dot(-l, -w): the light travels along -l, the camera is along -w.
    const double mu = vtkMath::Dot(l, w);
    double T[3];
    transmittance(l, tMax, T);
    double weight[3];
    if (!chromatic)
    {
      this->LightWeight(lit, mu, T[0], albedo, weight);
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        double channel[3];
        this->LightWeight(lit, mu, T[c], albedo, channel);
        weight[c] = channel[c];
      }
    }
    const double scale = light.Scaled ? lit.LightScale : 1.0;
    for (int c = 0; c < 3; ++c)
    {
      in[c] += scale * light.Color[c] * factor * weight[c];
    }
  }

  /**
   * The source term J at a point `point` of the media at the world point x
   * seen along w, of the medium lit as `lit` says (the camera media's:
   * *Parameters; a collision's medium's): albedo (ambient + AddInScattering())
   * + lit.EmissionScale emission, with `transmittance` as AddInScattering()'s.
   * The ambient radiance is Ambient, or with SampleSky the lit medium's
   * AmbientIntensity.
   */
  template <typename LightTransmittance>
  void Source(const vtkTyndallMedium::Point& point, const double x[3], const double w[3],
    const vtkTyndallMediumParameters& lit, LightTransmittance&& transmittance, double J[3]) const
  {
    const double* albedo = point.Albedo;
    double in[3];
    for (int c = 0; c < 3; ++c)
    {
      in[c] = this->SampleSky ? lit.AmbientIntensity : this->Ambient[c];
    }
    if (albedo[0] != 0.0 || albedo[1] != 0.0 || albedo[2] != 0.0)
    {
      this->AddInScattering(x, w, albedo, lit, transmittance, in);
    }
    for (int c = 0; c < 3; ++c)
    {
      J[c] = albedo[c] * in[c] + lit.EmissionScale * point.Emission[c];
    }
  }

  /**
   * p(mu) T per channel for the lit medium, or with several octaves the
   * octaves' sum at the albedo `albedo` (vtkTransmittanceMapMath::OctaveScattering()).
   */
  void LightWeight(const vtkTyndallMediumParameters& lit, double mu, double T,
    const double albedo[3], double weight[3]) const
  {
    if (this->Octaves > 1)
    {
      vtkTransmittanceMapMath::OctaveScattering(
        this->Octaves, lit.OctaveFactors, lit.ScatteringAnisotropy, mu, T, albedo, weight);
      return;
    }
    weight[0] = weight[1] = weight[2] = Phase(lit, mu) * T;
  }

  /**
   * The octaves the light is weighted with: the medium's (ReadScene()); an
   * integrator that scatters for real sets 1.
   */
  int Octaves = 1;

  /**
   * Calls `rows(begin, end)` over [0, Height) in at most 50 batches, with
   * `progress` (0 first, then after each batch) and a check of `abort`
   * between batches. False when aborted.
   */
  bool RenderRowBatches(const bool& abort, const std::function<void(double)>& progress,
    const std::function<void(vtkIdType, vtkIdType)>& rows) const;

  /**
   * Render()'s frame around `render`: `output` and `composite` emptied,
   * StartEvent and EndEvent invoked on `self` around the call, `output`
   * emptied again when `render` fails. Returns `output` (and the wall-clock
   * seconds of `render` in `seconds`), or nullptr when `render` fails.
   */
  static vtkImageData* TimedRender(vtkObject* self, vtkImageData* output, vtkImageData* composite,
    const std::function<bool()>& render, double& seconds);

  /**
   * Makes `output` the Width x Height image of the arrays: `radiance` its
   * scalars, `transmittance` (and `error` unless null) further arrays.
   */
  void SetOutput(vtkImageData* output, vtkDataArray* radiance, vtkDataArray* transmittance,
    vtkDataArray* error = nullptr) const;

  /**
   * Fills `output` with `image`'s extent and a 3-component unsigned char
   * array "RGB": clamp(radiance + transmittance * background, 0, 1) rounded
   * to 0..255.
   */
  static void Composite(vtkImageData* image, vtkDataArray* radiance, vtkDataArray* transmittance,
    const double background[3], vtkImageData* output);

private:
  void SetUpMedia(const vtkTyndallSceneReader& reader);
  void SetUpLights(const vtkTyndallSceneReader& reader);
  static LightSource ToSource(const vtkTyndallLight& light);
};

#endif
