/**
 * @class   vtkTyndallOptions
 * @brief   the one table of options of Tyndall's programs: --help, the parser and the viewer's keys
 *
 * Every option of tyndall-render, tyndall-viewer and the Python examples is
 * one row of a single table (vtkTyndallOptions.cxx): its name, arguments,
 * range, default, help text, which programs take it, and for the viewer the
 * keys that change it. GetHelp() writes the help from the table, Parse()
 * reads a command line by it, and ApplyKey() changes options the way the
 * viewer's keys are documented, so the three can never disagree.
 *
 * Values are read by option name (the long name without "--"): IsSet(),
 * GetNumber(), GetVector(), GetText(), GetChoice(), GetFlag(). Unset options
 * keep their table default (GetNumber() returns it; vtkTyndallSceneBuilder
 * chooses the defaults that depend on the scene). Lights are repeatable:
 * each --light-direction or --light-position adds one, --light-color and
 * --light-intensity change the most recent one. Volumes too: each
 * --add-volume adds one, the --volume-* options change the most recent one.
 *
 * Numbers are parsed strictly: the whole argument, finite, inside the
 * option's documented range. Parse() stops at the first problem and keeps
 * its message (GetErrorMessage()), worded for a user ("--coefficients needs
 * an integer in 1..16, got '20'").
 *
 * @sa vtkTyndallSceneBuilder
 */

#ifndef vtkTyndallOptions_h
#define vtkTyndallOptions_h

#include "TyndallApplicationModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkStringArray;

class TYNDALLAPPLICATION_EXPORT vtkTyndallOptions : public vtkObject
{
public:
  static vtkTyndallOptions* New();
  vtkTypeMacro(vtkTyndallOptions, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The programs; an option belongs to one or both.
  enum Programs
  {
    RENDER = 1, ///< tyndall-render (and the Python examples)
    VIEWER = 2  ///< tyndall-viewer
  };

  ///@{
  /**
   * The program whose options are parsed and documented; default RENDER.
   */
  vtkSetClampMacro(Program, int, RENDER, VIEWER);
  vtkGetMacro(Program, int);
  ///@}

#ifndef __VTK_WRAP__
  /**
   * Parses a command line (argv[0] is the program and is skipped). Returns
   * false at the first problem (see GetErrorMessage()). Earlier values are
   * cleared first.
   */
  bool Parse(int argc, char* argv[]);
#endif

  /**
   * Parses the arguments in `arguments` (without the program's name): the
   * same as Parse(), for Python (sys.argv[1:]).
   */
  bool ParseArguments(vtkStringArray* arguments);

  /**
   * The first problem of the last Parse() ("" when it succeeded).
   */
  const char* GetErrorMessage()
  {
    return this->ErrorMessage.c_str();
  }

  /**
   * Whether -h/--help was given.
   */
  vtkGetMacro(HelpRequested, bool);

  /**
   * The help of the current Program: `description` (the program's own
   * lines), then every option of the program by group, then the viewer's
   * keys for VIEWER.
   */
  std::string GetHelp(const char* description);

  /**
   * The input path ("" for the built-in scene).
   */
  const char* GetInput()
  {
    return this->Input.c_str();
  }

  ///@{
  /**
   * The value of option `name` (its long name without "--"): whether it was
   * given; its number (component `i` of a vector; the table default when
   * unset; 0 for an unknown name, with an error); its vector (3 numbers, or
   * 2 for --size); its text; the index of a choice in the option's list;
   * whether a flag is on.
   */
  bool IsSet(const char* name);
  double GetNumber(const char* name, int i = 0);
  void GetVector(const char* name, double v[3]);
  const char* GetText(const char* name);
  int GetChoice(const char* name);
  bool GetFlag(const char* name);
  ///@}

  ///@{
  /**
   * Sets a number (or component `i`) or a flag as if it had been given.
   * The value is clamped to the option's range. For the viewer's keys and
   * for programs that decide a value themselves.
   */
  void SetNumber(const char* name, double value, int i = 0);
  void SetFlag(const char* name, bool on);
  ///@}

  ///@{
  /**
   * The volumes added with --add-volume, in order (at most
   * MaximumAddedVolumes): the file, and the --volume-* settings given
   * after it (position, scale about the origin, density scale; the preset
   * and transfer-function file, "" when not given).
   */
  static constexpr int MaximumAddedVolumes = 3;
  int GetNumberOfAddedVolumes();
  const char* GetAddedVolumeFile(int volume);
  void GetAddedVolumePosition(int volume, double v[3]);
  double GetAddedVolumeScale(int volume);
  double GetAddedVolumeDensityScale(int volume);
  const char* GetAddedVolumePreset(int volume);
  const char* GetAddedVolumeTransferFunction(int volume);
  ///@}

  ///@{
  /**
   * The lights given on the command line, in order: directional (the
   * direction the light travels) or positional (a point light's position),
   * colour and intensity.
   */
  int GetNumberOfLights();
  bool GetLightPositional(int light);
  void GetLightVector(int light, double v[3]);
  void GetLightColor(int light, double rgb[3]);
  double GetLightIntensity(int light);
  ///@}

  /// The codes ApplyKey() takes for the arrow keys (characters otherwise).
  enum Keys
  {
    KEY_LEFT = 28, ///< the left arrow
    KEY_RIGHT = 29 ///< the right arrow
  };

  /**
   * The viewer's keys: changes the option `key` is bound to (a method
   * number, +/- coefficients, ...) and returns the option's name, or the
   * name of a viewer action ("hud", "reset", "screenshot", "quit", "play",
   * "next-frame", "previous-frame"); nullptr for a key that is not bound.
   * `key` is a character or KEY_LEFT / KEY_RIGHT.
   */
  const char* ApplyKey(int key);

  /**
   * The name of the option or action a viewer key is bound to (what
   * ApplyKey() would change), or nullptr; nothing is changed.
   */
  const char* GetKeyOption(int key);

  /**
   * Whether the option `name` (without "--") applies to the medium only
   * (vtkParticipatingMediumProperty: its model, scattering, emission,
   * densities and scene rules, and its procedural detail with the
   * detail's sampling), which --vtk-property replaces by a plain
   * vtkVolumeProperty: a command line refuses one beside it, and the
   * viewer ignores its keys while it is on.
   */
  static bool IsMediumOption(const std::string& name);

  /**
   * The viewer's key bindings, one line each, for its help.
   */
  std::string GetKeyHelp();

#ifndef __VTK_WRAP__
  ///@{
  /**
   * Strict number parsing, as the options use it: the whole text, finite;
   * ParseInteger() also within [lo, hi]. For programs' own small parsers
   * (the viewer's scripts).
   */
  static bool ParseNumber(const std::string& text, double& value);
  static bool ParseInteger(const std::string& text, int lo, int hi, int& value);
  ///@}
#endif

protected:
  vtkTyndallOptions();
  ~vtkTyndallOptions() override;

  int Program = RENDER;
  bool HelpRequested = false;
  std::string ErrorMessage;
  std::string Input;

private:
  vtkTyndallOptions(const vtkTyndallOptions&) = delete;
  void operator=(const vtkTyndallOptions&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
