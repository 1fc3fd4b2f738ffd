// tyndall-viewer: an interactive viewer for vtkTransmittanceVolumeMapper.
//
// A GLFW window (OpenGL 3.2+ core profile, forward compatible) with GLEW,
// and VTK embedded through vtkGenericOpenGLRenderWindow on the window's own
// context. It shows the built-in cosine-noise cloud (or a volume file) lit by
// a low sun, with mouse navigation, keys for the mapper's settings, and an
// on-screen line with the method, the coefficient count, the frame time and
// the number of transmittance-map builds. Scripts (--script, --events) drive
// the same code paths as the mouse and keys, one command per frame, for
// tests. See Documentation/viewer.md.

// GLEW before GLFW (and before any VTK header, which include vtk_glew.h, the
// system GLEW on Debian): GLFW then includes no GL header of its own.
#include <GL/glew.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCosineNoiseSource.h"
#include "vtkDataArray.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtksys/SystemTools.hxx"

#ifdef TYNDALL_VIEWER_HAVE_LOADER
#include "tyndallLoadVolume.h"
#else
#include "vtkXMLImageDataReader.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* const Program = "tyndall-viewer";

void Usage(std::ostream& os)
{
  os << "Usage: tyndall-viewer [options] [VOLUME]\n"
        "Interactive viewer of vtkTransmittanceVolumeMapper: single scattering with\n"
        "transmittance-map shadows. Without VOLUME it shows the built-in cosine-noise\n"
        "cloud lit by a low sun. Needs an X display (use xvfb-run without one).\n\n"
        "Options:\n"
        "  -i, --input FILE      volume to show (same as VOLUME)\n"
#ifdef TYNDALL_VIEWER_HAVE_LOADER
        "  -g, --grid NAME       grid of a .vdb file (default: the first)\n"
#else
        "                        (.vti only in this build)\n"
#endif
        "  -r, --resolution N    voxels per axis of the default cloud, 8..512 (128)\n"
        "  -s, --size W H        window size in pixels, 16..8192 (default: 960 720)\n"
        "      --script FILE     run the commands in FILE, one per frame\n"
        "      --events TEXT     run the commands in TEXT (separated by ';'), one per frame\n"
        "  -v, --verbose         print a line per frame also without a script\n"
        "  -h, --help            show this help\n\n"
        "Mouse: left-drag orbit, middle-drag or shift+left-drag pan, wheel or\n"
        "right-drag zoom, ctrl+left-drag or L+left-drag move the sun.\n"
        "Keys: 1..6 method (None, BruteForce, TFM, AdaptiveTFM, ETM, AdaptiveETM),\n"
        "+/- coefficients, a/z anisotropy, d/c density scale, j jitter, h on-screen\n"
        "text, r reset camera, s screenshot, q or Esc quit.\n"
        "Script commands: orbit AZ EL, pan DX DY, zoom F, light AZ EL,\n"
        "drag BUTTON[+shift|+ctrl|+l] DX DY, key K, frames N, resize W H,\n"
        "hud on|off, screenshot PATH, quit.\n";
#ifdef TYNDALL_VIEWER_HAVE_LOADER
  os << "\nVolumes it reads:\n" << tyndallLoadVolumeFormats();
#endif
}

bool ParseInt(const std::string& text, int lo, int hi, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end || v < lo || v > hi)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseDouble(const std::string& text, double& value)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

//------------------------------------------------------------------------------
// Script commands.
struct Command
{
  std::string Text; // as written, for the log
  std::string Verb;
  std::vector<std::string> Args;
  std::string Where; // "FILE:LINE" or "--events #N"
};

// Key names a script can use beside single characters.
bool ParseKey(const std::string& name, int& key)
{
  std::string lower = vtksys::SystemTools::LowerCase(name);
  if (lower == "esc" || lower == "escape")
  {
    key = 27;
  }
  else if (lower == "plus")
  {
    key = '+';
  }
  else if (lower == "minus")
  {
    key = '-';
  }
  else if (name.size() == 1 && name[0] > ' ' && name[0] < 127)
  {
    key = name[0];
  }
  else
  {
    return false;
  }
  return true;
}

enum class DragMode
{
  None,
  Orbit,
  Pan,
  Zoom,
  Light
};

enum MouseButton
{
  ButtonLeft = 0,
  ButtonMiddle = 1,
  ButtonRight = 2
};

// What a drag with this button and these modifiers does: shared by the mouse
// and by the script's "drag" command.
DragMode DragModeFor(int button, bool shift, bool ctrl, bool lightKey)
{
  switch (button)
  {
    case ButtonLeft:
      if (ctrl || lightKey)
      {
        return DragMode::Light;
      }
      return shift ? DragMode::Pan : DragMode::Orbit;
    case ButtonMiddle:
      return DragMode::Pan;
    case ButtonRight:
      return DragMode::Zoom;
    default:
      return DragMode::None;
  }
}

// "left", "left+shift", "left+ctrl", "left+l", "middle", "right".
bool ParseDragButton(const std::string& spec, DragMode& mode)
{
  std::vector<std::string> parts;
  std::stringstream ss(vtksys::SystemTools::LowerCase(spec));
  std::string part;
  while (std::getline(ss, part, '+'))
  {
    parts.push_back(part);
  }
  if (parts.empty())
  {
    return false;
  }
  int button = -1;
  if (parts[0] == "left")
  {
    button = ButtonLeft;
  }
  else if (parts[0] == "middle")
  {
    button = ButtonMiddle;
  }
  else if (parts[0] == "right")
  {
    button = ButtonRight;
  }
  else
  {
    return false;
  }
  bool shift = false, ctrl = false, lightKey = false;
  for (size_t i = 1; i < parts.size(); ++i)
  {
    if (parts[i] == "shift")
    {
      shift = true;
    }
    else if (parts[i] == "ctrl")
    {
      ctrl = true;
    }
    else if (parts[i] == "l")
    {
      lightKey = true;
    }
    else
    {
      return false;
    }
  }
  mode = DragModeFor(button, shift, ctrl, lightKey);
  return true;
}

// Checks one command's verb and arguments; an empty string when it is valid.
std::string ValidateCommand(const Command& c)
{
  auto numbers = [&c](size_t count)
  {
    if (c.Args.size() != count)
    {
      return false;
    }
    for (const auto& a : c.Args)
    {
      double v;
      if (!ParseDouble(a, v))
      {
        return false;
      }
    }
    return true;
  };
  int iv;
  double dv;
  if (c.Verb == "orbit" || c.Verb == "pan" || c.Verb == "light")
  {
    return numbers(2) ? "" : "needs two numbers";
  }
  if (c.Verb == "zoom")
  {
    return numbers(1) && ParseDouble(c.Args[0], dv) && dv > 0.0 ? "" : "needs one number above 0";
  }
  if (c.Verb == "drag")
  {
    DragMode mode;
    if (c.Args.size() != 3 || !ParseDragButton(c.Args[0], mode) || !ParseDouble(c.Args[1], dv) ||
      !ParseDouble(c.Args[2], dv))
    {
      return "needs BUTTON[+shift|+ctrl|+l] DX DY with BUTTON left, middle or right";
    }
    return "";
  }
  if (c.Verb == "key")
  {
    return c.Args.size() == 1 && ParseKey(c.Args[0], iv)
      ? ""
      : "needs one key: a character, plus, minus or esc";
  }
  if (c.Verb == "frames")
  {
    return c.Args.size() == 1 && ParseInt(c.Args[0], 1, 100000, iv)
      ? ""
      : "needs a frame count in 1..100000";
  }
  if (c.Verb == "resize")
  {
    return c.Args.size() == 2 && ParseInt(c.Args[0], 16, 8192, iv) &&
        ParseInt(c.Args[1], 16, 8192, iv)
      ? ""
      : "needs two integers in 16..8192";
  }
  if (c.Verb == "hud")
  {
    return c.Args.size() == 1 && (c.Args[0] == "on" || c.Args[0] == "off") ? "" : "needs on or off";
  }
  if (c.Verb == "screenshot")
  {
    return c.Args.size() == 1 ? "" : "needs one file name";
  }
  if (c.Verb == "quit")
  {
    return c.Args.empty() ? "" : "takes no arguments";
  }
  return "unknown command";
}

// Parses script text: one command per line or per ';', '#' starts a
// comment. Returns false with a message on the first bad command.
bool ParseScript(const std::string& text, const std::string& origin, bool semicolons,
  std::vector<Command>& commands, std::string& error)
{
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  int index = 0;
  while (std::getline(lines, line))
  {
    ++lineNumber;
    const size_t hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::vector<std::string> pieces;
    if (semicolons)
    {
      std::stringstream ss(line);
      std::string piece;
      while (std::getline(ss, piece, ';'))
      {
        pieces.push_back(piece);
      }
    }
    else
    {
      pieces.push_back(line);
    }
    for (const auto& piece : pieces)
    {
      std::istringstream words(piece);
      Command c;
      std::string word;
      while (words >> word)
      {
        if (c.Verb.empty())
        {
          c.Verb = vtksys::SystemTools::LowerCase(word);
        }
        else
        {
          c.Args.push_back(word);
        }
      }
      if (c.Verb.empty())
      {
        continue;
      }
      ++index;
      c.Text = c.Verb;
      for (const auto& a : c.Args)
      {
        c.Text += " " + a;
      }
      c.Where = semicolons ? origin + " command " + std::to_string(index)
                           : origin + ":" + std::to_string(lineNumber);
      const std::string problem = ValidateCommand(c);
      if (!problem.empty())
      {
        error = c.Where + ": '" + c.Text + "': " + problem;
        return false;
      }
      commands.push_back(c);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Input.
vtkSmartPointer<vtkImageData> LoadInput(
  const std::string& path, const std::string& grid, std::string& error)
{
#ifdef TYNDALL_VIEWER_HAVE_LOADER
  return tyndallLoadVolume(path, grid, error);
#else
  (void)grid;
  const std::string ext =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (ext != ".vti")
  {
    error = path +
      ": this build of tyndall-viewer reads only .vti files (the examples' volume "
      "loader was not available when it was configured)";
    return nullptr;
  }
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    error = path + ": no such file";
    return nullptr;
  }
  vtkNew<vtkXMLImageDataReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    error = path + ": not a VTK XML image data file";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !image || image->GetNumberOfPoints() == 0)
  {
    error = path + ": cannot read the image data";
    return nullptr;
  }
  return image;
#endif
}

//------------------------------------------------------------------------------
// The viewer.
class Viewer
{
public:
  Viewer() = default;
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Options.
  std::string InputPath;
  std::string GridName;
  int Resolution = 128;
  int Size[2] = { 960, 720 };
  std::vector<Command> Script;
  bool Verbose = false;

  int Run();

private:
  bool LoadScene();
  bool OpenWindow();
  void SetUpVTK();
  void ResetCamera();
  void RenderFrame();
  bool WriteScreenshot(const std::string& path);
  void UpdateText();
  void LogFrame();

  // Actions: the mouse, the keys and the script all go through these.
  void Orbit(double azimuth, double elevation);
  void Pan(double dx, double dy);
  void Zoom(double factor);
  void MoveLight(double azimuth, double elevation);
  void Drag(DragMode mode, double dx, double dy);
  void Key(int key);
  void Execute(const Command& c);

  // GLFW callbacks.
  static Viewer* From(GLFWwindow* w) { return static_cast<Viewer*>(glfwGetWindowUserPointer(w)); }
  static void OnCursor(GLFWwindow* w, double x, double y);
  static void OnButton(GLFWwindow* w, int button, int action, int mods);
  static void OnScroll(GLFWwindow* w, double dx, double dy);
  static void OnKey(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void OnChar(GLFWwindow* w, unsigned int codepoint);
  static void OnFramebufferSize(GLFWwindow* w, int width, int height);
  static void OnRefresh(GLFWwindow* w);

  GLFWwindow* Window = nullptr;
  bool GlfwInitialized = false;

  vtkSmartPointer<vtkAlgorithm> Source;
  vtkSmartPointer<vtkImageData> Image;
  bool DefaultCloud = true;
  double Bounds[6] = { -1, 1, -1, 1, -1, 1 };
  vtkNew<vtkTransmittanceVolumeMapper> Mapper;
  vtkSmartPointer<vtkParticipatingMediumProperty> Medium;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Sun;
  vtkNew<vtkTextActor> Text;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> RenderWindow;
  double InitialCamera[10] = {};

  bool Quit = false;
  bool NeedsRender = true;
  bool ShowText = true;
  int FrameNumber = 0;
  double LastFrameMs = 0.0;
  std::vector<double> FrameTimes;
  std::string PendingScreenshot;
  int ScreenshotCounter = 0;
  int ExitCode = EXIT_SUCCESS;
  std::string CurrentCommand;

  // Mouse state.
  bool ButtonDown[3] = { false, false, false };
  double LastCursor[2] = { 0.0, 0.0 };
};

Viewer::~Viewer()
{
  if (this->RenderWindow && this->Window)
  {
    // Release VTK's GL objects while their context still exists.
    glfwMakeContextCurrent(this->Window);
    this->RenderWindow->SetIsCurrent(true);
    this->RenderWindow->Finalize();
    this->RenderWindow->SetReadyForRendering(false);
  }
  this->RenderWindow = nullptr;
  if (this->Window)
  {
    glfwDestroyWindow(this->Window);
  }
  if (this->GlfwInitialized)
  {
    glfwTerminate();
  }
}

bool Viewer::LoadScene()
{
  if (this->InputPath.empty())
  {
    vtkNew<vtkCosineNoiseSource> cloud;
    const int n = this->Resolution - 1;
    cloud->SetWholeExtent(0, n, 0, n, 0, n);
    cloud->SetSpacing(2.0 / n, 2.0 / n, 2.0 / n);
    cloud->Update();
    this->Source = cloud;
    this->Image = cloud->GetOutput();
    this->DefaultCloud = true;
    this->Mapper->SetInputConnection(cloud->GetOutputPort());
  }
  else
  {
    std::string error;
    this->Image = LoadInput(this->InputPath, this->GridName, error);
    if (!this->Image)
    {
      // The loader's messages start with the path.
      std::cerr << Program << ": " << (error.empty() ? this->InputPath + ": cannot load it" : error)
                << "\n";
      return false;
    }
    vtkDataArray* scalars = this->Image->GetPointData()->GetScalars();
    if (!scalars)
    {
      scalars = this->Image->GetCellData()->GetScalars();
    }
    if (!scalars)
    {
      std::cerr << Program << ": '" << this->InputPath << "' has no scalars to render\n";
      return false;
    }
    this->DefaultCloud = false;
    this->Mapper->SetInputData(this->Image);
  }
  this->Image->GetBounds(this->Bounds);

  vtkNew<vtkPiecewiseFunction> opacity;
  vtkNew<vtkColorTransferFunction> albedo;
  vtkNew<vtkParticipatingMediumProperty> property;
  if (this->DefaultCloud)
  {
    // tyndall-render's white cloud: 0.5 opacity per 0.05 units at density 8.
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(8.0, 0.5);
    albedo->AddRGBPoint(0.0, 0.95, 0.95, 0.95);
    property->SetScalarOpacityUnitDistance(0.05);
  }
  else
  {
    // Any other volume: a linear opacity ramp over the upper 95 % of the
    // scalar range, a white medium about 40 unit distances across; d/c
    // scale the density from there.
    vtkDataArray* scalars = this->Image->GetPointData()->GetScalars();
    if (!scalars)
    {
      scalars = this->Image->GetCellData()->GetScalars();
    }
    double range[2];
    scalars->GetRange(range, 0);
    if (!(range[1] > range[0]))
    {
      range[1] = range[0] + 1.0;
    }
    opacity->AddPoint(range[0], 0.0);
    opacity->AddPoint(range[0] + 0.05 * (range[1] - range[0]), 0.0);
    opacity->AddPoint(range[1], 0.5);
    albedo->AddRGBPoint(range[0], 0.95, 0.95, 0.95);
    const double low[3] = { this->Bounds[0], this->Bounds[2], this->Bounds[4] };
    const double high[3] = { this->Bounds[1], this->Bounds[3], this->Bounds[5] };
    const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(low, high));
    property->SetScalarOpacityUnitDistance(diagonal > 0.0 ? diagonal / 40.0 : 1.0);
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(albedo);
  property->SetInterpolationTypeToLinear();

  property->SetScatteringModelToSingleScattering();
  property->SetScatteringAnisotropy(0.3);
  property->SetAmbientIntensity(0.45);
  this->Medium = property;
  this->Mapper->SetTransmittanceMethodToAdaptiveETM();
  this->Mapper->SetNumberOfCoefficients(8);
  this->Mapper->SetTransmittanceMapSize(256);
  this->Volume->SetMapper(this->Mapper);
  this->Volume->SetProperty(property);
  return true;
}

//------------------------------------------------------------------------------
// VTK asks for the context through these events (Render, ReadPixels, release).
void OnMakeCurrent(vtkObject*, unsigned long, void* clientData, void*)
{
  glfwMakeContextCurrent(static_cast<GLFWwindow*>(clientData));
}

void OnIsCurrent(vtkObject*, unsigned long, void* clientData, void* callData)
{
  *static_cast<bool*>(callData) = glfwGetCurrentContext() == static_cast<GLFWwindow*>(clientData);
}

void OnSupportsOpenGL(vtkObject*, unsigned long, void*, void* callData)
{
  *static_cast<int*>(callData) = 1;
}

std::string LastGlfwError;

void OnGlfwError(int code, const char* description)
{
  LastGlfwError = std::string(description ? description : "unknown") + " (GLFW error 0x";
  std::ostringstream hex;
  hex << std::hex << code << ")";
  LastGlfwError += hex.str();
}

bool Viewer::OpenWindow()
{
  glfwSetErrorCallback(OnGlfwError);
  if (!glfwInit())
  {
    std::cerr << Program << ": cannot initialise GLFW: " << LastGlfwError << "\n";
    const char* display = std::getenv("DISPLAY");
    std::cerr << Program << ": it needs an X display"
              << (display && *display ? "" : " and DISPLAY is not set")
              << "; without a screen, run it under xvfb-run -a -s \"-screen 0 1280x1024x24\"\n";
    return false;
  }
  this->GlfwInitialized = true;

  // VTK 9.1 needs OpenGL 3.2 core; GLX is what Debian's VTK and GLEW use.
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_NATIVE_CONTEXT_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_STENCIL_BITS, 8);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  const std::string title = std::string("Tyndall viewer - ") +
    (this->InputPath.empty() ? std::string("cosine-noise cloud")
                             : vtksys::SystemTools::GetFilenameName(this->InputPath));
  this->Window = glfwCreateWindow(this->Size[0], this->Size[1], title.c_str(), nullptr, nullptr);
  if (!this->Window)
  {
    std::cerr << Program << ": cannot create a window with an OpenGL 3.2 core profile context: "
              << LastGlfwError << "\n"
              << Program << ": Tyndall needs OpenGL 3.2 or later (Mesa's llvmpipe gives 4.5)\n";
    return false;
  }
  glfwSetWindowUserPointer(this->Window, this);
  glfwMakeContextCurrent(this->Window);
  // Scripts run as fast as they can; interactive frames wait for the screen.
  glfwSwapInterval(this->Script.empty() ? 1 : 0);

  glewExperimental = GL_TRUE;
  const GLenum glewStatus = glewInit();
  if (glewStatus != GLEW_OK)
  {
    std::cerr << Program << ": cannot initialise GLEW: "
              << reinterpret_cast<const char*>(glewGetErrorString(glewStatus)) << "\n";
    return false;
  }
  // glewInit asks for GL_EXTENSIONS the pre-3.0 way, which a core profile
  // answers with GL_INVALID_ENUM: clear it so that VTK does not report it.
  while (glGetError() != GL_NO_ERROR)
  {
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  while (glGetError() != GL_NO_ERROR)
  {
  }
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (major * 100 + minor < 302)
  {
    std::cerr << Program << ": OpenGL " << (version ? version : "(unknown version)")
              << " is too old: Tyndall needs OpenGL 3.2 or later\n";
    return false;
  }
  std::cerr << Program << ": OpenGL " << (version ? version : "?") << " on "
            << (renderer ? renderer : "?") << "\n";

  glfwSetCursorPosCallback(this->Window, &Viewer::OnCursor);
  glfwSetMouseButtonCallback(this->Window, &Viewer::OnButton);
  glfwSetScrollCallback(this->Window, &Viewer::OnScroll);
  glfwSetKeyCallback(this->Window, &Viewer::OnKey);
  glfwSetCharCallback(this->Window, &Viewer::OnChar);
  glfwSetFramebufferSizeCallback(this->Window, &Viewer::OnFramebufferSize);
  glfwSetWindowRefreshCallback(this->Window, &Viewer::OnRefresh);
  return true;
}

void Viewer::SetUpVTK()
{
  this->Renderer->AddVolume(this->Volume);
  this->Renderer->GradientBackgroundOn();
  this->Renderer->SetBackground(0.55, 0.68, 0.82);
  this->Renderer->SetBackground2(0.16, 0.32, 0.58);
  this->Renderer->AutomaticLightCreationOff();

  // A low sun from the front right (tyndall-render's), aimed at the centre.
  const double center[3] = { 0.5 * (this->Bounds[0] + this->Bounds[1]),
    0.5 * (this->Bounds[2] + this->Bounds[3]), 0.5 * (this->Bounds[4] + this->Bounds[5]) };
  this->Sun->SetLightTypeToSceneLight();
  this->Sun->SetPositional(false);
  this->Sun->SetPosition(center[0] + 1.0, center[1] + 0.3, center[2] + 0.5);
  this->Sun->SetFocalPoint(center);
  this->Sun->SetColor(1.0, 0.9, 0.75);
  this->Sun->SetIntensity(1.2);
  this->Renderer->AddLight(this->Sun);

  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0], center[1] - 0.6, center[2] + 4.2);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  if (!this->DefaultCloud)
  {
    this->Renderer->ResetCamera(this->Bounds); // keeps the direction, fits the volume
  }
  this->Renderer->ResetCameraClippingRange();
  camera->GetPosition(&this->InitialCamera[0]);
  camera->GetFocalPoint(&this->InitialCamera[3]);
  camera->GetViewUp(&this->InitialCamera[6]);
  this->InitialCamera[9] = camera->GetViewAngle();

  vtkTextProperty* tp = this->Text->GetTextProperty();
  tp->SetFontFamilyToCourier();
  tp->SetColor(1.0, 1.0, 1.0);
  tp->ShadowOn();
  this->Text->SetDisplayPosition(8, 8);
  this->Renderer->AddActor2D(this->Text);

  // VTK on GLFW's context: it does not own the context, renders into its
  // own framebuffers and blits the result to the window's back buffer.
  this->RenderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  this->RenderWindow->SetOwnContext(false);
  this->RenderWindow->SetMultiSamples(0);
  this->RenderWindow->SetFrameBlitModeToBlitToCurrent();
  this->RenderWindow->AddRenderer(this->Renderer);
  const struct
  {
    unsigned long Event;
    void (*Function)(vtkObject*, unsigned long, void*, void*);
  } observers[] = { { vtkCommand::WindowMakeCurrentEvent, OnMakeCurrent },
    { vtkCommand::WindowIsCurrentEvent, OnIsCurrent },
    { vtkCommand::WindowSupportsOpenGLEvent, OnSupportsOpenGL },
    { vtkCommand::WindowIsDirectEvent, OnSupportsOpenGL } };
  for (const auto& o : observers)
  {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(o.Function);
    command->SetClientData(this->Window);
    this->RenderWindow->AddObserver(o.Event, command);
  }
  int fb[2];
  glfwGetFramebufferSize(this->Window, &fb[0], &fb[1]);
  this->RenderWindow->SetSize(std::max(fb[0], 1), std::max(fb[1], 1));
  this->RenderWindow->InitializeFromCurrentContext();
  this->RenderWindow->SetIsCurrent(true);
  this->UpdateText();
}

void Viewer::ResetCamera()
{
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetPosition(&this->InitialCamera[0]);
  camera->SetFocalPoint(&this->InitialCamera[3]);
  camera->SetViewUp(&this->InitialCamera[6]);
  camera->SetViewAngle(this->InitialCamera[9]);
  this->Renderer->ResetCameraClippingRange();
  this->NeedsRender = true;
}

void Viewer::UpdateText()
{
  std::ostringstream os;
  os << std::fixed << this->Mapper->GetTransmittanceMethodAsString() << " | "
     << this->Mapper->GetNumberOfCoefficients() << " coefficients | g " << std::setprecision(2)
     << this->Medium->GetScatteringAnisotropy() << " | density " << std::setprecision(2)
     << this->Medium->GetDensityScale() << " | jitter "
     << (this->Mapper->GetJitter() ? "on" : "off") << "\n";
  if (this->FrameNumber > 0)
  {
    os << std::setprecision(1) << this->LastFrameMs << " ms";
  }
  else
  {
    os << "-- ms";
  }
  os << " | map builds " << this->Mapper->GetMapBuildCount();
  this->Text->SetInput(os.str().c_str());
  this->Text->SetVisibility(this->ShowText ? 1 : 0);
  // About 65 characters across the window, 9 to 16 points.
  const int width = this->RenderWindow ? this->RenderWindow->GetSize()[0] : this->Size[0];
  this->Text->GetTextProperty()->SetFontSize(std::max(9, std::min(16, width / 42)));
}

void Viewer::RenderFrame()
{
  int width = 0, height = 0;
  glfwGetFramebufferSize(this->Window, &width, &height);
  if (width <= 0 || height <= 0)
  {
    // Minimised: nothing to draw into.
    this->RenderWindow->SetReadyForRendering(false);
    return;
  }
  glfwMakeContextCurrent(this->Window);
  const int* size = this->RenderWindow->GetSize();
  if (size[0] != width || size[1] != height)
  {
    this->RenderWindow->SetSize(width, height);
  }
  this->UpdateText();
  // VTK blits its image into the bound draw framebuffer: the window's.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);

  glFinish();
  const auto start = std::chrono::steady_clock::now();
  this->RenderWindow->SetReadyForRendering(true);
  this->RenderWindow->SetIsCurrent(true);
  this->RenderWindow->Render();
  glFinish();
  const auto stop = std::chrono::steady_clock::now();
  this->LastFrameMs = std::chrono::duration<double, std::milli>(stop - start).count();
  this->FrameTimes.push_back(this->LastFrameMs);
  ++this->FrameNumber;

  if (!this->PendingScreenshot.empty())
  {
    if (!this->WriteScreenshot(this->PendingScreenshot) && !this->Script.empty())
    {
      this->ExitCode = EXIT_FAILURE;
      this->Quit = true;
    }
    this->PendingScreenshot.clear();
  }
  glfwSwapBuffers(this->Window);
}

// Reads what the window shows (its back buffer before the swap).
bool Viewer::WriteScreenshot(const std::string& path)
{
  int width = 0, height = 0;
  glfwGetFramebufferSize(this->Window, &width, &height);
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  while (glGetError() != GL_NO_ERROR)
  {
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image->GetScalarPointer());
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
  {
    std::cerr << Program << ": cannot read the window's pixels (GL error 0x" << std::hex << error
              << std::dec << ")\n";
    return false;
  }
  const std::string directory = vtksys::SystemTools::GetFilenamePath(path);
  if (!directory.empty())
  {
    vtksys::SystemTools::MakeDirectory(directory);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << Program << ": cannot write the screenshot " << path << "\n";
    return false;
  }
  std::cout << "screenshot " << vtksys::SystemTools::CollapseFullPath(path) << " " << width << " x "
            << height << std::endl;
  return true;
}

void Viewer::LogFrame()
{
  std::cout << "frame " << this->FrameNumber << " render-ms " << std::fixed << std::setprecision(2)
            << this->LastFrameMs << std::defaultfloat << " map-builds "
            << this->Mapper->GetMapBuildCount() << " method "
            << this->Mapper->GetTransmittanceMethodAsString() << " coefficients "
            << this->Mapper->GetNumberOfCoefficients() << " command "
            << (this->CurrentCommand.empty() ? "-" : this->CurrentCommand) << std::endl;
}

//------------------------------------------------------------------------------
// Actions.
void Viewer::Orbit(double azimuth, double elevation)
{
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->Azimuth(azimuth);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
  this->Renderer->ResetCameraClippingRange();
  this->NeedsRender = true;
}

void Viewer::Pan(double dx, double dy)
{
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  int width = 1, height = 1;
  glfwGetWindowSize(this->Window, &width, &height);
  height = std::max(height, 1);
  double dop[3], up[3], right[3];
  camera->GetDirectionOfProjection(dop);
  camera->GetViewUp(up);
  vtkMath::Cross(dop, up, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(right, dop, up);
  vtkMath::Normalize(up);
  // World units per pixel at the focal point.
  const double perPixel = camera->GetParallelProjection()
    ? 2.0 * camera->GetParallelScale() / height
    : 2.0 * camera->GetDistance() *
      std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) / height;
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  for (int k = 0; k < 3; ++k)
  {
    // The scene follows the cursor: the camera moves the other way.
    const double motion = (-dx * right[k] + dy * up[k]) * perPixel;
    position[k] += motion;
    focal[k] += motion;
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  this->Renderer->ResetCameraClippingRange();
  this->NeedsRender = true;
}

void Viewer::Zoom(double factor)
{
  if (!(factor > 0.0))
  {
    return;
  }
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  if (camera->GetParallelProjection())
  {
    camera->SetParallelScale(camera->GetParallelScale() / factor);
  }
  else
  {
    camera->Dolly(factor);
  }
  this->Renderer->ResetCameraClippingRange();
  this->NeedsRender = true;
}

// Turns the sun about the focal point: azimuth about the camera's up axis
// (positive: towards the right of the screen for a sun in front), elevation
// about the camera's right axis (positive: up).
void Viewer::MoveLight(double azimuth, double elevation)
{
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  double dop[3], up[3], right[3];
  camera->GetDirectionOfProjection(dop);
  camera->GetViewUp(up);
  vtkMath::Cross(dop, up, right);
  vtkMath::Normalize(right);
  double position[3], focal[3], direction[3];
  this->Sun->GetPosition(position);
  this->Sun->GetFocalPoint(focal);
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = position[k] - focal[k];
  }
  vtkNew<vtkTransform> rotation;
  rotation->PostMultiply();
  rotation->RotateWXYZ(azimuth, up);
  rotation->RotateWXYZ(-elevation, right);
  double rotated[3];
  rotation->TransformVector(direction, rotated);
  for (int k = 0; k < 3; ++k)
  {
    position[k] = focal[k] + rotated[k];
  }
  this->Sun->SetPosition(position);
  this->NeedsRender = true;
}

// A drag by (dx, dy) pixels, y down (GLFW's cursor coordinates), scaled as
// vtkInteractorStyleTrackballCamera does.
void Viewer::Drag(DragMode mode, double dx, double dy)
{
  int width = 1, height = 1;
  glfwGetWindowSize(this->Window, &width, &height);
  width = std::max(width, 1);
  height = std::max(height, 1);
  switch (mode)
  {
    case DragMode::Orbit:
      this->Orbit(-200.0 * dx / width, 200.0 * dy / height);
      break;
    case DragMode::Pan:
      this->Pan(dx, dy);
      break;
    case DragMode::Zoom:
      this->Zoom(std::pow(1.1, -20.0 * dy / height));
      break;
    case DragMode::Light:
      this->MoveLight(200.0 * dx / width, -200.0 * dy / height);
      break;
    case DragMode::None:
      break;
  }
}

void Viewer::Key(int key)
{
  vtkTransmittanceVolumeMapper* m = this->Mapper;
  switch (key)
  {
    case '1':
    case '2':
    case '3':
    case '4':
    case '5':
    case '6':
      m->SetTransmittanceMethod(key - '1');
      break;
    case '+':
    case '=':
      m->SetNumberOfCoefficients(m->GetNumberOfCoefficients() + 1);
      break;
    case '-':
    case '_':
      m->SetNumberOfCoefficients(m->GetNumberOfCoefficients() - 1);
      break;
    case 'a':
      this->Medium->SetScatteringAnisotropy(
        std::min(0.9, std::round(10.0 * this->Medium->GetScatteringAnisotropy() + 1.0) / 10.0));
      break;
    case 'z':
      this->Medium->SetScatteringAnisotropy(
        std::max(-0.9, std::round(10.0 * this->Medium->GetScatteringAnisotropy() - 1.0) / 10.0));
      break;
    case 'd':
      this->Medium->SetDensityScale(this->Medium->GetDensityScale() * 1.25);
      break;
    case 'c':
      this->Medium->SetDensityScale(this->Medium->GetDensityScale() / 1.25);
      break;
    case 'j':
      m->SetJitter(!m->GetJitter());
      break;
    case 'h':
      this->ShowText = !this->ShowText;
      break;
    case 'r':
      this->ResetCamera();
      break;
    case 's':
    {
      std::ostringstream name;
      name << "tyndall-viewer-" << std::setw(3) << std::setfill('0') << ++this->ScreenshotCounter
           << ".png";
      this->PendingScreenshot = name.str();
      break;
    }
    case 'q':
    case 27:
      this->Quit = true;
      break;
    default:
      return;
  }
  this->NeedsRender = true;
}

void Viewer::Execute(const Command& c)
{
  // Arguments were validated when the script was read.
  auto number = [&c](size_t i) { return std::strtod(c.Args[i].c_str(), nullptr); };
  if (c.Verb == "orbit")
  {
    this->Orbit(number(0), number(1));
  }
  else if (c.Verb == "pan")
  {
    this->Pan(number(0), number(1));
  }
  else if (c.Verb == "zoom")
  {
    this->Zoom(number(0));
  }
  else if (c.Verb == "light")
  {
    this->MoveLight(number(0), number(1));
  }
  else if (c.Verb == "drag")
  {
    DragMode mode = DragMode::None;
    ParseDragButton(c.Args[0], mode);
    this->Drag(mode, number(1), number(2));
  }
  else if (c.Verb == "key")
  {
    int key = 0;
    ParseKey(c.Args[0], key);
    this->Key(key);
  }
  else if (c.Verb == "resize")
  {
    glfwSetWindowSize(this->Window, std::atoi(c.Args[0].c_str()), std::atoi(c.Args[1].c_str()));
  }
  else if (c.Verb == "hud")
  {
    this->ShowText = c.Args[0] == "on";
  }
  else if (c.Verb == "screenshot")
  {
    this->PendingScreenshot = c.Args[0];
  }
  else if (c.Verb == "quit")
  {
    this->Quit = true;
  }
  // "frames N" is counted by Run().
  this->NeedsRender = true;
}

//------------------------------------------------------------------------------
// GLFW callbacks.
void Viewer::OnCursor(GLFWwindow* w, double x, double y)
{
  Viewer* self = From(w);
  const double dx = x - self->LastCursor[0];
  const double dy = y - self->LastCursor[1];
  self->LastCursor[0] = x;
  self->LastCursor[1] = y;
  const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
    glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  const bool ctrl = glfwGetKey(w, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
    glfwGetKey(w, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  const bool lightKey = glfwGetKey(w, GLFW_KEY_L) == GLFW_PRESS;
  for (int button : { ButtonLeft, ButtonMiddle, ButtonRight })
  {
    if (self->ButtonDown[button])
    {
      self->Drag(DragModeFor(button, shift, ctrl, lightKey), dx, dy);
      return;
    }
  }
}

void Viewer::OnButton(GLFWwindow* w, int button, int action, int)
{
  Viewer* self = From(w);
  int index = -1;
  switch (button)
  {
    case GLFW_MOUSE_BUTTON_LEFT:
      index = ButtonLeft;
      break;
    case GLFW_MOUSE_BUTTON_MIDDLE:
      index = ButtonMiddle;
      break;
    case GLFW_MOUSE_BUTTON_RIGHT:
      index = ButtonRight;
      break;
    default:
      return;
  }
  self->ButtonDown[index] = action == GLFW_PRESS;
  glfwGetCursorPos(w, &self->LastCursor[0], &self->LastCursor[1]);
}

void Viewer::OnScroll(GLFWwindow* w, double, double dy)
{
  From(w)->Zoom(std::pow(1.1, dy));
}

void Viewer::OnKey(GLFWwindow* w, int key, int, int action, int)
{
  if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS)
  {
    From(w)->Key(27);
  }
}

void Viewer::OnChar(GLFWwindow* w, unsigned int codepoint)
{
  if (codepoint > ' ' && codepoint < 127)
  {
    From(w)->Key(static_cast<int>(codepoint));
  }
}

void Viewer::OnFramebufferSize(GLFWwindow* w, int, int)
{
  From(w)->NeedsRender = true;
}

void Viewer::OnRefresh(GLFWwindow* w)
{
  From(w)->NeedsRender = true;
}

//------------------------------------------------------------------------------
int Viewer::Run()
{
  if (!this->LoadScene() || !this->OpenWindow())
  {
    return EXIT_FAILURE;
  }
  this->SetUpVTK();

  size_t next = 0;
  int framesLeft = 0;
  bool announced = this->Script.empty();
  while (!this->Quit && !glfwWindowShouldClose(this->Window))
  {
    bool scripted = false;
    if (framesLeft > 0)
    {
      --framesLeft;
      scripted = true;
    }
    else if (next < this->Script.size())
    {
      const Command& c = this->Script[next++];
      this->CurrentCommand = c.Text;
      if (c.Verb == "frames")
      {
        framesLeft = std::atoi(c.Args[0].c_str()) - 1;
      }
      this->Execute(c);
      scripted = true;
    }
    else if (!announced)
    {
      announced = true;
      std::cerr << Program << ": script finished; the window stays open (q quits)\n";
    }

    if (scripted || this->NeedsRender)
    {
      glfwPollEvents();
    }
    else
    {
      glfwWaitEvents();
    }
    if (this->Quit)
    {
      break;
    }
    if (this->NeedsRender || scripted)
    {
      this->NeedsRender = false;
      this->RenderFrame();
      if (scripted || this->Verbose)
      {
        this->LogFrame();
      }
    }
    if (framesLeft == 0)
    {
      this->CurrentCommand.clear();
    }
  }

  // Timings without the first frame, which compiles shaders and builds maps.
  if (this->FrameTimes.size() > 1)
  {
    std::vector<double> t(this->FrameTimes.begin() + 1, this->FrameTimes.end());
    std::sort(t.begin(), t.end());
    double sum = 0.0;
    for (double v : t)
    {
      sum += v;
    }
    std::cout << "summary frames " << this->FrameTimes.size() << " first-frame-ms " << std::fixed
              << std::setprecision(1) << this->FrameTimes.front() << " later-frames-ms mean "
              << sum / t.size() << " median " << t[t.size() / 2] << " min " << t.front() << " max "
              << t.back() << std::defaultfloat << " map-builds " << this->Mapper->GetMapBuildCount()
              << std::endl;
  }
  return this->ExitCode;
}
}

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  Viewer viewer;
  std::string scriptFile;
  std::vector<std::string> events;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help")
    {
      Usage(std::cout);
      return EXIT_SUCCESS;
    }
    else if ((arg == "-i" || arg == "--input") && i + 1 < argc)
    {
      viewer.InputPath = argv[++i];
    }
    else if ((arg == "-g" || arg == "--grid") && i + 1 < argc)
    {
      viewer.GridName = argv[++i];
    }
    else if ((arg == "-r" || arg == "--resolution") && i + 1 < argc)
    {
      if (!ParseInt(argv[++i], 8, 512, viewer.Resolution))
      {
        std::cerr << Program << ": --resolution needs an integer in 8..512\n";
        return 2;
      }
    }
    else if ((arg == "-s" || arg == "--size") && i + 2 < argc)
    {
      if (!ParseInt(argv[i + 1], 16, 8192, viewer.Size[0]) ||
        !ParseInt(argv[i + 2], 16, 8192, viewer.Size[1]))
      {
        std::cerr << Program << ": --size needs two integers in 16..8192\n";
        return 2;
      }
      i += 2;
    }
    else if (arg == "--script" && i + 1 < argc)
    {
      scriptFile = argv[++i];
    }
    else if (arg == "--events" && i + 1 < argc)
    {
      events.emplace_back(argv[++i]);
    }
    else if (arg == "-v" || arg == "--verbose")
    {
      viewer.Verbose = true;
    }
    else if (!arg.empty() && arg[0] != '-' && viewer.InputPath.empty())
    {
      viewer.InputPath = arg;
    }
    else
    {
      std::cerr << Program << ": unknown or incomplete option '" << arg << "'\n";
      Usage(std::cerr);
      return 2;
    }
  }

  std::string error;
  if (!scriptFile.empty())
  {
    std::ifstream in(scriptFile);
    if (!in)
    {
      std::cerr << Program << ": cannot read the script " << scriptFile << "\n";
      return 2;
    }
    std::stringstream text;
    text << in.rdbuf();
    if (!ParseScript(text.str(), scriptFile, false, viewer.Script, error))
    {
      std::cerr << Program << ": " << error << "\n";
      return 2;
    }
  }
  for (const auto& e : events)
  {
    if (!ParseScript(e, "--events", true, viewer.Script, error))
    {
      std::cerr << Program << ": " << error << "\n";
      return 2;
    }
  }
  return viewer.Run();
}
