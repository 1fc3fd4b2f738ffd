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
 * Several components (vtkTyndallComponents), as VTK 9.1 draws them:
 *
 * - independent: each component i gathered on its own (its value v_i, its
 *   tables' functions a_i and c_i, its unit u_i on its finite range, its
 *   weight w_i). MAXIMUM / MINIMUM / SLICE: the pixel is
 *   (sum w_i a_i(m_i) c_i(m_i), sum w_i a_i(m_i)) of each component's
 *   extremum m_i (its own sample), each channel clamped to [0, 1];
 *   AVERAGE: sum over the components with a counted sample of
 *   w_i (sum a_i u_i) / n_i, a value v_i counted when it lies in the range
 *   (grey, clamped, alpha 1, also where none counts: VTK draws black there);
 *   ADDITIVE: sum w_i sum a_i u_i dt / d_i (d_i the component's unit
 *   distance), grey, clamped, alpha 1;
 * - dependent (2: colour function at component 0, opacity function at
 *   component 1; 4: RGBA): MAXIMUM / MINIMUM / SLICE keep the sample whose
 *   opacity component (the last) is the largest / smallest, drawn as the
 *   composite mode classifies it (colour c, opacity a: (c a, a)); AVERAGE
 *   and ADDITIVE gather a(opacity component) u_0 (component 0 on its
 *   range; AVERAGE counts the samples whose component 0 lies in the range;
 *   ADDITIVE's unit distance is the opacity component's, as VTK's).
 *
 * Where VTK 9.1 draws other than it means to, Tyndall draws what it means
 * (vtkTyndallVolumeSettings names each): with independent components
 * VTK's minimum keeps each component's maximum and writes its opacity into
 * blue (alpha 0); with 2 dependent components its maximum and minimum keep
 * the first sample (its two-channel texture reads 1 for the last). VTK
 * cannot draw independent components in the slice mode (its shader does
 * not compile); Tyndall draws them as the maximum's pixel of the one sample.
 *
 * What differs from VTK (Documentation/mapper.md): the CPU reference's
 * samples lie at the middles of equal steps (the GPU's where VTK's are, at
 * the end of each step from the box's entry); VTK's additive
 * leaves opacities at or below 1e-4 unscaled (here every opacity is scaled,
 * so the sum does not depend on the step); a maximum or minimum ray whose
 * samples are all clipped away draws nothing (VTK: the colour at the
 * range's end). Shadows and procedural detail play no part: a projection
 * volume is lit by nothing (but a shaded slice of one component, by the
 * lights unshadowed: vtkTyndallShading) and casts no shadow into other
 * volumes.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallProjection_h
#define vtkTyndallProjection_h

#include "TyndallMediumModule.h" // For export macro

#include "vtkTyndallComponents.h" // For MaximumCount

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
   * NONE), the unit distances of `property` (each component's) and its
   * slice function (SLICE needs a vtkPlane).
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
  /// The property's scalar opacity unit distance of component c (0 .. 3).
  double GetUnitDistance(int c = 0) const
  {
    return this->UnitDistances[c < 0 ? 0 : (c > 3 ? 3 : c)];
  }

  /**
   * What a ray of several components reads: how they are classified, the
   * tables (table t tabulates over component Components->TableComponent(t);
   * vtkTyndallGridMedium::GetComponentTable()) and each component's finite
   * range (vtkTyndallGridMedium::GetComponentRange()).
   */
  struct Classes
  {
    const vtkTyndallComponents* Components = nullptr;
    const vtkTyndallTransferTable* Tables[vtkTyndallComponents::MaximumCount] = {};
    const double* Ranges[vtkTyndallComponents::MaximumCount] = {};
  };

  /**
   * One ray's accumulation (the CPU twin of the shader's): Add() each
   * sample's value (finite, kept) and step length, then Pixel().
   */
  class Ray
  {
  public:
    Ray(const vtkTyndallProjection& projection, const vtkTyndallTransferTable& table);
    /// A ray of several components (AddComponents()); `classes` must outlive it.
    Ray(const vtkTyndallProjection& projection, const Classes& classes);
    void Add(double value, double dt);
    /// A sample of several components (the values of every component).
    void AddComponents(const double values[vtkTyndallComponents::MaximumCount], double dt);
    /// The premultiplied pixel (rgb, alpha); false when the ray draws nothing.
    bool Pixel(double rgba[4]) const;

  private:
    bool ComponentPixel(double rgba[4]) const;
    // The opacity function of table t at v (its component's value).
    double OpacityOf(int t, double v) const;
    // Component c's value v on its finite range.
    double UnitOf(int c, double v) const;

    const vtkTyndallProjection* P;
    const vtkTyndallTransferTable* Table;
    const Classes* C = nullptr;
    double Extremum = 0.0;
    double Sum = 0.0;
    int Count = 0;
    // Several components: the extremum (independent: each its own; dependent:
    // the whole sample), the sums and the counts per component.
    double Values[vtkTyndallComponents::MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
    double Sums[vtkTyndallComponents::MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
    int Counts[vtkTyndallComponents::MaximumCount] = { 0, 0, 0, 0 };
  };

private:
  int Mode = NONE;
  double AverageRange[2] = { 0.0, 0.0 };
  double SlicePlane[4] = { 0.0, 0.0, 1.0, 0.0 };
  double UnitDistances[vtkTyndallComponents::MaximumCount] = { 1.0, 1.0, 1.0, 1.0 };
};

#endif
