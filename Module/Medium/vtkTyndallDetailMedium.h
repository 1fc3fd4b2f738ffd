/**
 * @class   vtkTyndallDetailMedium
 * @brief   a procedural medium: a coarse shape grid times cosine noise, never voxelised
 *
 * When a volume's vtkParticipatingMediumProperty has a DetailNoise (a
 * vtkCosineNoise), both of Tyndall's renderers render
 *
 * \f[
 *   \sigma_t(\mathbf{p}) = \mathrm{shape}(\mathbf{p})\; s\;
 *     \max\!\big(0, \phi(\mathbf{x}(\mathbf{p}))\big)
 * \f]
 *
 * instead of the grid medium's extinction, where
 *
 * - shape is the *pre-classified* extinction of the grid: each voxel's
 *   scalar goes through the transfer table once (DensityScale times the
 *   table's extinction; NaN voxels are 0) and the results are interpolated
 *   trilinearly, clamped at the border like the scalars
 *   (vtkTyndallGridMedium::Sampler);
 * - phi is the noise (vtkCosineNoise: Offset plus its waves) evaluated at the
 *   point's *data* coordinates x(p) (the image's origin, spacing and
 *   direction, before the vtkVolume's matrix: the detail moves with the
 *   volume), and s is the noise's ExtinctionScale.
 *
 * Colour (albedo) and emission still come from the table at the
 * interpolated scalar, as for a plain grid medium, and so do missing data
 * (a sample interpolated from a NaN voxel is empty), the placement, the
 * clip region and the parameters: the grid is the detail's shape and
 * everything else of it. As a vtkTyndallMedium its OpticalDepth() and
 * SampleDistance() are the closed forms (ClosedFormDepth(),
 * ClosedFormDistance()) while nothing is clipped.
 *
 * Optical depth in closed form (ClosedFormDepth()). Along a ray in field index
 * space p(t) = o + t d, within one cell of the shape grid (between the
 * planes of consecutive samples; outside the samples, in the half cells of
 * cell data, the clamped coordinate is constant), the trilinear shape is a
 * cubic polynomial P(t), and the integral of P times each wave
 * a cos(alpha + beta t) is elemental (vtkTransmittanceMapMath has the
 * stable form). The ray is walked cell by cell (a 3-D DDA) and the cells'
 * integrals are summed. The waves' phases are carried along the ray by
 * complex products: from cell to cell, and from one crossing of an axis's
 * sample planes to the next (a geometric sequence), so a cell needs
 * trigonometry only where the ray enters the medium. What is clamped: each cell's integral of
 * shape x phi is clamped at 0 before the sum, while a camera sample sees
 * max(0, phi). The two agree exactly when the noise is non-negative
 * everywhere (vtkCosineNoise::GetMinimumValue() >= 0); otherwise a cell
 * whose negative lobes outweigh its positive ones adds nothing, and one
 * with both adds less than the integral of the clamped extinction.
 *
 * ClosedFormDistance() inverts the closed form (the paper's Algorithm 2): it
 * walks the cells until the cumulative depth passes the target, then solves
 * within that cell by safeguarded Halley iteration (one sincos per wave
 * and step gives the integral, the noise and its derivative). A lower
 * bound of a cell's integral that needs no trigonometry (one integration by
 * parts per wave from the phases at the cell's start) lets it solve in a
 * cell that surely holds the target without that cell's whole integral.
 * The moments of a cell's cubic times a wave are vtkCosineNoiseMoments.
 *
 * Coordinates: p is in field index coordinates (vtkTyndallGridMedium), and
 * t is a world distance when d is the field index image of a unit world
 * direction (as both renderers use it).
 *
 * Internal to Tyndall::Medium; not wrapped.
 *
 * @sa vtkCosineNoise vtkTyndallGridMedium
 */

#ifndef vtkTyndallDetailMedium_h
#define vtkTyndallDetailMedium_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkTimeStamp.h"        // For vtkTimeStamp
#include "vtkTyndallMedium.h"    // For the interface
#include "vtkType.h"             // For vtkMTimeType

#include <vector> // For std::vector

class vtkCosineNoise;
class vtkObject;
class vtkTyndallGridMedium;

class TYNDALLMEDIUM_EXPORT vtkTyndallDetailMedium : public vtkTyndallMedium
{
public:
  vtkTyndallDetailMedium() = default;
  vtkTyndallDetailMedium(const vtkTyndallDetailMedium&) = delete;
  vtkTyndallDetailMedium& operator=(const vtkTyndallDetailMedium&) = delete;

  /// The most waves (directions x octaves) the GPU's shaders take.
  static constexpr int MaximumNumberOfWaves = 256;

  /**
   * One cosine wave in field index coordinates: a cos(k . p + phase); |k|^2
   * in world units (WorldK2: k is A^T k in world coordinates, A the world ->
   * field index matrix), and the |k|^2 the footprint filter reads
   * (FilterK2, at most WorldK2: the |k|^2 of its group's level of the
   * filter, FilterLevel, see FilterFactor()).
   */
  struct Wave
  {
    double K[3];
    double Phase;
    double Amplitude;
    double WorldK2;
    double FilterK2;
    int FilterLevel;
  };

  /**
   * The footprint filter drops a wave whose factor exp(-|k|^2 sigma^2 / 2)
   * is below this (it would change the noise by less than 1/100 of its
   * amplitude).
   */
  static constexpr double FilterCutoff = 0.01;

  /**
   * The footprint filter's levels: |k|^2 = K0 FilterLevelRatio^n (K0 the
   * coarsest wave's), so the factor of level n + 1 is the factor of level n
   * to the power 1.5, f sqrt(f) (FilterFactor()).
   */
  static constexpr double FilterLevelRatio = 1.5;

  /**
   * Reads `noise` (null: no detail, Enabled() false) over `grid`'s shape.
   * Errors (more than MaximumNumberOfWaves waves, a non-finite wave) go
   * through `reporter`; false on error. Work is redone only when the grid's
   * scalars or extinction or the noise changed. The medium refers to `grid`
   * (which must outlive it) for everything but its extinction.
   * `filterWidth`: the footprint filter's width in pixels
   * (vtkParticipatingMediumProperty::DetailFilterWidth; 0: unfiltered).
   * The waves are kept in order of |k| (world), coarsest first.
   */
  bool Update(const vtkTyndallGridMedium& grid, vtkCosineNoise* noise, vtkObject* reporter,
    double filterWidth = 0.0);

  ///@{
  /**
   * The footprint filter (camera samples; see
   * vtkParticipatingMediumProperty::DetailFilterWidth). A sample where a
   * pixel is `pixel` wide (world; vtkTyndallFootprint) sees the waves
   * filtered by a Gaussian of standard deviation sigma = FilterWidth x
   * pixel: wave i with its amplitude times FilterFactor(i, sigma), that is
   * exp(-|k|^2 sigma^2 / 2), or 0 below FilterCutoff. The waves (sorted
   * coarsest first) are filtered in groups of four (the GPU's vectors),
   * each group with the |k|^2 of its level (Wave::FilterK2): the largest
   * K0 FilterLevelRatio^n at or below the |k|^2 of the group's coarsest
   * wave, K0 the coarsest wave's. On the GPU a level's factor is the one
   * below it times its square root, so a camera sample takes one
   * exponential and a square root per level crossed (an exponential per
   * wave made the default scene's frame 19% slower than one per group; with
   * one per group the filter cost 10% of the frame, with the levels 4%). So no wave is filtered
   * more than its own Gaussian asks; the finer ones a little less (a wave whose own factor is f
   * keeps f^(FilterK2 / WorldK2) of its amplitude: at most f^(1/1.5) for its group's coarsest wave,
   * more for the others of a group that spans more); the coarsest wave of all is filtered exactly.
   * The filter acts on the noise before its clamp at 0 (the extinction is shape x max(0, filtered
   * noise)): a filtered noise is smoother, not the mean of the clamped one.
   * GetLiveWaves(pixel): how many of the waves (coarsest first) a sample
   * with a pixel that wide or narrower keeps; GetFinestWavelength(n): the
   * world wavelength of the finest of the first n waves with an amplitude
   * (1e30 without any). FilteredNoise(p, pixel): the noise a camera sample
   * sees (Noise() when the pixel or the width is 0).
   */
  double GetFilterWidth() const { return this->FilterWidth; }
  double FilterFactor(int i, double sigma) const;
  int GetLiveWaves(double pixel) const;
  double GetFinestWavelength(int n) const;
  double FilteredNoise(const double p[3], double pixel) const;
  ///@}

  /**
   * The camera rays' step through the detail. With the footprint filter on
   * (FilterWidth > 0) a camera sample stands for its step's exact mean of
   * each wave (StepMeanNoise()), so the step need not resolve the waves,
   * only what else varies along the ray: `maximumStep` (half the shape's
   * spacing) and half `lightingWidth` (the finest scale of the samples'
   * light, a map's texel: vtkTransmittanceFrame::GetLightingWidth()). That
   * holds while the clamp at 0 is negligible (GetClampShare() at most
   * ClampTolerance: a step's mean clamped is not the clamped mean) and the
   * light does not carry the waves (`lightingWidth` 0: a brute-force light's
   * shadows show every wave, and a sample's light stands for its whole
   * step), and where that is longer than GetWaveStep() (UsesStepMeans()).
   * Otherwise (and for the unfiltered march) GetWaveStep(): the longest step h, at most
   * `maximumStep` and half the finest wavelength the rays evaluate
   * (GetLiveWaves(pixel)), at which the midpoint rule keeps its error on
   * those waves within StepTolerance of their amplitudes. A step sample of a
   * wave a cos(k . x) stands for its mean over the step, which is the wave
   * times sinc(|k| h / 2) at worst (along k); so the error is bounded by
   * sum_i |a_i| (1 - sinc(|k_i| h / 2)) over sum_i |a_i|. A fine octave of
   * small amplitude allows two samples per period (the default scene);
   * strong fine waves ask for four or more.
   */
  double GetCameraStep(double pixel, double maximumStep, double lightingWidth = 0.0) const;

  /**
   * The step that resolves the waves: the longest h, at most `maximumStep`
   * and half the finest wavelength of GetLiveWaves(pixel), whose midpoint
   * rule keeps its error within StepTolerance (GetCameraStep()).
   */
  double GetWaveStep(double pixel, double maximumStep) const;

  /**
   * Whether GetCameraStep() takes the longer step of the waves' means (the
   * camera samples must then stand for them: StepMeanNoise()).
   */
  bool UsesStepMeans(double pixel, double maximumStep, double lightingWidth) const;

  /**
   * The midpoint rule's error GetCameraStep() allows, relative to the
   * waves' amplitudes: the error at which the detail test's scene keeps the
   * agreement with the CPU reference it had with the former step of a
   * quarter of the shortest wavelength (49 dB, BruteForce).
   */
  static constexpr double StepTolerance = 0.035;

  /**
   * What a camera sample sees when its steps span waves (UsesStepMeans()):
   * the filtered noise (FilteredNoise()) averaged over a step's length
   * centred at `p`, whose extent is `span` (field index: the step's length
   * times the ray's direction), exactly: the mean of a cos(k . x + phase)
   * over the segment is the wave at its middle times sinc(k . span / 2).
   * The samples are a step apart (jittered or not), so those segments tile
   * the ray, and a sample of the waves is their integral over its segment
   * however many periods it spans: the march needs no more steps than the
   * shape and the light do. The
   * clamp at 0 and the shape are taken at the sample (exact where the noise
   * stays positive and the shape is constant over the step). The GLSL twin
   * is tyndallDetailRayStep() and tyndallDetailFilteredNoise().
   */
  double StepMeanNoise(const double p[3], double pixel, const double span[3]) const;

  /**
   * How much the clamp at 0 adds to the noise's mean: E[max(0, -n)] over
   * E[max(0, n)], n taken as Gaussian around the offset with the waves'
   * variance (sum of a^2 / 2); 0 where the offset exceeds the sum of the
   * amplitudes. A step's mean of the noise, clamped, is short of the
   * step's mean of the clamped noise by at most E[max(0, -n)] over the step,
   * so long camera steps (GetCameraStep()) are taken only where this is at
   * most ClampTolerance: the contrast 0.5 of the default scene gives 0.4 %,
   * a contrast of 1 gives 8 %.
   */
  double GetClampShare() const { return this->ClampShare; }
  static constexpr double ClampTolerance = 0.01;

  /// Whether a detail noise is set (the medium is procedural).
  bool Enabled() const { return this->IsEnabled; }

  /// The grid the detail multiplies (Update()'s; null before the first).
  const vtkTyndallGridMedium* GetGrid() const { return this->Grid; }

  ///@{
  /// The waves in field index coordinates, the offset and the scale s.
  const std::vector<Wave>& GetWaves() const { return this->Waves; }
  double GetOffset() const { return this->Offset; }
  double GetScale() const { return this->Scale; }
  ///@}

  ///@{
  /**
   * The shape: pre-classified extinction per sample (x fastest) and the
   * number of samples per axis.
   */
  const std::vector<float>& GetShape() const { return this->ShapeValues; }
  const int* GetDimensions() const { return this->Dimensions; }
  ///@}

  /// When the shape, the waves or the filter's width last changed (the GPU re-uploads on it).
  vtkMTimeType GetTime() const { return this->Time.GetMTime(); }

  /**
   * When the medium's extinction last changed: the shape or the waves, not
   * the footprint filter's width (which only camera samples see). What the
   * transmittance maps are built from.
   */
  vtkMTimeType GetExtinctionTime() const { return this->ExtinctionTime.GetMTime(); }

  ///@{
  /**
   * The shape and the noise at a field index point (the extinction is
   * vtkTyndallMedium::Extinction(): their product, clamped, counting a
   * trigonometric pass where the shape is not empty: delta tracking's work).
   */
  double Shape(const double p[3]) const;
  double Noise(const double p[3]) const;
  ///@}

  /**
   * An upper bound of the extinction everywhere: shape maximum x s x the
   * noise's maximum (Offset + the sum of the amplitudes). The majorant of
   * delta tracking.
   */
  double GetMajorant() const override;

  ///@{
  /// vtkTyndallMedium: the grid's placement, parameters, clip region and emission array.
  const char* GetKind() const override { return "detail"; }
  const double* GetWorldToLocal() const override;
  const double* GetLocalToWorld() const override;
  const double* GetBoxLow() const override { return this->BoxLow; }
  const double* GetBoxHigh() const override { return this->BoxHigh; }
  const vtkTyndallMediumParameters& GetParameters() const override;
  const vtkTyndallClipRegion* GetClip() const override;
  bool GetArrayEmission() const override;
  void ArrayEmission(const double p[3], double rgb[3]) const override;
  ///@}

  /// A voxel of the shape or half the shortest wavelength, whichever is shorter.
  double GetFinestFeature() const override;

  ///@{
  /**
   * vtkTyndallMedium's segments: the closed forms (ClosedFormDepth(),
   * ClosedFormDistance()), or while the clip region clips (and `clip` is on)
   * the optical depth marched.
   */
  bool HasClosedForm() const override { return true; }
  double OpticalDepth(const double o[3], const double d[3], double t0, double t1, double step,
    double maxDepth, bool clip = true, const PathCache* start = nullptr,
    Work* work = nullptr) const override;
  bool SampleDistance(const double o[3], const double d[3], double t0, double t1, double target,
    double& t, const PathCache* start = nullptr, PathCache* collision = nullptr,
    Work* work = nullptr) const override;
  ///@}

  /**
   * The shortest wavelength of the waves with a non-zero amplitude, in the
   * units of the space that `worldToIndex` (row-major 4x4, affine) maps to
   * field index coordinates; 1e30 without waves.
   */
  double GetShortestWavelength(const double worldToIndex[16]) const;

  /**
   * The waves' phases (cos and sin of k . p + phase) at one point, which a
   * ray that starts there reuses instead of a sincos per wave: a path's
   * collision point starts its shadow rays and its next flight.
   * ClosedFormDistance() fills it at the collision; ClosedFormDepth() and
   * ClosedFormDistance() read it when their ray starts close to the point
   * (the phases are turned by the small difference, to rounding; farther,
   * they compute their own). The integrators hold it as the path's
   * vtkTyndallMedium::PathCache.
   */
  using PointPhases = vtkTyndallMedium::PathCache;

  /**
   * The optical depth along p(t) = o + t d for t in [t0, t1], in closed form
   * (see the class description; each cell's integral clamped at 0). The
   * segment is clipped to the box [boxLow, boxHigh] of the grid medium.
   */
  double ClosedFormDepth(const double o[3], const double d[3], double t0, double t1,
    const PointPhases* start = nullptr, Work* work = nullptr) const;

  /**
   * Distance sampling: the t in [t0, t1] at which ClosedFormDepth(o, d, t0, t)
   * reaches `target` (>= 0). Returns true and sets t when it does, false
   * (t = t1) when the whole segment's depth is below the target (or the
   * target is negative or NaN). A target of 0 gives t = t0. `start`: the
   * phases at the ray's start, if known; `collision` (may be `start`)
   * receives those at the collision when one is found by the solve (not
   * for a target of 0; its Point says where they are, Valid whether any).
   */
  bool ClosedFormDistance(const double o[3], const double d[3], double t0, double t1, double target,
    double& t, const PointPhases* start = nullptr, PointPhases* collision = nullptr,
    Work* work = nullptr) const;

  /**
   * The extinction coefficients (ETM's DCT, vtkTransmittanceMapMath) of
   * the segment [t0, t1] of p(t) = o + t d in closed form:
   * c_j = 2 int_0^1 D sigma(u) cos(j pi u) du, D = t1 - t0, u = (t - t0) / D,
   * for j < count. Within each cell the cubic shape times each wave times
   * cos(j pi u) is two elemental integrals (the product of two cosines is a
   * sum of two), so a segment costs cells x count x (1 + 2 waves) of them;
   * the noise is integrated signed (the clamp at 0 of ClosedFormDepth() does
   * not apply to a coefficient). What a map texel's closed-form projection
   * would compute, against the march of the map passes (BenchDetail).
   */
  void ProjectExtinction(
    const double o[3], const double d[3], double t0, double t1, int count, double* c) const;

protected:
  double FieldExtinction(const double p[3], Work* work) const override;
  bool FieldSample(const double p[3], Point& point, double pixel) const override;
  bool FieldMaterial(const double p[3], Point& point) const override;

private:
  // One cell crossed by a ray: [Ta, Tb] and the cubic shape polynomial in
  // s = t - Ta, coefficients C[0] + C[1] s + C[2] s^2 + C[3] s^3.
  struct Segment
  {
    double Ta;
    double Tb;
    double C[4];
    // Per axis, the index of the sample plane the ray crosses at Tb, or
    // NoPlane (the cell ends on another axis's plane or at the ray's end).
    int Plane[3];
  };
  static constexpr int NoPlane = -1000000;
  // Calls visit(segment, p(Ta)) for each cell the clipped ray crosses, in
  // order, while it returns true.
  template <typename F>
  void WalkCells(const double o[3], const double d[3], double t0, double t1, F&& visit) const;
  // The shape polynomial of the cell `region` from pa along d.
  void CellPolynomial(
    const int region[3], const double pa[3], const double d[3], double c[4]) const;
  void BuildShape(const vtkTyndallGridMedium& grid);
  class RayWaves;
  double ShapeAt(int i, int j, int k) const;
  void Corners(const int cell[3], double v[8]) const;

  bool IsEnabled = false;
  const vtkTyndallGridMedium* Grid = nullptr;
  std::vector<Wave> Waves;
  double Offset = 0.0;
  double Scale = 1.0;
  double FilterWidth = 0.0;
  double NoiseMaximum = 0.0;
  double AmplitudeSum = 0.0; // sum of |a|
  double ClampShare = 0.0;   // GetClampShare()
  std::vector<float> ShapeValues;
  int Dimensions[3] = { 2, 2, 2 };
  double BoxLow[3] = { 0.0, 0.0, 0.0 };
  double BoxHigh[3] = { 1.0, 1.0, 1.0 };
  double ShapeMaximum = 0.0;
  double Density = 1.0;
  vtkTimeStamp Time;
  vtkTimeStamp ExtinctionTime;
  vtkMTimeType SourceTime = 0;
  vtkMTimeType NoiseTime = 0;
};

#endif
