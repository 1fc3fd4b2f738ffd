/**
 * @class   vtkOpenVDBImageReader
 * @brief   reads OpenVDB grids (.vdb) into a dense vtkImageData
 *
 * vtkOpenVDBImageReader reads one or several grids of an OpenVDB file with
 * OpenVDB's own library and densifies them into point arrays of a
 * vtkImageData, one array per grid, named after the grid.
 *
 * Supported grids: scalar float (FloatGrid, including float grids stored at
 * half precision, "is_saved_as_half_float") and double (DoubleGrid) grids,
 * read into one-component vtkFloatArray / vtkDoubleArray; vec3s and vec3d
 * grids, read into three-component float / double arrays. OpenVDB 10 has no
 * half-valued grid type; a file holding one (or any other grid type, such as
 * int32, bool, mask or point grids) is refused with an error naming the type.
 *
 * Geometry. The output's structured coordinates are OpenVDB's index
 * coordinates: extent (i0, i1, j0, j1, k0, k1) is the index bounding box of
 * the active voxels, point (i, j, k) is the centre of voxel (i, j, k), and
 * origin, spacing and direction come from the grid's linear transform, so
 * the image's world coordinates are OpenVDB's. A transform with rotation is
 * applied through the image's direction matrix (vtkImageData::
 * SetDirectionMatrix; not every VTK mapper honours it), with the voxel size
 * along each index axis as spacing (non-uniform scale is fine). Transforms
 * VTK cannot represent are refused: non-linear (frustum) maps and sheared
 * affine maps.
 *
 * Values. Active voxels and active tiles get their value; every other voxel
 * of the extent gets the grid's background value (whatever inactive voxels
 * store in the file is ignored). NaN and infinite values, active or
 * background, are replaced by 0; the count of replaced output voxels is
 * reported with one warning per update and is available from
 * GetNumberOfNonFiniteValues().
 *
 * Sparse grids. The arrays are allocated zeroed (calloc). A grid whose
 * background is 0 (a fog volume, an OpenVDB cache of smoke), read without
 * downsampling, gets its active values written and nothing else: the
 * reading costs its active values, not its box, and the memory pages of the
 * box that no active value touches are never allocated by the system (reads
 * of them, such as a mapper's scan of the scalars, allocate nothing
 * either). The array is a plain dense vtkFloatArray / vtkDoubleArray all
 * the same: whatever writes into it or copies it pays for the box. (A
 * piece of the grid whose voxels are fewer than the grid's active values is
 * read voxel by voxel: the cheaper of the two.) GetFilledActiveOnly() says
 * whether the last update did so for every grid.
 *
 * Grid selection. SetGridName() selects one grid and AddGridName() adds
 * more; with no name given the reader picks the float grid named "density",
 * else the first float grid, else the first supported grid. Several grids
 * become several arrays of one image: they must share one transform (up to
 * 1e-9 relative), and the extent is the union of their index bounding
 * boxes, so each grid is padded with its own background where it has no
 * voxels. The first selected grid is the active scalars. After
 * UpdateInformation() the file's grids can be listed (GetNumberOfGrids(),
 * GetGridName(), GetGridValueType(), GetGridClass(),
 * GetGridIndexBoundingBox(), ...) without reading any voxels: the index
 * bounding box comes from the file's "file_bbox_min/max" metadata, which
 * OpenVDB writes with every grid; only for a grid that lacks it is the grid
 * read at information time.
 *
 * Level sets (grid class "level set") are refused with an error unless
 * ConvertLevelSetToFog is on; then openvdb::tools::sdfToFogVolume turns them
 * into fog volumes (0 outside, rising linearly to 1 over the narrow band
 * inside) before densifying.
 *
 * Streaming. The reader can produce sub-extents: only the requested update
 * extent is densified (the grids are read whole from the file once and kept
 * until the file name, the file's size or time stamp, the selection or
 * ConvertLevelSetToFog change, or ReleaseGrids() is called).
 * DownsamplingFactor f > 1 averages f x f x f boxes of voxels (a box filter,
 * background included) into one output point: boxes are aligned to
 * multiples of f in OpenVDB index space, output index I covers voxels
 * I*f ... I*f + f - 1, its point sits at the box centre and the spacing is
 * f times the voxel size.
 *
 * Memory. Before allocating, the reader estimates the memory an update
 * needs: the dense arrays of the requested extent plus, for grids not yet in
 * memory, the grids' in-memory size recorded in the file ("file_mem_bytes").
 * Above MemoryLimit (MiB; default 4096) it reports an error naming the
 * estimate and produces an empty output. Grids whose index bounding box
 * exceeds 2^31 - 1 voxels along an axis are refused as absurd.
 *
 * Errors. Missing, empty, truncated or corrupted files, a missing grid name,
 * an unsupported grid type or transform, absurd dimensions or too little
 * memory give a vtkErrorMacro message and an empty output. Every exception
 * OpenVDB throws (openvdb::Exception, std::exception) is caught; none
 * reaches the pipeline. Progress events are fired while densifying, and
 * AbortExecute is honoured between batches of rows (of active values when
 * only those are written: every 2^20 of them).
 *
 * openvdb::initialize() is called once per process, on first use.
 *
 * @sa vtkOpenVDBImageWriter
 */

#ifndef vtkOpenVDBImageReader_h
#define vtkOpenVDBImageReader_h

#include "TyndallIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <memory> // For std::unique_ptr

class TYNDALLIO_EXPORT vtkOpenVDBImageReader : public vtkImageAlgorithm
{
public:
  static vtkOpenVDBImageReader* New();
  vtkTypeMacro(vtkOpenVDBImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .vdb file to read; default none.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Whether a file looks like an OpenVDB file (starts with OpenVDB's magic
   * number). Returns 1 if so, 0 otherwise; reads only its first 8 bytes.
   */
  static int CanReadFile(const char* fileName);

  ///@{
  /**
   * The grids to read. SetGridName() selects exactly one grid (nullptr or
   * "" returns to the automatic choice: "density" if it is a float grid,
   * else the first float grid, else the first supported grid);
   * AddGridName() appends one; RemoveAllGridNames() returns to the automatic
   * choice. The default is the automatic choice.
   */
  void SetGridName(const char* name);
  void AddGridName(const char* name);
  void RemoveAllGridNames();
  int GetNumberOfRequestedGridNames();
  const char* GetRequestedGridName(int i);
  ///@}

  ///@{
  /**
   * The file's grids, valid after UpdateInformation() (zero grids when the
   * file could not be read). Per grid: its name, its value type as OpenVDB
   * names it ("float", "double", "vec3s", "int32", ...), its tree type
   * ("Tree_float_5_4_3"), its class ("fog volume", "level set", "staggered",
   * "unknown"), whether this reader supports it, its index bounding box of
   * active voxels (i0, i1, j0, j1, k0, k1; returns false when unknown or
   * empty) and its number of active voxels (-1 when the file does not say).
   * Out-of-range indices give nullptr, false or -1.
   */
  int GetNumberOfGrids();
  const char* GetGridName(int i);
  const char* GetGridValueType(int i);
  const char* GetGridType(int i);
  const char* GetGridClass(int i);
  bool IsGridSupported(int i);
  bool GetGridIndexBoundingBox(int i, int bbox[6]);
  vtkTypeInt64 GetGridActiveVoxelCount(int i);
  int GetGridIndex(const char* name);
  ///@}

  ///@{
  /**
   * The grids the next update reads, after UpdateInformation(): the
   * requested names, or the automatic choice. Empty when the selection is
   * invalid (an error says why).
   */
  int GetNumberOfSelectedGrids();
  const char* GetSelectedGridName(int i);
  ///@}

  ///@{
  /**
   * Convert level sets to fog volumes with openvdb::tools::sdfToFogVolume
   * (default off: level sets are refused with an error).
   */
  vtkSetMacro(ConvertLevelSetToFog, bool);
  vtkGetMacro(ConvertLevelSetToFog, bool);
  vtkBooleanMacro(ConvertLevelSetToFog, bool);
  ///@}

  ///@{
  /**
   * Integer downsampling factor f in [1, 64]; default 1 (full resolution).
   * f > 1 box-filters f^3 voxels into one output point (see the class
   * documentation for the alignment).
   */
  vtkSetClampMacro(DownsamplingFactor, int, 1, 64);
  vtkGetMacro(DownsamplingFactor, int);
  ///@}

  ///@{
  /**
   * Memory limit in MiB for one update (dense output plus grids still to be
   * read), in [1, 1e9]; default 4096 (4 GiB). An update whose estimate is
   * above it fails with an error and an empty output.
   */
  vtkSetClampMacro(MemoryLimit, double, 1.0, 1.0e9);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  /**
   * Output voxels whose value was NaN or infinite (and was replaced by 0) in
   * the last update, summed over the arrays.
   */
  vtkGetMacro(NumberOfNonFiniteValues, vtkIdType);

  /**
   * Whether the last update wrote only the active values of every grid into
   * zeroed arrays (a background of 0, no downsampling): see "Sparse grids".
   */
  vtkGetMacro(FilledActiveOnly, bool);

  /**
   * The estimate, in bytes, that the last update compared with MemoryLimit.
   */
  vtkGetMacro(LastMemoryEstimate, double);

  /**
   * Frees the grids kept in memory for streaming; the next update reads
   * them from the file again.
   */
  void ReleaseGrids();

protected:
  vtkOpenVDBImageReader();
  ~vtkOpenVDBImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  bool ConvertLevelSetToFog = false;
  int DownsamplingFactor = 1;
  double MemoryLimit = 4096.0;
  vtkIdType NumberOfNonFiniteValues = 0;
  bool FilledActiveOnly = false;
  double LastMemoryEstimate = 0.0;

private:
  vtkOpenVDBImageReader(const vtkOpenVDBImageReader&) = delete;
  void operator=(const vtkOpenVDBImageReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  // Steps of RequestInformation; each reports its problem with vtkErrorMacro.
  bool ReadFileInformation();
  bool SelectGrids();
  bool ComputeGeometry();
  // Reads (or finds in memory) the selected grids.
  bool LoadGrids();
};

#endif
