/**
 * @class   vtkOpenVDBImageWriter
 * @brief   writes a vtkImageData's point scalars as a sparse OpenVDB fog volume
 *
 * vtkOpenVDBImageWriter writes the active point scalars of its input image
 * (one component, any numeric type) to a .vdb file as one sparse float grid
 * (openvdb::FloatGrid) of class "fog volume", named GridName (default
 * "density"), with background 0. Values whose magnitude is at most
 * Tolerance (default 0) are left inactive (they read back as the background,
 * 0); every other value becomes an active voxel holding the value converted
 * to float. Constant regions are then pruned into tiles, which changes no
 * value. NaN and infinite values (and doubles beyond the float range) are
 * not written: they stay inactive, and one warning says how many there were
 * (GetNumberOfNonFiniteValues()).
 *
 * Geometry. Image point (i, j, k) (structured coordinates of the extent)
 * becomes voxel (i, j, k), and the grid's transform maps it to the point's
 * world position: origin + direction * (spacing * (i, j, k)). The
 * transform is a uniform scale and translation when the spacing is the same
 * on all axes and the direction matrix is the identity, a scale and
 * translation for other spacings, and an affine map with a direction
 * matrix. vtkOpenVDBImageReader reads this back onto the same points, so a
 * write-read round trip restores every value exactly for float input (for
 * other types, to float precision), except that values with magnitude at
 * most Tolerance read back as 0; the read-back extent is the bounding box of
 * the active voxels, and every point outside it is 0. The spacing must be
 * positive and finite.
 *
 * Bad input (no input, no point scalars, several components, an empty
 * image, non-positive spacing, no file name or grid name) and failures
 * while writing (any exception OpenVDB throws is caught) are reported with
 * vtkErrorMacro; Write() then returns 0 and, for a failure while writing,
 * the file may be incomplete. Progress events are fired while the grid is
 * built.
 *
 * @sa vtkOpenVDBImageReader
 */

#ifndef vtkOpenVDBImageWriter_h
#define vtkOpenVDBImageWriter_h

#include "TyndallIOModule.h" // For export macro
#include "vtkWriter.h"

class vtkImageData;

class TYNDALLIO_EXPORT vtkOpenVDBImageWriter : public vtkWriter
{
public:
  static vtkOpenVDBImageWriter* New();
  vtkTypeMacro(vtkOpenVDBImageWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .vdb file to write; default none.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The name of the grid; default "density". Must not be empty.
   */
  vtkSetStringMacro(GridName);
  vtkGetStringMacro(GridName);
  ///@}

  ///@{
  /**
   * Values with |v| <= Tolerance are not stored (inactive background, 0);
   * in [0, VTK_DOUBLE_MAX]; default 0 (only exact zeros are dropped).
   */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Store the float values at half precision in the file (OpenVDB's
   * "is_saved_as_half_float"); default off. On, the round trip is exact only
   * to half precision.
   */
  vtkSetMacro(SaveFloatAsHalf, bool);
  vtkGetMacro(SaveFloatAsHalf, bool);
  vtkBooleanMacro(SaveFloatAsHalf, bool);
  ///@}

  /**
   * Active voxels of the last written grid (before pruning into tiles).
   */
  vtkGetMacro(NumberOfActiveVoxels, vtkIdType);

  /**
   * NaN or infinite input values (or doubles beyond float range) skipped by
   * the last write.
   */
  vtkGetMacro(NumberOfNonFiniteValues, vtkIdType);

  /**
   * The input image.
   */
  vtkImageData* GetInput();

protected:
  vtkOpenVDBImageWriter();
  ~vtkOpenVDBImageWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;
  char* GridName = nullptr;
  double Tolerance = 0.0;
  bool SaveFloatAsHalf = false;
  vtkIdType NumberOfActiveVoxels = 0;
  vtkIdType NumberOfNonFiniteValues = 0;

private:
  vtkOpenVDBImageWriter(const vtkOpenVDBImageWriter&) = delete;
  void operator=(const vtkOpenVDBImageWriter&) = delete;
};

#endif
