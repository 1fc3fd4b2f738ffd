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

private:
  vtkParticipatingMediumMapper(const vtkParticipatingMediumMapper&) = delete;
  void operator=(const vtkParticipatingMediumMapper&) = delete;
};

#endif
