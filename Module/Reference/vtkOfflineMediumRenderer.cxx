#include "vtkOfflineMediumRenderer.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTyndallReferenceScene.h"
#include "vtkTyndallSceneReader.h"

//------------------------------------------------------------------------------
vtkOfflineMediumRenderer::vtkOfflineMediumRenderer()
  : SceneReader(new vtkTyndallSceneReader)
{
  this->Output = vtkImageData::New();
  this->CompositeOutput = vtkImageData::New();
}

//------------------------------------------------------------------------------
vtkOfflineMediumRenderer::~vtkOfflineMediumRenderer()
{
  this->Output->Delete();
  this->CompositeOutput->Delete();
}

//------------------------------------------------------------------------------
vtkImageData* vtkOfflineMediumRenderer::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
void vtkOfflineMediumRenderer::UpdateProgress(double progress)
{
  this->Progress = progress;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
}

//------------------------------------------------------------------------------
vtkImageData* vtkOfflineMediumRenderer::Render(
  vtkRenderer* renderer, vtkVolume* volume, int width, int height)
{
  this->AbortExecute = false;
  this->Progress = 0.0;
  vtkImageData* image = vtkTyndallReferenceScene::TimedRender(
    this, this->Output, this->CompositeOutput,
    [&] { return this->RenderImage(renderer, volume, width, height); }, this->LastRenderTime);
  if (image)
  {
    renderer->GetBackground(this->LastBackground);
  }
  return image;
}

//------------------------------------------------------------------------------
vtkImageData* vtkOfflineMediumRenderer::Composite()
{
  return this->Composite(this->LastBackground);
}

//------------------------------------------------------------------------------
vtkImageData* vtkOfflineMediumRenderer::Composite(const double background[3])
{
  vtkDataArray* radiance = this->Output->GetPointData()->GetArray("Radiance");
  vtkDataArray* transmittance = this->Output->GetPointData()->GetArray("Transmittance");
  this->CompositeOutput->Initialize();
  if (!radiance || !transmittance)
  {
    vtkErrorMacro(<< "Composite: there is no rendered image; call Render() first.");
    return nullptr;
  }
  if (!background)
  {
    vtkErrorMacro(<< "Composite: the background colour is null.");
    return nullptr;
  }
  vtkTyndallReferenceScene::Composite(
    this->Output, radiance, transmittance, background, this->CompositeOutput);
  return this->CompositeOutput;
}

//------------------------------------------------------------------------------
void vtkOfflineMediumRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AbortExecute: " << (this->AbortExecute ? "On" : "Off") << "\n";
  os << indent << "Progress: " << this->Progress << "\n";
  os << indent << "LastBackground: (" << this->LastBackground[0] << ", " << this->LastBackground[1]
     << ", " << this->LastBackground[2] << ")\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
}
