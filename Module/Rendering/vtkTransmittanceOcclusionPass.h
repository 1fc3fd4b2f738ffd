/**
 * @class   vtkTransmittanceOcclusionPass
 * @brief   the light-space occlusion pass of vtkTransmittanceVolumeMapper
 *
 * Opaque actors block light entering the medium (the TFM paper's
 * light-space depth): each frame with visible opaque vtkActors, their depth
 * is rendered from every light's map frustum (a camera configured by
 * vtkTransmittanceLightFrustum::ConfigureCamera()) and converted by
 * vtkTransmittanceOcclusionFS.glsl into the distance along each map ray to
 * the first opaque surface, one slice per light of GetTexture(). Lights
 * without a frustum (inside the box) are not blocked.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceOcclusionPass_h
#define vtkTransmittanceOcclusionPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

#include <vector> // For std::vector

class vtkActor;
class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceOcclusionPass : public vtkObject
{
public:
  static vtkTransmittanceOcclusionPass* New();
  vtkTypeMacro(vtkTransmittanceOcclusionPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Renders the occluders of the frame's renderer from its lights. Returns
   * true when the ray cast must test occlusion (there are occluders and the
   * pass succeeded); errors go through `reporter`.
   */
  bool Render(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  /// Per light slice: distance along the map ray to the first opaque surface.
  vtkTextureObject* GetTexture() const { return this->OcclusionTexture; }
  int GetSlices() const { return this->Slices; }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceOcclusionPass();
  ~vtkTransmittanceOcclusionPass() override;

private:
  vtkTransmittanceOcclusionPass(const vtkTransmittanceOcclusionPass&) = delete;
  void operator=(const vtkTransmittanceOcclusionPass&) = delete;

  bool Allocate(const vtkTransmittanceFrame& frame);
  bool RenderLight(const vtkTransmittanceFrame& frame, int light, vtkObject* reporter);

  vtkSmartPointer<vtkTextureObject> OcclusionTexture;
  vtkSmartPointer<vtkTextureObject> LightDepthTexture;
  vtkSmartPointer<vtkTextureObject> LightColorTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTransmittanceShaderQuad Quad;
  std::vector<vtkActor*> Actors; // the occluders, during Render()
  int Slices = 0;
  int Size = 0;
};

#endif
