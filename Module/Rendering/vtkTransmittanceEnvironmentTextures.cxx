#include "vtkTransmittanceEnvironmentTextures.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransmittanceOffscreenDraw.h"
#include "vtkTyndallEnvironment.h"

vtkStandardNewMacro(vtkTransmittanceEnvironmentTextures);

namespace
{
// Makes `texture` a width x height nearest, clamped texture of `data`.
bool Upload(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window, int width,
  int height, int components, const float* data)
{
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTransmittanceOffscreenDraw::SetClamped(texture, window, false);
  return texture->Create2DFromRaw(width, height, components, VTK_FLOAT, const_cast<float*>(data));
}
}

//------------------------------------------------------------------------------
vtkTransmittanceEnvironmentTextures::vtkTransmittanceEnvironmentTextures() = default;
vtkTransmittanceEnvironmentTextures::~vtkTransmittanceEnvironmentTextures() = default;

//------------------------------------------------------------------------------
bool vtkTransmittanceEnvironmentTextures::Update(
  const vtkTyndallEnvironment& sky, vtkOpenGLRenderWindow* window, vtkObject* reporter)
{
  if (this->UploadedSerial != 0 && this->UploadedSerial == sky.GetSerial() && this->Radiance &&
    this->Radiance->GetContext() == window)
  {
    return true;
  }
  const bool failedBefore = this->FailedSerial == sky.GetSerial() && this->FailedContext == window;
  this->UploadedSerial = 0;
  const int W = sky.GetWidth();
  const int H = sky.GetHeight();
  if (failedBefore || !Upload(this->Radiance, window, W, H, 3, sky.GetRadiance().data()) ||
    !Upload(this->Rows, window, H, 1, 1, sky.GetRowTable().data()) ||
    !Upload(this->Columns, window, W, H, 1, sky.GetColumnTable().data()))
  {
    if (!failedBefore) // said once per sky and context
    {
      vtkErrorWithObjectMacro(
        reporter, << "Could not make the textures of the renderer's environment (" << W << " x "
                  << H << "): the paths are not traced under it.");
    }
    this->FailedSerial = sky.GetSerial();
    this->FailedContext = window;
    return false;
  }
  this->UploadedSerial = sky.GetSerial();
  return true;
}

//------------------------------------------------------------------------------
std::vector<vtkTextureObject*> vtkTransmittanceEnvironmentTextures::GetTextures() const
{
  return { this->Radiance, this->Rows, this->Columns };
}

//------------------------------------------------------------------------------
void vtkTransmittanceEnvironmentTextures::SetUniforms(
  const vtkTyndallEnvironment& sky, vtkShaderProgram* program) const
{
  program->SetUniformi("skyRadianceTexture", this->Radiance->GetTextureUnit());
  program->SetUniformi("skyRowTexture", this->Rows->GetTextureUnit());
  program->SetUniformi("skyColumnTexture", this->Columns->GetTextureUnit());
  const int size[2] = { sky.GetWidth(), sky.GetHeight() };
  program->SetUniform2i("skySize", size);
  program->SetUniformf("skyTotal", static_cast<float>(sky.GetTotal()));
  float frame[3][3];
  for (int c = 0; c < 3; ++c)
  {
    frame[0][c] = static_cast<float>(sky.GetUp()[c]);
    frame[1][c] = static_cast<float>(sky.GetRight()[c]);
    frame[2][c] = static_cast<float>(sky.GetFront()[c]);
  }
  program->SetUniform3f("skyUp", frame[0]);
  program->SetUniform3f("skyRight", frame[1]);
  program->SetUniform3f("skyFront", frame[2]);
}

//------------------------------------------------------------------------------
void vtkTransmittanceEnvironmentTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkSmartPointer<vtkTextureObject>* texture :
    { &this->Radiance, &this->Rows, &this->Columns })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
    }
    *texture = nullptr;
  }
  this->UploadedSerial = 0;
  this->FailedSerial = 0;
  this->FailedContext = nullptr;
}

//------------------------------------------------------------------------------
void vtkTransmittanceEnvironmentTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UploadedSerial: " << this->UploadedSerial << "\n";
}
