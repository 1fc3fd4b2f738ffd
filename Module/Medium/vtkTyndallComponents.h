/**
 * @class   vtkTyndallComponents
 * @brief   multi-component scalars: how VTK classifies 2 to 4 components, for both renderers
 *
 * A volume's scalars may have 1 to 4 components (more is an error: nothing
 * is drawn). Read() takes their number and the property's
 * IndependentComponents and component weights; Mix() is the CPU twin of
 * the shaders' tyndallComponentMedium() (vtkTransmittanceCommonFS.glsl).
 * Each component is interpolated on its own, then classified, as VTK 9.1's
 * GPU mapper does; a sample with a missing (NaN, masked) component is
 * missing data. The transfer functions are tabulated in GetTableCount()
 * tables, table t tabulating function TableFunction(t) of the property over
 * the finite range of component TableComponent(t) (with that component's
 * scalar opacity unit distance), and read at that component's value:
 *
 * - one component (Single): the property's functions 0 (as before);
 * - dependent, 2 components (LA): colour from function 0 at component 0
 *   (table 0), opacity from function 0 at component 1 (table 1);
 * - dependent, 4 components (RGBA): the colour is components 0, 1 and 2,
 *   each on its finite range as [0, 1] (VTK's normalised texture), the
 *   opacity function 0 at component 3 (table 0); 3 dependent components
 *   are an error (VTK draws 2 or 4);
 * - independent, 2 to 4 components: each component its own functions
 *   (table i: functions i over component i's range) and weight w_i
 *   (vtkVolumeProperty::GetComponentWeight()); with extinctions sigma_i and
 *   colours c_i, over the components of positive weight,
 *       emission-absorption colour per unit length  E = sum w_i sigma_i c_i
 *       extinction (a plain vtkVolumeProperty)      sigma = sum sigma_i^2 / sum w_i sigma_i
 *       extinction (vtkParticipatingMediumProperty) sigma = sum w_i sigma_i
 *   and the colour (or albedo) E / sigma. The first is VTK's mixing
 *   (its step's alpha sum a_i^2 / sum w_i a_i, premultiplied colour
 *   sum w_i a_i c_i) in the limit of small steps: the picture of an
 *   unshaded volume is VTK's. The second is a mixture of media whose
 *   extinctions add (Tyndall's meaning: multichannel data as one medium).
 *   Either way the mixture is one extinction, which the camera and the
 *   light both see: one set of maps per light serves every component.
 *
 * Majorant() bounds Mix()'s extinction from bounds of the tables'.
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallComponents_h
#define vtkTyndallComponents_h

#include "TyndallMediumModule.h" // For export macro

#include <string> // For the error

class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallComponents
{
public:
  /// The most components drawn (VTK's mappers draw at most 4).
  static constexpr int MaximumCount = 4;

  /// How the components are classified (the shaders' TYNDALL_COMPONENT_MODE).
  enum Mode
  {
    Single = 0,
    Independent = 1,
    DependentLA = 2,
    DependentRGBA = 3
  };

  /**
   * Reads `count` components of the scalars and the property's
   * IndependentComponents and weights (`additive`: a
   * vtkParticipatingMediumProperty's mixture). False, with `error` set, for
   * fewer than 1 or more than MaximumCount components, or 3 dependent ones.
   */
  bool Read(vtkVolumeProperty* property, int count, bool additive, std::string& error);

  /// The number of components (1 by default).
  int GetCount() const { return this->Count; }
  /// Whether there are several components.
  bool Enabled() const { return this->Count > 1; }
  Mode GetMode() const { return this->ComponentMode; }
  /// Whether independent components' extinctions add (GetMode() Independent).
  bool GetAdditive() const { return this->Additive; }
  /// The component weights (Independent; 1 otherwise).
  const double* GetWeights() const { return this->Weights; }

  ///@{
  /**
   * The tables: their number, the property's function index each
   * tabulates, and the component whose range it spans and at whose value
   * it is read.
   */
  int GetTableCount() const;
  int TableFunction(int t) const;
  int TableComponent(int t) const;
  ///@}

  /**
   * The mixture at a sample: sigma[t] and color[t] the extinction and
   * colour of table t at its component's value, unit[i] component i on its
   * finite range (0..1, for RGBA's colour); the extinction returned, the
   * colour (or albedo) in rgb (0 where the extinction is 0).
   */
  double Mix(const double sigma[MaximumCount], const double color[MaximumCount][3],
    const double unit[MaximumCount], double rgb[3]) const;

  /**
   * Independent components' parts in Mix()'s colour: weights[i] = w_i
   * sigma_i / sigma (0 for a component of weight 0, and all 0 where the
   * extinction is 0), so that the colour is sum weights[i] color[i]. What
   * the shading of independent components mixes (vtkTyndallShading).
   */
  void Parts(const double sigma[MaximumCount], double weights[MaximumCount]) const;

  /// An upper bound of Mix()'s extinction where table t's is at most sigmaMax[t].
  double Majorant(const double sigmaMax[MaximumCount]) const;

  /// A name for messages ("2 dependent components", "3 independent components").
  std::string Describe() const;

private:
  int Count = 1;
  Mode ComponentMode = Single;
  bool Additive = false;
  double Weights[MaximumCount] = { 1.0, 1.0, 1.0, 1.0 };
};

#endif
