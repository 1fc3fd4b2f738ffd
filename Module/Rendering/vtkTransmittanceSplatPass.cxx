#include "vtkTransmittanceSplatPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTransmittanceFrame.h"
#include "vtkTransmittanceShaderSource.h"
#include "vtkTyndallParticles.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkTransmittanceSplatPass);

//------------------------------------------------------------------------------
vtkTransmittanceSplatPass::vtkTransmittanceSplatPass() = default;
vtkTransmittanceSplatPass::~vtkTransmittanceSplatPass() = default;

//------------------------------------------------------------------------------
vtkShaderProgram* vtkTransmittanceSplatPass::ReadyProgram(
  const vtkTransmittanceFrame& frame, const std::string& outputs)
{
  if (this->VertexSource.empty())
  {
    vtkTransmittanceShaderSource::GetSplatShaders(
      vtkTransmittanceShaderSource::Variant(), this->VertexSource, this->FragmentSource);
  }
  std::string fragment = this->FragmentSource;
  vtkShaderProgram::Substitute(fragment, "//TYNDALL::MapOutputs", outputs);
  vtkShaderProgram* program = frame.Window->GetShaderCache()->ReadyShaderProgram(
    this->VertexSource.c_str(), fragment.c_str(), "");
  return program && program->GetCompiled() ? program : nullptr;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceSplatPass::UploadBuffers(
  const vtkTransmittanceFrame& frame, vtkObject* reporter)
{
  this->Buffers.resize(frame.Splats.size());
  for (size_t i = 0; i < frame.Splats.size(); ++i)
  {
    const vtkTyndallParticles& particles = *frame.Splats[i].Particles;
    Buffer& buffer = this->Buffers[i];
    if (buffer.Object && buffer.ReadTime == particles.GetReadTime())
    {
      continue;
    }
    if (!buffer.Object)
    {
      buffer.Object = vtkSmartPointer<vtkOpenGLBufferObject>::New();
      buffer.Object->SetType(vtkOpenGLBufferObject::ArrayBuffer);
      buffer.Array = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    }
    if (!buffer.Object->Upload(particles.GetSplatVertices(), vtkOpenGLBufferObject::ArrayBuffer))
    {
      vtkErrorWithObjectMacro(reporter, << "Could not upload " << particles.GetNumberOfParticles()
                                        << " particles to the GPU: " << buffer.Object->GetError());
      buffer.Object = nullptr;
      return false;
    }
    buffer.ReadTime = particles.GetReadTime();
    buffer.Count = particles.GetNumberOfParticles();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransmittanceSplatPass::Render(
  const vtkTransmittanceFrame& frame, int light, const std::string& outputs, vtkObject* reporter)
{
  if (frame.Splats.empty())
  {
    return true;
  }
  if (!this->UploadBuffers(frame, reporter))
  {
    return false;
  }
  vtkShaderProgram* program = this->ReadyProgram(frame, outputs);
  if (!program)
  {
    vtkErrorWithObjectMacro(reporter, << "The particle splatting shader did not compile.");
    return false;
  }
  frame.SetLightMapUniforms(program);
  const float size = static_cast<float>(frame.Integrator.MapSize);
  program->SetUniformf("mapSize", size);
  program->SetUniformi("lightIndex", light);
  program->SetUniformi("coefficientCount", frame.Integrator.Coefficients);

  vtkOpenGLState* state = frame.State;
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlendFunc(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glBlendEquation(GL_FUNC_ADD);
  constexpr size_t stride = 5 * sizeof(float);
  for (size_t i = 0; i < frame.Splats.size(); ++i)
  {
    const vtkTransmittanceFrame::Splat& splat = frame.Splats[i];
    Buffer& buffer = this->Buffers[i];
    program->SetUniformMatrix4x4("worldToData", const_cast<float*>(splat.WorldToData));
    program->SetUniformMatrix4x4("dataToWorld", const_cast<float*>(splat.DataToWorld));
    program->SetUniformf("splatDensityScale", static_cast<float>(splat.DensityScale));
    buffer.Array->Bind();
    if (!buffer.Array->AddAttributeArrayWithDivisor(
          program, buffer.Object, "particle", 0, stride, VTK_FLOAT, 4, false, 1, false) ||
      !buffer.Array->AddAttributeArrayWithDivisor(program, buffer.Object, "density",
        4 * sizeof(float), stride, VTK_FLOAT, 1, false, 1, false))
    {
      buffer.Array->Release();
      vtkErrorWithObjectMacro(reporter, << "Could not bind the particles for splatting.");
      return false;
    }
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(buffer.Count));
    buffer.Array->Release();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTransmittanceSplatPass::ReleaseGraphicsResources(vtkWindow* window)
{
  for (Buffer& buffer : this->Buffers)
  {
    if (buffer.Object)
    {
      buffer.Object->ReleaseGraphicsResources();
    }
    if (buffer.Array)
    {
      buffer.Array->ReleaseGraphicsResources();
    }
  }
  this->Buffers.clear();
  (void)window;
}

//------------------------------------------------------------------------------
void vtkTransmittanceSplatPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Media: " << this->Buffers.size() << "\n";
}
