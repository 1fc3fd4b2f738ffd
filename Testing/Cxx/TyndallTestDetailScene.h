// A detailed medium for the tests of procedural detail's footprint filter
// (CPU): a constant-density image, rotated, anisotropically spaced, scaled
// and translated, under a noise of `directions` x `octaves` waves, read as
// the grid and detail media both renderers use. Header only; not part of
// the library.
#ifndef TyndallTestDetailScene_h
#define TyndallTestDetailScene_h

#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTyndallDetailMedium.h"
#include "vtkTyndallGridMedium.h"
#include "vtkVolume.h"

#include "TyndallTestScene.h"

namespace tyndall_test
{
// A rotated, anisotropically spaced and translated image with a noise of
// `directions` x `octaves` waves over it.
struct DetailScene
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkSmartVolumeMapper> Mapper;
  vtkNew<vtkParticipatingMediumProperty> Property;
  vtkNew<vtkCosineNoise> Noise;
  vtkTyndallGridMedium Grid;
  vtkTyndallDetailMedium Detail;

  DetailScene(int directions, int octaves, double width)
  {
    tyndall_test::SetSkewedGeometry(this->Image);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(this->Image->GetNumberOfPoints());
    values->Fill(1.0);
    this->Image->GetPointData()->SetScalars(values);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, 0.5);
    this->Property->SetScalarOpacity(opacity);
    this->Mapper->SetInputData(this->Image);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Volume->SetPosition(0.3, -0.2, 0.1);
    this->Volume->RotateX(20.0);
    this->Volume->SetScale(1.0, 1.5, 0.8);
    this->Noise->SetNumberOfDirections(directions);
    this->Noise->SetNumberOfOctaves(octaves);
    this->Noise->SetFrequency(0.9);
    this->Noise->SetOffset(0.3);
    this->Update(width);
  }

  bool Update(double width)
  {
    return this->Grid.Update(this->Volume, this->Volume) &&
      this->Detail.Update(this->Grid, this->Noise, this->Volume, width);
  }

  void ToIndex(const double x[3], double p[3]) const
  {
    const double* m = this->Grid.GetWorldToIndex();
    for (int r = 0; r < 3; ++r)
    {
      p[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
    }
  }
};

}

#endif
