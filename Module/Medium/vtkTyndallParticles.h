/**
 * @class   vtkTyndallParticles
 * @brief   a particle cloud's data: particles, exact density, its grid and its splatting data
 *
 * The particles of a vtkTransmittanceParticleMapper's input (a vtkPolyData:
 * the points, and the point-data arrays "radius" and "density", as
 * vtkParticleFileReader writes them), each the smooth sphere of
 * vtkParticleKernel: density rho (1 - r^2/R^2)^2 within the radius R. Their
 * sum is the medium's scalar, in the *data* coordinates of the points (the
 * vtkVolume's matrix places them like an image's).
 *
 * - Density() is the exact sum at a data point (the CPU reference samples it:
 *   a uniform grid of cells lists the particles overlapping each cell).
 * - Voxelize() samples the exact sum at the nodes of an image around the
 *   particles (isotropic spacing, the longest side a given count of
 *   samples): the grid medium both renderers read (its placement, colour
 *   and emission, and the GPU's camera rays and shadow rays march it); the
 *   image's outermost nodes lie on the particles' bounding box, where the
 *   kernel is zero.
 * - GetSplatVertices() is what the GPU splats into the extinction maps: per
 *   particle its centre, radius and density (5 floats).
 * - Colours (optional): with a three-component point-data array "color"
 *   (vtkParticleFileReader's), each particle's colour is its albedo, and
 *   where particles overlap the medium's albedo is their mean weighted by
 *   their extinctions, sum(rho_i k_i c_i) / sum(rho_i k_i): scattering adds
 *   like extinction. Density() gives it exactly; Voxelize() adds the
 *   scattering density sum(rho_i k_i c_i) as a three-component array, from
 *   which the GPU divides the interpolated scattering by the interpolated
 *   density.
 *
 * Update() reads a vtkPolyData: at least one point and at most
 * MaximumNumberOfParticles, finite coordinates, the two arrays (one
 * component, one value per point), every radius finite and > 0 and every
 * density finite and >= 0, and if there is a "color" array, three components
 * in [0, 1] per point. Anything else is an error and an empty medium.
 *
 * Internal to Tyndall::Medium; not wrapped.
 *
 * @sa vtkParticleKernel vtkTransmittanceParticleMapper
 */

#ifndef vtkTyndallParticles_h
#define vtkTyndallParticles_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkTimeStamp.h"        // For vtkTimeStamp
#include "vtkType.h"             // For vtkIdType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkPolyData;

class TYNDALLMEDIUM_EXPORT vtkTyndallParticles
{
public:
  /// The most particles a medium holds.
  static constexpr vtkIdType MaximumNumberOfParticles = 50000000;

  /**
   * Reads the particles of `particles` (see the class description). False
   * with `error` set, and the medium empty, when they cannot be used.
   */
  bool Update(vtkPolyData* particles, std::string& error);

  vtkIdType GetNumberOfParticles() const { return static_cast<vtkIdType>(this->Radius.size()); }

  /// The box around every particle's sphere, in data coordinates (xmin, xmax, ymin, ...).
  const double* GetBounds() const { return this->Bounds; }

  /// The largest radius.
  double GetMaximumRadius() const { return this->MaximumRadius; }

  /**
   * An upper bound of Density() everywhere: the largest sum of the peak
   * densities of the particles listed in one cell (for delta tracking's
   * majorant).
   */
  double GetDensityBound() const { return this->DensityBound; }

  /// The exact density (the sum of the kernels) at the data point x.
  double Density(const double x[3]) const;

  /// Whether the particles have colours (a "color" array).
  bool HasColors() const { return !this->Colors.empty(); }

  /**
   * The exact density at the data point x, and in `color` the albedo there:
   * the particles' colours weighted by their extinctions (without colours,
   * or where the density is 0: white).
   */
  double Density(const double x[3], double color[3]) const;

  /**
   * Samples Density() at the nodes of `image`: isotropic spacing, the
   * longest side of GetBounds() `longestSide` nodes (at least 2), the
   * outermost nodes on the bounds. The point scalars are a float array
   * named "density"; with colours, a three-component float array named
   * "scattering" holds the density times the albedo at each node.
   */
  void Voxelize(int longestSide, vtkImageData* image) const;

  /// When the particles were last read (unique among every medium's reads; 0: never).
  vtkMTimeType GetReadTime() const { return this->ReadTime.GetMTime(); }

  /// Per particle: centre x, y, z, radius, density (data coordinates).
  const std::vector<float>& GetSplatVertices() const { return this->SplatVertices; }

private:
  void BuildCells();
  // The density at x, and with `color` the sum of density x colour.
  double Sum(const double x[3], double* color) const;
  // The cell of a data coordinate along axis a, clamped to the grid.
  int CellIndex(int a, double x) const;

  // Per particle: centre x, y, z, R^2, 1 / R^2 and density (Sum()'s reads,
  // side by side), and the radius. A radius whose square underflows has no
  // extent (nothing lies inside: its mass is 0), one whose square overflows
  // fills space (1 / R^2 is 0).
  static constexpr int KernelSize = 6;
  std::vector<double> Kernels;
  std::vector<double> Radius;
  std::vector<double> Colors; // 3 per particle, or none
  std::vector<float> SplatVertices;
  double Bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double MaximumRadius = 0.0;
  double DensityBound = 0.0;
  vtkTimeStamp ReadTime;

  // The cells: CellStart[c] .. CellStart[c + 1] index CellParticles.
  int CellDims[3] = { 0, 0, 0 };
  double CellSize = 1.0;
  std::vector<vtkIdType> CellStart;
  std::vector<vtkIdType> CellParticles;
};

#endif
