/**
 * @class   vtkTransmittanceLightCachePass
 * @brief   caches every map light's transmittance on a lattice over the camera rays' box
 *
 * After vtkTransmittanceMapPass, evaluates each map light's transmittance
 * (the same map lookup and reconstruction the camera rays would do per
 * sample, vtkTransmittanceCommonFS.glsl's tyndallMapTransmittance()) once
 * per texel of a lattice over the medium's box, into one half-float 3-D
 * texture (vtkTransmittanceLightCacheFS.glsl). The camera rays then read a
 * light's transmittance with one trilinear fetch (TYNDALL_LIGHT_CACHE)
 * instead of two or three map fetches, a ray-box intersection and a series
 * reconstruction per sample.
 *
 * The lattice spans the camera rays' box (vtkTransmittanceFrame::
 * CameraBoxToWorld: the medium's box, or the box around it and the guests
 * drawn with it). Its longest side has `size` texels (the frame's
 * Settings::CacheSize), the others in proportion to the box's world
 * extents, at least 2; its outer texels lie on the box's faces. The lights'
 * lattices are stacked along the third axis. The cache is rebuilt whenever
 * the maps are rebuilt or its size changes; GetBuildCount() counts the
 * builds. A cache over MaximumBytes or the driver's largest 3-D texture is
 * refused with an error, and the camera rays read the maps.
 *
 * With a coloured extinction the texels hold the three channels'
 * transmittances (an RGBA half-float texture, 8 bytes per texel and light,
 * rebuilt when the extinction colour changes): each channel stored, not
 * the densest one's to be raised to a power, which half floats near 0
 * could not carry.
 *
 * What it costs: one map lookup per texel and light when the maps change
 * (a 256^3 lattice is 16.8 million lookups), 2 bytes per texel and light;
 * and the picture differs from per-sample lookups by the trilinear
 * interpolation of the transmittance between texels (measured in
 * Documentation/benchmarks.md).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceLightCachePass_h
#define vtkTransmittanceLightCachePass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceLightCachePass : public vtkObject
{
public:
  static vtkTransmittanceLightCachePass* New();
  vtkTypeMacro(vtkTransmittanceLightCachePass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Fills the cache from `maps` (a map pass's texture, `mapSlices`
   * slices, its build `mapBuild`: vtkTransmittanceMapPass::GetBuildSerial())
   * when the frame asks for a cache and the maps or the size changed. Errors go through `reporter`;
   * false on error (the camera rays then read the maps).
   */
  bool Render(const vtkTransmittanceFrame& frame, vtkTextureObject* maps, int mapSlices,
    vtkMTimeType mapBuild, vtkObject* reporter);

  /// The cache (null before the first build or when the frame has none).
  vtkTextureObject* GetTexture() const { return this->CacheTexture; }
  /// Texels per axis of one light's lattice.
  const int* GetSize() const { return this->Size; }
  /// Lattices stacked in the texture.
  int GetLights() const { return this->Lights; }

  ///@{
  /// How many times the cache was built; the last build's seconds (after glFinish).
  int GetBuildCount() const { return this->BuildCount; }
  double GetLastBuildTime() const { return this->LastBuildTime; }
  ///@}

  /// The largest cache allocated (1 GiB); a larger one is an error.
  static constexpr double MaximumBytes = 1024.0 * 1024.0 * 1024.0;

  /// The lattice for a box with world edge lengths `extents` and longest side `size`.
  static void LatticeSize(const double extents[3], int size, int lattice[3]);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceLightCachePass();
  ~vtkTransmittanceLightCachePass() override;

private:
  vtkTransmittanceLightCachePass(const vtkTransmittanceLightCachePass&) = delete;
  void operator=(const vtkTransmittanceLightCachePass&) = delete;

  bool Allocate(const vtkTransmittanceFrame& frame, const int size[3], vtkObject* reporter);
  bool Build(
    const vtkTransmittanceFrame& frame, vtkTextureObject* maps, int mapSlices, vtkObject* reporter);

  vtkSmartPointer<vtkTextureObject> CacheTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad Quad;
  int Size[3] = { 0, 0, 0 };
  int Lights = 0;
  vtkMTimeType BuiltFromMaps = 0;      // the map build the cache holds; 0: none
  bool Chromatic = false;              // per-channel texels (RGBA)
  double Color[3] = { 1.0, 1.0, 1.0 }; // the extinction colour they were built for
  float BoxToWorld[16] = {};           // the camera box the lattice spans
  int BuildCount = 0;
  double LastBuildTime = 0.0;
};

#endif
