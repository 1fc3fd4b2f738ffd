// The scalars' texture in the data's own type (issue 37): 8- and 16-bit
// integers, signed and unsigned, are kept as normalized textures of their
// type and read back as values, floats as floats. VTK's wavelet in each type
// (shaded by the renderer's light, with the maps' shadows: the gradient,
// the table lookup and the empty-space grid all read the values) must give
// the picture of the same values as floats, and one mapper fed each type in
// turn must give the picture a new mapper gives (a texture keeps no earlier
// type's format).
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageCast.h"
#include "vtkImageData.h"
#include "vtkImageShiftScale.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"
#include "TyndallTestImage.h"

#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

struct Type
{
  const char* Name;
  int Id;
  double Shift; // the wavelet (37 .. 277 here) shifted and scaled into the type
  double Scale;
};

vtkSmartPointer<vtkImageData> Wavelet(const Type& type)
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-19, 20, -19, 20, -19, 20);
  vtkNew<vtkImageShiftScale> cast;
  cast->SetInputConnection(source->GetOutputPort());
  cast->SetShift(type.Shift);
  cast->SetScale(type.Scale);
  cast->SetOutputScalarType(type.Id);
  cast->ClampOverflowOn();
  cast->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(cast->GetOutput());
  return image;
}

// The same values as floats.
vtkSmartPointer<vtkImageData> AsFloats(vtkImageData* image)
{
  vtkNew<vtkImageCast> cast;
  cast->SetInputData(image);
  cast->SetOutputScalarTypeToFloat();
  cast->Update();
  auto floats = vtkSmartPointer<vtkImageData>::New();
  floats->DeepCopy(cast->GetOutput());
  return floats;
}

// A shaded property over the data's range: colour and a soft opacity.
void SetFunctions(vtkVolumeProperty* property, vtkImageData* data)
{
  double r[2];
  data->GetPointData()->GetScalars()->GetRange(r);
  const double span = r[1] - r[0];
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(r[0], 0.1, 0.2, 0.8);
  color->AddRGBPoint(r[0] + 0.5 * span, 0.9, 0.8, 0.3);
  color->AddRGBPoint(r[1], 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(r[0], 0.0);
  opacity->AddPoint(r[0] + 0.45 * span, 0.0);
  opacity->AddPoint(r[1], 0.4);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
}
}

int TestTransmittanceMapperDataTypes(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(40.0, 60.0, 30.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetPositional(false);
  renderer->AddLight(light);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkTest::ErrorObserver> errors;

  // A mapper per picture (the reference), and the one fed every type.
  auto draw = [&](vtkTransmittanceVolumeMapper* mapper, vtkImageData* data)
  {
    mapper->SetInputData(data);
    mapper->SetTransmittanceMethodToAdaptiveETM();
    mapper->JitterOff();
    // The types' pictures against each other, not the transmittance cache
    // (on by default; TestTransmittanceMapperTransmittanceCache checks it):
    // its 256^3 lattice per picture was 34 of the test's 50 s.
    mapper->TransmittanceCacheOff();
    volume->SetMapper(mapper);
    SetFunctions(property, data);
    window->Render();
    return tyndall_test::Grab(window);
  };
  vtkNew<vtkTransmittanceVolumeMapper> reused;
  reused->AddObserver(vtkCommand::ErrorEvent, errors);
  const Type types[] = { { "float", VTK_FLOAT, 0.0, 1.0 },
    { "unsigned char", VTK_UNSIGNED_CHAR, -37.0, 1.0 },
    { "signed char", VTK_SIGNED_CHAR, -157.0, 1.0 },
    { "unsigned short", VTK_UNSIGNED_SHORT, 0.0, 200.0 }, { "short", VTK_SHORT, -157.0, 200.0 },
    { "float again", VTK_FLOAT, 0.0, 1.0 } };
  bool first = true;
  for (const Type& type : types)
  {
    vtkSmartPointer<vtkImageData> data = Wavelet(type);
    vtkSmartPointer<vtkImageData> floats = AsFloats(data);
    if (first)
    {
      renderer->ResetCamera(data->GetBounds());
      renderer->GetActiveCamera()->Azimuth(30.0);
      renderer->GetActiveCamera()->Elevation(20.0);
      first = false;
    }
    vtkNew<vtkTransmittanceVolumeMapper> fresh, asFloats;
    fresh->AddObserver(vtkCommand::ErrorEvent, errors);
    asFloats->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkSmartPointer<vtkImageData> typed = draw(fresh, data);
    vtkSmartPointer<vtkImageData> expected = draw(asFloats, floats);
    vtkSmartPointer<vtkImageData> again = draw(reused, data);
    const double asFloat = tyndall_test::PSNR(typed, expected);
    const double reuse = tyndall_test::PSNR(again, typed);
    std::cout << type.Name << ": against the same values as floats " << asFloat
              << " dB, one mapper fed each type in turn against a new one " << reuse << " dB\n";
    // (8-bit textures: llvmpipe filters them with 8-bit weights.)
    Check(asFloat >= 40.0, std::string(type.Name) + ": the floats' picture");
    Check(reuse >= 60.0, std::string(type.Name) + ": a mapper that drew another type before");
    Check(!errors->GetError(), std::string(type.Name) + ": no error");
  }
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
