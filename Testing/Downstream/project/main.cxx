// Uses the installed Tyndall: closed-form transmittance of a cosine noise.
#include "vtkCosineNoise.h"
#include "vtkCosineNoiseSource.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkTransmittanceVolumeMapper.h"

#include <cmath>
#include <iostream>

int main()
{
  vtkNew<vtkCosineNoise> noise;
  noise->SetOffset(-noise->GetMinimumValue());
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double direction[3] = { 0.0, 0.0, 1.0 };
  const double transmittance = noise->ComputeTransmittance(origin, direction, 0.0, 0.1);
  vtkNew<vtkTransmittanceVolumeMapper> mapper; // links Tyndall::Rendering
  mapper->SetTransmittanceMethodToAdaptiveETM();
  vtkNew<vtkCosineNoiseSource> source;
  source->SetWholeExtent(0, 15, 0, 15, 0, 15);
  source->Update();
  std::cout << "downstream: transmittance " << transmittance << ", "
            << source->GetOutput()->GetNumberOfPoints() << " voxels, mapper method "
            << mapper->GetTransmittanceMethodAsString() << std::endl;
  return (transmittance > 0.0 && transmittance < 1.0 &&
           source->GetOutput()->GetNumberOfPoints() == 4096)
    ? 0
    : 1;
}
