/**
 * @class   vtkTransmittanceDenoisePass
 * @brief   the path-traced picture's denoiser on the GPU
 *
 * Filter() runs vtkTyndallDenoiser's edge-avoiding a-trous filter
 * (vtkTransmittanceDenoiseFS.glsl, one full-screen quad per pass, two
 * RGBA32F images in turn) on the running mean of the paths, with the
 * map-based frame as the noise-free guide: guide + A(mean - guide). The
 * result is an image the compositor draws in place of the mean
 * (vtkTransmittancePathTracePass). vtkTyndallDenoiser, its CPU twin,
 * describes the filter; the tests compare the two.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceDenoisePass_h
#define vtkTransmittanceDenoisePass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceDenoisePass : public vtkObject
{
public:
  static vtkTransmittanceDenoisePass* New();
  vtkTypeMacro(vtkTransmittanceDenoisePass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The denoised picture of `mean` guided by `guide` (the same size):
   * `iterations` passes (in [1, vtkTyndallDenoiser::MaximumIterations]) at
   * `edgeStop`. Valid until the next Filter(); nullptr (with an error
   * through `reporter`) when the sizes differ, the images cannot be made or
   * the shader does not compile.
   */
  vtkTextureObject* Filter(const vtkTransmittanceFrame& frame, vtkTextureObject* mean,
    vtkTextureObject* guide, int iterations, double edgeStop, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceDenoisePass();
  ~vtkTransmittanceDenoisePass() override;

private:
  vtkTransmittanceDenoisePass(const vtkTransmittanceDenoisePass&) = delete;
  void operator=(const vtkTransmittanceDenoisePass&) = delete;

  vtkSmartPointer<vtkTextureObject> Images[2];
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad Quad;
};

#endif
