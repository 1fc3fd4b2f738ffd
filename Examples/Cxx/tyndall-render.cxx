// tyndall-render: Tyndall's main job, a command-line renderer.
//
// A thin front-end over the programs' kit (Tyndall::Application): the
// options are vtkTyndallOptions' one table (shared with tyndall-viewer and
// the Python examples), the scene is vtkTyndallSceneBuilder's (the built-in
// cosine-noise cloud, or a volume file with its transfer function, camera
// and lights). This file only renders it off screen and writes the outputs:
// an 8-bit PNG of the frame buffer and, with --exr, a linear float OpenEXR
// image. The PNG's path is printed on stdout; progress and timings go to
// stderr. See Documentation/cli.md.
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFramebufferPass.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkParticipatingMediumProperty.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkRenderPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTransferFunctionFileReader.h"
#include "vtkTransmittanceVolumeMapper.h"
#include "vtkTyndallDisplay.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkTyndallFrameSequence.h"
#include "vtkTyndallOptions.h"
#include "vtkTyndallSceneBuilder.h"
#include "vtkTyndallToneMapping.h"
#include "vtkVolumeFileReader.h"
#include "vtkWindowToImageFilter.h"
#include "vtksys/SystemTools.hxx"

#ifdef TYNDALL_HAVE_THEORA
#include "vtkOggTheoraWriter.h"
#endif

#ifdef TYNDALL_HAVE_OPENEXR
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const char* const Program = "tyndall-render";

// Exit codes (documented in --help and Documentation/cli.md).
constexpr int ExitUsage = 2;   // bad command line
constexpr int ExitFailure = 1; // a file could not be read, rendered or written

std::string Description()
{
  std::string text =
    "Usage: tyndall-render [options] [INPUT]\n"
    "\n"
    "Renders a participating medium with physically based single scattering\n"
    "(vtkTransmittanceVolumeMapper) to an 8-bit PNG and prints the PNG's path on\n"
    "stdout. Progress and timings go to stderr. Needs an X display (Debian's VTK\n"
    "renders through GLX): run under xvfb-run -a -s \"-screen 0 1280x1024x24\" on\n"
    "machines without one. See Documentation/cli.md.\n"
    "\n"
    "Without INPUT: the built-in default scene, a procedural cloud (a 128^3\n"
    "cosine-noise shape times cosine-noise detail evaluated in the shader, never\n"
    "voxelised; --no-detail: the shape alone) lit by a low sun (single scattering,\n"
    "adaptive ETM shadows) under a sky gradient.\n"
    "With INPUT, a volume file or a DICOM directory:\n";
  text += vtkVolumeFileReader::GetFormatsDescription();
  text += "Data inputs get a camera fitted to the data, a white directional key light\n"
          "coming from the upper right in front of the data (as seen by the camera),\n"
          "ambient 0.25, a black background and the preset guessed from the data.\n"
          "Defaults in brackets: default scene / data.\n";
  return text;
}

std::string Footer()
{
  std::string text = "Transfer-function files (--transfer-function): ";
  text += vtkTransferFunctionFileReader::GetFormatDescription();
  text += "\nExit status: 0 on success, 2 for a bad command line, 1 when an input cannot be\n"
          "read or the image cannot be rendered or written.\n";
  return text;
}

// Progress on stderr: "label: 0% 20% ... 100%".
struct Progress
{
  vtkTyndallSceneBuilder* Builder = nullptr;
  int Next = 0;
  bool Quiet = false;
  void Report(double fraction)
  {
    const int percent = static_cast<int>(std::floor(fraction * 100.0 + 1e-9));
    while (!this->Quiet && this->Next <= 100 && percent >= this->Next)
    {
      std::cerr << (this->Next == 0 ? std::string(this->Builder->GetProgressLabel()) + ": "
                                    : std::string(" "))
                << this->Next << "%" << (this->Next == 100 ? "\n" : "") << std::flush;
      this->Next += 20;
    }
  }
  static void Callback(vtkObject*, unsigned long, void* client, void* call)
  {
    static_cast<Progress*>(client)->Report(*static_cast<double*>(call));
  }
};

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

// "loaded FILE: 64 x 64 x 93 short, scalars 'x' in [lo, hi], bounds [...] in T s".
void LogLoaded(const std::string& input, vtkImageData* image, double seconds)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  scalars = scalars ? scalars : image->GetCellData()->GetScalars();
  double range[2], bounds[6];
  scalars->GetRange(range);
  image->GetBounds(bounds);
  std::cerr << "loaded " << input << ": " << dims[0] << " x " << dims[1] << " x " << dims[2] << " "
            << scalars->GetDataTypeAsString() << ", scalars '"
            << (scalars->GetName() ? scalars->GetName() : "") << "' in [" << range[0] << ", "
            << range[1] << "], bounds [" << bounds[0] << ", " << bounds[1] << "] x [" << bounds[2]
            << ", " << bounds[3] << "] x [" << bounds[4] << ", " << bounds[5] << "] in " << seconds
            << " s\n";
}

int Fail(const std::string& message, int code = ExitFailure)
{
  std::cerr << Program << ": " << message << "\n";
  return code;
}

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
        std::copy(src + 4 * x, src + 4 * x + 3, dst + 3 * x);
      }
    }
    Imf::Header header(width, height);
    for (const char* channel : { "R", "G", "B" })
    {
      header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    }
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer frame;
    const size_t xStride = 3 * sizeof(float), yStride = xStride * width;
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

// The float colour texture of the frame just rendered, as an EXR.
int WriteFloatFrame(
  const std::string& path, vtkRenderWindow* window, vtkFramebufferPass* pass, bool verbose)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->MakeCurrent();
  vtkTextureObject* texture = pass->GetColorTexture();
  const int width = static_cast<int>(texture->GetWidth());
  const int height = static_cast<int>(texture->GetHeight());
  std::vector<float> rgba;
  bool ok = texture->GetComponents() == 4 && texture->GetVTKDataType() == VTK_FLOAT &&
    width == window->GetSize()[0] && height == window->GetSize()[1];
  vtkPixelBufferObject* pbo = ok ? texture->Download() : nullptr;
  const float* data = pbo ? static_cast<const float*>(pbo->MapPackedBuffer()) : nullptr;
  if (data)
  {
    rgba.assign(data, data + static_cast<size_t>(width) * height * 4);
    pbo->UnmapPackedBuffer();
  }
  if (pbo)
  {
    pbo->Delete();
  }
  if (!data)
  {
    return Fail("cannot read the float frame buffer back (" + std::to_string(width) + " x " +
      std::to_string(height) + ", " + std::to_string(texture->GetComponents()) + " components)");
  }
  float maximum = 0.0f;
  for (size_t k = 0; k < rgba.size(); ++k)
  {
    maximum = k % 4 != 3 ? std::max(maximum, rgba[k]) : maximum;
  }
  std::string error;
  if (!WriteExr(path, width, height, rgba, error))
  {
    return Fail(error);
  }
  timer->StopTimer();
  if (verbose)
  {
    std::cerr << "exr: " << path << " (linear float RGB, maximum " << maximum << ") in "
              << timer->GetElapsedTime() << " s\n";
  }
  return EXIT_SUCCESS;
}
#endif

// Whether the options ask for a display transform (the mapper's Exposure,
// ToneCurve, EncodeSRGB) other than the identity.
bool DisplayTransformed(vtkTyndallOptions* options)
{
  return !vtkTyndallToneMapping::IsIdentity(
    options->GetNumber("exposure"), options->GetChoice("tone-curve"), options->GetFlag("srgb"));
}

// Path tracing (--path-trace): renders still frames until the picture has
// its samples per pixel (the first render drew the map-based frame); stops
// early when a render fails or the picture stops growing (the tracer
// refused the scene: its warning says why, and the map-based frame is the
// picture). False when a render failed.
bool RefinePaths(vtkRenderWindow* window, vtkTransmittanceVolumeMapper* mapper,
  vtkTyndallErrorObserver* errors, bool verbose)
{
  if (!mapper->GetPathTracing())
  {
    return true;
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const int target = mapper->GetPathTraceSamplesPerPixel();
  int renders = 0;
  for (int last = -1; mapper->GetLastPathTraceSamples() < target && !errors->HasErrors(); ++renders)
  {
    const int samples = mapper->GetLastPathTraceSamples();
    if (renders > 0 && samples <= last)
    {
      break; // not path traced: the map-based frame stays
    }
    last = samples;
    window->Render();
  }
  vtkOpenGLRenderWindow::SafeDownCast(window)->WaitForCompletion();
  timer->StopTimer();
  if (verbose && mapper->GetLastPathTraceSamples() > 0)
  {
    std::cerr << "path tracing: " << mapper->GetLastPathTraceSamples() << " samples per pixel in "
              << renders << " frames, " << timer->GetElapsedTime() << " s\n";
  }
  return !errors->HasErrors();
}

// Renders the first frame (and --frames - 1 cached ones); reports errors.
int RenderFrames(vtkRenderWindow* window, vtkTyndallSceneBuilder* builder,
  vtkTyndallErrorObserver* errors, int frames, bool verbose)
{
  vtkTransmittanceVolumeMapper* mapper = builder->GetMapper();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  vtkOpenGLRenderWindow::SafeDownCast(window)->WaitForCompletion();
  timer->StopTimer();
  if (errors->HasErrors())
  {
    for (const std::string& message : errors->GetMessages())
    {
      Fail("rendering failed: " + message);
    }
    return ExitFailure;
  }
  if (verbose)
  {
    std::cerr << "first frame: " << timer->GetElapsedTime() << " s (transmittance maps: "
              << (mapper->GetMapBuildCount() > 0
                     ? std::to_string(mapper->GetLastMapBuildTime()) + " s"
                     : std::string("none"))
              << "; the rest: shader compilation, upload and ray casting)\n";
  }
  if (!RefinePaths(window, mapper, errors, verbose))
  {
    return Fail("path tracing failed: " + errors->GetMessages().front());
  }
  if (frames > 1)
  {
    // Frames with the maps and shaders cached: the cost of a camera move.
    const int builds = mapper->GetMapBuildCount();
    timer->StartTimer();
    for (int f = 1; f < frames; ++f)
    {
      window->Render();
    }
    vtkOpenGLRenderWindow::SafeDownCast(window)->WaitForCompletion();
    timer->StopTimer();
    if (verbose)
    {
      std::cerr << "cached frames: " << frames - 1 << " in " << timer->GetElapsedTime() << " s, "
                << timer->GetElapsedTime() / (frames - 1) << " s per frame (maps rebuilt "
                << mapper->GetMapBuildCount() - builds << " times)\n";
      if (mapper->GetAccumulatedFrames() > 0)
      {
        std::cerr << "sampled detail: the picture averages " << mapper->GetAccumulatedFrames()
                  << " frames of " << mapper->GetLastDetailSamplesPerPixel()
                  << " samples per pixel\n";
      }
    }
  }
  return EXIT_SUCCESS;
}

int WritePng(const std::string& path, vtkRenderWindow* window, bool verbose);

// --video: the pictures of a sequence as an Ogg Theora video, each taken
// from the window's frame buffer after its PNG. A run that fails removes
// the video (never half a video).
class Video
{
public:
  // False (with the reason printed) where this build has no encoder.
  bool Open(const std::string& path, int rate, vtkRenderWindow* window)
  {
    this->Path = path;
#ifdef TYNDALL_HAVE_THEORA
    this->Grab->SetInput(window);
    this->Grab->ReadFrontBufferOff();
    this->Grab->ShouldRerenderOff();
    this->Writer->SetInputConnection(this->Grab->GetOutputPort());
    this->Writer->SetFileName(path.c_str());
    this->Writer->SetRate(rate);
    this->Writer->SetQuality(2);
    this->Errors->Watch(this->Writer);
    // The writer opens its file at the first frame: a path that cannot be
    // written is found here, before any rendering (appending: a file that is
    // there is left as it is until the first frame replaces it).
    const bool existed = vtksys::SystemTools::FileExists(path, true);
    if (FILE* probe = vtksys::SystemTools::Fopen(path, "ab"))
    {
      std::fclose(probe);
      if (!existed)
      {
        vtksys::SystemTools::RemoveFile(path);
      }
    }
    else
    {
      Fail("cannot write the video " + path);
      return false;
    }
    this->Writer->Start();
    this->Started = !this->Errors->HasErrors();
    if (!this->Started)
    {
      Fail("cannot write the video " + path + ": " + this->Errors->GetMessages().front());
    }
    return this->Started;
#else
    (void)rate;
    (void)window;
    Fail("--video is not available: this build's VTK has no Ogg Theora writer "
         "(VTK::IOOggTheora)");
    return false;
#endif
  }
  // The frame just rendered; false (printed) when the encoder fails.
  bool Add()
  {
#ifdef TYNDALL_HAVE_THEORA
    this->Grab->Modified();
    this->Writer->Write();
    if (this->Errors->HasErrors() || this->Writer->GetErrorCode() != 0)
    {
      Fail("cannot write the video " + this->Path + ": " +
        (this->Errors->HasErrors() ? this->Errors->GetMessages().front()
                                   : std::string("the encoder failed")));
      return false;
    }
    ++this->Frames;
#endif
    return true;
  }
  // Ends the file: kept (its path printed) when `keep`, else removed. The
  // writer creates its file at the first frame: without one there is
  // nothing to end or remove (and vtkOggTheoraWriter::End() would clear a
  // stream it never set up).
  void Close(bool keep)
  {
    if (this->Frames == 0)
    {
      return; // no --video, or no frame in it
    }
#ifdef TYNDALL_HAVE_THEORA
    if (!this->Started)
    {
      return;
    }
    this->Writer->End();
    this->Started = false;
#endif
    if (keep)
    {
      std::cout << vtksys::SystemTools::CollapseFullPath(this->Path) << std::endl;
    }
    else
    {
      vtksys::SystemTools::RemoveFile(this->Path);
    }
  }
  int GetFrames() const
  {
    return this->Frames;
  }

private:
  std::string Path;
  int Frames = 0;
#ifdef TYNDALL_HAVE_THEORA
  bool Started = false;
  vtkNew<vtkWindowToImageFilter> Grab;
  vtkNew<vtkOggTheoraWriter> Writer;
  vtkNew<vtkTyndallErrorObserver> Errors;
#endif
};

// A time series (--sequence) or a camera path (--orbit): frame FIRST is the
// built scene; each later frame of a series is read into it; the camera
// takes the path's place for the frame; each is rendered (the maps rebuilt
// when the data changed) and written to its own picture (and the video),
// with its times. A frame that cannot be read ends the run (or, with
// `skipBad`, is skipped with a warning).
int RenderSequence(vtkRenderWindow* window, vtkTyndallSceneBuilder* builder,
  vtkTyndallErrorObserver* errors, vtkTyndallFrameSequence* sequence, int renders, bool skipBad,
  Video* video, bool verbose)
{
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  vtkTransmittanceVolumeMapper* mapper = builder->GetMapper();
  vtkNew<vtkCamera> start; // the camera of frame FIRST, where the orbit starts
  start->DeepCopy(renderer->GetActiveCamera());
  vtkNew<vtkTimerLog> timer;
  double firstTime = 0.0, laterLoad = 0.0, laterRender = 0.0;
  int later = 0, skipped = 0;
  const int buildsBefore = mapper->GetMapBuildCount();
  for (int f = sequence->GetFirst(); f <= sequence->GetLast(); ++f)
  {
    const std::string input = sequence->GetInputPath(f);
    const std::string what = "frame " + std::to_string(f) +
      (sequence->GetStill() ? std::string()
                            : " (" + input +
            (sequence->GetNumberedFiles() ? std::string() : ", time frame " + std::to_string(f)) +
            ")");
    double load = 0.0;
    errors->Clear();
    if (f != sequence->GetFirst() && !sequence->GetStill())
    {
      timer->StartTimer();
      const bool loaded = builder->LoadFrame(input, sequence->GetInputFrame(f));
      timer->StopTimer();
      load = timer->GetElapsedTime();
      if (!loaded)
      {
        const std::string why =
          errors->HasErrors() ? errors->GetMessages().front() : std::string("cannot be read");
        if (!skipBad)
        {
          return Fail(what + ": " + why + " (--skip-bad-frames skips such frames)");
        }
        std::cerr << Program << ": warning: skipped " << what << ": " << why << "\n";
        ++skipped;
        continue;
      }
    }
    // The camera on its path, its near and far planes around this frame's
    // data (a simulation's box may grow); `renders` still frames (sampled
    // detail averages them).
    if (sequence->GetOrbitDegrees() != 0.0)
    {
      vtkCamera* camera = renderer->GetActiveCamera();
      camera->DeepCopy(start);
      camera->Azimuth(sequence->GetAzimuth(f));
      camera->OrthogonalizeViewUp();
    }
    renderer->ResetCameraClippingRange();
    const int builds = mapper->GetMapBuildCount();
    timer->StartTimer();
    for (int r = 0; r < renders; ++r)
    {
      window->Render();
    }
    RefinePaths(window, mapper, errors, false);
    vtkOpenGLRenderWindow::SafeDownCast(window)->WaitForCompletion();
    timer->StopTimer();
    const double render = timer->GetElapsedTime();
    if (errors->HasErrors())
    {
      return Fail(what + ": rendering failed: " + errors->GetMessages().front());
    }
    const std::string output = sequence->GetOutputPath(f);
    if (WritePng(output, window, false) != EXIT_SUCCESS || (video && !video->Add()))
    {
      return ExitFailure;
    }
    std::cout << vtksys::SystemTools::CollapseFullPath(output) << std::endl;
    if (verbose)
    {
      std::cerr << what << ": load " << load << " s, render " << render << " s (maps "
                << (mapper->GetMapBuildCount() > builds
                       ? std::to_string(mapper->GetLastMapBuildTime()) + " s"
                       : std::string("not rebuilt"))
                << "), " << output << "\n";
    }
    if (f == sequence->GetFirst())
    {
      firstTime = render;
    }
    else
    {
      laterLoad += load;
      laterRender += render;
      ++later;
    }
  }
  if (verbose && later == 0 && skipped > 0)
  {
    std::cerr << "sequence: 1 frame drawn, " << skipped << " skipped\n";
  }
  if (verbose && later > 0)
  {
    const double perFrame = (laterLoad + laterRender) / later;
    std::cerr << "sequence: " << later + 1 << " frames drawn" << (skipped ? ", " : "")
              << (skipped ? std::to_string(skipped) + " skipped" : std::string())
              << "; after the first (" << firstTime << " s to render), " << perFrame
              << " s per frame (load " << laterLoad / later << " s, render " << laterRender / later
              << " s), " << perFrame / firstTime << " x the first frame's render; maps built "
              << mapper->GetMapBuildCount() - buildsBefore
              << (mapper->GetMapBuildCount() - buildsBefore == 1 ? " time" : " times")
              << " in all\n";
  }
  if (verbose && video)
  {
    std::cerr << "video: " << video->GetFrames() << " frames\n";
  }
  return EXIT_SUCCESS;
}

// The PNG: the window's frame buffer of the frame just rendered.
int WritePng(const std::string& path, vtkRenderWindow* window, bool verbose)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(writer);
  writer->Write();
  if (writer->GetErrorCode() != 0 || errors->HasErrors())
  {
    return Fail("cannot write " + path +
      (errors->HasErrors() ? ": " + errors->GetMessages().front() : std::string()));
  }
  timer->StopTimer();
  if (verbose)
  {
    std::cerr << "png: " << path << " in " << timer->GetElapsedTime() << " s\n";
  }
  return EXIT_SUCCESS;
}
}

int main(int argc, char* argv[])
{
  vtkNew<vtkTyndallOptions> options;
  options->SetProgram(vtkTyndallOptions::RENDER);
  if (!options->Parse(argc, argv))
  {
    return Fail(options->GetErrorMessage(), ExitUsage);
  }
  if (options->GetHelpRequested())
  {
    std::cout << options->GetHelp(Description().c_str()) << Footer();
    return EXIT_SUCCESS;
  }
#ifndef TYNDALL_HAVE_OPENEXR
  if (options->IsSet("exr"))
  {
    return Fail("--exr is not available: this build has no OpenEXR", ExitUsage);
  }
#endif
#ifndef TYNDALL_HAVE_THEORA
  if (options->IsSet("video"))
  {
    return Fail("--video is not available: this build's VTK has no Ogg Theora writer "
                "(VTK::IOOggTheora)",
      ExitUsage);
  }
#endif
  const std::string input = options->GetInput();
  const std::string output = options->IsSet("output")
    ? options->GetText("output")
    : (input.empty() ? "tyndall-cloud.png" : DefaultOutputFor(input));
  const std::string exr = options->GetText("exr");
  const bool verbose = !options->GetFlag("quiet");
  vtkNew<vtkTyndallFrameSequence> sequence;
  const bool series = options->IsSet("sequence");
  const bool sequenced = series || options->IsSet("orbit");
  if (sequenced)
  {
    const std::string pictures =
      options->IsSet("output") ? output : vtkTyndallFrameSequence::DefaultOutput(output);
    const bool ok = series
      ? sequence->SetUp(input, pictures, static_cast<int>(options->GetNumber("sequence", 0)),
          static_cast<int>(options->GetNumber("sequence", 1)))
      : sequence->SetUpStill(pictures, static_cast<int>(options->GetNumber("orbit-frames")));
    if (!ok)
    {
      return Fail(sequence->GetErrorMessage(), ExitUsage);
    }
    sequence->SetOrbitDegrees(options->GetNumber("orbit"));
  }

  // The scene: the medium (loaded with progress), its transfer function,
  // camera, lights and background.
  vtkNew<vtkTyndallSceneBuilder> builder;
  builder->SetOptions(options);
  // With --exr the float frame is drawn linear (the EXR), then the PNG
  // with the display transform (after WriteFloatFrame(), below).
  builder->SetLinearOutput(!exr.empty());
  if (series)
  {
    builder->SetFrame(
      sequence->GetInputPath(sequence->GetFirst()), sequence->GetInputFrame(sequence->GetFirst()));
  }
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(builder);
  Progress progress;
  progress.Builder = builder;
  progress.Quiet = !verbose;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback(Progress::Callback);
  builder->AddObserver(vtkCommand::ProgressEvent, onProgress);
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const bool built = builder->Build(renderer);
  timer->StopTimer();
  if (!built)
  {
    if (verbose && progress.Next > 0 && progress.Next <= 100)
    {
      std::cerr << "\n";
    }
    for (const std::string& message : errors->GetMessages())
    {
      Fail(message);
    }
    if (!errors->HasErrors())
    {
      Fail("cannot build the scene");
    }
    return builder->GetBadOptions() ? ExitUsage : ExitFailure;
  }
  progress.Report(1.0);
  if (*builder->GetReadNotes())
  {
    // What the loader changed (NIfTI scaling, a 4-D file's frame): said even with -q.
    std::cerr << "note: " << builder->GetReadNotes() << "\n";
  }
  if (verbose)
  {
    if (builder->GetDefaultScene())
    {
      std::cerr << builder->GetProgressLabel() << " in " << timer->GetElapsedTime() << " s\n";
    }
    else
    {
      LogLoaded(series ? sequence->GetInputPath(sequence->GetFirst()) : input, builder->GetImage(),
        timer->GetElapsedTime());
    }
    double range[2];
    vtkDataArray* scalars = builder->GetImage()->GetPointData()->GetScalars();
    scalars = scalars ? scalars : builder->GetImage()->GetCellData()->GetScalars();
    scalars->GetRange(range);
    std::cerr << "transfer function: " << builder->GetTransferFunctionDescription()
              << " (scalar range [" << range[0] << ", " << range[1] << "])\n";
  }

  // The window, off screen, on a display connection opened patiently.
  vtkNew<vtkTyndallDisplay> display;
  if (!display->Open())
  {
    return Fail(display->GetErrorMessage());
  }
  vtkNew<vtkRenderWindow> window;
  display->Attach(window);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(static_cast<int>(options->GetNumber("size", 0)),
    static_cast<int>(options->GetNumber("size", 1)));
  window->AddRenderer(renderer);
  // With --exr the scene is drawn into a float (RGBA32F) frame buffer first,
  // which keeps radiance above 1; it is then blitted into the window's 8-bit
  // frame buffer, which the PNG reads.
  vtkNew<vtkFramebufferPass> floatPass;
  vtkNew<vtkRenderStepsPass> steps;
  vtkSmartPointer<vtkRenderPass> builderPass = renderer->GetPass(); // --ground's, or none
  if (!exr.empty())
  {
    floatPass->SetColorFormat(vtkTextureObject::Float32);
    // The builder's passes (--ground) inside the float frame buffer, else VTK's usual steps.
    floatPass->SetDelegatePass(renderer->GetPass() ? renderer->GetPass() : steps.Get());
    renderer->SetPass(floatPass);
  }
  errors->Clear();
  errors->Watch(builder->GetMapper());
  errors->Watch(window);
  errors->Watch(renderer);
  if (verbose)
  {
    std::cerr << "rendering " << window->GetSize()[0] << " x " << window->GetSize()[1] << ": "
              << builder->GetMapper()->GetTransmittanceMethodAsString() << ", "
              << (options->GetFlag("vtk-property") ? "a plain vtkVolumeProperty"
                     : builder->GetProperty()->GetScatteringModel() ==
                       vtkParticipatingMediumProperty::SINGLE_SCATTERING
                     ? "single scattering"
                     : "emission-absorption")
              << ", " << renderer->GetLights()->GetNumberOfItems() << " light(s)"
              << (exr.empty() ? "" : ", float frame buffer") << " ...\n";
  }
  int frames = static_cast<int>(options->GetNumber("frames"));
  if (options->GetFlag("detail") && options->GetNumber("detail-samples") > 0)
  {
    // Sampled detail: the picture is the average of still frames.
    frames = std::max(frames, static_cast<int>(options->GetNumber("detail-frames")));
  }
  if (sequenced)
  {
    Video video;
    const bool withVideo = options->IsSet("video");
    if (withVideo &&
      !video.Open(
        options->GetText("video"), static_cast<int>(options->GetNumber("video-rate")), window))
    {
      window->Finalize();
      return ExitFailure;
    }
    const int status = RenderSequence(window, builder, errors, sequence, frames,
      options->GetFlag("skip-bad-frames"), withVideo ? &video : nullptr, verbose);
    video.Close(status == EXIT_SUCCESS);
    window->Finalize(); // before the display connection closes
    return status;
  }
  int status = RenderFrames(window, builder, errors, frames, verbose);
#ifdef TYNDALL_HAVE_OPENEXR
  if (status == EXIT_SUCCESS && !exr.empty())
  {
    status = WriteFloatFrame(exr, window, floatPass, verbose);
  }
#endif
  if (!exr.empty())
  {
    floatPass->ReleaseGraphicsResources(window);
    renderer->SetPass(builderPass);
    if (status == EXIT_SUCCESS && DisplayTransformed(options))
    {
      // The PNG with the transform: the linear EXR's frame, mapped (a path-
      // traced picture keeps its samples; a map-based one is drawn again).
      builder->SetLinearOutput(false);
      builder->ApplyDisplayOptions();
      window->Render();
      status = errors->HasErrors() ? Fail("rendering failed: " + errors->GetMessages().front())
                                   : EXIT_SUCCESS;
    }
  }
  if (status == EXIT_SUCCESS)
  {
    status = WritePng(output, window, verbose);
  }
  window->Finalize(); // before the display connection closes
  if (status == EXIT_SUCCESS)
  {
    std::cout << vtksys::SystemTools::CollapseFullPath(output) << std::endl;
  }
  return status;
}
