/**
 * @class   vtkTyndallVolumeRepresentation
 * @brief   ParaView's volume representation of image data, drawn by Tyndall
 *
 * vtkTyndallVolumeRepresentation is the "Tyndall Volume" entry of ParaView's
 * Representation list for image data (Module/ParaView/Plugin/Tyndall.xml).
 * It is ParaView's vtkImageVolumeRepresentation with two things swapped in,
 * the way ParaView's NVIDIA IndeX plugin swaps in its own mapper:
 *
 * - the mapper is a vtkTransmittanceVolumeMapper (transmittance-map
 *   shadows, single scattering, emission);
 * - the volume's property is a vtkParticipatingMediumProperty that shares
 *   the transfer functions ParaView edits (the colour map and the opacity
 *   function of the coloured array, the scalar opacity unit distance, the
 *   interpolation), so the colour map editor drives the medium. The colour
 *   map is the medium's albedo and, with an EmissionScale above 0, the
 *   colour of its emission. A vector array is drawn as ParaView draws it:
 *   its colour map's magnitude or component (the mapper's vector mode), or,
 *   with Map Scalars off or Multi Components Mapping on, its components as
 *   colour and opacity (vtkTyndallComponents). ParaView's Shade and its
 *   Diffuse, Specular and Specular Power reach the medium: its gradient
 *   surface term, added to its scattering (vtkTyndallShading; its ambient
 *   is the Tyndall group's Ambient). ParaView's Use Transfer 2D, over the
 *   gradient magnitude, classifies the medium as VTK's mapper does
 *   (vtkTyndallGridMedium; its colours clamped to [0, 1], as VTK's mapper
 *   reads them); over a second array, or with several components drawn as
 *   such, it is not drawn (the 1-D functions, with a warning). With
 *   SetVTKProperty() on, the volume is drawn with a plain copy of the
 *   medium's vtkVolumeProperty settings instead: ParaView's Shade is then
 *   VTK's gradient shading, shadowed by the maps.
 *
 * Everything else is ParaView's: the data delivery, the outline shown while
 * interacting on ranks without data, the array selection, the volume's
 * placement. The renderer's lights are the view's: the light kit's lights
 * and those of ParaView's light inspector, up to
 * vtkTransmittanceVolumeMapper::GetMaximumNumberOfLights().
 *
 * The settings below forward to the mapper and the medium; their ranges and
 * defaults are those of vtkTransmittanceVolumeMapper and
 * vtkParticipatingMediumProperty, which clamp them.
 *
 * @sa vtkTransmittanceVolumeMapper vtkParticipatingMediumProperty
 */

#ifndef vtkTyndallVolumeRepresentation_h
#define vtkTyndallVolumeRepresentation_h

#include "TyndallParaViewRepresentationModule.h" // For export macro
#include "vtkImageVolumeRepresentation.h"
#include "vtkNew.h" // For vtkNew

class vtkImageData;
class vtkParticipatingMediumProperty;
class vtkTransmittanceVolumeMapper;

class TYNDALLPARAVIEWREPRESENTATION_EXPORT vtkTyndallVolumeRepresentation
  : public vtkImageVolumeRepresentation
{
public:
  static vtkTyndallVolumeRepresentation* New();
  vtkTypeMacro(vtkTyndallVolumeRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mapper's settings: the transmittance method
   * (vtkTransmittanceVolumeMapper::NONE to ADAPTIVE_ETM; default
   * ADAPTIVE_ETM), the number of map coefficients per light ([1, 16];
   * default 8) and the maps' size in texels ([16, 4096]; default 256).
   */
  void SetTransmittanceMethod(int method);
  void SetNumberOfCoefficients(int count);
  void SetTransmittanceMapSize(int size);
  ///@}

  ///@{
  /**
   * The mapper's display transform (vtkTransmittanceVolumeMapper, which
   * clamps them): exposure in stops ([-20, 20]; default 0), the tone curve
   * (TONE_CURVE_LINEAR, TONE_CURVE_REINHARD or TONE_CURVE_ACES; default
   * linear) and the sRGB encoding (default off).
   */
  void SetExposure(double stops);
  void SetToneCurve(int curve);
  void SetEncodeSRGB(int encode);
  ///@}

  ///@{
  /**
   * The mapper's path-traced mode (vtkTransmittanceVolumeMapper's
   * PathTracing, default off): each still render adds samples to the
   * picture up to PathTraceSamplesPerPixel ([1, 1e6]; default 1024), with
   * at most PathTraceMaximumBounces scattering events per path ([1, 1000];
   * default 8), shown denoised with PathTraceDenoise (default off; it
   * keeps the samples). ParaView renders a still view once: render again
   * (pvpython: Render() in a loop) to refine it. GetLastPathTraceSamples():
   * the samples per pixel of the last picture (0: the map-based frame).
   */
  void SetPathTracing(int on);
  void SetPathTraceSamplesPerPixel(int samples);
  void SetPathTraceMaximumBounces(int bounces);
  void SetPathTraceDenoise(int on);
  int GetLastPathTraceSamples();
  ///@}

  /**
   * Whether the view's sky lights the medium (vtkParticipatingMediumMapper::
   * SkyLight): the environment colour, gradient or texture the view gives
   * its renderer for ray tracing. Default off here: ParaView gives every
   * view a grey-blue environment colour.
   */
  void SetSkyLight(int on);

  /**
   * How many directional lights carry the sky in the map-based frame
   * (vtkParticipatingMediumMapper::SkyLightDirections, which clamps it to
   * [0, 8]; default 4).
   */
  void SetSkyLightDirections(int count);

  ///@{
  /**
   * The medium's settings (vtkParticipatingMediumProperty, which clamps
   * them): the scattering model (EMISSION_ABSORPTION or SINGLE_SCATTERING;
   * default SINGLE_SCATTERING), the density scale ([0, 1e6]; default 1),
   * the Henyey-Greenstein anisotropy ([-0.99, 0.99]; default 0), the light
   * scale ([0, 1e6]; default 4 pi), the ambient intensity ([0, 1e6];
   * default 0), the emission scale ([0, 1e6]; default 0; the emission's
   * colour is the colour map's) and the number of multiple-scattering
   * octaves ([1, 8]; default 2).
   */
  void SetScatteringModel(int model);
  void SetDensityScale(double scale);
  void SetScatteringAnisotropy(double g);
  void SetLightScale(double scale);
  void SetAmbientIntensity(double intensity);
  void SetEmissionScale(double scale);
  void SetScatteringOctaves(int octaves);
  ///@}

  /**
   * Whether the volume is drawn with a plain vtkVolumeProperty made from
   * the medium's vtkVolumeProperty settings (vtkParticipatingMediumProperty::
   * CopyVolumeProperty(): ParaView's colour map, opacity, Shade and its
   * coefficients), so that the mapper gives them VTK's meaning: unlit, or
   * with Shade VTK's gradient shading (Ambient, Diffuse, Specular, Specular
   * Power) shadowed by the maps, and path traced a shaded CT; the medium's
   * own settings (the scattering model, anisotropy, ambient and emission,
   * octaves, density and light scale) do not apply. Default off (the medium:
   * Tyndall's meaning). tyndall-render's --vtk-property.
   */
  void SetVTKProperty(int on);

  ///@{
  /**
   * Under MPI (more than one process in VTK's global controller) the mapper
   * gets a vtkTyndallMPIMapReducer and the maps are added over the
   * processes in ProcessViewRequest(REQUEST_RENDER), where ParaView's ranks
   * are in step. The last reduction's seconds (read back, add, upload) and
   * its size in floats on this process; 0 in one process or before the first.
   */
  double GetLastMapReductionTime();
  double GetLastMapReductionSize();
  ///@}

  /**
   * ParaView's requests; REQUEST_RENDER under MPI also builds the maps and
   * adds them over the processes (collective, see
   * vtkTransmittanceVolumeMapper::PrepareDistributedMaps()).
   */
  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

  /**
   * The mapper and the medium property, for C++ code that reads these
   * settings or needs others the XML does not list (the plugin wraps this class for ParaView's
   * client-server layer only, not for Python).
   */
  vtkTransmittanceVolumeMapper* GetTyndallMapper();
  vtkParticipatingMediumProperty* GetMediumProperty();

protected:
  vtkTyndallVolumeRepresentation();
  ~vtkTyndallVolumeRepresentation() override;

  /**
   * ParaView's parameters, then the medium's share of the volume property's
   * transfer functions (the medium is the rendered volume's property from
   * the constructor on, or its plain copy: SetVTKProperty()).
   */
  void UpdateMapperParameters() override;

private:
  vtkTyndallVolumeRepresentation(const vtkTyndallVolumeRepresentation&) = delete;
  void operator=(const vtkTyndallVolumeRepresentation&) = delete;

  vtkNew<vtkTransmittanceVolumeMapper> TyndallMapper;
  vtkNew<vtkParticipatingMediumProperty> Medium;
  // ParaView's 2-D transfer function, clamped to [0, 1] (UpdateTransfer2D()).
  void UpdateTransfer2D();
  vtkNew<vtkImageData> Transfer2D;
  vtkImageData* Transfer2DSource = nullptr; // compared only
  vtkMTimeType Transfer2DCopyTime = 0;
  bool WarnedTransfer2D = false; // the 1-D functions used instead, said once
  // SetVTKProperty(): the drawn property, the medium or its plain copy
  // (vtkParticipatingMediumProperty::GetPlainCopy()).
  void UpdateDrawnProperty();
  bool VTKProperty = false;
};

#endif
