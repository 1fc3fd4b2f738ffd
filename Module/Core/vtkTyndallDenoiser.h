/**
 * @class   vtkTyndallDenoiser
 * @brief   the path-traced picture's denoiser, guided by the noise-free map-based frame
 *
 * vtkTransmittanceVolumeMapper's path-traced picture (PathTracing) is a
 * running mean M of noisy paths. Its map-based frame G (single scattering
 * through the transmittance maps, octaves for the rest) is noise free and
 * has the same edges: the medium's silhouette, its shadows, its
 * classification. The denoiser filters only what the paths add to it, the
 * residual R = M - G (mostly multiple scattering: smooth), and adds G back:
 *
 *     out = G + A(M - G)
 *
 * A is the edge-avoiding a-trous wavelet filter of Dammertz et al.
 * ("Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination
 * Filtering", HPG 2010): `iterations` passes of the 5 x 5 B3-spline kernel
 * h = (1, 4, 6, 4, 1) / 16 (outer product), the taps of pass i spaced 2^i
 * pixels apart (two passes, the default, reach 6 pixels), each tap q of
 * pixel p weighted
 * h(q) exp(-D(G(p), G(q)) / EdgeStop^2), the sum divided by its weights,
 * taps outside the picture left out. D is the guide's relative difference
 * over its four channels (premultiplied radiance and opacity):
 *
 *     D(a, b) = |a - b|^2 / (|a|^2 + |b|^2 + Epsilon)
 *
 * so a tap across the medium's silhouette (D near 1) weighs at most
 * exp(-4) of its kernel weight at 1 sample per pixel and exp(-64) at 16,
 * one into a shadow half as bright (D = 0.2) exp(-0.8) and exp(-12.8), and
 * two pixels whose guide differs by a small fraction r weigh about
 * exp(-r^2 / (2 EdgeStop^2)). The guide is the only edge stop: no
 * variance, normal or depth buffers (a medium has no surface).
 *
 * The filter's bias is what A changes in the residual's own detail. It
 * shrinks as the samples grow: EdgeStopFor() narrows the edge stop as the
 * noise the filter must remove falls (as 1 / sqrt(samples)), so the
 * denoised picture tends to the mean itself. The two passes and the edge
 * stop were chosen on the path-tracing tests' cloud and dense medium
 * (Documentation/rendering-model.md, "Denoising"): more passes reach
 * farther and blur the residual's own structure (multiple scattering
 * varies within a few tens of pixels), a wider edge stop too.
 *
 * This is the CPU twin of vtkTransmittanceDenoiseFS.glsl (the mapper's
 * PathTraceDenoise); the tests compare the two pixel by pixel. Pictures are
 * RGBA, premultiplied, width x height pixels, rows in any order (both
 * pictures the same).
 */

#ifndef vtkTyndallDenoiser_h
#define vtkTyndallDenoiser_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

class vtkFloatArray;

class TYNDALLCORE_EXPORT vtkTyndallDenoiser : public vtkObject
{
public:
  static vtkTyndallDenoiser* New();
  vtkTypeMacro(vtkTyndallDenoiser, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The filter's passes by default: taps up to 6 pixels away.
  static constexpr int DefaultIterations = 2;

  /// The most passes (taps 2^(MaximumIterations - 1) apart).
  static constexpr int MaximumIterations = 10;

  /// D()'s floor for dark guides (squared premultiplied radiance).
  static constexpr double Epsilon = 1.0e-4;

  /// The B3-spline kernel's weight h(tap), tap in [-2, 2] (0 outside).
  static double KernelWeight(int tap);

  /// The edge stop at 1 sample per pixel (EdgeStopFor()).
  static constexpr double FirstEdgeStop = 0.5;

  /**
   * The edge stop for a mean of `samples` samples per pixel (below 1: 1):
   * FirstEdgeStop / sqrt(samples) (0.5 at 1, 0.125 at 16, 0.016 at 1024),
   * as the residual's noise falls.
   */
  static double EdgeStopFor(int samples);

  /// D(a, b) above, for two RGBA pixels.
  static double Difference(const float a[4], const float b[4]);

  /**
   * Filters: out = guide + A(mean - guide) (the description), `out`'s
   * radiance at least 0 and its opacity in [0, 1] (NaN: 0); `iterations` in [0,
   * MaximumIterations] (0: out = mean), `edgeStop` above 0. False (out
   * untouched) for sizes below 1 or a parameter out of range. `out` may not
   * be `mean` or `guide`.
   */
  VTK_WRAPEXCLUDE static bool Filter(const float* mean, const float* guide, int width, int height,
    int iterations, double edgeStop, float* out);

  /// Filter() on arrays of 4 components and width x height tuples (out resized).
  static bool Filter(vtkFloatArray* mean, vtkFloatArray* guide, int width, int height,
    int iterations, double edgeStop, vtkFloatArray* out);

protected:
  vtkTyndallDenoiser() = default;
  ~vtkTyndallDenoiser() override = default;

private:
  vtkTyndallDenoiser(const vtkTyndallDenoiser&) = delete;
  void operator=(const vtkTyndallDenoiser&) = delete;
};

#endif
