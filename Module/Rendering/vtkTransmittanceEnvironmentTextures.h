/**
 * @class   vtkTransmittanceEnvironmentTextures
 * @brief   the renderer's sky on the GPU: vtkTyndallEnvironment's tables as textures
 *
 * Update() uploads the tables of a vtkTyndallEnvironment (its radiance,
 * RGB32F, W x H; the rows' cumulative probabilities, R32F, H x 1; each
 * row's columns', R32F, W x H; nearest, clamped) when they changed (its
 * GetSerial()) or the context did (a failed upload said once per sky and
 * context); SetUniforms() binds them for
 * vtkTransmittanceEnvironmentFS.glsl, which samples them as the CPU twin
 * does. Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceEnvironmentTextures_h
#define vtkTransmittanceEnvironmentTextures_h

#include "TyndallRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <vector> // For std::vector

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTyndallEnvironment;
class vtkWindow;

class TYNDALLRENDERING_EXPORT vtkTransmittanceEnvironmentTextures : public vtkObject
{
public:
  static vtkTransmittanceEnvironmentTextures* New();
  vtkTypeMacro(vtkTransmittanceEnvironmentTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Makes the textures hold `sky`'s tables in `window`. False (with an error
   * through `reporter`, once per sky and context) when a texture cannot be
   * made.
   */
  bool Update(const vtkTyndallEnvironment& sky, vtkOpenGLRenderWindow* window, vtkObject* reporter);

  /// The three textures, to activate before SetUniforms().
  std::vector<vtkTextureObject*> GetTextures() const;

  /// Sets the sky's uniforms (the textures activated) on `program`.
  void SetUniforms(const vtkTyndallEnvironment& sky, vtkShaderProgram* program) const;

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkTransmittanceEnvironmentTextures();
  ~vtkTransmittanceEnvironmentTextures() override;

private:
  vtkTransmittanceEnvironmentTextures(const vtkTransmittanceEnvironmentTextures&) = delete;
  void operator=(const vtkTransmittanceEnvironmentTextures&) = delete;

  vtkSmartPointer<vtkTextureObject> Radiance;
  vtkSmartPointer<vtkTextureObject> Rows;
  vtkSmartPointer<vtkTextureObject> Columns;
  vtkMTimeType UploadedSerial = 0; // the sky's serial the textures hold (0: none)
  vtkMTimeType FailedSerial = 0;   // the sky's serial whose upload failed (0: none)
  vtkWindow* FailedContext = nullptr;
};

#endif
