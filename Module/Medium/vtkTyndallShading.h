/**
 * @class   vtkTyndallShading
 * @brief   VTK's gradient shading of a plain vtkVolumeProperty with Shade on, shadowed by the maps
 *
 * A plain vtkVolumeProperty keeps VTK's meaning: with Shade on (component
 * 0) in any blend mode but a projection (vtkTyndallProjection) other than
 * the slice of one component, each sample's colour c (the colour
 * function's) is shaded as VTK 9.1's GPU mapper shades it, with the
 * property's Ambient Ka, Diffuse Kd, Specular Ks and SpecularPower p, the
 * normal n being the scalar's gradient normalised (0 where the gradient
 * is 0), and each light l in addition shadowed by its light transmittance
 * T_l (Tyndall's maps, brute force, or 1 with the method None):
 *
 *     rgb = clamp(Ka c + sum_l T_l E_l (Kd |n.l| c + Ks |n.h|^p), 0, 1)
 *
 * E_l the light's intensity times its colour, l the unit direction towards
 * the light (a headlight's: towards the camera along the ray, as VTK's
 * default light shades), h = normalize(l + v), v towards the camera;
 * two-sided (VTK's renderer default). T_l is taken from ShadowOffset voxels
 * (the smallest world spacing) towards the light: a sample on a surface
 * does not shadow itself (without it the maps' reconstruction of the wall
 * the sample sits in darkens every lit surface). The opacity is the property's, as
 * unshaded; the sample is then composited as emission-absorption (its
 * colour rgb per unit extinction).
 *
 * The gradient is taken by central differences one voxel apart along each
 * index axis (one texel of the GPU's texture, Factor voxels where it is
 * downsampled) and mapped to world directions (the volume's matrix and the
 * image's spacing and direction), on both renderers; 0 where a difference
 * meets missing data (NaN).
 *
 * What differs from VTK (Documentation/mapper.md): VTK's ambient term is
 * Ka c with its default headlight and Ka times the lights' ambient colours
 * (black by default) with other lights; here it is always Ka c. With
 * several lights VTK keeps the last light's specular term only; here every
 * light adds its own.
 *
 * VTK 9.2's volumetric scattering blending b (vtkParticipatingMediumMapper::
 * GetVolumetricScatteringBlending(), in [0, 2], default 0; 0 in the
 * isosurface blend mode) blends isotropic single scattering into each
 * sample, with VTK 9.2's weight k of the gradient magnitude G and the
 * sample's opacity a:
 *
 *     rgb = clamp((1 - k) S + k V, 0, 1),   S = Ka c + sum_l T_l E_l (Kd |n.l| c + Ks |n.h|^p)
 *                                           V = Ka c + sum_l T_l E_l Kd c
 *     k = b exp(-b G a)                        for b < 1
 *     k = (2 - b) exp(-b G a) + b - 1          for b >= 1
 *
 * (VTK 9.2 passes b / 2 to its shader), G = 2 |grad s| / (s_max - s_min)
 * (VTK's central difference of the scalar on its range, per world unit)
 * and a = 1 - exp(-sigma h) (the opacity over VTK's automatic step, h the
 * smallest world spacing). So b = 0 is the surface shading above, b = 1
 * VTK's "smart" blend k = exp(-G a): surface-like where the gradient is
 * strong and volumetric (the light scattered without a normal,
 * isotropically: its phase function 1 here) where it is weak, and b = 2
 * volumetric only. Where VTK differs: with gradient opacity VTK's G is
 * that of a unit vector (1) and its a is the opacity before gradient
 * opacity; here G is the gradient's and a the sample's.
 *
 * A vtkParticipatingMediumProperty keeps Tyndall's meaning: with Shade on
 * the surface term sum_l T_l E_l (Kd |n.l| c + Ks |n.h|^p) (component 0's
 * gradient and coefficients; no ambient term, no clamp) is added to the
 * sample's single scattering and emission (GetAdditive()): the medium
 * glows and scatters as before, and its surfaces catch highlights. The
 * blending does not apply, and its isosurfaces (the isosurface blend mode)
 * and a medium with procedural detail are lit by its scattering alone.
 *
 * Independent components (vtkTyndallComponents) are shaded each with its
 * own gradient, colour and coefficients (the property's for that
 * component), clamped, then mixed with the weights w_i sigma_i / sigma of
 * their mixture (vtkTyndallGridMedium::ComponentParts()), as VTK 9.1
 * shades and mixes them; dependent ones with component 0's gradient and
 * coefficients, as VTK does.
 *
 * Start(), AddLight() and Finish() are the CPU twin of the shader's
 * tyndallSurfaceShading() and tyndallComponentShading()
 * (vtkTransmittanceRayCastFS.glsl), and of tyndallProjectionSurface()
 * (vtkTransmittanceProjectionFS.glsl: the slice, as VTK 9.1 shades it, with
 * T_l = 1 and no blending, a projection having no maps).
 *
 * Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallShading_h
#define vtkTyndallShading_h

#include "TyndallMediumModule.h" // For export macro

class vtkVolumeMapper;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTyndallShading
{
public:
  /**
   * Reads `property`: enabled with Shade on for component 0, drawn by
   * `mapper` in a blend mode that is not a projection (a
   * vtkParticipatingMediumProperty's not for isosurfaces nor with
   * procedural detail), or in the slice of one component
   * (vtkTyndallVolumeSettings::SliceReadsGradient(), as VTK 9.1 shades it,
   * unshadowed, for either kind of property); its coefficients.
   */
  void Read(vtkVolumeMapper* mapper, vtkVolumeProperty* property);

  bool Enabled() const { return this->On; }
  ///@{
  /// The property's Ambient, Diffuse, Specular and SpecularPower (of a component, 0 .. 3).
  double GetAmbient(int c = 0) const { return this->Coefficients[c][0]; }
  double GetDiffuse(int c = 0) const { return this->Coefficients[c][1]; }
  double GetSpecular(int c = 0) const { return this->Coefficients[c][2]; }
  double GetSpecularPower(int c = 0) const { return this->Coefficients[c][3]; }
  ///@}

  /**
   * Whether the surface term is added to single scattering (a
   * vtkParticipatingMediumProperty with Shade on: Tyndall's meaning) rather
   * than replacing it (a plain property: VTK's).
   */
  bool GetAdditive() const { return this->Additive; }

  /// The volumetric scattering blending b drawn (see the class description).
  double GetBlending() const { return this->Blending; }

  /// A sample's sums: the surface term S and the volumetric term V.
  struct Sums
  {
    double Surface[3];
    double Volume[3];
  };

  /**
   * Starts a sample's shading with component c's coefficients: S = V = Ka c.
   */
  void Start(const double color[3], Sums& sums, int c = 0) const;

  /**
   * Adds light l's terms T E (Kd |n.l| c + Ks |n.h|^p) to S and T E Kd c to
   * V: n the unit normal (or 0), l the unit direction towards the light, v
   * towards the camera, E the light's colour at the sample, T its
   * transmittance per channel.
   */
  void AddLight(const double n[3], const double l[3], const double v[3], const double color[3],
    const double E[3], const double T[3], Sums& sums, int c = 0) const;

  /**
   * Adds a sky of mean radiance m as light from every direction, unshadowed
   * (the map-based frame's sky without its directional lights:
   * vtkTyndallSceneReader::GetShadingSkyMean()): the two-sided diffuse
   * lobe's Kd c 2 pi m to S (|n.l| over the sphere is 2 pi; a constant sky's
   * exact light) where the unit normal n is not 0 (as AddLight() adds
   * nothing there), and Kd c 4 pi m to V (the sky's light, no cosine), as
   * the sky's directional lights, whose colours add up to 4 pi m, would add
   * them. No specular term.
   */
  void AddSkyMean(
    const double n[3], const double color[3], const double m[3], Sums& sums, int c = 0) const;

  /**
   * The blending weight k of a sample of gradient magnitude G (per world
   * unit: |grad s|) and extinction sigma, for scalars over `range` (s_max -
   * s_min) and the smallest world spacing h (the class description); 0
   * when the blending is 0.
   */
  double BlendWeight(double gradient, double sigma, double range, double h) const;

  /// VTK 9.2's weight k of the blending B, the gradient term G and the opacity a.
  static double Weight(double B, double G, double a);

  /// How far towards a light its transmittance is taken, in voxels (see the class description).
  static constexpr double ShadowOffset = 1.0;

  /// rgb = clamp((1 - k) S + k V, 0, 1) (VTK clamps the shaded colour).
  static void Finish(const Sums& sums, double k, double rgb[3]);

private:
  bool On = false;
  bool Additive = false;
  double Blending = 0.0;
  // Per component: Ambient, Diffuse, Specular, SpecularPower.
  double Coefficients[4][4] = { { 0.1, 0.7, 0.2, 10.0 }, { 0.1, 0.7, 0.2, 10.0 },
    { 0.1, 0.7, 0.2, 10.0 }, { 0.1, 0.7, 0.2, 10.0 } };
};

#endif
