// vtkTyndallFrameSequence: the frame numbers of a sequence's names (printf
// %d, %Nd, %0Nd; %% a percent sign), the names of frames, the default
// picture names and the refused set-ups, against the expected strings.
#include "vtkNew.h"
#include "vtkTyndallFrameSequence.h"

#include "TyndallTestCheck.h"

#include <iostream>
#include <string>

namespace
{
using tyndall_test::Check;

int Count(const std::string& pattern)
{
  std::string error;
  return vtkTyndallFrameSequence::CountFrameNumbers(pattern, error);
}
}

int TestTyndallFrameSequence(int, char*[])
{
  using S = vtkTyndallFrameSequence;
  Check(Count("smoke_%04d.vdb") == 1, "one frame number");
  Check(Count("smoke.vdb") == 0, "none");
  Check(Count("100%%/smoke_%d.vdb") == 1, "%% is a percent sign, not a frame number");
  Check(Count("a_%d_%3d.vdb") == 2, "two frame numbers");
  Check(Count("smoke_%s.vdb") == -1, "%s is refused");
  Check(Count("smoke_%") == -1, "a '%' at the end is refused");
  Check(Count("smoke_%123d.vdb") == -1, "a width of 3 digits is refused");
  Check(S::Format("smoke_%04d.vdb", 12) == "smoke_0012.vdb", "%04d");
  Check(S::Format("smoke_%d.vdb", 12) == "smoke_12.vdb", "%d");
  Check(S::Format("s_%3d.vdb", 7) == "s_  7.vdb", "%3d");
  Check(S::Format("100%%/smoke_%02d.vdb", 5) == "100%/smoke_05.vdb", "%% and %02d");
  Check(S::Format("smoke_%99d", 1).size() == 105, "a width of 99 is written whole");
  Check(S::DefaultOutput("smoke_%04d.png") == "smoke_%04d.png", "a default with a number stays");
  Check(S::DefaultOutput("blob-4d.png") == "blob-4d_%04d.png", "a number before the extension");
  Check(
    S::DefaultOutput("dir.v2/out") == "dir.v2/out_%04d", "a dot in a directory is no extension");
  Check(S::IsFourDimensional("a/b.NII.GZ") && S::IsFourDimensional("b.nii") &&
      !S::IsFourDimensional("b.mha"),
    "4-D files: NIfTI");

  vtkNew<vtkTyndallFrameSequence> sequence;
  Check(sequence->SetUp("smoke_%04d.vdb", "out_%03d.png", 10, 12), "numbered files");
  Check(sequence->GetNumberedFiles() && sequence->GetInputPath(11) == "smoke_0011.vdb" &&
      sequence->GetInputFrame(11) == 0 && sequence->GetOutputPath(11) == "out_011.png",
    "frame 11 of numbered files");
  Check(sequence->SetUp("blob.nii.gz", "out_%d.png", 0, 2), "a 4-D file");
  Check(!sequence->GetNumberedFiles() && sequence->GetInputPath(2) == "blob.nii.gz" &&
      sequence->GetInputFrame(2) == 2 && sequence->GetOutputPath(2) == "out_2.png",
    "frame 2 of a 4-D file");
  auto refused = [&](const std::string& input, const std::string& output, int first, int last,
                   const std::string& text)
  {
    const bool ok = sequence->SetUp(input, output, first, last);
    const std::string message = sequence->GetErrorMessage();
    std::cout << input << " -> " << output << " " << first << ".." << last << ": " << message
              << "\n";
    Check(!ok && message.find(text) != std::string::npos, "refused: " + text);
  };
  refused("smoke_%04d.vdb", "out.png", 0, 1, "need a frame number");
  refused("a_%d_%d.vdb", "out_%d.png", 0, 1, "more than one frame number");
  refused("smoke_%04d.vdb", "out_%d_%d.png", 0, 1, "more than one frame number");
  refused("smoke.vdb", "out_%d.png", 0, 1, "no frame number");
  refused("smoke_%s.vdb", "out_%d.png", 0, 1, "no frame number (%d");
  refused("smoke_%04d.vdb", "out_%d.png", 3, 2, "comes before its first");

  // A still scene's pictures (a camera path alone) and the orbit's angles.
  Check(sequence->SetUpStill("turn_%02d.png", 8), "a still scene's 8 pictures");
  Check(sequence->GetStill() && sequence->GetFirst() == 0 && sequence->GetLast() == 7 &&
      sequence->GetInputPath(3).empty() && sequence->GetOutputPath(7) == "turn_07.png",
    "pictures 0 to 7 of a still scene, no input");
  sequence->SetOrbitDegrees(360.0);
  Check(sequence->GetAzimuth(0) == 0.0 && sequence->GetAzimuth(2) == 90.0 &&
      sequence->GetAzimuth(7) == 315.0,
    "a full turn over 8 pictures: 45 degrees apart, the last short of 360");
  Check(sequence->SetUp("smoke_%04d.vdb", "out_%03d.png", 10, 12) && !sequence->GetStill() &&
      sequence->GetAzimuth(10) == 0.0 && sequence->GetAzimuth(11) == 120.0,
    "an orbit over frames 10 to 12 starts at frame 10");
  Check(!sequence->SetUpStill("turn.png", 4) &&
      std::string(sequence->GetErrorMessage()).find("need a frame number") != std::string::npos,
    "a still scene's pictures need a frame number");
  Check(!sequence->SetUpStill("turn_%d.png", 0), "a still scene has at least one picture");
  return tyndall_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
