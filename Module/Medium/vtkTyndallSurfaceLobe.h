/**
 * @class   vtkTyndallSurfaceLobe
 * @brief   How a path tracer scatters at a collision in a volume with Shade on
 *
 * VTK's gradient shading (vtkTyndallShading) is a local model: each sample
 * reflects the lights as a surface whose normal is the scalar's gradient.
 * The path tracers (vtkVolumetricPathTracer) give it a meaning with more
 * than one bounce: the volume is a medium whose collisions scatter as such
 * a surface, with a lobe about the unit normal n of the collision (the
 * gradient normalised), v the unit direction towards where the path came
 * from and l the one towards where the light comes from, h = normalize(l +
 * v), two-sided as VTK shades:
 *
 *     f(v, l) = Kd c |n.l| / (2 pi) + Ks |n.h|^p / (2 pi)      (per steradian)
 *
 * c the colour function's colour, Kd, Ks and p the property's Diffuse,
 * Specular and SpecularPower (of component 0, or of the independent
 * component the collision is shaded as). The diffuse lobe scatters the
 * share Kd c of the light (it integrates to Kd c over the sphere), the
 * specular one at most 4 Ks / (p + 1) of it: with Kd + 4 Ks / (p + 1) <= 1
 * (VTK's defaults 0.7, 0.2 and 10: 0.77) no collision adds energy.
 *
 * **Light units.** VTK's lights shade a facing surface with Kd c E (E the
 * light's intensity times its colour): against f above a light is 2 pi
 * brighter (LightUnit). A path tracer multiplies the renderer's lights and
 * its sky by LightUnit at a collision that scatters by this lobe (its
 * next-event estimates, and the sky a path meets after it; a plain
 * property with Shade on), not at other media's collisions, so that the
 * first bounce of a light is VTK's own term, Kd c |n.l| E + Ks |n.h|^p E
 * (vtkTyndallShading::AddLight()), and the bounces after it are this
 * lobe's, which does not add energy (without the blending below). VTK's
 * ambient term Ka c stays what it
 * is in VTK, an emission per unit extinction (not scaled); VTK's clamp of
 * the shaded colour to 1 does not apply (light is not clamped in a path).
 *
 * Where the gradient is 0 (n = 0) the lobe is 0 (but the blending's part
 * below): the collision absorbs, as VTK's shading gives such a sample its
 * ambient term alone.
 *
 * **Volumetric scattering blending.** VTK 9.2's blending (vtkTyndallShading:
 * the weight k of a collision, from its gradient magnitude and opacity)
 * mixes a volumetric term into the lobe, isotropic and without a normal,
 * whose first bounce of a light is VTK's Kd c E as the surface's is:
 *
 *     f_k(v, l) = (1 - k) f(v, l) + k Kd c / (2 pi)
 *
 * (at n = 0 the surface part is 0 and the volumetric one remains, as VTK
 * gives such a sample k V). The volumetric part scatters 2 Kd c of the light
 * (the sphere's 4 pi against the lobe's light unit 2 pi): above Kd c = 1/2
 * its collisions add energy, which the paths' bounce limit bounds, as VTK's
 * term does for its one bounce.
 *
 * **A vtkParticipatingMediumProperty with Shade on** (its surface term
 * added to its single scattering, vtkTyndallShading::GetAdditive()): the
 * lights are not scaled, a collision scatters by the medium's phase
 * function, and the lobe (component 0's gradient and coefficients, the
 * collision's colour, no blending) only gives the surface term it adds,
 * LightUnit times its light from the lights and the sky; it is never
 * sampled (vtkVolumetricPathTracer).
 *
 * Sample() draws l from the mixture of a two-sided cosine lobe about n and
 * Blinn-Phong's half-vector lobe (h about n turned towards v, cos theta_h =
 * u^(1 / (p + 1)), l the mirror of v about h), each chosen in proportion
 * to its share (Kd times the colour's mean, Ks min(1, 4 / (p + 1)), both
 * times 1 - k) or, with the share k 2 Kd times the colour's mean, uniformly
 * over the sphere; Pdf() is that mixture's density, which Sample() returns
 * with f / Pdf() per channel. Internal to Tyndall::Medium; not wrapped.
 */

#ifndef vtkTyndallSurfaceLobe_h
#define vtkTyndallSurfaceLobe_h

#include "TyndallMediumModule.h" // For export macro

class vtkTyndallShading;

class TYNDALLMEDIUM_EXPORT vtkTyndallSurfaceLobe
{
public:
  /// How much brighter a light is against the lobe than in VTK's shading (2 pi).
  static const double LightUnit;

  /**
   * Sets the lobe of a collision: `shading`'s coefficients of `component`
   * (0 .. 3), the unit normal n (or 0), the unit direction v towards where
   * the path came from, the colour c and the blending weight k in [0, 1]
   * (vtkTyndallShading::BlendWeight(); 0: the surface lobe alone). f is
   * `scale` (at least 0) times the lobe above: independent components'
   * parts in the mixture may add up to other than 1 (VTK's mixture,
   * vtkTyndallComponents::Parts()), and a collision shaded as one part
   * drawn with its share of them carries their sum.
   */
  void Set(const vtkTyndallShading& shading, const double n[3], const double v[3],
    const double color[3], int component = 0, double blend = 0.0, double scale = 1.0);

  /**
   * Sets the lobe from the coefficients Kd, Ks and p themselves (what Set()
   * reads from a vtkTyndallShading), the blending weight k (clamped to
   * [0, 1]) and the scale.
   */
  void Set(double diffuse, double specular, double power, const double n[3], const double v[3],
    const double color[3], double blend = 0.0, double scale = 1.0);

  /// Whether the collision scatters at all (a lobe of any weight).
  bool Scatters() const
  {
    return this->DiffuseShare + this->SpecularShare + this->VolumeShare > 0.0;
  }

  /// f(v, l) per channel (per steradian) for the unit direction l.
  void Evaluate(const double l[3], double f[3]) const;

  /// The density (per steradian) with which Sample() draws the unit direction l.
  double Pdf(const double l[3]) const;

  /**
   * Draws the unit direction l from three uniform numbers in [0, 1); sets
   * `weight` to f(v, l) / Pdf(l) per channel and returns Pdf(l) (0, with
   * `weight` 0, when the lobe does not scatter).
   */
  double Sample(double u0, double u1, double u2, double l[3], double weight[3]) const;

private:
  double N[3] = { 0.0, 0.0, 0.0 };
  double V[3] = { 0.0, 0.0, 1.0 };
  double Diffuse[3] = { 0.0, 0.0, 0.0 }; // Kd c
  double Specular = 0.0;                 // Ks
  double Power = 0.0;                    // p
  double Blend = 0.0;                    // k
  double Scale = 1.0;                    // f's factor
  double DiffuseShare = 0.0;             // the probability of drawing from the cosine lobe
  double SpecularShare = 0.0;            // ... from the half-vector lobe
  double VolumeShare = 0.0;              // ... and from the sphere (the blending's part)
};

#endif
