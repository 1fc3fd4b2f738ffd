// tyndall-render: Tyndall's main job, a command-line renderer.
//
// Without an input it renders the built-in default scene, a cosine-noise
// cloud lit by a low sun with single scattering and adaptive ETM shadows
// (vtkTransmittanceVolumeMapper); with an input path it renders that volume
// (see tyndallLoadVolume.h for the formats). Every option of the mapper,
// transfer functions (presets or a text file), the camera, lights, the
// background and the outputs (an 8-bit PNG of the frame buffer, a linear
// float OpenEXR image of the radiance) are set on the command line; see
// Usage() below and Documentation/cli.md. The PNG's path is printed on
// stdout; progress and timings go to stderr.
#include "tyndallLoadVolume.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCosineNoiseSource.h"
#include "vtkDataArray.h"
#include "vtkFramebufferPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#ifdef TYNDALL_HAVE_IO
#include "vtkTransferFunctionPresets.h"
#endif

#ifdef TYNDALL_HAVE_OPENEXR
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#endif

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* const Program = "tyndall-render";

// Exit codes (documented in --help and Documentation/cli.md).
constexpr int ExitUsage = 2;   // bad command line
constexpr int ExitFailure = 1; // a file could not be read, rendered or written

// The presets' names and descriptions for --help, wrapped at 80 columns.
std::string PresetHelp()
{
#ifdef TYNDALL_HAVE_IO
  std::string text;
  for (int i = 0; i < vtkTransferFunctionPresets::GetNumberOfPresets(); ++i)
  {
    std::string line = std::string("    ") + vtkTransferFunctionPresets::GetPresetName(i) + ":";
    const char* description = vtkTransferFunctionPresets::GetPresetDescription(i);
    std::istringstream words(description ? description : "");
    for (std::string word; words >> word;)
    {
      if (line.size() + 1 + word.size() > 80)
      {
        text += line + "\n";
        line = "      ";
      }
      line += " " + word;
    }
    text += line + "\n";
  }
  return text;
#else
  return "    (not available: this build has no Tyndall::IO)\n";
#endif
}

void Usage(std::ostream& os)
{
  os << "Usage: tyndall-render [options] [INPUT]\n"
        "\n"
        "Renders a participating medium with physically based single scattering\n"
        "(vtkTransmittanceVolumeMapper) to an 8-bit PNG and prints the PNG's path on\n"
        "stdout. Progress and timings go to stderr. Needs an X display (Debian's VTK\n"
        "renders through GLX): run under xvfb-run -a -s \"-screen 0 1280x1024x24\" on\n"
        "machines without one. See Documentation/cli.md.\n"
        "\n"
        "Without INPUT: the built-in default scene, a procedural cosine-noise cloud lit\n"
        "by a low sun (single scattering, adaptive ETM shadows) under a sky gradient.\n"
        "With INPUT, a volume file or a DICOM directory:\n"
     << tyndallLoadVolumeFormats()
     << "Data inputs get a camera fitted to the data, a white directional key light\n"
        "coming from the upper right in front of the data (as seen by the camera),\n"
        "ambient 0.25, a black background and a transfer function guessed from the data\n"
        "(see --preset).\n"
        "\n"
        "Input:\n"
        "  --grid NAME             grid of a .vdb file (default: 'density' if it is a\n"
        "                          float grid, else the first float grid)\n"
        "  --component N           component of multi-component scalars to render\n"
        "                          (default: multi-component data is refused)\n"
        "  -r, --resolution N      voxels per axis of the built-in cloud, 8..512\n"
        "                          (default: 128; default scene only)\n"
        "\n"
        "Scattering (the mapper's options; defaults in brackets, default scene / data):\n"
        "  --method M              light transmittance: none, brute-force, tfm,\n"
        "                          adaptive-tfm, etm or adaptive-etm [adaptive-etm]\n"
        "  --model M               single-scattering (colour = albedo) or\n"
        "                          emission-absorption (colour = emitted colour, as\n"
        "                          vtkGPUVolumeRayCastMapper) [single-scattering]\n"
        "  --coefficients N        series coefficients per map texel, 1..16 [8]\n"
        "  --map-size N            transmittance map size in texels, 16..4096 [256]\n"
        "  --anisotropy G          Henyey-Greenstein g, -0.99..0.99; > 0 scatters\n"
        "                          forward [0.3 / 0]\n"
        "  --density-scale S       multiplies the extinction, 0..1e6 [1]\n"
        "  --sample-distance D     camera-ray step in world units, 0..1e6; 0 = half\n"
        "                          the smallest voxel spacing [0]\n"
        "  --light-samples N       samples per light ray (map build, brute force),\n"
        "                          1..2048 [128]\n"
        "  --adaptive-threshold T  transmittance threshold of the adaptive methods,\n"
        "                          1e-6..0.5 [0.01]\n"
        "  --ambient A             unshadowed ambient in-scattering, 0..1e6 [0.45 / 0.25]\n"
        "  --emission-scale E      emission strength (single scattering), 0..1e6 [0];\n"
        "                          the emission colour comes from the transfer function\n"
        "                          file's 'emission' lines, else its colour\n"
        "  --light-scale K         irradiance per unit of light intensity, 0..1e6 [4 pi]\n"
        "  --no-jitter             do not jitter the ray samples per pixel\n"
        "\n"
        "Transfer function (default scene: a white cloud, alpha 0.5 per 0.05 units at\n"
        "density 8, albedo 0.95):\n"
        "  --preset NAME           a named preset (vtkTransferFunctionPresets) over the\n"
        "                          data's scalar range, unit distance = the mean voxel\n"
        "                          spacing; names ignore case, spaces, '-' and '_':\n"
     << PresetHelp()
     << "                          Default for data inputs: a guessed preset - CT when\n"
        "                          the minimum is below -500 (Hounsfield units), else\n"
        "                          Cloud for floating-point data, else MR - or, without\n"
        "                          presets, a generic ramp: opacity 0 up to 5% of the\n"
        "                          scalar range, rising linearly to 1 at the maximum,\n"
        "                          white albedo 0.9, unit distance 1/50 of the data's\n"
        "                          diagonal\n"
        "  --transfer-function FILE  a text file, one entry per line ('#' comments):\n"
        "                            opacity <value> <alpha>       alpha in [0, 1]\n"
        "                            color <value> <r> <g> <b>     in [0, 1]\n"
        "                            emission <value> <r> <g> <b>  >= 0\n"
        "                            unit-distance <d>             world units, > 0\n"
        "                          alpha is the opacity of a slab unit-distance thick\n"
        "                          (VTK's convention; default 1); no color lines: white\n"
        "\n"
        "Camera (default scene: a fixed view of the cloud; data: fitted to the data,\n"
        "looking down -z with +y up; options override parts of it):\n"
        "  --camera-position X Y Z where the camera is\n"
        "  --focal-point X Y Z     the point it looks at\n"
        "  --view-up X Y Z         the image's up direction (made orthogonal to the view\n"
        "                          direction; must not be parallel to it)\n"
        "  --view-angle DEG        field of view in degrees, 0 < DEG < 180 [30]\n"
        "  --horizontal-view-angle the view angle is horizontal (default: vertical)\n"
        "\n"
        "Lights (repeatable, up to 8 are used; any of them replaces the default light):\n"
        "  --light-direction X Y Z a directional light travelling along (X, Y, Z), i.e.\n"
        "                          coming from -(X, Y, Z): 0 -1 0 shines downwards\n"
        "  --light-position X Y Z  a point light at (X, Y, Z), no fall-off\n"
        "  --light-color R G B     colour of the most recent light, >= 0 [1 1 1]\n"
        "  --light-intensity I     intensity of the most recent light, 0..1e6 [1]\n"
        "\n"
        "Image:\n"
        "  -s, --size W H          image size in pixels, 16..8192 each [512 512]\n"
        "  --background R G B      background colour in [0, 1] (the bottom colour of a\n"
        "                          gradient) [default scene: sky gradient; data: black]\n"
        "  --background2 R G B     top colour: makes the background a vertical gradient\n"
        "\n"
        "Output:\n"
        "  -o, --output FILE       the PNG: the 8-bit frame buffer, i.e. linear radiance\n"
        "                          clamped to [0, 1] and quantised (no other tone\n"
        "                          mapping) [default scene: tyndall-cloud.png; data:\n"
        "                          <input name>.png in the current directory]\n"
        "  --exr FILE              also write a linear float OpenEXR image (RGB, 32-bit\n"
        "                          float, unclamped radiance) captured from a float\n"
        "                          frame buffer"
#ifndef TYNDALL_HAVE_OPENEXR
        " (not available: built without OpenEXR)"
#endif
        "\n"
        "  --frames N              render N frames, 1..1000 [1]: frames after the first\n"
        "                          reuse the maps and shaders; their mean time is\n"
        "                          reported (the images are identical)\n"
        "  -q, --quiet             no progress or timings on stderr (errors only)\n"
        "  -h, --help              show this help and exit\n"
        "\n"
        "Exit status: 0 on success, 2 for a bad command line, 1 when an input cannot be\n"
        "read or the image cannot be rendered or written.\n";
}

using Vec3 = std::array<double, 3>;

struct LightSpec
{
  bool Positional = false;
  Vec3 Vector = { 0, 0, 0 }; // direction of travel, or position
  Vec3 Color = { 1, 1, 1 };
  double Intensity = 1.0;
};

struct Options
{
  std::string Input;
  std::string Grid;
  int Component = -1;
  int Resolution = 128;
  bool ResolutionSet = false;

  int Method = -1;
  int Model = -1;
  int Coefficients = -1;
  int MapSize = -1;
  int LightSamples = -1;
  double Anisotropy = std::numeric_limits<double>::quiet_NaN();
  double DensityScale = std::numeric_limits<double>::quiet_NaN();
  double SampleDistance = std::numeric_limits<double>::quiet_NaN();
  double AdaptiveThreshold = std::numeric_limits<double>::quiet_NaN();
  double Ambient = std::numeric_limits<double>::quiet_NaN();
  double EmissionScale = std::numeric_limits<double>::quiet_NaN();
  double LightScale = std::numeric_limits<double>::quiet_NaN();
  bool NoJitter = false;

  std::string Preset;
  std::string TransferFunctionFile;

  bool HasCameraPosition = false, HasFocalPoint = false, HasViewUp = false;
  Vec3 CameraPosition, FocalPoint, ViewUp;
  double ViewAngle = std::numeric_limits<double>::quiet_NaN();
  bool HorizontalViewAngle = false;

  std::vector<LightSpec> Lights;

  int Size[2] = { 512, 512 };
  int Frames = 1;
  bool HasBackground = false, HasBackground2 = false;
  Vec3 Background, Background2;

  std::string Output;
  std::string Exr;
  bool Quiet = false;
};

// A transfer function read from a file.
struct TransferFunction
{
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkColorTransferFunction> Emission;
  bool HasColor = false;
  bool HasEmission = false;
  double UnitDistance = 1.0;
};

// Strict number parsing: the whole text, finite.
bool ParseDouble(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

bool ParseInt(const std::string& text, long& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (*end || errno == ERANGE)
  {
    return false;
  }
  value = v;
  return true;
}

std::string RangeText(double lo, double hi)
{
  std::ostringstream os;
  os << lo << ".." << hi;
  return os.str();
}

// The command-line parser: reports the first problem and remembers it.
class ArgumentParser
{
public:
  ArgumentParser(int argc, char* argv[])
    : Argc(argc)
    , Argv(argv)
  {
  }

  bool Failed() const { return !this->Error.empty(); }
  const std::string& GetError() const { return this->Error; }
  void Fail(const std::string& message)
  {
    if (this->Error.empty())
    {
      this->Error = message;
    }
  }

  // Takes the next `count` arguments after option `i` as values.
  bool Values(int& i, int count, const std::string& option, const char* what,
    std::vector<std::string>& values)
  {
    values.clear();
    if (i + count >= this->Argc)
    {
      this->Fail(option + " needs " + what);
      return false;
    }
    for (int k = 1; k <= count; ++k)
    {
      values.emplace_back(this->Argv[i + k]);
    }
    i += count;
    return true;
  }

  bool Int(int& i, const std::string& option, long lo, long hi, int& value)
  {
    std::vector<std::string> v;
    const std::string what = "an integer in " + RangeText(lo, hi);
    if (!this->Values(i, 1, option, what.c_str(), v))
    {
      return false;
    }
    long n = 0;
    if (!ParseInt(v[0], n) || n < lo || n > hi)
    {
      this->Fail(option + " needs " + what + ", got '" + v[0] + "'");
      return false;
    }
    value = static_cast<int>(n);
    return true;
  }

  bool Double(int& i, const std::string& option, double lo, double hi, double& value)
  {
    std::vector<std::string> v;
    const std::string what = "a number in " + RangeText(lo, hi);
    if (!this->Values(i, 1, option, what.c_str(), v))
    {
      return false;
    }
    double x = 0;
    if (!ParseDouble(v[0], x) || x < lo || x > hi)
    {
      this->Fail(option + " needs " + what + ", got '" + v[0] + "'");
      return false;
    }
    value = x;
    return true;
  }

  bool Triple(int& i, const std::string& option, double lo, double hi, Vec3& value)
  {
    std::vector<std::string> v;
    const std::string what = "three numbers in " + RangeText(lo, hi);
    if (!this->Values(i, 3, option, what.c_str(), v))
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      double x = 0;
      if (!ParseDouble(v[k], x) || x < lo || x > hi)
      {
        this->Fail(option + " needs " + what + ", got '" + v[k] + "'");
        return false;
      }
      value[k] = x;
    }
    return true;
  }

  bool Text(int& i, const std::string& option, const char* what, std::string& value)
  {
    std::vector<std::string> v;
    if (!this->Values(i, 1, option, what, v))
    {
      return false;
    }
    value = v[0];
    return true;
  }

  int Argc;
  char** Argv;
  std::string Error;
};

// Parses argv into `options`. Returns false (with `error`) on a bad command
// line; sets `help` for -h/--help.
bool ParseArguments(int argc, char* argv[], Options& o, bool& help, std::string& error)
{
  constexpr double Huge = 1.0e6;
  constexpr double Coordinate = 1.0e30;
  ArgumentParser p(argc, argv);
  bool endOfOptions = false;
  for (int i = 1; i < argc && !p.Failed(); ++i)
  {
    const std::string arg = argv[i];
    if (endOfOptions || arg.empty() || arg[0] != '-' || arg == "-")
    {
      if (!o.Input.empty())
      {
        p.Fail("more than one input given ('" + o.Input + "' and '" + arg + "')");
      }
      o.Input = arg;
    }
    else if (arg == "--")
    {
      endOfOptions = true;
    }
    else if (arg == "-h" || arg == "--help")
    {
      help = true;
      return true;
    }
    else if (arg == "-q" || arg == "--quiet")
    {
      o.Quiet = true;
    }
    else if (arg == "-o" || arg == "--output")
    {
      p.Text(i, arg, "a file name", o.Output);
    }
    else if (arg == "--exr")
    {
      p.Text(i, arg, "a file name", o.Exr);
    }
    else if (arg == "-s" || arg == "--size")
    {
      std::vector<std::string> v;
      if (p.Values(i, 2, arg, "two integers in 16..8192", v))
      {
        for (int k = 0; k < 2; ++k)
        {
          long n = 0;
          if (!ParseInt(v[k], n) || n < 16 || n > 8192)
          {
            p.Fail(arg + " needs two integers in 16..8192, got '" + v[k] + "'");
            break;
          }
          o.Size[k] = static_cast<int>(n);
        }
      }
    }
    else if (arg == "--frames")
    {
      p.Int(i, arg, 1, 1000, o.Frames);
    }
    else if (arg == "-r" || arg == "--resolution")
    {
      o.ResolutionSet = p.Int(i, arg, 8, 512, o.Resolution);
    }
    else if (arg == "--grid")
    {
      p.Text(i, arg, "a grid name", o.Grid);
      if (o.Grid.empty())
      {
        p.Fail("--grid needs a non-empty grid name");
      }
    }
    else if (arg == "--component")
    {
      p.Int(i, arg, 0, 1024, o.Component);
    }
    else if (arg == "--method")
    {
      std::string m;
      if (p.Text(i, arg, "a method name", m))
      {
        static const char* const names[] = { "none", "brute-force", "tfm", "adaptive-tfm", "etm",
          "adaptive-etm" };
        for (int k = 0; k < 6; ++k)
        {
          if (m == names[k])
          {
            o.Method = k; // the values of vtkTransmittanceVolumeMapper::TransmittanceMethods
          }
        }
        if (o.Method < 0)
        {
          p.Fail("--method needs one of none, brute-force, tfm, adaptive-tfm, etm, "
                 "adaptive-etm; got '" +
            m + "'");
        }
      }
    }
    else if (arg == "--model")
    {
      std::string m;
      if (p.Text(i, arg, "a model name", m))
      {
        if (m == "single-scattering")
        {
          o.Model = vtkParticipatingMediumProperty::SINGLE_SCATTERING;
        }
        else if (m == "emission-absorption")
        {
          o.Model = vtkParticipatingMediumProperty::EMISSION_ABSORPTION;
        }
        else
        {
          p.Fail("--model needs single-scattering or emission-absorption, got '" + m + "'");
        }
      }
    }
    else if (arg == "--coefficients")
    {
      p.Int(i, arg, 1, 16, o.Coefficients);
    }
    else if (arg == "--map-size")
    {
      p.Int(i, arg, 16, 4096, o.MapSize);
    }
    else if (arg == "--light-samples")
    {
      p.Int(i, arg, 1, 2048, o.LightSamples);
    }
    else if (arg == "--anisotropy")
    {
      p.Double(i, arg, -0.99, 0.99, o.Anisotropy);
    }
    else if (arg == "--density-scale")
    {
      p.Double(i, arg, 0.0, Huge, o.DensityScale);
    }
    else if (arg == "--sample-distance")
    {
      p.Double(i, arg, 0.0, Huge, o.SampleDistance);
    }
    else if (arg == "--adaptive-threshold")
    {
      p.Double(i, arg, 1.0e-6, 0.5, o.AdaptiveThreshold);
    }
    else if (arg == "--ambient")
    {
      p.Double(i, arg, 0.0, Huge, o.Ambient);
    }
    else if (arg == "--emission-scale")
    {
      p.Double(i, arg, 0.0, Huge, o.EmissionScale);
    }
    else if (arg == "--light-scale")
    {
      p.Double(i, arg, 0.0, Huge, o.LightScale);
    }
    else if (arg == "--no-jitter")
    {
      o.NoJitter = true;
    }
    else if (arg == "--preset")
    {
      p.Text(i, arg, "a preset name", o.Preset);
    }
    else if (arg == "--transfer-function")
    {
      p.Text(i, arg, "a file name", o.TransferFunctionFile);
    }
    else if (arg == "--camera-position")
    {
      o.HasCameraPosition = p.Triple(i, arg, -Coordinate, Coordinate, o.CameraPosition);
    }
    else if (arg == "--focal-point")
    {
      o.HasFocalPoint = p.Triple(i, arg, -Coordinate, Coordinate, o.FocalPoint);
    }
    else if (arg == "--view-up")
    {
      o.HasViewUp = p.Triple(i, arg, -Coordinate, Coordinate, o.ViewUp);
      if (o.HasViewUp && vtkMath::Norm(o.ViewUp.data()) == 0.0)
      {
        p.Fail("--view-up needs a non-zero vector");
      }
    }
    else if (arg == "--view-angle")
    {
      std::vector<std::string> v;
      if (p.Values(i, 1, arg, "an angle in degrees, 0 < DEG < 180", v))
      {
        double a = 0;
        if (!ParseDouble(v[0], a) || a <= 0.0 || a >= 180.0)
        {
          p.Fail("--view-angle needs an angle in degrees, 0 < DEG < 180, got '" + v[0] + "'");
        }
        o.ViewAngle = a;
      }
    }
    else if (arg == "--horizontal-view-angle")
    {
      o.HorizontalViewAngle = true;
    }
    else if (arg == "--light-direction" || arg == "--light-position")
    {
      LightSpec light;
      light.Positional = arg == "--light-position";
      if (p.Triple(i, arg, -Coordinate, Coordinate, light.Vector))
      {
        if (!light.Positional && vtkMath::Norm(light.Vector.data()) == 0.0)
        {
          p.Fail("--light-direction needs a non-zero vector");
        }
        o.Lights.push_back(light);
      }
    }
    else if (arg == "--light-color" || arg == "--light-intensity")
    {
      if (o.Lights.empty())
      {
        p.Fail(arg +
          " applies to the most recent light: give --light-direction or "
          "--light-position before it");
      }
      else if (arg == "--light-color")
      {
        p.Triple(i, arg, 0.0, Huge, o.Lights.back().Color);
      }
      else
      {
        p.Double(i, arg, 0.0, Huge, o.Lights.back().Intensity);
      }
    }
    else if (arg == "--background")
    {
      o.HasBackground = p.Triple(i, arg, 0.0, 1.0, o.Background);
    }
    else if (arg == "--background2")
    {
      o.HasBackground2 = p.Triple(i, arg, 0.0, 1.0, o.Background2);
    }
    else
    {
      p.Fail("unknown option '" + arg + "' (see --help)");
    }
  }
  if (!p.Failed())
  {
    if (o.Input.empty())
    {
      if (!o.Grid.empty())
      {
        p.Fail("--grid needs a .vdb input");
      }
      else if (o.Component >= 0)
      {
        p.Fail("--component needs an input file");
      }
    }
    else if (o.ResolutionSet)
    {
      p.Fail("--resolution applies to the built-in cloud only, not to an input file");
    }
    if (!o.Preset.empty() && !o.TransferFunctionFile.empty())
    {
      p.Fail("give either --preset or --transfer-function, not both");
    }
  }
  error = p.GetError();
  return !p.Failed();
}

// Reads the transfer-function file format documented in Usage().
bool ReadTransferFunction(const std::string& path, TransferFunction& tf, std::string& error)
{
  std::ifstream in(path);
  if (!in)
  {
    error = path + ": cannot open the transfer-function file";
    return false;
  }
  int opacityPoints = 0;
  bool unitDistanceSeen = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number)
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;)
    {
      w.push_back(word);
    }
    if (w.empty())
    {
      continue;
    }
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const std::string& key = w[0];
    size_t expected = 0;
    const char* syntax = nullptr;
    if (key == "opacity")
    {
      expected = 2;
      syntax = "opacity <value> <alpha>";
    }
    else if (key == "color" || key == "colour")
    {
      expected = 4;
      syntax = "color <value> <r> <g> <b>";
    }
    else if (key == "emission")
    {
      expected = 4;
      syntax = "emission <value> <r> <g> <b>";
    }
    else if (key == "unit-distance")
    {
      expected = 1;
      syntax = "unit-distance <d>";
    }
    else
    {
      error = where + "unknown keyword '" + key +
        "' (expected opacity, color, emission or unit-distance)";
      return false;
    }
    if (w.size() != expected + 1)
    {
      error = where + "expected '" + syntax + "' (" + std::to_string(expected) + " number" +
        (expected == 1 ? "" : "s") + "), got " + std::to_string(w.size() - 1);
      return false;
    }
    double v[4] = { 0, 0, 0, 0 };
    for (size_t k = 0; k < expected; ++k)
    {
      if (!ParseDouble(w[k + 1], v[k]))
      {
        error = where + "'" + w[k + 1] + "' is not a finite number (in '" + syntax + "')";
        return false;
      }
    }
    if (key == "opacity")
    {
      if (v[1] < 0.0 || v[1] > 1.0)
      {
        error = where + "alpha must be in [0, 1], got " + w[2];
        return false;
      }
      tf.Opacity->AddPoint(v[0], v[1]);
      ++opacityPoints;
    }
    else if (key == "color" || key == "colour")
    {
      for (int k = 1; k < 4; ++k)
      {
        if (v[k] < 0.0 || v[k] > 1.0)
        {
          error = where + "colour components must be in [0, 1], got " + w[k + 1];
          return false;
        }
      }
      tf.Color->AddRGBPoint(v[0], v[1], v[2], v[3]);
      tf.HasColor = true;
    }
    else if (key == "emission")
    {
      for (int k = 1; k < 4; ++k)
      {
        if (v[k] < 0.0)
        {
          error = where + "emission components must be >= 0, got " + w[k + 1];
          return false;
        }
      }
      tf.Emission->AddRGBPoint(v[0], v[1], v[2], v[3]);
      tf.HasEmission = true;
    }
    else
    {
      if (unitDistanceSeen)
      {
        error = where + "unit-distance given twice";
        return false;
      }
      if (v[0] <= 0.0)
      {
        error = where + "unit-distance must be > 0, got " + w[1];
        return false;
      }
      tf.UnitDistance = v[0];
      unitDistanceSeen = true;
    }
  }
  if (in.bad())
  {
    error = path + ": read error";
    return false;
  }
  if (opacityPoints == 0)
  {
    error = path + ": no 'opacity <value> <alpha>' line: the medium would be empty";
    return false;
  }
  if (!tf.HasColor)
  {
    tf.Color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  }
  return true;
}

// Progress on stderr: "label: 0% 20% ... 100%".
struct Progress
{
  std::string Label;
  int Next = 0;
  bool Quiet = false;
  void Report(double fraction)
  {
    if (this->Quiet)
    {
      return;
    }
    const int percent = static_cast<int>(std::floor(fraction * 100.0 + 1e-9));
    while (this->Next <= 100 && percent >= this->Next)
    {
      std::cerr << (this->Next == 0 ? this->Label + ": " : std::string(" ")) << this->Next << "%"
                << (this->Next == 100 ? "\n" : "") << std::flush;
      this->Next += 20;
    }
  }
  void Finish() { this->Report(1.0); }
};

// Collects VTK errors of an object instead of printing them.
struct ErrorCollector
{
  std::vector<std::string> Messages;
  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ErrorCollector*>(clientData);
    std::string message = callData ? static_cast<const char*>(callData) : "unknown error";
    // "ERROR: In file, line N\nclass (0x...): text\n\n" -> "class: text"
    const auto newline = message.find('\n');
    if (message.rfind("ERROR: In ", 0) == 0 && newline != std::string::npos)
    {
      message = message.substr(newline + 1);
    }
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
    {
      message.pop_back();
    }
    self->Messages.push_back(message);
  }
  void Watch(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(&ErrorCollector::Callback);
    command->SetClientData(this);
    object->AddObserver(vtkCommand::ErrorEvent, command);
  }
};

#ifdef TYNDALL_HAVE_OPENEXR
// Writes an RGB float EXR from bottom-up RGBA float rows (OpenGL order).
bool WriteExr(const std::string& path, int width, int height, const std::vector<float>& rgba,
  std::string& error)
{
  try
  {
    std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
    {
      const float* src = rgba.data() + static_cast<size_t>(height - 1 - y) * width * 4;
      float* dst = rgb.data() + static_cast<size_t>(y) * width * 3;
      for (int x = 0; x < width; ++x)
      {
        dst[3 * x + 0] = src[4 * x + 0];
        dst[3 * x + 1] = src[4 * x + 1];
        dst[3 * x + 2] = src[4 * x + 2];
      }
    }
    Imf::Header header(width, height);
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    header.channels().insert("G", Imf::Channel(Imf::FLOAT));
    header.channels().insert("B", Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer frame;
    const size_t xStride = 3 * sizeof(float);
    const size_t yStride = xStride * width;
    char* base = reinterpret_cast<char*>(rgb.data());
    frame.insert("R", Imf::Slice(Imf::FLOAT, base + 0 * sizeof(float), xStride, yStride));
    frame.insert("G", Imf::Slice(Imf::FLOAT, base + 1 * sizeof(float), xStride, yStride));
    frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
    file.setFrameBuffer(frame);
    file.writePixels(height);
  }
  catch (const std::exception& e)
  {
    error = path + ": cannot write the OpenEXR file: " + e.what();
    return false;
  }
  return true;
}
#endif

// The built-in cloud's transfer function, as in the README's picture.
void DefaultCloudTransferFunction(vtkVolumeProperty* property)
{
  // A white cloud: VTK opacity semantics (0.5 per 0.05 units at density 8),
  // albedo 0.95.
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(8.0, 0.5);
  vtkNew<vtkColorTransferFunction> albedo;
  albedo->AddRGBPoint(0.0, 0.95, 0.95, 0.95);
  property->SetScalarOpacity(opacity);
  property->SetColor(albedo);
  property->SetScalarOpacityUnitDistance(0.05);
}

// The generic ramp for data inputs without presets (see Usage()).
void GenericRamp(vtkVolumeProperty* property, const double range[2], const double bounds[6])
{
  const double lo = range[0];
  const double hi = range[1];
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(lo + 0.05 * (hi - lo), 0.0);
  opacity->AddPoint(hi, 1.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.9, 0.9, 0.9);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  property->SetScalarOpacityUnitDistance(diagonal > 0 ? diagonal / 50.0 : 1.0);
}

#ifdef TYNDALL_HAVE_IO
// The preset guessed for data inputs (see Usage()).
std::string GuessPreset(vtkImageData* image, const double range[2])
{
  if (range[0] < -500.0)
  {
    return "CT";
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    scalars = image->GetCellData()->GetScalars();
  }
  const int type = scalars ? scalars->GetDataType() : VTK_FLOAT;
  return (type == VTK_FLOAT || type == VTK_DOUBLE) ? "Cloud" : "MR";
}
#endif

// The mapper and medium: the default scene's settings, then the options.
void ConfigureMapper(vtkTransmittanceVolumeMapper* mapper, const Options& o, bool defaultScene,
  const TransferFunction& tf, vtkParticipatingMediumProperty* property)
{
  property->SetScatteringModelToSingleScattering();
  mapper->SetTransmittanceMethodToAdaptiveETM();
  mapper->SetNumberOfCoefficients(8);
  mapper->SetTransmittanceMapSize(256);
  property->SetScatteringAnisotropy(defaultScene ? 0.3 : 0.0);
  property->SetAmbientIntensity(defaultScene ? 0.45 : 0.25);
  if (o.Method >= 0)
  {
    mapper->SetTransmittanceMethod(o.Method);
  }
  if (o.Model >= 0)
  {
    property->SetScatteringModel(o.Model);
  }
  if (o.Coefficients > 0)
  {
    mapper->SetNumberOfCoefficients(o.Coefficients);
  }
  if (o.MapSize > 0)
  {
    mapper->SetTransmittanceMapSize(o.MapSize);
  }
  if (o.LightSamples > 0)
  {
    mapper->SetLightSampleCount(o.LightSamples);
  }
  if (!std::isnan(o.Anisotropy))
  {
    property->SetScatteringAnisotropy(o.Anisotropy);
  }
  if (!std::isnan(o.DensityScale))
  {
    property->SetDensityScale(o.DensityScale);
  }
  if (!std::isnan(o.SampleDistance))
  {
    mapper->SetSampleDistance(o.SampleDistance);
  }
  if (!std::isnan(o.AdaptiveThreshold))
  {
    mapper->SetAdaptiveThreshold(o.AdaptiveThreshold);
  }
  if (!std::isnan(o.Ambient))
  {
    property->SetAmbientIntensity(o.Ambient);
  }
  if (!std::isnan(o.LightScale))
  {
    property->SetLightScale(o.LightScale);
  }
  if (!std::isnan(o.EmissionScale))
  {
    property->SetEmissionScale(o.EmissionScale);
    if (o.EmissionScale > 0.0)
    {
      property->SetEmissionColor(
        tf.HasEmission ? tf.Emission.Get() : property->GetRGBTransferFunction());
    }
  }
  if (o.NoJitter)
  {
    mapper->JitterOff();
  }
}

// The background: the default scene's sky or black, then the options.
void SetUpBackground(vtkRenderer* renderer, const Options& o, bool defaultScene)
{
  if (defaultScene)
  {
    renderer->GradientBackgroundOn();
    renderer->SetBackground(0.55, 0.68, 0.82);
    renderer->SetBackground2(0.16, 0.32, 0.58);
  }
  else
  {
    renderer->SetBackground(0.0, 0.0, 0.0);
  }
  if (o.HasBackground)
  {
    renderer->SetBackground(o.Background.data());
    renderer->SetGradientBackground(o.HasBackground2);
  }
  if (o.HasBackground2)
  {
    renderer->SetBackground2(o.Background2.data());
    renderer->GradientBackgroundOn();
  }
}

// The camera: the default scene's view or a fit to the data's bounds, then
// the options. Returns false (with `error`) for a degenerate view.
bool SetUpCamera(vtkRenderer* renderer, const Options& o, bool defaultScene, const double bounds[6],
  std::string& error)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetViewAngle(30.0);
  if (!std::isnan(o.ViewAngle))
  {
    camera->SetViewAngle(o.ViewAngle);
  }
  if (o.HorizontalViewAngle)
  {
    camera->UseHorizontalViewAngleOn();
  }
  if (defaultScene)
  {
    camera->SetPosition(0.0, -0.6, 4.2);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
  }
  else
  {
    // Fitted to the data (the window's aspect is needed for the fit).
    renderer->SetAspect(static_cast<double>(o.Size[0]) / o.Size[1], 1.0);
    renderer->ResetCamera(bounds);
  }
  if (o.HasCameraPosition)
  {
    camera->SetPosition(o.CameraPosition.data());
  }
  if (o.HasFocalPoint)
  {
    camera->SetFocalPoint(o.FocalPoint.data());
  }
  if (o.HasViewUp)
  {
    camera->SetViewUp(o.ViewUp.data());
  }
  {
    double position[3], focal[3], up[3], direction[3], side[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    vtkMath::Subtract(focal, position, direction);
    if (vtkMath::Norm(direction) < 1e-12)
    {
      error = "the camera position and the focal point coincide";
      return false;
    }
    vtkMath::Normalize(direction);
    vtkMath::Normalize(up);
    vtkMath::Cross(direction, up, side);
    if (vtkMath::Norm(side) < 1e-6)
    {
      error = "the view-up vector is parallel to the view direction";
      return false;
    }
    // SetPosition/SetFocalPoint keep the old view-up: make it orthogonal.
    camera->OrthogonalizeViewUp();
  }

  return true;
}

// The lights: the given ones, else the default scene's sun or a key light
// relative to the camera (for data inputs).
void AddLights(vtkRenderer* renderer, const Options& o, bool defaultScene, const double bounds[6])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  if (o.Lights.empty() && defaultScene)
  {
    vtkNew<vtkLight> sun; // a low sun from the front right
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetPosition(1.0, 0.3, 0.5);
    sun->SetFocalPoint(0.0, 0.0, 0.0);
    sun->SetColor(1.0, 0.9, 0.75);
    sun->SetIntensity(1.2);
    renderer->AddLight(sun);
  }
  else if (o.Lights.empty())
  {
    // A key light from the camera's upper right, in front of the data.
    double position[3], focal[3], up[3], back[3], right[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    vtkMath::Subtract(position, focal, back);
    vtkMath::Normalize(back);
    vtkMath::Cross(up, back, right);
    vtkMath::Normalize(right);
    double from[3];
    for (int k = 0; k < 3; ++k)
    {
      from[k] = 0.6 * right[k] + 0.6 * up[k] + 0.55 * back[k];
    }
    vtkMath::Normalize(from);
    vtkNew<vtkLight> key;
    key->SetLightTypeToSceneLight();
    key->SetPositional(false);
    key->SetFocalPoint(focal);
    key->SetPosition(focal[0] + from[0], focal[1] + from[1], focal[2] + from[2]);
    key->SetColor(1.0, 1.0, 1.0);
    key->SetIntensity(1.0);
    renderer->AddLight(key);
  }
  for (const LightSpec& spec : o.Lights)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    if (spec.Positional)
    {
      // A point light: positional with a 90 degree cone (not a spot light),
      // VTK's default attenuation (1, 0, 0): no fall-off.
      light->SetPositional(true);
      light->SetConeAngle(90.0);
      light->SetPosition(spec.Vector.data());
      light->SetFocalPoint(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
        0.5 * (bounds[4] + bounds[5]));
    }
    else
    {
      // VTK's directional lights shine from Position towards FocalPoint.
      light->SetPositional(false);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      light->SetPosition(-spec.Vector[0], -spec.Vector[1], -spec.Vector[2]);
    }
    light->SetColor(spec.Color.data());
    light->SetIntensity(spec.Intensity);
    renderer->AddLight(light);
  }
}

std::string DefaultOutputFor(const std::string& input)
{
  std::string name = vtksys::SystemTools::GetFilenameName(vtksys::SystemTools::ConvertToOutputPath(
    input.back() == '/' ? input.substr(0, input.size() - 1) : input));
  const std::string lower = vtksys::SystemTools::LowerCase(name);
  if (lower.size() > 7 && lower.compare(lower.size() - 7, 7, ".nii.gz") == 0)
  {
    name.erase(name.size() - 7);
  }
  else
  {
    name = vtksys::SystemTools::GetFilenameWithoutLastExtension(name);
  }
  if (name.empty() || name == "." || name == "..")
  {
    name = "tyndall-render";
  }
  return name + ".png";
}
}

int main(int argc, char* argv[])
{
  Options o;
  bool help = false;
  std::string error;
  if (!ParseArguments(argc, argv, o, help, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return ExitUsage;
  }
  if (help)
  {
    Usage(std::cout);
    return EXIT_SUCCESS;
  }
#ifndef TYNDALL_HAVE_IO
  if (!o.Preset.empty())
  {
    std::cerr << Program << ": --preset needs Tyndall::IO, which this build does not have\n";
    return ExitUsage;
  }
#else
  if (!o.Preset.empty() && vtkTransferFunctionPresets::GetPresetIndex(o.Preset.c_str()) < 0)
  {
    std::cerr << Program << ": unknown preset '" << o.Preset << "' (known:";
    for (int i = 0; i < vtkTransferFunctionPresets::GetNumberOfPresets(); ++i)
    {
      std::cerr << " " << vtkTransferFunctionPresets::GetPresetName(i);
    }
    std::cerr << ")\n";
    return ExitUsage;
  }
#endif
#ifndef TYNDALL_HAVE_OPENEXR
  if (!o.Exr.empty())
  {
    std::cerr << Program << ": --exr is not available: this build has no OpenEXR\n";
    return ExitUsage;
  }
#endif
  const bool defaultScene = o.Input.empty();
  if (o.Output.empty())
  {
    o.Output = defaultScene ? "tyndall-cloud.png" : DefaultOutputFor(o.Input);
  }
  std::ostream& log = std::cerr;
  const bool verbose = !o.Quiet;

  // The transfer-function file is read before the (maybe slow) data.
  TransferFunction tf;
  if (!o.TransferFunctionFile.empty() && !ReadTransferFunction(o.TransferFunctionFile, tf, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return ExitFailure;
  }

  // 1. The medium.
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkSmartPointer<vtkImageData> image;
  vtkNew<vtkCosineNoiseSource> cloud;
  if (defaultScene)
  {
    const int n = o.Resolution - 1;
    cloud->SetWholeExtent(0, n, 0, n, 0, n);
    cloud->SetSpacing(2.0 / n, 2.0 / n, 2.0 / n);
    Progress progress;
    progress.Label = "cloud: " + std::to_string(o.Resolution) + "^3 voxels";
    progress.Quiet = !verbose;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&progress);
    onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
      { static_cast<Progress*>(client)->Report(*static_cast<double*>(call)); });
    cloud->AddObserver(vtkCommand::ProgressEvent, onProgress);
    cloud->Update();
    progress.Finish();
    image = cloud->GetOutput();
    timer->StopTimer();
    if (verbose)
    {
      log << "cloud: " << o.Resolution << "^3 voxels in " << timer->GetElapsedTime() << " s\n";
    }
  }
  else
  {
    Progress progress;
    progress.Label = "loading " + o.Input;
    progress.Quiet = !verbose;
    tyndallLoadVolumeOptions loadOptions;
    loadOptions.GridName = o.Grid;
    loadOptions.Component = o.Component;
    loadOptions.Progress = [&progress](double f) { progress.Report(f); };
    image = tyndallLoadVolume(o.Input, loadOptions, error);
    timer->StopTimer();
    if (!image)
    {
      if (verbose && progress.Next > 0 && progress.Next <= 100)
      {
        log << "\n";
      }
      std::cerr << Program << ": " << error << "\n";
      return ExitFailure;
    }
    if (progress.Next > 0)
    {
      progress.Finish();
    }
    if (verbose)
    {
      int dims[3];
      image->GetDimensions(dims);
      vtkDataArray* scalars = image->GetPointData()->GetScalars();
      if (!scalars)
      {
        scalars = image->GetCellData()->GetScalars();
      }
      double range[2];
      scalars->GetRange(range);
      double bounds[6];
      image->GetBounds(bounds);
      log << "loaded " << o.Input << ": " << dims[0] << " x " << dims[1] << " x " << dims[2] << " "
          << scalars->GetDataTypeAsString() << ", scalars '"
          << (scalars->GetName() ? scalars->GetName() : "") << "' in [" << range[0] << ", "
          << range[1] << "], bounds [" << bounds[0] << ", " << bounds[1] << "] x [" << bounds[2]
          << ", " << bounds[3] << "] x [" << bounds[4] << ", " << bounds[5] << "] in "
          << timer->GetElapsedTime() << " s\n";
    }
  }
  double range[2] = { 0.0, 1.0 };
  {
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    if (!scalars)
    {
      scalars = image->GetCellData()->GetScalars();
    }
    if (scalars)
    {
      scalars->GetRange(range);
    }
  }
  double bounds[6];
  image->GetBounds(bounds);

  // 2. The transfer function, over the scalar range (constant data c: over
  // [0, c], so that the medium is visible).
  double tfRange[2] = { range[0], range[1] };
  if (!(range[1] > range[0]))
  {
    tfRange[0] = std::min(0.0, range[0]);
    tfRange[1] = std::max(0.0, range[0]);
    if (tfRange[0] == tfRange[1])
    {
      tfRange[1] = tfRange[0] + 1.0;
    }
  }
  vtkNew<vtkParticipatingMediumProperty> property;
  std::string tfDescription;
  if (!o.TransferFunctionFile.empty())
  {
    property->SetScalarOpacity(tf.Opacity);
    property->SetColor(tf.Color);
    property->SetScalarOpacityUnitDistance(tf.UnitDistance);
    tfDescription = "file " + o.TransferFunctionFile;
  }
  else if (!o.Preset.empty() || !defaultScene)
  {
#ifdef TYNDALL_HAVE_IO
    std::string preset = o.Preset;
    if (preset.empty())
    {
      preset = GuessPreset(image, range);
    }
    // Presets give opacities per voxel: the unit distance is the mean
    // spacing.
    if (!vtkTransferFunctionPresets::Apply(preset.c_str(), property, tfRange))
    {
      std::cerr << Program << ": cannot apply the preset '" << preset << "'\n";
      return ExitFailure;
    }
    double spacing[3];
    image->GetSpacing(spacing);
    property->SetScalarOpacityUnitDistance(
      (std::fabs(spacing[0]) + std::fabs(spacing[1]) + std::fabs(spacing[2])) / 3.0);
    tfDescription = "preset " + preset + (o.Preset.empty() ? " (guessed)" : "");
#else
    GenericRamp(property, tfRange, bounds);
    tfDescription = "generic ramp";
#endif
  }
  else
  {
    DefaultCloudTransferFunction(property);
    tfDescription = "white cloud";
  }
  property->SetInterpolationTypeToLinear();
  if (verbose)
  {
    log << "transfer function: " << tfDescription << " (scalar range [" << range[0] << ", "
        << range[1] << "])\n";
  }

  // 3. The mapper: the default scene's settings, then the options.
  vtkNew<vtkTransmittanceVolumeMapper> mapper;
  if (defaultScene)
  {
    mapper->SetInputConnection(cloud->GetOutputPort());
  }
  else
  {
    mapper->SetInputData(image);
  }
  ConfigureMapper(mapper, o, defaultScene, tf, property);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  // 4. Renderer, background, camera, lights.
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  SetUpBackground(renderer, o, defaultScene);
  renderer->AutomaticLightCreationOff();

  if (!SetUpCamera(renderer, o, defaultScene, bounds, error))
  {
    std::cerr << Program << ": " << error << "\n";
    return ExitUsage;
  }
  AddLights(renderer, o, defaultScene, bounds);
  renderer->ResetCameraClippingRange();

  // Checked only now, so that bad inputs are reported without a display.
  if (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY"))
  {
    std::cerr << Program
              << ": no X display (DISPLAY is not set); Debian's VTK renders through "
                 "GLX: run under xvfb-run -a -s \"-screen 0 1280x1024x24\"\n";
    return ExitFailure;
  }

  // 5. The window. With --exr the scene is drawn into a float (RGBA32F)
  // frame buffer first, which keeps radiance above 1; it is then blitted
  // into the window's 8-bit frame buffer, which the PNG reads.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.Size[0], o.Size[1]);
  window->AddRenderer(renderer);
  vtkNew<vtkFramebufferPass> floatPass;
  vtkNew<vtkRenderStepsPass> steps;
  if (!o.Exr.empty())
  {
    floatPass->SetColorFormat(vtkTextureObject::Float32);
    floatPass->SetDelegatePass(steps);
    renderer->SetPass(floatPass);
  }
  ErrorCollector renderErrors;
  renderErrors.Watch(mapper);
  renderErrors.Watch(window);
  renderErrors.Watch(renderer);
  if (verbose)
  {
    log << "rendering " << o.Size[0] << " x " << o.Size[1] << ": "
        << mapper->GetTransmittanceMethodAsString() << ", "
        << (property->GetScatteringModel() == vtkParticipatingMediumProperty::SINGLE_SCATTERING
               ? "single scattering"
               : "emission-absorption")
        << ", " << renderer->GetLights()->GetNumberOfItems() << " light(s)"
        << (o.Exr.empty() ? "" : ", float frame buffer") << " ...\n";
  }
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  const double frameTime = timer->GetElapsedTime();
  if (!renderErrors.Messages.empty())
  {
    for (const auto& message : renderErrors.Messages)
    {
      std::cerr << Program << ": rendering failed: " << message << "\n";
    }
    if (!o.Exr.empty())
    {
      floatPass->ReleaseGraphicsResources(window);
    }
    return ExitFailure;
  }
  if (verbose)
  {
    log << "first frame: " << frameTime << " s (transmittance maps: "
        << (mapper->GetMapBuildCount() > 0 ? std::to_string(mapper->GetLastMapBuildTime()) + " s"
                                           : std::string("none"))
        << "; the rest: shader compilation, upload and ray casting)\n";
  }
  if (o.Frames > 1)
  {
    // Frames with the maps and shaders cached: the cost of a camera move.
    const int builds = mapper->GetMapBuildCount();
    timer->StartTimer();
    for (int f = 1; f < o.Frames; ++f)
    {
      window->Render();
    }
    window->WaitForCompletion();
    timer->StopTimer();
    if (verbose)
    {
      log << "cached frames: " << o.Frames - 1 << " in " << timer->GetElapsedTime() << " s, "
          << timer->GetElapsedTime() / (o.Frames - 1) << " s per frame (maps rebuilt "
          << mapper->GetMapBuildCount() - builds << " times)\n";
    }
  }

  // 6. The PNG: the window's frame buffer of the frame just rendered.
  timer->StartTimer();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(o.Output.c_str());
  ErrorCollector writeErrors;
  writeErrors.Watch(writer);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !writeErrors.Messages.empty())
  {
    std::cerr << Program << ": cannot write " << o.Output
              << (writeErrors.Messages.empty() ? "" : ": " + writeErrors.Messages.front()) << "\n";
    if (!o.Exr.empty())
    {
      floatPass->ReleaseGraphicsResources(window);
    }
    return ExitFailure;
  }
  timer->StopTimer();
  if (verbose)
  {
    log << "png: " << o.Output << " in " << timer->GetElapsedTime() << " s\n";
  }

  // 7. The EXR: the float colour texture of the same frame.
  if (!o.Exr.empty())
  {
#ifdef TYNDALL_HAVE_OPENEXR
    timer->StartTimer();
    window->MakeCurrent();
    vtkTextureObject* texture = floatPass->GetColorTexture();
    const int width = static_cast<int>(texture->GetWidth());
    const int height = static_cast<int>(texture->GetHeight());
    std::vector<float> rgba;
    bool ok = texture->GetComponents() == 4 && texture->GetVTKDataType() == VTK_FLOAT &&
      width == o.Size[0] && height == o.Size[1];
    if (ok)
    {
      vtkPixelBufferObject* pbo = texture->Download();
      ok = pbo != nullptr;
      if (ok)
      {
        const float* data = static_cast<const float*>(pbo->MapPackedBuffer());
        ok = data != nullptr;
        if (ok)
        {
          rgba.assign(data, data + static_cast<size_t>(width) * height * 4);
          pbo->UnmapPackedBuffer();
        }
        pbo->Delete();
      }
    }
    floatPass->ReleaseGraphicsResources(window);
    renderer->SetPass(nullptr);
    if (!ok)
    {
      std::cerr << Program << ": cannot read the float frame buffer back (" << width << " x "
                << height << ", " << texture->GetComponents() << " components)\n";
      return ExitFailure;
    }
    float maximum = 0.0f;
    for (size_t k = 0; k < rgba.size(); ++k)
    {
      if (k % 4 != 3)
      {
        maximum = std::max(maximum, rgba[k]);
      }
    }
    if (!WriteExr(o.Exr, width, height, rgba, error))
    {
      std::cerr << Program << ": " << error << "\n";
      return ExitFailure;
    }
    timer->StopTimer();
    if (verbose)
    {
      log << "exr: " << o.Exr << " (linear float RGB, maximum " << maximum << ") in "
          << timer->GetElapsedTime() << " s\n";
    }
#endif
  }
  std::cout << vtksys::SystemTools::CollapseFullPath(o.Output) << std::endl;
  return EXIT_SUCCESS;
}
