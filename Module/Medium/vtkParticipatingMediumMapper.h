/**
 * @class   vtkParticipatingMediumMapper
 * @brief   what Tyndall's scene reader reads of a volume mapper that draws a participating medium
 *
 * The GL-free base of Tyndall's volume mappers (vtkTransmittanceVolumeMapper
 * and its particle mapper). Tyndall's scene reader (vtkTyndallSceneReader,
 * shared by the GPU mapper and the CPU integrators) reads a volume's medium
 * through this class, without knowing the OpenGL mapper: the image whose
 * scalars are the medium, and for a particle cloud the particles. Other
 * volumes of a renderer are Tyndall media when their mapper is one of
 * these.
 *
 * A mask, through the API of vtkGPUVolumeRayCastMapper: SetMaskInput()
 * with the binary mask type hides the samples whose mask voxel is 0 or
 * less; with the label-map type its labels select the property's label
 * functions, mixed by MaskBlendFactor (vtkTyndallLabelMap); on both
 * renderers (vtkTyndallGridMedium).
 *
 * Not instantiated: create a vtkTransmittanceVolumeMapper or a
 * vtkTransmittanceParticleMapper.
 *
 * @sa vtkTransmittanceVolumeMapper vtkTransmittanceParticleMapper
 */

#ifndef vtkParticipatingMediumMapper_h
#define vtkParticipatingMediumMapper_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkVolumeMapper.h"

class vtkImageData;
class vtkTyndallParticles;

class TYNDALLMEDIUM_EXPORT vtkParticipatingMediumMapper : public vtkVolumeMapper
{
public:
  vtkTypeMacro(vtkParticipatingMediumMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The image whose scalars are the medium: the input itself here (null
   * when it is not a vtkImageData); a particle mapper's grid of its
   * particles (vtkTransmittanceParticleMapper), read from the input first.
   */
  virtual vtkImageData* GetMediumImage();

  /// The mask types (VTK's values: vtkGPUVolumeRayCastMapper's).
  enum MaskTypes
  {
    BinaryMaskType = 0,
    LabelMapMaskType = 1
  };

  ///@{
  /**
   * A mask over the volume, as vtkGPUVolumeRayCastMapper takes it (null:
   * none, the default): an image of the volume's dimensions whose scalars
   * (one component; point scalars for a volume of point scalars, cell
   * scalars for cell scalars) lie on the volume's samples. With
   * BinaryMaskType, a sample is empty medium (for the camera and the
   * light) where the mask is 0 or less: at the nearest mask voxel with the
   * nearest interpolation (VTK's), where any of the 8 mask voxels around it
   * is with trilinear interpolation (missing data's rule). A mask of other
   * dimensions is an error (nothing is drawn).
   */
  void SetMaskInput(vtkImageData* mask);
  vtkGetObjectMacro(MaskInput, vtkImageData);
  ///@}

  ///@{
  /**
   * The mask's type: BinaryMaskType or LabelMapMaskType (the default, as
   * vtkGPUVolumeRayCastMapper's). A label map's value at a sample (its
   * nearest, rounded, 0 to 255) selects the property's label functions
   * (vtkVolumeProperty::SetLabelColor(), SetLabelScalarOpacity(); label 0
   * and labels without functions the volume's), mixed with the volume's by
   * the blend factor as VTK 9.1 mixes them (Documentation/mapper.md,
   * "Masks"); a mask of other dimensions or with a NaN is an error.
   */
  vtkSetClampMacro(MaskType, int, BinaryMaskType, LabelMapMaskType);
  vtkGetMacro(MaskType, int);
  void SetMaskTypeToBinary() { this->SetMaskType(BinaryMaskType); }
  void SetMaskTypeToLabelMap() { this->SetMaskType(LabelMapMaskType); }
  ///@}

  ///@{
  /**
   * A label map's blend between the volume's and the labels' transfer
   * functions, in [0, 1], default 1 (vtkGPUVolumeRayCastMapper's): 0 the
   * volume's alone, 1 the labels' alone where the label is not 0.
   */
  vtkSetClampMacro(MaskBlendFactor, float, 0.0f, 1.0f);
  vtkGetMacro(MaskBlendFactor, float);
  ///@}

  ///@{
  /**
   * VTK 9.2's VolumetricScatteringBlending (of vtkGPUVolumeRayCastMapper),
   * for a plain vtkVolumeProperty with Shade on: in [0, 2], how much of each
   * shaded sample's colour is isotropic single scattering (lit by the
   * lights through the medium, no normal) instead of VTK's gradient
   * (surface) shading, by VTK 9.2's formula in the gradient magnitude and
   * the opacity (vtkTyndallShading): 0 surface shading only (VTK's
   * picture), 1 VTK's "smart" blend (surface-like where the gradient is
   * strong, volumetric where it is weak), 2 volumetric only. Default 0,
   * VTK 9.2's: surface shading, shadowed. The isosurface blend mode is
   * surface shaded whatever the value.
   */
  vtkSetClampMacro(VolumetricScatteringBlending, float, 0.0f, 2.0f);
  vtkGetMacro(VolumetricScatteringBlending, float);
  ///@}

  ///@{
  /**
   * Whether the renderer's sky lights the medium: its environment as VTK's
   * ray tracers read it (EnvironmentalBG, its gradient, an equirectangular
   * EnvironmentTexture with UseImageBasedLighting; vtkTyndallEnvironment),
   * sampled by the path tracers, and in the map-based frame carried by
   * SkyLightDirections directional lights (or its mean radiance added to
   * the ambient term). Default on: VTK's default sky is black (no light).
   * ParaView gives every view's renderer a grey-blue environment colour, so
   * the ParaView plugin turns it off unless asked.
   */
  vtkSetMacro(SkyLight, bool);
  vtkGetMacro(SkyLight, bool);
  vtkBooleanMacro(SkyLight, bool);
  ///@}

  ///@{
  /**
   * How many directional lights carry the sky in the map-based frame (and
   * in its CPU twin, vtkSingleScatteringReference): in [0, 8], default 4.
   * The sky is cut into that many regions of about equal light (a median
   * cut, vtkTyndallSkyLights), each a directional light with its own
   * transmittance map, so that the sky's light is shadowed inside the
   * medium as the path tracers' sampled sky is. They take the slots the
   * renderer's lights leave of the 8 a scene has
   * (vtkTransmittanceVolumeMapper::GetMaximumNumberOfLights()): with 6
   * renderer lights the sky gets at most 2. They light the medium's
   * scattering and gradient shading (not surfaces). 0 adds the sky's
   * mean radiance to the ambient term instead (and to gradient shading as
   * diffuse light): unshadowed, evenly bright inside dense media, but no
   * map's cost. The path tracers sample the sky
   * itself and ignore this.
   */
  vtkSetClampMacro(SkyLightDirections, int, 0, 8);
  vtkGetMacro(SkyLightDirections, int);
  ///@}

  /// vtkSmartVolumeMapper's vector modes (the same values).
  enum VectorModes
  {
    DISABLED = -1,
    MAGNITUDE = 0,
    COMPONENT = 1
  };

  ///@{
  /**
   * vtkSmartVolumeMapper's vector mode, for scalars of several components
   * with a property's IndependentComponents on: DISABLED (the default)
   * draws the components (vtkTyndallComponents' rules), MAGNITUDE the
   * length of each tuple and COMPONENT the component VectorComponent (in
   * [0, 3], default 0; one that the scalars lack is an error), each as one
   * component classified by the property's functions 0. Dependent
   * components and one-component scalars are drawn as they are, whatever
   * the mode (ParaView sets it from its colour map's vector mode).
   */
  vtkSetClampMacro(VectorMode, int, DISABLED, COMPONENT);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, 3);
  vtkGetMacro(VectorComponent, int);
  ///@}

#ifndef __VTK_WRAP__
  /// Internal (the scene reader): whether the medium is a particle cloud (GetParticles()).
  virtual bool DrawsParticles()
  {
    return false;
  }

  /**
   * Internal (the scene reader): the particles whose sum the medium is (read
   * by GetMediumImage()), or null for an image input.
   */
  virtual const vtkTyndallParticles* GetParticles()
  {
    return nullptr;
  }

  /// Internal: whether the extinction maps add the particles in closed form (splatting).
  virtual bool GetSplatsParticles()
  {
    return false;
  }
#endif

protected:
  vtkParticipatingMediumMapper();
  ~vtkParticipatingMediumMapper() override;

  vtkImageData* MaskInput = nullptr;
  int MaskType = LabelMapMaskType;
  float MaskBlendFactor = 1.0f;
  float VolumetricScatteringBlending = 0.0f;
  int VectorMode = DISABLED;
  int VectorComponent = 0;
  bool SkyLight = true;
  int SkyLightDirections = 4;

private:
  vtkParticipatingMediumMapper(const vtkParticipatingMediumMapper&) = delete;
  void operator=(const vtkParticipatingMediumMapper&) = delete;
};

#endif
