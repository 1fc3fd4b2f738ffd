/**
 * @class   vtkTransmittanceDepthPass
 * @brief   the depth-capture pass of vtkTransmittanceVolumeMapper
 *
 * Copies the depth of the opaque geometry already drawn into a texture, so
 * that camera rays stop at it. The copy is a blit (the window's frame buffer
 * may be multisampled, which glCopyTexImage refuses) into a depth texture of
 * the window's depth format (a blit needs the same format on both sides).
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceDepthPass_h
#define vtkTransmittanceDepthPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

class vtkOpenGLFramebufferObject;
class vtkTextureObject;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceDepthPass : public vtkObject
{
public:
  static vtkTransmittanceDepthPass* New();
  vtkTypeMacro(vtkTransmittanceDepthPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Captures the window's depth buffer; false (with an error) on failure.
  bool Render(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  vtkTextureObject* GetTexture() const { return this->DepthTexture; }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceDepthPass();
  ~vtkTransmittanceDepthPass() override;

private:
  vtkTransmittanceDepthPass(const vtkTransmittanceDepthPass&) = delete;
  void operator=(const vtkTransmittanceDepthPass&) = delete;

  vtkSmartPointer<vtkTextureObject> DepthTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int DepthFormat = -1;
};

#endif
