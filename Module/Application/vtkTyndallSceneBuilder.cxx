#include "vtkTyndallSceneBuilder.h"

#include "vtkAbstractPolyDataReader.h"
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContourValues.h"
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkCullerCollection.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkParticleFileReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataReader.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkStringArray.h"
#include "vtkTransferFunctionFileReader.h"
#include "vtkTransferFunctionPresets.h"
#include "vtkTransmittanceParticleMapper.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallIsosurfaces.h"
#include "vtkTyndallOptions.h"
#include "vtkTyndallSky.h"
#include "vtkVolume.h"
#include "vtkVolumeFileReader.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeShadowReceiverPass.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkTyndallSceneBuilder);
vtkCxxSetObjectMacro(vtkTyndallSceneBuilder, Options, vtkTyndallOptions);

namespace
{
// The default scene, in one place.
constexpr double kCloudHalfWidth = 1.0;
const double kCloudCameraPosition[3] = { 0.0, -0.6, 4.2 };
const double kSunFrom[3] = { 1.0, 0.3, 0.5 };
const double kSunColor[3] = { 1.0, 0.9, 0.75 };
// Lights and ambient of the programs' scenes, set for multiple scattering
// (the octaves, on by default, add about as much light again as single
// scattering gives): before them the sun was 1.2, the key light 1, the
// ambient 0.45 (default scene) and 0.25 (data).
constexpr double kSunIntensity = 0.85;
constexpr double kKeyLightIntensity = 0.7;
const double kSkyBottom[3] = { 0.55, 0.68, 0.82 };
const double kSkyTop[3] = { 0.16, 0.32, 0.58 };
constexpr double kViewAngle = 30.0;

void DefaultCloudTransferFunction(vtkVolumeProperty* property)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(8.0, 0.5);
  vtkNew<vtkColorTransferFunction> albedo;
  albedo->AddRGBPoint(0.0, 0.95, 0.95, 0.95);
  property->SetScalarOpacity(opacity);
  property->SetColor(albedo);
  property->SetScalarOpacityUnitDistance(0.05);
}

// Forwards an event (a source's progress or error) as the builder's.
void Forward(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  static_cast<vtkObject*>(clientData)->InvokeEvent(event, callData);
}
}

//------------------------------------------------------------------------------
vtkTyndallSceneBuilder::vtkTyndallSceneBuilder() = default;

//------------------------------------------------------------------------------
vtkTyndallSceneBuilder::~vtkTyndallSceneBuilder()
{
  this->SetOptions(nullptr);
}

//------------------------------------------------------------------------------
vtkImageData* vtkTyndallSceneBuilder::GetImage()
{
  return this->Image;
}
const char* vtkTyndallSceneBuilder::GetReadNotes()
{
  this->ReadNotes.clear();
  auto* notes = this->Image ? vtkStringArray::SafeDownCast(
                                this->Image->GetFieldData()->GetAbstractArray("TyndallReadNotes"))
                            : nullptr;
  for (vtkIdType i = 0; notes && i < notes->GetNumberOfValues(); ++i)
  {
    this->ReadNotes += (i ? "\n" : "") + notes->GetValue(i);
  }
  return this->ReadNotes.c_str();
}
vtkTransmittanceVolumeMapper* vtkTyndallSceneBuilder::GetMapper()
{
  return this->Mapper;
}
vtkParticipatingMediumProperty* vtkTyndallSceneBuilder::GetProperty()
{
  return this->Property;
}
vtkVolume* vtkTyndallSceneBuilder::GetVolume()
{
  return this->Volume;
}
vtkLight* vtkTyndallSceneBuilder::GetKeyLight()
{
  return this->KeyLight;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::Build(vtkRenderer* renderer)
{
  if (!this->Options || !renderer)
  {
    vtkErrorMacro(<< "Build: " << (renderer ? "no options" : "no renderer") << ".");
    return false;
  }
  this->DefaultScene = !*this->Options->GetInput();
  this->BadOptions = false;
  if (!this->ReadIsoValues())
  {
    this->BadOptions = true;
    return false;
  }
  // The defaults that depend on the scene become the options' values, so
  // that the viewer's keys step from what is shown.
  if (!this->Options->IsSet("anisotropy"))
  {
    this->Options->SetNumber("anisotropy", this->DefaultScene ? 0.3 : 0.0);
  }
  if (!this->Options->IsSet("ambient"))
  {
    this->Options->SetNumber("ambient", this->DefaultScene ? 0.25 : 0.2);
  }
  // The built-in cloud is procedural: its grid is the shape of cosine-noise
  // detail, which stays sharp close up (unless --no-detail).
  if (this->DefaultScene && !this->Options->GetFlag("no-detail"))
  {
    this->Options->SetFlag("detail", true);
  }
  if (!this->Options->IsSet("detail-contrast"))
  {
    this->Options->SetNumber("detail-contrast", this->DefaultScene ? 0.5 : 0.3);
  }
  this->Mapper = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
  this->Property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  this->Volume = vtkSmartPointer<vtkVolume>::New();
  // A transfer-function file is read before the (maybe slow) data.
  if (!this->ReadTransferFunctionFile() || !this->LoadMedium() || !this->ChooseTransferFunction())
  {
    return false;
  }
  this->ApplyLabels();
  this->Property->SetInterpolationTypeToLinear();
  this->Mapper->SetInputConnection(this->Source->GetOutputPort());
  this->Volume->SetMapper(this->Mapper);
  this->Volume->SetProperty(this->Property);
  double position[3];
  this->Options->GetVector("position", position);
  this->Volume->SetPosition(position);
  this->Volume->SetScale(this->Options->GetNumber("scale"));
  this->AddedVolumes.clear();
  if (!this->LoadAddedVolumes() || !this->LoadParticles())
  {
    return false;
  }
  this->ApplyOptions();

  renderer->AddVolume(this->Volume);
  for (const AddedVolume& added : this->AddedVolumes)
  {
    renderer->AddVolume(added.Volume);
  }
  if (!this->AddedVolumes.empty())
  {
    // Several volumes are composited in the order they are drawn: farthest first.
    vtkCullerCollection* cullers = renderer->GetCullers();
    cullers->InitTraversal();
    while (vtkCuller* culler = cullers->GetNextItem())
    {
      if (auto* coverage = vtkFrustumCoverageCuller::SafeDownCast(culler))
      {
        coverage->SetSortingStyleToBackToFront();
      }
    }
  }
  renderer->AutomaticLightCreationOff();
  this->SetUpBackground(renderer);
  if (!this->SetUpCamera(renderer))
  {
    return false;
  }
  this->SetUpLights(renderer);
  if (!vtkTyndallSky::Apply(this->Options, renderer, this))
  {
    return false;
  }
  this->GroundShadows = nullptr;
  this->AddGround(renderer);
  if (!this->AddSurface(renderer))
  {
    return false;
  }
  renderer->ResetCameraClippingRange();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::ReadIsoValues()
{
  this->IsoValues.clear();
  const std::string text = this->Options->GetText("iso-values");
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(value))
    {
      vtkErrorMacro(<< "--iso-values " << text << ": \"" << item << "\" is not a finite number.");
      return false;
    }
    this->IsoValues.push_back(value);
  }
  if (this->IsoValues.size() > static_cast<size_t>(vtkTyndallIsosurfaces::MaximumCount))
  {
    vtkErrorMacro(<< "--iso-values: " << this->IsoValues.size() << " values; at most "
                  << vtkTyndallIsosurfaces::MaximumCount << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::AddGround(vtkRenderer* renderer)
{
  this->Ground = nullptr;
  if (!this->Options->GetFlag("ground"))
  {
    return;
  }
  // Perpendicular to the camera's view-up, a tenth of the volume's diagonal
  // below its lowest corner, four diagonals wide.
  double bounds[6], up[3], center[3];
  this->GetSceneBounds(bounds);
  renderer->GetActiveCamera()->GetViewUp(up);
  vtkMath::Normalize(up);
  double lowest = 0.0, diagonal = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    center[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    lowest -= 0.5 * std::abs(up[a]) * (bounds[2 * a + 1] - bounds[2 * a]);
    diagonal += (bounds[2 * a + 1] - bounds[2 * a]) * (bounds[2 * a + 1] - bounds[2 * a]);
  }
  diagonal = std::sqrt(diagonal);
  double u[3], v[3];
  vtkMath::Perpendiculars(up, u, v, 0.0);
  vtkMath::Cross(up, u, v); // u x v = up: the plane's normal points up
  vtkNew<vtkPlaneSource> plane;
  double origin[3], p1[3], p2[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = center[a] + (lowest - 0.1 * diagonal) * up[a] - 2.0 * diagonal * (u[a] + v[a]);
    p1[a] = origin[a] + 4.0 * diagonal * u[a];
    p2[a] = origin[a] + 4.0 * diagonal * v[a];
  }
  plane->SetOrigin(origin);
  plane->SetPoint1(p1);
  plane->SetPoint2(p2);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  this->Ground = vtkSmartPointer<vtkActor>::New();
  this->Ground->SetMapper(mapper);
  this->Ground->GetProperty()->SetColor(0.8, 0.8, 0.8);
  this->Ground->GetProperty()->SetAmbient(0.35);
  this->Ground->GetProperty()->SetDiffuse(0.65);
  this->Ground->GetProperty()->SetSpecular(0.0);
  renderer->AddActor(this->Ground);
  this->ReceiveShadows(renderer);
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ReceiveShadows(vtkRenderer* renderer)
{
  if (!this->GroundShadows)
  {
    this->GroundShadows = vtkSmartPointer<vtkVolumeShadowReceiverPass>::New();
    this->GroundShadows->Install(renderer);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::AddSurface(vtkRenderer* renderer)
{
  this->Surface = nullptr;
  if (!this->Options->IsSet("surface"))
  {
    return true;
  }
  const std::string path = this->Options->GetText("surface");
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    vtkErrorMacro(<< path << ": no such surface file.");
    return false;
  }
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtp")
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  else if (extension == ".vtk")
  {
    auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(path.c_str());
    reader = legacy;
  }
  else if (extension == ".stl" || extension == ".obj" || extension == ".ply")
  {
    vtkSmartPointer<vtkAbstractPolyDataReader> mesh;
    if (extension == ".stl")
    {
      mesh = vtkSmartPointer<vtkSTLReader>::New();
    }
    else if (extension == ".obj")
    {
      mesh = vtkSmartPointer<vtkOBJReader>::New();
    }
    else
    {
      mesh = vtkSmartPointer<vtkPLYReader>::New();
    }
    mesh->SetFileName(path.c_str());
    reader = mesh;
  }
  else
  {
    vtkErrorMacro(<< path << ": not a surface file this program reads (.vtp, .vtk, .stl, .obj, "
                  << ".ply).");
    return false;
  }
  // The reader's own errors are the builder's too; an unreadable file or
  // one without polygons is an error naming it.
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback(Forward);
  reader->AddObserver(vtkCommand::ErrorEvent, forward);
  reader->Update();
  auto* surface = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!surface || surface->GetNumberOfPolys() + surface->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< path << ": no polygons read (a damaged file, or not a polygonal surface).");
    return false;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  mapper->ScalarVisibilityOff();
  this->Surface = vtkSmartPointer<vtkActor>::New();
  this->Surface->SetMapper(mapper);
  this->Surface->GetProperty()->SetColor(0.85, 0.85, 0.85);
  this->Surface->GetProperty()->SetAmbient(0.2);
  this->Surface->GetProperty()->SetDiffuse(0.8);
  renderer->AddActor(this->Surface);
  this->ReceiveShadows(renderer);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::Update(vtkAlgorithm* source)
{
  // The source's progress and errors are the builder's; its executive's
  // errors ("returned failure for request") only repeat them.
  vtkNew<vtkCallbackCommand> forward;
  forward->SetCallback(Forward);
  forward->SetClientData(this);
  vtkNew<vtkCallbackCommand> quiet;
  const unsigned long progressTag = source->AddObserver(vtkCommand::ProgressEvent, forward);
  const unsigned long errorTag = source->AddObserver(vtkCommand::ErrorEvent, forward);
  const unsigned long executiveTag =
    source->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  // (A failed request leaves the last output in place: a sequence's
  // missing frame would keep the frame before it.)
  const bool executed = source->GetExecutive()->Update() != 0;
  source->RemoveObserver(progressTag);
  source->RemoveObserver(errorTag);
  source->GetExecutive()->RemoveObserver(executiveTag);
  auto* data = vtkDataSet::SafeDownCast(source->GetOutputDataObject(0));
  return executed && data && data->GetNumberOfPoints() > 0;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::Run(vtkAlgorithm* source)
{
  const bool ok = this->Update(source);
  this->Source = source;
  this->Image = vtkImageData::SafeDownCast(source->GetOutputDataObject(0));
  return ok;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkVolumeFileReader> vtkTyndallSceneBuilder::MakeReader(const char* path)
{
  vtkTyndallOptions* o = this->Options;
  auto reader = vtkSmartPointer<vtkVolumeFileReader>::New();
  reader->SetFileName(path);
  reader->SetMemoryLimit(o->GetNumber("memory-limit"));
  reader->SetRescale(!o->IsSet("no-rescale"));
  reader->SetConvertLevelSetToFog(o->IsSet("level-set-to-fog"));
  return reader;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::LoadAddedVolumes()
{
  vtkTyndallOptions* o = this->Options;
  for (int i = 0; i < o->GetNumberOfAddedVolumes(); ++i)
  {
    const std::string path = o->GetAddedVolumeFile(i);
    vtkSmartPointer<vtkVolumeFileReader> reader = this->MakeReader(path.c_str());
    this->ProgressLabel = "loading " + path;
    if (!this->Update(reader))
    {
      return false; // the reader's error names the file
    }
    AddedVolume added;
    added.Image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
    added.Property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
    added.Property->SetInterpolationTypeToLinear();
    if (*o->GetAddedVolumeTransferFunction(i))
    {
      vtkNew<vtkTransferFunctionFileReader> file;
      file->SetFileName(o->GetAddedVolumeTransferFunction(i));
      vtkNew<vtkCallbackCommand> forward;
      forward->SetClientData(this);
      forward->SetCallback(Forward);
      file->AddObserver(vtkCommand::ErrorEvent, forward);
      if (!file->Read())
      {
        return false;
      }
      file->Apply(added.Property);
    }
    else
    {
      std::string preset = o->GetAddedVolumePreset(i);
      const char* guess = vtkTransferFunctionPresets::GuessPreset(added.Image);
      preset = preset.empty() && guess ? guess : preset;
      if (preset.empty() ||
        !vtkTransferFunctionPresets::ApplyToImage(preset.c_str(), added.Property, added.Image))
      {
        vtkErrorMacro(<< path << ": cannot apply the preset '" << preset << "'");
        return false;
      }
    }
    added.Mapper = vtkSmartPointer<vtkTransmittanceVolumeMapper>::New();
    added.Mapper->SetInputConnection(reader->GetOutputPort());
    added.Volume = vtkSmartPointer<vtkVolume>::New();
    added.Volume->SetMapper(added.Mapper);
    added.Volume->SetProperty(added.Property);
    double position[3];
    o->GetAddedVolumePosition(i, position);
    added.Volume->SetPosition(position);
    added.Volume->SetScale(o->GetAddedVolumeScale(i));
    added.DensityScale = o->GetAddedVolumeDensityScale(i);
    this->AddedVolumes.push_back(added);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::LoadParticles()
{
  vtkTyndallOptions* o = this->Options;
  if (!o->IsSet("particles"))
  {
    return true;
  }
  vtkNew<vtkParticleFileReader> reader;
  reader->SetFileName(o->GetText("particles"));
  this->ProgressLabel = std::string("loading ") + o->GetText("particles");
  if (!this->Update(reader))
  {
    return false; // the reader's error names the file
  }
  AddedVolume added;
  auto mapper = vtkSmartPointer<vtkTransmittanceParticleMapper>::New();
  mapper->SetInputConnection(reader->GetOutputPort());
  mapper->SetGridResolution(static_cast<int>(o->GetNumber("particles-grid")));
  mapper->SetSplatting(!o->GetFlag("no-splatting"));
  added.Mapper = mapper;
  added.Property = vtkSmartPointer<vtkParticipatingMediumProperty>::New();
  added.Property->SetInterpolationTypeToLinear();
  vtkNew<vtkColorTransferFunction> white;
  white->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
  added.Property->SetColor(white);
  added.Volume = vtkSmartPointer<vtkVolume>::New();
  added.Volume->SetMapper(added.Mapper);
  added.Volume->SetProperty(added.Property);
  double position[3];
  o->GetVector("particles-position", position);
  added.Volume->SetPosition(position);
  added.Volume->SetScale(o->GetNumber("particles-scale"));
  added.DensityScale = o->GetNumber("particles-density-scale");
  added.Particles = true;
  this->AddedVolumes.push_back(added);
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::GetSceneBounds(double bounds[6])
{
  this->Volume->GetBounds(bounds);
  for (const AddedVolume& added : this->AddedVolumes)
  {
    const double* b = added.Volume->GetBounds();
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
  }
}

//------------------------------------------------------------------------------
int vtkTyndallSceneBuilder::GetNumberOfAddedVolumes()
{
  return static_cast<int>(this->AddedVolumes.size());
}

//------------------------------------------------------------------------------
vtkVolume* vtkTyndallSceneBuilder::GetAddedVolume(int i)
{
  return i >= 0 && i < this->GetNumberOfAddedVolumes() ? this->AddedVolumes[i].Volume.Get()
                                                       : nullptr;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::LoadMedium()
{
  vtkTyndallOptions* o = this->Options;
  if (this->DefaultScene)
  {
    const int n = static_cast<int>(o->GetNumber("resolution"));
    vtkNew<vtkCosineNoiseSource> cloud;
    cloud->SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1);
    const double spacing = 2.0 * kCloudHalfWidth / (n - 1);
    cloud->SetSpacing(spacing, spacing, spacing);
    this->ProgressLabel = "cloud: " + std::to_string(n) + "^3 voxels";
    return this->Run(cloud);
  }
  const std::string path = this->FramePath.empty() ? o->GetInput() : this->FramePath;
  vtkSmartPointer<vtkVolumeFileReader> reader = this->MakeReader(path.c_str());
  this->ConfigureReader(
    reader, this->FrameIndex >= 0 ? this->FrameIndex : static_cast<int>(o->GetNumber("frame")));
  this->ProgressLabel = "loading " + path;
  // The reader reports its own error (one line starting with the path).
  return this->Run(reader) && this->LoadMask();
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ConfigureReader(vtkVolumeFileReader* reader, int frame)
{
  vtkTyndallOptions* o = this->Options;
  if (o->IsSet("grid"))
  {
    reader->SetGridName(o->GetText("grid"));
  }
  if (o->IsSet("emission-array"))
  {
    reader->SetExtraGridName(o->GetText("emission-array")); // .vdb only
  }
  if (o->IsSet("component"))
  {
    reader->SetComponent(static_cast<int>(o->GetNumber("component")));
  }
  reader->SetAllComponents(o->GetChoice("components") != 0); // --components
  reader->SetFrame(frame);
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::SetFrame(const std::string& path, int frame)
{
  this->FramePath = path;
  this->FrameIndex = path.empty() ? -1 : frame;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::LoadFrame(const std::string& path, int frame)
{
  auto* reader = vtkVolumeFileReader::SafeDownCast(this->Source);
  if (!reader || !this->Mapper)
  {
    vtkErrorMacro(<< "LoadFrame: no volume file was built (Build() first, with an input).");
    return false;
  }
  this->SetFrame(path, frame);
  reader->SetFileName(path.c_str());
  reader->SetFrame(frame);
  this->ProgressLabel = "loading " + path;
  const bool ok = this->Update(reader);
  this->Image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  return ok;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::LoadMask()
{
  vtkTyndallOptions* o = this->Options;
  this->Mapper->SetMaskInput(nullptr);
  const bool labels = o->IsSet("labels");
  if (!o->IsSet("mask") && !labels)
  {
    return true;
  }
  const char* file = o->GetText(labels ? "labels" : "mask");
  vtkSmartPointer<vtkVolumeFileReader> reader = this->MakeReader(file);
  this->ProgressLabel = std::string(labels ? "loading the label map " : "loading the mask ") + file;
  if (!this->Update(reader))
  {
    return false;
  }
  // Its dimensions against the volume's: the mapper says so when drawing.
  auto mask = vtkSmartPointer<vtkImageData>::New();
  mask->ShallowCopy(reader->GetOutput());
  this->Mapper->SetMaskInput(mask);
  if (labels)
  {
    this->Mapper->SetMaskTypeToLabelMap();
    this->Mapper->SetMaskBlendFactor(static_cast<float>(o->GetNumber("label-blend")));
  }
  else
  {
    this->Mapper->SetMaskTypeToBinary();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyLabels()
{
  vtkImageData* mask = this->Mapper->GetMaskInput();
  if (!mask || this->Mapper->GetMaskType() != vtkParticipatingMediumMapper::LabelMapMaskType)
  {
    return;
  }
  vtkDataArray* values = mask->GetPointData()->GetScalars();
  values = values ? values : mask->GetCellData()->GetScalars();
  if (!values || values->GetNumberOfComponents() != 1)
  {
    return; // the mapper says what is wrong with it
  }
  // The labels present, each its palette colour (Tableau's ten, then again).
  std::set<int> present;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    const double v = std::round(values->GetComponent(i, 0));
    if (v >= 1.0 && v <= 255.0)
    {
      present.insert(static_cast<int>(v));
    }
  }
  static const double palette[10][3] = { { 0.12, 0.47, 0.71 }, { 1.0, 0.5, 0.05 },
    { 0.17, 0.63, 0.17 }, { 0.84, 0.15, 0.16 }, { 0.58, 0.4, 0.74 }, { 0.55, 0.34, 0.29 },
    { 0.89, 0.47, 0.76 }, { 0.5, 0.5, 0.5 }, { 0.74, 0.74, 0.13 }, { 0.09, 0.75, 0.81 } };
  // The volume's opacity as a per-step opacity at the mapper's label step
  // (the smallest world spacing): a label's row then keeps the volume's
  // extinction, and only its colour changes (vtkTyndallLabelMap).
  vtkImageData* image = vtkImageData::SafeDownCast(this->Source->GetOutputDataObject(0));
  double step = 1.0;
  if (image)
  {
    const double* spacing = image->GetSpacing();
    step = std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) }) *
      this->Options->GetNumber("scale");
  }
  vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity(0);
  const double unit = this->Property->GetScalarOpacityUnitDistance(0);
  double range[2];
  opacity->GetRange(range);
  vtkNew<vtkPiecewiseFunction> perStep;
  const int points = 256;
  for (int i = 0; i < points; ++i)
  {
    const double s = range[0] + (range[1] - range[0]) * i / (points - 1.0);
    const double a = std::min(std::max(opacity->GetValue(s), 0.0), 0.999999);
    perStep->AddPoint(s, 1.0 - std::pow(1.0 - a, step / unit));
  }
  for (int label : present)
  {
    const double* rgb = palette[(label - 1) % 10];
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(range[0], rgb[0], rgb[1], rgb[2]);
    color->AddRGBPoint(range[1], rgb[0], rgb[1], rgb[2]);
    this->Property->SetLabelColor(label, color);
    this->Property->SetLabelScalarOpacity(label, perStep);
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::ReadTransferFunctionFile()
{
  vtkTyndallOptions* o = this->Options;
  this->TransferFunctionFile = nullptr;
  if (!o->IsSet("transfer-function"))
  {
    return true;
  }
  this->TransferFunctionFile = vtkSmartPointer<vtkTransferFunctionFileReader>::New();
  this->TransferFunctionFile->SetFileName(o->GetText("transfer-function"));
  // Its errors (file and line) are the builder's.
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback(Forward);
  this->TransferFunctionFile->AddObserver(vtkCommand::ErrorEvent, forward);
  return this->TransferFunctionFile->Read();
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::ChooseTransferFunction()
{
  vtkTyndallOptions* o = this->Options;
  if (this->TransferFunctionFile)
  {
    this->TransferFunctionFile->Apply(this->Property);
    this->TransferFunctionDescription = std::string("file ") + o->GetText("transfer-function");
    return this->ApplyComponents("");
  }
  if (o->IsSet("preset") || !this->DefaultScene)
  {
    std::string preset = o->GetText("preset");
    const bool guessed = preset.empty();
    if (guessed)
    {
      const char* guess = vtkTransferFunctionPresets::GuessPreset(this->Image);
      preset = guess ? guess : "";
    }
    if (preset.empty() ||
      !vtkTransferFunctionPresets::ApplyToImage(preset.c_str(), this->Property, this->Image))
    {
      vtkErrorMacro(<< "cannot apply the preset '" << preset << "'");
      return false;
    }
    this->TransferFunctionDescription = "preset " + preset + (guessed ? " (guessed)" : "");
    return this->ApplyComponents(preset);
  }
  DefaultCloudTransferFunction(this->Property);
  this->TransferFunctionDescription = "white cloud";
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::ApplyComponents(const std::string& preset)
{
  vtkTyndallOptions* o = this->Options;
  const int mode = o->GetChoice("components"); // one, independent, dependent
  vtkDataArray* scalars = this->Image ? this->Image->GetPointData()->GetScalars() : nullptr;
  scalars = scalars || !this->Image ? scalars : this->Image->GetCellData()->GetScalars();
  const int count = scalars ? scalars->GetNumberOfComponents() : 1;
  std::vector<double> weights;
  if (o->IsSet("component-weights"))
  {
    std::istringstream in(o->GetText("component-weights"));
    std::string item;
    while (std::getline(in, item, ','))
    {
      char* end = nullptr;
      const double w = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || !(w >= 0.0 && w <= 1.0))
      {
        vtkErrorMacro(<< "--component-weights: \"" << item << "\" is not a number in [0, 1].");
        return false;
      }
      weights.push_back(w);
    }
    if (mode != 1 || static_cast<int>(weights.size()) != count)
    {
      vtkErrorMacro(<< "--component-weights: " << weights.size() << " weights; --components "
                    << "independent needs one per component (" << count << ").");
      return false;
    }
  }
  if (mode == 0)
  {
    return true;
  }
  if (count < 2)
  {
    vtkErrorMacro(<< "--components " << o->GetText("components")
                  << ": the scalars have one component (a 4-D file's time frames are not "
                     "components: --frame picks one).");
    return false;
  }
  this->Property->SetIndependentComponents(mode == 1);
  if (mode == 2 && count == 3)
  {
    vtkErrorMacro(<< "--components dependent: the scalars have 3 components; dependent "
                     "components are 2 (colour, opacity) or 4 (RGBA).");
    return false;
  }
  const double unit = this->Property->GetScalarOpacityUnitDistance(0);
  // The preset over component c's finite range (a file's functions as they are).
  auto over = [&](int c, vtkVolumeProperty* target)
  {
    double range[2];
    scalars->GetFiniteRange(range, c);
    if (!(range[1] > range[0]))
    {
      range[1] = range[0] + 1.0;
    }
    if (preset.empty())
    {
      this->TransferFunctionFile->Apply(target);
    }
    else
    {
      vtkTransferFunctionPresets::Apply(preset.c_str(), target, range);
    }
    return std::vector<double>{ range[0], range[1] };
  };
  vtkNew<vtkVolumeProperty> opacitySource;
  if (mode == 2)
  {
    // Function 0: its colour over component 0's range, its opacity over the
    // last component's.
    over(0, this->Property);
    over(count - 1, opacitySource);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->DeepCopy(opacitySource->GetScalarOpacity());
    this->Property->SetScalarOpacity(0, opacity);
    this->Property->SetScalarOpacityUnitDistance(count - 1, unit);
    this->TransferFunctionDescription +=
      count == 2 ? ", 2 dependent components (colour, opacity)" : ", 4 dependent components (RGBA)";
    return true;
  }
  // Independent: each component its own opacity over its range, and a
  // colour of its own (as microscopy viewers show channels) with a preset.
  const double palette[4][3] = { { 1.0, 0.3, 0.25 }, { 0.3, 1.0, 0.3 }, { 0.3, 0.45, 1.0 },
    { 0.9, 0.9, 0.9 } };
  for (int c = 0; c < count; ++c)
  {
    vtkNew<vtkVolumeProperty> source;
    const std::vector<double> range = over(c, source);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->DeepCopy(source->GetScalarOpacity());
    this->Property->SetScalarOpacity(c, opacity);
    this->Property->SetScalarOpacityUnitDistance(c, unit);
    vtkNew<vtkColorTransferFunction> color;
    if (preset.empty())
    {
      color->DeepCopy(source->GetRGBTransferFunction());
    }
    else
    {
      color->AddRGBPoint(range[0], palette[c][0], palette[c][1], palette[c][2]);
      color->AddRGBPoint(range[1], palette[c][0], palette[c][1], palette[c][2]);
    }
    this->Property->SetColor(c, color);
    this->Property->SetComponentWeight(c, weights.empty() ? 1.0 : weights[c]);
  }
  this->TransferFunctionDescription += ", " + std::to_string(count) + " independent components";
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyOptions()
{
  vtkTyndallOptions* o = this->Options;
  if (!o || !this->Mapper || !this->Property)
  {
    return;
  }
  this->ApplyMapperOptions(this->Mapper);
  this->ApplyMediumOptions(this->Property);
  this->Property->SetDensityScale(o->GetNumber("density-scale"));
  for (const AddedVolume& added : this->AddedVolumes)
  {
    this->ApplyMapperOptions(added.Mapper);
    if (added.Particles && !o->IsSet("method"))
    {
      added.Mapper->SetTransmittanceMethodToETM(); // the method that splats
    }
    this->ApplyMediumOptions(added.Property);
    added.Property->SetDensityScale(added.DensityScale);
  }
  this->ApplyDetail();
  this->ApplyClipping();
  this->ApplySlice();
  this->ApplyEmission();
  this->ApplyPropertyKind();
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyPropertyKind()
{
  // --vtk-property: each grid volume drawn with a plain vtkVolumeProperty
  // made from its medium's settings (VTK's meaning; the same one while the
  // medium is unchanged: a new property would rebuild the maps), else the
  // medium.
  const bool plain = this->Options->GetFlag("vtk-property");
  auto apply = [plain](vtkVolume* volume, vtkParticipatingMediumProperty* medium)
  { volume->SetProperty(plain ? medium->GetPlainCopy() : medium); };
  apply(this->Volume, this->Property);
  for (AddedVolume& added : this->AddedVolumes)
  {
    if (!added.Particles) // a particle cloud is a medium only
    {
      apply(added.Volume, added.Property);
    }
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyMapperOptions(vtkTransmittanceVolumeMapper* mapper)
{
  vtkTyndallOptions* o = this->Options;
  mapper->SetTransmittanceMethod(o->GetChoice("method"));
  static_assert(vtkVolumeMapper::ADDITIVE_BLEND == 4 && vtkVolumeMapper::SLICE_BLEND == 6,
    "--blend-mode's choices are VTK's order");
  mapper->SetBlendMode(o->GetChoice("blend-mode"));
  mapper->SetNumberOfCoefficients(static_cast<int>(o->GetNumber("coefficients")));
  mapper->SetTransmittanceMapSize(static_cast<int>(o->GetNumber("map-size")));
  mapper->SetLightSampleCount(static_cast<int>(o->GetNumber("light-samples")));
  mapper->SetSampleDistance(o->GetNumber("sample-distance"));
  mapper->SetAdaptiveThreshold(o->GetNumber("adaptive-threshold"));
  mapper->SetJitter(!o->GetFlag("no-jitter"));
  mapper->SetEmptySpaceSkipping(!o->GetFlag("no-skip"));
  mapper->SetTransmittanceCache(!o->GetFlag("no-cache"));
  mapper->SetTransmittanceCacheSize(static_cast<int>(o->GetNumber("cache-size")));
  static_assert(vtkTransmittanceVolumeMapper::BRICKING_OFF == 0 &&
      vtkTransmittanceVolumeMapper::BRICKING_AUTO == 2,
    "--bricking's choices are the mapper's order");
  mapper->SetVolumeBricking(o->GetChoice("bricking"));
  mapper->SetDetailSamplesPerPixel(static_cast<int>(o->GetNumber("detail-samples")));
  const int pathSamples = static_cast<int>(o->GetNumber("path-trace"));
  mapper->SetPathTracing(pathSamples > 0);
  mapper->SetPathTraceSamplesPerPixel(std::max(pathSamples, 1));
  mapper->SetPathTraceMaximumBounces(static_cast<int>(o->GetNumber("path-bounces")));
  static_assert(vtkTransmittanceVolumeMapper::PATH_SHADOWS_FROM_MAPS == 0 &&
      vtkTransmittanceVolumeMapper::PATH_SHADOWS_TRACKED == 1,
    "--path-shadows's choices are the mapper's order");
  mapper->SetPathTraceShadows(o->GetChoice("path-shadows"));
  static_assert(vtkTransmittanceVolumeMapper::PATH_DISTANCE_CLOSED_FORM == 0 &&
      vtkTransmittanceVolumeMapper::PATH_DISTANCE_DELTA_TRACKING == 1,
    "--path-distance's choices are the mapper's order");
  mapper->SetPathTraceDistanceSampling(o->GetChoice("path-distance"));
  mapper->SetSkyLightDirections(static_cast<int>(o->GetNumber("sky-lights")));
  this->ApplyDisplayOptions(mapper);
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyDisplayOptions(vtkTransmittanceVolumeMapper* mapper)
{
  vtkTyndallOptions* o = this->Options;
  static_assert(vtkTransmittanceVolumeMapper::TONE_CURVE_LINEAR == 0 &&
      vtkTransmittanceVolumeMapper::TONE_CURVE_ACES == 2,
    "--tone-curve's choices are the mapper's order");
  const bool linear = this->LinearOutput;
  mapper->SetExposure(linear ? 0.0 : o->GetNumber("exposure"));
  mapper->SetToneCurve(
    linear ? vtkTransmittanceVolumeMapper::TONE_CURVE_LINEAR : o->GetChoice("tone-curve"));
  mapper->SetEncodeSRGB(!linear && o->GetFlag("srgb"));
  mapper->SetPathTraceDenoise(o->GetFlag("path-denoise")); // the EXR's too
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyDisplayOptions()
{
  if (!this->Options)
  {
    return;
  }
  if (this->Mapper)
  {
    this->ApplyDisplayOptions(this->Mapper);
  }
  for (const AddedVolume& added : this->AddedVolumes)
  {
    this->ApplyDisplayOptions(added.Mapper);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyMediumOptions(vtkParticipatingMediumProperty* medium)
{
  vtkTyndallOptions* o = this->Options;
  medium->SetScatteringModel(o->GetChoice("model"));
  medium->SetShade(o->GetFlag("shade"));
  medium->SetScatteringAnisotropy(o->GetNumber("anisotropy"));
  medium->SetAmbientIntensity(o->GetNumber("ambient"));
  medium->SetScatteringOctaves(static_cast<int>(o->GetNumber("octaves")));
  medium->SetOctaveScattering(o->GetNumber("octave-scattering"));
  medium->SetOctaveExtinction(o->GetNumber("octave-extinction"));
  medium->SetOctaveAnisotropy(o->GetNumber("octave-anisotropy"));
  medium->SetOctaveBuildUp(o->GetNumber("octave-build-up"));
  if (o->IsSet("extinction-color"))
  {
    double color[3];
    o->GetVector("extinction-color", color);
    medium->SetExtinctionColor(color);
  }
  medium->SetLightScale(
    o->IsSet("light-scale") ? o->GetNumber("light-scale") : 4.0 * vtkMath::Pi());
  medium->GetIsoSurfaceValues()->SetNumberOfContours(static_cast<int>(this->IsoValues.size()));
  for (size_t i = 0; i < this->IsoValues.size(); ++i)
  {
    medium->GetIsoSurfaceValues()->SetValue(static_cast<int>(i), this->IsoValues[i]);
  }
  medium->SetSceneShadows(!o->GetFlag("no-scene-shadows"));
  medium->SetSceneCompositing(!o->GetFlag("no-scene-compositing"));
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyEmission()
{
  vtkTyndallOptions* o = this->Options;
  vtkParticipatingMediumProperty* medium = this->Property;
  const bool emissionArray = o->IsSet("emission-array");
  medium->SetEmissionArrayName(emissionArray ? o->GetText("emission-array") : nullptr);
  medium->SetBlackbody(o->GetFlag("blackbody"));
  medium->SetTemperatureScale(o->GetNumber("temperature-scale"));
  medium->SetEmissionScale(
    emissionArray && !o->IsSet("emission-scale") ? 1.0 : o->GetNumber("emission-scale"));
  if (medium->GetEmissionScale() > 0.0 && !medium->GetEmissionColor())
  {
    // The file's emission lines, else the colour.
    const bool fromFile =
      this->TransferFunctionFile && this->TransferFunctionFile->GetHasEmission();
    medium->SetEmissionColor(
      fromFile ? this->TransferFunctionFile->GetEmission() : medium->GetRGBTransferFunction());
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPlane> vtkTyndallSceneBuilder::MakePlane(
  const std::string& prefix, const double bounds[6], int axis)
{
  vtkTyndallOptions* o = this->Options;
  double normal[3] = { 0.0, 0.0, 0.0 };
  normal[axis] = 1.0;
  double origin[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  if (o->IsSet((prefix + "-normal").c_str()))
  {
    o->GetVector((prefix + "-normal").c_str(), normal);
  }
  if (o->IsSet((prefix + "-origin").c_str()))
  {
    o->GetVector((prefix + "-origin").c_str(), origin);
  }
  if (!(vtkMath::Normalize(normal) > 0.0))
  {
    normal[0] = normal[1] = normal[2] = 0.0; // a zero normal: along the axis
    normal[axis] = 1.0;
  }
  const double low[3] = { bounds[0], bounds[2], bounds[4] };
  const double high[3] = { bounds[1], bounds[3], bounds[5] };
  const double offset = o->GetNumber((prefix + "-offset").c_str()) *
    std::sqrt(vtkMath::Distance2BetweenPoints(low, high));
  auto plane = vtkSmartPointer<vtkPlane>::New();
  plane->SetNormal(normal);
  plane->SetOrigin(
    origin[0] + offset * normal[0], origin[1] + offset * normal[1], origin[2] + offset * normal[2]);
  return plane;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplySlice()
{
  // Every volume's property holds the plane (it is drawn in world
  // coordinates, through the first volume's centre by default); none
  // without --blend-mode slice. One plane, changed in place.
  vtkPlane* plane = nullptr;
  if (this->Mapper->GetBlendMode() == vtkVolumeMapper::SLICE_BLEND)
  {
    double bounds[6];
    this->Volume->GetBounds(bounds);
    vtkSmartPointer<vtkPlane> made = this->MakePlane("slice", bounds, 2);
    if (!this->SlicePlane)
    {
      this->SlicePlane = vtkSmartPointer<vtkPlane>::New();
    }
    this->SlicePlane->SetNormal(made->GetNormal());
    this->SlicePlane->SetOrigin(made->GetOrigin());
    plane = this->SlicePlane;
  }
  else if (this->Options->IsSet("slice-offset"))
  {
    // (The viewer's ] / [ keys; the command line refuses it.)
    vtkWarningMacro(<< "--slice-offset moves the plane of --blend-mode slice; this volume is "
                       "drawn in another blend mode.");
  }
  this->Property->SetSliceFunction(plane);
  for (const AddedVolume& added : this->AddedVolumes)
  {
    added.Property->SetSliceFunction(plane);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyClipping()
{
  vtkTyndallOptions* o = this->Options;
  vtkTransmittanceVolumeMapper* mapper = this->Mapper;
  mapper->RemoveAllClippingPlanes();
  double bounds[6];
  this->Image->GetBounds(bounds);
  // A plane from --clip-normal, or from --clip-offset alone (the viewer's
  // p / o keys without a normal given): then the normal is +x. The plane is
  // in world coordinates, through the centre of the volume as placed.
  if (o->IsSet("clip-normal") || o->IsSet("clip-offset"))
  {
    double worldBounds[6];
    this->Volume->GetBounds(worldBounds);
    mapper->AddClippingPlane(this->MakePlane("clip", worldBounds, 0));
  }
  mapper->SetCropping(o->IsSet("crop-low") || o->IsSet("crop-high"));
  if (mapper->GetCropping())
  {
    double low[3] = { bounds[0], bounds[2], bounds[4] };
    double high[3] = { bounds[1], bounds[3], bounds[5] };
    if (o->IsSet("crop-low"))
    {
      o->GetVector("crop-low", low);
    }
    if (o->IsSet("crop-high"))
    {
      o->GetVector("crop-high", high);
    }
    mapper->SetCroppingRegionPlanes(low[0], high[0], low[1], high[1], low[2], high[2]);
    mapper->SetCroppingRegionFlagsToSubVolume();
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::ApplyDetail()
{
  vtkTyndallOptions* o = this->Options;
  if (!o->GetFlag("detail"))
  {
    this->Property->SetDetailNoise(nullptr);
    return;
  }
  if (!this->DetailNoise)
  {
    this->DetailNoise = vtkSmartPointer<vtkCosineNoise>::New();
  }
  vtkCosineNoise* noise = this->DetailNoise;
  noise->SetNumberOfOctaves(static_cast<int>(o->GetNumber("detail-octaves")));
  noise->SetNumberOfDirections(static_cast<int>(o->GetNumber("detail-directions")));
  double frequency = o->GetNumber("detail-frequency");
  if (frequency <= 0.0 && this->Image)
  {
    // The first octave at one cycle per 8 samples along the smallest side.
    const double* b = this->Image->GetBounds();
    const int* n = this->Image->GetDimensions();
    double side = 0.0;
    int samples = 2;
    for (int a = 0; a < 3; ++a)
    {
      if (n[a] > 1 && (side == 0.0 || b[2 * a + 1] - b[2 * a] < side))
      {
        side = b[2 * a + 1] - b[2 * a];
        samples = n[a];
      }
    }
    frequency = side > 0.0 ? samples / (8.0 * side) : 1.0;
  }
  noise->SetFrequency(frequency > 0.0 ? frequency : 1.0);
  // Offset 1, and the amplitudes scaled so that the factor's standard
  // deviation (random phases: sqrt(sum a^2 / 2)) is the contrast.
  // (The deviation is linear in the amplitude: measured at the amplitude
  // the noise has, which an unchanged contrast keeps, so that applying the
  // options again does not modify the medium.)
  if (!(noise->GetAmplitude() > 0.0))
  {
    noise->SetAmplitude(1.0);
  }
  const double deviation = noise->GetStandardDeviation() / noise->GetAmplitude();
  const double amplitude = deviation > 0.0 ? o->GetNumber("detail-contrast") / deviation : 0.0;
  if (std::abs(amplitude - noise->GetAmplitude()) > 1e-12 * amplitude)
  {
    noise->SetAmplitude(amplitude); // (not for a last bit's rounding)
  }
  noise->SetOffset(1.0);
  noise->SetExtinctionScale(1.0);
  this->Property->SetDetailNoise(noise);
  this->Property->SetDetailFilterWidth(o->GetNumber("detail-filter"));
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::SetUpBackground(vtkRenderer* renderer)
{
  vtkTyndallOptions* o = this->Options;
  const double black[3] = { 0.0, 0.0, 0.0 };
  renderer->SetGradientBackground(this->DefaultScene);
  renderer->SetBackground(this->DefaultScene ? kSkyBottom : black);
  renderer->SetBackground2(kSkyTop);
  double color[3];
  if (o->IsSet("background"))
  {
    o->GetVector("background", color);
    renderer->SetBackground(color);
    renderer->SetGradientBackground(o->IsSet("background2"));
  }
  if (o->IsSet("background2"))
  {
    o->GetVector("background2", color);
    renderer->SetBackground2(color);
    renderer->GradientBackgroundOn();
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallSceneBuilder::SetUpCamera(vtkRenderer* renderer)
{
  vtkTyndallOptions* o = this->Options;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetViewAngle(o->IsSet("view-angle") ? o->GetNumber("view-angle") : kViewAngle);
  camera->SetUseHorizontalViewAngle(o->GetFlag("horizontal-view-angle"));
  if (this->DefaultScene && this->AddedVolumes.empty() && !o->IsSet("position") &&
    !o->IsSet("scale"))
  {
    camera->SetPosition(kCloudCameraPosition);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
  }
  else
  {
    // Fitted to the volumes (the image's aspect is needed for the fit).
    double bounds[6];
    this->GetSceneBounds(bounds);
    renderer->SetAspect(o->GetNumber("size", 0) / o->GetNumber("size", 1), 1.0);
    camera->SetPosition(0.0, 0.0, 1.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCamera(bounds);
  }
  double v[3];
  if (o->IsSet("camera-position"))
  {
    o->GetVector("camera-position", v);
    camera->SetPosition(v);
  }
  if (o->IsSet("focal-point"))
  {
    o->GetVector("focal-point", v);
    camera->SetFocalPoint(v);
  }
  if (o->IsSet("view-up"))
  {
    o->GetVector("view-up", v);
    camera->SetViewUp(v);
  }
  double position[3], focal[3], up[3], direction[3], side[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  vtkMath::Subtract(focal, position, direction);
  if (vtkMath::Norm(direction) < 1e-12)
  {
    vtkErrorMacro(<< "the camera position and the focal point coincide");
    this->BadOptions = true;
    return false;
  }
  vtkMath::Normalize(direction);
  vtkMath::Normalize(up);
  vtkMath::Cross(direction, up, side);
  if (vtkMath::Norm(side) < 1e-6)
  {
    vtkErrorMacro(<< "the view-up vector is parallel to the view direction");
    this->BadOptions = true;
    return false;
  }
  // SetPosition/SetFocalPoint keep the old view-up: make it orthogonal when
  // the options moved the camera (the built-in views keep their +y up, the
  // axis the viewer's first orbit turns about).
  if (o->IsSet("camera-position") || o->IsSet("focal-point") || o->IsSet("view-up"))
  {
    camera->OrthogonalizeViewUp();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::SetUpLights(vtkRenderer* renderer)
{
  vtkTyndallOptions* o = this->Options;
  vtkCamera* camera = renderer->GetActiveCamera();
  this->KeyLight = nullptr;
  double center[3];
  this->Image->GetCenter(center);
  if (o->GetNumberOfLights() == 0)
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    double from[3];
    if (this->DefaultScene)
    {
      // A low sun from the front right.
      std::copy(kSunFrom, kSunFrom + 3, from);
      light->SetColor(kSunColor[0], kSunColor[1], kSunColor[2]);
      light->SetIntensity(kSunIntensity);
    }
    else
    {
      // A key light from the camera's upper right, in front of the data.
      double position[3], focal[3], up[3], back[3], right[3];
      camera->GetPosition(position);
      camera->GetFocalPoint(focal);
      camera->GetViewUp(up);
      vtkMath::Subtract(position, focal, back);
      vtkMath::Normalize(back);
      vtkMath::Cross(up, back, right);
      vtkMath::Normalize(right);
      for (int k = 0; k < 3; ++k)
      {
        from[k] = 0.6 * right[k] + 0.6 * up[k] + 0.55 * back[k];
      }
      vtkMath::Normalize(from);
      std::copy(focal, focal + 3, center);
      light->SetColor(1.0, 1.0, 1.0);
      light->SetIntensity(kKeyLightIntensity);
    }
    light->SetFocalPoint(center);
    light->SetPosition(center[0] + from[0], center[1] + from[1], center[2] + from[2]);
    renderer->AddLight(light);
    this->KeyLight = light;
    return;
  }
  for (int l = 0; l < o->GetNumberOfLights(); ++l)
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    double v[3], color[3];
    o->GetLightVector(l, v);
    if (o->GetLightPositional(l))
    {
      // A point light: positional with a 90 degree cone (not a spot light),
      // VTK's default attenuation (1, 0, 0): no fall-off.
      light->SetPositional(true);
      light->SetConeAngle(90.0);
      light->SetPosition(v);
      light->SetFocalPoint(center);
    }
    else
    {
      // VTK's directional lights shine from Position towards FocalPoint.
      light->SetPositional(false);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      light->SetPosition(-v[0], -v[1], -v[2]);
    }
    o->GetLightColor(l, color);
    light->SetColor(color);
    light->SetIntensity(o->GetLightIntensity(l));
    renderer->AddLight(light);
    this->KeyLight = this->KeyLight ? this->KeyLight : light;
  }
}

//------------------------------------------------------------------------------
void vtkTyndallSceneBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Options: " << this->Options << "\n";
  os << indent << "DefaultScene: " << this->DefaultScene << "\n";
  os << indent << "TransferFunction: " << this->TransferFunctionDescription << "\n";
}
