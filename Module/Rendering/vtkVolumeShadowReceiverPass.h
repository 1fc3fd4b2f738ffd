/**
 * @class   vtkVolumeShadowReceiverPass
 * @brief   opaque surfaces receive the soft shadow of a participating medium
 *
 * vtkVolumeShadowReceiverPass wraps the pass that draws the opaque geometry
 * (its DelegatePass, e.g. vtkRenderStepsPass's opaque step) so that actors
 * drawn by VTK's own polydata mappers show the shadow of the renderer's
 * medium: a cloud's shadow on the terrain, a smoke plume's on the floor, a
 * CT's soft shadow on a segmented surface.
 *
 * Before the opaque geometry is drawn it brings the transmittance maps of the
 * caster, the renderer's first visible volume drawn by
 * vtkTransmittanceVolumeMapper, up to date
 * (vtkTransmittanceVolumeMapper::UpdateShadowMaps(): the volume's own render
 * later in the frame reuses them). While its delegate draws, it extends the
 * fragment shader of every actor through vtkOpenGLRenderPass's shader hooks
 * (the mechanism vtkShadowMapPass uses; it works with the stock
 * vtkOpenGLPolyDataMapper): each light's diffuse and specular terms are
 * multiplied by the medium's transmittance T_l(x) from the surface point x
 * to that light, read from the same maps the medium is lit with
 * (vtkTransmittanceLightMapFS.glsl; per channel for a coloured extinction).
 * The actors' own lighting, materials and textures are otherwise unchanged.
 *
 * Rules (Documentation/rendering-model.md, "Opaque surfaces in the medium's
 * shadow"): only lights with a map cast the shadow (not with the None or
 * BruteForce methods, nor a light inside the volume's box); a surface point
 * outside a light's map frustum, or between the light and the medium, gets
 * T = 1; actors with lighting off are drawn as they are; ambient light is not
 * shadowed (as in VTK). One caster: with several Tyndall volumes the first
 * casts (a warning says so once). Opaque geometry does not shadow opaque
 * geometry here (vtkShadowMapPass does that).
 *
 * Use Install() on a renderer, or build the pass chain yourself:
 * @code
 * vtkNew<vtkVolumeShadowReceiverPass> shadows;
 * shadows->Install(renderer); // vtkRenderStepsPass with this as its opaque step
 * @endcode
 *
 * vtkSingleScatteringReference::ComputeLightTransmittance() gives the CPU
 * reference's transmittance at any point, which the tests compare with what
 * the surfaces receive.
 *
 * @sa vtkTransmittanceVolumeMapper vtkShadowMapPass vtkRenderStepsPass
 */

#ifndef vtkVolumeShadowReceiverPass_h
#define vtkVolumeShadowReceiverPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkOpenGLRenderPass.h"

#include <memory> // For std::unique_ptr

class vtkRenderer;
class vtkVolume;

class TYNDALLRENDERING_EXPORT vtkVolumeShadowReceiverPass : public vtkOpenGLRenderPass
{
public:
  static vtkVolumeShadowReceiverPass* New();
  vtkTypeMacro(vtkVolumeShadowReceiverPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that draws the opaque geometry (default none: then nothing is
   * drawn, and an error says so).
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  /**
   * Makes `renderer` draw with this pass: a renderer without a pass gets a
   * vtkRenderStepsPass (VTK's usual steps: camera, lights, opaque,
   * translucent, volumes, overlay) whose opaque step this pass wraps; a
   * renderer that already draws with a vtkRenderStepsPass has its opaque
   * step wrapped. False (with an error) for a null renderer or another kind
   * of pass.
   */
  bool Install(vtkRenderer* renderer);

  /**
   * The volume whose shadow the last Render() cast on the surfaces (nullptr:
   * none, e.g. no Tyndall volume or no light with a map).
   */
  vtkVolume* GetLastCaster();

  ///@{
  /**
   * vtkRenderPass and vtkOpenGLRenderPass hooks (called by the renderer and
   * the polydata mappers).
   */
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}

protected:
  vtkVolumeShadowReceiverPass();
  ~vtkVolumeShadowReceiverPass() override;

  vtkRenderPass* DelegatePass = nullptr;

private:
  vtkVolumeShadowReceiverPass(const vtkVolumeShadowReceiverPass&) = delete;
  void operator=(const vtkVolumeShadowReceiverPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
