#include "vtkTransmittanceVolumeTiling.h"

#include "vtkDataArray.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

namespace
{
// Whether the GL holds `texture`'s level 0 at its size: a driver out of
// memory may refuse a large texture without raising an error.
bool HoldsLevel(vtkTextureObject* texture)
{
  texture->Bind();
  GLint width = 0;
  glGetTexLevelParameteriv(texture->GetTarget(), 0, GL_TEXTURE_WIDTH, &width);
  return width == static_cast<GLint>(texture->GetWidth());
}
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeTiling::Plan(const int dims[3], int maximumSize)
{
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || maximumSize < 2 || dims[0] > maximumSize ||
    dims[1] > maximumSize)
  {
    return false;
  }
  int tiles = 1, tilesX = 1, slices = std::max(dims[2] - 1, 1);
  if (dims[2] > maximumSize)
  {
    // Tiles of at most maximumSize slices, one shared with the next: the
    // fewest that cover nz, then as even as they can be (the last one
    // short), and the count again (an even split can need one fewer).
    const int gaps = dims[2] - 1;
    tiles = (gaps + maximumSize - 2) / (maximumSize - 1);
    slices = (gaps + tiles - 1) / tiles;
    tiles = (gaps + slices - 1) / slices;
    const int across = maximumSize / dims[0], down = maximumSize / dims[1];
    if (static_cast<long long>(across) * down < tiles)
    {
      return false;
    }
    tilesX = std::min(tiles, across);
  }
  const int rows = (tiles + tilesX - 1) / tilesX;
  std::copy(dims, dims + 3, this->Dimensions);
  this->Tiles = tiles;
  this->TilesX = tilesX;
  this->SlicesPerTile = slices;
  this->TextureDimensions[0] = tilesX * dims[0];
  this->TextureDimensions[1] = rows * dims[1];
  this->TextureDimensions[2] = tiles > 1 ? slices + 1 : dims[2];
  return true;
}

//------------------------------------------------------------------------------
double vtkTransmittanceVolumeTiling::GetOverhead() const
{
  const int* d = this->Dimensions;
  const int* t = this->TextureDimensions;
  return (static_cast<double>(t[0]) * t[1] * t[2]) / (static_cast<double>(d[0]) * d[1] * d[2]);
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeTiling::GetTile(int k, int& first, int& count, int origin[2]) const
{
  first = this->Tiles > 1 ? k * this->SlicesPerTile : 0;
  count = this->Tiles > 1 ? std::min(this->SlicesPerTile + 1, this->Dimensions[2] - first)
                          : this->Dimensions[2];
  origin[0] = (k % this->TilesX) * this->Dimensions[0];
  origin[1] = (k / this->TilesX) * this->Dimensions[1];
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeTiling::GetUniforms(
  float tiling[3], float dims[3], float textureDims[3]) const
{
  tiling[0] = static_cast<float>(this->TilesX);
  tiling[1] = static_cast<float>(this->SlicesPerTile);
  tiling[2] = static_cast<float>(this->Tiles);
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<float>(this->Dimensions[a]);
    textureDims[a] = static_cast<float>(this->TextureDimensions[a]);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeTiling::MapCoordinate(const double t[3], double texel[3]) const
{
  // As tyndallTiledTexel() (vtkTransmittanceCommonFS.glsl).
  double v[3];
  for (int a = 0; a < 3; ++a)
  {
    v[a] = std::min(std::max(t[a] * this->Dimensions[a] - 0.5, 0.0), this->Dimensions[a] - 1.0);
  }
  const double k = std::min(std::floor(v[2] / this->SlicesPerTile), this->Tiles - 1.0);
  const double row = std::floor(k / this->TilesX);
  const double origin[2] = { (k - row * this->TilesX) * this->Dimensions[0],
    row * this->Dimensions[1] };
  texel[0] = (origin[0] + v[0] + 0.5) / this->TextureDimensions[0];
  texel[1] = (origin[1] + v[1] + 0.5) / this->TextureDimensions[1];
  texel[2] = (v[2] - k * this->SlicesPerTile + 0.5) / this->TextureDimensions[2];
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeTiling::Upload(
  vtkTextureObject* texture, int components, int type, const void* values) const
{
  const int* dims = this->Dimensions;
  const int* size = this->TextureDimensions;
  if (!this->IsTiled())
  {
    return texture->Create3DFromRaw(
             dims[0], dims[1], dims[2], components, type, const_cast<void*>(values)) &&
      HoldsLevel(texture);
  }
  // The texture without data, then each tile's slices from the values'
  // own memory (a run of whole slices), and zeros where no tile's slice
  // is (a short last tile, empty places in the last row): a linear fetch
  // at a tile's clamped edge weighs those texels by 0, which must not be NaN.
  if (!texture->Create3DFromRaw(size[0], size[1], size[2], components, type, nullptr) ||
    !HoldsLevel(texture))
  {
    return false;
  }
  const size_t sliceBytes = static_cast<size_t>(dims[0]) * dims[1] * components *
    static_cast<size_t>(vtkDataArray::GetDataTypeSize(type));
  const GLenum format = texture->GetFormat(type, components, false);
  const GLenum dataType = texture->GetDataType(type);
  std::vector<char> zeros;
  try
  {
    zeros.resize(sliceBytes);
  }
  catch (const std::bad_alloc&)
  {
    return false;
  }
  texture->Bind();
  GLint alignment = 4;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
    // (errors raised before: not this upload's)
  }
  const int places = this->TilesX * (size[1] / dims[1]);
  for (int k = 0; k < places; ++k)
  {
    int first = 0, count = 0, origin[2];
    this->GetTile(k, first, count, origin);
    count = k < this->Tiles ? count : 0;
    if (count > 0)
    {
      glTexSubImage3D(GL_TEXTURE_3D, 0, origin[0], origin[1], 0, dims[0], dims[1], count, format,
        dataType, static_cast<const char*>(values) + first * sliceBytes);
    }
    for (int z = count; z < size[2]; ++z)
    {
      glTexSubImage3D(GL_TEXTURE_3D, 0, origin[0], origin[1], z, dims[0], dims[1], 1, format,
        dataType, zeros.data());
    }
  }
  const bool ok = glGetError() == GL_NO_ERROR;
  glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  return ok;
}
