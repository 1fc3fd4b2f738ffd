/**
 * @class   vtkTyndallSkyLights
 * @brief   the sky as a few directional lights (median cut), for the map-based frame
 *
 * The map-based frame lights the medium by its lights' transmittance maps.
 * vtkTyndallSkyLights turns the renderer's sky (vtkTyndallEnvironment) into
 * a few directional lights that the maps then shadow like any other, so
 * that the sky darkens inside dense media as the path tracers' sampled sky
 * does, instead of lighting every point evenly.
 *
 * The split is a median cut (Debevec, "A median cut algorithm for light
 * probe sampling", 2005) of the sky's equirectangular table (each texel cut
 * into equal cells until there are at least 64 x 32, so that a constant
 * sky, one texel, and a gradient, one column, can be cut): starting from
 * the whole table, the region of most light is shrunk to its rows and
 * columns with light and cut in two, across its
 * longer side (the columns' width measured at the region's middle
 * elevation, times its cosine, against the rows' height, both in radians;
 * across the rows on a tie),
 * where the light on either side is closest to half, until there are
 * `count` regions or no region with light can be cut. The light is the
 * mean channel x solid angle, the sampling's measure. Each region with light
 * becomes one directional light:
 *
 * - its irradiance per channel, the integral of the radiance over the
 *   region's solid angle (sum of L x texel solid angle), so that the
 *   lights' irradiances add up to 4 pi times the sky's mean radiance: with
 *   no shadow and an isotropic phase function the lights give exactly the
 *   mean radiance the ambient approximation adds;
 * - its direction, from the light-weighted mean of its texels' centre
 *   directions (the region's centre where that mean vanishes).
 *
 * The lights are placed in the world by the sky's frame (EnvironmentUp and
 * EnvironmentRight, vtkTyndallEnvironment). Internal to Tyndall::Medium;
 * not wrapped.
 */

#ifndef vtkTyndallSkyLights_h
#define vtkTyndallSkyLights_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkTyndallLight.h"     // For vtkTyndallLight

#include <vector> // For std::vector

class vtkTyndallEnvironment;

class TYNDALLMEDIUM_EXPORT vtkTyndallSkyLights
{
public:
  /**
   * At most `count` directional lights carrying `sky`'s light (fewer when
   * fewer cells have light; none for a black sky or a count below 1). Their Color and Irradiance
   * are the region's irradiance (the sky is not scaled by the medium's LightScale), RendererIndex
   * -1 (no renderer light: surfaces are not lit by them).
   */
  static std::vector<vtkTyndallLight> Split(const vtkTyndallEnvironment& sky, int count);
};

#endif
