#include "vtkCosineNoiseSource.h"

#include "vtkCosineNoise.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkCosineNoiseSource);

namespace
{
// Waves are advanced along a row by complex rotation and restarted exactly
// at whole-extent x indices that are multiples of this block length.
constexpr int kBlock = 16;

inline double SmoothStep(double e0, double e1, double x)
{
  if (e1 <= e0)
  {
    return x < e0 ? 0.0 : 1.0;
  }
  const double t = std::min(std::max((x - e0) / (e1 - e0), 0.0), 1.0);
  return t * t * (3.0 - 2.0 * t);
}

struct WaveTable
{
  std::vector<double> Kx, Ky, Kz, Phase, Amp;
  // cos and sin of the phase advance kx * dx between neighbouring voxels.
  std::vector<double> StepCos, StepSin;
};

// Fills rows [begin, end) of the update extent; row r is (j, k) =
// (ext[2] + r % ny, ext[4] + r / ny).
class RowFiller
{
public:
  vtkCosineNoiseSource* Source;
  vtkCosineNoise* Noise;
  const WaveTable* Waves;
  bool UseTransform;
  double Offset;
  bool Clamp;
  int Ext[6];
  int WholeX0;
  double Origin[3], Spacing[3];
  float* Out;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    const int nx = this->Ext[1] - this->Ext[0] + 1;
    const int ny = this->Ext[3] - this->Ext[2] + 1;
    std::vector<double> envelope(nx), noise(nx);
    for (vtkIdType r = begin; r < end; ++r)
    {
      const int j = this->Ext[2] + static_cast<int>(r % ny);
      const int k = this->Ext[4] + static_cast<int>(r / ny);
      float* row = this->Out + r * nx;
      double x[3] = { 0.0, this->Origin[1] + j * this->Spacing[1],
        this->Origin[2] + k * this->Spacing[2] };
      bool any = false;
      for (int i = 0; i < nx; ++i)
      {
        x[0] = this->Origin[0] + (this->Ext[0] + i) * this->Spacing[0];
        envelope[i] = this->Source->EvaluateEnvelope(x);
        any = any || envelope[i] > 0.0;
      }
      if (!any)
      {
        std::fill(row, row + nx, 0.0f);
        continue;
      }
      if (this->UseTransform)
      {
        for (int i = 0; i < nx; ++i)
        {
          x[0] = this->Origin[0] + (this->Ext[0] + i) * this->Spacing[0];
          noise[i] = this->Noise->FunctionValue(x);
        }
      }
      else
      {
        this->SumWaves(x[1], x[2], noise.data());
      }
      for (int i = 0; i < nx; ++i)
      {
        const double n = this->Clamp ? std::max(0.0, noise[i]) : noise[i];
        row[i] = static_cast<float>(envelope[i] * n);
      }
    }
  }

  // noise[i] for the row at (y, z), by blocks aligned to the whole extent.
  void SumWaves(double y, double z, double* noise) const
  {
    const WaveTable& w = *this->Waves;
    const size_t nWaves = w.Amp.size();
    const int iEnd = this->Ext[1] + 1;
    int i = this->Ext[0];
    while (i < iEnd)
    {
      const int blockStart = this->WholeX0 + ((i - this->WholeX0) / kBlock) * kBlock;
      const int blockEnd = std::min(blockStart + kBlock, iEnd);
      double acc[kBlock] = { 0.0 };
      const double xStart = this->Origin[0] + blockStart * this->Spacing[0];
      for (size_t j = 0; j < nWaves; ++j)
      {
        const double theta = w.Kx[j] * xStart + w.Ky[j] * y + w.Kz[j] * z + w.Phase[j];
        double c = std::cos(theta);
        double s = std::sin(theta);
        const double dc = w.StepCos[j], ds = w.StepSin[j], a = w.Amp[j];
        for (int b = blockStart; b < blockEnd; ++b)
        {
          acc[b - blockStart] += a * c;
          const double cNext = c * dc - s * ds;
          s = s * dc + c * ds;
          c = cNext;
        }
      }
      for (int b = i; b < blockEnd; ++b)
      {
        noise[b - this->Ext[0]] = this->Offset + acc[b - blockStart];
      }
      i = blockEnd;
    }
  }
};
}

//------------------------------------------------------------------------------
vtkCosineNoiseSource::vtkCosineNoiseSource()
{
  this->SetNumberOfInputPorts(0);
  vtkNew<vtkCosineNoise> noise;
  noise->SetNumberOfOctaves(6);
  noise->SetFrequency(1.0);
  noise->SetGain(0.55);
  noise->SetOffset(1.5);
  this->SetNoise(noise);
}

//------------------------------------------------------------------------------
vtkCosineNoiseSource::~vtkCosineNoiseSource()
{
  if (this->Noise)
  {
    this->Noise->UnRegister(this);
  }
}

//------------------------------------------------------------------------------
void vtkCosineNoiseSource::SetNoise(vtkCosineNoise* noise)
{
  if (!noise)
  {
    vtkErrorMacro(<< "SetNoise: the noise cannot be null; keeping the current one.");
    return;
  }
  if (noise == this->Noise)
  {
    return;
  }
  if (this->Noise)
  {
    this->Noise->UnRegister(this);
  }
  this->Noise = noise;
  this->Noise->Register(this);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCosineNoiseSource::GetMTime()
{
  vtkMTimeType mtime = this->Superclass::GetMTime();
  if (this->Noise)
  {
    mtime = std::max(mtime, this->Noise->GetMTime());
  }
  return mtime;
}

//------------------------------------------------------------------------------
double vtkCosineNoiseSource::EvaluateEnvelope(const double x[3])
{
  double r2 = 0.0;
  switch (this->EnvelopeType)
  {
    case ENVELOPE_SPHERE:
      for (int c = 0; c < 3; ++c)
      {
        const double d = (x[c] - this->EnvelopeCenter[c]) / this->EnvelopeRadius;
        r2 += d * d;
      }
      break;
    case ENVELOPE_ELLIPSOID:
      for (int c = 0; c < 3; ++c)
      {
        const double d = (x[c] - this->EnvelopeCenter[c]) / this->EnvelopeRadii[c];
        r2 += d * d;
      }
      break;
    default:
      return 1.0;
  }
  if (r2 >= 1.0)
  {
    return 0.0;
  }
  return 1.0 - SmoothStep(1.0 - this->EnvelopeFalloff, 1.0, std::sqrt(r2));
}

//------------------------------------------------------------------------------
bool vtkCosineNoiseSource::CheckParameters()
{
  const int* e = this->WholeExtent;
  if (e[0] > e[1] || e[2] > e[3] || e[4] > e[5])
  {
    vtkErrorMacro(<< "The whole extent (" << e[0] << ", " << e[1] << ", " << e[2] << ", " << e[3]
                  << ", " << e[4] << ", " << e[5] << ") is empty or inverted.");
    return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    if (!(this->Spacing[c] > 0.0) || !std::isfinite(this->Spacing[c]))
    {
      vtkErrorMacro(<< "The spacing must be positive and finite; axis " << c << " has "
                    << this->Spacing[c] << ".");
      return false;
    }
    if (!std::isfinite(this->Origin[c]) || !std::isfinite(this->EnvelopeCenter[c]))
    {
      vtkErrorMacro(<< "The origin and the envelope centre must be finite.");
      return false;
    }
    if (this->EnvelopeType == ENVELOPE_ELLIPSOID &&
      (!(this->EnvelopeRadii[c] > 0.0) || !std::isfinite(this->EnvelopeRadii[c])))
    {
      vtkErrorMacro(<< "The ellipsoid envelope's radii must be positive and finite; axis " << c
                    << " has " << this->EnvelopeRadii[c] << ".");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkCosineNoiseSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  static const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  const bool valid = this->CheckParameters();
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), valid ? this->WholeExtent : emptyExtent, 6);
  const double unitSpacing[3] = { 1.0, 1.0, 1.0 };
  const double zeroOrigin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkDataObject::SPACING(), valid ? this->Spacing : unitSpacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), valid ? this->Origin : zeroOrigin, 3);
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCosineNoiseSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  if (!this->CheckParameters())
  {
    return 1;
  }

  int ext[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), ext);
  if (ext[0] > ext[1] || ext[2] > ext[3] || ext[4] > ext[5])
  {
    return 1; // an empty request gets an empty image
  }
  const vtkIdType nx = ext[1] - ext[0] + 1;
  const vtkIdType ny = ext[3] - ext[2] + 1;
  const vtkIdType nz = ext[5] - ext[4] + 1;
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  const vtkIdType maxTuples = VTK_ID_MAX / 4;
  if (nx * ny > maxTuples / nz || !density->Allocate(nx * ny * nz))
  {
    vtkErrorMacro(<< "Cannot allocate " << nx << " x " << ny << " x " << nz
                  << " float voxels; request a smaller extent or stream it in pieces.");
    return 1;
  }
  density->SetNumberOfTuples(nx * ny * nz);
  output->SetExtent(ext);
  output->SetSpacing(this->Spacing);
  output->SetOrigin(this->Origin);
  output->GetPointData()->SetScalars(density);

  // The wave table, with the per-voxel phase advance along x.
  WaveTable waves;
  const int nWaves = this->Noise->GetNumberOfWaves();
  for (int j = 0; j < nWaves; ++j)
  {
    double k[3], phase, amplitude;
    this->Noise->GetWave(j, k, phase, amplitude);
    waves.Kx.push_back(k[0]);
    waves.Ky.push_back(k[1]);
    waves.Kz.push_back(k[2]);
    waves.Phase.push_back(phase);
    waves.Amp.push_back(amplitude);
    waves.StepCos.push_back(std::cos(k[0] * this->Spacing[0]));
    waves.StepSin.push_back(std::sin(k[0] * this->Spacing[0]));
  }
  // Evaluate once so the noise's own table is built before threads start.
  double probe[3] = { 0.0, 0.0, 0.0 };
  this->Noise->FunctionValue(probe);

  RowFiller filler;
  filler.Source = this;
  filler.Noise = this->Noise;
  filler.Waves = &waves;
  filler.UseTransform = this->Noise->GetTransform() != nullptr;
  filler.Offset = this->Noise->GetOffset();
  filler.Clamp = this->ClampNegative;
  std::copy(ext, ext + 6, filler.Ext);
  filler.WholeX0 = this->WholeExtent[0];
  std::copy(this->Origin, this->Origin + 3, filler.Origin);
  std::copy(this->Spacing, this->Spacing + 3, filler.Spacing);
  filler.Out = density->GetPointer(0);

  // Batches of rows, with progress and abort checks between them.
  const vtkIdType rows = ny * nz;
  const vtkIdType batches = std::min<vtkIdType>(rows, 20);
  this->UpdateProgress(0.0);
  for (vtkIdType b = 0; b < batches && !this->AbortExecute; ++b)
  {
    const vtkIdType begin = rows * b / batches;
    const vtkIdType end = rows * (b + 1) / batches;
    vtkSMPTools::For(begin, end, std::max<vtkIdType>(1, (end - begin) / 64), filler);
    this->UpdateProgress(static_cast<double>(b + 1) / batches);
  }
  if (this->AbortExecute)
  {
    output->Initialize();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkCosineNoiseSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Noise: " << this->Noise << "\n";
  os << indent << "WholeExtent: (" << this->WholeExtent[0] << ", " << this->WholeExtent[1] << ", "
     << this->WholeExtent[2] << ", " << this->WholeExtent[3] << ", " << this->WholeExtent[4] << ", "
     << this->WholeExtent[5] << ")\n";
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Spacing: (" << this->Spacing[0] << ", " << this->Spacing[1] << ", "
     << this->Spacing[2] << ")\n";
  os << indent << "EnvelopeType: " << this->EnvelopeType << "\n";
  os << indent << "EnvelopeCenter: (" << this->EnvelopeCenter[0] << ", " << this->EnvelopeCenter[1]
     << ", " << this->EnvelopeCenter[2] << ")\n";
  os << indent << "EnvelopeRadius: " << this->EnvelopeRadius << "\n";
  os << indent << "EnvelopeRadii: (" << this->EnvelopeRadii[0] << ", " << this->EnvelopeRadii[1]
     << ", " << this->EnvelopeRadii[2] << ")\n";
  os << indent << "EnvelopeFalloff: " << this->EnvelopeFalloff << "\n";
  os << indent << "ClampNegative: " << (this->ClampNegative ? "On" : "Off") << "\n";
}
