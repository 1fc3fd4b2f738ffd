/**
 * @class   vtkTransmittanceSplatPass
 * @brief   the particle splats of vtkTransmittanceMapPass: particles added to the extinction maps
 *
 * For each particle medium of the frame whose maps are splatted
 * (vtkTransmittanceFrame::Splats: the ETM method), draws every particle
 * into one light's map as an instanced square over its footprint
 * (vtkTransmittanceSplatVS.glsl), each covered texel adding the closed-form
 * cosine coefficients of the particle's extinction along its light ray
 * (vtkTransmittanceSplatFS.glsl), blended additively over what the map
 * pass's march wrote into the bound framebuffer. The particles live in one
 * vertex buffer per medium (5 floats each), uploaded when the particles
 * change.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceSplatPass_h
#define vtkTransmittanceSplatPass_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTransmittanceFrame;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceSplatPass : public vtkObject
{
public:
  static vtkTransmittanceSplatPass* New();
  vtkTypeMacro(vtkTransmittanceSplatPass, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Adds the frame's splats for light `light` to the bound framebuffer's
   * draw buffers (a map's layers, `outputs` the fragment shader's lines that
   * write them, vtkTransmittanceMapPass). Errors go through `reporter`;
   * false on error.
   */
  bool Render(
    const vtkTransmittanceFrame& frame, int light, const std::string& outputs, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceSplatPass();
  ~vtkTransmittanceSplatPass() override;

private:
  vtkTransmittanceSplatPass(const vtkTransmittanceSplatPass&) = delete;
  void operator=(const vtkTransmittanceSplatPass&) = delete;

  vtkShaderProgram* ReadyProgram(const vtkTransmittanceFrame& frame, const std::string& outputs);
  bool UploadBuffers(const vtkTransmittanceFrame& frame, vtkObject* reporter);

  // One medium's particles on the GPU, and the read they hold.
  struct Buffer
  {
    vtkSmartPointer<vtkOpenGLBufferObject> Object;
    vtkSmartPointer<vtkOpenGLVertexArrayObject> Array;
    vtkMTimeType ReadTime = 0;
    long long Count = 0;
  };
  std::vector<Buffer> Buffers;
  std::string VertexSource;
  std::string FragmentSource;
};

#endif
