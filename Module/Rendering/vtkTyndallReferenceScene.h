/**
 * @class   vtkTyndallReferenceScene
 * @brief   what Tyndall's CPU renderers share: the scene in field index space, camera rays, lights,
 * the row loop and compositing
 *
 * vtkTyndallReferenceScene is the part of a frame that the single-scattering
 * reference (vtkSingleScatteringReference) and the Monte Carlo path tracer
 * (vtkVolumetricPathTracer) set up and read the same way; each renderer's
 * own scene derives from it and adds its integrator's settings.
 *
 * - Set-up: ReadScene() checks the image size, reads (renderer, volume)
 *   through a vtkTyndallSceneReader and copies the medium's placement
 *   (world -> field index A x + B, the box [BoxLow, BoxHigh]) and
 *   parameters; SetUpView() inverts the camera's composite projection and
 *   copies the lights.
 * - Geometry: ToIndexPoint() / ToIndexDirection(), ClipToBox(), the camera
 *   ray of a pixel (CameraRay(), pixel centres unprojected from the near to
 *   the far plane) and the direction, attenuation, spot cone and distance
 *   of a light seen from a point (LightGeometry()).
 * - Light: AddInScattering() sums E_l f_l p(mu_l) T_l over the lights, with
 *   the light transmittance T_l left to the integrator.
 * - The frame: TimedRender() wraps a render in its events and timing,
 *   RenderRowBatches() renders rows in batches with progress and abort
 *   checks between them, SetOutput() assembles the image and Composite()
 *   blends it over a background.
 *
 * World distances are the ray parameter in both spaces: a direction is a
 * unit world vector and its index-space image.
 *
 * Internal to Tyndall::Rendering; not wrapped.
 */

#ifndef vtkTyndallReferenceScene_h
#define vtkTyndallReferenceScene_h

#include "TyndallRenderingModule.h"  // For export macro
#include "vtkMath.h"                 // For vtkMath::Dot
#include "vtkTransmittanceMapMath.h" // For the phase function
#include "vtkTyndallClipRegion.h"    // For Inside()
#include "vtkType.h"                 // For vtkIdType

#include <algorithm>  // For std::min, std::max, std::swap
#include <cmath>      // For std::pow
#include <functional> // For std::function
#include <vector>     // For std::vector

class vtkDataArray;
class vtkImageData;
class vtkObject;
class vtkRenderer;
class vtkTyndallDetailMedium;
class vtkTyndallGridMedium;
class vtkTyndallSceneReader;
class vtkTyndallTransferTable;
class vtkVolume;

class TYNDALLRENDERING_EXPORT vtkTyndallReferenceScene
{
public:
  /// One light, as the integrators read it.
  struct LightSource
  {
    bool Positional = false;
    double ToLight[3] = { 0.0, 0.0, 1.0 };        // directional: unit, world
    double ToLightIndex[3] = { 0.0, 0.0, 1.0 };   // the same in index space
    double Position[3] = { 0.0, 0.0, 0.0 };       // positional, world
    double SpotDirection[3] = { 0.0, 0.0, -1.0 }; // unit, from the light to its focal point
    bool Spot = false;
    double CosCone = -1.0;
    double Exponent = 0.0;
    double Attenuation[3] = { 1.0, 0.0, 0.0 };
    double E[3] = { 0.0, 0.0, 0.0 }; // LightScale * Intensity * DiffuseColor
  };

  int Width = 1;
  int Height = 1;
  double InverseProjection[16]; // world <- normalised device coordinates
  double A[3][3];               // world -> field index: A x + B
  double B[3];
  double BoxLow[3];
  double BoxHigh[3];
  double DensityScale = 1.0;
  /// Coloured extinction: channel k's extinction is ExtinctionColor[k] times the medium's.
  bool Chromatic = false;
  double ExtinctionColor[3] = { 1.0, 1.0, 1.0 };
  bool SingleScattering = true;
  double G = 0.0;
  double Ambient = 0.0;
  /// Multiple-scattering octaves (1: single scattering alone) and their factors a, b, c, k
  /// (k: the build-up).
  int Octaves = 1;
  double OctaveFactors[4] = { 0.0, 0.0, 0.0, 0.0 };
  double EmissionScale = 0.0;
  bool HasEmission = false;
  std::vector<LightSource> Lights;
  const vtkTyndallTransferTable* Table = nullptr;
  const vtkTyndallDetailMedium* Detail = nullptr; // procedural detail, or null
  const vtkTyndallClipRegion* Clip = nullptr;     // clipping planes or cropping, or null
  const vtkTyndallGridMedium* Medium = nullptr;   // the grid medium read
  bool EmissionArray = false;                     // emission per unit length from a separate array

  /**
   * A guest (vtkTyndallSceneReader::GetGuests()): another medium the light
   * crosses. This medium's field index point p is the guest's index point M p
   * + C; Scalar() samples the guest's field at its own index point (NaN at
   * missing data), Table is its transfer table. Camera: the camera rays
   * sample it too (vtkTyndallSceneReader::GetCameraGuests()).
   */
  struct Guest
  {
    double M[3][3];
    double C[3];
    double BoxLow[3];
    double BoxHigh[3];
    double DensityScale = 1.0;
    const vtkTyndallTransferTable* Table = nullptr;
    std::function<double(const double q[3])> Scalar;
    bool Camera = false;
    /// The guest's medium (a coloured particle cloud's albedo: ParticleColor()).
    const vtkTyndallGridMedium* Medium = nullptr;

    /// The guest's index point of this medium's index point p.
    void ToGuest(const double p[3], double q[3]) const;
    /**
     * At the guest's index point q: false outside its box or at missing
     * data, else its extinction and its table position (k, f).
     */
    bool Sample(const double q[3], double& sigma, int& k, double& f) const;
  };
  std::vector<Guest> Guests;

  /**
   * The guests' optical depth along the ray p + t d (this medium's index
   * space, t a world distance) for t in [0, tMax]: each guest's part of the
   * ray in midpoint steps of at most `step`, stopping past `maxDepth`.
   */
  double GuestOpticalDepth(
    const double p[3], const double d[3], double tMax, double step, double maxDepth) const;

  /// Whether the camera rays sample guests (some Guest::Camera), and their smallest world spacing.
  bool CameraGuests = false;
  double CameraGuestSpacing = 0.0;
  /// The sum of the guests' world diagonals (how far beyond its own box a ray may march).
  double GuestDiagonals = 0.0;
  /// Whether this medium is drawn by another volume's camera rays
  /// (vtkTyndallSceneReader::GetDrawnBy()).
  bool DrawnByAnother = false;

  /**
   * The camera rays' part [t0, t1] of the ray p + t d (this medium's index
   * space): its box's, or with camera guests from the first entry into any
   * of their boxes to the last exit. False when it misses them all.
   */
  bool ClipToCameraBoxes(const double p[3], const double d[3], double& t0, double& t1) const;

  /// Whether the field index point p is kept by the clipping and cropping.
  bool Inside(const double p[3]) const { return !this->Clip || this->Clip->InsideIndex(p); }
  double* Radiance = nullptr;
  double* Transmittance = nullptr;

  /**
   * Checks the image size (each side in [1, 16384]), updates
   * `reader` from (renderer, volume) and sets the image size, the medium
   * and Detail. Errors go through `reporter`; false on error.
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

  ///@{
  /// World -> field index space: a direction (A w) and a point (A x + B).
  void ToIndexDirection(const double w[3], double d[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      d[r] = this->A[r][0] * w[0] + this->A[r][1] * w[1] + this->A[r][2] * w[2];
    }
  }
  void ToIndexPoint(const double x[3], double p[3]) const
  {
    this->ToIndexDirection(x, p);
    for (int r = 0; r < 3; ++r)
    {
      p[r] += this->B[r];
    }
  }
  ///@}

  /**
   * Channel k's transmittance where the densest channel's is T:
   * T^ExtinctionColor[k] (1 for a channel without extinction).
   */
  double ChannelTransmittance(double T, int k) const
  {
    const double e = this->ExtinctionColor[k];
    return e == 0.0 ? 1.0 : (T > 0.0 ? std::pow(std::min(T, 1.0), e) : 0.0);
  }

  /// The phase function at the cosine mu (Henyey-Greenstein, anisotropy G).
  double Phase(double mu) const { return vtkTransmittanceMapMath::HenyeyGreenstein(this->G, mu); }

  /// Whether the point p lies in the box [lo, hi].
  static bool InsideBox(const double p[3], const double lo[3], const double hi[3])
  {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
      p[2] <= hi[2];
  }

  /**
   * Clips the parameter interval [t0, t1] of the ray o + t d to the box
   * [lo, hi] (all in field index space); false if nothing is left.
   */

  static bool ClipToBox(const double o[3], const double d[3], const double lo[3],
    const double hi[3], double& t0, double& t1)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (d[a] == 0.0)
      {
        if (o[a] < lo[a] || o[a] > hi[a])
        {
          return false;
        }
        continue;
      }
      const double inv = 1.0 / d[a];
      double ta = (lo[a] - o[a]) * inv;
      double tb = (hi[a] - o[a]) * inv;
      if (ta > tb)
      {
        std::swap(ta, tb);
      }
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    return t0 < t1;
  }

  /**
   * The camera ray of pixel (i, j): its world origin on the near plane, the
   * unit world direction w towards the far plane and the world length
   * between the planes. False for a degenerate ray.
   */
  bool CameraRay(int i, int j, double origin[3], double w[3], double& length) const;

  /**
   * Towards `light` from the world point x: the unit world direction l, its
   * index-space image dl, the attenuation and spot cone factor and the world
   * distance tMax to a positional light (infinity for a directional one).
   * False when the light does not reach x.
   */
  bool LightGeometry(const LightSource& light, const double x[3], double l[3], double dl[3],
    double& factor, double& tMax) const;

  /**
   * Adds E_l * f_l * p(mu_l) * T_l of every light to `in`, at the world
   * point x seen along the unit world direction w; `transmittance(dl,
   * tMax)` is the light transmittance T_l along dl (see LightGeometry()).
   * With Octaves > 1, p(mu_l) T_l becomes the octaves' sum at the albedo
   * `albedo` (vtkTransmittanceMapMath::OctaveScattering()). With a
   * coloured extinction, channel k sees ChannelTransmittance(T_l, k).
   */
  template <typename LightTransmittance>
  void AddInScattering(const double x[3], const double w[3], const double albedo[3],
    LightTransmittance&& transmittance, double in[3]) const
  {
    for (const LightSource& light : this->Lights)
    {
      double l[3], dl[3], factor, tMax;
      if (!this->LightGeometry(light, x, l, dl, factor, tMax))
      {
        continue;
      }
      // mu = dot(-l, -w): the light travels along -l, the camera is along -w.
      const double mu = vtkMath::Dot(l, w);
      const double T = transmittance(dl, tMax);
      double weight[3];
      if (!this->Chromatic)
      {
        this->LightWeight(mu, T, albedo, weight);
      }
      else
      {
        for (int c = 0; c < 3; ++c)
        {
          double channel[3];
          this->LightWeight(mu, this->ChannelTransmittance(T, c), albedo, channel);
          weight[c] = channel[c];
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        in[c] += light.E[c] * factor * weight[c];
      }
    }
  }

  /**
   * p(mu) T per channel, or with Octaves > 1 the octaves' sum at the albedo
   * `albedo` (vtkTransmittanceMapMath::OctaveScattering()).
   */
  void LightWeight(double mu, double T, const double albedo[3], double weight[3]) const
  {
    if (this->Octaves > 1)
    {
      vtkTransmittanceMapMath::OctaveScattering(
        this->Octaves, this->OctaveFactors, this->G, mu, T, albedo, weight);
      return;
    }
    weight[0] = weight[1] = weight[2] = this->Phase(mu) * T;
  }

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
  void SetUpMedium(const vtkTyndallGridMedium& medium);
  void SetUpGuests(const vtkTyndallSceneReader& reader);
  void SetUpLights(const vtkTyndallSceneReader& reader);
};

#endif
