/**
 * @class   vtkTransferFunctionFileReader
 * @brief   reads Tyndall's transfer-function text files into a volume property
 *
 * The format, one entry per line, '#' starts a comment:
 *
 *     opacity <value> <alpha>          alpha in [0, 1]
 *     color <value> <r> <g> <b>        in [0, 1] ("colour" too)
 *     emission <value> <r> <g> <b>     >= 0
 *     unit-distance <d>                world units, > 0, at most once
 *
 * alpha is VTK's scalar opacity: the opacity of a slab unit-distance thick
 * (default 1). At least one opacity line is needed (without one the medium
 * would be empty); without color lines the colour is white. Numbers must be
 * finite.
 *
 * Read() parses FileName; on success the functions are available from the
 * getters and Apply() sets them on a property (the emission colour and
 * nothing else on a vtkParticipatingMediumProperty, when the file has
 * emission lines). On failure Read() reports one error (vtkErrorMacro)
 * naming the file and line, e.g. "tf.txt:3: alpha must be in [0, 1], got 2",
 * and returns false.
 *
 * @sa vtkTransferFunctionPresets vtkParticipatingMediumProperty
 */

#ifndef vtkTransferFunctionFileReader_h
#define vtkTransferFunctionFileReader_h

#include "TyndallMediumModule.h" // For export macro
#include "vtkNew.h"              // For vtkNew
#include "vtkObject.h"

class vtkColorTransferFunction;
class vtkPiecewiseFunction;
class vtkVolumeProperty;

class TYNDALLMEDIUM_EXPORT vtkTransferFunctionFileReader : public vtkObject
{
public:
  static vtkTransferFunctionFileReader* New();
  vtkTypeMacro(vtkTransferFunctionFileReader, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Reads FileName; false (with an error) when it cannot be read or parsed.
   */
  bool Read();

  ///@{
  /**
   * What the last successful Read() found: the opacity, the colour (white
   * without color lines), whether there were emission lines and their
   * colour, and the unit distance (1 by default).
   */
  vtkPiecewiseFunction* GetScalarOpacity() { return this->Opacity; }
  vtkColorTransferFunction* GetColor() { return this->Color; }
  vtkGetMacro(HasEmission, bool);
  vtkColorTransferFunction* GetEmission() { return this->Emission; }
  vtkGetMacro(UnitDistance, double);
  ///@}

  /**
   * Sets the opacity, colour and unit distance of the last Read() on
   * `property`, and the emission colour when the file has one and the
   * property is a vtkParticipatingMediumProperty. False without a
   * successful Read().
   */
  bool Apply(vtkVolumeProperty* property);

  /**
   * The format's description, for a program's --help.
   */
  static const char* GetFormatDescription();

protected:
  vtkTransferFunctionFileReader();
  ~vtkTransferFunctionFileReader() override;

  char* FileName = nullptr;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkColorTransferFunction> Emission;
  bool HasEmission = false;
  double UnitDistance = 1.0;
  bool Valid = false;

private:
  vtkTransferFunctionFileReader(const vtkTransferFunctionFileReader&) = delete;
  void operator=(const vtkTransferFunctionFileReader&) = delete;

  bool ParseLine(const std::string& line, const std::string& where, int& opacityPoints,
    bool& unitDistanceSeen, bool& hasColor);
};

#endif
