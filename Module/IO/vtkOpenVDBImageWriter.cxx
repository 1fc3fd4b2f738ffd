#include "vtkOpenVDBImageWriter.h"

#include "vtkOpenVDBInternals.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <openvdb/io/File.h>

#include <cmath>
#include <limits>
#include <string>

vtkStandardNewMacro(vtkOpenVDBImageWriter);

namespace
{
// The transform that maps voxel (i, j, k) to the image point's world
// position: origin + direction * (spacing * (i, j, k)).
openvdb::math::Transform::Ptr MakeTransform(
  const double origin[3], const double spacing[3], const double direction[9])
{
  bool identity = true;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      identity = identity && direction[3 * r + c] == (r == c ? 1.0 : 0.0);
    }
  }
  const openvdb::Vec3d translation(origin[0], origin[1], origin[2]);
  if (identity && spacing[0] == spacing[1] && spacing[1] == spacing[2])
  {
    openvdb::math::Transform::Ptr transform =
      openvdb::math::Transform::createLinearTransform(spacing[0]);
    transform->postTranslate(translation);
    return transform;
  }
  if (identity)
  {
    openvdb::math::MapBase::Ptr map(new openvdb::math::ScaleTranslateMap(
      openvdb::Vec3d(spacing[0], spacing[1], spacing[2]), translation));
    return openvdb::math::Transform::Ptr(new openvdb::math::Transform(map));
  }
  // OpenVDB's row-vector convention: row a is index axis a (column a of
  // the direction matrix) scaled by the spacing; row 3 the translation.
  openvdb::Mat4d m = openvdb::Mat4d::identity();
  for (int a = 0; a < 3; ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      m(a, c) = spacing[a] * direction[3 * c + a];
    }
    m(3, a) = origin[a];
  }
  return openvdb::math::Transform::createLinearTransform(m);
}

// Fills the grid from the image's scalars, slice by slice.
template <class T>
void FillGrid(const T* values, const int ext[6], double tolerance, openvdb::FloatGrid& grid,
  vtkIdType& active, vtkIdType& nonFinite, vtkOpenVDBImageWriter* self)
{
  auto acc = grid.getAccessor();
  const vtkIdType nx = ext[1] - ext[0] + 1;
  const vtkIdType ny = ext[3] - ext[2] + 1;
  const vtkIdType nz = ext[5] - ext[4] + 1;
  const double maxFloat = std::numeric_limits<float>::max();
  vtkIdType id = 0;
  for (vtkIdType k = 0; k < nz; ++k)
  {
    for (vtkIdType j = 0; j < ny; ++j)
    {
      for (vtkIdType i = 0; i < nx; ++i, ++id)
      {
        const double v = static_cast<double>(values[id]);
        if (!std::isfinite(v) || std::abs(v) > maxFloat)
        {
          ++nonFinite;
          continue;
        }
        if (std::abs(v) <= tolerance)
        {
          continue;
        }
        acc.setValue(
          openvdb::Coord(ext[0] + int(i), ext[2] + int(j), ext[4] + int(k)), static_cast<float>(v));
        ++active;
      }
    }
    self->UpdateProgress(0.9 * double(k + 1) / double(nz));
  }
}
}

//------------------------------------------------------------------------------
vtkOpenVDBImageWriter::vtkOpenVDBImageWriter()
{
  this->SetGridName("density");
}

//------------------------------------------------------------------------------
vtkOpenVDBImageWriter::~vtkOpenVDBImageWriter()
{
  this->SetFileName(nullptr);
  this->SetGridName(nullptr);
}

//------------------------------------------------------------------------------
vtkImageData* vtkOpenVDBImageWriter::GetInput()
{
  return vtkImageData::SafeDownCast(this->Superclass::GetInput());
}

//------------------------------------------------------------------------------
int vtkOpenVDBImageWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageWriter::WriteData()
{
  this->NumberOfActiveVoxels = 0;
  this->NumberOfNonFiniteValues = 0;
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkImageData* image = this->GetInput();
  if (!image)
  {
    vtkErrorMacro(<< "No input image.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No FileName was set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  if (!this->GridName || !*this->GridName)
  {
    vtkErrorMacro(<< "The GridName must not be empty.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  int ext[6];
  image->GetExtent(ext);
  if (ext[0] > ext[1] || ext[2] > ext[3] || ext[4] > ext[5])
  {
    vtkErrorMacro(<< "The input image is empty.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    vtkErrorMacro(<< "The input image has no point scalars.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "The input scalars '" << (scalars->GetName() ? scalars->GetName() : "")
                  << "' have " << scalars->GetNumberOfComponents()
                  << " components; the writer writes one-component scalars.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    vtkErrorMacro(<< "The input scalars have " << scalars->GetNumberOfTuples() << " values for "
                  << image->GetNumberOfPoints() << " points.");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  double origin[3], spacing[3], direction[9];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = image->GetDirectionMatrix()->GetElement(r, c);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    if (!(spacing[c] > 0.0) || !std::isfinite(spacing[c]) || !std::isfinite(origin[c]))
    {
      vtkErrorMacro(<< "The input's spacing must be positive and finite and its origin finite; "
                    << "axis " << c << " has spacing " << spacing[c] << " and origin " << origin[c]
                    << ".");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
  }

  std::string failure;
  this->UpdateProgress(0.0);
  try
  {
    tyndall_io::InitializeOpenVDB();
    openvdb::FloatGrid::Ptr grid = tyndall_io::NewGrid<openvdb::FloatGrid>(0.0f);
    grid->setName(this->GridName);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->setTransform(MakeTransform(origin, spacing, direction));
    grid->setSaveFloatAsHalf(this->SaveFloatAsHalf);
    vtkIdType active = 0, nonFinite = 0;
    // The data array's values, through a typed pointer (a copy for arrays
    // that are not contiguous arrays of structures).
    vtkSmartPointer<vtkDataArray> contiguous = scalars;
    if (!scalars->HasStandardMemoryLayout())
    {
      contiguous.TakeReference(vtkDataArray::CreateDataArray(scalars->GetDataType()));
      contiguous->DeepCopy(scalars);
    }
    switch (contiguous->GetDataType())
    {
      vtkTemplateMacro(FillGrid(static_cast<const VTK_TT*>(contiguous->GetVoidPointer(0)), ext,
        this->Tolerance, *grid, active, nonFinite, this));
      default:
        throw std::runtime_error(
          std::string("unsupported scalar type ") + contiguous->GetDataTypeAsString());
    }
    this->NumberOfActiveVoxels = active;
    this->NumberOfNonFiniteValues = nonFinite;
    grid->tree().prune(); // constant nodes become tiles; no value changes
    openvdb::io::File file(this->FileName);
    file.write(openvdb::GridCPtrVec{ grid });
    file.close();
  }
  catch (const openvdb::Exception& e)
  {
    failure = e.what();
  }
  catch (const std::exception& e)
  {
    failure = e.what();
  }
  catch (...)
  {
    failure = "an unknown exception";
  }
  if (!failure.empty())
  {
    vtkErrorMacro(<< "Cannot write the OpenVDB file '" << this->FileName << "': " << failure);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  if (this->NumberOfNonFiniteValues > 0)
  {
    vtkWarningMacro(<< "Skipped " << this->NumberOfNonFiniteValues
                    << " NaN, infinite or out-of-float-range value(s) of the input; they are "
                       "inactive (0) in '"
                    << this->FileName << "'.");
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkOpenVDBImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "GridName: " << (this->GridName ? this->GridName : "(none)") << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "SaveFloatAsHalf: " << (this->SaveFloatAsHalf ? "On" : "Off") << "\n";
  os << indent << "NumberOfActiveVoxels: " << this->NumberOfActiveVoxels << "\n";
  os << indent << "NumberOfNonFiniteValues: " << this->NumberOfNonFiniteValues << "\n";
}
