#include "vtkTransmittanceMediumTextures.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkTyndallGridMedium.h"
#include "vtkTypeTraits.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkTransmittanceMediumTextures);

namespace
{
// The cleaned scalars (every component) at every `factor`-th sample, as
// floats, and where `valid` is given, 0 for a NaN component (which becomes
// its range's minimum) and for a masked sample
// (vtkTyndallGridMedium::GetMask()), 255 elsewhere.
template <typename T>
void Gather(const vtkTyndallGridMedium& medium, const T* data, int components, int factor,
  const int dims[3], float* out, unsigned char* valid)
{
  const int* full = medium.GetDimensions();
  const bool floating = std::numeric_limits<T>::has_quiet_NaN;
  const unsigned char* mask = medium.GetMask().empty() ? nullptr : medium.GetMask().data();
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      const vtkIdType row =
        (static_cast<vtkIdType>(z) * factor * full[1] + static_cast<vtkIdType>(y) * factor) *
        full[0];
      for (int x = 0; x < dims[0]; ++x, ++i)
      {
        const vtkIdType index = row + static_cast<vtkIdType>(x) * factor;
        bool missing = false;
        for (int c = 0; c < components; ++c)
        {
          const double v = static_cast<double>(data[index * components + c]);
          const bool nan = std::isnan(v);
          missing = missing || nan;
          out[i * components + c] = static_cast<float>(
            nan ? medium.GetComponentRange(c)[0] : (floating ? medium.Clean(v, c) : v));
        }
        if (valid)
        {
          valid[i] = missing || (mask && !mask[index]) ? 0 : 255;
        }
      }
    }
  }
}

// Whether the GL holds `texture`'s level 0 at its size: a driver out of
// memory may refuse a large texture without raising an error (Mesa's
// llvmpipe left a 4 GiB volume texture empty, and the picture black).
bool Allocated(vtkTextureObject* texture)
{
  texture->Activate();
  GLint width = 0;
  glGetTexLevelParameteriv(texture->GetTarget(), 0, GL_TEXTURE_WIDTH, &width);
  texture->Deactivate();
  return width == static_cast<GLint>(texture->GetWidth());
}

// Whether the scalars reach the GPU read in place at every sample (no copy
// of the volume first): 8- and 16-bit integers (UploadStored()), and float
// scalars that need no cleaning (UploadFloats()).
bool UploadsInPlace(const vtkTyndallGridMedium& medium)
{
  switch (medium.GetScalars()->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_SHORT:
    case VTK_SHORT:
      return !medium.HasMissingData();
    case VTK_FLOAT:
      return !medium.HasMissingData() && medium.GetNumberOfInfiniteValues() == 0;
    default:
      return false;
  }
}

// 2nd, 3rd, 4th, 11th, 21st ...
std::string Ordinal(int n)
{
  const int tens = n % 100, ones = n % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
    : ones == 1                                   ? "st"
    : ones == 2                                   ? "nd"
    : ones == 3                                   ? "rd"
                                                  : "th";
  return std::to_string(n) + suffix;
}

// What the GL says of its free memory, where it says (NVIDIA's and AMD's
// extensions; Mesa's llvmpipe says nothing: its textures are in the
// process's memory).
std::string FreeMemoryNote()
{
  GLint kib[4] = { 0, 0, 0, 0 };
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  if (glewIsSupported("GL_NVX_gpu_memory_info"))
  {
    glGetIntegerv(0x9049, kib); // GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
  }
  else if (glewIsSupported("GL_ATI_meminfo"))
  {
    glGetIntegerv(0x87FC, kib); // GL_TEXTURE_FREE_MEMORY_ATI: total free, largest block, ...
  }
  const bool said = glGetError() == GL_NO_ERROR && kib[0] > 0;
  std::ostringstream note;
  if (said)
  {
    note << " (the GPU has " << kib[0] / 1024 << " MiB free)";
  }
  return note.str();
}

// The type the volume texture holds for scalars of `type`: 8- and 16-bit
// integers their own (char as the signed or unsigned char it is here),
// every other type floats.
int StoredType(int type)
{
  switch (type)
  {
    case VTK_UNSIGNED_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_SHORT:
    case VTK_SHORT:
      return type;
    case VTK_CHAR:
      return std::numeric_limits<char>::is_signed ? VTK_SIGNED_CHAR : VTK_UNSIGNED_CHAR;
    default:
      return VTK_FLOAT;
  }
}

// Releases `texture`'s graphics resources and drops it.
void Release(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
  }
  texture = nullptr;
}

// Every `factor`-th sample of `values` (`components` per sample, `full`
// samples per axis) into `out` (`dims` samples per axis).
template <typename T>
void EveryFactorth(
  const T* values, int components, int factor, const int full[3], const int dims[3], T* out)
{
  size_t i = 0;
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const size_t from =
          (static_cast<size_t>(z) * factor * full[1] + static_cast<size_t>(y) * factor) * full[0] +
          static_cast<size_t>(x) * factor;
        for (int c = 0; c < components; ++c)
        {
          out[i++] = values[components * from + c];
        }
      }
    }
  }
}
}

//------------------------------------------------------------------------------
vtkTransmittanceMediumTextures::vtkTransmittanceMediumTextures() = default;
vtkTransmittanceMediumTextures::~vtkTransmittanceMediumTextures() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::Update(vtkOpenGLRenderWindow* window,
  const vtkTyndallGridMedium& medium, const Extras& extras, vtkObject* reporter)
{
  // What keeps the scalars dense (another texture at their resolution):
  // a change of it uploads them again.
  const bool blocked = !medium.GetLabelMap().GetLabels().empty() ||
    !medium.GetEmissionValues().empty() || medium.HasMissingData() || extras.Scattering;
  const bool sameMedium = this->UploadedMedium == &medium && this->VolumeTexture &&
    this->VolumeTexture->GetContext() == window &&
    this->UploadedMaximumSize == this->MaximumTextureSize &&
    this->UploadedBricking == this->Bricking && this->UploadedBlocked == blocked;
  const bool newScalars = !sameMedium || medium.GetScalarsTime() > this->ScalarsTime;
  if (newScalars)
  {
    // A volume that failed after its copy and plan (too large dense, no
    // bricks it could take) is not copied and planned again until something
    // changes; each render still says so.
    const bool failedBefore = this->FailedMedium == &medium &&
      this->FailedScalarsTime == medium.GetScalarsTime() &&
      this->FailedBricking == this->Bricking &&
      this->FailedMaximumSize == this->MaximumTextureSize && this->FailedBlocked == blocked;
    this->ScalarsTime = 0;
    this->UploadedBlocked = blocked;
    if (failedBefore)
    {
      vtkErrorWithObjectMacro(reporter, << "The volume fits the GPU neither whole nor as bricks "
                                           "(said when it was first uploaded); not drawn.");
      return false;
    }
    if (!this->UploadScalars(window, medium, reporter))
    {
      if (!this->DenseFits &&
        ((this->BricksAllowed && this->Bricking != BRICKING_OFF) || this->WideBricksTried))
      {
        this->FailedMedium = &medium;
        this->FailedScalarsTime = medium.GetScalarsTime();
        this->FailedBricking = this->Bricking;
        this->FailedMaximumSize = this->MaximumTextureSize;
        this->FailedBlocked = blocked;
      }
      return false;
    }
    this->FailedMedium = nullptr;
    this->ScalarsTime = medium.GetScalarsTime();
    this->UploadedMaximumSize = this->MaximumTextureSize;
    this->UploadedBricking = this->Bricking;
  }
  // The scalars' interpolation (vtkTyndallGridMedium::GetNearest()): the
  // volume's and its validity's filter, sent when the textures are bound.
  const int filter = medium.GetNearest() ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
  for (vtkTextureObject* texture : { this->VolumeTexture.Get(), this->ValidityTexture.Get() })
  {
    if (texture)
    {
      texture->SetMinificationFilter(filter);
      texture->SetMagnificationFilter(filter);
    }
  }
  if (newScalars && !this->UploadLabels(window, medium, reporter))
  {
    this->ScalarsTime = 0;
    return false;
  }
  // A coloured particle cloud's scattering grid changes with its scalars.
  if (newScalars || (extras.Scattering != nullptr) != (this->ScatteringTexture != nullptr))
  {
    if (!this->UploadScattering(window, medium, extras.Scattering, reporter))
    {
      this->ScalarsTime = 0;
      return false;
    }
  }
  // The emission array: its own upload, at the scalars' sampling (Factor).
  if (newScalars || medium.GetEmissionTime() > this->EmissionTime)
  {
    this->EmissionTime = 0;
    if (!this->UploadEmission(window, medium, reporter))
    {
      return false;
    }
    this->EmissionTime = medium.GetEmissionTime();
  }
  if (!sameMedium || medium.GetTableTime() > this->TableTime || newScalars)
  {
    this->TableTime = 0;
    this->BlockRangeTime = newScalars ? this->BlockRangeTime : 0.0;
    if (!this->UploadTable(window, medium, reporter) ||
      !this->UploadMajorants(window, medium, reporter))
    {
      return false;
    }
    this->TableTime = medium.GetTableTime();
  }
  // What a map build sees of this medium: its scalars, its extinction (the
  // table's, not its colours) and its clipping (the medium's extinction time).
  if (newScalars || medium.GetExtinctionTime() != this->SeenExtinctionTime)
  {
    this->SeenExtinctionTime = medium.GetExtinctionTime();
    this->ExtinctionContentTime.Modified();
  }
  this->UploadedMedium = &medium;
  if (!this->UpdateDetail(window, extras.Detail, reporter))
  {
    return false;
  }

  // The box as [0, 1]^3 -> texture coordinates: field index p = low + q (high
  // - low), texture sample p / factor, texel centre (p / factor + 0.5) / n.
  for (int a = 0; a < 3; ++a)
  {
    const double low = medium.GetBoxLow()[a], high = medium.GetBoxHigh()[a];
    const double n = this->Dimensions[a];
    this->TextureScale[a] = static_cast<float>((high - low) / (this->Factor * n));
    this->TextureShift[a] = static_cast<float>((low / this->Factor + 0.5) / n);
    // Sample coordinate v = texture coordinate * n - 0.5; block = v / BlockSize.
    const double perBlock = 1.0 / vtkTyndallMajorantGrid::BlockSize;
    this->BlockScale[a] = static_cast<float>((high - low) / this->Factor * perBlock);
    this->BlockShift[a] = static_cast<float>(low / this->Factor * perBlock);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadScalars(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  const int* full = medium.GetDimensions();
  int maxSize = vtkTextureObject::GetMaximumTextureSize3D(window);
  maxSize = maxSize > 0 ? maxSize : 2048; // (a GL that does not say: its minimum is 256)
  if (this->MaximumTextureSize > 0)
  {
    maxSize = std::min(maxSize, std::max(this->MaximumTextureSize, 2));
  }
  // Every sample in tiles of slices where the slices pass the limit
  // (vtkTransmittanceVolumeTiling); else every factor-th sample, the
  // smallest factor that fits.
  // (It ends: at the largest side's factor the volume is 1 x 1 x 1.)
  int factor = 1;
  for (;; ++factor)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Dimensions[a] = (full[a] - 1) / factor + 1;
    }
    if (this->Tiling.Plan(this->Dimensions, maxSize))
    {
      break;
    }
  }
  this->UploadSize = maxSize;
  this->WideBricks = false;
  this->WideBricksTried = false;
  std::string bricksFailed;
  if (factor > 1 && this->Bricking != BRICKING_OFF && !this->UploadedBlocked &&
    UploadsInPlace(medium))
  {
    // Wider or taller than the limit: every sample as bricks where their
    // atlas fits (it holds the bricks in any arrangement; scalars read in
    // place, no copy of the whole volume first); where it does not, or the
    // GL cannot make it, every factor-th sample and the warning, which says
    // why (an error here would go with a picture).
    std::copy(full, full + 3, this->Dimensions);
    this->Tiling.Plan(full, std::max({ full[0], full[1], full[2], maxSize }));
    this->Factor = 1;
    this->BricksAllowed = true;
    this->WideBricks = true;
    this->WideBricksTried = true;
    this->DenseFits = false;
    this->Bricks.Clear();
    vtkNew<vtkObject> quiet;
    vtkNew<vtkTyndallErrorObserver> swallowed;
    swallowed->Watch(quiet);
    if (this->UploadValues(window, medium, quiet))
    {
      return true;
    }
    bricksFailed = swallowed->HasErrors() ? "; as bricks: " + swallowed->GetMessages()[0]
                                          : "; its bricks do not fit either";
    this->WideBricks = false;
    for (int a = 0; a < 3; ++a)
    {
      this->Dimensions[a] = (full[a] - 1) / factor + 1;
    }
    this->Tiling.Plan(this->Dimensions, maxSize);
  }
  this->Factor = factor;
  // Bricks (vtkTransmittanceVolumeBricks) replace the scalars' texture
  // alone: not where another texture shares its layout.
  this->BricksAllowed = factor == 1 && !this->Tiling.IsTiled() && !this->UploadedBlocked;
  this->Bricks.Clear(); // (until this upload plans them)
  if (factor > 1)
  {
    vtkWarningWithObjectMacro(reporter, << "The volume (" << full[0] << " x " << full[1] << " x "
                                        << full[2] << ") exceeds the GPU's 3-D texture size "
                                        << maxSize << " (a side of " << maxSize
                                        << " or less across, slices in tiles" << bricksFailed
                                        << "); rendering every " << Ordinal(factor) << " sample.");
  }
  vtkDataArray* scalars = medium.GetScalars();
  // Asked of the GL before any copy or pass over the data: a volume the
  // GPU cannot hold fails at once (a 1024^3 volume: before any copy or
  // plan), unless it may go as bricks (then planned over the values).
  const bool bricks = this->BricksAllowed && this->Bricking != BRICKING_OFF;
  this->DenseFits = this->VolumeFits(window, scalars->GetNumberOfComponents(),
    StoredType(scalars->GetDataType()), bricks ? nullptr : reporter);
  if (!this->DenseFits && !bricks)
  {
    return false;
  }
  return this->UploadValues(window, medium, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadValues(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  vtkDataArray* scalars = medium.GetScalars();
  const void* data = scalars->GetVoidPointer(0);
  switch (scalars->GetDataType())
  {
    case VTK_UNSIGNED_CHAR:
      return this->UploadStored(window, medium, static_cast<const unsigned char*>(data), reporter);
    case VTK_CHAR: // the signed or unsigned char it is here
      if (std::numeric_limits<char>::is_signed)
      {
        return this->UploadStored(window, medium, static_cast<const signed char*>(data), reporter);
      }
      return this->UploadStored(window, medium, static_cast<const unsigned char*>(data), reporter);
    case VTK_SIGNED_CHAR:
      return this->UploadStored(window, medium, static_cast<const signed char*>(data), reporter);
    case VTK_UNSIGNED_SHORT:
      return this->UploadStored(window, medium, static_cast<const unsigned short*>(data), reporter);
    case VTK_SHORT:
      return this->UploadStored(window, medium, static_cast<const short*>(data), reporter);
    default:
      return this->UploadFloats(window, medium, reporter);
  }
}

//------------------------------------------------------------------------------
template <typename T>
bool vtkTransmittanceMediumTextures::UploadStored(vtkOpenGLRenderWindow* window,
  const vtkTyndallGridMedium& medium, const T* data, vtkObject* reporter)
{
  // A normalized texture of T (GL_R8, GL_R8_SNORM, GL_R16, GL_R16_SNORM, as
  // VTK's mapper stores them) that the GPU reads as c / max(T), clamped to
  // -1 (so the lowest signed value reads as -max(T)); the value is the
  // texel times max(T), a product alone (no added term a compiler could
  // fuse into it and round otherwise).
  const int components = medium.GetScalars()->GetNumberOfComponents();
  const size_t count =
    static_cast<size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  const bool masked = !medium.GetMask().empty(); // integers hold no NaN
  std::vector<T> sampled;
  std::vector<unsigned char> valid;
  const bool copy = this->Factor > 1;
  try
  {
    sampled.resize(copy ? count * components : 0);
    valid.resize(masked ? count : 0);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot allocate "
                                      << (copy ? count * components * sizeof(T) : 0) + valid.size()
                                      << " bytes for the volume's textures.");
    return false;
  }
  if (copy)
  {
    EveryFactorth(
      data, components, this->Factor, medium.GetDimensions(), this->Dimensions, sampled.data());
  }
  const T* values = copy ? sampled.data() : data;
  if (masked)
  {
    const unsigned char* mask = medium.GetMask().data();
    EveryFactorth(mask, 1, this->Factor, medium.GetDimensions(), this->Dimensions, valid.data());
    for (unsigned char& v : valid)
    {
      v = v ? 255 : 0;
    }
  }
  this->BlockRangeTime = this->Majorants.BuildRanges(
    values, components, masked ? valid.data() : nullptr, this->Dimensions);
  this->ValueMap[0] = static_cast<float>(std::numeric_limits<T>::max());
  this->ValueMap[1] = 0.0f;
  return this->CreateVolumeTexture(window, components, vtkTypeTraits<T>::VTKTypeID(),
    const_cast<T*>(values), masked ? valid.data() : nullptr, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadFloats(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  const size_t count =
    static_cast<size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  const bool missing = medium.HasMissingData(); // NaN scalars or a mask
  vtkDataArray* scalars = medium.GetScalars();
  const int components = scalars->GetNumberOfComponents();
  if (scalars->GetDataType() == VTK_FLOAT && this->Factor == 1 && !missing &&
    medium.GetNumberOfInfiniteValues() == 0)
  {
    // Every sample finite, so within its component's finite range: the
    // cleaned copy would be the scalars themselves (a 1024^3 volume's 4 GiB
    // copy not made; the bricks and the texture read the array).
    const float* data = static_cast<const float*>(scalars->GetVoidPointer(0));
    this->BlockRangeTime = this->Majorants.BuildRanges(data, components, nullptr, this->Dimensions);
    this->ValueMap[0] = 1.0f;
    this->ValueMap[1] = 0.0f;
    return this->CreateVolumeTexture(
      window, components, VTK_FLOAT, const_cast<float*>(data), nullptr, reporter);
  }
  std::vector<float> values;
  std::vector<unsigned char> valid;
  try
  {
    values.resize(count * components);
    valid.resize(missing ? count : 0);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot allocate " << count << " floats for the volume.");
    return false;
  }
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(Gather(medium, static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)),
      components, this->Factor, this->Dimensions, values.data(), missing ? valid.data() : nullptr));
  }
  this->BlockRangeTime = this->Majorants.BuildRanges(
    values.data(), components, missing ? valid.data() : nullptr, this->Dimensions);
  this->ValueMap[0] = 1.0f;
  this->ValueMap[1] = 0.0f;
  return this->CreateVolumeTexture(
    window, components, VTK_FLOAT, values.data(), missing ? valid.data() : nullptr, reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::VolumeFits(
  vtkOpenGLRenderWindow* window, int components, int type, vtkObject* reporter)
{
  const int* dims = this->Tiling.GetTextureDimensions();
  vtkNew<vtkTextureObject> probe; // only for the GL's names of the format
  probe->SetContext(window);
  vtkOpenGLClearErrorMacro();
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0,
    static_cast<GLint>(probe->GetDefaultInternalFormat(type, components, false)), dims[0], dims[1],
    dims[2], 0, probe->GetDefaultFormat(type, components, false), probe->GetDefaultDataType(type),
    nullptr);
  GLint width = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &width);
  vtkOpenGLClearErrorMacro();
  if (width == dims[0])
  {
    return true;
  }
  if (reporter)
  {
    this->ReportTooLarge(components, type, " (asked before uploading it)", reporter);
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMediumTextures::ReportTooLarge(
  int components, int type, const char* when, vtkObject* reporter) const
{
  const int* dims = this->Tiling.GetTextureDimensions();
  const double mib = static_cast<double>(dims[0]) * dims[1] * dims[2] * components *
    vtkDataArray::GetDataTypeSize(type) / (1024.0 * 1024.0);
  std::ostringstream tiles;
  if (this->Tiling.IsTiled())
  {
    const int* volume = this->Tiling.GetDimensions();
    tiles << "; the " << volume[0] << " x " << volume[1] << " x " << volume[2] << " samples in "
          << this->Tiling.GetTiles() << " tiles of slices";
  }
  vtkErrorWithObjectMacro(
    reporter, << "The GPU could not create the volume's 3-D texture (" << dims[0] << " x "
              << dims[1] << " x " << dims[2] << tiles.str() << ", " << components << " x "
              << vtkImageScalarTypeNameMacro(type) << ", " << mib << " MiB" << when
              << "): too large for its memory" << FreeMemoryNote() << ", or a format it lacks.");
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::CreateVolumeTexture(vtkOpenGLRenderWindow* window,
  int components, int type, void* values, unsigned char* valid, vtkObject* reporter)
{
  const int* dims = this->Dimensions;
  if (!this->VolumeTexture)
  {
    this->VolumeTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->VolumeTexture, window, true);
  // The format of these scalars (vtkTextureObject keeps the last upload's
  // format and type otherwise: another type's data read as the old one).
  this->VolumeTexture->ResetFormatAndType();
  // (Bricks whatever they save where the dense texture does not fit.)
  // (Wider than the limit, WideBricks: the bricks whatever they take.)
  const double share = this->WideBricks
    ? VTK_DOUBLE_MAX
    : (this->Bricking == BRICKING_ON || !this->DenseFits ? 1.0 : 0.5);
  if (!valid && this->BricksAllowed && this->Bricking != BRICKING_OFF &&
    this->Bricks.Plan(this->Dimensions, components, vtkDataArray::GetDataTypeSize(type), values,
      this->UploadSize, share))
  {
    Release(this->ValidityTexture, window);
    return this->UploadBricks(window, components, type, values, reporter);
  }
  this->Bricks.Clear();
  if (this->WideBricks)
  {
    return false; // (UploadScalars() samples it then)
  }
  if (!this->DenseFits)
  {
    this->ReportTooLarge(
      components, type, " (asked before uploading it; no bricks it could take)", reporter);
    Release(this->BrickTexture, window);
    Release(this->ValidityTexture, window);
    Release(this->VolumeTexture, window);
    return false;
  }
  Release(this->BrickTexture, window);
  if (!this->Tiling.Upload(this->VolumeTexture, components, type, values) ||
    !Allocated(this->VolumeTexture))
  {
    this->ReportTooLarge(components, type, "", reporter);
    Release(this->VolumeTexture, window);
    return false;
  }
  if (!valid)
  {
    Release(this->ValidityTexture, window);
    return true;
  }
  if (!this->ValidityTexture)
  {
    this->ValidityTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->ValidityTexture, window, true);
  if (!this->Tiling.Upload(this->ValidityTexture, 1, VTK_UNSIGNED_CHAR, valid) ||
    !Allocated(this->ValidityTexture))
  {
    vtkErrorWithObjectMacro(reporter, << "The GPU could not create the volume's validity texture ("
                                      << dims[0] << " x " << dims[1] << " x " << dims[2]
                                      << " bytes).");
    Release(this->ValidityTexture, window);
    Release(this->VolumeTexture, window);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadBricks(
  vtkOpenGLRenderWindow* window, int components, int type, void* values, vtkObject* reporter)
{
  if (!this->BrickTexture)
  {
    this->BrickTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->BrickTexture, window, false); // read nearest
  this->BrickTexture->ResetFormatAndType();
  if (!this->Bricks.Upload(this->VolumeTexture, this->BrickTexture, type, values) ||
    !Allocated(this->VolumeTexture) || !Allocated(this->BrickTexture))
  {
    const int* atlas = this->Bricks.GetAtlasDimensions();
    vtkErrorWithObjectMacro(
      reporter, << "The GPU could not create the volume's bricks (an atlas of " << atlas[0] << " x "
                << atlas[1] << " x " << atlas[2] << ", " << components << " x "
                << vtkImageScalarTypeNameMacro(type) << ")" << FreeMemoryNote() << ".");
    this->Bricks.Clear();
    Release(this->BrickTexture, window);
    Release(this->VolumeTexture, window);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
size_t vtkTransmittanceMediumTextures::GetVolumeTextureBytes() const
{
  if (!this->VolumeTexture)
  {
    return 0;
  }
  if (this->Bricks.IsBricked())
  {
    return this->Bricks.GetAtlasBytes() + this->Bricks.GetIndirectionBytes();
  }
  const int* dims = this->Tiling.GetTextureDimensions();
  return static_cast<size_t>(dims[0]) * dims[1] * dims[2] * this->VolumeTexture->GetComponents() *
    static_cast<size_t>(vtkDataArray::GetDataTypeSize(this->VolumeTexture->GetVTKDataType()));
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadEmission(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  const std::vector<float>& emission = medium.GetEmissionValues();
  if (emission.empty())
  {
    Release(this->EmissionTexture, window);
    return true;
  }
  return this->UploadSampled(
    window, medium, emission.data(), 1, this->EmissionTexture, "emission array", reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadScattering(vtkOpenGLRenderWindow* window,
  const vtkTyndallGridMedium& medium, const float* scattering, vtkObject* reporter)
{
  if (!scattering)
  {
    Release(this->ScatteringTexture, window);
    return true;
  }
  return this->UploadSampled(
    window, medium, scattering, 3, this->ScatteringTexture, "particles' colour", reporter);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadSampled(vtkOpenGLRenderWindow* window,
  const vtkTyndallGridMedium& medium, const float* values, int components,
  vtkSmartPointer<vtkTextureObject>& texture, const char* what, vtkObject* reporter)
{
  // Every Factor-th sample, as the scalars (all of them: no copy).
  const int* full = medium.GetDimensions();
  const int* dims = this->Dimensions;
  std::vector<float> sampled;
  try
  {
    sampled.resize(
      this->Factor > 1 ? static_cast<size_t>(dims[0]) * dims[1] * dims[2] * components : 0);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot allocate the " << what << "'s texture.");
    return false;
  }
  if (this->Factor > 1)
  {
    EveryFactorth(values, components, this->Factor, full, dims, sampled.data());
  }
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(texture, window, true);
  if (!this->Tiling.Upload(texture, components, VTK_FLOAT,
        this->Factor > 1 ? static_cast<const float*>(sampled.data()) : values))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the " << what << "'s 3-D texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadTable(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  std::vector<float> rgba;
  medium.GetTable().GetTexture(rgba);
  if (!this->TransferTexture)
  {
    this->TransferTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->TransferTexture, window, true);
  if (!this->TransferTexture->Create2DFromRaw(
        vtkTyndallTransferTable::Size, vtkTyndallTransferTable::Rows, 4, VTK_FLOAT, rgba.data()))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the transfer-function texture.");
    return false;
  }
  if (!this->UploadComponentTables(window, medium, reporter) ||
    !this->UploadLabelRows(window, medium, reporter))
  {
    return false;
  }
  const vtkTyndallTransferTable& table = medium.GetTable();
  if (!table.Has2D())
  {
    Release(this->Transfer2DTexture, window);
    return true;
  }
  if (!this->Transfer2DTexture)
  {
    this->Transfer2DTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  // Linear between pixel centres (nearest with the nearest interpolation),
  // clamped at the edges (VTK's lookup).
  vtkTransmittanceOffscreenDraw::SetClamped(
    this->Transfer2DTexture, window, !table.Transfer2DNearest);
  if (!this->Transfer2DTexture->Create2DFromRaw(table.Transfer2DSize[0], table.Transfer2DSize[1], 4,
        VTK_FLOAT, const_cast<float*>(table.Transfer2D.data())))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the 2-D transfer-function texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadLabels(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  // With the scalars (a new mask re-reads them): the labels of every
  // Factor-th sample, one byte each (label / 255 in the shader), read nearest.
  const std::vector<unsigned char>& labels = medium.GetLabelMap().GetLabels();
  if (labels.empty())
  {
    Release(this->LabelTexture, window);
    return true;
  }
  const int* full = medium.GetDimensions();
  const int* dims = this->Dimensions;
  std::vector<unsigned char> sampled;
  try
  {
    sampled.resize(this->Factor > 1 ? static_cast<size_t>(dims[0]) * dims[1] * dims[2] : 0);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot allocate the label map's texture.");
    return false;
  }
  if (this->Factor > 1)
  {
    EveryFactorth(labels.data(), 1, this->Factor, full, dims, sampled.data());
  }
  if (!this->LabelTexture)
  {
    this->LabelTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->LabelTexture, window, false);
  if (!this->Tiling.Upload(this->LabelTexture, 1, VTK_UNSIGNED_CHAR,
        this->Factor > 1 ? sampled.data() : labels.data()))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the label map's 3-D texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadLabelRows(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  const vtkTyndallLabelMap& labels = medium.GetLabelMap();
  if (!labels.Enabled())
  {
    Release(this->LabelRowsTexture, window);
    return true;
  }
  if (!this->LabelRowsTexture)
  {
    this->LabelRowsTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->LabelRowsTexture, window, false);
  if (!this->LabelRowsTexture->Create2DFromRaw(vtkTyndallLabelMap::Width, labels.GetRowCount() + 1,
        4, VTK_FLOAT, const_cast<float*>(labels.GetRows().data())))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the label map's transfer texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadComponentTables(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  // Tables 1 .. of several components (vtkTyndallComponents): two rows
  // each, its albedo row (colour, extinction) and its emission row
  // (emission, the opacity function: what the projections read), as
  // tyndallComponentRow() reads them.
  const int tables = medium.GetComponents().GetTableCount();
  if (tables < 2)
  {
    Release(this->ComponentTexture, window);
    return true;
  }
  std::vector<float> rows, table;
  const size_t width = 4 * static_cast<size_t>(vtkTyndallTransferTable::Size);
  for (int t = 1; t < tables; ++t)
  {
    medium.GetComponentTable(t).GetTexture(table);
    for (const int r : { vtkTyndallTransferTable::AlbedoRow, vtkTyndallTransferTable::EmissionRow })
    {
      const auto row = table.begin() + width * r;
      rows.insert(rows.end(), row, row + width);
    }
  }
  if (!this->ComponentTexture)
  {
    this->ComponentTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(this->ComponentTexture, window, true);
  if (!this->ComponentTexture->Create2DFromRaw(
        vtkTyndallTransferTable::Size, 2 * (tables - 1), 4, VTK_FLOAT, rows.data()))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the components' transfer texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UploadMajorants(
  vtkOpenGLRenderWindow* window, const vtkTyndallGridMedium& medium, vtkObject* reporter)
{
  const vtkTyndallComponents& components = medium.GetComponents();
  const vtkTyndallTransferTable* tables[vtkTyndallComponents::MaximumCount] = {};
  for (int t = 0; t < components.GetTableCount(); ++t)
  {
    tables[t] = &medium.GetMajorantTable(t);
  }
  this->MajorantTime = this->Majorants.BuildMajorants(tables, components);
  if (!this->BlockTexture)
  {
    this->BlockTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* texture = this->BlockTexture;
  vtkTransmittanceOffscreenDraw::SetClamped(texture, window, false);
  const int* counts = this->Majorants.GetBlockCounts();
  if (!texture->Create3DFromRaw(counts[0], counts[1], counts[2], 1, VTK_FLOAT,
        const_cast<float*>(this->Majorants.GetMajorants().data())))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the volume's majorant texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceMediumTextures::UpdateDetail(
  vtkOpenGLRenderWindow* window, const vtkTyndallDetailMedium* detailOrNull, vtkObject* reporter)
{
  if (!detailOrNull || !detailOrNull->Enabled())
  {
    if (this->DetailTexture)
    {
      this->DetailTexture->ReleaseGraphicsResources(window);
      this->ExtinctionContentTime.Modified(); // the maps lose the detail
    }
    this->DetailTexture = nullptr;
    this->DetailExtinctionTime = 0;
    return true;
  }
  const vtkTyndallDetailMedium& detail = *detailOrNull;
  // The maps see the detail's extinction (its shape and waves; not the
  // footprint filter, which only camera samples take).
  if (detail.GetExtinctionTime() != this->DetailExtinctionTime)
  {
    this->DetailExtinctionTime = detail.GetExtinctionTime();
    this->ExtinctionContentTime.Modified();
  }
  if (this->DetailTexture && this->DetailTexture->GetContext() == window &&
    detail.GetTime() <= this->DetailTime)
  {
    return true;
  }
  if (!this->DetailTexture)
  {
    this->DetailTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->DetailTime = 0;
  vtkTransmittanceOffscreenDraw::SetClamped(this->DetailTexture, window, true);
  const int* n = detail.GetDimensions();
  const int maxSize = vtkTextureObject::GetMaximumTextureSize3D(window);
  if (maxSize > 0 && std::max(n[0], std::max(n[1], n[2])) > maxSize)
  {
    // (The shape is evaluated at the grid's samples; it is not tiled.)
    vtkErrorWithObjectMacro(reporter, << "Procedural detail over a volume past one 3-D texture ("
                                      << n[0] << " x " << n[1] << " x " << n[2] << ", limit "
                                      << maxSize << " per side) is not supported.");
    this->DetailTexture = nullptr;
    return false;
  }
  if (!this->DetailTexture->Create3DFromRaw(
        n[0], n[1], n[2], 1, VTK_FLOAT, const_cast<float*>(detail.GetShape().data())))
  {
    vtkErrorWithObjectMacro(reporter, << "Could not create the procedural detail's " << n[0] << "x"
                                      << n[1] << "x" << n[2] << " shape texture.");
    this->DetailTexture = nullptr;
    return false;
  }
  this->DetailTime = detail.GetTime();
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMediumTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkTextureObject* texture :
    { this->VolumeTexture.Get(), this->ValidityTexture.Get(), this->TransferTexture.Get(),
      this->Transfer2DTexture.Get(), this->BlockTexture.Get(), this->ComponentTexture.Get(),
      this->DetailTexture.Get(), this->EmissionTexture.Get(), this->ScatteringTexture.Get(),
      this->LabelTexture.Get(), this->LabelRowsTexture.Get(), this->BrickTexture.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  this->BrickTexture = nullptr;
  this->Bricks.Clear();
  this->FailedMedium = nullptr;
  this->VolumeTexture = nullptr;
  this->ValidityTexture = nullptr;
  this->TransferTexture = nullptr;
  this->Transfer2DTexture = nullptr;
  this->ComponentTexture = nullptr;
  this->LabelTexture = nullptr;
  this->LabelRowsTexture = nullptr;
  this->BlockTexture = nullptr;
  this->DetailTexture = nullptr;
  this->EmissionTexture = nullptr;
  this->ScatteringTexture = nullptr;
  this->DetailTime = 0;
  this->UploadedMedium = nullptr;
  this->ScalarsTime = this->TableTime = this->EmissionTime = 0;
}

//------------------------------------------------------------------------------
void vtkTransmittanceMediumTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Dimensions: " << this->Dimensions[0] << " x " << this->Dimensions[1] << " x "
     << this->Dimensions[2] << "\n";
  os << indent << "Downsampling: " << this->Factor << "\n";
  os << indent << "MaximumTextureSize: " << this->MaximumTextureSize << "\n";
  os << indent << "Bricking: " << this->Bricking << " (bricked: " << this->Bricks.IsBricked()
     << ", " << this->Bricks.GetSlots() << " slots)\n";
  os << indent << "Tiles: " << this->Tiling.GetTiles() << " (" << this->Tiling.GetTilesX()
     << " across, " << this->Tiling.GetSlicesPerTile() << " slices apart)\n";
  const int* blocks = this->Majorants.GetBlockCounts();
  os << indent << "Blocks: " << blocks[0] << " x " << blocks[1] << " x " << blocks[2] << " ("
     << 100.0 * this->Majorants.GetEmptyFraction() << " % empty)\n";
  os << indent << "BlockRangeTime: " << this->BlockRangeTime << " s\n";
  os << indent << "MajorantTime: " << this->MajorantTime << " s\n";
}
