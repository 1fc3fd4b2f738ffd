/**
 * @class   vtkTyndallTransferTable
 * @brief   a medium's transfer functions, tabulated once for both renderers
 *
 * The GPU mapper uploads this table as a 2-D texture and samples it with
 * linear filtering; the CPU reference interpolates the same entries the same
 * way. Size entries (4096) tabulate, at the scalar values
 * v_i = Minimum + i (Maximum - Minimum) / (Size - 1):
 *
 * - Extinction: sigma_t per world unit at DensityScale 1, from VTK's opacity
 *   semantics (vtkTransmittanceMapMath::ExtinctionFromOpacity of the scalar
 *   opacity and its unit distance); interpolated linearly in sigma_t; with
 *   `linearExtinction` (a particle medium) the scalar itself (its negative
 *   part 0), the opacity unused;
 * - Albedo: the colour transfer function (RGB, or grey when the property has
 *   one colour channel);
 * - Emission: the emission colour transfer function (zero without one);
 * - Opacity: the scalar opacity function itself (what VTK's projection
 *   blend modes read, vtkTyndallProjection).
 *
 * Minimum and Maximum are the data's finite scalar range.
 *
 * Lookup (both renderers): x = clamp((s - Minimum) * Scale, 0, Size - 1),
 * k = min(floor(x), Size - 2), f = x - k, value = entry k + f (entry k+1 -
 * entry k). On the GPU: texture coordinate s * TextureScale + TextureShift
 * on a Size-texel row (texel centres), the same lookup.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallTransferTable_h
#define vtkTyndallTransferTable_h

#include "TyndallMediumModule.h" // For export macro

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkColorTransferFunction;
class vtkImageData;
class vtkPiecewiseFunction;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallTransferTable
{
public:
  /// The number of entries (the GPU texture's width).
  static constexpr int Size = 4096;

  ///@{
  /// The GPU texture's rows (GetTexture()).
  static constexpr int AlbedoRow = 0;
  static constexpr int EmissionRow = 1;
  static constexpr int GradientRow = 2;
  static constexpr int Rows = 3;
  ///@}

  /**
   * Tabulates the functions of index `function` of `property` (and
   * `emission`, may be null) over the finite scalar range [lo, hi], the
   * opacity with the scalar opacity unit distance of component
   * `unitComponent` (vtkTyndallComponents: the component read). False with
   * `error` set when the property cannot be used (non-positive or
   * non-finite unit distance).
   */
  bool Build(vtkVolumeProperty* property, vtkColorTransferFunction* emission, double lo, double hi,
    std::string& error, bool linearExtinction = false, int function = 0, int unitComponent = 0);

  ///@{
  /**
   * A plain property's gradient opacity (vtkTyndallGridMedium::
   * GetGradientOpacity()): TabulateGradientOpacity() tabulates `function`
   * (null: none) over the gradient magnitudes [0, GradientMaximum],
   * GradientMaximum = (Maximum - Minimum) / 4 (1 / 4 for a single value),
   * as VTK 9.1 does, clamped to [0, 1]; GradientOpacityAt(g) is the table
   * at min(g, GradientMaximum), interpolated (1 without a function). On the
   * GPU: row GradientRow, coordinate min(g / GradientMaximum, 1) (Size - 1)
   * / Size + 0.5 / Size.
   */
  void TabulateGradientOpacity(vtkPiecewiseFunction* function);
  std::vector<double> GradientOpacity;
  double GradientMaximum = 0.0;
  double GradientOpacityAt(double g) const
  {
    if (this->GradientOpacity.empty())
    {
      return 1.0;
    }
    int k;
    double f;
    Position(g / this->GradientMaximum * (Size - 1), k, f);
    return this->GradientOpacity[k] + f * (this->GradientOpacity[k + 1] - this->GradientOpacity[k]);
  }
  ///@}

  ///@{
  /**
   * A plain property's 2-D transfer function (TF_2D,
   * vtkVolumeProperty::GetTransferFunction2D()), as VTK 9.1 reads it: an
   * image of W x H pixels of 4 components (colour, opacity), its x axis the
   * scalar over [Minimum, Maximum], its y axis the gradient magnitude over
   * [0, GradientMaximum] (the change per average voxel, TabulateGradientOpacity()'s
   * units). VTK resamples it to its texture's size, each side the next
   * power of two and at least 1024 (a height of 1 stays 1), with
   * vtkImageResize's defaults (a Lanczos sinc over the corner pixels'
   * centres); so does Tabulate2D(), keeping the result in [0, 1] (VTK
   * keeps the sinc's ringing past a hard edge of a colour).
   * The table (Transfer2DSize, W' x H') is read at u = position / extent
   * across it (pixel i spans [i / W', (i + 1) / W']), interpolated
   * bilinearly between pixel centres, clamped at the edges (the GPU's
   * texture lookup), or with `nearest` (VTK reads it so with the property's
   * nearest interpolation) the pixel the point falls in. Tabulate2D() reads
   * the function
   * (false, with `error`, for no image, another shape than W x H x 1 with
   * W, H >= 1, more than Largest2D pixels on a side (a 4096^2 texture of
   * RGBA floats is 256 MiB), other than 4 components, a non-finite value,
   * or a colour or opacity outside [0, 1]); it replaces Extinction by an upper bound of
   * the function's extinction around each entry, over every gradient, at
   * `distance` per opacity (what empty-space skipping and the majorant
   * read). Transfer2DAt() is the lookup (rgba). Build() clears it.
   */
  static constexpr int Largest2D = 4096;
  bool Tabulate2D(vtkImageData* function, double distance, bool nearest, std::string& error);
  void Transfer2DAt(double u, double g, double rgba[4]) const;
  bool Has2D() const { return !this->Transfer2D.empty(); }
  std::vector<float> Transfer2D; // RGBA, row by row (y = gradient), W x H
  int Transfer2DSize[2] = { 0, 0 };
  bool Transfer2DNearest = false;
  ///@}

  double Minimum = 0.0;
  double Maximum = 1.0;
  /// Entries per scalar unit, (Size - 1) / (Maximum - Minimum); 0 for a single value.
  double Scale = 0.0;
  std::vector<double> Extinction;
  std::vector<double> Albedo;   // RGB
  std::vector<double> Emission; // RGB
  std::vector<double> Opacity;

  ///@{
  /**
   * Emission from a separate array (vtkParticipatingMediumProperty::
   * EmissionArrayName): the Emission entries then tabulate the emission
   * colour over that array's finite range [lo, hi] instead, at
   * EmissionMinimum + i / EmissionEntries; `color(v, rgb)` gives the colour
   * of value v. LocateEmission() and EmissionTextureScale() / Shift() are
   * Locate() and TextureScale() / Shift() for it.
   */
  void TabulateEmission(double lo, double hi, const std::function<void(double, double[3])>& color);
  bool EmissionFromArray = false;
  double EmissionMinimum = 0.0;
  double EmissionEntries = 0.0;
  void LocateEmission(double v, int& k, double& f) const
  {
    Position((v - this->EmissionMinimum) * this->EmissionEntries, k, f);
  }
  double EmissionTextureScale() const { return this->EmissionEntries / Size; }
  double EmissionTextureShift() const
  {
    return 0.5 / Size - this->EmissionMinimum * this->EmissionEntries / Size;
  }
  ///@}

  /// The table position of scalar s (see the class description).
  void Locate(double s, int& k, double& f) const
  {
    Position((s - this->Minimum) * this->Scale, k, f);
  }
  /// Entry k and fraction f of the table position x (clamped to the table).
  static void Position(double x, int& k, double& f)
  {
    x = x > 0.0 ? (x < Size - 1 ? x : Size - 1) : 0.0;
    k = static_cast<int>(x);
    k = k < Size - 2 ? k : Size - 2;
    f = x - k;
  }
  double ExtinctionAt(int k, double f) const
  {
    return this->Extinction[k] + f * (this->Extinction[k + 1] - this->Extinction[k]);
  }
  double OpacityAt(int k, double f) const
  {
    return this->Opacity[k] + f * (this->Opacity[k + 1] - this->Opacity[k]);
  }
  /// The opacity function at scalar s (Locate() and OpacityAt()).
  double OpacityOf(double s) const
  {
    int k;
    double f;
    this->Locate(s, k, f);
    return this->OpacityAt(k, f);
  }
  ///@{
  /**
   * The scalar on the finite range, u = (s - Minimum) / (Maximum - Minimum)
   * (0 for a single value), as UnitScale() s + UnitShift() (the shaders'
   * uniforms).
   */
  double UnitScale() const
  {
    return this->Maximum > this->Minimum ? 1.0 / (this->Maximum - this->Minimum) : 0.0;
  }
  double UnitShift() const { return -this->Minimum * this->UnitScale(); }
  double Unit(double s) const { return (s - this->Minimum) * this->UnitScale(); }
  ///@}
  static void RGBAt(const std::vector<double>& table, int k, double f, double rgb[3])
  {
    const double* a = table.data() + 3 * k;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = a[c] + f * (a[c + 3] - a[c]);
    }
  }

  ///@{
  /**
   * The GPU's texture coordinate along the table: s * TextureScale() +
   * TextureShift() (texel i's centre is at (i + 0.5) / Size).
   */
  double TextureScale() const { return this->Scale / Size; }
  double TextureShift() const { return 0.5 / Size - this->Minimum * this->Scale / Size; }
  ///@}

  /**
   * The GPU layout: Rows RGBA float rows of Size texels; row AlbedoRow =
   * (albedo, extinction), row EmissionRow = (emission, opacity), row
   * GradientRow = (gradient opacity, 0, 0, 0) (1 without one).
   */
  void GetTexture(std::vector<float>& rgba) const;

private:
  // Tabulate2D()'s resampling of the validated W x H pixels `rgba` to VTK's
  // texture size (dims becomes it); sets Transfer2D and Transfer2DSize.
  void Resample2D(std::vector<float>& rgba, int dims[3]);
};

#endif
