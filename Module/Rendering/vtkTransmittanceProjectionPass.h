/**
 * @class   vtkTransmittanceProjectionPass
 * @brief   the camera-ray pass of a volume drawn in one of VTK's projection blend modes
 *
 * One full-viewport quad (vtkTransmittanceProjectionFS.glsl): each pixel's
 * ray gathers the maximum, minimum, average or additive projection of the
 * volume's scalars up to the depth of opaque geometry, as
 * vtkTyndallProjection describes, and is blended as premultiplied colour
 * over what was drawn (ONE, ONE_MINUS_SRC_ALPHA). The step is the mapper's
 * SampleDistance, or VTK's automatic one (the volume's smallest world
 * spacing: a projection needs no finer one), the samples at the steps
 * ends as VTK places them (the mapper's Jitter does not apply). No map or
 * accumulation image is involved (a shaded slice reads the lights,
 * unshadowed: vtkTransmittanceLightsFS.glsl): a step is one loop trip, and a ray takes
 * at most MaximumSteps of them (Mesa's llvmpipe ends a fragment's loops
 * after 65535 iterations in all, silently); a ray that would need more takes
 * longer steps, with a warning.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceProjectionPass_h
#define vtkTransmittanceProjectionPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"
#include "vtkTransmittanceAccumulationPass.h" // For vtkTransmittanceAccumulationPass
#include "vtkTransmittanceShaderQuad.h"       // For vtkTransmittanceShaderQuad

class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceProjectionPass : public vtkObject
{
public:
  static vtkTransmittanceProjectionPass* New();
  vtkTypeMacro(vtkTransmittanceProjectionPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The most steps one ray takes (half llvmpipe's loop limit).
  static constexpr int MaximumSteps = 32768;

  /**
   * Draws the frame's volume (its grid medium's projection must be
   * Enabled()) in front of the opaque geometry whose depth `depth` holds;
   * false (with an error through `reporter`) when the shader does not compile.
   * With `segment` 0 or 1, `depth` holds a depth-peeling stage's ranges
   * (vtkTransmittancePeelingPass) and the part `segment` names is projected
   * into GetImage(segment) instead of over the picture.
   */
  bool Render(const vtkTransmittanceFrame& frame, vtkTextureObject* depth, vtkObject* reporter,
    int segment = -1);

  /// The image of the part `segment` the last Render() of it drew.
  vtkTextureObject* GetImage(int segment) const
  {
    return this->Offscreen[segment == 1 ? 1 : 0]->GetResult();
  }

  void ReleaseGraphicsResources(vtkWindow* window);

  /// The step the last Render() took (world units).
  double GetLastStepLength() const { return this->LastStepLength; }

protected:
  vtkTransmittanceProjectionPass();
  ~vtkTransmittanceProjectionPass() override;

private:
  vtkTransmittanceProjectionPass(const vtkTransmittanceProjectionPass&) = delete;
  void operator=(const vtkTransmittanceProjectionPass&) = delete;

  void SetUniforms(const vtkTransmittanceFrame& frame, vtkShaderProgram* program) const;

  vtkTransmittanceShaderQuad Quad;
  vtkNew<vtkTransmittanceAccumulationPass> Offscreen[2]; // depth peeling's parts
  double LastStepLength = 0.0;
  bool WarnedLongSteps = false;
};

#endif
