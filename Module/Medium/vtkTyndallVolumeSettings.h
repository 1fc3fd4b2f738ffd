/**
 * @class   vtkTyndallVolumeSettings
 * @brief   the settings of a volume that VTK's volume mappers draw and Tyndall does not yet
 *
 * An application that swaps vtkGPUVolumeRayCastMapper for a Tyndall mapper
 * must not get a different picture without a word. NotDrawn() names each
 * setting of the volume's mapper and its property that VTK
 * draws and Tyndall does not yet (Documentation/mapper.md, "Compatibility
 * with VTK's mapper"), with what Tyndall draws instead:
 * - the slice blend mode without a vtkPlane as the property's slice
 *   function (drawn as composite; the projections, the slice through a
 *   plane included, are drawn, vtkTyndallProjection, and the isosurface
 *   mode, vtkTyndallIsosurfaces);
 * - procedural detail in a projection blend mode (the grid's scalars are
 *   projected) or the isosurface blend mode (the grid's surfaces are drawn);
 * - a label-map mask (vtkParticipatingMediumMapper::SetMaskInput() with
 *   LabelMapMaskType, drawn by vtkTyndallLabelMap) with a 2-D transfer
 *   function, isosurfaces, procedural detail or several components (the
 *   volume is drawn without its labels), and the labels' gradient opacity
 *   (their scalar opacity is drawn);
 * for both kinds of property (the slice and the classification are VTK's):
 * - gradient shading in the slice blend mode of several components or a
 *   2-D function (unshaded; drawn in the slice of one component, and a
 *   plain property's in the composite and isosurface modes,
 *   vtkTyndallShading; VTK 9.1 shades no other projection);
 * - gradient opacity in the maximum or minimum intensity or isosurface
 *   blend mode, or with several components (ignored; drawn in the others
 *   and the slice of one component, vtkTyndallGridMedium::GetGradientOpacity();
 *   VTK 9.1 ignores it in the average intensity and additive modes too);
 * - 2-D transfer functions in a projection or the isosurface blend mode
 *   (TF_2D: the 1-D functions are used; drawn in the others);
 * and for a vtkParticipatingMediumProperty:
 * - a 2-D transfer function or gradient opacity with procedural detail
 *   (the 1-D functions: the detail multiplies the 1-D extinction);
 * - emission (EmissionColor) with a 2-D transfer function (not drawn).
 * Named too, where VTK 9.1's shader draws other than it means and Tyndall
 * draws what it means (vtkTyndallProjection): the minimum intensity of
 * independent components, the maximum or minimum intensity of 2 dependent
 * components.
 * (Nearest interpolation, vtkVolumeProperty's default, is drawn:
 * vtkTyndallGridMedium::GetNearest().)
 * The first component's settings are read (several components are
 * classified by vtkTyndallComponents and vtkTyndallProjection; the
 * settings they are not drawn with are an error there). vtkTyndallSceneReader warns with the list
 * once when it changes, for both renderers.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallVolumeSettings_h
#define vtkTyndallVolumeSettings_h

#include "TyndallMediumModule.h" // For export macro

#include <string> // For std::string
#include <vector> // For std::vector

class vtkVolume;
class vtkVolumeMapper;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallVolumeSettings
{
public:
  /**
   * The settings of `volume` (its mapper and property) that Tyndall does
   * not draw, one text each; empty when there are none or the volume has no
   * property.
   */
  static std::vector<std::string> NotDrawn(vtkVolume* volume);

  /**
   * Whether a component's gradient opacity (the first's by default)
   * changes VTK's picture: TF_1D, enabled, and a function below 1
   * somewhere (VTK's default, disabled or all 1, multiplies by 1).
   */
  static bool HasGradientOpacity(vtkVolumeProperty* property, int component = 0);

  /**
   * The number of components of the scalars `mapper` draws with `property`
   * (0 without; 1 for a Tyndall mapper's vector mode of independent ones;
   * the data's count in the isosurface blend mode, whose independent
   * components are drawn as one: vtkTyndallGridMedium).
   */
  static int ScalarComponents(vtkVolumeMapper* mapper, vtkVolumeProperty* property);

  /**
   * Whether `mapper` draws the slice through a plane (vtkTyndallProjection)
   * of one component with `property`'s 1-D functions: the slice that VTK
   * 9.1 lights (Shade, of either kind of property) and whose opacity it multiplies
   * by the gradient opacity, which Tyndall draws as VTK does.
   */
  static bool SliceReadsGradient(vtkVolumeMapper* mapper, vtkVolumeProperty* property);

  /// The texts of NotDrawn() as one sentence (empty for none).
  static std::string Describe(const std::vector<std::string>& notDrawn);
};

#endif
