// Baseline comparison for Tyndall's rendering tests. Header only; not part
// of the library.
//
// VTK's vtkRegressionTestImage forgives per-pixel differences below a
// threshold (after averaging and shifting), which lets soft images such as
// clouds change visibly and still pass. Tyndall's rendering tests therefore
// run VTK's comparison (for the standard -V/-T handling and dashboard
// output) and also require a minimum PSNR of the whole RGB image against the
// same baseline.
#ifndef TyndallTestImage_h
#define TyndallTestImage_h

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace tyndall_test
{
// PSNR in dB of two 8-bit images over their first three components; -1 when
// their sizes or component counts differ, +inf when they are identical.
inline double PSNR(vtkImageData* a, vtkImageData* b)
{
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  if (da[0] != db[0] || da[1] != db[1] || a->GetNumberOfScalarComponents() < 3 ||
    b->GetNumberOfScalarComponents() < 3 || a->GetScalarType() != VTK_UNSIGNED_CHAR ||
    b->GetScalarType() != VTK_UNSIGNED_CHAR)
  {
    return -1.0;
  }
  const int ca = a->GetNumberOfScalarComponents(), cb = b->GetNumberOfScalarComponents();
  const auto* pa = static_cast<unsigned char*>(a->GetScalarPointer());
  const auto* pb = static_cast<unsigned char*>(b->GetScalarPointer());
  const size_t n = static_cast<size_t>(da[0]) * da[1];
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double d = double(pa[i * ca + c]) - double(pb[i * cb + c]);
      sum += d * d;
    }
  }
  const double mse = sum / (3.0 * n);
  return mse == 0.0 ? std::numeric_limits<double>::infinity()
                    : 10.0 * std::log10(255.0 * 255.0 / mse);
}

// The window's back buffer as a new 8-bit image.
inline vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

/// Pixels of an 8-bit picture more than 10 levels from `background` (RGB in [0, 1]).
inline int CountDrawn(vtkImageData* image, const double background[3])
{
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  const int components = image->GetNumberOfScalarComponents();
  int count = 0;
  for (vtkIdType n = 0; n < image->GetNumberOfPoints(); ++n, p += components)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::abs(p[c] - 255.0 * background[c]) > 10.0)
      {
        ++count;
        break;
      }
    }
  }
  return count;
}

// The largest difference of two 8-bit images of the same size, in any value.
inline int MaxDifference(vtkImageData* a, vtkImageData* b)
{
  const auto* pa = static_cast<const unsigned char*>(a->GetScalarPointer());
  const auto* pb = static_cast<const unsigned char*>(b->GetScalarPointer());
  const vtkIdType n = a->GetNumberOfPoints() * a->GetNumberOfScalarComponents();
  int worst = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int d = static_cast<int>(pa[i]) - static_cast<int>(pb[i]);
    worst = d > worst ? d : (-d > worst ? -d : worst);
  }
  return worst;
}

// VTK's regression test plus a PSNR floor against the same baseline.
// Returns vtkRegressionTester's result codes (FAILED, PASSED, DO_INTERACTOR).
inline int RegressionTestWithPSNR(int argc, char* argv[], vtkRenderWindow* window, double minPSNR)
{
  const int vtkResult = vtkRegressionTestImage(window);
  if (vtkResult != vtkTesting::PASSED)
  {
    return vtkResult;
  }
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    testing->AddArgument(argv[i]);
  }
  if (!testing->IsValidImageSpecified())
  {
    return vtkResult;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(testing->GetValidImageFileName());
  reader->Update();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  const double psnr = PSNR(grab->GetOutput(), reader->GetOutput());
  std::cout << "<DartMeasurement name=\"PSNR\" type=\"numeric/double\">" << psnr
            << "</DartMeasurement>" << std::endl;
  std::cout << "PSNR against the baseline: " << psnr << " dB (floor " << minPSNR << " dB)"
            << std::endl;
  if (!(psnr >= minPSNR))
  {
    // VTK's comparison passed, so it wrote no candidate: write it here, where
    // Documentation/testing.md says candidates are.
    std::string name = testing->GetValidImageFileName();
    name = name.substr(name.find_last_of("/\\") + 1);
    const std::string candidate = std::string(testing->GetTempDirectory()) + "/" + name;
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(candidate.c_str());
    writer->Write();
    std::cout << "<DartMeasurementFile name=\"TestImage\" type=\"image/png\">" << candidate
              << "</DartMeasurementFile>" << std::endl;
    std::cerr << "Failed Image Test: PSNR " << psnr << " dB is below " << minPSNR
              << " dB; candidate image: " << candidate << std::endl;
    return vtkTesting::FAILED;
  }
  return vtkResult;
}

// The linear "Radiance" array of a CPU renderer's image
// (vtkSingleScatteringReference, vtkVolumetricPathTracer), every component
// in order.
inline std::vector<double> RadianceValues(vtkImageData* image)
{
  vtkDataArray* array = image->GetPointData()->GetArray("Radiance");
  std::vector<double> values(static_cast<size_t>(array->GetNumberOfValues()));
  for (size_t i = 0; i < values.size(); ++i)
  {
    values[i] = array->GetVariantValue(static_cast<vtkIdType>(i)).ToDouble();
  }
  return values;
}

// The 8-bit picture of several CPU reference images (grey media: one
// "Transmittance" component) composited front to back over `background`:
// each image's radiance attenuated by the transmittance of those in front,
// the background by all of them (vtkTyndallReferenceScene::Composite()'s
// rounding). Exact where the media lie one behind the other along every
// ray, or where their pictures do not overlap. Empty when an array is missing.
inline vtkSmartPointer<vtkImageData> CompositeFrontToBack(
  const std::vector<vtkImageData*>& images, const double background[3])
{
  auto picture = vtkSmartPointer<vtkImageData>::New();
  if (images.empty())
  {
    return picture;
  }
  const int* dims = images[0]->GetDimensions();
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<vtkDataArray*> L, T;
  for (vtkImageData* image : images)
  {
    L.push_back(image->GetPointData()->GetArray("Radiance"));
    T.push_back(image->GetPointData()->GetArray("Transmittance"));
    if (!L.back() || !T.back() || L.back()->GetNumberOfTuples() != n ||
      T.back()->GetNumberOfTuples() != n)
    {
      return picture;
    }
  }
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double color[3] = { 0.0, 0.0, 0.0 }, transmittance = 1.0;
    for (size_t k = 0; k < images.size(); ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        color[c] += transmittance * L[k]->GetComponent(i, c);
      }
      transmittance *= T[k]->GetComponent(i, 0);
    }
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(1.0, std::max(0.0, color[c] + transmittance * background[c]));
      rgb->SetComponent(i, c, std::floor(v * 255.0 + 0.5));
    }
  }
  picture->SetDimensions(dims[0], dims[1], 1);
  picture->GetPointData()->SetScalars(rgb);
  return picture;
}

// The root mean square difference of two arrays of the same size.
inline double RMS(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    sum += (a[i] - b[i]) * (a[i] - b[i]);
  }
  return std::sqrt(sum / static_cast<double>(a.size()));
}
}

#endif
