/**
 * @class   vtkTransmittanceAccumulationPass
 * @brief   runs the camera-ray pass in pieces into an offscreen image, then draws it over the
 * window
 *
 * Two uses share it (vtkTransmittanceRayCastPass):
 * - a march split over several passes, each continuing the rays where the
 *   previous one stopped, so that no fragment runs more loop iterations than
 *   a driver allows (Mesa's llvmpipe ends a fragment's loops silently after
 *   65535 in all);
 * - a reduced image while the user interacts (interactive level of detail),
 *   upscaled with linear filtering.
 *
 * - a running average of still frames (progressive rendering: camera rays
 *   that draw random samples, vtkTransmittanceVolumeMapper's
 *   DetailSamplesPerPixel): with `historyFrames` >= 0 the passes' image is
 *   averaged into a third, persistent image holding the mean of the
 *   `historyFrames` frames before it (blended with constant alpha 1 / (n +
 *   1); 0 starts a new average), and that mean is what is drawn.
 *
 * Render() clears two RGBA32F images of the reduced size to 0 and calls
 * `draw(pass, previous, previousOpacity)` `passes` times, each drawing into
 * one image with the other bound as `previous` (the rays' state so far:
 * premultiplied radiance and 1 - transmittance); then it draws the last
 * image over the renderer's viewport in the framebuffer that was bound,
 * blended ONE, ONE_MINUS_SRC_ALPHA (vtkTransmittanceCompositeFS.glsl).
 *
 * With a coloured extinction (`chromatic`) each image has a second one
 * beside it, drawn as the second render target: 1 - the transmittance per
 * channel (`previousOpacity`). The result is then composited in two draws,
 * the window's colour multiplied by the transmittance (blended ZERO,
 * ONE_MINUS_SRC_COLOR), then the radiance added (ONE, ONE): radiance +
 * transmittance x background, per channel. A history then averages the
 * opacity images too (GetHistoryOpacity()), and the running average is
 * composited the same way.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceAccumulationPass_h
#define vtkTransmittanceAccumulationPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

#include <functional> // For std::function

class vtkOpenGLFramebufferObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceAccumulationPass : public vtkObject
{
public:
  static vtkTransmittanceAccumulationPass* New();
  vtkTypeMacro(vtkTransmittanceAccumulationPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Draws one pass into the bound image (and opacity image); `previous`
   * (and `previousOpacity`, else null) hold the passes before it.
   */
  using DrawFunction =
    std::function<void(int pass, vtkTextureObject* previous, vtkTextureObject* previousOpacity)>;

  /**
   * Runs `passes` passes into width x height images and composites the
   * result over `viewport` (x, y, width, height in window pixels); with
   * `historyFrames` >= 0 (0, or the last GetHistoryFrames(): the mean goes
   * on), composites the mean of the result and the `historyFrames` results
   * before it instead (a history of another size restarts at this frame),
   * each result weighed by its `samples` (the mean of every sample when each
   * result is the mean of its own). `chromatic`: the passes draw a second
   * image of per-channel opacity, averaged beside the first. With
   * `composite` false nothing is composited: the result is kept in
   * GetResult() (and the mean in GetHistory()). False (with an error through
   * `reporter`) when the images or their framebuffer cannot be made.
   */
  bool Render(const vtkTransmittanceFrame& frame, const int viewport[4], int width, int height,
    int passes, const DrawFunction& draw, vtkObject* reporter, int historyFrames = -1,
    bool chromatic = false, bool composite = true, int samples = 1);

  /**
   * The last Render()'s image (premultiplied radiance, alpha the opacity);
   * valid until the next Render().
   */
  vtkTextureObject* GetResult() const { return this->Result; }

  /**
   * Composites the last Render()'s result (with its opacity image, with a
   * coloured extinction) over the renderer's viewport, as Render() with
   * `composite` does: a result kept (`composite` false) and shown after all.
   * It must be the viewport's size. False (with an error through `reporter`)
   * when there is none or the compositing program does not compile.
   */
  bool CompositeResult(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  /// Frames in the running average after the last Render() (0: no history kept).
  int GetHistoryFrames() const { return this->HistoryFrames; }

  /// Their samples (Render()'s `samples` summed over them; 0: no history kept).
  int GetHistorySamples() const { return this->HistoryFrames > 0 ? this->HistorySamples : 0; }

  /**
   * Composites the running average as it stands over the renderer's
   * viewport, adding no frame (a progressive picture that has all the
   * samples it was asked for); its size must be the viewport's. False
   * (with an error through `reporter`) when there is no average or the
   * compositing program does not compile.
   */
  bool CompositeHistory(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  /**
   * Makes `image` a width x height RGBA32F image in the frame's window
   * (clamped to its edges), keeping the one it holds when it has that size
   * and context. False (with an error through `reporter`) when it cannot be
   * allocated (`image` then null).
   */
  static bool AllocateImage(const vtkTransmittanceFrame& frame,
    vtkSmartPointer<vtkTextureObject>& image, int width, int height, vtkObject* reporter);

  /**
   * Composites `image` (premultiplied radiance and opacity, the viewport's
   * size) over the renderer's viewport, as the running average is
   * (CompositeHistory()). False (with an error through `reporter`) when the
   * compositing program does not compile.
   */
  bool CompositeImage(
    const vtkTransmittanceFrame& frame, vtkTextureObject* image, vtkObject* reporter);

  /// The running average (null before the first Render() that keeps one).
  vtkTextureObject* GetHistory() const { return this->HistoryFrames > 0 ? this->History : nullptr; }

  /**
   * The running average of the opacity images (1 - the transmittance per
   * channel) beside GetHistory(), with a coloured extinction; else null.
   */
  vtkTextureObject* GetHistoryOpacity() const
  {
    return this->HistoryFrames > 0 ? this->HistoryOpacity : nullptr;
  }

  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Frees the images the last Render()'s result is not (the passes' other
   * image and its opacity): a kept result (Inputs::Offscreen) holds one
   * image, not two. The next Render() makes them again.
   */
  void ReleaseScratch(vtkWindow* window);

protected:
  vtkTransmittanceAccumulationPass();
  ~vtkTransmittanceAccumulationPass() override;

private:
  vtkTransmittanceAccumulationPass(const vtkTransmittanceAccumulationPass&) = delete;
  void operator=(const vtkTransmittanceAccumulationPass&) = delete;

  bool Allocate(
    const vtkTransmittanceFrame& frame, int width, int height, bool chromatic, vtkObject* reporter);
  /// Binds image `k` (and its opacity image) as the framebuffer's render targets; returns their
  /// count.
  int Attach(int k, bool chromatic);
  bool Composite(const vtkTransmittanceFrame& frame, vtkTextureObject* image,
    vtkTextureObject* opacity, bool upscaled, vtkObject* reporter);

  /// The texture-copy program, bound; nullptr (with an error) when it does not compile.
  vtkShaderProgram* CompositeProgram(const vtkTransmittanceFrame& frame, vtkObject* reporter);
  /// Adds `image` (and `opacity`, with a coloured extinction) of `samples` to the running average.
  bool AddToHistory(const vtkTransmittanceFrame& frame, vtkTextureObject* image,
    vtkTextureObject* opacity, int width, int height, int historyFrames, int samples,
    vtkObject* reporter);

  vtkSmartPointer<vtkTextureObject> Images[2];
  vtkSmartPointer<vtkTextureObject> Opacities[2]; // beside Images, with a coloured extinction
  vtkSmartPointer<vtkTextureObject> History;
  // Beside History while the mean is of a coloured extinction's frames, else null.
  vtkSmartPointer<vtkTextureObject> HistoryOpacity;
  int HistoryFrames = 0;
  int HistorySamples = 0;                    // the samples of the HistoryFrames
  vtkTextureObject* Result = nullptr;        // one of Images
  vtkTextureObject* ResultOpacity = nullptr; // beside Result, with a coloured extinction
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad Quad;
};

#endif
