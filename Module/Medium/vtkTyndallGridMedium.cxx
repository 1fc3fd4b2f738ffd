#include "vtkTyndallGridMedium.h"

#include "vtkAbstractMapper.h"
#include "vtkAbstractVolumeMapper.h"
#include "vtkAlgorithm.h"
#include "vtkBlackbody.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkParticipatingMediumMapper.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTransmittanceMapMath.h"
#include "vtkTyndallProjection.h"
#include "vtkTyndallVolumeSettings.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace
{
// Each component's finite range (of `components` per sample, n samples),
// the count of samples with a NaN component and of infinite values.
template <typename T>
void ScanScalars(
  const T* data, vtkIdType n, int components, double range[][2], vtkIdType& nan, vtkIdType& inf)
{
  for (int c = 0; c < components; ++c)
  {
    range[c][0] = std::numeric_limits<double>::infinity();
    range[c][1] = -std::numeric_limits<double>::infinity();
  }
  nan = inf = 0;
  if constexpr (std::numeric_limits<T>::is_integer)
  {
    // No NaN or infinity: each component's range in T (a loop the compiler
    // vectorises; a 1024^3 volume of bytes took 1.2 s the general way).
    for (int c = 0; c < components; ++c)
    {
      T lo = std::numeric_limits<T>::max(), hi = std::numeric_limits<T>::lowest();
      for (vtkIdType i = c; i < n * components; i += components)
      {
        lo = std::min(lo, data[i]);
        hi = std::max(hi, data[i]);
      }
      range[c][0] = n > 0 ? static_cast<double>(lo) : range[c][0];
      range[c][1] = n > 0 ? static_cast<double>(hi) : range[c][1];
    }
    return;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    bool missing = false;
    for (int c = 0; c < components; ++c)
    {
      const double v = static_cast<double>(data[i * components + c]);
      if (std::isnan(v))
      {
        missing = true;
      }
      else if (std::isinf(v))
      {
        ++inf;
      }
      else
      {
        range[c][0] = std::min(range[c][0], v);
        range[c][1] = std::max(range[c][1], v);
      }
    }
    nan += missing ? 1 : 0;
  }
}

// The component whose isosurfaces VTK 9.1 draws of `count` independent
// components: the first of the largest weight.
int IsoComponent(vtkVolumeProperty* property, int count)
{
  int chosen = 0;
  for (int c = 1; c < count && c < 4; ++c)
  {
    chosen = property->GetComponentWeight(c) > property->GetComponentWeight(chosen) ? c : chosen;
  }
  return chosen;
}

// vtkParticipatingMediumMapper's vector mode applied to `scalars` (several
// components): their magnitude, or one component (null, with `error`, for a
// component they lack).
vtkSmartPointer<vtkDataArray> VectorScalars(
  vtkDataArray* scalars, int mode, int component, std::ostream& error)
{
  const int count = scalars->GetNumberOfComponents();
  vtkSmartPointer<vtkDataArray> one;
  if (mode == vtkParticipatingMediumMapper::COMPONENT)
  {
    if (component >= count)
    {
      error << "The mapper's vector mode draws component " << component << "; the scalars '"
            << (scalars->GetName() ? scalars->GetName() : "") << "' have " << count << ".";
      return nullptr;
    }
    one.TakeReference(scalars->NewInstance());
    one->SetNumberOfComponents(1);
    one->SetNumberOfTuples(scalars->GetNumberOfTuples());
    one->CopyComponent(0, scalars, component);
  }
  else
  {
    one = vtkSmartPointer<vtkDoubleArray>::New();
    one->SetNumberOfTuples(scalars->GetNumberOfTuples());
    std::vector<double> tuple(static_cast<size_t>(count));
    for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
    {
      scalars->GetTuple(i, tuple.data());
      double sum = 0.0;
      for (double v : tuple)
      {
        sum += v * v;
      }
      one->SetComponent(i, 0, std::sqrt(sum));
    }
  }
  one->SetName(scalars->GetName());
  return one;
}

bool AllFinite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
class vtkTyndallGridMedium::FieldBase
{
public:
  virtual ~FieldBase() = default;
  virtual double Scalar(const double p[3]) const = 0;
  virtual void Values(const double p[3], double* values) const = 0;
};

template <typename T>
class vtkTyndallGridMedium::TypedField : public vtkTyndallGridMedium::FieldBase
{
public:
  TypedField(const vtkTyndallGridMedium& medium, int component)
    : S(medium, component)
  {
  }
  double Scalar(const double p[3]) const override { return this->S.Scalar(p); }
  void Values(const double p[3], double* values) const override { this->S.Values(p, values); }

private:
  Sampler<T> S;
};

//------------------------------------------------------------------------------
vtkTyndallGridMedium::vtkTyndallGridMedium() = default;

//------------------------------------------------------------------------------
vtkTyndallGridMedium::~vtkTyndallGridMedium() = default;

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::Update(vtkVolume* volume, vtkObject* reporter)
{
  // VTK's meaning of a plain property's interpolation: nearest is honoured.
  vtkVolumeProperty* property = volume ? volume->GetProperty() : nullptr;
  const bool nearest = property && !vtkParticipatingMediumProperty::SafeDownCast(property) &&
    property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION && !this->GetLinearExtinction();
  if (nearest != this->Nearest)
  {
    this->Nearest = nearest;
    this->Field.clear();
    this->ExtinctionTime.Modified(); // the maps see the other interpolation
  }
  // The blend mode first: the table reads it (gradient opacity is not
  // projected but in the slice).
  auto* volumeMapper = volume ? vtkVolumeMapper::SafeDownCast(volume->GetMapper()) : nullptr;
  this->Projection.Read(volumeMapper, property);
  this->Shading.Read(volumeMapper, property);
  std::string isoError;
  if (!this->Isosurfaces.Read(volumeMapper, property, isoError))
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot draw the volume's isosurfaces: " << isoError);
    this->Valid = false;
    return false;
  }
  this->Valid = this->UpdateScalars(volume, reporter) && this->UpdateMask(volume, reporter) &&
    this->UpdateEmissionArray(volume, reporter) && this->UpdateComponents(volume, reporter) &&
    this->UpdateGeometry(volume, reporter) && this->UpdateTable(volume, reporter);
  if (this->Valid && this->Field.empty())
  {
    this->MakeField();
  }
  if (this->Valid && this->Clip.Update(volume, this->IndexToWorld, this->IndexToData, reporter))
  {
    this->ExtinctionTime.Modified(); // the maps see the clipped medium
  }
  return this->Valid;
}

//------------------------------------------------------------------------------
vtkDataSet* vtkTyndallGridMedium::ReadInput(vtkVolume* volume, vtkObject* reporter)
{
  vtkAbstractVolumeMapper* mapper = volume ? volume->GetMapper() : nullptr;
  if (!mapper)
  {
    vtkErrorWithObjectMacro(reporter, << "The volume has no mapper.");
    return nullptr;
  }
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    int port = 0;
    if (vtkAlgorithm* producer = mapper->GetInputAlgorithm(0, 0, port))
    {
      producer->Update(port);
    }
  }
  // A Tyndall mapper's medium image (its input, or a particle mapper's
  // grid), else the mapper's input.
  auto* tyndall = vtkParticipatingMediumMapper::SafeDownCast(mapper);
  vtkDataSet* input = tyndall ? tyndall->GetMediumImage() : mapper->GetDataSetInput();
  if (!vtkImageData::SafeDownCast(input))
  {
    vtkErrorWithObjectMacro(reporter, << (input ? "The input is a " : "There is no input")
                                      << (input ? input->GetClassName() : "")
                                      << "; a vtkImageData is needed.");
    return nullptr;
  }
  return input;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateScalars(vtkVolume* volume, vtkObject* reporter)
{
  this->Input = vtkImageData::SafeDownCast(this->ReadInput(volume, reporter));
  vtkImageData* image = this->Input;
  if (!image)
  {
    return false;
  }
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  // The image's MTime, not only its extent: VTK's convention lets a program
  // edit the values in place and mark the image (not the array) modified.
  // A spacing or origin change then rescans too, which is rare.
  // vtkSmartVolumeMapper's vector mode (a Tyndall mapper's): independent
  // components drawn as their magnitude or one of them.
  auto* tyndall = vtkParticipatingMediumMapper::SafeDownCast(mapper);
  vtkVolumeProperty* property = volume->GetProperty();
  const bool independent = property && property->GetIndependentComponents() && scalars &&
    scalars->GetNumberOfComponents() > 1;
  int vectorMode =
    tyndall && independent ? tyndall->GetVectorMode() : vtkParticipatingMediumMapper::DISABLED;
  int vectorComponent = tyndall ? tyndall->GetVectorComponent() : 0;
  // VTK 9.1's isosurfaces of independent components are those of the
  // component of the largest weight (the first of equal ones) with its
  // functions, its values compared on component 0's range: drawn here when
  // that is component 0, as that one component (else UpdateComponents()
  // refuses them).
  if (independent && vectorMode == vtkParticipatingMediumMapper::DISABLED &&
    this->Isosurfaces.Enabled() && IsoComponent(property, scalars->GetNumberOfComponents()) == 0)
  {
    vectorMode = vtkParticipatingMediumMapper::COMPONENT;
    vectorComponent = 0;
  }
  const std::vector<double> key = { static_cast<double>(reinterpret_cast<uintptr_t>(image)),
    static_cast<double>(image->GetMTime()),
    static_cast<double>(reinterpret_cast<uintptr_t>(scalars)),
    scalars ? static_cast<double>(scalars->GetMTime()) : -1.0, double(cellFlag), double(vectorMode),
    double(vectorComponent) };
  if (key == this->ScalarsKey)
  {
    // Unchanged: the same result, and the same error again without a rescan.
    if (!this->Scalars)
    {
      vtkErrorWithObjectMacro(reporter, << this->ScalarsError);
    }
    return this->Scalars != nullptr;
  }
  this->ScalarsKey = key;
  this->Scalars = nullptr;
  this->Field.clear();
  this->ScalarsTime.Modified();
  std::ostringstream error;
  vtkSmartPointer<vtkDataArray> derived;
  if (vectorMode != vtkParticipatingMediumMapper::DISABLED)
  {
    derived = VectorScalars(scalars, vectorMode, vectorComponent, error);
  }
  const bool ok = (vectorMode == vtkParticipatingMediumMapper::DISABLED || derived) &&
    this->ReadScalars(image, derived ? derived.Get() : scalars, cellFlag, error, reporter);
  this->ScalarsError = error.str();
  if (!ok)
  {
    vtkErrorWithObjectMacro(reporter, << this->ScalarsError);
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateMask(vtkVolume* volume, vtkObject* reporter)
{
  auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper());
  vtkImageData* mask = mapper ? mapper->GetMaskInput() : nullptr;
  const bool labels =
    mask && mapper->GetMaskType() == vtkParticipatingMediumMapper::LabelMapMaskType;
  vtkDataArray* values = nullptr;
  if (mask)
  {
    values =
      this->CellScalars ? mask->GetCellData()->GetScalars() : mask->GetPointData()->GetScalars();
  }
  // The mask's values and what they lie on (the scalars' samples, read first).
  std::vector<double> key = { static_cast<double>(reinterpret_cast<uintptr_t>(mask)),
    mask ? static_cast<double>(mask->GetMTime()) : -1.0, double(labels),
    static_cast<double>(reinterpret_cast<uintptr_t>(values)),
    values ? static_cast<double>(values->GetMTime()) : -1.0 };
  key.insert(key.end(), this->ScalarsKey.begin(), this->ScalarsKey.end());
  if (key == this->MaskKey)
  {
    return true;
  }
  this->MaskKey = key;
  this->Mask.clear();
  this->LabelMap.Clear();
  this->TableKey.clear(); // the label rows and bound follow the labels
  this->MaskedCount = 0;
  this->Field.clear();          // the sampler reads the mask
  this->ScalarsTime.Modified(); // the GPU's validity texture holds it
  this->ExtinctionTime.Modified();
  std::ostringstream error;
  if (mask && !this->ReadMask(mask, labels, error))
  {
    this->MaskKey.clear(); // read again (and said again) next time
    this->Mask.clear();
    this->LabelMap.Clear();
    this->MaskedCount = 0;
    vtkErrorWithObjectMacro(reporter, << "Cannot use the mapper's mask: " << error.str());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::ReadMask(vtkImageData* mask, bool labels, std::ostream& error)
{
  int dims[3];
  mask->GetDimensions(dims);
  const int* own = this->Input->GetDimensions();
  if (dims[0] != own[0] || dims[1] != own[1] || dims[2] != own[2])
  {
    error << "it has " << dims[0] << " x " << dims[1] << " x " << dims[2] << " points, the volume "
          << own[0] << " x " << own[1] << " x " << own[2]
          << "; a mask lies on the volume's samples.";
    return false;
  }
  vtkDataArray* values =
    this->CellScalars ? mask->GetCellData()->GetScalars() : mask->GetPointData()->GetScalars();
  const vtkIdType count =
    static_cast<vtkIdType>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (!values || values->GetNumberOfComponents() != 1 || values->GetNumberOfTuples() != count)
  {
    error << "it needs " << (this->CellScalars ? "cell" : "point")
          << " scalars of one component, one per sample of the volume (" << count << ").";
    return false;
  }
  if (labels)
  {
    return this->LabelMap.ReadLabels(values, count, error);
  }
  this->Mask.resize(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    const bool kept = values->GetComponent(i, 0) > 0.0; // VTK hides 0 or less
    this->Mask[static_cast<size_t>(i)] = kept ? 1 : 0;
    this->MaskedCount += kept ? 0 : 1;
  }
  if (this->MaskedCount == 0)
  {
    this->Mask.clear(); // nothing masked: nothing to check
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::ReadScalars(vtkImageData* image, vtkDataArray* scalars, int cellFlag,
  std::ostream& error, vtkObject* reporter)
{
  int extent[6];
  image->GetExtent(extent);
  int points[3];
  for (int a = 0; a < 3; ++a)
  {
    points[a] = extent[2 * a + 1] - extent[2 * a] + 1;
  }
  if (points[0] < 1 || points[1] < 1 || points[2] < 1)
  {
    error << "The input image is empty.";
    return false;
  }
  if (points[0] < 2 || points[1] < 2 || points[2] < 2)
  {
    error << "The input image is flat (" << points[0] << " x " << points[1] << " x " << points[2]
          << " points): a volume needs at least 2 points along each "
             "axis.";
    return false;
  }
  if (!scalars)
  {
    error << "The input has no scalars to render (check the mapper's "
             "scalar mode and array selection).";
    return false;
  }
  if (cellFlag != 0 && cellFlag != 1)
  {
    error << "The selected scalars are field data, which cannot be rendered.";
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > vtkTyndallComponents::MaximumCount)
  {
    error << "The scalars '" << (scalars->GetName() ? scalars->GetName() : "") << "' have "
          << components << " components; 1 to " << vtkTyndallComponents::MaximumCount
          << " are drawn (VTK's mappers draw at most 4).";
    return false;
  }
  this->CellScalars = cellFlag == 1;
  for (int a = 0; a < 3; ++a)
  {
    this->Dimensions[a] = this->CellScalars ? points[a] - 1 : points[a];
    this->Extent[2 * a] = extent[2 * a];
    this->Extent[2 * a + 1] = extent[2 * a + 1];
  }
  const vtkIdType expected =
    static_cast<vtkIdType>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (scalars->GetNumberOfTuples() != expected)
  {
    error << "The scalars have " << scalars->GetNumberOfTuples() << " values; the image needs "
          << expected << ".";
    return false;
  }

  // Raw access: the array itself, or a copy in doubles (other layouts, types).
  vtkSmartPointer<vtkDataArray> values = scalars;
  bool supported = false;
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(supported = true);
  }
  if (!supported || !scalars->HasStandardMemoryLayout())
  {
    vtkNew<vtkDoubleArray> copy;
    copy->DeepCopy(scalars);
    values = copy;
  }
  switch (values->GetDataType())
  {
    vtkTemplateMacro(ScanScalars(static_cast<const VTK_TT*>(values->GetVoidPointer(0)), expected,
      components, this->ComponentRanges, this->NaNCount, this->InfCount));
  }
  for (int c = 0; c < components; ++c)
  {
    if (!(this->ComponentRanges[c][0] <= this->ComponentRanges[c][1]))
    {
      error << "The scalars have no finite value"
            << (components > 1 ? " in component " + std::to_string(c) : std::string()) << ".";
      return false;
    }
  }
  this->FiniteRange[0] = this->ComponentRanges[0][0];
  this->FiniteRange[1] = this->ComponentRanges[0][1];
  if (this->NaNCount > 0 || this->InfCount > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << this->NaNCount << (components > 1 ? " samples with a NaN component" : " NaN scalars")
      << " (missing data: samples interpolated from them are empty medium) and " << this->InfCount
      << " infinite values (given the finite range's ends, [" << this->FiniteRange[0] << ", "
      << this->FiniteRange[1] << "]" << (components > 1 ? " for component 0" : "") << ").");
  }
  this->Scalars = values;
  this->MakeField();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::IndexDifferences(const double p[3], double g[3], int component) const
{
  // Several components: each difference of the one asked for, missing
  // where any component is (the GPU's validity).
  auto value = [this, component](const double q[3])
  {
    double values[vtkTyndallComponents::MaximumCount];
    return !this->Components.Enabled()
      ? this->FieldScalar(q)
      : (this->FieldComponents(q, values) ? values[component]
                                          : std::numeric_limits<double>::quiet_NaN());
  };
  for (int a = 0; a < 3; ++a)
  {
    double plus[3] = { p[0], p[1], p[2] }, minus[3] = { p[0], p[1], p[2] };
    plus[a] += 1.0;
    minus[a] -= 1.0;
    g[a] = 0.5 * (value(plus) - value(minus));
    if (std::isnan(g[a]))
    {
      g[0] = g[1] = g[2] = 0.0;
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallGridMedium::FieldGradient(const double p[3], double gradient[3], int component) const
{
  double g[3];
  this->IndexDifferences(p, g, component); // 0 at missing data
  // p = W x (W: world -> index): d/dx = W^T d/dp.
  const double* w = this->WorldToIndex;
  for (int j = 0; j < 3; ++j)
  {
    gradient[j] = w[j] * g[0] + w[4 + j] * g[1] + w[8 + j] * g[2];
  }
}

//------------------------------------------------------------------------------
void vtkTyndallGridMedium::MakeField()
{
  this->Field.clear();
  for (int c = 0; c < this->Scalars->GetNumberOfComponents(); ++c)
  {
    switch (this->Scalars->GetDataType())
    {
      vtkTemplateMacro(this->Field.emplace_back(new TypedField<VTK_TT>(*this, c)));
    }
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateEmissionArray(vtkVolume* volume, vtkObject* reporter)
{
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(volume->GetProperty());
  const char* name = medium ? medium->GetEmissionArrayName() : nullptr;
  vtkImageData* image = this->Input;
  vtkDataSetAttributes* data = this->CellScalars
    ? static_cast<vtkDataSetAttributes*>(image->GetCellData())
    : static_cast<vtkDataSetAttributes*>(image->GetPointData());
  vtkDataArray* array = name && *name ? data->GetArray(name) : nullptr;
  const std::vector<double> key = { static_cast<double>(reinterpret_cast<uintptr_t>(array)),
    array ? static_cast<double>(array->GetMTime()) : -1.0, static_cast<double>(image->GetMTime()),
    static_cast<double>(reinterpret_cast<uintptr_t>(this->Scalars.Get())) };
  const bool wanted = name && *name;
  if (!wanted)
  {
    if (!this->EmissionValues.empty())
    {
      this->EmissionValues.clear();
      this->EmissionArrayTime.Modified(); // the GPU drops its texture
    }
    this->EmissionKey.clear();
    return true;
  }
  if (!array || array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() != this->Scalars->GetNumberOfTuples())
  {
    if (array)
    {
      vtkErrorWithObjectMacro(reporter, << "The emission array '" << name
                                        << "' must have one component and one value per sample "
                                           "of the rendered scalars.");
    }
    else
    {
      vtkErrorWithObjectMacro(reporter, << "The emission array '" << name
                                        << "' is not in the input's "
                                        << (this->CellScalars ? "cell" : "point") << " data.");
    }
    this->EmissionValues.clear();
    this->EmissionKey.clear();
    return false;
  }
  if (key == this->EmissionKey)
  {
    return true;
  }
  this->EmissionKey = key;
  const vtkIdType n = array->GetNumberOfTuples();
  this->EmissionValues.resize(static_cast<size_t>(n));
  double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double v = array->GetComponent(i, 0);
    this->EmissionValues[i] = static_cast<float>(v);
    if (std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi))
  {
    lo = hi = 0.0;
  }
  for (float& v : this->EmissionValues)
  {
    v = std::isfinite(v) ? v : static_cast<float>(lo); // non-finite: the coolest value
  }
  this->EmissionRange[0] = lo;
  this->EmissionRange[1] = hi;
  this->EmissionArrayTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::EmissionValue(const double p[3]) const
{
  return Sampler<float>(*this, this->EmissionValues.data()).Scalar(p);
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateGeometry(vtkVolume* volume, vtkObject* reporter)
{
  vtkImageData* image = this->Input;
  const double* spacing = image->GetSpacing();
  const double* origin = image->GetOrigin();
  const double* direction = image->GetDirectionMatrix()->GetData();
  for (int a = 0; a < 3; ++a)
  {
    if (spacing[a] == 0.0 || !std::isfinite(spacing[a]) || !std::isfinite(origin[a]))
    {
      vtkErrorWithObjectMacro(reporter, << "The input image's spacing must be non-zero and "
                                           "finite, and its origin finite.");
      return false;
    }
  }
  const double directionDeterminant = vtkMatrix3x3::Determinant(direction);
  if (!AllFinite(direction, 9) || directionDeterminant == 0.0 ||
    !std::isfinite(directionDeterminant))
  {
    vtkErrorWithObjectMacro(reporter, << "The input image's direction matrix must be invertible.");
    return false;
  }
  vtkMatrix4x4* matrix = volume->GetMatrix();
  const double(*m)[4] = matrix->Element;
  const double linear[9] = { m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1],
    m[2][2] };
  const double determinant = vtkMatrix3x3::Determinant(linear);
  if (!AllFinite(*matrix->Element, 16) || m[3][0] != 0.0 || m[3][1] != 0.0 || m[3][2] != 0.0 ||
    m[3][3] != 1.0 || determinant == 0.0 || !std::isfinite(determinant))
  {
    vtkErrorWithObjectMacro(reporter, << "The volume's matrix must be affine and invertible.");
    return false;
  }

  // Field index -> data: origin + D diag(spacing) (extent start + index [+ 0.5]).
  const double half = this->CellScalars ? 0.5 : 0.0;
  vtkNew<vtkMatrix4x4> indexToData;
  for (int r = 0; r < 3; ++r)
  {
    double translation = origin[r];
    for (int c = 0; c < 3; ++c)
    {
      const double a = direction[3 * r + c] * spacing[c];
      indexToData->SetElement(r, c, a);
      translation += a * (this->Extent[2 * c] + half);
    }
    indexToData->SetElement(r, 3, translation);
  }
  std::copy(*indexToData->Element, *indexToData->Element + 16, this->IndexToData);
  vtkNew<vtkMatrix4x4> indexToWorld;
  vtkMatrix4x4::Multiply4x4(matrix, indexToData, indexToWorld);
  std::copy(*indexToWorld->Element, *indexToWorld->Element + 16, this->IndexToWorld);
  vtkMatrix4x4::Invert(this->IndexToWorld, this->WorldToIndex);
  for (int a = 0; a < 3; ++a)
  {
    this->BoxLow[a] = -half;
    this->BoxHigh[a] = this->Dimensions[a] - 1 + half;
  }
  // Gradient opacity's change per average voxel: each index axis' data
  // spacing (the length of IndexToData's column), their mean over it.
  double axisSpacing[3], mean = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const double* m = this->IndexToData;
    axisSpacing[a] = std::sqrt(m[a] * m[a] + m[4 + a] * m[4 + a] + m[8 + a] * m[8 + a]);
    mean += axisSpacing[a] / 3.0;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->GradientToVoxel[a] = mean / axisSpacing[a];
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateTable(vtkVolume* volume, vtkObject* reporter)
{
  vtkVolumeProperty* property = volume->GetProperty();
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  vtkColorTransferFunction* emission = medium ? medium->GetEmissionColor() : nullptr;
  const bool fromArray = !this->EmissionValues.empty();
  if (!this->Parameters.Read(property, emission || fromArray, reporter))
  {
    this->TableKey.clear();
    return false;
  }

  // What the table depends on (not the property's other settings: changing
  // the anisotropy or the ambient must not rebuild the GPU's maps), the
  // extinction's part first.
  auto identify = [](std::vector<double>& key, vtkObject* function)
  {
    key.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(function)));
    key.push_back(function ? static_cast<double>(function->GetMTime()) : -1.0);
  };
  std::vector<double> extinction = { property->GetScalarOpacityUnitDistance(0),
    this->FiniteRange[0], this->FiniteRange[1], double(this->GetLinearExtinction()) };
  identify(extinction, property->GetScalarOpacity(0));
  // Multi-component scalars (vtkTyndallComponents): each table's function,
  // range and unit distance, and how the tables mix.
  const vtkTyndallComponents& components = this->Components;
  const int tables = components.GetTableCount();
  extinction.insert(extinction.end(),
    { double(components.GetMode()), double(components.GetCount()),
      double(components.GetAdditive()) });
  extinction.insert(extinction.end(), components.GetWeights(),
    components.GetWeights() + vtkTyndallComponents::MaximumCount);
  for (int t = 0; t < tables; ++t)
  {
    const int c = components.TableComponent(t);
    extinction.insert(extinction.end(),
      { this->ComponentRanges[c][0], this->ComponentRanges[c][1],
        property->GetScalarOpacityUnitDistance(c) });
    identify(extinction, property->GetScalarOpacity(components.TableFunction(t)));
  }
  // Gradient opacity multiplies the extinction (not in a projection, which
  // reads the opacity alone, but the slice's opacity as VTK 9.1 does, nor
  // for isosurfaces, nor for several components, nor with procedural
  // detail, which multiplies the 1-D extinction: vtkTyndallVolumeSettings
  // names them).
  // (A projection draws no detail: the grid's gradient opacity then.)
  const bool detail = medium && medium->GetDetailNoise() && !this->Projection.Enabled();
  const bool projected = this->Projection.Enabled() &&
    !vtkTyndallVolumeSettings::SliceReadsGradient(
      vtkVolumeMapper::SafeDownCast(volume->GetMapper()), property);
  vtkPiecewiseFunction* gradientOpacity = !detail && !projected && !this->Isosurfaces.Enabled() &&
      !this->GetLinearExtinction() && !components.Enabled() &&
      vtkTyndallVolumeSettings::HasGradientOpacity(property)
    ? property->GetGradientOpacity(0)
    : nullptr;
  identify(extinction, gradientOpacity);
  if (gradientOpacity)
  {
    // The change per average voxel depends on the spacings' ratios.
    extinction.insert(extinction.end(), this->GradientToVoxel, this->GradientToVoxel + 3);
  }
  // A 2-D transfer function (TF_2D) replaces the 1-D ones for the medium
  // (not in a projection, for isosurfaces or with procedural detail, which
  // read the 1-D functions, as named by vtkTyndallVolumeSettings); its
  // opacity is per VTK's automatic step, the smallest spacing.
  vtkImageData* transfer2D = !detail && !this->Projection.Enabled() &&
      !this->Isosurfaces.Enabled() && !this->GetLinearExtinction() &&
      property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D
    ? property->GetTransferFunction2D(0)
    : nullptr;
  if (property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D && !detail &&
    !this->Projection.Enabled() && !this->Isosurfaces.Enabled() && !this->GetLinearExtinction() &&
    !transfer2D)
  {
    this->TableKey.clear();
    vtkErrorWithObjectMacro(reporter, << "Cannot use the volume's property: its transfer function "
                                         "mode is TF_2D and it has no 2-D transfer function.");
    return false;
  }
  identify(extinction, transfer2D);
  if (transfer2D)
  {
    extinction.push_back(double(this->Nearest));
    extinction.push_back(this->GetMinimumWorldSpacing());
    extinction.insert(extinction.end(), this->GradientToVoxel, this->GradientToVoxel + 3);
  }
  // A label map's functions, blend and step (vtkTyndallLabelMap).
  const bool labels = this->LabelsApply(property);
  extinction.push_back(double(labels));
  if (labels)
  {
    auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper());
    extinction.push_back(mapper->GetMaskBlendFactor());
    extinction.push_back(this->GetMinimumWorldSpacing());
    for (int label : property->GetLabelMapLabels())
    {
      extinction.push_back(label);
      identify(extinction, property->GetLabelScalarOpacity(label));
    }
  }
  // The isosurfaces are what the light meets instead of the medium.
  extinction.push_back(double(this->Isosurfaces.Enabled()));
  const std::vector<double>& isoValues = this->Isosurfaces.GetValues();
  extinction.insert(extinction.end(), isoValues.begin(), isoValues.end());
  const bool gray = property->GetColorChannels(0) == 1;
  std::vector<double> key = extinction;
  for (int t = 0; t < tables; ++t)
  {
    const int function = components.TableFunction(t);
    const bool grayFunction = property->GetColorChannels(function) == 1;
    key.push_back(double(grayFunction));
    identify(key,
      grayFunction ? static_cast<vtkObject*>(property->GetGrayTransferFunction(function))
                   : static_cast<vtkObject*>(property->GetRGBTransferFunction(function)));
  }
  identify(key, emission);
  if (labels)
  {
    // The labels' colours (the volume's are above).
    for (int label : property->GetLabelMapLabels())
    {
      identify(key, property->GetLabelColor(label));
    }
  }
  const bool blackbody = fromArray && medium->GetBlackbody();
  const double temperatureScale = medium ? medium->GetTemperatureScale() : 1.0;
  if (fromArray)
  {
    key.insert(key.end(),
      { this->EmissionRange[0], this->EmissionRange[1], double(blackbody), temperatureScale,
        static_cast<double>(this->EmissionArrayTime.GetMTime()) });
  }
  if (key == this->TableKey)
  {
    return true;
  }
  this->TableKey.clear();
  this->TableTime.Modified();
  std::string error;
  this->ComponentTables.resize(static_cast<size_t>(tables - 1));
  for (int t = 0; t < tables; ++t)
  {
    const int c = components.TableComponent(t);
    vtkTyndallTransferTable& table = t == 0 ? this->Table : this->ComponentTables[t - 1];
    if (!table.Build(property, emission, this->ComponentRanges[c][0], this->ComponentRanges[c][1],
          error, this->GetLinearExtinction(), components.TableFunction(t), c))
    {
      this->ExtinctionKey.clear();
      vtkErrorWithObjectMacro(reporter, << "Cannot use the volume's property: " << error);
      return false;
    }
  }
  this->Table.TabulateGradientOpacity(gradientOpacity);
  this->LabelMap.ClearRows();
  if (labels)
  {
    auto* mapper = vtkParticipatingMediumMapper::SafeDownCast(volume->GetMapper());
    this->LabelMap.Tabulate(property, this->Table.Minimum, this->Table.Maximum,
      mapper->GetMaskBlendFactor(), this->GetMinimumWorldSpacing());
    this->LabelBoundTable = this->Table;
    this->LabelBoundTable.Extinction = this->LabelMap.Bound(this->Table.Extinction);
  }
  if (transfer2D &&
    !this->Table.Tabulate2D(transfer2D, this->GetMinimumWorldSpacing(), this->Nearest, error))
  {
    this->ExtinctionKey.clear();
    vtkErrorWithObjectMacro(reporter, << "Cannot use the volume's property: " << error);
    return false;
  }
  if (fromArray)
  {
    // The emission colour over the array's range: a black body normalised
    // to luminance 1 at the hottest value, or a colour transfer function.
    const double hottest = this->EmissionRange[1] * temperatureScale;
    vtkColorTransferFunction* colors =
      emission ? emission : (gray ? nullptr : property->GetRGBTransferFunction(0));
    this->Table.TabulateEmission(this->EmissionRange[0], this->EmissionRange[1],
      [&](double v, double rgb[3])
      {
        if (blackbody)
        {
          vtkBlackbody::LinearSRGB(v * temperatureScale, hottest, rgb);
        }
        else if (colors)
        {
          colors->GetColor(v, rgb);
        }
        else
        {
          rgb[0] = rgb[1] = rgb[2] = property->GetGrayTransferFunction(0)->GetValue(v);
        }
      });
  }
  if (extinction != this->ExtinctionKey)
  {
    this->ExtinctionKey = extinction;
    this->ExtinctionTime.Modified();
  }
  this->TableKey = key;
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::WorldExtinction(const double world[3]) const
{
  if (!this->Valid)
  {
    return 0.0;
  }
  double p[3];
  this->ToLocalPoint(world, p);
  if (!InsideBox(p, this->BoxLow, this->BoxHigh))
  {
    return 0.0;
  }
  return this->FieldExtinction(p, nullptr);
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::FieldScalar(const double p[3]) const
{
  return this->Field[0]->Scalar(p);
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::FieldComponents(
  const double p[3], double values[vtkTyndallComponents::MaximumCount]) const
{
  this->Field[0]->Values(p, values);
  for (size_t c = 0; c < this->Field.size(); ++c)
  {
    if (std::isnan(values[c]))
    {
      return false; // missing data
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::TablePosition(const double p[3], int& k, double& f) const
{
  const double s = this->FieldScalar(p);
  if (std::isnan(s))
  {
    return false; // missing data
  }
  this->Table.Locate(s, k, f);
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::GradientMagnitudeAt(const double p[3]) const
{
  double g[3], sum = 0.0;
  this->IndexDifferences(p, g); // 0 at missing data: no gradient
  for (int a = 0; a < 3; ++a)
  {
    const double d = g[a] * this->GradientToVoxel[a];
    sum += d * d;
  }
  return std::sqrt(sum);
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::GradientOpacityAt(const double p[3]) const
{
  return this->GetGradientOpacity() ? this->Table.GradientOpacityAt(this->GradientMagnitudeAt(p))
                                    : 1.0;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::KeptScalar(const double p[3], bool clip, double& value) const
{
  if (clip && !this->Clip.InsideIndex(p))
  {
    return false;
  }
  value = this->FieldScalar(p);
  return !std::isnan(value);
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::KeptComponents(
  const double p[3], bool clip, double values[vtkTyndallComponents::MaximumCount]) const
{
  if (clip && !this->Clip.InsideIndex(p))
  {
    return false;
  }
  return this->FieldComponents(p, values);
}

//------------------------------------------------------------------------------
vtkTyndallProjection::Classes vtkTyndallGridMedium::GetProjectionClasses() const
{
  vtkTyndallProjection::Classes classes;
  classes.Components = &this->Components;
  for (int t = 0; t < vtkTyndallComponents::MaximumCount; ++t)
  {
    classes.Tables[t] = &this->GetComponentTable(t);
    classes.Ranges[t] = this->GetComponentRange(t);
  }
  return classes;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::IsoSample(
  const double p0[3], const double p1[3], double dt, Point& point, double& first) const
{
  double v0, v1, rgb[3], alpha;
  first = 0.0;
  if (!this->KeptScalar(p0, true, v0) || !this->KeptScalar(p1, true, v1) ||
    !this->Isosurfaces.Composite(this->Table, v0, v1, rgb, alpha, first) || !(alpha > 0.0))
  {
    return false;
  }
  alpha = std::min(alpha, vtkTyndallIsosurfaces::MaximumOpacity);
  point.Extinction = -std::log1p(-alpha) / dt;
  for (int c = 0; c < 3; ++c)
  {
    point.Albedo[c] = rgb[c] / alpha;
    point.Emission[c] = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::OpticalDepth(const double o[3], const double d[3], double t0,
  double t1, double step, double maxDepth, bool clip, const PathCache* cache, Work* work) const
{
  if (!this->Isosurfaces.Enabled() || !(step > 0.0))
  {
    return vtkTyndallMedium::OpticalDepth(o, d, t0, t1, step, maxDepth, clip, cache, work);
  }
  if (!ClipToBox(o, d, this->BoxLow, this->BoxHigh, t0, t1))
  {
    return 0.0;
  }
  // The steps of the base class's march (n equal steps over [t0, t1]), each
  // read at its two ends.
  const int n = static_cast<int>(std::max(1.0, std::ceil((t1 - t0) / step)));
  const double dt = (t1 - t0) / n;
  const bool clipped = clip && this->Clip.Enabled();
  double tau = 0.0, v0 = 0.0;
  bool valid0 = false;
  for (int m = 0; m <= n && tau <= maxDepth; ++m)
  {
    const double t = t0 + m * dt;
    const double q[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    double v1;
    const bool valid1 = this->KeptScalar(q, clipped, v1);
    if (valid0 && valid1)
    {
      tau += this->Isosurfaces.OpticalDepth(this->Table, v0, v1);
    }
    v0 = v1;
    valid0 = valid1;
  }
  return tau;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::Transfer2DSample(const double p[3], double rgba[4]) const
{
  const double s = this->FieldScalar(p);
  if (std::isnan(s))
  {
    return false; // missing data
  }
  const vtkTyndallTransferTable& t = this->Table;
  t.Transfer2DAt(t.Unit(s), std::min(this->GradientMagnitudeAt(p) / t.GradientMaximum, 1.0), rgba);
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::Transfer2DExtinction(double opacity) const
{
  return vtkTransmittanceMapMath::ExtinctionFromOpacity(
    std::min(opacity, 0.999999), this->GetMinimumWorldSpacing(), this->Parameters.DensityScale);
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::FieldExtinction(const double p[3], Work*) const
{
  if (this->Components.Enabled())
  {
    Point point;
    return this->ComponentSample(p, point) ? point.Extinction : 0.0;
  }
  if (this->Table.Has2D())
  {
    double rgba[4];
    return this->Transfer2DSample(p, rgba) ? this->Transfer2DExtinction(rgba[3]) : 0.0;
  }
  int k;
  double f;
  if (!this->TablePosition(p, k, f))
  {
    return 0.0;
  }
  const double sigma = this->TableExtinction(p, k, f);
  int label, entry;
  if (!this->LabelAt(p, label, entry))
  {
    return sigma;
  }
  double color[3] = { 0.0, 0.0, 0.0 };
  return this->LabelMap.Mix(label, entry, sigma, this->Parameters.DensityScale, color);
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::TableExtinction(const double p[3], int k, double f) const
{
  return this->Parameters.DensityScale * this->Table.ExtinctionAt(k, f) *
    this->GradientOpacityAt(p);
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::LabelAt(const double p[3], int& label, int& entry) const
{
  if (!this->LabelMap.Enabled())
  {
    return false;
  }
  vtkIdType index = 0, stride = 1;
  for (int a = 0; a < 3; ++a)
  {
    const double i = std::min(std::max(std::floor(p[a] + 0.5), 0.0), this->Dimensions[a] - 1.0);
    index += static_cast<vtkIdType>(i) * stride;
    stride *= this->Dimensions[a];
  }
  label = this->LabelMap.LabelAt(index);
  if (label <= 0)
  {
    return false;
  }
  const double s = this->FieldScalar(p);
  if (std::isnan(s))
  {
    return false;
  }
  entry = vtkTyndallLabelMap::Entry(this->Table.Unit(s));
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::LabelsApply(vtkVolumeProperty* property) const
{
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  return !this->LabelMap.GetLabels().empty() && !this->Projection.Enabled() &&
    !this->Isosurfaces.Enabled() && !this->GetLinearExtinction() && !this->Components.Enabled() &&
    property->GetTransferFunctionMode() != vtkVolumeProperty::TF_2D &&
    !(medium && medium->GetDetailNoise());
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::FieldSample(const double p[3], Point& point, double) const
{
  if (this->Components.Enabled())
  {
    return this->ComponentSample(p, point) && point.Extinction > 0.0;
  }
  if (this->Table.Has2D())
  {
    double rgba[4];
    if (!this->Transfer2DSample(p, rgba))
    {
      return false;
    }
    point.Extinction = this->Transfer2DExtinction(rgba[3]);
    std::copy(rgba, rgba + 3, point.Albedo);
    std::fill(point.Emission, point.Emission + 3, 0.0);
    return point.Extinction > 0.0;
  }
  int k;
  double f;
  if (!this->TablePosition(p, k, f))
  {
    return false;
  }
  point.Extinction = this->TableExtinction(p, k, f);
  int label, entry;
  const bool labelled = this->LabelAt(p, label, entry);
  if (!labelled && !(point.Extinction > 0.0))
  {
    return false;
  }
  this->TableColors(p, k, f, point);
  if (labelled)
  {
    point.Extinction = this->LabelMap.Mix(
      label, entry, point.Extinction, this->Parameters.DensityScale, point.Albedo);
  }
  return point.Extinction > 0.0;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::FieldMaterial(const double p[3], Point& point) const
{
  if (this->Components.Enabled())
  {
    return this->ComponentSample(p, point);
  }
  if (this->Table.Has2D())
  {
    double rgba[4];
    if (!this->Transfer2DSample(p, rgba))
    {
      return false;
    }
    std::copy(rgba, rgba + 3, point.Albedo);
    std::fill(point.Emission, point.Emission + 3, 0.0);
    return true;
  }
  int k;
  double f;
  if (!this->TablePosition(p, k, f))
  {
    return false;
  }
  this->TableColors(p, k, f, point);
  int label, entry;
  if (this->LabelAt(p, label, entry))
  {
    const double sigma = this->TableExtinction(p, k, f);
    this->LabelMap.Mix(label, entry, sigma, this->Parameters.DensityScale, point.Albedo);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallGridMedium::TableColors(const double p[3], int k, double f, Point& point) const
{
  vtkTyndallTransferTable::RGBAt(this->Table.Albedo, k, f, point.Albedo);
  this->FieldAlbedo(p, point.Albedo);
  if (this->Parameters.HasEmission && !this->GetEmissionFromArray())
  {
    vtkTyndallTransferTable::RGBAt(this->Table.Emission, k, f, point.Emission);
  }
  else
  {
    point.Emission[0] = point.Emission[1] = point.Emission[2] = 0.0;
  }
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::FieldAlbedo(const double*, double*) const
{
  return false;
}

//------------------------------------------------------------------------------
void vtkTyndallGridMedium::ArrayEmission(const double p[3], double rgb[3]) const
{
  if (!this->GetArrayEmission() || !this->Inside(p))
  {
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    return;
  }
  int k;
  double f;
  this->Table.LocateEmission(this->EmissionValue(p), k, f);
  vtkTyndallTransferTable::RGBAt(this->Table.Emission, k, f, rgb);
}

//------------------------------------------------------------------------------
double vtkTyndallGridMedium::GetMajorant() const
{
  double largest[vtkTyndallComponents::MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
  for (int t = 0; t < this->Components.GetTableCount(); ++t)
  {
    const std::vector<double>& extinction = this->GetMajorantTable(t).Extinction;
    largest[t] = extinction.empty() ? 0.0 : *std::max_element(extinction.begin(), extinction.end());
  }
  return this->Parameters.DensityScale * this->Components.Majorant(largest);
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::LookUpComponents(const double p[3], ComponentLookup& lookup) const
{
  if (!this->FieldComponents(p, lookup.Values))
  {
    return false;
  }
  const vtkTyndallComponents& components = this->Components;
  for (int t = 0; t < components.GetTableCount(); ++t)
  {
    const vtkTyndallTransferTable& table = this->GetComponentTable(t);
    int k;
    double f;
    table.Locate(lookup.Values[components.TableComponent(t)], k, f);
    lookup.Sigma[t] = table.ExtinctionAt(k, f);
    vtkTyndallTransferTable::RGBAt(table.Albedo, k, f, lookup.Colors[t]);
    if (t == 0)
    {
      lookup.K0 = k;
      lookup.F0 = f;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::ComponentParts(const double p[3],
  double weights[vtkTyndallComponents::MaximumCount],
  double colors[vtkTyndallComponents::MaximumCount][3],
  double sigma[vtkTyndallComponents::MaximumCount]) const
{
  ComponentLookup lookup;
  if (!this->LookUpComponents(p, lookup))
  {
    return false;
  }
  this->Components.Parts(lookup.Sigma, weights);
  for (int t = 0; t < vtkTyndallComponents::MaximumCount; ++t)
  {
    sigma[t] = this->Parameters.DensityScale * lookup.Sigma[t];
  }
  std::copy(&lookup.Colors[0][0], &lookup.Colors[0][0] + 3 * vtkTyndallComponents::MaximumCount,
    &colors[0][0]);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::ComponentSample(const double p[3], Point& point) const
{
  ComponentLookup lookup;
  if (!this->LookUpComponents(p, lookup))
  {
    return false;
  }
  double unit[vtkTyndallComponents::MaximumCount] = { 0.0, 0.0, 0.0, 0.0 };
  for (int c = 0; c < this->Components.GetCount(); ++c)
  {
    const double* r = this->ComponentRanges[c];
    unit[c] = r[1] > r[0] ? (lookup.Values[c] - r[0]) / (r[1] - r[0]) : 0.0;
  }
  point.Extinction = this->Parameters.DensityScale *
    this->Components.Mix(lookup.Sigma, lookup.Colors, unit, point.Albedo);
  // Emission through the table: table 0's, at its component's value.
  if (this->Parameters.HasEmission && !this->GetEmissionFromArray())
  {
    vtkTyndallTransferTable::RGBAt(this->Table.Emission, lookup.K0, lookup.F0, point.Emission);
  }
  else
  {
    point.Emission[0] = point.Emission[1] = point.Emission[2] = 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallGridMedium::UpdateComponents(vtkVolume* volume, vtkObject* reporter)
{
  vtkVolumeProperty* property = volume->GetProperty();
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  std::string error;
  if (!this->Components.Read(
        property, this->Scalars->GetNumberOfComponents(), medium != nullptr, error))
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot draw the volume: " << error);
    return false;
  }
  if (!this->Components.Enabled())
  {
    return true;
  }
  std::string what;
  if (this->Projection.Enabled())
  {
    return true; // (vtkTyndallProjection: every mode reads the components)
  }
  if (this->Isosurfaces.Enabled())
  {
    // (Independent ones drawn when component 0 has the largest weight:
    // UpdateScalars().)
    what = this->Components.GetMode() == vtkTyndallComponents::Independent
      ? "the isosurface blend mode when a component other than the first has the largest weight "
        "(VTK 9.1 draws that component's isosurfaces, its values on component 0's range; Tyndall "
        "draws those of independent components whose first has the largest weight)"
      : "the isosurface blend mode";
  }
  else if (property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D)
  {
    what = "a 2-D transfer function (TF_2D)";
  }
  else if (medium && medium->GetDetailNoise())
  {
    what = "procedural detail";
  }
  else if (!this->EmissionValues.empty())
  {
    what = "an emission array";
  }
  else if (medium && medium->GetEmissionColor() && medium->GetEmissionScale() > 0.0 &&
    medium->GetScatteringModel() == vtkParticipatingMediumProperty::SINGLE_SCATTERING &&
    this->Components.GetMode() != vtkTyndallComponents::DependentLA)
  {
    // (2 dependent components emit by their colour component's function.)
    what = "emission through the transfer functions (EmissionScale above 0)";
  }
  else if (this->GetLinearExtinction())
  {
    what = "a particle cloud's density";
  }
  if (!what.empty())
  {
    vtkErrorWithObjectMacro(reporter, << "Cannot draw the volume's " << this->Components.Describe()
                                      << " with " << what
                                      << ": several components are drawn in the composite blend "
                                         "mode, with 1-D transfer functions.");
    return false;
  }
  return true;
}
