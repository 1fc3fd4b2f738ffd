/**
 * @class   vtkTyndallSceneBuilder
 * @brief   builds the scene of Tyndall's programs from their options
 *
 * tyndall-render, tyndall-viewer and the Python examples are thin
 * front-ends over this class and vtkTyndallOptions: Build() fills a
 * vtkRenderer with what the options describe, by one set of rules:
 *
 * - the medium: without an input the built-in default scene, a procedural
 *   cosine-noise cloud (vtkCosineNoiseSource, Resolution^3 voxels over
 *   [-1, 1]^3) as the shape of cosine-noise detail evaluated in the shader
 *   (--detail is on, contrast 0.5, unless --no-detail); with one, the volume
 *   read by vtkVolumeFileReader; placed by --position and --scale (its
 *   vtkVolume's matrix);
 * - further volumes (--add-volume, each with its --volume-* placement,
 *   transfer function and density scale), each drawn by its own mapper with
 *   the same settings, lit through the others (their maps shared), the
 *   renderer's volumes sorted back to front; clipping, detail and emission
 *   apply to the first volume;
 * - the transfer function: a --transfer-function file
 *   (vtkTransferFunctionFileReader), a --preset, or for data the guessed
 *   preset (vtkTransferFunctionPresets::GuessPreset), each applied by
 *   vtkTransferFunctionPresets::ApplyToImage(); the default scene's white
 *   cloud otherwise (opacity 0.5 per 0.05 units at density 8, albedo 0.95);
 * - the medium's and the mapper's settings (vtkParticipatingMediumProperty,
 *   vtkTransmittanceVolumeMapper): the options, else the defaults: for the
 *   default scene anisotropy 0.3 and ambient 0.25, for data 0 and 0.2;
 *   adaptive ETM, 8 coefficients, 256^2 maps;
 * - the camera: the default scene's fixed view (from (0, -0.6, 4.2) at the
 *   origin, view angle 30), or a fit to the data's bounds looking down -z,
 *   +y up (with added volumes or a placement, a fit to all volumes, also for
 *   the default scene); then --camera-position, --focal-point, --view-up, --view-angle;
 * - the lights: the given ones; else the default scene's low sun from the
 *   front right (warm white, intensity 0.85), or for data a white key light
 *   (intensity 0.7) from the camera's upper right in front of the data;
 * - the background: the default scene's sky gradient, or black; then
 *   --background and --background2.
 *
 * ApplyOptions() pushes the medium's and the mapper's settings again after
 * the options changed (the viewer's keys), without reloading anything.
 *
 * Errors (an unreadable input or transfer-function file, a degenerate
 * camera) are reported with vtkErrorMacro and Build() returns false.
 * During Build() the loading of the medium fires ProgressEvent (call data:
 * a double* in [0, 1]) with GetProgressLabel() saying what is loading.
 *
 * @sa vtkTyndallOptions
 */

#ifndef vtkTyndallSceneBuilder_h
#define vtkTyndallSceneBuilder_h

#include "TyndallApplicationModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkActor;
class vtkAlgorithm;
class vtkImageData;
class vtkLight;
class vtkCosineNoise;
class vtkParticipatingMediumProperty;
class vtkPlane;
class vtkRenderer;
class vtkTransferFunctionFileReader;
class vtkTransmittanceVolumeMapper;
class vtkTyndallOptions;
class vtkVolume;
class vtkVolumeFileReader;
class vtkVolumeProperty;
class vtkVolumeShadowReceiverPass;

class TYNDALLAPPLICATION_EXPORT vtkTyndallSceneBuilder : public vtkObject
{
public:
  static vtkTyndallSceneBuilder* New();
  vtkTypeMacro(vtkTyndallSceneBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The options the scene is built from.
   */
  void SetOptions(vtkTyndallOptions* options);
  vtkGetObjectMacro(Options, vtkTyndallOptions);
  ///@}

  /**
   * Loads the medium and fills `renderer` (its volume, lights, camera and
   * background; automatic light creation is turned off). False (with an
   * error) when something cannot be used.
   */
  bool Build(vtkRenderer* renderer);

  /**
   * Sets the medium's and the mapper's settings from the options again.
   */
  void ApplyOptions();

  /**
   * Sets only how the mappers show their picture from the options: the
   * display transform (--exposure, --tone-curve, --srgb; the identity with
   * LinearOutput) and the paths' denoiser (--path-denoise, whatever
   * LinearOutput). A path-traced picture keeps its samples.
   */
  void ApplyDisplayOptions();

  ///@{
  /**
   * Linear output: the mappers' display transform (--exposure, --tone-curve,
   * --srgb) left at the identity, whatever the options say (tyndall-render
   * draws its linear EXR so, then the PNG with the transform). Default
   * off; takes effect at Build() or ApplyOptions().
   */
  vtkSetMacro(LinearOutput, bool);
  vtkGetMacro(LinearOutput, bool);
  ///@}

  ///@{
  /**
   * A time series (tyndall-render --sequence): SetFrame() names the file
   * and its time frame that Build() reads in place of the options' input
   * and --frame (an empty path: the options' again). After Build(),
   * LoadFrame() reads another frame into the built scene: the same reader
   * settings, the volume's data replaced, its transfer function, camera and
   * lights kept; the mask or labels, added volumes, particles, ground and
   * surface of the options stay those of the first frame. False, with the
   * reader's error (naming the file), when the frame cannot be read (the
   * reader may keep the frame before: do not draw the scene then).
   */
  void SetFrame(const std::string& path, int frame);
  bool LoadFrame(const std::string& path, int frame);
  ///@}

  ///@{
  /**
   * What Build() made (null before a successful Build()).
   */
  vtkImageData* GetImage();
  vtkTransmittanceVolumeMapper* GetMapper();
  /// The volume's medium (with --vtk-property the volume draws a plain copy
  /// of it, made anew by ApplyOptions(): change the medium, then apply).
  vtkParticipatingMediumProperty* GetProperty();
  vtkVolume* GetVolume();
  /// The first light (the sun, the key light or the first given light).
  vtkLight* GetKeyLight();
  /// The volumes of --add-volume, in order.
  int GetNumberOfAddedVolumes();
  vtkVolume* GetAddedVolume(int i);
  ///@}

  /// Whether the built scene is the built-in default scene.
  vtkGetMacro(DefaultScene, bool);

  /**
   * Whether the last Build() failed because the options contradict each
   * other (a camera whose position and focal point coincide, a view-up
   * along the view direction) rather than because an input could not be
   * used: programs treat it as a bad command line.
   */
  vtkGetMacro(BadOptions, bool);

  /// How the transfer function was chosen ("preset CT (guessed)", "file tf.txt", ...).
  const char* GetTransferFunctionDescription() { return this->TransferFunctionDescription.c_str(); }

  /**
   * What the loader did to the data beyond reading it (vtkVolumeFileReader's
   * notes: NIfTI scaling applied, the frame of a 4-D file), one per line;
   * "" if nothing. Programs print them.
   */
  const char* GetReadNotes();

  /// What is loading during a ProgressEvent ("cloud: 128^3 voxels", "loading FILE").
  const char* GetProgressLabel() { return this->ProgressLabel.c_str(); }

protected:
  vtkTyndallSceneBuilder();
  ~vtkTyndallSceneBuilder() override;

  vtkTyndallOptions* Options = nullptr;
  bool DefaultScene = true;
  bool BadOptions = false;
  bool LinearOutput = false;
  std::vector<double> IsoValues; // --iso-values (ReadIsoValues())
  std::string TransferFunctionDescription;
  std::string ProgressLabel;
  std::string ReadNotes;

private:
  vtkTyndallSceneBuilder(const vtkTyndallSceneBuilder&) = delete;
  void operator=(const vtkTyndallSceneBuilder&) = delete;

  // The scene's placement, settings and extra volumes.
  bool LoadAddedVolumes();
  void GetSceneBounds(double bounds[6]);
  vtkSmartPointer<vtkVolumeFileReader> MakeReader(const char* path);
  void ApplyMapperOptions(vtkTransmittanceVolumeMapper* mapper);
  void ApplyDisplayOptions(vtkTransmittanceVolumeMapper* mapper);
  void ApplyMediumOptions(vtkParticipatingMediumProperty* medium);
  // The --emission-... options: the first volume's emission.
  void ApplyEmission();
  // --vtk-property: the volumes' plain vtkVolumeProperty copies, or their media.
  void ApplyPropertyKind();
  // Updates `source` with its progress and errors forwarded; false on error or no points.
  bool Update(vtkAlgorithm* source);
  bool ReadTransferFunctionFile();
  bool LoadMedium();
  // --mask FILE: the mapper's binary mask; false (with the reader's error)
  // when the file cannot be read.
  bool LoadMask();
  // --labels: each label present its palette colour and the volume's opacity.
  void ApplyLabels();
  // Parses --iso-values into IsoValues; false (with an error) for a value
  // that is not a finite number or more than vtkTyndallIsosurfaces allows.
  bool ReadIsoValues();
  bool ChooseTransferFunction();
  // --components: several components drawn together, each component's
  // functions over its own range (vtkTyndallComponents' rules); false (with
  // an error) for a mode the data cannot be drawn in or bad weights.
  bool ApplyComponents(const std::string& preset);
  // The --detail options: the property's DetailNoise (null without --detail).
  void ApplyDetail();
  // The --clip-... and --crop-... options: the mapper's clipping plane and cropping.
  void ApplyClipping();
  // The --slice-... options: every volume's slice plane (none but in the slice blend mode).
  void ApplySlice();
  // The plane of the options PREFIX-normal (default: +`axis`), PREFIX-origin
  // (default: the centre of `bounds`) and PREFIX-offset (times the diagonal of `bounds`).
  vtkSmartPointer<vtkPlane> MakePlane(const std::string& prefix, const double bounds[6], int axis);
  bool SetUpCamera(vtkRenderer* renderer);
  void SetUpLights(vtkRenderer* renderer);
  void SetUpBackground(vtkRenderer* renderer);
  // --ground: a white ground under the volume that receives its shadow.
  void AddGround(vtkRenderer* renderer);
  // --surface FILE: a surface that receives the volume's shadow; false (with
  // an error naming the file) when it cannot be read or has no polygons.
  bool AddSurface(vtkRenderer* renderer);
  // --particles FILE: a particle cloud as another volume (vtkTransmittanceParticleMapper);
  // false (with the reader's error) when it cannot be read.
  bool LoadParticles();
  // The actors with shadows: the receiver pass installed once.
  void ReceiveShadows(vtkRenderer* renderer);
  bool Run(vtkAlgorithm* source);

  // The volume's file and time frame (SetFrame()); "" and -1: the options'.
  std::string FramePath;
  int FrameIndex = -1;
  // LoadMedium()'s and LoadFrame()'s reader settings from the options.
  void ConfigureReader(vtkVolumeFileReader* reader, int frame);

  vtkSmartPointer<vtkAlgorithm> Source;
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Property;
  vtkSmartPointer<vtkCosineNoise> DetailNoise;
  vtkSmartPointer<vtkPlane> SlicePlane; // --blend-mode slice's plane (ApplySlice())
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkLight> KeyLight;
  vtkSmartPointer<vtkActor> Ground;
  vtkSmartPointer<vtkActor> Surface;
  vtkSmartPointer<vtkVolumeShadowReceiverPass> GroundShadows;
  vtkSmartPointer<vtkTransferFunctionFileReader> TransferFunctionFile;

  /// A volume added with --add-volume.
  struct AddedVolume
  {
    vtkSmartPointer<vtkImageData> Image;
    vtkSmartPointer<vtkTransmittanceVolumeMapper> Mapper;
    vtkSmartPointer<vtkParticipatingMediumProperty> Property;
    vtkSmartPointer<vtkVolume> Volume;
    bool Particles = false; // a --particles cloud
    double DensityScale = 1.0;
  };
  std::vector<AddedVolume> AddedVolumes;
};

#endif
