/**
 * @class   vtkOfflineMediumRenderer
 * @brief   the base of Tyndall's CPU integrators: a scene in, a radiance and transmittance image
 * out
 *
 * What vtkSingleScatteringReference and vtkVolumetricPathTracer share: both
 * render one vtkVolume as seen by a vtkRenderer's active camera and lights
 * (read by Tyndall's scene reader, exactly as the GPU mapper reads it) into
 * an image of their own, on the CPU, in double precision and in parallel
 * (vtkSMPTools over rows, in batches). This class holds the frame around
 * an integrator: Render() times the render and fires StartEvent, EndEvent
 * and ProgressEvent (after each batch of rows, when AbortExecute is read),
 * GetOutput() is the last image (point-data arrays "Radiance", linear and
 * premultiplied, and "Transmittance", the view transmittance, 1 component
 * or 3 with a coloured extinction), and Composite() blends it over a
 * background like an 8-bit frame buffer.
 *
 * Bad input (a size outside [1, 16384], whatever the scene reader refuses, a
 * camera projection that cannot be inverted) is reported with vtkErrorMacro
 * and Render() returns nullptr; so does an aborted render, without an error.
 *
 * Not instantiated: create a vtkSingleScatteringReference or a
 * vtkVolumetricPathTracer.
 *
 * @sa vtkSingleScatteringReference vtkVolumetricPathTracer
 */

#ifndef vtkOfflineMediumRenderer_h
#define vtkOfflineMediumRenderer_h

#include "TyndallReferenceModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkRenderer;
class vtkTyndallSceneReader;
class vtkVolume;

class TYNDALLREFERENCE_EXPORT vtkOfflineMediumRenderer : public vtkObject
{
public:
  vtkTypeMacro(vtkOfflineMediumRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Renders `volume` as seen by `renderer`'s active camera and lights into a
   * width x height image (each in [1, 16384]). Returns the image, owned by
   * this object and valid until the next Render() (see the integrator's
   * description for its arrays), or nullptr on bad input (with an error) or
   * when aborted.
   */
  vtkImageData* Render(vtkRenderer* renderer, vtkVolume* volume, int width, int height);

  /**
   * The image of the last successful Render(); empty before one and after a
   * failed or aborted one.
   */
  vtkImageData* GetOutput();

  ///@{
  /**
   * Set to true (from a ProgressEvent observer, for example) to stop the
   * current render after the running batch of rows; Render() then returns
   * nullptr without an error. Reset to false when a render starts.
   */
  vtkSetMacro(AbortExecute, bool);
  vtkGetMacro(AbortExecute, bool);
  vtkBooleanMacro(AbortExecute, bool);
  ///@}

  ///@{
  /**
   * Composites the last render over a constant background colour (by default
   * the background of the renderer passed to the last Render()) and converts
   * it like an 8-bit frame buffer: each channel clamp(Radiance + T *
   * background, 0, 1), rounded to the nearest of 0..255. Returns a width x
   * height image with 3-component unsigned char scalars "RGB" (row 0 at the
   * bottom), owned by this object and valid until the next call of Render()
   * or Composite(); nullptr (with an error) when there is no render.
   */
  vtkImageData* Composite();
  vtkImageData* Composite(const double background[3]);
  ///@}

  /**
   * Progress of the current render, in [0, 1].
   */
  vtkGetMacro(Progress, double);

  ///@{
  /**
   * Facts about the last successful render: the renderer's background
   * colour and the wall-clock time in seconds.
   */
  vtkGetVector3Macro(LastBackground, double);
  vtkGetMacro(LastRenderTime, double);
  ///@}

protected:
  vtkOfflineMediumRenderer();
  ~vtkOfflineMediumRenderer() override;

  /**
   * The integrator: renders into Output (see
   * vtkTyndallReferenceScene::SetOutput()) after Render()'s events and
   * timing are set up; false on error (reported) or abort.
   */
  virtual bool RenderImage(vtkRenderer* renderer, vtkVolume* volume, int width, int height) = 0;

  /// Sets Progress and fires ProgressEvent (between batches of rows).
  void UpdateProgress(double progress);

  bool AbortExecute = false;
  double Progress = 0.0;
  double LastBackground[3] = { 0.0, 0.0, 0.0 };
  double LastRenderTime = 0.0;
  vtkImageData* Output = nullptr;
  vtkImageData* CompositeOutput = nullptr;
  /// The scene's reader, kept between renders (its media's caches).
  std::unique_ptr<vtkTyndallSceneReader> SceneReader;

private:
  vtkOfflineMediumRenderer(const vtkOfflineMediumRenderer&) = delete;
  void operator=(const vtkOfflineMediumRenderer&) = delete;
};

#endif
