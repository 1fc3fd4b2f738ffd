/**
 * @class   vtkTyndallEnvironment
 * @brief   the light from a renderer's sky, read as VTK's ray tracers read it, and sampled
 *
 * vtkTyndallEnvironment turns the environment a vtkRenderer gives VTK's ray
 * tracing backends (the rule of VTK 9.1's vtkOSPRayRendererNode) into a
 * radiance L(w) for every direction w, with the importance sampling both of
 * Tyndall's path tracers use (vtkVolumetricPathTracer on the CPU,
 * vtkTransmittancePathTracePass on the GPU, its tables as textures):
 *
 * - with UseImageBasedLighting on and an EnvironmentTexture holding a 2-D
 *   image (its input, updated): that image, an equirectangular projection;
 * - else, with GradientEnvironmentalBG on: a vertical gradient from
 *   EnvironmentalBG (straight down) to EnvironmentalBG2 (straight up), linear
 *   in the elevation angle, tabulated in GradientRows rows;
 * - else the constant EnvironmentalBG (VTK's default, black, is no light).
 *
 * The image is placed as vtkSkybox places an equirectangular image: up U =
 * the renderer's EnvironmentUp, right R = its EnvironmentRight made
 * orthogonal to U, front F = U x R; the direction w = x R + y U + z F falls
 * in the column floor(W (1/2 + atan2(x, z) / (2 pi))) and the row
 * floor(H (1/2 + atan2(y, sqrt(x^2 + z^2)) / pi)) of a W x H image (row 0,
 * VTK's first, looks straight down). L is constant over each texel (the
 * nearest texel, as the GPU's texelFetch reads it): a texel is a patch of
 * the sphere of solid angle (2 pi / W) (sin e1 - sin e0), e0 and e1 its
 * rows' elevations.
 *
 * Units: the colours and a floating-point image are linear radiance in the
 * picture's units, as the medium's AmbientIntensity is (not scaled by its
 * LightScale, which turns a light's intensity into irradiance): a white sky
 * of 1 around a white, non-absorbing medium gives a picture of 1
 * everywhere. An image of 8- or 16-bit integers holds display values:
 * scaled to [0, 1] by its type's largest value and sRGB-decoded (as VTK's
 * path tracer reads an 8-bit one); a floating-point texture with
 * UseSRGBColorSpace is sRGB-decoded too (the curve continued past 1). The alpha channel is
 * not read; one or two components are grey.
 *
 * Sampling: a texel is drawn with a probability proportional to the mean of
 * its three channels times its solid angle (the rows' and then the
 * columns' cumulative tables), then a direction uniformly within its patch
 * (the azimuth and the sine of the elevation uniform): the density in solid
 * angle is the texel's mean channel over the sum of mean channel x solid
 * angle, exactly proportional to a grey environment's radiance, 1 / (4 pi)
 * for a constant one, 0 where every channel is 0.
 *
 * Bad input is refused with an error through the reporter, once per change,
 * and the environment is then black (the scene renders without its light):
 * a cube map, an image that is not 2-D, has more than 4 components or
 * integers wider than 16 bits, a side above MaximumImageSide, or a
 * negative, NaN or infinite value or colour (or one above MaximumRadiance);
 * an up vector of length 0 or a right vector parallel to it (unless the sky
 * is black: no image and black colours, whose frame is not read). A NaN
 * setting is refused once, not at every frame.
 *
 * Update() rebuilds the tables only when the renderer's settings, the
 * texture or its image change (GetSerial() counts the
 * rebuilds, for the GPU's upload). Internal to Tyndall::Medium; not
 * wrapped.
 */

#ifndef vtkTyndallEnvironment_h
#define vtkTyndallEnvironment_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkType.h"             // For vtkMTimeType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkObject;
class vtkRenderer;
class vtkTexture;

class TYNDALLMEDIUM_EXPORT vtkTyndallEnvironment
{
public:
  /// Rows of a tabulated gradient.
  static constexpr int GradientRows = 256;
  /// The largest side of an image read (texels).
  static constexpr int MaximumImageSide = 8192;
  /// The largest radiance read (the GPU's float sums of it stay finite).
  static constexpr double MaximumRadiance = 1e20;

  /**
   * Reads `renderer`'s environment (see the class description); a null
   * renderer is no light. False (with an error through `reporter`, once per
   * change) when the environment is refused: it is then black.
   */
  bool Update(vtkRenderer* renderer, vtkObject* reporter);

  /// Whether any direction has light (the path tracers then sample it).
  bool Enabled() const { return this->Total > 0.0; }

  ///@{
  /// The table: Width x Height texels (row 0 straight down).
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }
  /// RGB radiance per texel, row after row.
  const std::vector<float>& GetRadiance() const { return this->Radiance; }
  /// The rows' cumulative probabilities: Height values, the last 1 (row j's ends at value j).
  const std::vector<float>& GetRowTable() const { return this->RowTable; }
  /// Each row's columns' cumulative probabilities: Width values per row, the last 1.
  const std::vector<float>& GetColumnTable() const { return this->ColumnTable; }
  /// The sum over the texels of mean channel x solid angle (the density's normaliser).
  double GetTotal() const { return this->Total; }
  ///@}

  ///@{
  /// The frame: up, right and front (unit, orthogonal).
  const double* GetUp() const { return this->Up; }
  const double* GetRight() const { return this->Right; }
  const double* GetFront() const { return this->Front; }
  ///@}

  /// The world direction x Right + y Up + z Front (the sky's frame to the world's).
  void FromFrame(double x, double y, double z, double w[3]) const;

  /// The texel (column i, row j) the unit direction w falls in.
  void Texel(const double w[3], int& i, int& j) const;

  /**
   * The unit direction at the table's point (u, v), in texels: column u,
   * row v (texel (i, j)'s centre at (i + 1/2, j + 1/2)); Texel()'s inverse.
   */
  void Direction(double u, double v, double w[3]) const;

  /// The solid angle of one texel of row j.
  double SolidAngle(int j) const;

  /// L(w) for the unit direction w.
  void Evaluate(const double w[3], double L[3]) const;

  /// The sampling density of the unit direction w, per steradian.
  double Pdf(const double w[3]) const;

  /**
   * Draws a direction w from four uniform numbers in [0, 1) (the row, the
   * column, the azimuth and the elevation within the texel); returns its
   * density per steradian (0, w untouched, when nothing has light) and its
   * radiance in L.
   */
  double Sample(const double u[4], double w[3], double L[3]) const;

  /// The mean radiance over the sphere, (1 / 4 pi) times the integral of L.
  const double* GetMeanRadiance() const { return this->Mean; }

  /// Counts the tables' rebuilds (0 before the first).
  vtkMTimeType GetSerial() const { return this->Serial; }

private:
  struct Key
  {
    bool Image = false;
    vtkTexture* Texture = nullptr;
    vtkMTimeType TextureTime = 0;
    bool Gradient = false;
    double Colors[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
    double Up[3] = { 0.0, 1.0, 0.0 }; // VTK's defaults
    double Right[3] = { 1.0, 0.0, 0.0 };
    bool operator==(const Key& other) const;
  };

  /// The key of `renderer`'s environment (the texture's image updated); its image in `image`.
  static Key MakeKey(vtkRenderer* renderer, vtkImageData*& image);
  /// Fills the table from the key (and image); false with the reason in `why`.
  bool Build(const Key& key, vtkImageData* image, std::string& why);
  bool ReadImage(vtkImageData* image, bool srgb, std::string& why);
  bool SetFrame(const double up[3], const double right[3], std::string& why);
  /// Fills the sampling tables and the mean from the radiance.
  void Tabulate();
  /// Makes the environment black (one texel of 0).
  void Clear();

  int Width = 1;
  int Height = 1;
  std::vector<float> Radiance = std::vector<float>(3, 0.0f);
  std::vector<float> RowTable = { 1.0f };
  std::vector<float> ColumnTable = { 1.0f };
  double Total = 0.0;
  double Mean[3] = { 0.0, 0.0, 0.0 };
  double Up[3] = { 0.0, 1.0, 0.0 };
  double Right[3] = { 1.0, 0.0, 0.0 };
  double Front[3] = { 0.0, 0.0, -1.0 };
  Key Last;
  bool Read = false;  // Last holds a key read before
  bool LastOk = true; // what Update() returned for Last
  vtkMTimeType Serial = 0;
};

#endif
