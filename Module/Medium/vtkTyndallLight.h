/**
 * @class   vtkTyndallLight
 * @brief   one light of a Tyndall scene, in the convention both renderers use
 *
 * vtkTyndallSceneReader turns each usable vtkLight of a renderer into one of these
 * (see vtkTyndallSceneReader for which lights are used and how they are placed).
 * Internal to Tyndall::Medium; not wrapped.
 *
 * The irradiance a medium receives before attenuation and shadowing,
 * Irradiance, is LightScale * Color, LightScale being the medium's
 * (vtkParticipatingMediumProperty::GetLightScale()); the scene reader
 * computes it once for both renderers. The sky's lights
 * (vtkTyndallSkyLights) are directional, with the irradiance of their part
 * of the sky as Color and Irradiance (the sky is not scaled by LightScale)
 * and RendererIndex -1.
 */

#ifndef vtkTyndallLight_h
#define vtkTyndallLight_h

#include "TyndallMediumModule.h" // For export macro

class TYNDALLMEDIUM_EXPORT vtkTyndallLight
{
public:
  /// Positional (point or spot) or directional.
  bool Positional = false;
  /// World position of a positional light.
  double Position[3] = { 0.0, 0.0, 0.0 };
  /// Unit direction the light travels (directional lights, spot axis).
  double Direction[3] = { 0.0, 0.0, -1.0 };
  /// vtkLight's Intensity times its DiffuseColor.
  double Color[3] = { 1.0, 1.0, 1.0 };
  /// The medium's LightScale times Color.
  double Irradiance[3] = { 1.0, 1.0, 1.0 };
  /// VTK's attenuation 1 / (a0 + a1 r + a2 r^2) of positional lights.
  double Attenuation[3] = { 1.0, 0.0, 0.0 };
  /**
   * A headlight (vtkLight::LightTypeIsHeadlight()): gradient shading
   * (vtkTyndallShading) takes its direction along each camera ray, as VTK's
   * default light shades.
   */
  bool Headlight = false;
  /// A positional light with ConeAngle < 90 degrees.
  bool Spot = false;
  /// Cosine of the cone angle, and the spot exponent (spot lights).
  double ConeCosine = -1.0;
  double Exponent = 1.0;
  /**
   * The light's index among the renderer's switched-on lights (-1 for the
   * sky's lights, which are none of them; the index
   * of its lightColor<i> uniform in VTK's polydata shaders).
   */
  int RendererIndex = 0;
};

#endif
