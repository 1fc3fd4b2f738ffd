/**
 * @class   vtkTyndallFootprint
 * @brief   the world width of a pixel along the camera rays: what procedural detail is filtered by
 *
 * A pixel of a picture covers a patch of world space that grows with the
 * distance from the camera: at camera depth z (the distance along the
 * direction of projection) a pixel is Constant + PerDepth z wide, with
 * PerDepth = 2 tan(view angle / 2) / pixels and Constant 0 for a
 * perspective camera, and Constant = 2 parallel scale / pixels and PerDepth
 * 0 for a parallel one (pixels: the picture's height, its width with
 * vtkCamera::UseHorizontalViewAngle). Camera samples of procedural detail
 * (vtkTyndallDetailMedium) filter the noise by a Gaussian of a few tenths of
 * that width, so that waves finer than a pixel fade instead of aliasing.
 *
 * The GPU mapper and the CPU reference both read it from the camera here,
 * so that they filter alike. What it leaves out: a view shear, a window
 * centre and an explicit projection matrix of the camera (the width is the
 * plain camera's), and the slight narrowing of pixels towards the corners
 * of a wide view angle.
 *
 * Internal to Tyndall::Medium; not wrapped.
 *
 * @sa vtkTyndallDetailMedium
 */

#ifndef vtkTyndallFootprint_h
#define vtkTyndallFootprint_h

#include "TyndallMediumModule.h" // For export macro

class vtkCamera;

class TYNDALLMEDIUM_EXPORT vtkTyndallFootprint
{
public:
  /**
   * Reads `camera` for a picture of width x height pixels (positive).
   * False (and the footprint 0 everywhere) for a camera whose direction of
   * projection is not finite or a picture without pixels.
   */
  bool SetCamera(vtkCamera* camera, int width, int height);

  /// The world width of a pixel at the world point x (0 behind the camera).
  double At(const double x[3]) const;

  /**
   * The narrowest pixel over the eight world corners' box (24 doubles, as
   * vtkTyndallMedium::GetWorldCorners() gives them): at the box's nearest
   * depth, no nearer than `nearDepth` (the camera rays start at the near
   * clipping plane).
   */
  double Minimum(const double corners[24], double nearDepth) const;

  ///@{
  /**
   * The camera depth of world point x is Plane[0..2] . x + Plane[3]; a pixel
   * there is Constant + PerDepth max(depth, 0) wide (what the shaders get).
   */
  double Plane[4] = { 0.0, 0.0, 0.0, 0.0 };
  double Constant = 0.0;
  double PerDepth = 0.0;
  ///@}
};

#endif
