// tyndall-viewer: an interactive viewer for vtkTransmittanceVolumeMapper.
//
// A GLFW window (OpenGL 3.2+ core profile, forward compatible) with GLEW,
// and VTK embedded through vtkGenericOpenGLRenderWindow on the window's own
// context. The scene is tyndall-render's: the options are vtkTyndallOptions'
// one table (with the keys that change them) and vtkTyndallSceneBuilder
// builds the scene, so a volume looks the same in both programs. On top:
// mouse navigation, the keys, and an on-screen line with the method, the
// coefficient count, the frame time and the number of transmittance-map
// builds. Scripts (--script, --events) drive the same code paths as the
// mouse and keys, one command per frame, for tests. See
// Documentation/viewer.md.

// GLEW before GLFW (and before any VTK header, which include vtk_glew.h, the
// system GLEW on Debian): GLFW then includes no GL header of its own.
#include <GL/glew.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkTyndallFrameSequence.h"
#include "vtkTyndallOptions.h"
#include "vtkTyndallSceneBuilder.h"
#include "vtkVolumeFileReader.h"
#include "vtksys/SystemTools.hxx"

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
#include <thread>
#include <unistd.h>
#include <vector>

namespace
{
const char* const Program = "tyndall-viewer";

std::string Description()
{
  std::string text =
    "Usage: tyndall-viewer [options] [VOLUME]\n"
    "Interactive viewer of vtkTransmittanceVolumeMapper: single scattering with\n"
    "transmittance-map shadows, the scene of tyndall-render (the same options,\n"
    "see Documentation/cli.md). Without VOLUME it shows the built-in cosine-noise\n"
    "cloud lit by a low sun. Needs an X display (use xvfb-run without one).\n\n"
    "Mouse: left-drag orbit, middle-drag or shift+left-drag pan, wheel or\n"
    "right-drag zoom, ctrl+left-drag or L+left-drag move the key light.\n"
    "Script commands (--script, --events): orbit AZ EL, pan DX DY, zoom F,\n"
    "light AZ EL, drag BUTTON[+shift|+ctrl|+l] DX DY, key K (a character,\n"
    "plus, minus, space, left, right or esc), frames N, resize W H,\n"
    "hud on|off, screenshot PATH, report, quit.\n"
    "A time series (--sequence FIRST LAST): Space plays and pauses, the arrow\n"
    "keys step.\n\n"
    "Volumes it reads:\n";
  return text + vtkVolumeFileReader::GetFormatsDescription();
}

bool ParseInt(const std::string& text, int lo, int hi, int& value)
{
  return vtkTyndallOptions::ParseInteger(text, lo, hi, value);
}

bool ParseDouble(const std::string& text, double& value)
{
  return vtkTyndallOptions::ParseNumber(text, value);
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
  else if (lower == "space")
  {
    key = ' ';
  }
  else if (lower == "left")
  {
    key = vtkTyndallOptions::KEY_LEFT;
  }
  else if (lower == "right")
  {
    key = vtkTyndallOptions::KEY_RIGHT;
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
      : "needs one key: a character, plus, minus, space, left, right or esc";
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
  if (c.Verb == "quit" || c.Verb == "report")
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
// The viewer.
class Viewer
{
public:
  Viewer() = default;
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Options (the table's; the script is parsed from them).
  vtkNew<vtkTyndallOptions> Options;
  std::vector<Command> Script;

  int Run();

private:
  bool LoadScene();
  bool OpenWindow();
  void SetUpVTK();
  void ResetCamera();
  // Sampled detail: a still view keeps refining up to --detail-frames while
  // its average grows (a restart that no input caused stops it: something
  // the viewer does not see changes every frame).
  void UpdateRefinement(bool requested)
  {
    const int averaged = this->Mapper->GetAccumulatedFrames();
    const bool grew = requested || averaged > this->LastAveraged;
    this->Refine = averaged > 0 && grew &&
      averaged < static_cast<int>(this->Options->GetNumber("detail-frames"));
    this->LastAveraged = averaged;
    // Path tracing: the map-based frame after a move (0 samples), then the
    // paths up to --path-trace.
    const int samples = this->Mapper->GetLastPathTraceSamples();
    const bool traced = requested || samples > this->LastPathSamples;
    this->Refine = this->Refine ||
      (this->Mapper->GetPathTracing() && traced &&
        samples < this->Mapper->GetPathTraceSamplesPerPixel());
    this->LastPathSamples = samples;
  }

  // A time series (--sequence): the frame shown, playback.
  bool SetUpSequence();
  void StepFrame(int delta);
  void PlayOn(bool scripted);
  double UntilNextPlayFrame() const;

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
  void Report();
  void SetInteracting(bool interacting);

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

  vtkNew<vtkTyndallSceneBuilder> Builder;
  vtkTransmittanceVolumeMapper* Mapper = nullptr; // the builder's
  // Sampled detail: whether the next frame only refines the still view, and
  // the frames the average held after the last frame.
  bool Refine = false;
  int LastPathSamples = 0;
  int LastAveraged = 0;
  vtkParticipatingMediumProperty* Medium = nullptr; // the builder's
  vtkLight* Sun = nullptr;                          // the builder's key light
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkTextActor> Text;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> RenderWindow;
  double InitialCamera[10] = {};

  vtkNew<vtkTyndallFrameSequence> Sequence;
  bool Sequenced = false;
  int ShownFrame = 0;
  bool Playing = false;
  std::chrono::steady_clock::time_point NextPlayFrame;

  bool Quit = false;
  bool NeedsRender = true;
  bool ShowText = true;
  int FrameNumber = 0;
  double LastFrameMs = 0.0;
  std::vector<double> FrameTimes;
  std::vector<double> DragFrameTimes; // frames drawn while interacting
  bool Interacting = false;
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
  // The scene of tyndall-render, from the same options.
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(this->Builder);
  this->Builder->SetOptions(this->Options);
  if (!this->SetUpSequence())
  {
    return false;
  }
  if (!this->Builder->Build(this->Renderer))
  {
    for (const std::string& message : errors->GetMessages())
    {
      std::cerr << Program << ": " << message << "\n";
    }
    return false;
  }
  if (*this->Builder->GetReadNotes())
  {
    std::cerr << Program << ": note: " << this->Builder->GetReadNotes() << "\n";
  }
  this->Mapper = this->Builder->GetMapper();
  this->Medium = this->Builder->GetProperty();
  this->Sun = this->Builder->GetKeyLight();
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->GetPosition(&this->InitialCamera[0]);
  camera->GetFocalPoint(&this->InitialCamera[3]);
  camera->GetViewUp(&this->InitialCamera[6]);
  this->InitialCamera[9] = camera->GetViewAngle();
  return true;
}

// --sequence: frame FIRST is the one Build() reads.
bool Viewer::SetUpSequence()
{
  this->Sequenced = this->Options->IsSet("sequence");
  if (!this->Sequenced)
  {
    return true;
  }
  if (!this->Sequence->SetUp(this->Options->GetInput(), std::string(),
        static_cast<int>(this->Options->GetNumber("sequence", 0)),
        static_cast<int>(this->Options->GetNumber("sequence", 1))))
  {
    std::cerr << Program << ": " << this->Sequence->GetErrorMessage() << "\n";
    return false;
  }
  this->ShownFrame = this->Sequence->GetFirst();
  this->Builder->SetFrame(this->Sequence->GetInputPath(this->ShownFrame),
    this->Sequence->GetInputFrame(this->ShownFrame));
  return true;
}

// The sequence's frame `delta` steps away (looping), read into the scene; a
// frame that cannot be read is skipped with a warning, and when none can,
// the frame shown stays and playback pauses.
void Viewer::StepFrame(int delta)
{
  if (!this->Sequenced)
  {
    std::cerr << Program << ": no sequence to step through (--sequence FIRST LAST)\n";
    return;
  }
  const int first = this->Sequence->GetFirst();
  const int count = this->Sequence->GetLast() - first + 1;
  // The builder's errors while reading (the observer removed again: one
  // left per step would pile up while playing).
  vtkNew<vtkTyndallErrorObserver> errors;
  const unsigned long tag = this->Builder->AddObserver(vtkCommand::ErrorEvent, errors);
  int frame = this->ShownFrame;
  for (int tries = 0; tries < count; ++tries)
  {
    frame = first + ((frame - first + delta) % count + count) % count;
    errors->Clear();
    const std::string path = this->Sequence->GetInputPath(frame);
    if (this->Builder->LoadFrame(path, this->Sequence->GetInputFrame(frame)))
    {
      this->Builder->RemoveObserver(tag);
      this->ShownFrame = frame;
      this->Renderer->ResetCameraClippingRange();
      this->NeedsRender = true;
      return;
    }
    std::cerr << Program << ": warning: skipped frame " << frame << " (" << path
              << "): " << (errors->HasErrors() ? errors->GetMessages().front() : "cannot be read")
              << "\n";
    delta = delta < 0 ? -1 : 1;
  }
  // None could be read: the frame shown again (the reader may hold a failed
  // one), and no more playing.
  this->Builder->RemoveObserver(tag);
  this->Playing = false;
  std::cerr << Program << ": warning: no other frame can be read; frame " << this->ShownFrame
            << " stays" << (count > 1 ? " (playback paused)" : "") << "\n";
  if (!this->Builder->LoadFrame(this->Sequence->GetInputPath(this->ShownFrame),
        this->Sequence->GetInputFrame(this->ShownFrame)))
  {
    std::cerr << Program << ": frame " << this->ShownFrame << " cannot be read again either\n";
  }
  this->NeedsRender = true;
}

// While playing: the next frame when it is due (--play-rate); a script's
// frame waits for it (each frame of a script while playing is the next one).
void Viewer::PlayOn(bool scripted)
{
  const auto now = std::chrono::steady_clock::now();
  if (!scripted && now < this->NextPlayFrame)
  {
    return; // not yet: the loop waits for events until then
  }
  std::this_thread::sleep_until(this->NextPlayFrame);
  this->NextPlayFrame = std::chrono::steady_clock::now() +
    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / this->Options->GetNumber("play-rate")));
  this->StepFrame(1);
}

// Seconds until the next frame of a playing sequence is due (0: now).
double Viewer::UntilNextPlayFrame() const
{
  const std::chrono::duration<double> left = this->NextPlayFrame - std::chrono::steady_clock::now();
  return std::max(0.0, left.count());
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
  const std::string input = this->Options->GetInput();
  const std::string title = std::string("Tyndall viewer - ") +
    (input.empty() ? std::string("cosine-noise cloud")
                   : vtksys::SystemTools::GetFilenameName(input));
  this->Window = glfwCreateWindow(static_cast<int>(this->Options->GetNumber("size", 0)),
    static_cast<int>(this->Options->GetNumber("size", 1)), title.c_str(), nullptr, nullptr);
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
  // The scene (volume, lights, camera, background) is the builder's.
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
     << this->Mapper->GetNumberOfCoefficients() << " coefficients | ";
  if (this->Options->GetFlag("vtk-property"))
  {
    os << "VTK's vtkVolumeProperty";
  }
  else
  {
    os << "g " << std::setprecision(2) << this->Medium->GetScatteringAnisotropy() << " | density "
       << std::setprecision(2) << this->Medium->GetDensityScale() << " | octaves "
       << this->Medium->GetScatteringOctaves();
  }
  os << " | jitter " << (this->Mapper->GetJitter() ? "on" : "off") << "\n";
  if (this->FrameNumber > 0)
  {
    os << std::setprecision(1) << this->LastFrameMs << " ms";
  }
  else
  {
    os << "-- ms";
  }
  os << " | map builds " << this->Mapper->GetMapBuildCount();
  if (this->Sequenced)
  {
    os << " | frame " << this->ShownFrame << " of " << this->Sequence->GetFirst() << ".."
       << this->Sequence->GetLast() << (this->Playing ? " playing" : "");
  }
  if (this->Mapper->GetLastImageReduction() > 1)
  {
    os << " | 1/" << this->Mapper->GetLastImageReduction() << " size";
  }
  if (this->Mapper->GetPathTracing())
  {
    os << " | paths " << this->Mapper->GetLastPathTraceSamples() << " / "
       << this->Mapper->GetPathTraceSamplesPerPixel() << " spp";
  }
  this->Text->SetInput(os.str().c_str());
  this->Text->SetVisibility(this->ShowText ? 1 : 0);
  // About 65 characters across the window, 9 to 16 points.
  const int width = this->RenderWindow ? this->RenderWindow->GetSize()[0]
                                       : static_cast<int>(this->Options->GetNumber("size", 0));
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
  if (this->Interacting)
  {
    this->DragFrameTimes.push_back(this->LastFrameMs);
  }
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
            << this->Mapper->GetNumberOfCoefficients() << " reduction "
            << this->Mapper->GetLastImageReduction() << " sequence-frame "
            << (this->Sequenced ? std::to_string(this->ShownFrame) : std::string("-"))
            << " path-samples " << this->Mapper->GetLastPathTraceSamples() << " command "
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

// A key: the options table says what it changes (vtkTyndallOptions::ApplyKey).
void Viewer::Key(int key)
{
  // A plain vtkVolumeProperty (--vtk-property) has none of the medium's
  // settings: their keys would change nothing drawn (and rebuild the maps).
  const char* option = this->Options->GetKeyOption(key);
  if (option && this->Options->GetFlag("vtk-property") && vtkTyndallOptions::IsMediumOption(option))
  {
    std::cerr << Program << ": key '" << static_cast<char>(key) << "' sets the medium's --"
              << option << ", which --vtk-property (k) does not draw\n";
    return;
  }
  const char* bound = this->Options->ApplyKey(key);
  if (!bound)
  {
    return;
  }
  const std::string name = bound;
  if (name == "hud")
  {
    this->ShowText = !this->ShowText;
  }
  else if (name == "reset")
  {
    this->ResetCamera();
  }
  else if (name == "screenshot")
  {
    std::ostringstream file;
    file << "tyndall-viewer-" << std::setw(3) << std::setfill('0') << ++this->ScreenshotCounter
         << ".png";
    this->PendingScreenshot = file.str();
  }
  else if (name == "quit")
  {
    this->Quit = true;
  }
  else if (name == "play")
  {
    this->Playing = this->Sequenced && !this->Playing;
    this->NextPlayFrame = std::chrono::steady_clock::now();
    if (!this->Sequenced)
    {
      std::cerr << Program << ": no sequence to play (--sequence FIRST LAST)\n";
    }
  }
  else if (name == "next-frame" || name == "previous-frame")
  {
    this->Playing = false;
    this->StepFrame(name == "next-frame" ? 1 : -1);
  }
  else if (name == "vtk-property")
  {
    if (this->Options->GetFlag("vtk-property"))
    {
      std::cerr << Program << ": the volumes drawn with a plain vtkVolumeProperty (VTK's "
                << "meaning): the medium's settings do not apply until k again\n";
    }
    this->Builder->ApplyOptions();
  }
  else if (name == "exposure" || name == "path-denoise")
  {
    this->Builder->ApplyDisplayOptions(); // keeps the path-traced picture's samples
  }
  else
  {
    this->Builder->ApplyOptions();
  }
  this->NeedsRender = true;
}

// One stdout line on the process and its GL context, for soak runs:
// resident memory and the live OpenGL objects among the first 16384 names.
void Viewer::Report()
{
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r"))
  {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
    {
      resident = 0;
    }
    std::fclose(f);
  }
  glfwMakeContextCurrent(this->Window);
  int live[5] = { 0, 0, 0, 0, 0 };
  for (GLuint id = 1; id <= 16384; ++id)
  {
    live[0] += glIsTexture(id);
    live[1] += glIsBuffer(id);
    live[2] += glIsFramebuffer(id);
    live[3] += glIsProgram(id);
    live[4] += glIsVertexArray(id);
  }
  std::cout << "report frame " << this->FrameNumber << " rss-mib " << std::fixed
            << std::setprecision(1) << resident * (sysconf(_SC_PAGESIZE) / 1048576.0)
            << std::defaultfloat << " textures " << live[0] << " buffers " << live[1]
            << " framebuffers " << live[2] << " programs " << live[3] << " vertex-arrays "
            << live[4] << std::endl;
}

// VTK's interactive/still protocol: while a button is down (or a script
// drags), the render window asks for --interactive-rate frames per second
// and the mapper reduces the image to meet it; the still rate gives the
// full-size frame.
void Viewer::SetInteracting(bool interacting)
{
  const double rate = this->Options->GetNumber("interactive-rate");
  this->Mapper->SetInteractiveAdjustment(rate > 0.0);
  this->Interacting = interacting && rate > 0.0;
  this->RenderWindow->SetDesiredUpdateRate(this->Interacting ? rate : 0.0001);
}

void Viewer::Execute(const Command& c)
{
  this->SetInteracting(c.Verb == "drag");
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
  else if (c.Verb == "report")
  {
    this->Report();
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
  // A release ends the interaction: the next frame is the full-size one.
  self->SetInteracting(self->ButtonDown[0] || self->ButtonDown[1] || self->ButtonDown[2]);
  self->NeedsRender = true;
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
  else if (key == GLFW_KEY_SPACE && action == GLFW_PRESS)
  {
    From(w)->Key(' ');
  }
  else if ((key == GLFW_KEY_LEFT || key == GLFW_KEY_RIGHT) && action != GLFW_RELEASE)
  {
    From(w)->Key(key == GLFW_KEY_LEFT ? vtkTyndallOptions::KEY_LEFT : vtkTyndallOptions::KEY_RIGHT);
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
    // Playing from the frame before on: this frame shows the next one.
    const bool wasPlaying = this->Playing;
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

    if (scripted || this->NeedsRender || this->Refine)
    {
      glfwPollEvents();
    }
    else if (this->Playing)
    {
      // The keys and the mouse answer while it plays: events until the
      // next frame is due.
      glfwWaitEventsTimeout(this->UntilNextPlayFrame());
    }
    else
    {
      glfwWaitEvents();
    }
    if (this->Quit)
    {
      break;
    }
    if (wasPlaying && this->Playing)
    {
      this->PlayOn(scripted);
    }
    if (this->NeedsRender || scripted || this->Refine)
    {
      const bool requested = this->NeedsRender || scripted; // by input or the script
      this->NeedsRender = false;
      this->Refine = false;
      this->RenderFrame();
      this->UpdateRefinement(requested);
      if (scripted || this->Options->GetFlag("verbose"))
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
  if (!this->DragFrameTimes.empty())
  {
    double sum = 0.0;
    for (double v : this->DragFrameTimes)
    {
      sum += v;
    }
    const double mean = sum / this->DragFrameTimes.size();
    std::cout << "summary drag-frames " << this->DragFrameTimes.size() << " mean-ms " << std::fixed
              << std::setprecision(1) << mean << " fps " << 1000.0 / mean << std::defaultfloat
              << std::endl;
  }
  return this->ExitCode;
}
}

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  Viewer viewer;
  vtkTyndallOptions* options = viewer.Options;
  options->SetProgram(vtkTyndallOptions::VIEWER);
  if (!options->Parse(argc, argv))
  {
    std::cerr << Program << ": " << options->GetErrorMessage() << "\n";
    return 2;
  }
  if (options->GetHelpRequested())
  {
    std::cout << options->GetHelp(Description().c_str());
    return EXIT_SUCCESS;
  }
  const std::string scriptFile = options->GetText("script");
  std::vector<std::string> events;
  if (options->IsSet("events"))
  {
    events.emplace_back(options->GetText("events"));
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
