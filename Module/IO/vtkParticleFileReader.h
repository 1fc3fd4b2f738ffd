/**
 * @class   vtkParticleFileReader
 * @brief   reads a particle cloud: points with a radius and a density each, and an optional colour
 *
 * The particles of a particle medium (vtkParticleKernel: a smooth sphere of
 * radius R and peak extinction rho per world unit), from a file chosen by its
 * extension (case-insensitive):
 *
 * - `.csv`, `.txt`: one particle per line, `x y z radius density` or
 *   `x y z radius density r g b`, the numbers separated by commas, spaces or
 *   tabs (every line the same count); empty lines and lines starting with
 *   `#` are skipped, and a first line that is not numbers (a header such as
 *   `x,y,z,radius,density`) too;
 * - `.vtp` (VTK XML polydata) and `.vtk` (legacy polydata): the points, with
 *   the point-data arrays named RadiusArrayName (default "radius") and
 *   DensityArrayName (default "density"), one component each, and
 *   optionally ColorArrayName (default "color", three components).
 *
 * The output is a vtkPolyData: the points (double), one vertex cell per
 * point, and the point-data arrays "radius" and "density" (double) and, when
 * the file has colours, "color" (three doubles).
 *
 * Every particle is checked: finite coordinates, a finite radius > 0, a
 * finite density >= 0, colour components in [0, 1]; and a file holds at most
 * MaximumNumberOfParticles. A missing, unreadable or empty file, a line that
 * is not 5 or 8 numbers, a missing array or any particle that fails the
 * checks is an error through VTK's error mechanism naming the file and the
 * line or particle, and the output is empty: never a partial cloud.
 */

#ifndef vtkParticleFileReader_h
#define vtkParticleFileReader_h

#include "TyndallIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For std::string

class vtkPolyData;

class TYNDALLIO_EXPORT vtkParticleFileReader : public vtkPolyDataAlgorithm
{
public:
  static vtkParticleFileReader* New();
  vtkTypeMacro(vtkParticleFileReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read (see the class description for the formats).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// The point-data arrays of a `.vtp` / `.vtk` file: radius, density, colour (optional).
  vtkSetStringMacro(RadiusArrayName);
  vtkGetStringMacro(RadiusArrayName);
  vtkSetStringMacro(DensityArrayName);
  vtkGetStringMacro(DensityArrayName);
  vtkSetStringMacro(ColorArrayName);
  vtkGetStringMacro(ColorArrayName);
  ///@}

  /// The most particles a file may hold (100 million).
  static constexpr long long MaximumNumberOfParticles = 100000000LL;

  /// Whether the extension is one this reader reads (.csv, .txt, .vtp, .vtk).
  static bool CanReadExtension(const char* fileName);

protected:
  vtkParticleFileReader();
  ~vtkParticleFileReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* RadiusArrayName = nullptr;
  char* DensityArrayName = nullptr;
  char* ColorArrayName = nullptr;

private:
  vtkParticleFileReader(const vtkParticleFileReader&) = delete;
  void operator=(const vtkParticleFileReader&) = delete;

  bool ReadText(vtkPolyData* output);
  bool ReadPolyData(vtkPolyData* output, bool xml);
  /// Checks every particle of `output`; false (with an error) at the first that fails.
  bool Validate(vtkPolyData* output);
};

#endif
