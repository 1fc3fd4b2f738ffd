/**
 * @class   vtkTyndallMajorantGrid
 * @brief   the largest extinction in each block of a volume, for skipping empty space
 *
 * The volume's samples are grouped in blocks of BlockSize^3. Block b (per
 * axis) answers for every point whose continuous sample coordinate v (sample
 * i's centre at v = i) lies in [b BlockSize, (b + 1) BlockSize): trilinear
 * interpolation there reads samples b BlockSize .. (b + 1) BlockSize. The
 * block's scalar range is taken over samples b BlockSize - 1 .. (b + 1)
 * BlockSize + 1, one more each side, so that a point the GPU rounds across
 * a block face (its 8-bit filtering weights, a point computed a rounding
 * error off the face) still reads only samples of its block's range; points
 * outside the samples clamp to the edge ones, which belong to the first and
 * last blocks. Missing samples (NaN, given by `valid`) make a point empty
 * and are left out.
 *
 * Two steps, each repeated only when its input changes:
 * - BuildRanges(): the scalar range of each block (a pass over the samples,
 *   O(N), each sample read ((BlockSize + 3) / BlockSize)^3 times on
 *   average);
 * - BuildMajorants(): each block's majorant, the largest table extinction
 *   over the table entries its range can touch (linear filtering weighs
 *   entries floor(x) and floor(x) + 1, the second by x - floor(x), so
 *   values in [lo, hi] read entries floor(x_lo) .. ceil(x_hi); a GPU that
 *   rounds a table coordinate by a fraction of a texel can give an entry
 *   next to that span a weight of at most a rounding error, far below what
 *   an 8-bit pixel resolves). O(blocks + Size log Size) with a sparse table
 *   of range maxima: cheap enough for every transfer-function edit.
 *
 * A majorant of 0 means the block is empty: every sample the renderers can
 * take inside it has zero extinction, so skipping it changes no picture.
 * The majorants are in table units (before the density scale), i.e. exactly
 * what the GPU's table texture holds in its alpha channel.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallMajorantGrid_h
#define vtkTyndallMajorantGrid_h

#include "TyndallMediumModule.h" // For export macro

#include <vector> // For std::vector

class vtkTyndallComponents;
class vtkTyndallTransferTable;

class TYNDALLMEDIUM_EXPORT vtkTyndallMajorantGrid
{
public:
  /// Samples per block edge.
  static constexpr int BlockSize = 8;

  /**
   * The range of each of the `components` of every block of `values`
   * (dims[0] x dims[1] x dims[2] samples, x fastest, `components` values
   * each); `valid` (may be null) is 0 for missing samples. Returns the
   * seconds it took. T: float, or the 8- and 16-bit integers the GPU keeps
   * in their own type (unsigned and signed char and short).
   */
  template <typename T>
  double BuildRanges(
    const T* values, int components, const unsigned char* valid, const int dims[3]);

  ///@{
  /**
   * Each block's majorant (after BuildRanges()) under one `table`, or under
   * the tables of `components` (vtkTyndallComponents::GetTableCount() of
   * them, each over the range of its component; vtkTyndallComponents::
   * Majorant() bounds their mixture). Returns the seconds it took.
   */
  double BuildMajorants(const vtkTyndallTransferTable& table);
  double BuildMajorants(
    const vtkTyndallTransferTable* const tables[], const vtkTyndallComponents& components);
  ///@}

  /// Blocks per axis.
  const int* GetBlockCounts() const { return this->Counts; }

  /// One majorant per block, x fastest (table units).
  const std::vector<float>& GetMajorants() const { return this->Majorants; }

  /// The fraction of blocks whose majorant is 0.
  double GetEmptyFraction() const;

  /// The block of sample coordinate v along axis a (clamped to the grid).
  int BlockOf(int a, double v) const;

private:
  int Counts[3] = { 0, 0, 0 };
  int Components = 1;
  std::vector<float> Low;  // per block and component; +inf when every sample is missing
  std::vector<float> High; // per block and component; -inf when every sample is missing
  std::vector<float> Majorants;
};

#endif
