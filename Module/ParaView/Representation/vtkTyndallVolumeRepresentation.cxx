#include "vtkTyndallVolumeRepresentation.h"

#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVProcessWindow.h"
#include "vtkPVRenderView.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPointData.h"
#include "vtkTransmittanceMapReducer.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallMPIMapReducer.h"
#include "vtkVolumeProperty.h"

vtkStandardNewMacro(vtkTyndallVolumeRepresentation);

//------------------------------------------------------------------------------
vtkTyndallVolumeRepresentation::vtkTyndallVolumeRepresentation()
{
  this->VolumeMapper = this->TyndallMapper.Get();
  this->Actor->SetProperty(this->Medium);
  // ParaView gives every view's renderer a grey-blue environment colour: no
  // sky light unless the Tyndall Sky Light property asks for it.
  this->TyndallMapper->SkyLightOff();
  // Under MPI every rank draws its piece: the light crosses the ranks
  // through maps added over them.
  vtkNew<vtkTyndallMPIMapReducer> reducer;
  if (reducer->GetNumberOfProcesses() > 1)
  {
    this->TyndallMapper->SetMapReducer(reducer);
  }
}

//------------------------------------------------------------------------------
int vtkTyndallVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (result && request == vtkPVView::REQUEST_RENDER() && this->TyndallMapper->GetMapReducer())
  {
    // Every rank renders the view, but IceT draws only the ranks whose piece
    // is on screen: the maps are added here, before the window renders.
    vtkPVRenderView* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
    // The view's window borrows the process window's context, which exists
    // from the first render on: make it now.
    vtkPVProcessWindow::PrepareForRendering();
    this->TyndallMapper->PrepareDistributedMaps(view ? view->GetRenderer() : nullptr, this->Actor);
  }
  return result;
}

//------------------------------------------------------------------------------
vtkTyndallVolumeRepresentation::~vtkTyndallVolumeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  // The medium shares ParaView's transfer functions: setting the same
  // objects again modifies nothing, so the maps are rebuilt only when
  // ParaView edits a function.
  vtkVolumeProperty* paraview = this->Property;
  this->Medium->SetColor(paraview->GetRGBTransferFunction(0));
  // Emission (EmissionScale > 0) is coloured by the same colour map.
  this->Medium->SetEmissionColor(paraview->GetRGBTransferFunction(0));
  this->Medium->SetScalarOpacity(paraview->GetScalarOpacity(0));
  this->Medium->SetScalarOpacityUnitDistance(paraview->GetScalarOpacityUnitDistance(0));
  this->Medium->SetInterpolationType(paraview->GetInterpolationType());
  // ParaView's Shade and its coefficients: the medium's surface term
  // (vtkTyndallShading: added to its scattering, Tyndall's meaning).
  this->Medium->SetShade(paraview->GetShade());
  this->Medium->SetAmbient(paraview->GetAmbient());
  this->Medium->SetDiffuse(paraview->GetDiffuse());
  this->Medium->SetSpecular(paraview->GetSpecular());
  this->Medium->SetSpecularPower(paraview->GetSpecularPower());
  // ParaView's Map Scalars and Multi Components Mapping (the superclass
  // sets IndependentComponents from them): a vector array drawn as its
  // colour map's magnitude or component (the vector mode ParaView gives its
  // own vtkSmartVolumeMapper), or with them off its components as colour
  // and opacity (vtkTyndallComponents).
  this->Medium->SetIndependentComponents(paraview->GetIndependentComponents());
  // The Slice blend mode's plane (the Tyndall Volume's own TyndallSliceFunction).
  this->Medium->SetSliceFunction(paraview->GetSliceFunction());
  vtkColorTransferFunction* colors = paraview->GetRGBTransferFunction(0);
  const int vectorMode = colors ? colors->GetVectorMode() : vtkScalarsToColors::MAGNITUDE;
  this->TyndallMapper->SetVectorMode(vectorMode == vtkScalarsToColors::COMPONENT
      ? vtkParticipatingMediumMapper::COMPONENT
      : (vectorMode == vtkScalarsToColors::MAGNITUDE ? vtkParticipatingMediumMapper::MAGNITUDE
                                                     : vtkParticipatingMediumMapper::DISABLED));
  this->TyndallMapper->SetVectorComponent(colors ? colors->GetVectorComponent() : 0);
  // The Isosurface blend mode's values (ParaView's Isosurfaces property),
  // copied only when they change.
  vtkContourValues* values = paraview->GetIsoSurfaceValues();
  vtkContourValues* medium = this->Medium->GetIsoSurfaceValues();
  bool same = values->GetNumberOfContours() == medium->GetNumberOfContours();
  for (int i = 0; same && i < values->GetNumberOfContours(); ++i)
  {
    same = values->GetValue(i) == medium->GetValue(i);
  }
  if (!same)
  {
    medium->DeepCopy(values);
    this->Medium->Modified();
  }
  this->UpdateTransfer2D();
  this->UpdateDrawnProperty();
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::UpdateDrawnProperty()
{
  if (!this->VTKProperty)
  {
    this->Actor->SetProperty(this->Medium);
    return;
  }
  // (A new copy only when the medium changed: a new property rebuilds the maps.)
  this->Actor->SetProperty(this->Medium->GetPlainCopy());
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetVTKProperty(int on)
{
  if (this->VTKProperty != (on != 0))
  {
    this->VTKProperty = on != 0;
    this->UpdateDrawnProperty();
  }
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::UpdateTransfer2D()
{
  // ParaView's 2-D transfer function (Use Transfer 2D) over the gradient
  // magnitude: the medium's classification, as VTK's. Over a second array,
  // or with several components drawn as such, it cannot be: the 1-D
  // functions, said once.
  vtkVolumeProperty* paraview = this->Property;
  const bool secondArray =
    this->UseTransfer2D && !this->UseGradientForTransfer2D && !this->ColorArray2Name.empty();
  int cellFlag = 0;
  vtkDataSet* input = this->TyndallMapper->GetInput();
  vtkDataArray* scalars = input
    ? vtkAbstractMapper::GetScalars(input, this->TyndallMapper->GetScalarMode(),
        this->TyndallMapper->GetArrayAccessMode(), this->TyndallMapper->GetArrayId(),
        this->TyndallMapper->GetArrayName(), cellFlag)
    : nullptr;
  const bool components = this->UseTransfer2D && scalars && scalars->GetNumberOfComponents() > 1 &&
    this->TyndallMapper->GetVectorMode() == vtkParticipatingMediumMapper::DISABLED;
  const bool oneD = secondArray || components;
  if (oneD && !this->WarnedTransfer2D)
  {
    vtkWarningMacro(<< "The Tyndall Volume draws a 2-D transfer function over the gradient "
                       "magnitude of one component only, not over "
                    << (secondArray ? "a second array" : "several components")
                    << ": the 1-D functions are used.");
  }
  this->WarnedTransfer2D = oneD;
  // The mode after the function (VTK may set TF_2D with a new 2-D function).
  const int mode = oneD ? vtkVolumeProperty::TF_1D : paraview->GetTransferFunctionMode();
  // ParaView composites its boxes without premultiplying: overlapping ones
  // can exceed 1, which VTK's mapper clamps and Tyndall refuses; a clamped
  // copy, made again when ParaView's changes.
  vtkImageData* source = paraview->GetTransferFunction2D(0);
  if (!source)
  {
    this->Medium->SetTransferFunction2D(nullptr);
    this->Medium->SetTransferFunctionMode(mode);
    return;
  }
  if (source != this->Transfer2DSource || source->GetMTime() > this->Transfer2DCopyTime)
  {
    this->Transfer2DSource = source;
    this->Transfer2D->DeepCopy(source);
    vtkDataArray* values = this->Transfer2D->GetPointData()->GetScalars();
    for (vtkIdType i = 0; values && i < values->GetNumberOfValues(); ++i)
    {
      const double v = values->GetVariantValue(i).ToDouble();
      if (v > 1.0)
      {
        values->SetVariantValue(i, 1.0);
      }
    }
    this->Transfer2D->Modified();
    this->Transfer2DCopyTime = this->Transfer2D->GetMTime();
  }
  this->Medium->SetTransferFunction2D(this->Transfer2D);
  this->Medium->SetTransferFunctionMode(mode);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetTransmittanceMethod(int method)
{
  this->TyndallMapper->SetTransmittanceMethod(method);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetNumberOfCoefficients(int count)
{
  this->TyndallMapper->SetNumberOfCoefficients(count);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetTransmittanceMapSize(int size)
{
  this->TyndallMapper->SetTransmittanceMapSize(size);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetExposure(double stops)
{
  this->TyndallMapper->SetExposure(stops);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetToneCurve(int curve)
{
  this->TyndallMapper->SetToneCurve(curve);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetEncodeSRGB(int encode)
{
  this->TyndallMapper->SetEncodeSRGB(encode != 0);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetPathTracing(int on)
{
  this->TyndallMapper->SetPathTracing(on != 0);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetPathTraceSamplesPerPixel(int samples)
{
  this->TyndallMapper->SetPathTraceSamplesPerPixel(samples);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetPathTraceMaximumBounces(int bounces)
{
  this->TyndallMapper->SetPathTraceMaximumBounces(bounces);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetPathTraceDenoise(int on)
{
  this->TyndallMapper->SetPathTraceDenoise(on != 0);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetSkyLight(int on)
{
  this->TyndallMapper->SetSkyLight(on != 0);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetSkyLightDirections(int count)
{
  this->TyndallMapper->SetSkyLightDirections(count);
}

//------------------------------------------------------------------------------
int vtkTyndallVolumeRepresentation::GetLastPathTraceSamples()
{
  return this->TyndallMapper->GetLastPathTraceSamples();
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringModel(int model)
{
  this->Medium->SetScatteringModel(model);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetDensityScale(double scale)
{
  this->Medium->SetDensityScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringAnisotropy(double g)
{
  this->Medium->SetScatteringAnisotropy(g);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetLightScale(double scale)
{
  this->Medium->SetLightScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetAmbientIntensity(double intensity)
{
  this->Medium->SetAmbientIntensity(intensity);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetEmissionScale(double scale)
{
  this->Medium->SetEmissionScale(scale);
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::SetScatteringOctaves(int octaves)
{
  this->Medium->SetScatteringOctaves(octaves);
}

//------------------------------------------------------------------------------
vtkTransmittanceVolumeMapper* vtkTyndallVolumeRepresentation::GetTyndallMapper()
{
  return this->TyndallMapper;
}

//------------------------------------------------------------------------------
vtkParticipatingMediumProperty* vtkTyndallVolumeRepresentation::GetMediumProperty()
{
  return this->Medium;
}

//------------------------------------------------------------------------------
void vtkTyndallVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TyndallMapper:\n";
  this->TyndallMapper->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Medium:\n";
  this->Medium->PrintSelf(os, indent.GetNextIndent());
  os << indent << "VTKProperty: " << this->VTKProperty << "\n";
}

//------------------------------------------------------------------------------
double vtkTyndallVolumeRepresentation::GetLastMapReductionTime()
{
  vtkTransmittanceMapReducer* reducer = this->TyndallMapper->GetMapReducer();
  return reducer ? reducer->GetLastReductionTime() : 0.0;
}

//------------------------------------------------------------------------------
double vtkTyndallVolumeRepresentation::GetLastMapReductionSize()
{
  vtkTransmittanceMapReducer* reducer = this->TyndallMapper->GetMapReducer();
  return reducer ? static_cast<double>(reducer->GetLastReductionSize()) : 0.0;
}
