/**
 * @class   vtkTransmittancePeelingPass
 * @brief   draws the mapper's volume in VTK's dual depth peeling of volumes
 *
 * With a renderer's UseDepthPeeling and UseDepthPeelingForVolumes on and
 * translucent geometry in view, VTK 9.1 draws volumes inside its
 * vtkDualDepthPeelingPass, several times a frame, each time into the pass's
 * own targets and over the depth ranges between the geometry's peels. VTK's
 * own ray caster learns the stage from the pass's shader replacements; this
 * pass does the same for Tyndall's mapper in three steps, each a small
 * shader:
 *
 * 1. FindStage(): the pass among the volume's render passes and its stage
 *    (the samplers its replacements declare for a volume);
 * 2. RenderRanges(): per pixel, the window depths of the front and back
 *    parts of the ray in this stage (vtkTransmittancePeelRangesFS.glsl, VTK's
 *    rules), into a texture of the window's size that the camera rays read
 *    in place of the opaque depth (vtkTransmittanceRayCastPass::Inputs
 *    DepthRanges);
 * 3. Composite(): the two ray casts' images written to the pass's targets as
 *    VTK's ray caster writes them (vtkTransmittancePeelCompositeFS.glsl).
 *
 * The pass's textures reach both shaders through its SetShaderParameters().
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittancePeelingPass_h
#define vtkTransmittancePeelingPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

class vtkAbstractMapper;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderPass;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkVolume;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittancePeelingPass : public vtkObject
{
public:
  static vtkTransmittancePeelingPass* New();
  vtkTypeMacro(vtkTransmittancePeelingPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Not in a depth-peeling stage.
  static constexpr int NoStage = -1;
  /// In a depth-peeling pass whose stage is none of VTK 9.1's.
  static constexpr int UnknownStage = -2;

  /**
   * The depth-peeling pass drawing `volume` now (a vtkDualDepthPeelingPass
   * among its render passes, peeling volumes) and its stage (one of
   * vtkTransmittanceShaderSource::PeelStages); NoStage (and `pass` null)
   * when the volume is drawn outside one; UnknownStage (and `pass` set) when
   * the pass's replacements name none of the stages this class knows (a
   * later VTK's): the volume cannot be drawn there.
   */
  static int FindStage(vtkVolume* volume, vtkAbstractMapper* mapper, vtkOpenGLRenderPass*& pass);

  /**
   * Fills GetRanges() for `stage` of `pass`; false (with an error through
   * `reporter`) when its texture or framebuffer cannot be made.
   */
  bool RenderRanges(const vtkTransmittanceFrame& frame, vtkOpenGLRenderPass* pass, int stage,
    vtkAbstractMapper* mapper, vtkVolume* volume, vtkObject* reporter);

  /// The window-sized RGBA32F ranges: (start, end) of the front part, of the back part.
  vtkTextureObject* GetRanges() const { return this->Ranges; }

  /**
   * Writes the ray casts' images of the front and back ranges (`back` null in
   * the blending stage, which has one) to the pass's targets, bound now.
   * A pixel's opacity is raised to its radiance with `opacityCoversRadiance`
   * (an 8-bit compositor downstream, as vtkTransmittanceCompositeFS.glsl
   * does), else to at least 1/255 where it has radiance: the pass drops
   * the back peels' fragments whose 8-bit opacity is 0, and a medium's
   * emission with next to no extinction would be lost.
   */
  bool Composite(const vtkTransmittanceFrame& frame, vtkOpenGLRenderPass* pass, int stage,
    vtkTextureObject* front, vtkTextureObject* back, vtkAbstractMapper* mapper, vtkVolume* volume,
    bool opacityCoversRadiance, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittancePeelingPass();
  ~vtkTransmittancePeelingPass() override;

private:
  vtkTransmittancePeelingPass(const vtkTransmittancePeelingPass&) = delete;
  void operator=(const vtkTransmittancePeelingPass&) = delete;

  bool AllocateRanges(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  vtkSmartPointer<vtkTextureObject> Ranges;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad RangesQuad;
  vtkTransmittanceShaderQuad CompositeQuad;
};

#endif
