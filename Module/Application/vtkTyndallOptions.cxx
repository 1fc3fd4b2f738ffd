#include "vtkTyndallOptions.h"

#include "vtkObjectFactory.h"
#include "vtkStringArray.h"
#include "vtkTransferFunctionPresets.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkTyndallOptions);

namespace
{
constexpr int Both = vtkTyndallOptions::RENDER | vtkTyndallOptions::VIEWER;
constexpr int Render = vtkTyndallOptions::RENDER;
constexpr int Viewer = vtkTyndallOptions::VIEWER;
constexpr double Huge = 1.0e6;
constexpr double Coordinate = 1.0e30;

enum class Kind
{
  Flag,      // no argument
  Integer,   // one integer in [Min, Max]
  Number,    // one number in [Min, Max] (Open: exclusive)
  Triple,    // three numbers in [Min, Max]
  Pair,      // two integers in [Min, Max]
  Text,      // one word
  Choice,    // one of Choices ('|'-separated)
  Light,     // a new light: three numbers
  LightSet,  // the most recent light's colour (3 numbers) or intensity (1)
  Volume,    // another volume: a file name
  VolumeSet, // the most recent volume's position (3 numbers), scale or density (1), preset or
             // transfer function (a word: Metavar NAME or FILE)
  Help,      // -h, --help
  Action     // a viewer key without an option
};

// How a viewer key changes its option.
enum class KeyMode
{
  None,
  Add,      // KeysUp add Step, KeysDown subtract it
  Multiply, // KeysUp multiply by Step, KeysDown divide by it
  Toggle,   // KeysUp toggles the flag
  Choose    // the n-th key of KeysUp chooses choice n
};

// One option: a row of the table.
struct Spec
{
  const char* Name; // the long name without "--" (or an action's name)
  const char* Short;
  Kind Type;
  double Min, Max;
  bool Open; // the range excludes its ends
  const char* Choices;
  const char* Metavar;
  const char* Default; // in --help, and the value of an unset number
  const char* Group;
  int Programs;
  const char* Help;
  KeyMode Mode = KeyMode::None;
  const char* KeysUp = "";
  const char* KeysDown = "";
  double Step = 0.0;
};

// The groups whose options repeat (one heading in --help each).
constexpr const char* LightsGroup =
  "Lights (repeatable, up to 8 are used; any of them replaces the default light)";
constexpr const char* VolumesGroup =
  "Several volumes (repeatable, up to 3; each is lit through the others)";
// The particle cloud's options.
constexpr const char* ParticlesGroup = "Particles";

// The table. Help texts wrap at 80 columns; "\n" starts a new line.
const Spec kOptions[] = {
  { "grid", "", Kind::Text, 0, 0, false, "", "NAME", "", "Input", Both,
    "grid of a .vdb file (default: 'density' if it is a float grid, else the first float grid)" },
  { "component", "", Kind::Integer, 0, 1024, false, "", "N", "", "Input", Both,
    "component of multi-component scalars to render (default: multi-component data is "
    "refused)" },
  { "components", "", Kind::Choice, 0, 0, false, "one|independent|dependent", "MODE", "one",
    "Input", Both,
    "draw multi-component scalars (2 to 4) together: independent (each component its own "
    "transfer functions, the preset's over its range, coloured red, green, blue, grey; their "
    "extinctions add) or dependent (2: colour from the first, opacity from the second; 4: RGBA); "
    "default one (pick it with --component)" },
  { "component-weights", "", Kind::Text, 0, 0, false, "", "W,W,...", "", "Input", Both,
    "the weight of each independent component in [0, 1] (comma-separated; default 1 each)" },
  { "mask", "", Kind::Text, 0, 0, false, "", "FILE", "", "Input", Both,
    "a binary mask: a volume file of the input's dimensions whose samples of 0 or less hide the "
    "input's there (missing data, for the camera and the light; vtkGPUVolumeRayCastMapper's "
    "binary mask)" },
  { "labels", "", Kind::Text, 0, 0, false, "", "FILE", "", "Input", Both,
    "a label map: a volume file of the input's dimensions whose samples' values (rounded, 1 to "
    "255) are labels, each coloured by a categorical palette with the volume's opacity; 0 keeps "
    "the volume's colour (vtkGPUVolumeRayCastMapper's label-map mask)" },
  { "label-blend", "", Kind::Number, 0, 1, false, "", "F", "1", "Input", Both,
    "how much of the labels' colour a labelled sample takes, in [0, 1] (the mask blend factor)" },
  { "frame", "", Kind::Integer, 0, 1000000, false, "", "N", "0", "Input", Both,
    "time frame of a 4-D file (NIfTI with a time dimension)" },
  { "no-rescale", "", Kind::Flag, 0, 0, false, "", "", "", "Input", Both,
    "keep a NIfTI file's stored values (default: apply its scl_slope and scl_inter)" },
  { "level-set-to-fog", "", Kind::Flag, 0, 0, false, "", "", "", "Input", Both,
    "read an OpenVDB level set as a fog volume (OpenVDB's sdfToFogVolume: 0 outside, 1 inside, "
    "a ramp across the narrow band)" },
  { "memory-limit", "", Kind::Number, 1, 1e9, false, "", "MIB", "4096", "Input", Both,
    "largest volume to read, in MiB: a file whose header claims more is refused before anything "
    "is allocated" },
  { "resolution", "-r", Kind::Integer, 8, 512, false, "", "N", "128", "Input", Both,
    "voxels per axis of the built-in cloud (default scene only)" },
  { "position", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "0 0 0", "Input",
    Both, "translation of the volume (the input or the built-in cloud) in world units" },
  { "scale", "", Kind::Number, 0, Huge, true, "", "S", "1", "Input", Both,
    "scale of the volume about the world origin, > 0" },
  { "add-volume", "", Kind::Volume, 0, 0, false, "", "FILE", "", VolumesGroup, Both,
    "another volume, read like the input and drawn with the same method, lights and medium "
    "settings; the --volume-* options after it set it up (clipping, detail and emission apply "
    "to the first volume only)" },
  { "no-scene-shadows", "", Kind::Flag, 0, 0, false, "", "", "", VolumesGroup, Both,
    "light each volume as if it were alone (vtkParticipatingMediumProperty::SceneShadows off)",
    KeyMode::Toggle, "v" },
  { "no-scene-compositing", "", Kind::Flag, 0, 0, false, "", "", "", VolumesGroup, Both,
    "draw volumes whose boxes overlap as layers, each by its own mapper, instead of as one "
    "medium (vtkParticipatingMediumProperty::SceneCompositing off): for comparison" },
  { "particles", "", Kind::Text, 0, 0, false, "", "FILE", "", ParticlesGroup, Both,
    "a particle cloud (CSV or text of x y z radius density [r g b], .vtp or legacy .vtk "
    "polydata with radius and density arrays) drawn as a medium beside the input "
    "(vtkTransmittanceParticleMapper), lit and shadowed with it; it uses --method etm (its "
    "particles splatted into the extinction maps) unless --method is given" },
  { "particles-position", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "0 0 0",
    ParticlesGroup, Both, "translation of the particle cloud" },
  { "particles-scale", "", Kind::Number, 0, Huge, true, "", "S", "1", ParticlesGroup, Both,
    "scale of the particle cloud about the world origin, > 0" },
  { "particles-density-scale", "", Kind::Number, 0, Huge, false, "", "S", "1", ParticlesGroup, Both,
    "density scale of the particle cloud (its extinction is density times this)" },
  { "particles-grid", "", Kind::Integer, 8, 1024, false, "", "N", "128", ParticlesGroup, Both,
    "samples along the longest side of the grid the particles are sampled on for the camera "
    "rays (vtkTransmittanceParticleMapper::GridResolution)" },
  { "no-splatting", "", Kind::Flag, 0, 0, false, "", "", "", ParticlesGroup, Both,
    "march the particles' grid for the maps instead of splatting them: for comparison" },
  { "volume-position", "", Kind::VolumeSet, -Coordinate, Coordinate, false, "", "X Y Z", "0 0 0",
    VolumesGroup, Both, "translation of the most recent --add-volume" },
  { "volume-scale", "", Kind::VolumeSet, 0, Huge, true, "", "S", "1", VolumesGroup, Both,
    "scale of the most recent --add-volume about the world origin, > 0" },
  { "volume-density-scale", "", Kind::VolumeSet, 0, Huge, false, "", "S", "1", VolumesGroup, Both,
    "density scale of the most recent --add-volume" },
  { "volume-preset", "", Kind::VolumeSet, 0, 0, false, "", "NAME", "", VolumesGroup, Both,
    "transfer-function preset of the most recent --add-volume (default: guessed from its data)" },
  { "volume-transfer-function", "", Kind::VolumeSet, 0, 0, false, "", "FILE", "", VolumesGroup,
    Both, "transfer-function file of the most recent --add-volume" },
  { "method", "", Kind::Choice, 0, 0, false, "none|brute-force|tfm|adaptive-tfm|etm|adaptive-etm",
    "M", "adaptive-etm", "Scattering", Both, "light transmittance", KeyMode::Choose, "123456" },
  { "shade", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "add VTK's gradient surface term (VTK's Diffuse 0.7, Specular 0.2, specular power 10; the "
    "CT and MR presets' 0.9, 0.3, 10) to the medium's single scattering, shadowed like it: its "
    "surfaces catch highlights (with --vtk-property: VTK's gradient shading instead)",
    KeyMode::Toggle, "g" },
  { "vtk-property", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "draw the volumes with a plain vtkVolumeProperty (VTK's meaning) made from their transfer "
    "functions: unlit, or with --shade VTK's gradient shading shadowed by the transmittance "
    "maps (path traced: its collisions scatter as shaded surfaces, a shaded CT); the medium's "
    "own options do not apply (the built-in cloud without its detail; particles keep theirs)",
    KeyMode::Toggle, "k" },
  { "model", "", Kind::Choice, 0, 0, false, "emission-absorption|single-scattering", "M",
    "single-scattering", "Scattering", Both,
    "single-scattering (colour = albedo) or emission-absorption (colour = emitted colour, as "
    "vtkGPUVolumeRayCastMapper)" },
  { "blend-mode", "", Kind::Choice, 0, 0, false,
    "composite|maximum|minimum|average|additive|isosurface|slice", "B", "composite", "Scattering",
    Both,
    "composite draws the medium; maximum, minimum and average intensity and additive project "
    "the volume's scalars as vtkGPUVolumeRayCastMapper does (unlit; the colour and opacity "
    "functions of the preset); isosurface draws the surfaces of --iso-values, lit and "
    "shadowed; slice draws the colour and opacity functions on the plane of --slice-normal "
    "(lit as a surface, unshadowed, with --shade)" },
  { "iso-values", "", Kind::Text, 0, 0, false, "", "V,V,...", "", "Scattering", Both,
    "the scalar values whose surfaces --blend-mode isosurface draws (at most 16, comma-separated; "
    "their colour and opacity are the preset's at each value)" },
  { "coefficients", "", Kind::Integer, 1, 16, false, "", "N", "8", "Scattering", Both,
    "series coefficients per map texel", KeyMode::Add, "+=", "-_", 1.0 },
  { "map-size", "", Kind::Integer, 16, 4096, false, "", "N", "256", "Scattering", Both,
    "transmittance map size in texels" },
  { "anisotropy", "", Kind::Number, -0.99, 0.99, false, "", "G", "0.3 / 0", "Scattering", Both,
    "Henyey-Greenstein g; > 0 scatters forward", KeyMode::Add, "a", "z", 0.1 },
  { "density-scale", "", Kind::Number, 0, Huge, false, "", "S", "1", "Scattering", Both,
    "multiplies the extinction", KeyMode::Multiply, "d", "c", 1.25 },
  { "extinction-color", "", Kind::Triple, 0, 1, false, "", "R G B", "1 1 1", "Scattering", Both,
    "extinction per channel, relative to the density (a chromatic medium: the light it lets "
    "through takes the colour of the weakest components)" },
  { "sample-distance", "", Kind::Number, 0, Huge, false, "", "D", "0", "Scattering", Both,
    "camera-ray step in world units; 0 = half the smallest voxel spacing" },
  { "light-samples", "", Kind::Integer, 1, 2048, false, "", "N", "128", "Scattering", Both,
    "samples per light ray (map build, brute force)" },
  { "adaptive-threshold", "", Kind::Number, 1e-6, 0.5, false, "", "T", "0.01", "Scattering", Both,
    "transmittance threshold of the adaptive methods" },
  { "ambient", "", Kind::Number, 0, Huge, false, "", "A", "0.25 / 0.2", "Scattering", Both,
    "unshadowed ambient in-scattering" },
  { "octaves", "", Kind::Integer, 1, 8, false, "", "N", "2", "Scattering", Both,
    "multiple-scattering octaves (single scattering): each adds light seen through less "
    "extinction, scattered more isotropically; 1 = single scattering alone",
    KeyMode::Add, "m", "n", 1.0 },
  { "octave-scattering", "", Kind::Number, 0, 4, false, "", "A", "1.3", "Scattering", Both,
    "light scattered by each further octave, times the albedo" },
  { "octave-extinction", "", Kind::Number, 0, 1, false, "", "B", "0.45", "Scattering", Both,
    "extinction the light of each further octave sees (relative to the one before)" },
  { "octave-anisotropy", "", Kind::Number, 0, 1, false, "", "C", "0", "Scattering", Both,
    "anisotropy of each further octave (relative to the one before)" },
  { "octave-build-up", "", Kind::Number, 0, 64, false, "", "K", "6", "Scattering", Both,
    "build-up of the further octaves: times 1 - T^K (T the light's transmittance; 0 = off)" },
  { "emission-scale", "", Kind::Number, 0, Huge, false, "", "E", "0", "Scattering", Both,
    "emission strength (single scattering); the emission colour comes from the transfer "
    "function file's 'emission' lines, else its colour" },
  { "emission-array", "", Kind::Text, 0, 0, false, "", "NAME", "", "Scattering", Both,
    "emit from this array of the input (a .vdb: this grid, read beside the rendered one), per unit "
    "length and independently of the density: fire from a temperature grid; --emission-scale "
    "defaults to 1 with it" },
  { "blackbody", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "the emission array is a temperature: black-body colours, luminance 1 at its hottest value "
    "(else the transfer function's emission colour)" },
  { "temperature-scale", "", Kind::Number, 0, Huge, false, "", "K", "1", "Scattering", Both,
    "Kelvin per unit of the emission array (--blackbody)" },
  { "light-scale", "", Kind::Number, 0, Huge, false, "", "K", "4 pi", "Scattering", Both,
    "irradiance per unit of light intensity" },
  { "no-jitter", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "do not jitter the ray samples per pixel", KeyMode::Toggle, "j" },
  { "no-skip", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "march every sample: no empty-space skipping (same picture, slower; for timing)" },
  { "cache-size", "", Kind::Integer, 16, 1024, false, "", "N", "256", "Scattering", Both,
    "texels along the longest side of the transmittance cache (map methods; 2 bytes per texel "
    "and light)" },
  { "no-cache", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "no transmittance cache: every camera sample reads the maps (full map resolution, slower)" },
  { "bricking", "", Kind::Choice, 0, 0, false, "off|on|auto", "M", "auto", "Scattering", Both,
    "the volume's scalars on the GPU as the 8^3 bricks that vary, bricks of one value shared "
    "(sparse data: an OpenVDB cache, air around a CT): auto when that takes at most half the "
    "dense texture's bytes; same picture" },
  { "path-trace", "", Kind::Integer, 0, 1000000, false, "", "SPP", "0", "Scattering", Both,
    "0: off; SPP > 0: the cinematic mode, volumetric path tracing on the GPU (full multiple "
    "scattering) refining a still picture up to SPP samples per pixel (tyndall-render renders "
    "until it has them; the viewer refines a still view and shows the map-based frame while "
    "anything moves)" },
  { "path-bounces", "", Kind::Integer, 1, 1000, false, "", "N", "8", "Scattering", Both,
    "with --path-trace: the most scattering events of a path (1: single scattering)" },
  { "path-shadows", "", Kind::Choice, 0, 0, false, "maps|tracked", "M", "maps", "Scattering", Both,
    "with --path-trace: the light's transmittance at a path's collisions read from the "
    "transmittance maps (fast) or ratio tracked (unbiased)" },
  { "path-distance", "", Kind::Choice, 0, 0, false, "closed-form|delta-tracking", "M",
    "delta-tracking", "Scattering", Both,
    "with --path-trace: free flights and tracked light transmittance through procedural detail "
    "in closed form (the cosine-noise paper's) or by delta and ratio tracking (a grid is always "
    "tracked)" },
  { "path-denoise", "", Kind::Flag, 0, 0, false, "", "", "", "Scattering", Both,
    "with --path-trace: show the paths' picture denoised, an edge-avoiding filter of what the "
    "paths add to the map-based frame, which guides it (its edges; noise-free); the filter "
    "narrows as the samples grow; the EXR is denoised too",
    KeyMode::Toggle, "x" },
  { "detail", "", Kind::Flag, 0, 0, false, "", "", "", "Procedural detail", Both,
    "multiply the medium's extinction by cosine noise evaluated in the shader, never voxelised "
    "(the volume becomes the coarse shape); light transmittance through it is exact with "
    "--method brute-force (closed form per sample), approximate with the maps. On by default "
    "in the built-in scene, off for data" },
  { "no-detail", "", Kind::Flag, 0, 0, false, "", "", "", "Procedural detail", Both,
    "the built-in scene without its procedural detail: the voxelised cloud alone (faster, "
    "blurred close up)" },
  { "detail-octaves", "", Kind::Integer, 1, 16, false, "", "N", "4", "Procedural detail", Both,
    "octaves of the noise (directions x octaves <= 256)" },
  { "detail-directions", "", Kind::Integer, 1, 256, false, "", "N", "24", "Procedural detail", Both,
    "cosine waves per octave" },
  { "detail-frequency", "", Kind::Number, 0, Huge, false, "", "F", "0", "Procedural detail", Both,
    "cycles of the first octave per data unit; 0 = one cycle per 8 samples of the volume along "
    "its smallest side (the last octaves are then finer than its voxels)" },
  { "detail-contrast", "", Kind::Number, 0, 10, false, "", "C", "0.5 / 0.3", "Procedural detail",
    Both,
    "standard deviation of the noise factor, whose mean is 1 (the shape's density is kept); "
    "above about 0.3 it dips below 0 in places, where it is clamped (see the rendering model)" },
  { "detail-filter", "", Kind::Number, 0, 4, false, "", "W", "0.5", "Procedural detail", Both,
    "width (standard deviation, in pixels) of the Gaussian that filters the noise's waves on "
    "camera rays: waves finer than about 2 pixels fade instead of aliasing and are not evaluated "
    "where the volume is too far to show them; 0: unfiltered" },
  { "detail-samples", "", Kind::Integer, 0, 64, false, "", "N", "0", "Procedural detail", Both,
    "0: camera rays march the detail at a quarter of its shortest wavelength; N > 0: each pixel "
    "draws N free-flight samples in closed form instead (the paper's section 7), and still "
    "frames are averaged (--detail-frames)" },
  { "detail-frames", "", Kind::Integer, 1, 4096, false, "", "N", "32", "Procedural detail", Both,
    "with --detail-samples: still frames averaged into the picture (tyndall-render renders at "
    "least this many; the viewer keeps refining a still view up to it)" },
  { "preset", "", Kind::Text, 0, 0, false, "", "NAME", "", "Transfer function", Both,
    "a named preset (vtkTransferFunctionPresets) over the data's scalar range, unit distance = "
    "the mean voxel spacing; names ignore case, spaces, '-' and '_'. Default for data inputs: "
    "the guessed preset (vtkTransferFunctionPresets::GuessPreset)" },
  { "transfer-function", "", Kind::Text, 0, 0, false, "", "FILE", "", "Transfer function", Both,
    "a transfer-function text file (format below)" },
  { "clip-normal", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Clipping",
    Both,
    "clip the medium with a plane that keeps the side (X, Y, Z) points to; the clipped part "
    "casts no shadow" },
  { "clip-origin", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Clipping",
    Both, "a point of the clipping plane (default: the centre of the data)" },
  { "clip-offset", "", Kind::Number, -1, 1, false, "", "F", "0", "Clipping", Both,
    "moves the clipping plane along its normal by F times the volume's diagonal (without "
    "--clip-normal: a plane of normal +x through the centre)",
    KeyMode::Add, "p", "o", 0.05 },
  { "crop-low", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Clipping", Both,
    "crop the medium to the box from X Y Z (data coordinates) to --crop-high" },
  { "crop-high", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Clipping",
    Both, "the far corner of the cropping box (default: the data's upper bounds)" },
  { "slice-normal", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "0 0 1",
    "Clipping", Both, "the normal of the plane --blend-mode slice draws (world coordinates)" },
  { "slice-origin", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Clipping",
    Both, "a point of the slice's plane (default: the centre of the volume)" },
  { "slice-offset", "", Kind::Number, -1, 1, false, "", "F", "0", "Clipping", Both,
    "moves the slice's plane along its normal by F times the volume's diagonal", KeyMode::Add, "]",
    "[", 0.02 },
  { "camera-position", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Camera",
    Both, "where the camera is" },
  { "focal-point", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Camera",
    Both, "the point it looks at" },
  { "view-up", "", Kind::Triple, -Coordinate, Coordinate, false, "", "X Y Z", "", "Camera", Both,
    "the image's up direction (made orthogonal to the view direction; must not be parallel to "
    "it)" },
  { "view-angle", "", Kind::Number, 0, 180, true, "", "DEG", "30", "Camera", Both,
    "field of view in degrees, 0 < DEG < 180" },
  { "horizontal-view-angle", "", Kind::Flag, 0, 0, false, "", "", "", "Camera", Both,
    "the view angle is horizontal (default: vertical)" },
  { "light-direction", "", Kind::Light, -Coordinate, Coordinate, false, "", "X Y Z", "",
    LightsGroup, Both,
    "a directional light travelling along (X, Y, Z), i.e. coming from -(X, Y, Z): 0 -1 0 "
    "shines downwards" },
  { "light-position", "", Kind::Light, -Coordinate, Coordinate, false, "", "X Y Z", "", LightsGroup,
    Both, "a point light at (X, Y, Z), no fall-off" },
  { "light-color", "", Kind::LightSet, 0, Huge, false, "", "R G B", "1 1 1", LightsGroup, Both,
    "colour of the most recent light, >= 0" },
  { "light-intensity", "", Kind::LightSet, 0, Huge, false, "", "I", "1", LightsGroup, Both,
    "intensity of the most recent light" },
  { "size", "-s", Kind::Pair, 16, 8192, false, "", "W H", "512 512", "Image", Render,
    "image size in pixels" },
  { "size", "-s", Kind::Pair, 16, 8192, false, "", "W H", "960 720", "Image", Viewer,
    "window size in pixels" },
  { "background", "", Kind::Triple, 0, 1, false, "", "R G B", "", "Image", Both,
    "background colour in [0, 1] (the bottom colour of a gradient) [default scene: sky "
    "gradient; data: black]" },
  { "ground", "", Kind::Flag, 0, 0, false, "", "", "", "Image", Both,
    "a grey ground under the volume (perpendicular to the view-up) that receives its shadow "
    "(vtkVolumeShadowReceiverPass)" },
  { "surface", "", Kind::Text, 0, 0, false, "", "FILE", "", "Image", Both,
    "a surface (.vtp, legacy .vtk polydata, .stl, .obj, .ply) drawn in the volume's world "
    "coordinates that receives its shadow" },
  { "background2", "", Kind::Triple, 0, 1, false, "", "R G B", "", "Image", Both,
    "top colour: makes the background a vertical gradient" },
  { "sky", "", Kind::Triple, 0, Huge, false, "", "R G B", "", "Image", Both,
    "light from a constant sky of this linear radiance (the renderer's EnvironmentalBG; with "
    "--sky-top the colour straight down), around the view-up: the path tracer samples it, the "
    "map-based frame has it as --sky-lights lights" },
  { "sky-lights", "", Kind::Integer, 0, 8, false, "", "N", "4", "Image", Both,
    "the map-based frame's sky as N directional lights with their own maps (shadowed; a median "
    "cut of the sky, in the slots the lights leave of 8); 0: its mean radiance as ambient light, "
    "unshadowed (the mapper's SkyLightDirections)" },
  { "sky-top", "", Kind::Triple, 0, Huge, false, "", "R G B", "", "Image", Both,
    "the sky's colour straight up: a vertical gradient from --sky (default black), linear in "
    "the elevation (EnvironmentalBG2)" },
  { "sky-image", "", Kind::Text, 0, 0, false, "", "FILE", "", "Image", Both,
    "light from an equirectangular sky image (.hdr, .exr: linear; .png, .jpg: sRGB), its "
    "centre in the camera's direction of view, its top row up (the renderer's "
    "EnvironmentTexture with UseImageBasedLighting)" },
  { "exposure", "", Kind::Number, -20, 20, false, "", "EV", "0", "Image", Both,
    "the medium's radiance times 2^EV before the tone curve (the mapper's Exposure; the "
    "background and geometry keep their colours where there is no medium)",
    KeyMode::Add, "e", "w", 0.5 },
  { "tone-curve", "", Kind::Choice, 0, 0, false, "linear|reinhard|aces", "C", "linear", "Image",
    Both,
    "the medium's tone curve: linear (none: above 1 clips in 8 bits), reinhard (x / (1 + x)) or "
    "aces (Narkowicz's filmic fit of ACES); tyndall-render's EXR stays linear, its PNG gets "
    "the curve" },
  { "srgb", "", Kind::Flag, 0, 0, false, "", "", "", "Image", Both,
    "encode the medium's light with the sRGB transfer function (8-bit output; the EXR stays "
    "linear)" },
  { "output", "-o", Kind::Text, 0, 0, false, "", "FILE", "", "Output", Render,
    "the PNG: the 8-bit frame buffer, i.e. linear radiance clamped to [0, 1] and quantised "
    "(--exposure, --tone-curve, --srgb map the medium's light first) [default scene: "
    "tyndall-cloud.png; data: <input name>.png in the current directory]" },
  { "exr", "", Kind::Text, 0, 0, false, "", "FILE", "", "Output", Render,
    "also write a linear float OpenEXR image (RGB, 32-bit float, unclamped radiance) captured "
    "from a float frame buffer" },
  { "sequence", "", Kind::Pair, 0, 1000000, false, "", "FIRST LAST", "", "Output", Render,
    "render frames FIRST to LAST of a time series, one picture each: INPUT names numbered files "
    "with a printf frame number (smoke_%04d.vdb is frame 12's smoke_0012.vdb), or is a 4-D file "
    "(NIfTI) whose time frames they are; -o names the pictures with a frame number too [default: "
    "<input name>_%04d.png]. Frame FIRST sets the transfer function, camera and lights; each frame "
    "rebuilds the maps; the times per frame are reported. A missing or damaged frame is an error "
    "that names it (the pictures before it are written)" },
  { "sequence", "", Kind::Pair, 0, 1000000, false, "", "FIRST LAST", "", "Viewer", Viewer,
    "show frames FIRST to LAST of a time series (INPUT as for tyndall-render --sequence: "
    "numbered files such as smoke_%04d.vdb, or a 4-D NIfTI file): Space plays and pauses, the "
    "left and right arrows step (both loop). Frame FIRST sets the transfer function, camera and "
    "lights; each frame rebuilds the maps. A frame that cannot be read is skipped with a warning "
    "(the frame before stays)" },
  { "play-rate", "", Kind::Number, 0.1, 240, false, "", "FPS", "24", "Viewer", Viewer,
    "with --sequence: frames per second while playing, at most (a frame is shown when it is "
    "read and drawn)" },
  { "skip-bad-frames", "", Kind::Flag, 0, 0, false, "", "", "", "Output", Render,
    "with --sequence: skip a missing or damaged frame with a warning (no picture for it) instead "
    "of stopping" },
  { "orbit", "", Kind::Number, -36000, 36000, false, "", "DEGREES", "", "Output", Render,
    "a camera path: the camera turns DEGREES about the data (about the view-up through the "
    "focal point) over the pictures, picture i of n at DEGREES x i / n (360 loops without "
    "repeating a picture). With --sequence over its frames, else --orbit-frames pictures of the "
    "one scene (the maps are built once); -o names them with a frame number [default: <name>_"
    "%04d.png]. The scene's lights stay where they are (a headlight turns with the camera)" },
  { "orbit-frames", "", Kind::Integer, 1, 100000, false, "", "N", "36", "Output", Render,
    "with --orbit and no --sequence: the number of pictures" },
  { "video", "", Kind::Text, 0, 0, false, "", "FILE", "", "Output", Render,
    "with --sequence or --orbit: also write the pictures as an Ogg Theora video (.ogv; VTK's "
    "vtkOggTheoraWriter and libtheora, the encoder Debian's VTK has). A run that fails leaves no "
    "video; skipped frames are not in it" },
  { "video-rate", "", Kind::Integer, 1, 120, false, "", "FPS", "24", "Output", Render,
    "the video's frames per second" },
  { "frames", "", Kind::Integer, 1, 1000, false, "", "N", "1", "Output", Render,
    "render N frames: frames after the first reuse the maps and shaders; their mean time is "
    "reported (the images are identical)" },
  { "quiet", "-q", Kind::Flag, 0, 0, false, "", "", "", "Output", Render,
    "no progress or timings on stderr (errors only)" },
  { "input", "-i", Kind::Text, 0, 0, false, "", "FILE", "", "Viewer", Viewer,
    "volume to show (same as VOLUME)" },
  { "script", "", Kind::Text, 0, 0, false, "", "FILE", "", "Viewer", Viewer,
    "run the commands in FILE, one per frame" },
  { "events", "", Kind::Text, 0, 0, false, "", "TEXT", "", "Viewer", Viewer,
    "run the commands in TEXT (separated by ';'), one per frame" },
  { "verbose", "-v", Kind::Flag, 0, 0, false, "", "", "", "Viewer", Viewer,
    "print a line per frame also without a script" },
  { "interactive-rate", "", Kind::Number, 0, 1000, false, "", "FPS", "10", "Viewer", Viewer,
    "frames per second asked while dragging (VTK's desired update rate): the camera rays are "
    "cast at a reduced size to meet it, shadows on, and the frame after the drag is full size; "
    "0: always full size" },
  { "help", "-h", Kind::Help, 0, 0, false, "", "", "", "Help", Both, "show this help and exit" },
  // The viewer's actions: keys without an option.
  { "hud", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer, "on-screen text on/off",
    KeyMode::Toggle, "h" },
  { "reset", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer, "reset the camera",
    KeyMode::Toggle, "r" },
  { "screenshot", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer,
    "screenshot (tyndall-viewer-NNN.png)", KeyMode::Toggle, "s" },
  { "quit", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer, "quit", KeyMode::Toggle,
    "q\033" },
  { "play", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer,
    "play or pause the sequence (--sequence)", KeyMode::Toggle, " " },
  { "next-frame", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer,
    "the sequence's next frame (after the last: the first)", KeyMode::Toggle, "\035" },
  { "previous-frame", "", Kind::Action, 0, 0, false, "", "", "", "Keys", Viewer,
    "the sequence's frame before (before the first: the last)", KeyMode::Toggle, "\034" },
};

struct Value
{
  bool Set = false;
  std::vector<double> Numbers;
  std::string Text;
  int Choice = -1;
};

struct Light
{
  bool Positional = false;
  double Vector[3] = { 0, 0, 0 };
  double Color[3] = { 1, 1, 1 };
  double Intensity = 1.0;
};

// A volume added with --add-volume and its --volume-* settings.
struct AddedVolume
{
  std::string File;
  double Position[3] = { 0, 0, 0 };
  double Scale = 1.0;
  double DensityScale = 1.0;
  std::string Preset;
  std::string TransferFunction;
};

// The error for a preset name that is not one ("" for a known one).
std::string UnknownPreset(const std::string& name)
{
  if (vtkTransferFunctionPresets::GetPresetIndex(name.c_str()) >= 0)
  {
    return "";
  }
  std::string known;
  for (int p = 0; p < vtkTransferFunctionPresets::GetNumberOfPresets(); ++p)
  {
    known += std::string(" ") + vtkTransferFunctionPresets::GetPresetName(p);
  }
  return "unknown preset '" + name + "' (known:" + known + ")";
}

// Whether the option's argument is a word (a name or a file), not numbers.
bool TakesWord(const Spec& spec)
{
  return spec.Type == Kind::Text || spec.Type == Kind::Volume ||
    (spec.Type == Kind::VolumeSet &&
      (std::string(spec.Metavar) == "NAME" || std::string(spec.Metavar) == "FILE"));
}

std::vector<std::string> Split(const char* text, char separator)
{
  std::vector<std::string> parts;
  std::string part;
  for (const char* p = text; *p; ++p)
  {
    if (*p == separator)
    {
      parts.push_back(part);
      part.clear();
    }
    else
    {
      part += *p;
    }
  }
  parts.push_back(part);
  return parts;
}

// Strict parsing: the whole text, finite; integers without a fraction.
bool ParseStrict(const std::string& text, bool integer, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const double v = integer ? static_cast<double>(std::strtol(text.c_str(), &end, 10))
                           : std::strtod(text.c_str(), &end);
  if (*end || !std::isfinite(v) || errno == ERANGE)
  {
    return false;
  }
  value = v;
  return true;
}

std::string RangeText(const Spec& s)
{
  std::ostringstream os;
  if (s.Open)
  {
    os << s.Min << " < " << s.Metavar << " < " << s.Max;
  }
  else
  {
    os << s.Min << ".." << s.Max;
  }
  return os.str();
}

// "an integer in 1..16", "three numbers in 0..1", ...
std::string Wanted(const Spec& s)
{
  switch (s.Type)
  {
    case Kind::Integer:
      return "an integer in " + RangeText(s);
    case Kind::Number:
      return s.Open ? "a number, " + RangeText(s) : "a number in " + RangeText(s);
    case Kind::Pair:
      return "two integers in " + RangeText(s);
    case Kind::Triple:
    case Kind::Light:
      return "three numbers in " + RangeText(s);
    case Kind::VolumeSet:
      if (TakesWord(s))
      {
        break;
      }
      return std::string(s.Name) == "volume-position"
        ? "three numbers in " + RangeText(s)
        : (s.Open ? "a number, " + RangeText(s) : "a number in " + RangeText(s));
    case Kind::Choice:
    {
      std::string list = s.Choices;
      std::replace(list.begin(), list.end(), '|', ' ');
      return "one of " + list;
    }
    default:
      break;
  }
  std::string what = s.Metavar;
  std::transform(what.begin(), what.end(), what.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return "a " + (what == "file" ? std::string("file name") : what);
}

// How many arguments an option takes after its name.
int ArgumentCount(const Spec& spec)
{
  switch (spec.Type)
  {
    case Kind::Flag:
    case Kind::Help:
      return 0;
    case Kind::Pair:
      return 2;
    case Kind::Triple:
    case Kind::Light:
      return 3;
    case Kind::LightSet:
      return std::string(spec.Name) == "light-color" ? 3 : 1;
    case Kind::VolumeSet:
      return std::string(spec.Name) == "volume-position" ? 3 : 1;
    default:
      return 1;
  }
}

// Reads the arguments of option `arg` (row `spec`) into `value`: a text, a
// choice or numbers within the row's range. False with `error` otherwise.
bool ReadValue(const Spec& spec, const std::string& arg, const std::vector<std::string>& args,
  Value& value, std::string& error)
{
  value.Set = true;
  if (TakesWord(spec))
  {
    value.Text = args[0];
    if (value.Text.empty())
    {
      error = arg + " needs a non-empty " + std::string(spec.Metavar);
    }
    return error.empty();
  }
  if (spec.Type == Kind::Choice)
  {
    const std::vector<std::string> choices = Split(spec.Choices, '|');
    const auto found = std::find(choices.begin(), choices.end(), args[0]);
    if (found == choices.end())
    {
      error = arg + " needs " + Wanted(spec) + "; got '" + args[0] + "'";
      return false;
    }
    value.Choice = static_cast<int>(found - choices.begin());
    value.Text = args[0];
    return true;
  }
  const bool integer = spec.Type == Kind::Integer || spec.Type == Kind::Pair;
  for (const std::string& a : args)
  {
    double v = 0.0;
    const bool parsed = ParseStrict(a, integer, v);
    const bool inside = spec.Open ? v > spec.Min && v < spec.Max : v >= spec.Min && v <= spec.Max;
    if (!parsed || !inside)
    {
      error = arg + " needs " + Wanted(spec) + ", got '" + a + "'";
      return false;
    }
    value.Numbers.push_back(v);
  }
  return true;
}

void Wrap(std::ostream& os, const std::string& left, const std::string& text)
{
  constexpr size_t column = 26, width = 80;
  std::string line = left;
  if (line.size() + 1 > column)
  {
    os << line << "\n";
    line.clear();
  }
  line.resize(column, ' ');
  std::istringstream words(text);
  bool first = true;
  for (std::string word; words >> word;)
  {
    if (!first && line.size() + 1 + word.size() > width)
    {
      os << line << "\n";
      line = std::string(column, ' ');
      first = true;
    }
    line += (first ? "" : " ") + word;
    first = false;
  }
  os << line << "\n";
}
}

//------------------------------------------------------------------------------
class vtkTyndallOptions::vtkInternals
{
public:
  std::map<std::string, Value> Values;
  bool VolumeDensityScaleGiven = false; // --volume-density-scale, any volume's
  std::vector<Light> Lights;
  std::vector<AddedVolume> Volumes;

  // The row of `name` for `program` (nullptr if none).
  static const Spec* Find(const std::string& name, int program)
  {
    for (const Spec& s : kOptions)
    {
      if ((s.Programs & program) && name == s.Name)
      {
        return &s;
      }
    }
    return nullptr;
  }

  // The input path, given once (as an operand or with --input).
  void SetInput(const std::string& path, std::string& input, std::string& error)
  {
    if (!input.empty())
    {
      error = "more than one input given ('" + input + "' and '" + path + "')";
      return;
    }
    input = path;
  }

  // Stores a parsed option: a new light, a setting of the latest light, the
  // input, or a value (checking what the row's range cannot say).
  void Store(const Spec& spec, const std::string& arg, const Value& value, std::string& input,
    std::string& error)
  {
    const std::string name = spec.Name;
    const std::vector<double>& n = value.Numbers;
    if (spec.Type == Kind::Light)
    {
      Light light;
      light.Positional = name == "light-position";
      std::copy(n.begin(), n.end(), light.Vector);
      if (!light.Positional && n[0] == 0 && n[1] == 0 && n[2] == 0)
      {
        error = "--light-direction needs a non-zero vector";
        return;
      }
      this->Lights.push_back(light);
    }
    else if (spec.Type == Kind::LightSet)
    {
      if (this->Lights.empty())
      {
        error = arg +
          " applies to the most recent light: give --light-direction or --light-position before "
          "it";
      }
      else if (name == "light-color")
      {
        std::copy(n.begin(), n.end(), this->Lights.back().Color);
      }
      else
      {
        this->Lights.back().Intensity = n[0];
      }
    }
    else if (spec.Type == Kind::Volume || spec.Type == Kind::VolumeSet)
    {
      this->StoreVolume(spec, arg, value, error);
    }
    else if (name == "view-up" && n[0] == 0 && n[1] == 0 && n[2] == 0)
    {
      error = "--view-up needs a non-zero vector";
    }
    else if (name == "preset" && !UnknownPreset(value.Text).empty())
    {
      error = UnknownPreset(value.Text);
    }
    else if (name == "input")
    {
      this->SetInput(value.Text, input, error);
    }
    else
    {
      this->Values[name] = value;
    }
  }

  // A new volume (--add-volume), or a setting of the most recent one.
  void StoreVolume(const Spec& spec, const std::string& arg, const Value& value, std::string& error)
  {
    const std::string name = spec.Name;
    if (spec.Type == Kind::Volume)
    {
      if (static_cast<int>(this->Volumes.size()) == MaximumAddedVolumes)
      {
        error = "at most " + std::to_string(MaximumAddedVolumes) + " --add-volume";
        return;
      }
      this->Volumes.emplace_back();
      this->Volumes.back().File = value.Text;
      return;
    }
    if (this->Volumes.empty())
    {
      error = arg + " applies to the most recent volume: give --add-volume before it";
      return;
    }
    AddedVolume& v = this->Volumes.back();
    const std::vector<double>& n = value.Numbers;
    if (name == "volume-position")
    {
      std::copy(n.begin(), n.end(), v.Position);
    }
    else if (name == "volume-scale")
    {
      v.Scale = n[0];
    }
    else if (name == "volume-density-scale")
    {
      v.DensityScale = n[0];
      this->VolumeDensityScaleGiven = true;
    }
    else if (name == "volume-preset")
    {
      error = UnknownPreset(value.Text);
      v.Preset = value.Text;
    }
    else
    {
      v.TransferFunction = value.Text;
    }
  }

  // Options that depend on others: the first problem, or "".
  std::string CheckCombinations(const std::string& input) const
  {
    auto set = [this](const char* name) { return this->Values.count(name) > 0; };
    if (input.empty() && set("grid"))
    {
      return "--grid needs a .vdb input";
    }
    if (set("component") && set("components"))
    {
      return "--component picks one component, --components draws them together";
    }
    if (set("component-weights") && !set("components"))
    {
      return "--component-weights needs --components independent";
    }
    if (set("mask") && set("labels"))
    {
      return "--mask and --labels are both the mapper's mask: give one";
    }
    if (set("label-blend") && !set("labels"))
    {
      return "--label-blend needs --labels";
    }
    const bool slice = set("blend-mode") && this->Values.at("blend-mode").Text == "slice";
    for (const char* name : { "slice-normal", "slice-origin", "slice-offset" })
    {
      if (set(name) && !slice)
      {
        return std::string("--") + name + " needs --blend-mode slice";
      }
    }
    for (const char* name : { "component", "components", "component-weights", "mask", "labels",
           "frame", "no-rescale", "level-set-to-fog" })
    {
      if (input.empty() && set(name))
      {
        return std::string("--") + name + " needs an input file";
      }
    }
    if (!input.empty() && set("resolution"))
    {
      return "--resolution applies to the built-in cloud only, not to an input file";
    }
    if (set("detail") && set("no-detail"))
    {
      return "give either --detail or --no-detail, not both";
    }
    if (!input.empty() && set("no-detail"))
    {
      return "--no-detail applies to the built-in cloud only (data has detail only with --detail)";
    }
    if (set("preset") && set("transfer-function"))
    {
      return "give either --preset or --transfer-function, not both";
    }
    if (set("sequence") && (input.empty() || set("frame") || set("frames") || set("exr")))
    {
      return input.empty()
        ? "--sequence needs an input (numbered files or a 4-D file)"
        : "--sequence renders frames FIRST to LAST into PNGs: give no --frame, --frames or --exr";
    }
    if ((set("path-bounces") || set("path-shadows") || set("path-distance") ||
          set("path-denoise")) &&
      !set("path-trace"))
    {
      return "--path-bounces, --path-shadows, --path-distance and --path-denoise need "
             "--path-trace";
    }
    if (set("vtk-property"))
    {
      // A plain vtkVolumeProperty has none of these (vtkParticipatingMediumProperty's).
      std::string medium;
      for (const auto& value : this->Values)
      {
        if (medium.empty() && vtkTyndallOptions::IsMediumOption(value.first))
        {
          medium = value.first;
        }
      }
      if (medium.empty() && this->VolumeDensityScaleGiven)
      {
        medium = "volume-density-scale";
      }
      if (!medium.empty())
      {
        return "--" + medium +
          " applies to the medium (vtkParticipatingMediumProperty) only, which --vtk-property "
          "replaces by a plain vtkVolumeProperty";
      }
    }
    if (set("skip-bad-frames") && !set("sequence"))
    {
      return "--skip-bad-frames needs --sequence";
    }
    if (set("play-rate") && !set("sequence"))
    {
      return "--play-rate needs --sequence";
    }
    if (set("orbit") && !set("sequence") && (set("frames") || set("exr")))
    {
      return "--orbit renders pictures along the path into PNGs: give no --frames or --exr";
    }
    if (set("orbit-frames") && (!set("orbit") || set("sequence")))
    {
      return set("sequence") ? "--orbit-frames is for a still scene: --sequence sets the frames"
                             : "--orbit-frames needs --orbit";
    }
    if (set("video") && !set("sequence") && !set("orbit"))
    {
      return "--video needs --sequence or --orbit (the pictures it holds)";
    }
    if (set("video-rate") && !set("video"))
    {
      return "--video-rate needs --video";
    }
    return std::string();
  }

  // The row of a command-line argument ("--method", "-s").
  static const Spec* FindArgument(const std::string& arg, int program)
  {
    for (const Spec& s : kOptions)
    {
      if ((s.Programs & program) && s.Type != Kind::Action &&
        (arg == std::string("--") + s.Name || (*s.Short && arg == s.Short)))
      {
        return &s;
      }
    }
    return nullptr;
  }
};

//------------------------------------------------------------------------------
vtkTyndallOptions::vtkTyndallOptions()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTyndallOptions::~vtkTyndallOptions() = default;

//------------------------------------------------------------------------------
bool vtkTyndallOptions::ParseArguments(vtkStringArray* arguments)
{
  std::vector<std::string> words = { "program" };
  for (vtkIdType i = 0; arguments && i < arguments->GetNumberOfValues(); ++i)
  {
    words.push_back(arguments->GetValue(i));
  }
  std::vector<char*> argv;
  for (std::string& w : words)
  {
    argv.push_back(&w[0]);
  }
  return this->Parse(static_cast<int>(argv.size()), argv.data());
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::Parse(int argc, char* argv[])
{
  vtkInternals& in = *this->Internals;
  in.Values.clear();
  in.Lights.clear();
  in.Volumes.clear();
  in.VolumeDensityScaleGiven = false;
  this->Input.clear();
  this->HelpRequested = false;
  this->ErrorMessage.clear();
  std::string error;
  bool endOfOptions = false;
  for (int i = 1; i < argc && error.empty(); ++i)
  {
    const std::string arg = argv[i];
    if (endOfOptions || arg.empty() || arg[0] != '-' || arg == "-")
    {
      in.SetInput(arg, this->Input, error);
      continue;
    }
    if (arg == "--")
    {
      endOfOptions = true;
      continue;
    }
    const Spec* spec = vtkInternals::FindArgument(arg, this->Program);
    if (!spec)
    {
      error = "unknown option '" + arg + "' (see --help)";
      break;
    }
    const int count = ArgumentCount(*spec);
    if (i + count >= argc)
    {
      error = arg + " needs " + Wanted(*spec);
      break;
    }
    if (spec->Type == Kind::Help)
    {
      this->HelpRequested = true;
      return true;
    }
    const std::vector<std::string> args(argv + i + 1, argv + i + 1 + count);
    i += count;
    Value value;
    if (ReadValue(*spec, arg, args, value, error))
    {
      in.Store(*spec, arg, value, this->Input, error);
    }
  }
  if (error.empty())
  {
    error = in.CheckCombinations(this->Input);
  }
  this->ErrorMessage = error;
  return error.empty();
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::IsSet(const char* name)
{
  const auto it = this->Internals->Values.find(name ? name : "");
  return it != this->Internals->Values.end() && it->second.Set;
}

//------------------------------------------------------------------------------
double vtkTyndallOptions::GetNumber(const char* name, int i)
{
  const Spec* spec = vtkInternals::Find(name ? name : "", this->Program);
  if (!spec)
  {
    vtkErrorMacro(<< "GetNumber: no option '" << (name ? name : "(null)") << "'.");
    return 0.0;
  }
  const auto it = this->Internals->Values.find(name);
  if (it != this->Internals->Values.end() && i >= 0 &&
    i < static_cast<int>(it->second.Numbers.size()))
  {
    return it->second.Numbers[i];
  }
  // The table default: the i-th word of Default (the first of "a / b").
  const std::vector<std::string> words = Split(spec->Default, ' ');
  double v = 0.0;
  return i >= 0 && i < static_cast<int>(words.size()) && ParseStrict(words[i], false, v) ? v : 0.0;
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::GetVector(const char* name, double v[3])
{
  for (int i = 0; i < 3; ++i)
  {
    v[i] = this->GetNumber(name, i);
  }
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::GetText(const char* name)
{
  const auto it = this->Internals->Values.find(name ? name : "");
  return it != this->Internals->Values.end() ? it->second.Text.c_str() : "";
}

//------------------------------------------------------------------------------
int vtkTyndallOptions::GetChoice(const char* name)
{
  const Spec* spec = vtkInternals::Find(name ? name : "", this->Program);
  if (!spec || spec->Type != Kind::Choice)
  {
    vtkErrorMacro(<< "GetChoice: no choice option '" << (name ? name : "(null)") << "'.");
    return -1;
  }
  const auto it = this->Internals->Values.find(name);
  if (it != this->Internals->Values.end())
  {
    return it->second.Choice;
  }
  const std::vector<std::string> choices = Split(spec->Choices, '|');
  return static_cast<int>(
    std::find(choices.begin(), choices.end(), spec->Default) - choices.begin());
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::GetFlag(const char* name)
{
  return this->IsSet(name);
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::SetNumber(const char* name, double value, int i)
{
  const Spec* spec = vtkInternals::Find(name ? name : "", this->Program);
  if (!spec || i < 0 || i > 2)
  {
    vtkErrorMacro(<< "SetNumber: no option '" << (name ? name : "(null)") << "'.");
    return;
  }
  Value& v = this->Internals->Values[name];
  if (spec->Type == Kind::Choice)
  {
    const int choices = static_cast<int>(Split(spec->Choices, '|').size());
    v.Choice = std::min(std::max(static_cast<int>(value), 0), choices - 1);
    v.Text = Split(spec->Choices, '|')[v.Choice];
    v.Set = true;
    this->Modified();
    return;
  }
  if (v.Numbers.size() <= static_cast<size_t>(i))
  {
    // Components not given yet keep their current values (the defaults):
    // read them all before the vector grows (GetNumber reads what it holds).
    std::vector<double> numbers;
    for (int k = 0; k <= i; ++k)
    {
      numbers.push_back(this->GetNumber(name, k));
    }
    v.Numbers = numbers;
  }
  v.Numbers[i] = std::min(std::max(value, spec->Min), spec->Max);
  if (spec->Type == Kind::Integer)
  {
    v.Numbers[i] = std::round(v.Numbers[i]);
  }
  v.Set = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::SetFlag(const char* name, bool on)
{
  if (on)
  {
    this->Internals->Values[name ? name : ""].Set = true;
  }
  else
  {
    this->Internals->Values.erase(name ? name : "");
  }
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkTyndallOptions::GetNumberOfAddedVolumes()
{
  return static_cast<int>(this->Internals->Volumes.size());
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::GetAddedVolumeFile(int volume)
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  return ok ? this->Internals->Volumes[volume].File.c_str() : "";
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::GetAddedVolumePosition(int volume, double v[3])
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  for (int k = 0; k < 3; ++k)
  {
    v[k] = ok ? this->Internals->Volumes[volume].Position[k] : 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallOptions::GetAddedVolumeScale(int volume)
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  return ok ? this->Internals->Volumes[volume].Scale : 1.0;
}

//------------------------------------------------------------------------------
double vtkTyndallOptions::GetAddedVolumeDensityScale(int volume)
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  return ok ? this->Internals->Volumes[volume].DensityScale : 1.0;
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::GetAddedVolumePreset(int volume)
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  return ok ? this->Internals->Volumes[volume].Preset.c_str() : "";
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::GetAddedVolumeTransferFunction(int volume)
{
  const bool ok = volume >= 0 && volume < this->GetNumberOfAddedVolumes();
  return ok ? this->Internals->Volumes[volume].TransferFunction.c_str() : "";
}

//------------------------------------------------------------------------------
int vtkTyndallOptions::GetNumberOfLights()
{
  return static_cast<int>(this->Internals->Lights.size());
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::GetLightPositional(int light)
{
  return light >= 0 && light < this->GetNumberOfLights() &&
    this->Internals->Lights[light].Positional;
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::GetLightVector(int light, double v[3])
{
  const bool ok = light >= 0 && light < this->GetNumberOfLights();
  for (int k = 0; k < 3; ++k)
  {
    v[k] = ok ? this->Internals->Lights[light].Vector[k] : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::GetLightColor(int light, double rgb[3])
{
  const bool ok = light >= 0 && light < this->GetNumberOfLights();
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = ok ? this->Internals->Lights[light].Color[k] : 1.0;
  }
}

//------------------------------------------------------------------------------
double vtkTyndallOptions::GetLightIntensity(int light)
{
  return light >= 0 && light < this->GetNumberOfLights() ? this->Internals->Lights[light].Intensity
                                                         : 1.0;
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::ApplyKey(int key)
{
  if (this->Program != VIEWER)
  {
    return nullptr; // only the viewer has keys
  }
  for (const Spec& s : kOptions)
  {
    if (!(s.Programs & this->Program) || s.Mode == KeyMode::None || key <= 0 || key > 255)
    {
      continue;
    }
    const char* up = std::strchr(s.KeysUp, key);
    const char* down = std::strchr(s.KeysDown, key);
    if (!up && !down)
    {
      continue;
    }
    switch (s.Mode)
    {
      case KeyMode::Choose:
        this->SetNumber(s.Name, static_cast<double>(up - s.KeysUp));
        break;
      case KeyMode::Add:
      {
        // Rounded to the step, so that repeated presses stay on the grid.
        const double v = this->GetNumber(s.Name) + (up ? s.Step : -s.Step);
        this->SetNumber(s.Name, std::round(v / s.Step) * s.Step);
        break;
      }
      case KeyMode::Multiply:
        this->SetNumber(s.Name, this->GetNumber(s.Name) * (up ? s.Step : 1.0 / s.Step));
        break;
      case KeyMode::Toggle:
        if (s.Type == Kind::Flag)
        {
          this->SetFlag(s.Name, !this->GetFlag(s.Name));
        }
        break;
      default:
        break;
    }
    return s.Name;
  }
  return nullptr;
}

//------------------------------------------------------------------------------
const char* vtkTyndallOptions::GetKeyOption(int key)
{
  if (this->Program != VIEWER)
  {
    return nullptr; // only the viewer has keys
  }
  for (const Spec& s : kOptions)
  {
    if ((s.Programs & this->Program) && s.Mode != KeyMode::None && key > 0 && key <= 255 &&
      (std::strchr(s.KeysUp, key) || std::strchr(s.KeysDown, key)))
    {
      return s.Name;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::IsMediumOption(const std::string& name)
{
  static const char* const medium[] = { "model", "anisotropy", "ambient", "density-scale",
    "volume-density-scale", "extinction-color", "octaves", "octave-scattering", "octave-extinction",
    "octave-anisotropy", "octave-build-up", "emission-scale", "emission-array", "blackbody",
    "temperature-scale", "light-scale", "no-scene-shadows", "no-scene-compositing" };
  // (--detail and every --detail-... option: the medium's procedural detail.)
  return name.compare(0, 6, "detail") == 0 ||
    std::find(std::begin(medium), std::end(medium), name) != std::end(medium);
}

//------------------------------------------------------------------------------
std::string vtkTyndallOptions::GetKeyHelp()
{
  std::ostringstream os;
  for (const Spec& s : kOptions)
  {
    if (!(s.Programs & this->Program) || s.Mode == KeyMode::None)
    {
      continue;
    }
    std::string keys;
    auto name = [](char c)
    {
      switch (c)
      {
        case '\033':
          return std::string("Esc");
        case ' ':
          return std::string("Space");
        case KEY_LEFT:
          return std::string("Left");
        case KEY_RIGHT:
          return std::string("Right");
        default:
          return std::string(1, c);
      }
    };
    if (s.Mode == KeyMode::Choose)
    {
      keys = name(s.KeysUp[0]) + ".." + name(s.KeysUp[std::strlen(s.KeysUp) - 1]);
    }
    else
    {
      for (const char* k = s.KeysUp; *k; ++k)
      {
        keys += (keys.empty() ? "" : " or ") + name(*k);
      }
      for (const char* k = s.KeysDown; *k; ++k)
      {
        keys += (k == s.KeysDown ? " / " : " or ") + name(*k);
      }
    }
    std::string what = s.Help;
    if (s.Type != Kind::Action)
    {
      what = std::string(s.Mode == KeyMode::Toggle ? "toggle --" : "--") + s.Name + ": " + what;
      if (s.Mode == KeyMode::Add || s.Mode == KeyMode::Multiply)
      {
        std::ostringstream step;
        step << (s.Mode == KeyMode::Add ? " (+/- " : " (x / divide by ") << s.Step << ")";
        what += step.str();
      }
      if (s.Mode == KeyMode::Choose)
      {
        std::string list = s.Choices;
        std::replace(list.begin(), list.end(), '|', ' ');
        what += " (" + list + ")";
      }
    }
    Wrap(os, "  " + keys, what);
  }
  return os.str();
}

//------------------------------------------------------------------------------
std::string vtkTyndallOptions::GetHelp(const char* description)
{
  std::ostringstream os;
  os << (description ? description : "") << "\n";
  std::vector<std::string> groups;
  for (const Spec& s : kOptions)
  {
    if ((s.Programs & this->Program) && s.Type != Kind::Action &&
      std::find(groups.begin(), groups.end(), s.Group) == groups.end())
    {
      groups.push_back(s.Group);
    }
  }
  for (const std::string& group : groups)
  {
    os << group << ":\n";
    for (const Spec& s : kOptions)
    {
      if (!(s.Programs & this->Program) || s.Type == Kind::Action || group != s.Group)
      {
        continue;
      }
      std::string left = std::string("  ") + (*s.Short ? std::string(s.Short) + ", " : "") + "--" +
        s.Name + (*s.Metavar ? std::string(" ") + s.Metavar : "");
      std::string text = s.Help;
      if (s.Type == Kind::Choice)
      {
        std::string list = s.Choices;
        std::replace(list.begin(), list.end(), '|', ' ');
        text += ": " + list;
      }
      else if (s.Type == Kind::Integer || s.Type == Kind::Number || s.Type == Kind::Pair)
      {
        text += ", " + RangeText(s);
      }
      if (*s.Default)
      {
        text += std::string(" [") + s.Default + "]";
      }
      Wrap(os, left, text);
    }
    os << "\n";
  }
  if (this->Program == VIEWER)
  {
    os << "Keys:\n" << this->GetKeyHelp() << "\n";
  }
  return os.str();
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::ParseNumber(const std::string& text, double& value)
{
  return ParseStrict(text, false, value);
}

//------------------------------------------------------------------------------
bool vtkTyndallOptions::ParseInteger(const std::string& text, int lo, int hi, int& value)
{
  double v = 0.0;
  if (!ParseStrict(text, true, v) || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

//------------------------------------------------------------------------------
void vtkTyndallOptions::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Program: " << (this->Program == RENDER ? "RENDER" : "VIEWER") << "\n";
  os << indent << "Input: " << this->Input << "\n";
  for (const auto& value : this->Internals->Values)
  {
    os << indent << "--" << value.first;
    for (double v : value.second.Numbers)
    {
      os << " " << v;
    }
    os << (value.second.Text.empty() ? "" : " ") << value.second.Text << "\n";
  }
  os << indent << "Lights: " << this->Internals->Lights.size() << "\n";
  os << indent << "AddedVolumes: " << this->Internals->Volumes.size() << "\n";
}
