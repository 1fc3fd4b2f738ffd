/**
 * @class   vtkTransmittanceMapPass
 * @brief   the transmittance-map pass of vtkTransmittanceVolumeMapper
 *
 * Builds every light's transmittance map (vtkTransmittanceMapBuildFS.glsl):
 * one fragment per texel marches the texel's light ray through the medium
 * and projects it onto the TFM or ETM basis, in the layout of
 * vtkTransmittanceMapMath::GetNumberOfMapLayers() (all layers of all lights
 * are slices of one RGBA float 3-D texture). With a coloured extinction the
 * transmittance-function methods build three sets, one per channel (its
 * extinction scaled by the channel's ExtinctionColor component; set k's
 * slices after set k - 1's, vtkTransmittanceFrame::MapSets). Maps are
 * rebuilt only when something they depend on changed: the medium's scalars
 * or table, its density scale or placement, the lights (position,
 * direction, type, method), the integrator's method, coefficient count, map
 * size, light samples or adaptive threshold (adaptive methods), or (for per-channel sets) the
 * extinction colour, or (with guests, other media the light crosses) any
 * of the guests' extinction or placement. GetBuildCount() counts the builds.
 *
 * Particle media of the ETM method are not marched but splatted
 * (vtkTransmittanceSplatPass, after the march, additively).
 *
 * GetMap() reads a light's map (the first set) back to the CPU (for tests and inspection).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceMapPass_h
#define vtkTransmittanceMapPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTimeStamp.h"               // For vtkTimeStamp
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad
#include "vtkTransmittanceSplatPass.h"  // For vtkTransmittanceSplatPass

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;
class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkTransmittanceMapReducer;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceMapPass : public vtkObject
{
public:
  static vtkTransmittanceMapPass* New();
  vtkTypeMacro(vtkTransmittanceMapPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Builds the maps when the frame needs them and something changed.
   * Errors go through `reporter`; false on error. With several processes
   * (the frame's Integrator.Reducer) the processes agree whether any must
   * rebuild, and the rebuilt maps are the sum of every process's
   * (vtkTransmittanceMapReducer); with a reducer this is collective, so
   * every process calls it once per frame
   * (vtkTransmittanceVolumeMapper::PrepareDistributedMaps()).
   */
  bool Render(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  /**
   * A process with nothing to draw this frame takes part in the
   * reductions of Render() with zeros (collective). False on a
   * communication error.
   */
  bool SkipReduction(vtkTransmittanceMapReducer* reducer, vtkObject* reporter);

  /// The maps (null before the first build) and their number of slices.
  vtkTextureObject* GetTexture() const { return this->MapTexture; }
  int GetSlices() const { return this->Slices; }

  ///@{
  /// How many times the maps were built; the last build's seconds (after glFinish).
  int GetBuildCount() const { return this->BuildCount; }
  double GetLastBuildTime() const { return this->LastBuildTime; }
  ///@}

  /**
   * The last build, unique among every map pass's builds (0: none): what
   * was built from these maps (the transmittance cache) is current while
   * it is unchanged.
   */
  vtkMTimeType GetBuildSerial() const { return this->BuildCount ? this->BuildTime.GetMTime() : 0; }

  /**
   * Whether the maps hold what `frame` needs (built, for the same key). The
   * key sees the media as a set: a frame whose medium is one of another
   * frame's guests and whose guests are the rest (another Tyndall volume's
   * mapper in the same renderer, with the same settings and lights) reads
   * the same maps, so mappers share them instead of building copies.
   */
  bool IsBuiltFor(const vtkTransmittanceFrame& frame) const;

  /**
   * Copies light `light`'s map, as last built with `layers` layers per light
   * (`boundsLayer` the adaptive bounds' layer or -1) and `coefficients`
   * coefficients, into `map` (see vtkTransmittanceVolumeMapper::GetTransmittanceMap()).
   * The window's context must be current.
   */
  bool GetMap(int light, int layers, int boundsLayer, int coefficients, vtkImageData* map);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceMapPass();
  ~vtkTransmittanceMapPass() override;

private:
  vtkTransmittanceMapPass(const vtkTransmittanceMapPass&) = delete;
  void operator=(const vtkTransmittanceMapPass&) = delete;

  std::vector<double> Key(const vtkTransmittanceFrame& frame) const;
  bool Allocate(const vtkTransmittanceFrame& frame, vtkObject* reporter);
  vtkShaderProgram* ReadyProgram(const vtkTransmittanceFrame& frame);
  bool Build(const vtkTransmittanceFrame& frame, vtkObject* reporter);
  bool Agree(
    vtkTransmittanceMapReducer* reducer, bool& build, vtkIdType& count, vtkObject* reporter) const;
  bool Reduce(
    vtkTransmittanceMapReducer* reducer, bool built, vtkIdType count, vtkObject* reporter);
  // The whole map texture (4 x Size^2 x Slices floats, `values` sized so);
  // false on a GL error.
  bool ReadBack(std::vector<float>& values) const;

  vtkSmartPointer<vtkTextureObject> MapTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad Quad;
  vtkNew<vtkTransmittanceSplatPass> Splats;
  std::vector<double> BuiltKey;
  bool BuiltAdded = false; // the maps are the sum over the processes
  int Slices = 0;
  int Size = 0;
  int BuildCount = 0;
  vtkTimeStamp BuildTime;
  double LastBuildTime = 0.0;
};

#endif
