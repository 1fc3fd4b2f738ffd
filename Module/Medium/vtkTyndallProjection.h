/**
 * @class   vtkTyndallProjection
 * @brief   VTK's projection blend modes: maximum, minimum and average intensity, additive
 *
 * A volume whose mapper's blend mode is one of VTK's projections is not a
 * medium: each pixel shows one number gathered along its ray, as VTK's GPU
 * mapper (vtkOpenGLGPUVolumeRayCastMapper, VTK 9.1) draws it. Read() takes
 * the mode from the mapper; both renderers then draw it with the same rules
 * (the GPU: vtkTransmittanceProjectionFS.glsl; the CPU:
 * vtkSingleScatteringReference through Ray, this class's twin of the shader):
 *
 * - a sample is the scalar interpolated at a point of the ray inside the
 *   volume's box, kept by the clipping planes and cropping, not missing
 *   (NaN); u = (value - min) / (max - min) is the scalar on the data's
 *   finite range (0 for a constant volume);
 * - MAXIMUM / MINIMUM: the largest / smallest value v along the ray; the
 *   pixel is the colour function's c(v) and the opacity function's a(v),
 *   premultiplied (c a, a); a ray without a sample draws nothing;
 * - AVERAGE: the mean of a(v) u over the samples whose value lies in the
 *   mapper's AverageIPScalarRange (inclusive); grey, clamped to [0, 1], at
 *   alpha 1; nothing where no sample counts;
 * - ADDITIVE: the sum of a(v) u dt / d over the samples, dt the step's
 *   length and d the property's scalar opacity unit distance (VTK scales
 *   the opacity table by its sample distance over the unit distance); grey,
 *   clamped to [0, 1], at alpha 1 wherever the ray crosses the box;
 * - SLICE (VTK's slice blend mode with a vtkPlane as the property's slice
 *   function; without one the mode is not a projection and is drawn as
 *   composite, with a warning): the one sample where the ray meets the
 *   plane (world coordinates, SliceDistance()), when that point lies on the
 *   ray's part in the box (before opaque geometry); the pixel is c(v) and
 *   a(v), premultiplied, as for MAXIMUM.
 *
 * What differs from VTK (Documentation/mapper.md): the CPU reference's
 * samples lie at the middles of equal steps (the GPU's where VTK's are, at
 * the end of each step from the box's entry); VTK's additive
 * leaves opacities at or below 1e-4 unscaled (here every opacity is scaled,
 * so the sum does not depend on the step); a maximum or minimum ray whose
 * samples are all clipped away draws nothing (VTK: the colour at the
 * range's end). Lights, shadows and procedural detail play no part: a
 * projection volume is lit by nothing and casts no shadow into other
 * volumes.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallProjection_h
#define vtkTyndallProjection_h

#include "TyndallMediumModule.h" // For export macro

class vtkTyndallTransferTable;
class vtkVolumeMapper;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallProjection
{
public:
  /// NONE: the volume is a medium (VTK's composite blend mode).
  enum Modes
  {
    NONE,
    MAXIMUM,
    MINIMUM,
    AVERAGE,
    ADDITIVE,
    SLICE
  };

  /**
   * Reads the blend mode and AverageIPScalarRange of `mapper` (a mapper that
   * is not a vtkVolumeMapper, or a blend mode that is not a projection, is
   * NONE), the unit distance of `property` (component 0) and its slice
   * function (SLICE needs a vtkPlane).
   */
  void Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property);

  int GetMode() const { return this->Mode; }
  bool Enabled() const { return this->Mode != NONE; }
  /// The mode's name ("maximum intensity", ...; "composite" for NONE).
  static const char* GetModeName(int mode);
  const double* GetAverageRange() const { return this->AverageRange; }
  /// SLICE: the plane n . x + d = 0 (world; the slice function's normal and origin), as (n, d).
  const double* GetSlicePlane() const { return this->SlicePlane; }
  /**
   * SLICE: the distance t along the world ray origin + t w where it meets
   * the plane; false where it runs parallel to it.
   */
  bool SliceDistance(const double origin[3], const double w[3], double& t) const;
  double GetUnitDistance() const { return this->UnitDistance; }

  /**
   * One ray's accumulation (the CPU twin of the shader's): Add() each
   * sample's value (finite, kept) and step length, then Pixel().
   */
  class Ray
  {
  public:
    Ray(const vtkTyndallProjection& projection, const vtkTyndallTransferTable& table);
    void Add(double value, double dt);
    /// The premultiplied pixel (rgb, alpha); false when the ray draws nothing.
    bool Pixel(double rgba[4]) const;

  private:
    const vtkTyndallProjection* P;
    const vtkTyndallTransferTable* Table;
    double Extremum = 0.0;
    double Sum = 0.0;
    int Count = 0;
  };

private:
  int Mode = NONE;
  double AverageRange[2] = { 0.0, 0.0 };
  double SlicePlane[4] = { 0.0, 0.0, 1.0, 0.0 };
  double UnitDistance = 1.0;
};

#endif
