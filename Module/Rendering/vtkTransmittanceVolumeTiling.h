/**
 * @class   vtkTransmittanceVolumeTiling
 * @brief   a volume deeper than the GPU's 3-D textures, laid out as tiles of slices in one texture
 *
 * GL_MAX_3D_TEXTURE_SIZE bounds each side of a 3-D texture (2048 on Mesa
 * llvmpipe and most GPUs), not its size in bytes. A volume of nx x ny x nz
 * samples whose nz passes it, but whose nx and ny leave room, is stored in
 * one texture as tiles: tile k holds slices k S .. k S + S (S + 1 slices,
 * one shared with the next tile, so that linear interpolation between any
 * two neighbouring slices reads one tile), and the tiles sit side by side,
 * TilesX across and as many rows as needed: tile k's origin is
 * ((k mod TilesX) nx, floor(k / TilesX) ny, 0). A 512 x 512 x 3000 CT
 * becomes one 1024 x 512 x 1501 texture, sampled as one volume: a sample's
 * volume texture coordinate t (texel i's centre at (i + 0.5) / n, as for
 * an untiled volume) maps to the tiled texture by MapCoordinate(), which
 * the shaders compute the same way (tyndallTiledTexel() in
 * vtkTransmittanceCommonFS.glsl): the sample coordinate v = t n - 0.5 is
 * clamped to [0, n - 1] (what clamp-to-edge does at the volume's faces,
 * and what keeps a tile's filtering off its neighbours), the tile is
 * floor(v.z / S), and the texel is the tile's origin plus v. Nothing is
 * copied: each tile is a run of whole slices of the data (x fastest),
 * uploaded from the data's memory with glTexSubImage3D (Upload()).
 *
 * The scalars and every texture at their resolution (validity, labels,
 * emission) share one tiling. A volume that fits is one tile (IsTiled()
 * false; MapCoordinate() is then the identity inside the volume). Plan()
 * fails when nx or ny passes the limit, or when the tiles of nz do not fit
 * beside each other: the caller samples the volume more coarsely then.
 *
 * Internal to Tyndall::Rendering; not wrapped.
 */

#ifndef vtkTransmittanceVolumeTiling_h
#define vtkTransmittanceVolumeTiling_h

#include "TyndallRenderingModule.h" // For export macro

class vtkTextureObject;

class TYNDALLRENDERING_EXPORT vtkTransmittanceVolumeTiling
{
public:
  /**
   * The layout of a volume of `dims` samples in a 3-D texture of at most
   * `maximumSize` texels per side: false (the layout unchanged) when it
   * cannot hold it.
   */
  bool Plan(const int dims[3], int maximumSize);

  /// Whether the volume needs more than one tile.
  bool IsTiled() const { return this->Tiles > 1; }
  int GetTiles() const { return this->Tiles; }
  int GetTilesX() const { return this->TilesX; }
  /// S: the slices from one tile's first to the next's (each holds S + 1).
  int GetSlicesPerTile() const { return this->SlicesPerTile; }
  /// The volume's samples per axis (Plan()'s `dims`).
  const int* GetDimensions() const { return this->Dimensions; }
  /// The texture's size: TilesX nx x rows ny x (S + 1), or the volume's.
  const int* GetTextureDimensions() const { return this->TextureDimensions; }
  /// The texels the texture holds over the volume's samples (>= 1).
  double GetOverhead() const;

  /// Tile k's slices: `first` and `count` (at most S + 1), and its origin in texels.
  void GetTile(int k, int& first, int& count, int origin[2]) const;

  /**
   * The shaders' uniforms: (TilesX, S, Tiles), the volume's dimensions and
   * the texture's, as floats.
   */
  void GetUniforms(float tiling[3], float dims[3], float textureDims[3]) const;

  /**
   * The CPU twin of the shaders' tyndallTiledTexel(): the tiled texture's
   * coordinate of volume texture coordinate `t`.
   */
  void MapCoordinate(const double t[3], double texel[3]) const;

  /**
   * Creates `texture` (its context current) at the texture's size with
   * `components` of VTK `type` per texel and uploads `values` (the volume's
   * samples, x fastest) tile by tile from their memory. False when the GL
   * cannot create or fill it.
   */
  bool Upload(vtkTextureObject* texture, int components, int type, const void* values) const;

private:
  int Dimensions[3] = { 1, 1, 1 };
  int TextureDimensions[3] = { 1, 1, 1 };
  int Tiles = 1;
  int TilesX = 1;
  int SlicesPerTile = 1;
};

#endif
