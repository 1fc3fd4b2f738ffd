/**
 * @class   vtkTransmittanceScopedTextures
 * @brief   activates textures for a scope and deactivates them when it ends
 *
 * The passes of vtkTransmittanceVolumeMapper bind their textures through
 * this guard, so that every return path (errors included) leaves the texture
 * units free. Null textures are skipped. Header only; internal to
 * Tyndall::Rendering.
 */

#ifndef vtkTransmittanceScopedTextures_h
#define vtkTransmittanceScopedTextures_h

#include "vtkTextureObject.h"

#include <initializer_list> // For std::initializer_list
#include <vector>           // For std::vector

class vtkTransmittanceScopedTextures
{
public:
  vtkTransmittanceScopedTextures(std::initializer_list<vtkTextureObject*> textures)
  {
    for (vtkTextureObject* texture : textures)
    {
      this->Add(texture);
    }
  }
  explicit vtkTransmittanceScopedTextures(const std::vector<vtkTextureObject*>& textures)
  {
    for (vtkTextureObject* texture : textures)
    {
      this->Add(texture);
    }
  }
  ~vtkTransmittanceScopedTextures()
  {
    for (auto it = this->Active.rbegin(); it != this->Active.rend(); ++it)
    {
      (*it)->Deactivate();
    }
  }
  vtkTransmittanceScopedTextures(const vtkTransmittanceScopedTextures&) = delete;
  vtkTransmittanceScopedTextures& operator=(const vtkTransmittanceScopedTextures&) = delete;

  /// Activates one more texture for the rest of the scope.
  void Add(vtkTextureObject* texture)
  {
    if (texture)
    {
      texture->Activate();
      this->Active.push_back(texture);
    }
  }

private:
  std::vector<vtkTextureObject*> Active;
};

#endif
