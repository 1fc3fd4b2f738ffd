/**
 * @class   vtkTyndallFrameSequence
 * @brief   the frames of a time series that a program renders one after another
 *
 * A sequence is either numbered files, named by a pattern with one printf
 * frame number (`smoke_%04d.vdb`: frame 12 is `smoke_0012.vdb`; `%d`,
 * `%Nd` or `%0Nd` with at most 2 digits, and `%%` for a percent sign), or
 * the time frames of one 4-D file (a NIfTI file whose name has no frame
 * number). Frames First
 * to Last (inclusive) are rendered; each picture is written to the output
 * pattern's name for the frame, which must hold a frame number too.
 *
 * SetUp() checks the patterns and the range (false with GetErrorMessage());
 * GetInputPath() and GetInputFrame() say what to read for a frame (the file,
 * and the time frame within it: 0 for numbered files), GetOutputPath() where
 * its picture goes. DefaultOutput() makes an output pattern from a picture
 * name ("smoke_%04d.png" stays, "blob-4d.png" becomes "blob-4d_%04d.png").
 *
 * A sequence can also be pictures of one still scene (SetUpStill(): no
 * input, pictures 0 to count - 1), for a camera path alone. The camera path
 * is an orbit: SetOrbitDegrees() turns the camera that many degrees about
 * the data over the pictures, picture i of n at GetAzimuth(i) = degrees x
 * i / n (so a full turn loops without repeating a picture); 0 (the default)
 * keeps it still.
 *
 * Not wrapped (a program-level helper of tyndall-render and the viewer).
 */

#ifndef vtkTyndallFrameSequence_h
#define vtkTyndallFrameSequence_h

#include "TyndallApplicationModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class TYNDALLAPPLICATION_EXPORT vtkTyndallFrameSequence : public vtkObject
{
public:
  static vtkTyndallFrameSequence* New();
  vtkTypeMacro(vtkTyndallFrameSequence, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The input pattern (numbered files) or 4-D file, the output pattern (or
   * "": no pictures, as in the viewer) and frames `first` to `last`. False,
   * with GetErrorMessage(), for a pattern
   * with more than one frame number or a malformed one, an output without a
   * frame number, an input with none that is no 4-D file (NIfTI), or
   * last < first.
   */
  bool SetUp(const std::string& input, const std::string& output, int first, int last);

  /**
   * Pictures 0 to `count` - 1 of one still scene, named by the output
   * pattern (a camera path alone). False, with GetErrorMessage(), for an
   * output without one frame number or a count below 1.
   */
  bool SetUpStill(const std::string& output, int count);

  /// Whether the pictures are of one still scene (SetUpStill()).
  bool GetStill() const { return this->Still; }

  ///@{
  /**
   * The orbit: the camera turns this many degrees (about the view-up through
   * the focal point) over the pictures; 0, the default, keeps it still.
   */
  void SetOrbitDegrees(double degrees) { this->OrbitDegrees = degrees; }
  double GetOrbitDegrees() const { return this->OrbitDegrees; }
  ///@}

  /// The camera's turn at `frame` from frame First's: degrees x (frame - First) / count.
  double GetAzimuth(int frame) const;

  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }
  int GetFirst() const { return this->First; }
  int GetLast() const { return this->Last; }
  /// Numbered files (the input has a frame number), else a 4-D file's frames.
  bool GetNumberedFiles() const { return this->NumberedFiles; }

  ///@{
  /// The file to read for `frame` (empty for a still scene), the time frame within it, and the
  /// picture's path.
  std::string GetInputPath(int frame) const;
  int GetInputFrame(int frame) const;
  std::string GetOutputPath(int frame) const;
  ///@}

  /**
   * `picture` with a frame number: unchanged when it has one, else "_%04d"
   * before its extension.
   */
  static std::string DefaultOutput(const std::string& picture);

  /**
   * The number of frame numbers in `pattern` (0 or more; -1, with `error`,
   * for a '%' that starts no frame number and is no "%%").
   */
  static int CountFrameNumbers(const std::string& pattern, std::string& error);

  /// Whether `path` names a kind of file with time frames (NIfTI: .nii, .nii.gz).
  static bool IsFourDimensional(const std::string& path);

  /// `pattern` with its frame number (if any) replaced by `frame`, "%%" by '%'.
  static std::string Format(const std::string& pattern, int frame);

protected:
  vtkTyndallFrameSequence() = default;
  ~vtkTyndallFrameSequence() override = default;

private:
  vtkTyndallFrameSequence(const vtkTyndallFrameSequence&) = delete;
  void operator=(const vtkTyndallFrameSequence&) = delete;

  std::string Input;
  std::string Output;
  std::string ErrorMessage;
  int First = 0;
  int Last = 0;
  bool NumberedFiles = false;
  bool Still = false;
  double OrbitDegrees = 0.0;

  bool CheckOutput(const std::string& output, int numbers);
};

#endif
