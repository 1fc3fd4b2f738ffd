#include "vtkTransmittanceParticleMapper.h"

#include "vtkAlgorithm.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"
#include "vtkTyndallParticles.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransmittanceParticleMapper);

// What was read from the input, and the key it was read for.
class vtkTransmittanceParticleMapper::vtkParticles
{
public:
  vtkTyndallParticles Medium;
  vtkNew<vtkImageData> Grid;
  std::vector<double> Key;
  bool Valid = false;
  std::string Error;
};

//------------------------------------------------------------------------------
vtkTransmittanceParticleMapper::vtkTransmittanceParticleMapper()
  : Particles(new vtkParticles)
{
  this->TransmittanceMethod = ETM; // the method that splats
}

vtkTransmittanceParticleMapper::~vtkTransmittanceParticleMapper() = default;

//------------------------------------------------------------------------------
int vtkTransmittanceParticleMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransmittanceParticleMapper::SetInputData(vtkPolyData* particles)
{
  this->SetInputDataInternal(0, particles);
}

//------------------------------------------------------------------------------
bool vtkTransmittanceParticleMapper::UpdateParticles(bool report)
{
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    int port = 0;
    if (vtkAlgorithm* producer = this->GetInputAlgorithm(0, 0, port))
    {
      producer->Update(port);
    }
  }
  auto* input = vtkPolyData::SafeDownCast(this->GetDataSetInput());
  vtkParticles& p = *this->Particles;
  const std::vector<double> key = { double(reinterpret_cast<uintptr_t>(input)),
    input ? double(input->GetMTime()) : -1.0, double(this->GridResolution) };
  if (key != p.Key)
  {
    p.Key = key;
    p.Error.clear();
    p.Valid = input && p.Medium.Update(input, p.Error);
    if (!input)
    {
      p.Error = "There is no particle cloud (a vtkPolyData) to render.";
    }
    if (p.Valid)
    {
      vtkNew<vtkTimerLog> timer;
      timer->StartTimer();
      p.Medium.Voxelize(this->GridResolution, p.Grid);
      timer->StopTimer();
      this->LastGridTime = timer->GetElapsedTime();
    }
    else
    {
      p.Grid->Initialize();
    }
    p.Grid->Modified();
  }
  if (!p.Valid && report)
  {
    vtkErrorMacro(<< p.Error);
  }
  return p.Valid;
}

//------------------------------------------------------------------------------
vtkImageData* vtkTransmittanceParticleMapper::GetMediumImage()
{
  return this->UpdateParticles(true) ? this->Particles->Grid.Get() : nullptr;
}

//------------------------------------------------------------------------------
const vtkTyndallParticles* vtkTransmittanceParticleMapper::GetParticles()
{
  return this->Particles->Valid ? &this->Particles->Medium : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkTransmittanceParticleMapper::GetNumberOfParticles()
{
  return this->Particles->Valid ? this->Particles->Medium.GetNumberOfParticles() : 0;
}

//------------------------------------------------------------------------------
double* vtkTransmittanceParticleMapper::GetBounds()
{
  // Silent: the renderer asks for bounds several times a frame; the render reports.
  if (this->GetNumberOfInputConnections(0) < 1 || !this->UpdateParticles(false))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  this->Particles->Grid->GetBounds(this->Bounds);
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkTransmittanceParticleMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GridResolution: " << this->GridResolution << "\n";
  os << indent << "Splatting: " << (this->Splatting ? "On" : "Off") << "\n";
  os << indent << "NumberOfParticles: " << this->GetNumberOfParticles() << "\n";
  os << indent << "LastGridTime: " << this->LastGridTime << "\n";
}
