#include "vtkTyndallVolumeSettings.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkParticipatingMediumMapper.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTyndallProjection.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

namespace
{
// VTK's name of a blend mode Tyndall does not draw (null for one it draws).
const char* NotDrawnBlendMode(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::COMPOSITE_BLEND:
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
    case vtkVolumeMapper::ADDITIVE_BLEND:
    case vtkVolumeMapper::ISOSURFACE_BLEND:
    case vtkVolumeMapper::SLICE_BLEND: // with a vtkPlane (else named in NotDrawn())
      return nullptr;
    default:
      return "unknown";
  }
}

// Whether a gradient opacity of any of the first `count` components'
// functions changes VTK's picture (HasGradientOpacity()'s rule).
bool AnyGradientOpacity(vtkVolumeProperty* property, int count)
{
  for (int c = 0; c < count && c < 4; ++c)
  {
    if (vtkTyndallVolumeSettings::HasGradientOpacity(property, c))
    {
      return true;
    }
  }
  return false;
}

}

//------------------------------------------------------------------------------
int vtkTyndallVolumeSettings::ScalarComponents(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  auto* tyndall = vtkParticipatingMediumMapper::SafeDownCast(mapper);
  vtkDataSet* input =
    tyndall ? static_cast<vtkDataSet*>(tyndall->GetMediumImage()) : mapper->GetDataSetInput();
  int cellFlag = 0;
  vtkDataArray* scalars = input
    ? vtkAbstractMapper::GetScalars(input, mapper->GetScalarMode(), mapper->GetArrayAccessMode(),
        mapper->GetArrayId(), mapper->GetArrayName(), cellFlag)
    : nullptr;
  const int count = scalars ? scalars->GetNumberOfComponents() : 0;
  const bool vectorMode = tyndall &&
    tyndall->GetVectorMode() != vtkParticipatingMediumMapper::DISABLED &&
    property->GetIndependentComponents();
  return count > 1 && vectorMode ? 1 : count;
}

//------------------------------------------------------------------------------
bool vtkTyndallVolumeSettings::SliceReadsGradient(
  vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  if (!mapper || !property || property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D)
  {
    return false;
  }
  vtkTyndallProjection projection;
  projection.Read(mapper, property);
  return projection.GetMode() == vtkTyndallProjection::SLICE &&
    ScalarComponents(mapper, property) == 1;
}

//------------------------------------------------------------------------------
bool vtkTyndallVolumeSettings::HasGradientOpacity(vtkVolumeProperty* property, int component)
{
  if (!property || property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D ||
    property->GetDisableGradientOpacity(component) || !property->HasGradientOpacity(component))
  {
    return false;
  }
  vtkPiecewiseFunction* function = property->GetStoredGradientOpacity(component);
  const int size = function ? function->GetSize() : 0;
  for (int i = 0; i < size; ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    if (!(node[1] >= 1.0))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkTyndallVolumeSettings::NotDrawn(vtkVolume* volume)
{
  std::vector<std::string> notDrawn;
  vtkVolumeProperty* property = volume ? volume->GetProperty() : nullptr;
  if (!property)
  {
    return notDrawn;
  }
  auto* mapper = vtkVolumeMapper::SafeDownCast(volume->GetMapper());
  const char* blendMode = mapper ? NotDrawnBlendMode(mapper->GetBlendMode()) : nullptr;
  if (blendMode)
  {
    notDrawn.push_back(std::string("the ") + blendMode + " blend mode (drawn as composite)");
  }
  vtkTyndallProjection projection;
  projection.Read(mapper, property);
  if (mapper && mapper->GetBlendMode() == vtkVolumeMapper::SLICE_BLEND && !projection.Enabled())
  {
    notDrawn.push_back("the slice blend mode without a vtkPlane as the property's slice function "
                       "(drawn as composite)");
  }
  auto* medium = vtkParticipatingMediumProperty::SafeDownCast(property);
  if (projection.Enabled() && medium && medium->GetDetailNoise())
  {
    notDrawn.push_back(std::string("procedural detail in the ") +
      vtkTyndallProjection::GetModeName(projection.GetMode()) +
      " blend mode (the grid's scalars are projected)");
  }
  if (mapper && mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND && medium &&
    medium->GetDetailNoise())
  {
    notDrawn.push_back("procedural detail in the isosurface blend mode (the grid's surfaces are "
                       "drawn)");
  }
  auto* tyndallMapper = vtkParticipatingMediumMapper::SafeDownCast(mapper);
  if (tyndallMapper && tyndallMapper->GetMaskInput() &&
    tyndallMapper->GetMaskType() == vtkParticipatingMediumMapper::LabelMapMaskType &&
    tyndallMapper->GetMaskBlendFactor() > 0.0f && !property->GetLabelMapLabels().empty())
  {
    // Drawn (vtkTyndallLabelMap) for one component's 1-D functions in the
    // composite blend mode; VTK's projections ignore labels too.
    const bool projected = mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND &&
      mapper->GetBlendMode() != vtkVolumeMapper::ISOSURFACE_BLEND;
    if (!projected &&
      (property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D ||
        mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND ||
        (medium && medium->GetDetailNoise()) || ScalarComponents(mapper, property) > 1))
    {
      notDrawn.push_back("a label map with a 2-D transfer function, isosurfaces, procedural "
                         "detail or several components (the volume is drawn without its labels)");
    }
    if (property->HasLabelGradientOpacity())
    {
      notDrawn.push_back("the labels' gradient opacity (their scalar opacity is drawn)");
    }
  }
  // Several components in a projection (vtkTyndallProjection) are drawn as
  // VTK 9.1 means them, where its shader draws otherwise.
  const int count = mapper && projection.Enabled() ? ScalarComponents(mapper, property) : 0;
  if (count > 1 && property->GetIndependentComponents() &&
    projection.GetMode() == vtkTyndallProjection::MINIMUM)
  {
    notDrawn.push_back("VTK 9.1's minimum intensity of independent components (it keeps each "
                       "component's maximum and adds w a^2 to blue at alpha 0; Tyndall draws "
                       "their minimum)");
  }
  if (count == 2 && !property->GetIndependentComponents() &&
    (projection.GetMode() == vtkTyndallProjection::MAXIMUM ||
      projection.GetMode() == vtkTyndallProjection::MINIMUM))
  {
    notDrawn.push_back(std::string("VTK 9.1's ") +
      vtkTyndallProjection::GetModeName(projection.GetMode()) +
      " of 2 dependent components (it draws each ray's first sample; Tyndall the sample of the "
      "extreme second component)");
  }
  // Shading is drawn but in the slice of several components or a 2-D
  // function (vtkTyndallShading; VTK 9.1 shades no other projection), for
  // either kind of property (elsewhere a medium's Shade is its own surface
  // term, documented with its meaning).
  const bool sliceGradient = SliceReadsGradient(mapper, property);
  if (property->GetShade(0) && projection.GetMode() == vtkTyndallProjection::SLICE &&
    !sliceGradient)
  {
    notDrawn.push_back(std::string("gradient shading in the ") +
      vtkTyndallProjection::GetModeName(projection.GetMode()) + " blend mode (unshaded)");
  }
  // The classification (gradient opacity, 2-D transfer functions) is VTK's
  // for both kinds of property (vtkTyndallGridMedium), but where named here.
  const bool detail = medium && medium->GetDetailNoise();
  const bool isosurfaces = mapper && mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND;
  // Gradient opacity is drawn but in a projection other than the slice of
  // one component (vtkTyndallGridMedium); VTK 9.1 ignores it too in the
  // average intensity and additive modes (the maximum and minimum multiply
  // their pixel's opacity by it, at the gradient where the ray leaves the
  // volume).
  const int mode = projection.GetMode();
  const bool summed =
    mode == vtkTyndallProjection::AVERAGE || mode == vtkTyndallProjection::ADDITIVE;
  const bool projectionNamed =
    projection.Enabled() && !summed && !sliceGradient && HasGradientOpacity(property);
  if (projectionNamed)
  {
    notDrawn.push_back(std::string("gradient opacity in the ") +
      vtkTyndallProjection::GetModeName(projection.GetMode()) + " blend mode (ignored)");
  }
  // Gradient opacity is not read with several components (vtkTyndallComponents;
  // named once, and not where VTK ignores it too; their isosurfaces are
  // one component's, named below).
  const int components = mapper ? ScalarComponents(mapper, property) : 0;
  if (components > 1 && !summed && !projectionNamed && !isosurfaces &&
    AnyGradientOpacity(property, components))
  {
    notDrawn.push_back("gradient opacity with several components (ignored)");
  }
  // Gradient opacity is not read in the isosurface blend mode (vtkTyndallIsosurfaces).
  if (isosurfaces && HasGradientOpacity(property))
  {
    notDrawn.push_back("gradient opacity in the isosurface blend mode (ignored)");
  }
  // 2-D transfer functions are drawn but in a projection or for isosurfaces.
  if (property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D &&
    (projection.Enabled() || isosurfaces))
  {
    notDrawn.push_back(std::string("2-D transfer functions in the ") +
      (projection.Enabled() ? vtkTyndallProjection::GetModeName(projection.GetMode())
                            : "isosurface") +
      " blend mode (TF_2D: the 1-D functions are used)");
  }
  // A medium's emission colour is of the 1-D scalar: none with a 2-D function.
  if (medium && !detail && !projection.Enabled() && !isosurfaces &&
    property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D && medium->GetEmissionColor() &&
    medium->GetEmissionScale() > 0.0 && !medium->GetEmissionArrayName())
  {
    notDrawn.push_back("emission with a 2-D transfer function (not drawn)");
  }
  // Procedural detail multiplies the 1-D extinction (vtkTyndallDetailMedium).
  if (detail && !projection.Enabled() && !isosurfaces &&
    (property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D ||
      HasGradientOpacity(property)))
  {
    notDrawn.push_back("a 2-D transfer function or gradient opacity with procedural detail (the "
                       "1-D functions are used)");
  }
  return notDrawn;
}

//------------------------------------------------------------------------------
std::string vtkTyndallVolumeSettings::Describe(const std::vector<std::string>& notDrawn)
{
  std::string text;
  for (size_t i = 0; i < notDrawn.size(); ++i)
  {
    text += (i == 0 ? "" : "; ") + notDrawn[i];
  }
  return text.empty()
    ? text
    : "Tyndall draws these settings otherwise than VTK 9.1's volume mappers: " + text + ".";
}
