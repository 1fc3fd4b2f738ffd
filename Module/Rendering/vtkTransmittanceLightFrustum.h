/**
 * @class   vtkTransmittanceLightFrustum
 * @brief   the frustum of one light's transmittance map, fitted to a box
 *
 * A transmittance map stores one function per texel; texel coordinates
 * (a, b) in [0, 1]^2 name one light ray. vtkTransmittanceLightFrustum fits
 * those rays tightly around the eight world-space corners of the volume's
 * (possibly rotated and scaled) bounding box:
 *
 * - Directional lights (orthographic): the ray of (a, b) starts at
 *   Origin + a AxisX + b AxisY and travels along AxisZ (unit), the direction
 *   the light travels. The rectangle spanned by AxisX and AxisY is the
 *   box's shadow on the plane perpendicular to AxisZ, padded by
 *   Padding on each side, and Origin lies on the light side of the box.
 * - Positional lights (perspective): every ray starts at Origin, the light's
 *   position, with direction normalize(AxisZ + (2a-1) AxisX + (2b-1) AxisY);
 *   AxisZ points at the box's centre and AxisX, AxisY are scaled by the
 *   tangents of the half-angles that enclose the box. A light inside the box
 *   or needing a field of view wider than MaximumFieldOfView cannot have a
 *   map: FitPositional() returns false and the mapper falls back to brute
 *   force for that light.
 *
 * GetRay() and GetTexel() are the CPU twins of the shader functions
 * tyndallLightRay() and tyndallLightTexel() (vtkTransmittanceCommonFS.glsl).
 *
 * Opaque geometry is drawn from the light by a camera whose projection is
 * ComputeClipMatrix(): clip x and y are 2a - 1 and 2b - 1 of the texel whose
 * ray the point lies on, so the depth buffer has one texel per map texel.
 * GetRayDistance() turns a depth value back into the distance along the
 * texel's ray (the CPU twin of vtkTransmittanceOcclusionFS.glsl).
 */

#ifndef vtkTransmittanceLightFrustum_h
#define vtkTransmittanceLightFrustum_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"

class vtkCamera;
class vtkMatrix4x4;

class TYNDALLRENDERING_EXPORT vtkTransmittanceLightFrustum : public vtkObject
{
public:
  static vtkTransmittanceLightFrustum* New();
  vtkTypeMacro(vtkTransmittanceLightFrustum, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Fit an orthographic frustum for a light travelling along `direction`
   * (need not be unit) around the 8 corners (24 doubles). False for a zero
   * direction or non-finite input.
   */
  bool FitDirectional(const double direction[3], const double corners[24]);

  /**
   * Fit a perspective frustum from `position` around the 8 corners. False
   * when the light is inside the box (or so close that the box is not
   * entirely in front of it) or the field of view would exceed
   * MaximumFieldOfView.
   */
  bool FitPositional(const double position[3], const double corners[24]);

  ///@{
  /**
   * Relative padding of the fitted rectangle or angles on each side, in
   * [0, 0.5]; default 0.01.
   */
  vtkSetClampMacro(Padding, double, 0.0, 0.5);
  vtkGetMacro(Padding, double);
  ///@}

  ///@{
  /**
   * Widest field of view of a perspective map in degrees, in [1, 170];
   * default 150.
   */
  vtkSetClampMacro(MaximumFieldOfView, double, 1.0, 170.0);
  vtkGetMacro(MaximumFieldOfView, double);
  ///@}

  ///@{
  /**
   * The fitted frustum (see the class documentation).
   */
  vtkGetMacro(Positional, bool);
  vtkGetVector3Macro(Origin, double);
  vtkGetVector3Macro(AxisX, double);
  vtkGetVector3Macro(AxisY, double);
  vtkGetVector3Macro(AxisZ, double);
  ///@}

  /**
   * The light ray of texel coordinates (a, b): origin and unit direction.
   */
  void GetRay(double a, double b, double origin[3], double direction[3]) const;

  /**
   * The texel coordinates (a, b) of a world point.
   */
  void GetTexel(const double x[3], double ab[2]) const;

  /**
   * The narrowest world width of a texel of a map `mapSize` texels on a
   * side over the box's 8 corners (24 doubles): orthographic, the shorter
   * side of the rectangle over mapSize; perspective, at the depth of the
   * nearest corner along AxisZ. What a map's light can show no finer than
   * (the camera step follows it through procedural detail). Call it after a
   * successful fit.
   */
  double GetTexelWidth(const double corners[24], int mapSize) const;

  /**
   * The world -> clip matrix (OpenGL convention, depth -1 .. 1) of a camera
   * that sees this frustum, for the box's 8 corners (24 doubles): x, y as
   * above; depth from GetNearDistance() to GetFarDistance() along AxisZ
   * from Origin (orthographic: linear, with the near plane 10 box diagonals
   * towards the light so that occluders far on the light's side count;
   * perspective: the usual hyperbolic depth, near a thousandth of the
   * nearest corner's depth, far one hundredth of a diagonal beyond the
   * farthest). Call it after a successful fit.
   */
  void ComputeClipMatrix(const double corners[24], vtkMatrix4x4* clip);

  /**
   * Makes `camera`'s composite projection (at aspect 1, depth -1 .. 1) the
   * matrix of ComputeClipMatrix(), with an explicit projection.
   */
  void ConfigureCamera(const double corners[24], vtkCamera* camera);

  ///@{
  /**
   * The depth range along AxisZ of the last ComputeClipMatrix().
   */
  vtkGetMacro(NearDistance, double);
  vtkGetMacro(FarDistance, double);
  ///@}

  /**
   * The distance along the ray of texel (a, b) from its origin to the point
   * whose window depth (0 .. 1, the depth buffer's value) is `depth`, for
   * the last ComputeClipMatrix().
   */
  double GetRayDistance(double a, double b, double depth) const;

protected:
  vtkTransmittanceLightFrustum() = default;
  ~vtkTransmittanceLightFrustum() override = default;

  double Padding = 0.01;
  double MaximumFieldOfView = 150.0;
  bool Positional = false;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double AxisX[3] = { 1.0, 0.0, 0.0 };
  double AxisY[3] = { 0.0, 1.0, 0.0 };
  double AxisZ[3] = { 0.0, 0.0, 1.0 };
  double NearDistance = 0.0;
  double FarDistance = 1.0;

private:
  vtkTransmittanceLightFrustum(const vtkTransmittanceLightFrustum&) = delete;
  void operator=(const vtkTransmittanceLightFrustum&) = delete;
};

#endif
