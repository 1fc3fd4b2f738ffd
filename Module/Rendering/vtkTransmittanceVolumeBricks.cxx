#include "vtkTransmittanceVolumeBricks.h"

#include "vtkTextureObject.h"
#include "vtkType.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <new>
#include <string>

namespace
{
constexpr int B = vtkTransmittanceVolumeBricks::BrickSize;
constexpr int Side = B + 1; // a slot's texels per side

// The sample index of a brick's local sample i along an axis of n samples
// (its apron past the volume's end repeats the last sample: clamp-to-edge).
inline int Sample(int brick, int i, int n)
{
  return std::min(brick * B + i, n - 1);
}

// Restores the GL's unpack alignment when it ends.
class ScopedUnpackAlignment
{
public:
  ScopedUnpackAlignment()
  {
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &this->Saved);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  ~ScopedUnpackAlignment() { glPixelStorei(GL_UNPACK_ALIGNMENT, this->Saved); }

private:
  GLint Saved = 4;
};
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeBricks::Clear()
{
  this->Bricked = false;
  this->Slots = 0;
  this->BrickSlot.clear();
  this->SlotBrick.clear();
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeBricks::Plan(const int dims[3], int components, int valueSize,
  const void* values, int maximumSize, double maximumShare)
{
  this->Clear();
  const int perAxis = std::min(maximumSize / Side, MaximumSlotsPerAxis);
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || components < 1 || valueSize < 1 || !values ||
    perAxis < 1)
  {
    return false;
  }
  std::copy(dims, dims + 3, this->Dimensions);
  this->Components = components;
  this->ValueSize = valueSize;
  size_t bricks = 1;
  for (int a = 0; a < 3; ++a)
  {
    this->BrickCounts[a] = std::max(1, (dims[a] - 1 + B - 1) / B);
    bricks *= static_cast<size_t>(this->BrickCounts[a]);
  }
  const size_t tuple = static_cast<size_t>(components) * valueSize;
  const auto* bytes = static_cast<const unsigned char*>(values);
  const auto at = [&](int x, int y, int z)
  { return bytes + ((static_cast<size_t>(z) * dims[1] + y) * dims[0] + x) * tuple; };
  try
  {
    this->BrickSlot.assign(bricks, -1);
  }
  catch (const std::bad_alloc&)
  {
    return false;
  }
  // Each brick's region (its samples and its +1 apron): constant when every
  // tuple there equals its first, byte for byte.
  std::map<std::string, int> constants; // a constant's bytes -> its slot
  const int* n = dims;
  const int* nb = this->BrickCounts;
  try
  {
    size_t b = 0;
    for (int bz = 0; bz < nb[2]; ++bz)
    {
      for (int by = 0; by < nb[1]; ++by)
      {
        for (int bx = 0; bx < nb[0]; ++bx, ++b)
        {
          const unsigned char* first =
            at(Sample(bx, 0, n[0]), Sample(by, 0, n[1]), Sample(bz, 0, n[2]));
          bool constant = true;
          for (int k = 0; constant && k < Side; ++k)
          {
            for (int j = 0; constant && j < Side; ++j)
            {
              const unsigned char* row = at(0, Sample(by, j, n[1]), Sample(bz, k, n[2]));
              for (int i = 0; constant && i < Side; ++i)
              {
                constant = std::memcmp(row + Sample(bx, i, n[0]) * tuple, first, tuple) == 0;
              }
            }
          }
          if (constant)
          {
            const std::string key(reinterpret_cast<const char*>(first), tuple);
            const auto found = constants.find(key);
            if (found != constants.end())
            {
              this->BrickSlot[b] = found->second;
              continue;
            }
            if (static_cast<int>(constants.size()) < MaximumConstants)
            {
              constants.emplace(key, this->Slots);
            }
          }
          this->BrickSlot[b] = this->Slots++;
          this->SlotBrick.push_back(static_cast<int>(b));
        }
      }
    }
  }
  catch (const std::bad_alloc&)
  {
    this->Clear();
    return false;
  }
  // The slots: rows of at most perAxis, the fewest layers of at most
  // perAxis rows, and in them the fewest rows (so the last layer is not
  // mostly empty: its unused slots count against the share).
  const long long slots = this->Slots, p = perAxis;
  const long long s0 = std::min(slots, p);
  const long long s2 = (slots + s0 * p - 1) / (s0 * p);
  const long long s1 = (slots + s0 * s2 - 1) / (s0 * s2);
  this->SlotCounts[0] = static_cast<int>(s0);
  this->SlotCounts[1] = static_cast<int>(std::min(s1, p));
  this->SlotCounts[2] = static_cast<int>(std::min(s2, p + 1)); // (p + 1: does not fit)
  for (int a = 0; a < 3; ++a)
  {
    this->AtlasDimensions[a] = this->SlotCounts[a] * Side;
  }
  this->Bricked = this->SlotCounts[2] <= perAxis &&
    static_cast<double>(this->GetAtlasBytes() + this->GetIndirectionBytes()) <=
      maximumShare * static_cast<double>(this->GetDenseBytes());
  if (!this->Bricked)
  {
    this->Clear();
  }
  return this->Bricked;
}

//------------------------------------------------------------------------------
size_t vtkTransmittanceVolumeBricks::GetAtlasBytes() const
{
  const int* a = this->AtlasDimensions;
  return static_cast<size_t>(a[0]) * a[1] * a[2] * this->Components * this->ValueSize;
}

//------------------------------------------------------------------------------
size_t vtkTransmittanceVolumeBricks::GetIndirectionBytes() const
{
  const int* nb = this->BrickCounts;
  return static_cast<size_t>(nb[0]) * nb[1] * nb[2] * 3; // RGB8
}

//------------------------------------------------------------------------------
size_t vtkTransmittanceVolumeBricks::GetDenseBytes() const
{
  const int* d = this->Dimensions;
  return static_cast<size_t>(d[0]) * d[1] * d[2] * this->Components * this->ValueSize;
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeBricks::GetUniforms(
  float dims[3], float brickCounts[3], float atlasDims[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = static_cast<float>(this->Dimensions[a]);
    brickCounts[a] = static_cast<float>(this->BrickCounts[a]);
    atlasDims[a] = static_cast<float>(this->AtlasDimensions[a]);
  }
}

//------------------------------------------------------------------------------
void vtkTransmittanceVolumeBricks::MapCoordinate(const double t[3], double texel[3]) const
{
  // As tyndallBrickedTexel() (vtkTransmittanceCommonFS.glsl).
  double v[3];
  int brick[3];
  for (int a = 0; a < 3; ++a)
  {
    v[a] = std::min(std::max(t[a] * this->Dimensions[a] - 0.5, 0.0), this->Dimensions[a] - 1.0);
    brick[a] = std::min(static_cast<int>(std::floor(v[a] / B)), this->BrickCounts[a] - 1);
  }
  const int* nb = this->BrickCounts;
  const int slot =
    this->BrickSlot[(static_cast<size_t>(brick[2]) * nb[1] + brick[1]) * nb[0] + brick[0]];
  const int* s = this->SlotCounts;
  const int origin[3] = { slot % s[0], (slot / s[0]) % s[1], slot / (s[0] * s[1]) };
  for (int a = 0; a < 3; ++a)
  {
    texel[a] = (origin[a] * Side + v[a] - brick[a] * B + 0.5) / this->AtlasDimensions[a];
  }
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeBricks::BuildAtlas(
  const void* values, std::vector<unsigned char>& atlas) const
{
  if (!this->Bricked)
  {
    return false;
  }
  const size_t tuple = static_cast<size_t>(this->Components) * this->ValueSize;
  try
  {
    atlas.assign(this->GetAtlasBytes(), 0); // unused slots: zeros, never read
  }
  catch (const std::bad_alloc&)
  {
    return false;
  }
  const int* n = this->Dimensions;
  const int* nb = this->BrickCounts;
  const int* s = this->SlotCounts;
  const int* a = this->AtlasDimensions;
  const auto* bytes = static_cast<const unsigned char*>(values);
  for (int slot = 0; slot < this->Slots; ++slot)
  {
    const int b = this->SlotBrick[slot];
    const int brick[3] = { b % nb[0], (b / nb[0]) % nb[1], b / (nb[0] * nb[1]) };
    const int origin[3] = { (slot % s[0]) * Side, ((slot / s[0]) % s[1]) * Side,
      (slot / (s[0] * s[1])) * Side };
    // Whole rows where the brick's apron lies inside the volume along x.
    const bool inside = brick[0] * B + B <= n[0] - 1;
    for (int k = 0; k < Side; ++k)
    {
      const int z = Sample(brick[2], k, n[2]);
      for (int j = 0; j < Side; ++j)
      {
        const int y = Sample(brick[1], j, n[1]);
        const unsigned char* row = bytes + (static_cast<size_t>(z) * n[1] + y) * n[0] * tuple;
        unsigned char* to = atlas.data() +
          ((static_cast<size_t>(origin[2] + k) * a[1] + origin[1] + j) * a[0] + origin[0]) * tuple;
        if (inside)
        {
          std::memcpy(to, row + static_cast<size_t>(brick[0]) * B * tuple, Side * tuple);
          continue;
        }
        for (int i = 0; i < Side; ++i)
        {
          std::memcpy(to + i * tuple, row + Sample(brick[0], i, n[0]) * tuple, tuple);
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceVolumeBricks::Upload(
  vtkTextureObject* atlas, vtkTextureObject* indirection, int type, const void* values) const
{
  std::vector<unsigned char> texels;
  std::vector<unsigned char> slots;
  if (!this->BuildAtlas(values, texels))
  {
    return false;
  }
  try
  {
    slots.resize(this->BrickSlot.size() * 3);
  }
  catch (const std::bad_alloc&)
  {
    return false;
  }
  const int* s = this->SlotCounts;
  for (size_t b = 0; b < this->BrickSlot.size(); ++b)
  {
    const int slot = this->BrickSlot[b];
    slots[3 * b] = static_cast<unsigned char>(slot % s[0]);
    slots[3 * b + 1] = static_cast<unsigned char>((slot / s[0]) % s[1]);
    slots[3 * b + 2] = static_cast<unsigned char>(slot / (s[0] * s[1]));
  }
  ScopedUnpackAlignment alignment;
  const int* a = this->AtlasDimensions;
  const int* nb = this->BrickCounts;
  return atlas->Create3DFromRaw(a[0], a[1], a[2], this->Components, type, texels.data()) &&
    indirection->Create3DFromRaw(nb[0], nb[1], nb[2], 3, VTK_UNSIGNED_CHAR, slots.data());
}
