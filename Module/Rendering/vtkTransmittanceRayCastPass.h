/**
 * @class   vtkTransmittanceRayCastPass
 * @brief   the camera-ray pass of vtkTransmittanceVolumeMapper
 *
 * One full-viewport quad (vtkTransmittanceRayCastFS.glsl): each pixel's ray
 * is marched through the medium's box up to the depth of opaque geometry,
 * integrating emission-absorption or single scattering with each light's
 * transmittance (maps, brute force or none, and the occlusion of opaque
 * geometry), and blended as premultiplied colour over what was drawn
 * (ONE, ONE_MINUS_SRC_ALPHA).
 *
 * Bounded work per fragment: Mesa's llvmpipe ends all loops of a shader
 * invocation after 65535 iterations in total, silently (a ray would stop
 * early), and other drivers reset a GPU whose shader runs too long. The
 * pass counts a camera step's loop iterations (the step, the light loop,
 * each brute-force light march of LightSampleCount / 8 iterations) and gives
 * each pass at most IterationBudget of them (an eighth of the limit, with a
 * margin for llvmpipe counting more than these trips): a ray that needs more is
 * marched over several passes (vtkTransmittanceAccumulationPass), each
 * continuing where the last stopped, so every step count gives the same
 * picture as an unbounded march. With one pass and no reduction the quad
 * draws straight into the window; one pass into an image (a reduced one,
 * a depth-peeling range: Inputs::DepthRanges) takes the same shader, which
 * discards the rays that miss, into a cleared image (the continuing
 * shader, which writes every pixel, ran 3 to 5 times slower on llvmpipe).
 *
 * With procedural detail and Inputs::DetailSamples > 0 the rays are not
 * marched: each pixel draws that many free-flight distances in closed form
 * (vtkTransmittanceDetailFS.glsl) and shades them, one pass; the pictures
 * of successive still frames are averaged by the accumulation pass
 * (Inputs::HistoryFrames, GetLastHistoryFrames(), which also picks each
 * frame's samples). The
 * samples are fewer when a pixel's loop iterations (a walk over the
 * shape's cells, each sample's solve and brute-force light walks) would
 * pass IterationBudget (GetLastDetailSamples()).
 *
 * Inputs::Reduction > 1 renders the rays at 1 / Reduction of the viewport's
 * width and height and upscales them, and Inputs::StepScale > 1 lengthens
 * the camera steps (interactive level of detail).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceRayCastPass_h
#define vtkTransmittanceRayCastPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"
#include "vtkTransmittanceAccumulationPass.h" // For vtkTransmittanceAccumulationPass
#include "vtkTransmittanceShaderQuad.h"       // For vtkTransmittanceShaderQuad
#include "vtkTransmittanceShaderSource.h"     // For vtkTransmittanceShaderSource::Variant

class vtkShaderProgram;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceRayCastPass : public vtkObject
{
public:
  static vtkTransmittanceRayCastPass* New();
  vtkTypeMacro(vtkTransmittanceRayCastPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What the ray cast reads besides the frame; null textures are unused.
  struct Inputs
  {
    vtkTextureObject* Depth = nullptr;
    vtkTextureObject* Maps = nullptr;
    int MapSlices = 1;
    vtkTextureObject* Cache = nullptr; // the transmittance cache: map lights read it, not Maps
    int CacheSize[3] = { 2, 2, 2 };
    int CacheLights = 1;
    vtkTextureObject* Occlusion = nullptr; // null: no opaque occluders
    int OcclusionSlices = 1;
    int Reduction = 1;      // rays at 1 / Reduction of the viewport's width and height
    double StepScale = 1.0; // camera steps StepScale times the frame's
    /// Procedural detail: free-flight samples per pixel drawn in closed form (0: march).
    int DetailSamples = 0;
    /// Frames already averaged into the history (DetailSamples > 0; 0: start
    /// anew); also the still frame's index, which picks its samples.
    int HistoryFrames = 0;
    /**
     * Drawn in a stage of VTK's depth peeling (vtkTransmittancePeelingPass):
     * Depth holds its depth ranges, Segment picks the part (0 front, 1
     * back), and the image is kept in GetImage(Segment), not composited.
     */
    bool DepthRanges = false;
    int Segment = 0;
    /// The image kept in GetImage(0), not composited (the path tracer's denoising guide).
    bool Offscreen = false;
    /// Whether the image is kept, not composited (Offscreen, or a depth-peeling part).
    bool KeepsImage() const { return this->Offscreen || this->DepthRanges; }
  };

  /**
   * Loop iterations (as counted by StepsPerPass()) one pass gives a
   * fragment. llvmpipe's own count runs higher than the loop trips counted
   * here: at 32768 a 256^3 cloud with 256 brute-force light samples was
   * still cut short (up to 54/255 in 2634 of 49152 values), at 16384 and
   * 8192 the pictures were identical. 8192 keeps a margin of 2.
   */
  static constexpr int IterationBudget = 8192;

  /// Draws the medium; false (with an error) when the shader does not compile.
  bool Render(const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

  /// Frees what a kept image does not need (vtkTransmittanceAccumulationPass::ReleaseScratch()).
  void ReleaseScratch(vtkWindow* window);

  /// Passes the last Render() split the rays over.
  int GetLastPassCount() const { return this->LastPassCount; }

  /// Free-flight samples per pixel the last Render() drew (0: it marched).
  int GetLastDetailSamples() const { return this->LastDetailSamples; }

  /**
   * Waves of procedural detail the last Render()'s camera samples evaluated
   * (those a pixel of the frame can show with the footprint filter; all
   * without it; 0 without detail).
   */
  int GetLastDetailCameraWaves() const { return this->LastDetailCameraWaves; }

  /**
   * The camera rays' step the last Render() marched with (world; 0 when it
   * drew free flights), and whether its samples of procedural detail stood
   * for the step's means of the waves (vtkTransmittanceFrame::
   * UsesDetailStepMeans()).
   */
  double GetLastStepLength() const { return this->LastStepLength; }
  bool GetLastDetailStepMeans() const { return this->LastDetailStepMeans; }

  /// Still frames averaged in the last Render()'s picture (0: no average kept).
  int GetLastHistoryFrames() const { return this->Accumulation[0]->GetHistoryFrames(); }

  /**
   * Composites the image the last Render() kept (Inputs::Offscreen) over
   * the viewport: the picture a Render() without Offscreen draws. False
   * (with an error) when there is none.
   */
  bool CompositeImage(const vtkTransmittanceFrame& frame, vtkObject* reporter)
  {
    return this->Accumulation[0]->CompositeResult(frame, reporter);
  }

  /// The image of the part `segment` (Inputs::DepthRanges) the last Render() of it drew.
  vtkTextureObject* GetImage(int segment) const
  {
    return this->Accumulation[segment == 1 ? 1 : 0]->GetResult();
  }

  /**
   * The free-flight samples per pixel a frame can draw when `requested` are
   * asked for: at most `requested`, fewer when the iterations would pass
   * IterationBudget; 0 when the frame has no procedural detail.
   */
  static int DetailSamplesFor(const vtkTransmittanceFrame& frame, int requested);

  /**
   * The loop iterations of one brute-force light march of the frame's
   * medium (LightSampleCount / 8 unrolled trips, or what the medium's
   * adapter says); the budgets of the march and of the path tracer count it.
   */
  static double LightMarchIterations(const vtkTransmittanceFrame& frame);

  /**
   * The camera rays' shader variant for `inputs` (the maps, cache and
   * occluders they read; the medium's colour switches, octaves, shading),
   * accumulating or not; the path tracer (vtkTransmittancePathTracePass)
   * takes it too.
   */
  static vtkTransmittanceShaderSource::Variant GetVariant(
    const vtkTransmittanceFrame& frame, const Inputs& inputs, bool accumulate);

  /**
   * Sets the camera rays' uniforms but the camera's and the step's: the
   * medium's, the maps' or cache's, the occluders', the integrator's and
   * the lights'. Not the sky's terms, which each integrator sets for
   * itself (vtkTransmittanceFrame::SetSkyUniforms()).
   */
  static void SetUniforms(
    const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkShaderProgram* program);

protected:
  vtkTransmittanceRayCastPass();
  ~vtkTransmittanceRayCastPass() override;

private:
  vtkTransmittanceRayCastPass(const vtkTransmittanceRayCastPass&) = delete;
  void operator=(const vtkTransmittanceRayCastPass&) = delete;

  static int StepsPerPass(const vtkTransmittanceFrame& frame);
  void DrawDirect(const vtkTransmittanceFrame& frame, vtkShaderProgram* program, int steps);

  vtkTransmittanceShaderQuad Quad;
  vtkNew<vtkTransmittanceAccumulationPass> Accumulation[2]; // the second: depth peeling's back part
  int LastPassCount = 0;
  int LastDetailSamples = 0;
  int LastDetailCameraWaves = 0;
  double LastStepLength = 0.0;
  bool LastDetailStepMeans = false;
};

#endif
