/**
 * @class   vtkTyndallLabelMap
 * @brief   a label-map mask's classification, as VTK 9.1's GPU ray caster draws it
 *
 * vtkGPUVolumeRayCastMapper's LabelMapMaskType (vtkParticipatingMediumMapper::
 * SetMaskInput() with SetMaskTypeToLabelMap()): the mask's value at a sample
 * (its nearest one; rounded, at most 255) is a label. Label 0 (a value of 0
 * or less) keeps the volume's transfer functions. Label L > 0 takes the
 * property's functions for L (vtkVolumeProperty::GetLabelColor(L),
 * GetLabelScalarOpacity(L); the property's own where L has none), tabulated
 * as VTK tabulates them: Width entries over the scalars' range, read at
 * the entry the scalar falls in (nearest), rows 1 .. RowCount (the largest
 * label with a function); a label above RowCount reads row RowCount (VTK's
 * texture clamps). A row's opacity is per sample, at VTK's step: VTK does
 * not correct it for the sample distance.
 *
 * The mapper's MaskBlendFactor f mixes the two as VTK does, colour and
 * opacity alike, (1 - f) (rgb_n, a_n) + f (rgb_L, a_L), a_n being the
 * volume's opacity at VTK's step h (1 - exp(-sigma_n h / density), sigma_n
 * the medium's extinction there, gradient opacity included) and rgb_n its
 * colour, 0 where a_n is 0 (as VTK mixes); f = 0 draws no label. The mixed opacity becomes the
 * extinction density * -ln(1 - a) / h (Mix()). h is the smallest world spacing (VTK's automatic
 * step; the same rule as a 2-D transfer function's opacity).
 *
 * Both renderers read this one class (the GPU its labels and rows as
 * textures, tyndallLabelMix() in vtkTransmittanceCommonFS.glsl).
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallLabelMap_h
#define vtkTyndallLabelMap_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkType.h"             // For vtkIdType

#include <ostream> // For std::ostream
#include <vector>  // For std::vector

class vtkDataArray;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallLabelMap
{
public:
  /// Entries per row (VTK's label table width).
  static constexpr int Width = 1024;
  /// The largest label.
  static constexpr int MaximumLabel = 255;

  /**
   * Reads the mask's values, one per sample (`count`, one component):
   * each rounded to a label in [0, MaximumLabel]. False, with `error`, for
   * a non-finite value. Clear() forgets them.
   */
  bool ReadLabels(vtkDataArray* values, vtkIdType count, std::ostream& error);
  void Clear();
  /// Forgets the rows (the labels draw nothing until Tabulate()).
  void ClearRows();

  /**
   * Tabulates `property`'s label functions over the scalars' range
   * [minimum, maximum], with the blend factor and VTK's step.
   */
  void Tabulate(
    vtkVolumeProperty* property, double minimum, double maximum, double blend, double step);

  /// Whether labels change the picture: some labels, some label functions, f > 0.
  bool Enabled() const { return !this->Labels.empty() && this->RowCount > 0 && this->Blend > 0.0; }

  /// The label of sample i (0 without labels).
  int LabelAt(vtkIdType i) const
  {
    return this->Labels.empty() ? 0 : this->Labels[static_cast<size_t>(i)];
  }

  /// The entry a scalar falls in, u = (s - minimum) / (maximum - minimum).
  static int Entry(double u);

  /**
   * Label `label`'s mix at entry `entry`: the medium's extinction `sigma`
   * (density scale `density` applied) and colour `color` (in and out)
   * become the mixed ones; label 0 leaves them.
   */
  double Mix(int label, int entry, double sigma, double density, double color[3]) const;

  /**
   * An upper bound of Mix()'s extinction (density 1) over every label at
   * the scalars whose entry in a table of `extinction.size()` entries over
   * the same range is i, given the volume's own extinction there: what
   * empty-space skipping and the majorants read.
   */
  std::vector<double> Bound(const std::vector<double>& extinction) const;

  ///@{
  /// The labels (one per sample), the rows (RGBA, RowCount + 1 rows of Width, row 0 unused).
  const std::vector<unsigned char>& GetLabels() const { return this->Labels; }
  const std::vector<float>& GetRows() const { return this->Rows; }
  int GetRowCount() const { return this->RowCount; }
  double GetBlend() const { return this->Blend; }
  double GetStep() const { return this->Step; }
  ///@}

private:
  std::vector<unsigned char> Labels;
  std::vector<float> Rows;
  int RowCount = 0;
  double Blend = 1.0;
  double Step = 1.0;
};

#endif
