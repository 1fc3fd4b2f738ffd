// vtkParticipatingMediumProperty::CopyVolumeProperty() and DeepCopy(): a
// plain vtkVolumeProperty made from a medium's settings (tyndall-render's
// --vtk-property) keeps everything of vtkVolumeProperty the medium was
// given, including what VTK 9.1's own DeepCopy() leaves out: the
// transfer-function mode and a component's 2-D function, the slice
// function and the label maps' colour, opacity and gradient opacity (copied:
// equal values, other objects); a medium copied into a medium keeps its own
// settings too; the mode is the source's when it holds a 2-D function but
// draws the 1-D ones, and a property without a 2-D function copies into one
// that has one (VTK 9.1 cannot set a null one); GetPlainCopy() is such a
// copy, the same object while the medium (its functions included) is
// unchanged and a new one after a change. Costs under 0.1 s.
#include "vtkColorTransferFunction.h"
#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include "TyndallTestCheck.h"

#include <cstdlib>

namespace
{
using tyndall_test::Check;

// A medium given one of each kind of vtkVolumeProperty setting.
void SetUp(vtkParticipatingMediumProperty* medium, vtkPlane* plane)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(10.0, 0.6);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.2, 0.3, 0.4);
  color->AddRGBPoint(10.0, 0.9, 0.8, 0.7);
  medium->SetScalarOpacity(opacity);
  medium->SetColor(color);
  medium->SetScalarOpacityUnitDistance(0.25);
  medium->ShadeOn();
  medium->SetDiffuse(0.45);
  medium->SetSpecularPower(22.0);
  medium->SetInterpolationTypeToLinear();
  vtkNew<vtkImageData> transfer;
  transfer->SetDimensions(4, 3, 1);
  transfer->AllocateScalars(VTK_FLOAT, 4);
  auto* values = vtkFloatArray::SafeDownCast(transfer->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetValue(i, 0.01f * static_cast<float>(i));
  }
  medium->SetTransferFunction2D(transfer);
  medium->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  plane->SetNormal(0.0, 1.0, 0.0);
  medium->SetSliceFunction(plane);
  vtkNew<vtkColorTransferFunction> labelColor;
  labelColor->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
  vtkNew<vtkPiecewiseFunction> labelOpacity;
  labelOpacity->AddPoint(0.0, 0.3);
  vtkNew<vtkPiecewiseFunction> labelGradient;
  labelGradient->AddPoint(0.0, 0.7);
  medium->SetLabelColor(3, labelColor);
  medium->SetLabelScalarOpacity(3, labelOpacity);
  medium->SetLabelGradientOpacity(3, labelGradient);
  medium->SetScatteringAnisotropy(0.4);
  medium->SetDensityScale(2.5);
  vtkNew<vtkCosineNoise> noise;
  medium->SetDetailNoise(noise);
}

// Whether `copy` holds the vtkVolumeProperty settings SetUp() gave `medium`.
void CheckVolumeSettings(vtkVolumeProperty* copy, vtkParticipatingMediumProperty* medium,
  vtkPlane* plane, const char* what)
{
  const std::string w = what;
  double rgb[3];
  copy->GetRGBTransferFunction()->GetColor(10.0, rgb);
  Check(rgb[0] == 0.9 && rgb[2] == 0.7, w + ": the colour function");
  Check(copy->GetScalarOpacity()->GetValue(10.0) == 0.6, w + ": the opacity function");
  Check(copy->GetScalarOpacityUnitDistance() == 0.25, w + ": the unit distance");
  Check(copy->GetShade() == 1 && copy->GetDiffuse() == 0.45 && copy->GetSpecularPower() == 22.0,
    w + ": Shade and the coefficients");
  Check(copy->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D, w + ": the 2-D mode");
  vtkImageData* transfer = copy->GetTransferFunction2D();
  Check(transfer && transfer != medium->GetTransferFunction2D() &&
      transfer->GetDimensions()[0] == 4 &&
      transfer->GetPointData()->GetScalars()->GetComponent(5, 2) ==
        medium->GetTransferFunction2D()->GetPointData()->GetScalars()->GetComponent(5, 2),
    w + ": the 2-D function, copied");
  Check(copy->GetSliceFunction() == plane, w + ": the slice function");
  vtkColorTransferFunction* labelColor = copy->GetLabelColor(3);
  vtkPiecewiseFunction* labelOpacity = copy->GetLabelScalarOpacity(3);
  vtkPiecewiseFunction* labelGradient = copy->GetLabelGradientOpacity(3);
  Check(labelColor && labelColor != medium->GetLabelColor(3) && labelColor->GetRedValue(0.0) == 1.0,
    w + ": label 3's colour, copied");
  Check(labelOpacity && labelOpacity != medium->GetLabelScalarOpacity(3) &&
      labelOpacity->GetValue(0.0) == 0.3,
    w + ": label 3's opacity, copied");
  Check(labelGradient && labelGradient != medium->GetLabelGradientOpacity(3) &&
      labelGradient->GetValue(0.0) == 0.7,
    w + ": label 3's gradient opacity, copied");
  Check(copy->GetLabelMapLabels().size() == 1, w + ": one label");
}
}

int TestParticipatingMediumPropertyCopy(int, char*[])
{
  vtkNew<vtkParticipatingMediumProperty> medium;
  vtkNew<vtkPlane> plane;
  SetUp(medium, plane);

  vtkNew<vtkVolumeProperty> plain;
  vtkParticipatingMediumProperty::CopyVolumeProperty(medium, plain);
  CheckVolumeSettings(plain, medium, plane, "a plain copy");

  vtkNew<vtkParticipatingMediumProperty> copy;
  copy->DeepCopy(medium);
  CheckVolumeSettings(copy, medium, plane, "a medium's copy");
  Check(copy->GetScatteringAnisotropy() == medium->GetScatteringAnisotropy() &&
      copy->GetDensityScale() == 2.5 && copy->GetDetailNoise() == medium->GetDetailNoise(),
    "a medium's copy: the medium's own settings");

  // The medium's own plain copy: kept while it is unchanged (a new
  // property would rebuild a mapper's maps), made anew when it or one of
  // its functions changed.
  vtkVolumeProperty* own = medium->GetPlainCopy();
  CheckVolumeSettings(own, medium, plane, "the medium's plain copy");
  Check(medium->GetPlainCopy() == own, "the plain copy kept while the medium is unchanged");
  own->Register(nullptr); // (kept alive to tell a new copy from a reused address)
  medium->GetScalarOpacity()->AddPoint(12.0, 0.8);
  vtkVolumeProperty* changed = medium->GetPlainCopy();
  Check(changed != own && changed->GetScalarOpacity()->GetValue(12.0) == 0.8,
    "a new plain copy after the opacity function changed");
  changed->Register(nullptr);
  const double diffuse = medium->GetDiffuse();
  medium->SetDiffuse(0.3);
  Check(medium->GetPlainCopy() != changed && medium->GetPlainCopy()->GetDiffuse() == 0.3,
    "a new plain copy after a setting changed");
  medium->SetDiffuse(diffuse);
  own->UnRegister(nullptr);
  changed->UnRegister(nullptr);
  // A medium without functions: reading them for the first copy makes VTK
  // create them (which modifies the medium), and the copy is still kept.
  vtkNew<vtkParticipatingMediumProperty> empty;
  vtkVolumeProperty* first = empty->GetPlainCopy();
  Check(empty->GetPlainCopy() == first, "a bare medium's plain copy kept too");

  // The 1-D functions asked for while a 2-D function is held (VTK sets TF_2D
  // when a 2-D function is set): the mode is the source's.
  medium->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  vtkNew<vtkVolumeProperty> oneD;
  vtkParticipatingMediumProperty::CopyVolumeProperty(medium, oneD);
  Check(oneD->GetTransferFunctionMode() == vtkVolumeProperty::TF_1D &&
      oneD->GetTransferFunction2D() != nullptr,
    "a copy of TF_1D with a 2-D function held: TF_1D, the function kept");
  // A property without a 2-D function copied into a medium that has one
  // (VTK 9.1 cannot set a null one): no crash, the source's mode.
  vtkNew<vtkVolumeProperty> bare;
  copy->DeepCopy(bare);
  Check(copy->GetTransferFunctionMode() == vtkVolumeProperty::TF_1D && copy->GetShade() == 0,
    "a bare property copied into a medium with a 2-D function: its settings, TF_1D");

  // Nothing to copy from or into: nothing happens (no crash).
  vtkParticipatingMediumProperty::CopyVolumeProperty(nullptr, plain);
  vtkParticipatingMediumProperty::CopyVolumeProperty(medium, nullptr);
  vtkParticipatingMediumProperty::CopyVolumeProperty(plain, plain);
  Check(plain->GetShade() == 1, "copying into itself leaves the property");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
