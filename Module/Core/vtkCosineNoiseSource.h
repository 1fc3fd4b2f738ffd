/**
 * @class   vtkCosineNoiseSource
 * @brief   samples vtkCosineNoise into a float image, shaped like a cloud
 *
 * vtkCosineNoiseSource writes the density
 *
 *   density(x) = E(x) * max(0, noise(x))     (ClampNegative on, the default)
 *   density(x) = E(x) * noise(x)             (ClampNegative off)
 *
 * at the points x = Origin + (i, j, k) * Spacing of its WholeExtent into a
 * one-component float point-scalar array named "density". noise is the
 * source's vtkCosineNoise (GetNoise(); its implicit Transform, if set, is
 * honoured) and E an optional smooth envelope: 1 inside, falling to 0 with
 * a smoothstep over the outer EnvelopeFalloff fraction of a sphere
 * (EnvelopeRadius) or an axis-aligned ellipsoid (EnvelopeRadii) around
 * EnvelopeCenter.
 *
 * The default output is a 128^3 cloud over [-1, 1]^3: six octaves of noise
 * (frequency 1, gain 0.55, offset 1.5) inside an ellipsoidal envelope;
 * densities range from 0 to about 15.
 *
 * The source generates only the requested update extent, so it streams
 * (vtkImageDataStreamer, pieces of a parallel pipeline); every voxel's value
 * is bit-identical whichever piece computes it. Rows are computed in
 * parallel with vtkSMPTools; each wave is advanced along a row by a complex
 * rotation, restarted exactly every 16 voxels. Progress events are fired,
 * and AbortExecute is honoured between batches of rows.
 *
 * Bad input (an empty or inverted extent, non-positive or non-finite
 * spacing, non-finite origin, more voxels than can be allocated) is reported
 * with vtkErrorMacro and gives an empty output.
 *
 * @sa vtkCosineNoise
 */

#ifndef vtkCosineNoiseSource_h
#define vtkCosineNoiseSource_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class vtkCosineNoise;

class TYNDALLCORE_EXPORT vtkCosineNoiseSource : public vtkImageAlgorithm
{
public:
  static vtkCosineNoiseSource* New();
  vtkTypeMacro(vtkCosineNoiseSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The noise to sample. Never null: setting nullptr is refused with an
   * error. The default is a vtkCosineNoise with 6 octaves, frequency 1,
   * gain 0.55 and offset 1.5.
   */
  void SetNoise(vtkCosineNoise* noise);
  vtkGetObjectMacro(Noise, vtkCosineNoise);
  ///@}

  ///@{
  /**
   * The whole extent of the output; default (0, 127, 0, 127, 0, 127).
   */
  vtkSetVector6Macro(WholeExtent, int);
  vtkGetVector6Macro(WholeExtent, int);
  ///@}

  ///@{
  /**
   * Origin (default (-1, -1, -1)) and spacing (default 2/127 on each axis;
   * must be positive) of the output.
   */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(Spacing, double);
  vtkGetVector3Macro(Spacing, double);
  ///@}

  enum EnvelopeTypes
  {
    ENVELOPE_NONE = 0,
    ENVELOPE_SPHERE = 1,
    ENVELOPE_ELLIPSOID = 2
  };

  ///@{
  /**
   * The shape of the envelope E: ENVELOPE_NONE (E = 1), ENVELOPE_SPHERE or
   * ENVELOPE_ELLIPSOID (the default).
   */
  vtkSetClampMacro(EnvelopeType, int, ENVELOPE_NONE, ENVELOPE_ELLIPSOID);
  vtkGetMacro(EnvelopeType, int);
  void SetEnvelopeTypeToNone() { this->SetEnvelopeType(ENVELOPE_NONE); }
  void SetEnvelopeTypeToSphere() { this->SetEnvelopeType(ENVELOPE_SPHERE); }
  void SetEnvelopeTypeToEllipsoid() { this->SetEnvelopeType(ENVELOPE_ELLIPSOID); }
  ///@}

  ///@{
  /**
   * Centre of the envelope; default (0, 0, 0).
   */
  vtkSetVector3Macro(EnvelopeCenter, double);
  vtkGetVector3Macro(EnvelopeCenter, double);
  ///@}

  ///@{
  /**
   * Radius of the sphere envelope, in [1e-12, 1e12]; default 0.9.
   */
  vtkSetClampMacro(EnvelopeRadius, double, 1.0e-12, 1.0e12);
  vtkGetMacro(EnvelopeRadius, double);
  ///@}

  ///@{
  /**
   * Semi-axes of the ellipsoid envelope; default (0.95, 0.6, 0.7). Each must
   * be positive (non-positive values give an error and an empty output).
   */
  vtkSetVector3Macro(EnvelopeRadii, double);
  vtkGetVector3Macro(EnvelopeRadii, double);
  ///@}

  ///@{
  /**
   * Fraction of the radius, in [0, 1], over which the envelope falls from 1
   * to 0 (a smoothstep in the normalised radius); default 0.6. 0 gives a
   * hard edge.
   */
  vtkSetClampMacro(EnvelopeFalloff, double, 0.0, 1.0);
  vtkGetMacro(EnvelopeFalloff, double);
  ///@}

  ///@{
  /**
   * Clamp negative noise values to 0 (default on), so the output is a
   * valid density.
   */
  vtkSetMacro(ClampNegative, bool);
  vtkGetMacro(ClampNegative, bool);
  vtkBooleanMacro(ClampNegative, bool);
  ///@}

  /**
   * Envelope value E(x) at a point, in [0, 1].
   */
  double EvaluateEnvelope(const double x[3]);

  /**
   * Modification time including the noise's.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkCosineNoiseSource();
  ~vtkCosineNoiseSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkCosineNoise* Noise = nullptr;
  int WholeExtent[6] = { 0, 127, 0, 127, 0, 127 };
  double Origin[3] = { -1.0, -1.0, -1.0 };
  double Spacing[3] = { 2.0 / 127.0, 2.0 / 127.0, 2.0 / 127.0 };
  int EnvelopeType = ENVELOPE_ELLIPSOID;
  double EnvelopeCenter[3] = { 0.0, 0.0, 0.0 };
  double EnvelopeRadius = 0.9;
  double EnvelopeRadii[3] = { 0.95, 0.6, 0.7 };
  double EnvelopeFalloff = 0.6;
  bool ClampNegative = true;

private:
  vtkCosineNoiseSource(const vtkCosineNoiseSource&) = delete;
  void operator=(const vtkCosineNoiseSource&) = delete;

  // Checks the parameters; reports the first problem with vtkErrorMacro.
  bool CheckParameters();
};

#endif
