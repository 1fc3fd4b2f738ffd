// TyndallCLICheck: the checker behind the tyndall-render tests
// (Testing/CLI/CMakeLists.txt). Subcommands:
//
//   run [--exit 0|nonzero|N] [--stdout-has TEXT]... [--stderr-has TEXT]...
//       [--stderr-lacks TEXT]... [--remove FILE]... [--absent FILE]...
//       [--skip-unless PATH]... -- PROGRAM ARGS...
//     Runs PROGRAM, checks its exit status (default 0) and that its stdout /
//     stderr contain (or lack) the texts. --remove deletes stale outputs
//     first; --absent files must not exist afterwards (no picture written).
//   psnr IMAGE BASELINE MIN_DB [--skip-unless PATH]...
//     PSNR of two 8-bit PNGs over RGB; fails below MIN_DB or without a
//     baseline (the message names the candidate to review).
//   exr EXR PNG WIDTH HEIGHT MAX_LEVELS [MIN_MAXIMUM]
//     The EXR has WIDTH x HEIGHT finite RGB pixels whose clamp(v, 0, 1) *
//     255 agrees with the PNG within MAX_LEVELS; with MIN_MAXIMUM, the EXR's
//     largest value must reach it (proving unclamped float capture).
//   differ A B MAX_DB
//     PSNR of two 8-bit PNGs over RGB below MAX_DB: different pictures.
//   nonempty PNG MIN_FRACTION [--skip-unless PATH]...
//     At least MIN_FRACTION of the pixels differ from the corner pixel by
//     more than 2 levels (something was drawn on the background).
//   sharper A B RATIO
//     A's detail finer than 5 pixels (RMS of the luminance minus its 5 x 5
//     box blur) is at least RATIO times B's.
//   video OGV WIDTH HEIGHT FRAMES RATE
//     An Ogg Theora file whose video is WIDTH x HEIGHT pixels at RATE frames
//     per second and holds FRAMES frames (its last granule position).
//   make-data DIR
//     Writes the synthetic inputs of the loader tests into DIR.
//   make-bad-inputs DIR [VDB]
//     Writes the files of the bad-input matrix (Documentation/bad-inputs.md).
//
// Exit status: 0 pass, 1 fail, 125 skipped (CTest SKIP_RETURN_CODE).
#include "TyndallTestData.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSphereSource.h"
#include "vtkStructuredPointsWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLImageDataWriter.h"
#include "vtksys/Process.h"
#include "vtksys/SystemTools.hxx"

#ifdef TYNDALL_HAVE_OPENEXR
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#endif

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using tyndall_test_data::Blob;
using tyndall_test_data::WriteText;
constexpr int Pass = 0;
constexpr int Fail = 1;
constexpr int Skip = 125;

int Usage()
{
  std::cerr
    << "usage: TyndallCLICheck run|psnr|differ|exr|nonempty|sharper|video|make-data ... (see the "
       "source)\n";
  return Fail;
}

// Handles --skip-unless PATH pairs in args[from..]; returns true to skip.
bool SkipUnless(const std::vector<std::string>& args, size_t from)
{
  for (size_t i = from; i + 1 < args.size(); ++i)
  {
    if (args[i] == "--skip-unless" && !vtksys::SystemTools::PathExists(args[i + 1]))
    {
      std::cout << "SKIP: " << args[i + 1] << " is absent\n";
      return true;
    }
  }
  return false;
}

int Run(const std::vector<std::string>& args)
{
  std::string exitSpec = "0";
  std::vector<std::string> stdoutHas, stderrHas, stderrLacks, removes, absent, skipUnless;
  size_t i = 0;
  for (; i < args.size() && args[i] != "--"; ++i)
  {
    if (i + 1 >= args.size())
    {
      return Usage();
    }
    const std::string& option = args[i];
    const std::string& value = args[++i];
    if (option == "--exit")
      exitSpec = value;
    else if (option == "--stdout-has")
      stdoutHas.push_back(value);
    else if (option == "--stderr-has")
      stderrHas.push_back(value);
    else if (option == "--stderr-lacks")
      stderrLacks.push_back(value);
    else if (option == "--remove")
      removes.push_back(value);
    else if (option == "--absent")
      absent.push_back(value);
    else if (option == "--skip-unless")
      skipUnless.push_back(value);
    else
      return Usage();
  }
  if (i + 1 >= args.size())
  {
    return Usage();
  }
  for (const auto& path : skipUnless)
  {
    if (!vtksys::SystemTools::PathExists(path))
    {
      std::cout << "SKIP: " << path << " is absent\n";
      return Skip;
    }
  }
  for (const auto& path : removes)
  {
    vtksys::SystemTools::RemoveFile(path);
  }
  for (const auto& path : absent)
  {
    vtksys::SystemTools::RemoveFile(path);
  }
  std::vector<const char*> command;
  for (size_t k = i + 1; k < args.size(); ++k)
  {
    command.push_back(args[k].c_str());
  }
  command.push_back(nullptr);

  // Under the sanitizers the child (tyndall-render) gets Mesa's driver
  // preloaded, this process libasan alone (TyndallSanitizers.cmake,
  // TYNDALL_SANITIZER_GL_IN_CHILD).
  const char* preload = std::getenv("TYNDALL_SANITIZER_CHILD_PRELOAD");
  if (preload && !vtksys::SystemTools::PutEnv(std::string("LD_PRELOAD=") + preload))
  {
    std::cout << "FAIL: LD_PRELOAD could not be set for the child\n";
    return Fail;
  }
  vtksysProcess* process = vtksysProcess_New();
  vtksysProcess_SetCommand(process, command.data());
  vtksysProcess_Execute(process);
  std::string out, err;
  char* data = nullptr;
  int length = 0;
  for (;;)
  {
    const int pipe = vtksysProcess_WaitForData(process, &data, &length, nullptr);
    if (pipe == vtksysProcess_Pipe_STDOUT)
      out.append(data, length);
    else if (pipe == vtksysProcess_Pipe_STDERR)
      err.append(data, length);
    else
      break;
  }
  vtksysProcess_WaitForExit(process, nullptr);
  const int state = vtksysProcess_GetState(process);
  const int exitValue = vtksysProcess_GetExitValue(process);
  vtksysProcess_Delete(process);

  std::cout << "command:";
  for (size_t k = i + 1; k < args.size(); ++k)
  {
    std::cout << " " << args[k];
  }
  std::cout << "\n--- stdout ---\n" << out << "--- stderr ---\n" << err << "--------------\n";
  if (state != vtksysProcess_State_Exited)
  {
    std::cout << "FAIL: the program did not exit normally (state " << state << ")\n";
    return Fail;
  }
  std::cout << "exit status " << exitValue << "\n";
  bool ok = true;
  if (exitSpec == "nonzero")
  {
    if (exitValue == 0)
    {
      std::cout << "FAIL: expected a non-zero exit status\n";
      ok = false;
    }
  }
  else if (std::to_string(exitValue) != exitSpec)
  {
    std::cout << "FAIL: expected exit status " << exitSpec << "\n";
    ok = false;
  }
  for (const auto& text : stdoutHas)
  {
    if (out.find(text) == std::string::npos)
    {
      std::cout << "FAIL: stdout lacks '" << text << "'\n";
      ok = false;
    }
  }
  for (const auto& text : stderrHas)
  {
    if (err.find(text) == std::string::npos)
    {
      std::cout << "FAIL: stderr lacks '" << text << "'\n";
      ok = false;
    }
  }
  for (const auto& path : absent)
  {
    if (vtksys::SystemTools::PathExists(path))
    {
      std::cout << "FAIL: " << path << " was written\n";
      ok = false;
    }
  }
  for (const auto& text : stderrLacks)
  {
    if (err.find(text) != std::string::npos)
    {
      std::cout << "FAIL: stderr has '" << text << "'\n";
      ok = false;
    }
  }
  return ok ? Pass : Fail;
}

vtkSmartPointer<vtkImageData> ReadPNG(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!vtksys::SystemTools::FileExists(path, true) || !reader->CanReadFile(path.c_str()))
  {
    std::cout << "FAIL: " << path << " is missing or not a PNG\n";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  if (!image->GetPointData()->GetScalars() ||
    image->GetPointData()->GetScalars()->GetNumberOfComponents() < 3 ||
    image->GetScalarType() != VTK_UNSIGNED_CHAR)
  {
    std::cout << "FAIL: " << path << " is not an 8-bit RGB(A) PNG\n";
    return nullptr;
  }
  return image;
}

// RGB value of pixel (x, y) (y up), channel c.
double Pixel(vtkImageData* image, int x, int y, int c)
{
  return image->GetScalarComponentAsDouble(x, y, 0, c);
}

// PSNR in dB of two 8-bit pictures of one size over RGB (inf when equal).
double PsnrOf(vtkImageData* a, vtkImageData* b)
{
  int d[3];
  a->GetDimensions(d);
  double sum = 0.0;
  for (int y = 0; y < d[1]; ++y)
  {
    for (int x = 0; x < d[0]; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double e = Pixel(a, x, y, c) - Pixel(b, x, y, c);
        sum += e * e;
      }
    }
  }
  const double mse = sum / (3.0 * d[0] * d[1]);
  return mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

int Psnr(const std::vector<std::string>& args)
{
  if (args.size() < 3)
  {
    return Usage();
  }
  if (SkipUnless(args, 3))
  {
    return Skip;
  }
  const std::string& candidate = args[0];
  const std::string& baseline = args[1];
  const double floor = std::atof(args[2].c_str());
  auto a = ReadPNG(candidate);
  if (!a)
  {
    return Fail;
  }
  if (!vtksys::SystemTools::FileExists(baseline, true))
  {
    std::cout << "FAIL: no baseline " << baseline << "; review the candidate " << candidate
              << " and copy it there if it is right (Documentation/testing.md)\n";
    return Fail;
  }
  auto b = ReadPNG(baseline);
  if (!b)
  {
    return Fail;
  }
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  if (da[0] != db[0] || da[1] != db[1])
  {
    std::cout << "FAIL: size " << da[0] << " x " << da[1] << " differs from the baseline's "
              << db[0] << " x " << db[1] << "\n";
    return Fail;
  }
  const double psnr = PsnrOf(a, b);
  std::cout << "PSNR of " << candidate << " against " << baseline << ": " << psnr << " dB (floor "
            << floor << " dB)\n";
  if (!(psnr >= floor))
  {
    std::cout << "FAIL: below the floor\n";
    return Fail;
  }
  return Pass;
}

// differ A B MAX_DB: the two pictures must be different ones (PSNR below MAX_DB).
int Differ(const std::vector<std::string>& args)
{
  if (args.size() != 3)
  {
    return Usage();
  }
  auto a = ReadPNG(args[0]);
  auto b = ReadPNG(args[1]);
  if (!a || !b)
  {
    return Fail;
  }
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  if (da[0] != db[0] || da[1] != db[1])
  {
    std::cout << args[0] << " and " << args[1] << " differ in size: different pictures\n";
    return Pass;
  }
  const double psnr = PsnrOf(a, b);
  const double ceiling = std::atof(args[2].c_str());
  std::cout << "PSNR of " << args[0] << " against " << args[1] << ": " << psnr
            << " dB (they must differ: below " << ceiling << " dB)\n";
  if (!(psnr < ceiling))
  {
    std::cout << "FAIL: the same picture\n";
    return Fail;
  }
  return Pass;
}

// Ogg pages (RFC 3533) of the file's first Theora stream: the
// identification header's picture size, frame rate and granule shift
// (Theora specification, section 6.2), and the last granule position.
struct TheoraStream
{
  bool Found = false;
  long Width = 0, Height = 0, RateNumerator = 0, RateDenominator = 0;
  int Shift = 0;
  int64_t LastGranule = -1;
};

uint64_t BigEndian(const unsigned char* p, int bytes)
{
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i)
  {
    v = (v << 8) | p[i];
  }
  return v;
}

bool ReadTheora(const std::string& path, TheoraStream& stream)
{
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  uint32_t serial = 0;
  size_t at = 0;
  while (at + 27 <= bytes.size())
  {
    const unsigned char* page = bytes.data() + at;
    if (std::memcmp(page, "OggS", 4) != 0)
    {
      std::cout << path << ": no Ogg page at byte " << at << "\n";
      return false;
    }
    const int segments = page[26];
    size_t body = 27 + segments, length = 0;
    for (int i = 0; i < segments && at + 27 + i < bytes.size(); ++i)
    {
      length += page[27 + i];
    }
    if (at + body + length > bytes.size())
    {
      std::cout << path << ": the Ogg page at byte " << at << " is cut off\n";
      return false;
    }
    int64_t granule = 0;
    for (int i = 7; i >= 0; --i)
    {
      granule = (granule << 8) | page[6 + i];
    }
    const uint32_t pageSerial = static_cast<uint32_t>(
      page[14] | page[15] << 8 | page[16] << 16 | static_cast<uint32_t>(page[17]) << 24);
    const unsigned char* data = page + body;
    if (!stream.Found && length >= 42 && std::memcmp(data, "\x80theora", 7) == 0)
    {
      stream.Found = true;
      serial = pageSerial;
      stream.Width = static_cast<long>(BigEndian(data + 14, 3));
      stream.Height = static_cast<long>(BigEndian(data + 17, 3));
      stream.RateNumerator = static_cast<long>(BigEndian(data + 22, 4));
      stream.RateDenominator = static_cast<long>(BigEndian(data + 26, 4));
      stream.Shift = ((data[40] & 0x03) << 3) | (data[41] >> 5);
    }
    else if (stream.Found && pageSerial == serial && granule != -1)
    {
      stream.LastGranule = granule;
    }
    at += body + length;
  }
  return stream.Found;
}

int Video(const std::vector<std::string>& args)
{
  if (args.size() != 5)
  {
    return Usage();
  }
  TheoraStream stream;
  if (!ReadTheora(args[0], stream))
  {
    std::cout << "FAIL: " << args[0] << " holds no Theora video\n";
    return Fail;
  }
  // Theora 3.2.1: the granule is the key frame's number << shift plus the
  // frames since it; their sum counts the frames up to this one.
  const int64_t frames = stream.LastGranule < 0 ? 0
                                                : (stream.LastGranule >> stream.Shift) +
      (stream.LastGranule & ((int64_t(1) << stream.Shift) - 1));
  std::cout << args[0] << ": " << stream.Width << " x " << stream.Height << ", "
            << stream.RateNumerator << "/" << stream.RateDenominator << " frames per second, "
            << frames << " frames\n";
  const bool ok = stream.Width == std::atol(args[1].c_str()) &&
    stream.Height == std::atol(args[2].c_str()) && frames == std::atol(args[3].c_str()) &&
    stream.RateDenominator > 0 &&
    stream.RateNumerator == std::atol(args[4].c_str()) * stream.RateDenominator;
  if (!ok)
  {
    std::cout << "FAIL: expected " << args[1] << " x " << args[2] << ", " << args[4]
              << " frames per second, " << args[3] << " frames\n";
    return Fail;
  }
  return Pass;
}

int Exr(const std::vector<std::string>& args)
{
#ifdef TYNDALL_HAVE_OPENEXR
  if (args.size() < 5)
  {
    return Usage();
  }
  const std::string& exr = args[0];
  auto png = ReadPNG(args[1]);
  if (!png)
  {
    return Fail;
  }
  const int width = std::atoi(args[2].c_str());
  const int height = std::atoi(args[3].c_str());
  const double tolerance = std::atof(args[4].c_str());
  const bool checkMaximum = args.size() > 5;
  const double minMaximum = checkMaximum ? std::atof(args[5].c_str()) : 0.0;
  std::vector<float> rgb;
  int w = 0, h = 0;
  try
  {
    Imf::InputFile file(exr.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    w = window.max.x - window.min.x + 1;
    h = window.max.y - window.min.y + 1;
    for (const char* name : { "R", "G", "B" })
    {
      const Imf::Channel* channel = file.header().channels().findChannel(name);
      if (!channel || channel->type != Imf::FLOAT)
      {
        std::cout << "FAIL: " << exr << " has no FLOAT channel " << name << "\n";
        return Fail;
      }
    }
    rgb.assign(static_cast<size_t>(w) * h * 3, 0.0f);
    Imf::FrameBuffer frame;
    char* base = reinterpret_cast<char*>(rgb.data()) -
      (static_cast<size_t>(window.min.x) + static_cast<size_t>(window.min.y) * w) * 3 *
        sizeof(float);
    const size_t xs = 3 * sizeof(float), ys = xs * w;
    frame.insert("R", Imf::Slice(Imf::FLOAT, base, xs, ys));
    frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xs, ys));
    frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
  }
  catch (const std::exception& e)
  {
    std::cout << "FAIL: cannot read " << exr << ": " << e.what() << "\n";
    return Fail;
  }
  int dims[3];
  png->GetDimensions(dims);
  if (w != width || h != height || dims[0] != width || dims[1] != height)
  {
    std::cout << "FAIL: EXR " << w << " x " << h << ", PNG " << dims[0] << " x " << dims[1]
              << ", expected " << width << " x " << height << "\n";
    return Fail;
  }
  double maxDiff = 0.0, maximum = -1.0, minimum = 1e30;
  long above = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        // EXR rows run top-down, the PNG reader's bottom-up.
        const float v = rgb[(static_cast<size_t>(y) * w + x) * 3 + c];
        if (!std::isfinite(v))
        {
          std::cout << "FAIL: non-finite value at (" << x << ", " << y << ")\n";
          return Fail;
        }
        maximum = std::max(maximum, static_cast<double>(v));
        minimum = std::min(minimum, static_cast<double>(v));
        above += v > 1.0f ? 1 : 0;
        const double expected = std::min(1.0, std::max(0.0, static_cast<double>(v))) * 255.0;
        maxDiff = std::max(maxDiff, std::fabs(expected - Pixel(png, x, h - 1 - y, c)));
      }
    }
  }
  std::cout << exr << ": " << w << " x " << h << ", values in [" << minimum << ", " << maximum
            << "], " << above
            << " channel values above 1; largest |clamp(exr) * 255 - png| = " << maxDiff
            << " levels (tolerance " << tolerance << ")\n";
  if (maxDiff > tolerance)
  {
    std::cout << "FAIL: the EXR and the PNG disagree\n";
    return Fail;
  }
  if (checkMaximum && maximum < minMaximum)
  {
    std::cout << "FAIL: the EXR's maximum " << maximum << " is below " << minMaximum << "\n";
    return Fail;
  }
  return Pass;
#else
  (void)args;
  std::cout << "SKIP: built without OpenEXR\n";
  return Skip;
#endif
}

int NonEmpty(const std::vector<std::string>& args)
{
  if (args.size() < 2)
  {
    return Usage();
  }
  if (SkipUnless(args, 2))
  {
    return Skip;
  }
  auto image = ReadPNG(args[0]);
  if (!image)
  {
    return Fail;
  }
  const double minFraction = std::atof(args[1].c_str());
  int dims[3];
  image->GetDimensions(dims);
  long drawn = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        if (std::fabs(Pixel(image, x, y, c) - Pixel(image, 0, 0, c)) > 2.0)
        {
          ++drawn;
          break;
        }
      }
    }
  }
  const double fraction = static_cast<double>(drawn) / (static_cast<double>(dims[0]) * dims[1]);
  std::cout << args[0] << ": " << fraction << " of the pixels differ from the corner (minimum "
            << minFraction << ")\n";
  return fraction >= minFraction ? Pass : Fail;
}

// The picture's detail finer than 5 pixels: the RMS of its luminance minus
// the luminance's 5 x 5 box blur, over the pixels 2 or more from the edge.
double FineDetail(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  auto luminance = [image](int x, int y)
  { return (Pixel(image, x, y, 0) + Pixel(image, x, y, 1) + Pixel(image, x, y, 2)) / 3.0; };
  double sum = 0.0;
  long count = 0;
  for (int y = 2; y < dims[1] - 2; ++y)
  {
    for (int x = 2; x < dims[0] - 2; ++x)
    {
      double blur = 0.0;
      for (int j = -2; j <= 2; ++j)
      {
        for (int i = -2; i <= 2; ++i)
        {
          blur += luminance(x + i, y + j) / 25.0;
        }
      }
      const double d = luminance(x, y) - blur;
      sum += d * d;
      ++count;
    }
  }
  return count > 0 ? std::sqrt(sum / count) : 0.0;
}

// sharper A.png B.png RATIO: A's fine detail (FineDetail) is at least RATIO
// times B's.
int Sharper(const std::vector<std::string>& args)
{
  if (args.size() != 3)
  {
    return Usage();
  }
  auto a = ReadPNG(args[0]);
  auto b = ReadPNG(args[1]);
  if (!a || !b)
  {
    return Fail;
  }
  const double ratio = std::atof(args[2].c_str());
  const double da = FineDetail(a), db = FineDetail(b);
  std::cout << "detail finer than 5 pixels (RMS, 8-bit): " << args[0] << " " << da << ", "
            << args[1] << " " << db << ": " << (db > 0.0 ? da / db : 0.0) << "x (minimum " << ratio
            << "x)\n";
  return da > 0.0 && da >= ratio * db ? Pass : Fail;
}

// An asymmetric CT-like volume (HU): a soft-tissue ball with a bone lump off
// its centre on every axis, 32 x 28 x 12 at spacing (1.25, 1.5, 2).
int16_t CtValue(int i, int j, int k)
{
  const double x = (i - 15.5) * 1.25, y = (j - 13.5) * 1.5, z = (k - 5.5) * 2.0;
  const double dx = x - 6.0, dy = y + 5.0, dz = z - 3.0;
  if (dx * dx + dy * dy + dz * dz < 25.0)
  {
    return 1200;
  }
  return static_cast<int16_t>(x * x + y * y + z * z < 225.0 ? 40 : -1000);
}

// The CT volume as a DICOM series (stored HU + 1024 with Rescale Intercept
// -1024, files named against the order of their positions) and as a
// MetaImage at the same place; and a DICOM series whose rows run along +y
// (Image Orientation (Patient) 0\1\0\-1\0\0) beside a VTI with that direction
// matrix. Each pair must render alike.
void WriteCtThreeWays(const std::string& dir)
{
  const int columns = 32, rows = 28, slices = 12;
  const double origin[3] = { -20.0, -20.0, 10.0 };
  vtksys::SystemTools::MakeDirectory(dir + "/ct-dicom");
  vtksys::SystemTools::MakeDirectory(dir + "/ct-dicom-rotated");
  vtksys::SystemTools::MakeDirectory(dir + "/ct-slices");
  std::string raw;
  auto volume = vtkSmartPointer<vtkImageData>::New();
  volume->SetDimensions(columns, rows, slices);
  volume->SetSpacing(1.25, 1.5, 2.0);
  volume->SetOrigin(origin);
  volume->AllocateScalars(VTK_SHORT, 1);
  for (int k = 0; k < slices; ++k)
  {
    tyndall_test_data::DicomSlice slice;
    slice.Index = slices - 1 - k; // file names against the positions
    slice.Columns = columns;
    slice.Rows = rows;
    slice.PixelSpacing = "1.5\\1.25"; // between rows \ between columns
    slice.Intercept = "-1024";
    for (int j = 0; j < rows; ++j)
    {
      for (int i = 0; i < columns; ++i)
      {
        const int16_t hu = CtValue(i, j, k);
        slice.Pixels.push_back(static_cast<int16_t>(hu + 1024));
        raw.append(reinterpret_cast<const char*>(&hu), 2);
        volume->SetScalarComponentFromDouble(i, j, k, 0, hu);
      }
    }
    // The stored values of the slice, raw, for Debian's DICOM tools
    // (MakeDicomWithGdcm.cmake).
    std::string stored;
    for (int16_t v : slice.Pixels)
    {
      stored.append(reinterpret_cast<const char*>(&v), 2);
    }
    WriteText(dir + "/ct-slices/slice" + std::to_string(k) + ".raw", stored);
    std::ostringstream position;
    position << origin[0] << "\\" << origin[1] << "\\" << origin[2] + 2.0 * k;
    slice.Position = position.str();
    const std::string name = "/im" + std::to_string(slice.Index) + ".dcm";
    tyndall_test_data::WriteDicomSlice(dir + "/ct-dicom" + name, slice);
    slice.Orientation = "0\\1\\0\\-1\\0\\0";
    tyndall_test_data::WriteDicomSlice(dir + "/ct-dicom-rotated" + name, slice);
  }
  WriteText(dir + "/ct.mhd",
    "ObjectType = Image\nNDims = 3\nDimSize = 32 28 12\nElementSpacing = 1.25 1.5 2\n"
    "Offset = -20 -20 10\nElementType = MET_SHORT\nElementDataFile = ct.raw\n");
  WriteText(dir + "/ct.raw", raw);
  const double rotated[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };
  volume->SetDirectionMatrix(rotated);
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(volume);
  writer->SetFileName((dir + "/ct-rotated.vti").c_str());
  writer->Write();
}

int MakeData(const std::vector<std::string>& args)
{
  if (args.size() != 1)
  {
    return Usage();
  }
  const std::string dir = args[0];
  vtksys::SystemTools::MakeDirectory(dir);
  vtksys::SystemTools::MakeDirectory(dir + "/empty-dir");
  auto blob = Blob(1);
  for (const char* name : { "/blob.nii", "/blob.nii.gz" })
  {
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName((dir + name).c_str());
    writer->Write();
  }
  {
    // NIfTI scaling (value = stored x 0.5 + 1000) and a 4-D file of 3 frames.
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(blob);
    writer->SetRescaleSlope(0.5);
    writer->SetRescaleIntercept(1000.0);
    writer->SetFileName((dir + "/blob-scaled.nii").c_str());
    writer->Write();
    vtkNew<vtkNIFTIImageWriter> frames;
    frames->SetInputData(Blob(3));
    frames->SetTimeDimension(3);
    frames->SetFileName((dir + "/blob-4d.nii.gz").c_str());
    frames->Write();
  }
  {
    vtkNew<vtkMetaImageWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName((dir + "/blob.mha").c_str());
    writer->SetCompression(false);
    writer->Write();
  }
  {
    // A numbered sequence of the 4-D file's frames (frame c: the blob times
    // c + 1), seq/blob_0000.mha .. blob_0002.mha; frame 3 is missing.
    vtksys::SystemTools::MakeDirectory(dir + "/seq");
    for (int c = 0; c < 3; ++c)
    {
      auto frame = Blob(1);
      vtkDataArray* values = frame->GetPointData()->GetScalars();
      for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
      {
        values->SetComponent(i, 0, (c + 1) * values->GetComponent(i, 0));
      }
      char name[64];
      std::snprintf(name, sizeof(name), "/seq/blob_%04d.mha", c);
      vtkNew<vtkMetaImageWriter> writer;
      writer->SetInputData(frame);
      writer->SetFileName((dir + name).c_str());
      writer->SetCompression(false);
      writer->Write();
    }
    // The same count of OpenVDB frames, a blob moving along x by 3 voxels
    // a frame (seq/blob_0000.vdb ..): a time series for ParaView.
    for (int c = 0; c < 3; ++c)
    {
      char name[64];
      std::snprintf(name, sizeof(name), "/seq/blob_%04d.vdb", c);
      if (!tyndall_test_data::WriteDensityBlob(dir + name, 3.0 * c))
      {
        std::cout << "cannot write " << dir << name << "\n";
        return Fail;
      }
    }
  }
  {
    vtkNew<vtkStructuredPointsWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName((dir + "/blob.vtk").c_str());
    writer->Write();
  }
  {
    // The same blob twice: extent from 0 and origin (10, -5, 3), and an
    // extent starting at (10, -5, 2) with origin 0: the same world points.
    auto shifted = Blob(1);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(shifted);
    shifted->SetOrigin(10.0, -5.0, 3.0);
    writer->SetFileName((dir + "/blob.vti").c_str());
    writer->Write();
    shifted->SetExtent(10, 33, -5, 14, 2, 17);
    shifted->SetOrigin(0.0, 0.0, 0.0);
    writer->SetFileName((dir + "/shifted.vti").c_str());
    writer->Write();
  }
  {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(Blob(3));
    writer->SetFileName((dir + "/rgb.vti").c_str());
    writer->Write();
  }
  {
    // A binary mask over the blob (its samples of x below 12 kept, 255; the
    // others hidden, 0), and the blob with NaN where the mask hides it.
    auto blob = Blob(1);
    vtkNew<vtkImageData> mask;
    mask->SetDimensions(blob->GetDimensions());
    mask->SetSpacing(blob->GetSpacing());
    vtkNew<vtkUnsignedCharArray> kept;
    kept->SetName("mask");
    kept->SetNumberOfTuples(blob->GetNumberOfPoints());
    vtkDataArray* values = blob->GetPointData()->GetScalars();
    const int* dims = blob->GetDimensions();
    for (vtkIdType id = 0; id < blob->GetNumberOfPoints(); ++id)
    {
      const bool keep = id % dims[0] < 12;
      kept->SetValue(id, keep ? 255 : 0);
      if (!keep)
      {
        values->SetComponent(id, 0, std::nan(""));
      }
    }
    mask->GetPointData()->SetScalars(kept);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(mask);
    writer->SetFileName((dir + "/blob-mask.vti").c_str());
    writer->Write();
    writer->SetInputData(blob);
    writer->SetFileName((dir + "/blob-masked.vti").c_str());
    writer->Write();
  }
  {
    // A label map over the blob (label 1 for x below 8, 2 from 16 on, 0
    // between) and one of label 0 everywhere.
    auto blob = Blob(1);
    const int* dims = blob->GetDimensions();
    for (const bool zero : { false, true })
    {
      vtkNew<vtkImageData> labels;
      labels->SetDimensions(blob->GetDimensions());
      labels->SetSpacing(blob->GetSpacing());
      vtkNew<vtkUnsignedCharArray> values;
      values->SetName("labels");
      values->SetNumberOfTuples(blob->GetNumberOfPoints());
      for (vtkIdType id = 0; id < blob->GetNumberOfPoints(); ++id)
      {
        const int x = static_cast<int>(id % dims[0]);
        values->SetValue(id, zero ? 0 : (x < 8 ? 1 : (x >= 16 ? 2 : 0)));
      }
      labels->GetPointData()->SetScalars(values);
      vtkNew<vtkXMLImageDataWriter> writer;
      writer->SetInputData(labels);
      writer->SetFileName((dir + (zero ? "/blob-labels-zero.vti" : "/blob-labels.vti")).c_str());
      writer->Write();
    }
  }
  {
    // Fire: the blob as the density and a "temperature" array (Kelvin),
    // 600 K at the top rising to 2200 K at the bottom.
    auto fire = Blob(1);
    double bounds[6];
    fire->GetBounds(bounds);
    vtkNew<vtkFloatArray> temperature;
    temperature->SetName("temperature");
    temperature->SetNumberOfTuples(fire->GetNumberOfPoints());
    for (vtkIdType i = 0; i < fire->GetNumberOfPoints(); ++i)
    {
      double x[3];
      fire->GetPoint(i, x);
      const double up = (x[1] - bounds[2]) / (bounds[3] - bounds[2]);
      temperature->SetValue(i, static_cast<float>(2200.0 - 1600.0 * up));
    }
    fire->GetPointData()->AddArray(temperature);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(fire);
    writer->SetFileName((dir + "/fire.vti").c_str());
    writer->Write();
  }
  {
    // A single slice: not a volume.
    auto flat = vtkSmartPointer<vtkImageData>::New();
    flat->SetDimensions(16, 16, 1);
    flat->AllocateScalars(VTK_FLOAT, 1);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(flat);
    writer->SetFileName((dir + "/flat.vti").c_str());
    writer->Write();
  }
  {
    auto bare = vtkSmartPointer<vtkImageData>::New();
    bare->SetDimensions(8, 8, 8);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(bare);
    writer->SetFileName((dir + "/noscalars.vti").c_str());
    writer->Write();
  }
  {
    vtkNew<vtkSphereSource> sphere;
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputConnection(sphere->GetOutputPort());
    writer->SetFileName((dir + "/sphere.vtk").c_str());
    writer->Write();
  }
  {
    // A particle cloud (x y z radius density): a ring of puffs, and a bad one.
    std::ostringstream csv;
    csv << "x,y,z,radius,density\n";
    for (int i = 0; i < 400; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * i / 400.0;
      const double wobble = 0.15 * std::sin(7.0 * a);
      csv << 0.9 * std::cos(a) << "," << wobble << "," << 0.9 * std::sin(a) << ","
          << 0.08 + 0.04 * std::cos(5.0 * a) << "," << 2.0 + std::sin(3.0 * a) << "\n";
    }
    WriteText(dir + "/ring.csv", csv.str());
    // The same ring with colours (x y z radius density r g b): orange and blue halves.
    std::ostringstream coloured;
    for (int i = 0; i < 400; ++i)
    {
      const double a = 2.0 * vtkMath::Pi() * i / 400.0;
      const bool left = std::cos(a) < 0.0;
      coloured << 0.9 * std::cos(a) << " " << 0.15 * std::sin(7.0 * a) << " " << 0.9 * std::sin(a)
               << " " << 0.08 + 0.04 * std::cos(5.0 * a) << " " << 2.0 + std::sin(3.0 * a)
               << (left ? " 0.95 0.45 0.15\n" : " 0.2 0.45 0.95\n");
    }
    WriteText(dir + "/ring-coloured.txt", coloured.str());
    WriteText(dir + "/bad-particles.csv", "0,0,0,0.1,1\n1,0,0,-0.1,1\n");
  }
  // Corrupt files: an XML image file cut in the middle of its data, garbage
  // behind a NIfTI name, a MetaImage header whose raw file is missing.
  {
    std::ifstream in(dir + "/rgb.vti", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    WriteText(dir + "/truncated.vti", text.substr(0, text.size() / 2));
  }
  WriteText(dir + "/garbage.nii", std::string(2000, 'x'));
  WriteText(dir + "/garbage.vdb", std::string(2000, 'x'));
  if (!tyndall_test_data::WriteLevelSetSphere(dir + "/levelset.vdb"))
  {
    std::cout << "cannot write " << dir << "/levelset.vdb\n";
    return Fail;
  }
  WriteText(dir + "/missing-raw.mhd",
    "ObjectType = Image\nNDims = 3\nDimSize = 8 8 8\nElementType = MET_UCHAR\n"
    "ElementDataFile = no-such-file.raw\n");
  WriteText(dir + "/volume.xyz", "not a volume\n");
  // A DICOM series: 12 slices of 32 x 28 int16 "CT" (air -1000 HU around a
  // soft-tissue ball of 40 HU with a bone core of 1200 HU), and a directory
  // of files that are not DICOM.
  vtksys::SystemTools::MakeDirectory(dir + "/dicom");
  for (int k = 0; k < 12; ++k)
  {
    std::vector<int16_t> pixels(32 * 28);
    for (int j = 0; j < 28; ++j)
    {
      for (int i = 0; i < 32; ++i)
      {
        const double x = (i - 15.5) * 1.5, y = (j - 13.5) * 1.5, z = (k - 5.5) * 2.0;
        const double r = std::sqrt(x * x + y * y + z * z);
        pixels[j * 32 + i] = static_cast<int16_t>(r < 6.0 ? 1200 : (r < 15.0 ? 40 : -1000));
      }
    }
    tyndall_test_data::DicomSlice slice;
    slice.Index = k;
    slice.Pixels = pixels;
    tyndall_test_data::WriteDicomSlice(dir + "/dicom/slice" + std::to_string(k) + ".dcm", slice);
  }
  WriteCtThreeWays(dir);
  tyndall_test_data::WriteSkyHdr(dir + "/sky.hdr");
  WriteText(dir + "/sky-damaged.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n");
  vtksys::SystemTools::MakeDirectory(dir + "/not-dicom");
  WriteText(dir + "/not-dicom/notes.txt", "not DICOM\n");
  std::cout << "wrote the loader test data into " << dir << "\n";
  return Pass;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    return Usage();
  }
  const std::string mode = argv[1];
  std::vector<std::string> args(argv + 2, argv + argc);
  if (mode == "run")
    return Run(args);
  if (mode == "psnr")
    return Psnr(args);
  if (mode == "exr")
    return Exr(args);
  if (mode == "differ")
    return Differ(args);
  if (mode == "nonempty")
    return NonEmpty(args);
  if (mode == "sharper")
    return Sharper(args);
  if (mode == "video")
    return Video(args);
  if (mode == "make-data")
    return MakeData(args);
  if (mode == "make-bad-inputs" && (args.size() == 1 || args.size() == 2))
    return tyndall_test_data::MakeBadInputs(args[0], args.size() == 2 ? args[1] : "");
  return Usage();
}
