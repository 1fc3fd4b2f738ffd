/**
 * @class   vtkTransmittanceMediumAdapter
 * @brief   the GPU side of one kind of medium: its textures, switches, uniforms and GLSL
 *
 * The medium model (Tyndall::Medium) knows no OpenGL; the passes of
 * vtkTransmittanceVolumeMapper know no kind of medium. Between them, one
 * adapter per kind of vtkTyndallMedium says what the shaders need of it:
 *
 * - GetGrid() and GetExtras(): its textures, which Upload() hands to
 *   vtkTransmittanceMediumTextures (which keeps them and uploads only what
 *   changed);
 * - DeclareSwitches(): its compile-time switches of
 *   vtkTransmittanceShaderSource::Variant, and its GLSL (Variant::MediumCode,
 *   put in place of the common shader's `//TYNDALL::Medium` line);
 *   DeclareColorSwitches() those of the camera rays' colour alone;
 * - SetUniforms(): the uniforms its switches declare;
 * - GetLightMarchIterations(): what one brute-force light march costs of
 *   the driver's loop budget;
 * - GetSplatted(): the particles splatted into the extinction maps.
 *
 * vtkTransmittanceMediumAdapters::For() is the one place on the GPU side
 * that picks by the medium's kind: vtkTransmittanceGridAdapter,
 * vtkTransmittanceParticleAdapter and vtkTransmittanceDetailAdapter.
 *
 * Adapters hold no state: every call is given the medium.
 *
 * Internal to Tyndall::Rendering.
 */

#ifndef vtkTransmittanceMediumAdapter_h
#define vtkTransmittanceMediumAdapter_h

#include "TyndallRenderingModule.h"         // For export macro
#include "vtkTransmittanceMediumTextures.h" // For vtkTransmittanceMediumTextures::Extras
#include "vtkTransmittanceShaderSource.h"   // For vtkTransmittanceShaderSource::Variant

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTyndallGridMedium;
class vtkTyndallMedium;
class vtkTyndallParticleMedium;

class TYNDALLRENDERING_EXPORT vtkTransmittanceMediumAdapter
{
public:
  using Variant = vtkTransmittanceShaderSource::Variant;

  virtual ~vtkTransmittanceMediumAdapter() = default;

  /**
   * The grid whose scalars and table the textures hold: the medium itself,
   * or the grid a procedural detail multiplies.
   */
  virtual const vtkTyndallGridMedium& GetGrid(const vtkTyndallMedium& medium) const = 0;

  /// What the medium adds to its grid's textures.
  virtual vtkTransmittanceMediumTextures::Extras GetExtras(
    const vtkTyndallMedium& medium) const = 0;

  /**
   * Uploads what changed of `medium` (GetGrid() and GetExtras()) into
   * `textures`; errors go through `reporter`. False when the medium cannot
   * be rendered.
   */
  bool Upload(vtkOpenGLRenderWindow* window, const vtkTyndallMedium& medium,
    vtkTransmittanceMediumTextures& textures, vtkObject* reporter) const;

  /**
   * Sets the switches that describe the medium's extinction (every pass):
   * missing data, clipping, coloured extinction, procedural detail and its
   * GLSL; vetoes empty-space skipping where the medium glows in empty blocks.
   */
  virtual void DeclareSwitches(const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures, Variant& variant) const = 0;

  /// Sets the switches of the camera rays' colour: emission, particle colours.
  virtual void DeclareColorSwitches(const vtkTyndallMedium& medium, Variant& variant) const = 0;

  /**
   * Sets the switches of the camera rays' samples (the ray-cast pass, after
   * its other switches), given the world width of a pixel at the medium's
   * nearest point in the frame (vtkTyndallFootprint::Minimum()): procedural
   * detail keeps the waves such a pixel shows, filtered. Nothing by default.
   */
  virtual void DeclareCameraSwitches(
    const vtkTyndallMedium& medium, double nearestPixel, Variant& variant) const
  {
    (void)medium;
    (void)nearestPixel;
    (void)variant;
  }

  /**
   * Sets the uniforms the medium's switches declare (those a program does
   * not declare are skipped by OpenGL).
   */
  virtual void SetUniforms(vtkShaderProgram* program, const vtkTyndallMedium& medium,
    const vtkTransmittanceMediumTextures& textures) const = 0;

  /**
   * Loop iterations of one brute-force light march through the medium,
   * given `gridMarch`, those of a march through a grid.
   */
  virtual double GetLightMarchIterations(const vtkTyndallMedium& medium, double gridMarch) const
  {
    (void)medium;
    return gridMarch;
  }

  /**
   * The particle cloud whose share of the extinction maps is splatted
   * (vtkTransmittanceSplatPass) instead of marched, when `medium` is one
   * whose mapper splats; null for every other medium.
   */
  virtual const vtkTyndallParticleMedium* GetSplatted(const vtkTyndallMedium& medium) const
  {
    (void)medium;
    return nullptr;
  }

protected:
  vtkTransmittanceMediumAdapter() = default;
};

#endif
