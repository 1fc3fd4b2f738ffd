/**
 * @class   vtkTyndallMedium
 * @brief   what every integrator asks of a participating medium: the one interface over Tyndall's
 * media
 *
 * A medium is one volume of a scene, as Tyndall's renderers see it (the
 * shape of pbrt-v4's Medium, src/pbrt/media.h): GL-free, double precision.
 * vtkTyndallSceneReader gives the integrators the list of media of a
 * renderer (vtkTyndallSceneReader::GetMedia(): the volume's own first, the
 * others after); they ask each the same questions and never which kind it
 * is. The kinds:
 *
 * - vtkTyndallGridMedium: an image's scalars through the transfer
 *   functions (trilinear, missing data empty);
 * - vtkTyndallParticleMedium: a particle cloud, its exact sum of kernels
 *   (a grid of it for the GPU's camera rays);
 * - vtkTyndallDetailMedium: a grid's shape times procedural cosine noise,
 *   with a closed-form optical depth and distance sampling.
 *
 * Coordinates. Each medium has a local frame ("field index" coordinates:
 * sample (i, j, k) of its grid at the point (i, j, k)), an affine image of
 * world space: p = A x + B (GetWorldToLocal()). It fills the box [BoxLow,
 * BoxHigh] of that frame. A ray is asked in the medium's frame: o + t d,
 * where d is the frame's image of a unit world direction, so that t is a
 * world distance in every medium's frame and one ray parameter serves a
 * whole scene (ToLocalRay()).
 *
 * Extinction is the densest channel's (per world unit); channel k's is
 * GetParameters().ExtinctionColor[k] times it. Colours are per unit
 * extinction: a point scatters Extinction x Albedo and emits
 * Extinction x EmissionScale x Emission (the transfer functions' emission);
 * an emission array emits per unit length instead (ArrayEmission()).
 *
 * What a medium keeps (clipping planes, cropping: GetClip()) is part of
 * it: every query is 0 outside it and outside the box.
 *
 * Internal to Tyndall::Medium; not wrapped.
 *
 * @sa vtkTyndallMediumParameters vtkTyndallSceneReader
 */

#ifndef vtkTyndallMedium_h
#define vtkTyndallMedium_h

#include "TyndallMediumModule.h"        // For export macro
#include "vtkTyndallMediumParameters.h" // For the parameters

#include <algorithm> // For std::max, std::min, std::swap
#include <vector>    // For std::vector

class vtkTyndallClipRegion;

class TYNDALLMEDIUM_EXPORT vtkTyndallMedium
{
public:
  virtual ~vtkTyndallMedium();

  /// What a point of the medium holds (see the class description).
  struct Point
  {
    double Extinction = 0.0;
    double Albedo[3] = { 0.0, 0.0, 0.0 };
    /// The emission colour per unit extinction, before EmissionScale (0 when the medium does not
    /// emit through its transfer functions).
    double Emission[3] = { 0.0, 0.0, 0.0 };
  };

  /**
   * The work of the queries, for the benchmarks, in passes over what a
   * point of the detail costs (vtkTyndallDetailMedium): a trigonometric pass
   * takes a sine and cosine per wave (an evaluation of the extinction for
   * delta and ratio tracking; in the closed forms where a ray enters the
   * medium, a cell whose phases are not carried, each step of a solve), a
   * cell pass only products and the polynomial moments, a bound pass only
   * the bound that lets a flight solve in a cell without its whole integral
   * (BoundSolves: the flights it did that for). The queries add to it when
   * given one; the other media count nothing.
   */
  struct Work
  {
    double TrigonometricPasses = 0.0;
    double CellPasses = 0.0;
    double BoundPasses = 0.0;
    double BoundSolves = 0.0;

    void Add(const Work& other)
    {
      this->TrigonometricPasses += other.TrigonometricPasses;
      this->CellPasses += other.CellPasses;
      this->BoundPasses += other.BoundPasses;
      this->BoundSolves += other.BoundSolves;
    }
  };

  /**
   * What a medium may keep between the queries of one path (one per path
   * and medium, opaque to the integrators): the detail medium keeps its
   * waves' phases (cos and sin of k . p + phase) at the last collision, which
   * the collision's shadow rays and next flight reuse instead of a sincos
   * per wave (vtkTyndallDetailMedium). Point says where they hold.
   */
  struct PathCache
  {
    double Point[3] = { 0.0, 0.0, 0.0 };
    std::vector<double> Cos;
    std::vector<double> Sin;
    bool Valid = false;
  };

  /// A short name of the kind ("grid", "particles", "detail"), for messages.
  virtual const char* GetKind() const = 0;

  ///@{
  /**
   * The placement: world -> local and local -> world (row-major 4x4,
   * affine) and the box in the local frame.
   */
  virtual const double* GetWorldToLocal() const = 0;
  virtual const double* GetLocalToWorld() const = 0;
  virtual const double* GetBoxLow() const = 0;
  virtual const double* GetBoxHigh() const = 0;
  ///@}

  /// The medium's lighting and extinction settings.
  virtual const vtkTyndallMediumParameters& GetParameters() const = 0;

  /// What the clipping planes and cropping keep, or null when they keep everything.
  virtual const vtkTyndallClipRegion* GetClip() const = 0;

  ///@{
  /**
   * Point queries at the local point p: the densest channel's extinction
   * (0 outside the box, the clip region or at missing data), and all the
   * point holds (false where the extinction is 0; the colours are then
   * undefined). `work` counts what an evaluation costs. `pixel`: for a
   * camera sample, the world width of a pixel there (vtkTyndallFootprint),
   * which procedural detail is filtered by (vtkTyndallDetailMedium); 0
   * (light rays, the path tracer): unfiltered.
   */
  double Extinction(const double p[3], Work* work = nullptr) const
  {
    return this->Inside(p) ? this->FieldExtinction(p, work) : 0.0;
  }
  bool Sample(const double p[3], Point& point, double pixel = 0.0) const
  {
    return this->Inside(p) && this->FieldSample(p, point, pixel);
  }
  ///@}

  /**
   * The colours alone at p (Albedo and Emission of `point`; its Extinction
   * is not computed): what a collision needs, where the extinction is known
   * to be positive. False at missing data or outside the box and clip region.
   */
  bool Material(const double p[3], Point& point) const
  {
    return this->Inside(p) && this->FieldMaterial(p, point);
  }

  ///@{
  /**
   * Emission from a separate array (vtkParticipatingMediumProperty::
   * EmissionArrayName): whether the medium has one, and its colour per unit
   * length at p, before EmissionScale (where the medium is kept; 0
   * elsewhere). None by default.
   */
  virtual bool GetArrayEmission() const { return false; }
  virtual void ArrayEmission(const double p[3], double rgb[3]) const;
  ///@}

  /**
   * How many stratified points of each segment of a path estimate an
   * emission array's light along it (per unit length: the segment's length
   * over this, times the emission and the transmittance to each point): the
   * path tracers' one setting, CPU (vtkVolumetricPathTracer) and GPU
   * (vtkTransmittancePathTracePass).
   */
  static constexpr int PathEmissionSamples = 4;

  /**
   * The optical depth of the densest channel along o + t d (local frame) for
   * t in [t0, t1] (within the box). The default marches the extinction in
   * equal midpoint steps of at most `step` (world length), stopping once the
   * depth passes `maxDepth`; without `clip` the clip region is ignored (the
   * box is not). A medium with a closed form integrates exactly instead, when
   * nothing is clipped (or `clip` is off), and ignores `step` and `maxDepth`;
   * `start` is its cache at o, if the path has one.
   */
  virtual double OpticalDepth(const double o[3], const double d[3], double t0, double t1,
    double step, double maxDepth, bool clip = true, const PathCache* start = nullptr,
    Work* work = nullptr) const;

  /**
   * Whether the medium has a closed form that OpticalDepth() and
   * SampleDistance() use (while nothing is clipped).
   */
  virtual bool HasClosedForm() const { return false; }

  /**
   * Distance sampling in closed form (where HasClosedForm()): the t in
   * [t0, t1] at which the optical depth from t0 reaches `target`; true and
   * t, or false (t = t1) when the whole segment's depth is below it.
   * `start` is the path's cache at o (if any), `collision` (may be `start`)
   * receives the one at the collision. Without a closed form: false.
   */
  virtual bool SampleDistance(const double o[3], const double d[3], double t0, double t1,
    double target, double& t, const PathCache* start = nullptr, PathCache* collision = nullptr,
    Work* work = nullptr) const;

  /// An upper bound of the extinction everywhere (per world unit): the majorant of delta tracking.
  virtual double GetMajorant() const = 0;

  /**
   * The world length of the finest feature the medium has (a voxel along
   * its shortest axis, or half the shortest wavelength of its detail): the
   * integrators' default steps are a fraction of it.
   */
  virtual double GetFinestFeature() const = 0;

  ///@{
  /// World -> local for a point (A x + B) and a direction (A w).
  void ToLocalPoint(const double x[3], double p[3]) const;
  void ToLocalDirection(const double w[3], double d[3]) const;
  ///@}

  /// Whether the local point p lies in the box and the clip region.
  bool Inside(const double p[3]) const;

  /// The length of the box's diagonal in world units.
  double GetWorldDiagonal() const;

  /// The world length of one local step along the shortest axis.
  double GetMinimumWorldSpacing() const;

  /// The eight world corners of the box (24 doubles; corner c has bit 0, 1, 2 for x, y, z high).
  void GetWorldCorners(double corners[24]) const;

  /// Whether the point p lies in the box [lo, hi].
  static bool InsideBox(const double p[3], const double lo[3], const double hi[3])
  {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
      p[2] <= hi[2];
  }

  /**
   * Clips the parameter interval [t0, t1] of the ray o + t d to the box
   * [lo, hi]; false if nothing is left.
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

protected:
  ///@{
  /**
   * The extinction and the point's properties at the local point p, inside
   * the box and the clip region (Extinction() and Sample() test those).
   */
  virtual double FieldExtinction(const double p[3], Work* work) const = 0;
  virtual bool FieldSample(const double p[3], Point& point, double pixel) const = 0;
  virtual bool FieldMaterial(const double p[3], Point& point) const = 0;
  ///@}

  vtkTyndallMedium() = default;
  vtkTyndallMedium(const vtkTyndallMedium&) = default;
  vtkTyndallMedium& operator=(const vtkTyndallMedium&) = default;
};

#endif
