/**
 * @class   vtkCosineNoise
 * @brief   procedural cosine noise with closed-form optical depth along rays
 *
 * vtkCosineNoise is the analytically integrable noise of Balint and Mantiuk
 * ("Closed Form Transmittance in Heterogeneous Media Using Cosine Noise"):
 *
 * \f[
 *   \phi(\mathbf{x}) = c_{\mathrm{offset}} + A \sum_{o=0}^{M-1} g^{o}
 *     \sum_{i=0}^{N-1} \cos\!\left(\mathbf{S}_i \cdot (2\pi f \lambda^{o} R^{o}\mathbf{x})
 *     + \varphi_{o,i}\right)
 * \f]
 *
 * with N directions \f$\mathbf{S}_i\f$ (by default 24 points of a 2-D Sobol
 * sequence mapped onto the unit sphere, each scaled by a seeded uniform factor
 * in [0.8, 1.2]), M fractal octaves of lacunarity \f$\lambda\f$ and gain
 * \f$g\f$, a rotation \f$R\f$ between octaves, frequency f (cycles per unit
 * length), amplitude A and offset. Each cosine is a "wave" with wave vector
 * \f$\mathbf{k} = 2\pi f \lambda^o (R^o)^T \mathbf{S}_i\f$, phase and
 * amplitude; GetWave() exposes them, for example to upload to a shader.
 * The phases \f$\varphi_{o,i}\f$ are zero in the paper; they are seeded
 * random numbers when RandomPhases is on (the default), which removes the
 * peak that all cosines otherwise share at the origin. With one octave, no
 * random phases, unit frequency scale \f$2\pi f = 1\f$ and unit amplitude
 * the function is exactly the paper's \f$\phi\f$.
 *
 * Extinction is \f$\sigma_t(\mathbf{x}) = s\,\phi(\mathbf{x})\f$ with s the
 * ExtinctionScale. Along a ray \f$\mathbf{x}(t) = \mathbf{o} + t\mathbf{w}\f$
 * (w is normalised, so t is a distance) the integral of each wave is exact:
 * \f[
 *   \int_{t_0}^{t_1} a\cos(\alpha + \beta t)\,dt
 *     = a\,\Delta\,\cos(\alpha + \beta\bar t)\,\mathrm{sinc}(\beta\Delta/2),
 * \f]
 * with \f$\beta = \mathbf{k}\cdot\mathbf{w}\f$, \f$\Delta = t_1 - t_0\f$,
 * \f$\bar t = (t_0+t_1)/2\f$. This form equals the paper's difference of
 * sines divided by \f$\beta\f$ but has no cancellation and no division, so
 * rays perpendicular to a wave (\f$\beta \to 0\f$) give the exact limit
 * \f$a\Delta\cos(\alpha+\beta\bar t)\f$ instead of NaN or Inf.
 *
 * Negative noise values. With an offset smaller than the sum of the
 * amplitudes (see GetMinimumValue()) the noise has negative regions. The
 * closed form then integrates the signed noise (ComputeIntegral()), so a
 * negative region lowers the optical depth of the whole segment. As in the
 * paper, only the integral is clamped: ComputeOpticalDepth() returns
 * \f$s \max(0, \int\phi)\f$, so transmittance never exceeds one. This is
 * not the integral of the clamped extinction \f$s\max(0,\phi)\f$ that a ray
 * marcher or vtkCosineNoiseSource (ClampNegative) sees; the two agree
 * exactly whenever GetMinimumValue() >= 0. SampleDistance() is exact and
 * unique when the noise is non-negative; otherwise see its documentation.
 *
 * vtkCosineNoise is a vtkImplicitFunction, so it can also drive VTK's
 * implicit-function machinery (vtkSampleFunction, clipping, contouring).
 * Evaluation methods may be called from several threads at once. The ray
 * methods (ComputeIntegral() and the ones built on it) work in the noise's
 * own coordinates: they ignore the implicit function's Transform, which
 * FunctionValue() and FunctionGradient() apply.
 *
 * @sa vtkCosineNoiseSource
 */

#ifndef vtkCosineNoise_h
#define vtkCosineNoise_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkImplicitFunction.h"

#include <memory> // For std::unique_ptr

class vtkDataArray;

class TYNDALLCORE_EXPORT vtkCosineNoise : public vtkImplicitFunction
{
public:
  static vtkCosineNoise* New();
  vtkTypeMacro(vtkCosineNoise, vtkImplicitFunction);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Evaluate the noise and its exact gradient at a point (world
   * coordinates; the implicit function's Transform, if any, applies).
   */
  using vtkImplicitFunction::EvaluateFunction;
  double EvaluateFunction(double x[3]) override;
  void EvaluateGradient(double x[3], double g[3]) override;
  ///@}

  ///@{
  /**
   * Number of generated directions S_i per octave, in [1, 1024]; default
   * 24. Values outside the range are reported with vtkErrorMacro and
   * clamped. Ignored while custom directions are set.
   */
  void SetNumberOfDirections(int n);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /**
   * Custom directions S_i: a 3-component array, one tuple per direction
   * (the vectors are used as given, so their length scales the frequency).
   * nullptr (the default) restores the generated Sobol directions. An
   * array with no tuples or not 3 components is refused with an error.
   */
  void SetCustomDirections(vtkDataArray* directions);
  vtkGetObjectMacro(CustomDirections, vtkDataArray);
  ///@}

  ///@{
  /**
   * Number of fractal octaves, in [1, 16]; default 4. Values outside the
   * range are reported with vtkErrorMacro and clamped.
   */
  void SetNumberOfOctaves(int n);
  vtkGetMacro(NumberOfOctaves, int);
  ///@}

  ///@{
  /**
   * Frequency multiplier between octaves, in [1, 8]; default 2.
   */
  vtkSetClampMacro(Lacunarity, double, 1.0, 8.0);
  vtkGetMacro(Lacunarity, double);
  ///@}

  ///@{
  /**
   * Amplitude multiplier between octaves, in [0, 1]; default 0.5.
   */
  vtkSetClampMacro(Gain, double, 0.0, 1.0);
  vtkGetMacro(Gain, double);
  ///@}

  ///@{
  /**
   * Rotation applied once more for every octave, as an angle in degrees in
   * [-180, 180] (default 37) about OctaveRotationAxis (default (1, 2, 3);
   * normalised internally; a zero axis means no rotation).
   */
  vtkSetClampMacro(OctaveRotationAngle, double, -180.0, 180.0);
  vtkGetMacro(OctaveRotationAngle, double);
  vtkSetVector3Macro(OctaveRotationAxis, double);
  vtkGetVector3Macro(OctaveRotationAxis, double);
  ///@}

  ///@{
  /**
   * Base frequency f in cycles per unit length, in [0, 1e6]; default 1.
   * Wave vectors are 2 pi f S_i for the first octave.
   */
  vtkSetClampMacro(Frequency, double, 0.0, 1.0e6);
  vtkGetMacro(Frequency, double);
  ///@}

  ///@{
  /**
   * Amplitude A of the first octave, in [0, 1e6]; default 1.
   */
  vtkSetClampMacro(Amplitude, double, 0.0, 1.0e6);
  vtkGetMacro(Amplitude, double);
  ///@}

  ///@{
  /**
   * Constant c_offset added to the sum, in [-1e6, 1e6]; default 0.
   */
  vtkSetClampMacro(Offset, double, -1.0e6, 1.0e6);
  vtkGetMacro(Offset, double);
  ///@}

  ///@{
  /**
   * Extinction per unit noise value and unit length, s in
   * sigma_t = s * noise; in [0, 1e9]; default 1. Scales the optical depth.
   */
  vtkSetClampMacro(ExtinctionScale, double, 0.0, 1.0e9);
  vtkGetMacro(ExtinctionScale, double);
  ///@}

  ///@{
  /**
   * Seed of the direction scale factors and phases; default 1. The same
   * seed and parameters give bit-identical noise on every platform.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Seeded random phase for every wave (default on). Off gives the paper's
   * phase-free cosines, whose maxima all coincide at the origin.
   */
  vtkSetMacro(RandomPhases, bool);
  vtkGetMacro(RandomPhases, bool);
  vtkBooleanMacro(RandomPhases, bool);
  ///@}

  /**
   * Number of cosine waves: directions times octaves.
   */
  int GetNumberOfWaves();

  /**
   * Wave i in [0, GetNumberOfWaves()): its wave vector k (radians per unit
   * length), phase (radians) and amplitude a, so that the noise is
   * Offset + sum_i a_i cos(k_i . x + phase_i). Returns false for an
   * invalid index.
   */
  bool GetWave(int i, double k[3], double& phase, double& amplitude);

  ///@{
  /**
   * Bounds of the noise: Offset -/+ the sum of the wave amplitudes. The
   * noise is non-negative everywhere when GetMinimumValue() >= 0.
   */
  double GetMinimumValue();
  double GetMaximumValue();
  ///@}

  /**
   * The noise's standard deviation over space, sqrt(sum_i a_i^2 / 2): the
   * products of different waves average out (exact when no two waves share
   * a wave vector). Its ratio to the Offset (the mean) is the noise's
   * contrast; with many waves the noise is close to normal, so an offset of
   * 2 standard deviations leaves about 2 % of space below 0.
   */
  double GetStandardDeviation();

  /**
   * Exact integral of the signed noise along o + t w over [t0, t1] (w is
   * normalised; t is a distance). Not scaled, not clamped. Returns 0 and
   * reports an error for a zero or non-finite direction or non-finite
   * arguments. t1 < t0 gives the negated integral.
   */
  double ComputeIntegral(const double origin[3], const double direction[3], double t0, double t1);

  /**
   * Optical depth ExtinctionScale * max(0, ComputeIntegral(...)) along
   * o + t w, t in [t0, t1] (t1 >= t0). Exact for non-negative noise; see
   * the class documentation for negative values. Returns 0 on bad input.
   */
  double ComputeOpticalDepth(
    const double origin[3], const double direction[3], double t0, double t1);

  /**
   * exp(-ComputeOpticalDepth(...)).
   */
  double ComputeTransmittance(
    const double origin[3], const double direction[3], double t0, double t1);

  /**
   * Distance sampling, the inverse of the closed form (the paper's
   * Algorithm 2): finds t in [t0, t1] with
   * ExtinctionScale * ComputeIntegral(o, w, t0, t) == targetDepth, by
   * safeguarded Newton iteration (bisection whenever a Newton step leaves
   * the bracket) on the closed form, whose derivative is the extinction.
   *
   * Returns 1 and sets t when the target is reached within [t0, t1];
   * returns 0 and sets t = t1 when the optical depth of the whole segment
   * is below the target (the ray escapes); returns -1 (t = t0, with an
   * error) on bad input: a zero direction, t1 < t0, a negative or
   * non-finite target. A target of 0 gives t = t0.
   *
   * When the noise is non-negative (GetMinimumValue() >= 0) the cumulative
   * depth is monotone and the solution is unique; the result matches the
   * target to about 1e-12 relative. With negative regions the cumulative
   * depth can fall and rise again: the segment is then scanned in steps of
   * a quarter of the shortest wavelength (at most 10^6 steps) and the first
   * sub-interval whose
   * end reaches the target is refined, which finds the first crossing
   * unless two crossings lie within one such step.
   */
  int SampleDistance(const double origin[3], const double direction[3], double t0, double t1,
    double targetDepth, double& t);

  /**
   * The integral of a cubic polynomial times one cosine wave,
   * \f$\int_0^L (c_0 + c_1 s + c_2 s^2 + c_3 s^3)\cos(\alpha + \beta s)\,ds\f$,
   * in closed form: with \f$\theta = \beta L\f$ and
   * \f$K_n(\theta) = \int_0^1 u^n e^{i\theta u} du\f$ it is
   * \f$L\,\mathrm{Re}\big(e^{i\alpha}\sum_n c_n L^n K_n(\theta)\big)\f$;
   * \f$K_n\f$ comes from its Taylor series for \f$|\theta| < 0.5\f$ (no
   * cancellation when a ray runs along a wave front) and from the recurrence
   * \f$K_n = (e^{i\theta} - n K_{n-1}) / (i\theta)\f$ otherwise (whose
   * error grows at most 3! / |theta|^3 <= 48 fold). Relative error near
   * machine precision; the shape x noise media of Tyndall integrate their
   * trilinear shape along a ray with it (vtkTyndallDetailMedium, and the
   * GLSL twin tyndallPolynomialWave()). L >= 0.
   */
  static double PolynomialWaveIntegral(const double c[4], double length, double alpha, double beta);

  /**
   * The core of PolynomialWaveIntegral() for callers that track the phases
   * themselves: (re, im) = sum_n e_n K_n(theta), e_n = c_n L^n, given
   * theta = beta L with its cosine and sine (the integral is then
   * L Re(e^{i alpha} (re + i im))). The Taylor series is used for
   * |theta| < 0.5, the recurrence otherwise.
   */
  static void PolynomialWaveMoments(
    const double e[4], double theta, double cosTheta, double sinTheta, double& re, double& im);

  /**
   * Modification time including the custom directions.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkCosineNoise();
  ~vtkCosineNoise() override;

  int NumberOfDirections = 24;
  vtkDataArray* CustomDirections = nullptr;
  int NumberOfOctaves = 4;
  double Lacunarity = 2.0;
  double Gain = 0.5;
  double OctaveRotationAngle = 37.0;
  double OctaveRotationAxis[3] = { 1.0, 2.0, 3.0 };
  double Frequency = 1.0;
  double Amplitude = 1.0;
  double Offset = 0.0;
  double ExtinctionScale = 1.0;
  unsigned int Seed = 1;
  bool RandomPhases = true;

private:
  vtkCosineNoise(const vtkCosineNoise&) = delete;
  void operator=(const vtkCosineNoise&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  // Rebuilds the wave table when a parameter changed; thread safe.
  const vtkInternals& GetWaves();
  bool CheckRay(const double origin[3], const double direction[3], double w[3], const char* who);
};

#endif
