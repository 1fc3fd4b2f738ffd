/**
 * @class   vtkTyndallSky
 * @brief   the programs' sky: --sky, --sky-top and --sky-image into a renderer's environment
 *
 * Apply() sets the environment a renderer gives Tyndall's path tracers (and
 * VTK's ray tracers; vtkTyndallEnvironment reads it) from the programs'
 * options: --sky R G B (EnvironmentalBG), --sky-top R G B (EnvironmentalBG2
 * and GradientEnvironmentalBG), --sky-image FILE (the renderer's
 * EnvironmentTexture, UseImageBasedLighting on). The sky's up is the
 * camera's view-up and its image's centre lies in the camera's direction of
 * view (EnvironmentUp, EnvironmentRight), so call it after the camera is
 * set. Without the options the renderer has VTK's default (black: no sky).
 *
 * ReadImage() reads an equirectangular image: .hdr through vtkHDRReader,
 * .exr through OpenEXR (when Tyndall is built with it: Debian's
 * libopenexr-dev), others (.png, .jpg, ...) through vtkImageReader2Factory
 * (8-bit: sRGB-decoded when the sky is read). Errors (no such file, a file
 * no reader takes, a damaged file, an image that is not 2-D) go to the
 * reporter's error mechanism, naming the file. Not wrapped.
 */

#ifndef vtkTyndallSky_h
#define vtkTyndallSky_h

#include "TyndallApplicationModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string

class vtkImageData;
class vtkRenderer;
class vtkTyndallOptions;

class TYNDALLAPPLICATION_EXPORT vtkTyndallSky : public vtkObject
{
public:
  static vtkTyndallSky* New();
  vtkTypeMacro(vtkTyndallSky, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Sets `renderer`'s environment from `options` (see the class
   * description). False (with an error through `reporter`) when the sky
   * image cannot be read.
   */
  static bool Apply(vtkTyndallOptions* options, vtkRenderer* renderer, vtkObject* reporter);

  /// An equirectangular image read from `path`; null (with an error through `reporter`) on failure.
  static vtkSmartPointer<vtkImageData> ReadImage(const std::string& path, vtkObject* reporter);

protected:
  vtkTyndallSky() = default;
  ~vtkTyndallSky() override = default;

private:
  vtkTyndallSky(const vtkTyndallSky&) = delete;
  void operator=(const vtkTyndallSky&) = delete;
};

#endif
