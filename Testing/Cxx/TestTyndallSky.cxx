// vtkTyndallSky, the programs' sky options (--sky, --sky-top, --sky-image)
// into a renderer's environment:
// 1. no option: VTK's defaults (black, no gradient, no texture);
// 2. --sky and --sky-top: EnvironmentalBG, EnvironmentalBG2 and the gradient;
//    the sky's up is the camera's view-up and its front (up x right, the
//    image's centre) the camera's direction of view, for a tilted camera;
// 3. --sky-image: a missing file and a file no reader takes are errors
//    naming the file; an image read (a 64 x 32 .hdr written here) becomes
//    the environment texture with UseImageBasedLighting.
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"
#include "vtkTyndallErrorObserver.h"
#include "vtkTyndallOptions.h"
#include "vtkTyndallSky.h"

#include "TyndallTestCheck.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

bool Parse(vtkTyndallOptions* o, std::vector<std::string> args)
{
  std::vector<char*> argv;
  static char program[] = "tyndall-render";
  argv.push_back(program);
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  return o->Parse(static_cast<int>(argv.size()), argv.data());
}

bool Near(const double* a, const double* b, double tolerance)
{
  return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance &&
    std::abs(a[2] - b[2]) <= tolerance;
}

// A 64 x 32 grey Radiance file (uncompressed rows).
void WriteHdr(const std::string& path)
{
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 32 +X 64\n";
  const unsigned char grey[4] = { 128, 128, 128, 128 }; // 0.5
  for (int k = 0; k < 64 * 32; ++k)
  {
    out.write(reinterpret_cast<const char*>(grey), 4);
  }
}
}

int TestTyndallSky(int argc, char* argv[])
{
  vtkNew<vtkObject> reporter;
  vtkNew<vtkTyndallErrorObserver> errors;
  errors->Watch(reporter);

  // 1. no option.
  {
    vtkNew<vtkTyndallOptions> o;
    vtkNew<vtkRenderer> renderer;
    Check(Parse(o, {}) && vtkTyndallSky::Apply(o, renderer, reporter), "no sky option applies");
    const double black[3] = { 0.0, 0.0, 0.0 };
    Check(Near(renderer->GetEnvironmentalBG(), black, 0.0) &&
        !renderer->GetGradientEnvironmentalBG() && !renderer->GetUseImageBasedLighting() &&
        !renderer->GetEnvironmentTexture(),
      "no sky option: VTK's black sky");
  }

  // 2. colours and orientation, the camera tilted.
  {
    vtkNew<vtkTyndallOptions> o;
    vtkNew<vtkRenderer> renderer;
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(3.0, -1.0, 2.0);
    camera->SetFocalPoint(0.0, 0.5, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->OrthogonalizeViewUp();
    Check(Parse(o, { "--sky", "0.1", "0.2", "0.3", "--sky-top", "1", "2", "3" }) &&
        vtkTyndallSky::Apply(o, renderer, reporter),
      "--sky and --sky-top apply");
    const double bottom[3] = { 0.1, 0.2, 0.3 }, top[3] = { 1.0, 2.0, 3.0 };
    Check(Near(renderer->GetEnvironmentalBG(), bottom, 1e-12) &&
        Near(renderer->GetEnvironmentalBG2(), top, 1e-12) && renderer->GetGradientEnvironmentalBG(),
      "--sky is straight down, --sky-top straight up, a gradient");
    double up[3], right[3], front[3], view[3];
    renderer->GetEnvironmentUp(up);
    renderer->GetEnvironmentRight(right);
    vtkMath::Cross(up, right, front);
    camera->GetDirectionOfProjection(view);
    Check(Near(up, camera->GetViewUp(), 1e-9), "the sky's up is the view-up");
    Check(Near(front, view, 1e-9) && std::abs(vtkMath::Norm(right) - 1.0) < 1e-9,
      "the sky's front (its image's centre) is the direction of view");
  }

  // 3. the image.
  std::string dir = ".";
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-T")
    {
      dir = argv[i + 1];
    }
  }
  const std::string hdr = dir + "/TestTyndallSky.hdr";
  const std::string text = dir + "/TestTyndallSky.txt";
  WriteHdr(hdr);
  std::ofstream(text) << "not an image\n";
  struct Case
  {
    std::string Path;
    const char* Says;
  };
  for (const Case& c : { Case{ dir + "/no-such-sky.hdr", "no such sky image" },
         Case{ text, "not a sky image this program reads" } })
  {
    vtkNew<vtkTyndallOptions> o;
    vtkNew<vtkRenderer> renderer;
    errors->Clear();
    const bool applied =
      Parse(o, { "--sky-image", c.Path }) && vtkTyndallSky::Apply(o, renderer, reporter);
    Check(!applied && errors->HasErrors() &&
        errors->GetMessages().front().find(c.Says) != std::string::npos &&
        errors->GetMessages().front().find(c.Path) != std::string::npos,
      c.Path + ": an error naming it (\"" + c.Says + "\")");
  }
  {
    vtkNew<vtkTyndallOptions> o;
    vtkNew<vtkRenderer> renderer;
    errors->Clear();
    Check(Parse(o, { "--sky-image", hdr }) && vtkTyndallSky::Apply(o, renderer, reporter) &&
        !errors->HasErrors(),
      "an .hdr sky image applies");
    vtkTexture* texture = renderer->GetEnvironmentTexture();
    vtkImageData* image = texture ? texture->GetInput() : nullptr;
    int dims[3] = { 0, 0, 0 };
    if (image)
    {
      image->GetDimensions(dims);
    }
    Check(renderer->GetUseImageBasedLighting() && dims[0] == 64 && dims[1] == 32 &&
        std::abs(image->GetScalarComponentAsDouble(5, 5, 0, 1) - 0.5) < 1e-6,
      "the image is the environment texture, with UseImageBasedLighting");
  }
  vtksys::SystemTools::RemoveFile(hdr);
  vtksys::SystemTools::RemoveFile(text);
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
