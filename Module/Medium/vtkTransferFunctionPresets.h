/**
 * @class   vtkTransferFunctionPresets
 * @brief   named colour and opacity transfer functions for volume rendering
 *
 * vtkTransferFunctionPresets fills a vtkVolumeProperty with one of a few
 * documented presets: a new vtkColorTransferFunction (SetColor), a new
 * vtkPiecewiseFunction (SetScalarOpacity), linear interpolation, and
 * shading with its lighting coefficients. Functions already set on the
 * property are replaced, not modified, so they may be shared safely. The
 * opacities are VTK's scalar opacities per ScalarOpacityUnitDistance, which
 * Apply() leaves alone: set it to about the voxel spacing.
 *
 * The presets (names are matched ignoring case, spaces, '-' and '_'):
 *
 * - "CT": computed tomography in Hounsfield units (HU), independent of the
 *   scalar range. Air (below -600 HU, lungs included) is transparent; fat
 *   (about -100 HU) starts faintly yellow; soft tissue (about 40 HU) is
 *   red-brown with opacity 0.15; bone rises from 300 HU (opacity 0.4) to
 *   opaque ivory-white at 1500 HU and above. Shaded (ambient 0.2, diffuse
 *   0.9, specular 0.3, power 10). Data not stored in HU (for example
 *   unsigned values with an offset of 1024) must be rescaled first.
 * - "MR": magnetic resonance, relative to the scalar range [lo, hi]
 *   (t = (v - lo) / (hi - lo)): transparent below t = 0.1 (background
 *   noise), grey-pink from 0.1 to 0.3 (opacity 0.1 at 0.3), light tissue at
 *   0.6 (opacity 0.4), white and opacity 0.8 at the top. Shaded like CT.
 * - "Cloud": a fog density, relative to the scalar range: transparent at
 *   t = 0, opacity rising linearly to 0.25 at t = 1; colour from a light
 *   blue-grey (0.80, 0.85, 0.92) in thin parts to white in dense parts.
 *   Unshaded (clouds are lit by scattering, not by gradients).
 * - "Smoke": relative: transparent up to t = 0.02, opacity rising
 *   linearly to 0.15 at t = 1; mid grey (0.55) in thin parts darkening to
 *   0.30 in dense parts. Unshaded.
 * - "DenseSmoke": relative: transparent up to t = 0.02, opacity 0.6 at
 *   t = 0.5 and 0.9 at t = 1; dark grey (0.20) to near black (0.06).
 *   Unshaded.
 *
 * The relative presets need a finite range with lo < hi; CT ignores the
 * range. Errors (unknown name, no property, bad range) are reported with
 * vtkErrorWithObjectMacro on the property (a generic warning when the
 * property is null), and Apply() returns false without changing anything.
 *
 * <b>The guessing rule.</b> Tyndall's programs (tyndall-render,
 * tyndall-viewer, the Python examples) choose a preset for a volume with
 * GuessPreset(), one rule for all, which looks at where the volume came
 * from and at its values:
 *
 * 1. a modality named by the file (the field-data string "TyndallModality"
 *    that vtkVolumeFileReader sets, e.g. from a MetaImage header): "CT"
 *    gives CT, any other (MR, PT, US, ...) gives MR;
 * 2. the Hounsfield signature: at least 1% of the finite scalars are air
 *    (-1100 .. -900 HU) and at least 1% are tissue or bone (-100 .. 3000)
 *    gives CT. An MR with a negative minimum (noise around 0, bias-field
 *    corrections, a -32768 padding) has no air peak and is not a CT;
 * 3. the format (field-data string "TyndallFormat"): "OpenVDB" (fog
 *    volumes: a density) gives Cloud; "DICOM" and "NIfTI" (scanners'
 *    formats) give MR;
 * 4. otherwise the values: integer scalars (scanner counts) give MR;
 *    floating-point scalars that look like a density, none negative and
 *    none above 100, give Cloud; other floating-point data (a float MR's
 *    intensities in the hundreds or thousands, negative values) give MR.
 *
 * ApplyToImage() applies a preset the way the programs do: over the image's
 * finite scalar range, with the unit distance set to the mean voxel
 * spacing (the presets' opacities are per voxel).
 */

#ifndef vtkTransferFunctionPresets_h
#define vtkTransferFunctionPresets_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkObject.h"

class vtkImageData;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTransferFunctionPresets : public vtkObject
{
public:
  static vtkTransferFunctionPresets* New();
  vtkTypeMacro(vtkTransferFunctionPresets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The presets: their number, names ("CT", "MR", "Cloud", "Smoke",
   * "DenseSmoke") and one-line descriptions; nullptr for an index out of
   * range. GetPresetIndex() matches a name ignoring case, spaces, '-' and
   * '_' and returns -1 for an unknown name.
   */
  static int GetNumberOfPresets();
  static const char* GetPresetName(int i);
  static const char* GetPresetDescription(int i);
  static int GetPresetIndex(const char* name);
  ///@}

  ///@{
  /**
   * Applies preset `name` to `property` for data whose scalar range is
   * scalarRange (ignored by "CT"). Returns true on success.
   */
  static bool Apply(const char* name, vtkVolumeProperty* property, const double scalarRange[2]);
  static bool Apply(
    const char* name, vtkVolumeProperty* property, double rangeMin, double rangeMax);
  ///@}

  /**
   * The preset Tyndall's programs choose for `image` (see the class
   * description): "CT", "MR" or "Cloud"; nullptr (with an error) for an
   * image without scalars. Reads the active point scalars, else the cell
   * scalars.
   */
  static const char* GuessPreset(vtkImageData* image);

  /**
   * Applies preset `name` to `property` for `image`: over the image's
   * finite scalar range (a constant volume c: over [min(0, c), max(0, c)],
   * or [c, c + 1] for c = 0), and sets the scalar opacity unit distance to
   * the mean of the absolute voxel spacings. Returns false (with an error)
   * for an unknown name, a null argument or an image without finite
   * scalars.
   */
  static bool ApplyToImage(const char* name, vtkVolumeProperty* property, vtkImageData* image);

protected:
  vtkTransferFunctionPresets() = default;
  ~vtkTransferFunctionPresets() override = default;

private:
  vtkTransferFunctionPresets(const vtkTransferFunctionPresets&) = delete;
  void operator=(const vtkTransferFunctionPresets&) = delete;
};

#endif
