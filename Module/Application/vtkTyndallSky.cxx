#include "vtkTyndallSky.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkHDRReader.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkTyndallOptions.h"

#include <vtksys/SystemTools.hxx>

#ifdef TYNDALL_HAVE_OPENEXR
#include <ImfArray.h>
#include <ImfRgbaFile.h>
#endif

#include <exception>
#include <sstream>

vtkStandardNewMacro(vtkTyndallSky);

namespace
{
// Keeps a reader's first error (an observer silences VTK's own message).
void KeepError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* error = static_cast<std::string*>(clientData);
  if (error->empty())
  {
    *error = callData ? static_cast<const char*>(callData) : "an error";
  }
}

#ifdef TYNDALL_HAVE_OPENEXR
// An EXR's RGB as a float image, row 0 at the bottom; null with `error`.
vtkSmartPointer<vtkImageData> ReadExr(const std::string& path, std::string& error)
{
  try
  {
    Imf::RgbaInputFile file(path.c_str());
    const Imath::Box2i window = file.dataWindow();
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, width);
    file.readPixels(window.min.y, window.max.y);
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(width, height, 1);
    vtkNew<vtkFloatArray> rgb;
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const Imf::Rgba& p = pixels[height - 1 - y][x]; // EXR rows run downwards
        const float values[3] = { p.r, p.g, p.b };
        rgb->SetTypedTuple(static_cast<vtkIdType>(y) * width + x, values);
      }
    }
    image->GetPointData()->SetScalars(rgb);
    return image;
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return nullptr;
  }
}
#endif
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkTyndallSky::ReadImage(const std::string& path, vtkObject* reporter)
{
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    vtkErrorWithObjectMacro(reporter, << path << ": no such sky image.");
    return nullptr;
  }
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  vtkSmartPointer<vtkImageData> image;
  if (extension == ".exr")
  {
#ifdef TYNDALL_HAVE_OPENEXR
    std::string error;
    image = ReadExr(path, error);
    if (!image)
    {
      vtkErrorWithObjectMacro(reporter, << path << ": cannot read the OpenEXR sky: " << error);
      return nullptr;
    }
#else
    vtkErrorWithObjectMacro(reporter,
      << path << ": this Tyndall was built without OpenEXR (Debian: libopenexr-dev); use .hdr.");
    return nullptr;
#endif
  }
  else
  {
    vtkSmartPointer<vtkImageReader2> reader;
    if (extension == ".hdr")
    {
      reader = vtkSmartPointer<vtkHDRReader>::New();
    }
    else
    {
      reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
    }
    if (!reader)
    {
      vtkErrorWithObjectMacro(
        reporter, << path << ": not a sky image this program reads (.hdr, .exr, .png, .jpg, ...).");
      return nullptr;
    }
    std::string error;
    vtkNew<vtkCallbackCommand> keep;
    keep->SetClientData(&error);
    keep->SetCallback(KeepError);
    reader->AddObserver(vtkCommand::ErrorEvent, keep);
    reader->SetFileName(path.c_str());
    reader->Update();
    image = reader->GetOutput();
    if (!error.empty() || !image || image->GetNumberOfPoints() == 0)
    {
      vtkErrorWithObjectMacro(reporter,
        << path << ": the sky image could not be read" << (error.empty() ? "." : ": " + error));
      return nullptr;
    }
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[2] != 1 || !image->GetPointData()->GetScalars())
  {
    vtkErrorWithObjectMacro(reporter, << path << ": the sky image is not a 2-D image.");
    return nullptr;
  }
  return image;
}

//------------------------------------------------------------------------------
bool vtkTyndallSky::Apply(vtkTyndallOptions* o, vtkRenderer* renderer, vtkObject* reporter)
{
  double bottom[3] = { 0.0, 0.0, 0.0 };
  if (o->IsSet("sky"))
  {
    o->GetVector("sky", bottom);
  }
  renderer->SetEnvironmentalBG(bottom);
  renderer->SetGradientEnvironmentalBG(o->IsSet("sky-top"));
  if (o->IsSet("sky-top"))
  {
    double top[3];
    o->GetVector("sky-top", top);
    renderer->SetEnvironmentalBG2(top);
  }
  // Up: the view-up; the image's centre (front = up x right) along the view.
  vtkCamera* camera = renderer->GetActiveCamera();
  double up[3], view[3], right[3];
  camera->GetViewUp(up);
  camera->GetDirectionOfProjection(view);
  vtkMath::Cross(view, up, right);
  if (vtkMath::Normalize(right) > 0.0)
  {
    renderer->SetEnvironmentUp(up);
    renderer->SetEnvironmentRight(right);
  }
  renderer->UseImageBasedLightingOff();
  renderer->SetEnvironmentTexture(nullptr);
  if (!o->IsSet("sky-image"))
  {
    return true;
  }
  vtkSmartPointer<vtkImageData> image = ReadImage(o->GetText("sky-image"), reporter);
  if (!image)
  {
    return false;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->MipmapOn(); // VTK prefilters it for its surfaces' image-based lighting
  texture->InterpolateOn();
  renderer->SetEnvironmentTexture(texture);
  renderer->UseImageBasedLightingOn();
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallSky::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
