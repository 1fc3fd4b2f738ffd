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
 * Mesa's llvmpipe stops all loops of a shader invocation after 65535
 * iterations in total, silently: a ray would end early. The pass warns once
 * when a frame can get there.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceRayCastPass_h
#define vtkTransmittanceRayCastPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkTransmittanceShaderQuad.h" // For vtkTransmittanceShaderQuad

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
    vtkTextureObject* Occlusion = nullptr; // null: no opaque occluders
    int OcclusionSlices = 1;
  };

  /// Draws the medium; false (with an error) when the shader does not compile.
  bool Render(const vtkTransmittanceFrame& frame, const Inputs& inputs, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceRayCastPass();
  ~vtkTransmittanceRayCastPass() override;

private:
  vtkTransmittanceRayCastPass(const vtkTransmittanceRayCastPass&) = delete;
  void operator=(const vtkTransmittanceRayCastPass&) = delete;

  void SetLightUniforms(const vtkTransmittanceFrame& frame, vtkShaderProgram* program) const;
  void WarnAboutLoopLimit(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  vtkTransmittanceShaderQuad Quad;
  int SoftwareRenderer = -1; // llvmpipe: 1, other: 0, unknown: -1
  bool WarnedLoopLimit = false;
};

#endif
