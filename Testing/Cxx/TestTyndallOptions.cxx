// vtkTyndallOptions, the one table behind the programs' --help, parser and
// viewer keys: every option of each program is in its help; values, ranges
// and defaults; repeatable lights; errors worded for a user; the viewer's
// keys change the options their help says they change; Python's
// ParseArguments() equals Parse().
#include "TyndallTestCheck.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkTyndallOptions.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using tyndall_test::Check;

bool Parse(vtkTyndallOptions* o, std::vector<std::string> args)
{
  args.insert(args.begin(), "program");
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  return o->Parse(static_cast<int>(argv.size()), argv.data());
}

void ExpectError(
  vtkTyndallOptions* o, const std::vector<std::string>& args, const std::string& text)
{
  const bool parsed = Parse(o, args);
  const std::string message = o->GetErrorMessage();
  if (parsed || message.find(text) == std::string::npos)
  {
    std::cerr << "expected an error with '" << text << "', got '" << message << "'" << std::endl;
  }
  Check(!parsed && message.find(text) != std::string::npos, "error: " + text);
}
}

int TestTyndallOptions(int, char*[])
{
  vtkNew<vtkTyndallOptions> o;

  // Defaults, from the table.
  Check(Parse(o, {}), "no arguments");
  Check(std::string(o->GetInput()).empty(), "no input: the default scene");
  Check(o->GetChoice("method") == 5 && o->GetNumber("coefficients") == 8 &&
      o->GetNumber("map-size") == 256 && o->GetNumber("light-samples") == 128 &&
      o->GetNumber("adaptive-threshold") == 0.01 && o->GetChoice("model") == 1 &&
      o->GetNumber("size", 0) == 512 && o->GetNumber("size", 1) == 512 &&
      o->GetNumber("resolution") == 128 && o->GetNumber("frames") == 1 &&
      !o->GetFlag("no-jitter") && !o->IsSet("method"),
    "table defaults (adaptive ETM, 8 coefficients, 256^2 maps, 512 x 512)");

  // Values.
  Check(Parse(o,
          { "--method", "tfm", "--coefficients", "12", "-s", "64", "32", "--anisotropy", "-0.5",
            "--no-jitter", "--background", "0", "0.5", "1", "-o", "out.png", "volume.vti" }),
    "a full command line");
  Check(o->GetChoice("method") == 2 && o->IsSet("method") && o->GetNumber("coefficients") == 12 &&
      o->GetNumber("size", 0) == 64 && o->GetNumber("size", 1) == 32 &&
      o->GetNumber("anisotropy") == -0.5 && o->GetFlag("no-jitter") &&
      o->GetNumber("background", 1) == 0.5 && std::string(o->GetText("output")) == "out.png" &&
      std::string(o->GetInput()) == "volume.vti",
    "the values given");
  Check(Parse(o, {}) && !o->IsSet("coefficients") && !o->GetFlag("no-jitter"),
    "parsing again starts afresh");

  // Setting one component of an unset option keeps the others' defaults.
  o->SetNumber("size", 800, 1);
  Check(o->GetNumber("size", 0) == 512 && o->GetNumber("size", 1) == 800,
    "SetNumber(size, 800, 1) on an unset size: 512 x 800");
  o->SetNumber("background", 0.5, 2);
  Check(o->GetNumber("background", 0) == 0 && o->GetNumber("background", 2) == 0.5,
    "SetNumber on an option without a default: the others 0");
  Check(Parse(o, {}), "parsing again");

  // Lights: repeatable, modifiers apply to the latest.
  Check(Parse(o,
          { "--light-direction", "0", "-1", "0", "--light-color", "1", "0.5", "0.25",
            "--light-position", "1", "2", "3", "--light-intensity", "2" }),
    "two lights");
  double v[3];
  o->GetLightColor(0, v);
  Check(o->GetNumberOfLights() == 2 && !o->GetLightPositional(0) && o->GetLightPositional(1) &&
      v[1] == 0.5 && o->GetLightIntensity(0) == 1.0 && o->GetLightIntensity(1) == 2.0,
    "light kinds, colours and intensities");
  o->GetLightVector(1, v);
  Check(v[0] == 1 && v[1] == 2 && v[2] == 3, "a point light's position");

  // Added volumes: repeatable, the --volume-* options apply to the latest.
  Check(Parse(o,
          { "--add-volume", "a.vdb", "--volume-position", "1", "2", "3", "--volume-preset", "Smoke",
            "--add-volume", "b.nii", "--volume-scale", "0.5", "--volume-density-scale", "2",
            "--volume-transfer-function", "b.tf", "--position", "0", "0", "-1" }),
    "two added volumes");
  o->GetAddedVolumePosition(0, v);
  Check(o->GetNumberOfAddedVolumes() == 2 && std::string(o->GetAddedVolumeFile(1)) == "b.nii" &&
      v[0] == 1 && v[2] == 3 && std::string(o->GetAddedVolumePreset(0)) == "Smoke" &&
      o->GetAddedVolumeScale(0) == 1.0 && o->GetAddedVolumeScale(1) == 0.5 &&
      o->GetAddedVolumeDensityScale(1) == 2.0 &&
      std::string(o->GetAddedVolumeTransferFunction(1)) == "b.tf" &&
      std::string(o->GetAddedVolumeTransferFunction(0)).empty() &&
      o->GetNumber("position", 2) == -1,
    "added volumes' files, placement, presets and transfer functions");
  ExpectError(o, { "--volume-scale", "2" },
    "--volume-scale applies to the most recent volume: give --add-volume before it");
  ExpectError(o, { "--add-volume", "a", "--volume-scale", "0" },
    "--volume-scale needs a number, 0 < S < 1e+06, got '0'");
  ExpectError(o, { "--add-volume", "a", "--volume-preset", "Fog" }, "unknown preset 'Fog'");
  ExpectError(o,
    { "--add-volume", "a", "--add-volume", "b", "--add-volume", "c", "--add-volume", "d" },
    "at most 3 --add-volume");
  Check(Parse(o, {}) && o->GetNumberOfAddedVolumes() == 0, "parsing again clears the volumes");

  // Errors, worded for a user.
  ExpectError(o, { "--frobnicate" }, "unknown option '--frobnicate' (see --help)");
  ExpectError(o, { "--coefficients", "17" }, "--coefficients needs an integer in 1..16, got '17'");
  ExpectError(o, { "--coefficients", "2.5" }, "--coefficients needs an integer in 1..16");
  ExpectError(
    o, { "--anisotropy", "abc" }, "--anisotropy needs a number in -0.99..0.99, got 'abc'");
  ExpectError(o, { "--density-scale", "nan" }, "--density-scale needs a number");
  ExpectError(o, { "--size", "100" }, "--size needs two integers in 16..8192");
  ExpectError(o, { "--method", "fast" }, "--method needs one of none brute-force");
  ExpectError(o, { "--view-angle", "180" }, "--view-angle needs a number, 0 < DEG < 180");
  ExpectError(o, { "--light-color", "1", "1", "1" }, "applies to the most recent light");
  ExpectError(o, { "--light-direction", "0", "0", "0" }, "--light-direction needs a non-zero");
  ExpectError(o, { "--view-up", "0", "0", "0" }, "--view-up needs a non-zero vector");
  ExpectError(o, { "a.vti", "b.vti" }, "more than one input given ('a.vti' and 'b.vti')");
  ExpectError(o, { "--preset", "CT", "--transfer-function", "tf.txt" }, "either --preset or");
  ExpectError(o, { "--preset", "bogus" }, "unknown preset 'bogus' (known: CT MR Cloud");
  ExpectError(o, { "--grid", "density" }, "--grid needs a .vdb input");
  ExpectError(o, { "--component", "1" }, "--component needs an input file");
  ExpectError(o, { "-r", "64", "a.vti" }, "--resolution applies to the built-in cloud only");
  ExpectError(o, { "--script", "s.txt" }, "unknown option '--script'"); // a viewer option
  // --vtk-property: a plain vtkVolumeProperty, none of the medium's options.
  ExpectError(o, { "--vtk-property", "--octaves", "3" },
    "--octaves applies to the medium (vtkParticipatingMediumProperty) only, which --vtk-property");
  ExpectError(
    o, { "--vtk-property", "--detail-octaves", "2" }, "--detail-octaves applies to the medium");
  ExpectError(o,
    { "a.vti", "--vtk-property", "--add-volume", "b.vti", "--volume-density-scale", "2" },
    "--volume-density-scale applies to the medium");
  Check(Parse(o,
          { "a.vti", "--vtk-property", "--shade", "--add-volume", "b.vti", "--volume-scale", "2" }),
    "--vtk-property with --shade and a volume's placement");
  Check(!o->GetKeyOption('a'), "tyndall-render has no keys");
  Check(vtkTyndallOptions::IsMediumOption("anisotropy") &&
      vtkTyndallOptions::IsMediumOption("detail-contrast") &&
      !vtkTyndallOptions::IsMediumOption("shade") && !vtkTyndallOptions::IsMediumOption("method"),
    "the medium's options: anisotropy and the detail, not Shade or the method");
  Check(Parse(o, { "--", "-odd-name.vti" }) && std::string(o->GetInput()) == "-odd-name.vti",
    "'--' ends the options");
  Check(Parse(o, { "-h" }) && o->GetHelpRequested(), "-h asks for help");

  // The help lists every option of the program, and no other program's.
  const std::string help = o->GetHelp("DESCRIPTION");
  for (const char* name : { "--method M", "--coefficients N", "-s, --size W H", "-o, --output FILE",
         "--exr FILE", "--light-direction X Y Z", "--preset NAME", "1..16 [8]",
         "light transmittance: none brute-force tfm", "[adaptive-etm]" })
  {
    Check(help.find(name) != std::string::npos, std::string("tyndall-render's help has ") + name);
  }
  Check(help.rfind("DESCRIPTION", 0) == 0 && help.find("--script") == std::string::npos &&
      help.find("Keys:") == std::string::npos,
    "tyndall-render's help: its description first, no viewer options or keys");

  // The viewer: its own options and the keys, from the same table.
  vtkNew<vtkTyndallOptions> viewer;
  viewer->SetProgram(vtkTyndallOptions::VIEWER);
  Check(Parse(viewer, { "--script", "s.txt", "-i", "smoke.vdb", "--method", "tfm" }),
    "the viewer's options");
  Check(std::string(viewer->GetInput()) == "smoke.vdb" && viewer->GetNumber("size", 0) == 960 &&
      std::string(viewer->GetText("script")) == "s.txt",
    "-i names the input; the viewer's own default size");
  ExpectError(viewer, { "--exr", "a.exr" }, "unknown option '--exr'");
  const std::string viewerHelp = viewer->GetHelp("");
  Check(viewerHelp.find("--events TEXT") != std::string::npos &&
      viewerHelp.find("Keys:") != std::string::npos &&
      viewerHelp.find("--exr") == std::string::npos,
    "the viewer's help: its options and its keys");
  const std::string keys = viewer->GetKeyHelp();
  for (const char* line : { "1..6", "+ or = / - or _", "--coefficients", "a / z", "d / c", "j ",
         "toggle --no-jitter", "q or Esc", "reset the camera" })
  {
    Check(keys.find(line) != std::string::npos, std::string("the key help has ") + line);
  }

  // The keys change what their help says.
  Parse(viewer, {});
  Check(
    std::string(viewer->ApplyKey('3')) == "method" && viewer->GetChoice("method") == 2, "3: TFM");
  Check(
    std::string(viewer->ApplyKey('+')) == "coefficients" && viewer->GetNumber("coefficients") == 9,
    "+: one more coefficient");
  for (int k = 0; k < 20; ++k)
  {
    viewer->ApplyKey('-');
  }
  Check(viewer->GetNumber("coefficients") == 1, "-: down to the range's end, no further");
  Check(std::string(viewer->GetKeyOption('a')) == "anisotropy" &&
      std::string(viewer->GetKeyOption('k')) == "vtk-property" && !viewer->GetKeyOption('#'),
    "a key's option, unchanged: a the anisotropy, k --vtk-property, # none");
  Check(std::string(viewer->GetKeyOption('p')) == "clip-offset" &&
      viewer->GetNumber("clip-offset") == 0.0,
    "GetKeyOption() changes nothing");
  Check(std::string(viewer->ApplyKey('p')) == "clip-offset" && viewer->ApplyKey('p') &&
      viewer->ApplyKey('o') && viewer->GetNumber("clip-offset") == 0.05,
    "p, p, o: the clipping plane forward twice and back once by 0.05");
  Check(std::string(viewer->ApplyKey('m')) == "octaves" && viewer->GetNumber("octaves") == 3 &&
      viewer->ApplyKey('n') && viewer->ApplyKey('n') && viewer->GetNumber("octaves") == 1,
    "m, n, n: one octave more, then two fewer");
  viewer->ApplyKey('a');
  viewer->ApplyKey('a');
  Check(std::abs(viewer->GetNumber("anisotropy") - 0.5) < 1e-12,
    "a twice from the default scene's 0.3 (the table's first default): 0.5");
  viewer->ApplyKey('d');
  Check(std::abs(viewer->GetNumber("density-scale") - 1.25) < 1e-12, "d: density x 1.25");
  Check(std::string(viewer->ApplyKey('v')) == "no-scene-shadows" &&
      viewer->GetFlag("no-scene-shadows") && viewer->ApplyKey('v') &&
      !viewer->GetFlag("no-scene-shadows"),
    "v, v: scene shadows off, then on again");
  viewer->ApplyKey('j');
  Check(viewer->GetFlag("no-jitter"), "j: jitter off");
  viewer->ApplyKey('j');
  Check(!viewer->GetFlag("no-jitter"), "j: jitter on again");
  Check(std::string(viewer->ApplyKey('q')) == "quit" && std::string(viewer->ApplyKey(27)) == "quit",
    "q and Esc quit");
  Check(std::string(viewer->ApplyKey('x')) == "path-denoise" && viewer->GetFlag("path-denoise") &&
      viewer->ApplyKey('x') && !viewer->GetFlag("path-denoise"),
    "x, x: the paths' denoiser on, then off again");
  Check(viewer->ApplyKey('y') == nullptr && o->ApplyKey('1') == nullptr,
    "unbound keys (and tyndall-render, which has none) do nothing");

  // Python's entry: the same parse.
  vtkNew<vtkStringArray> args;
  for (const char* a : { "--map-size", "64", "--model", "emission-absorption", "in.vdb" })
  {
    args->InsertNextValue(a);
  }
  Check(o->ParseArguments(args) && o->GetNumber("map-size") == 64 && o->GetChoice("model") == 0 &&
      std::string(o->GetInput()) == "in.vdb",
    "ParseArguments");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
