/**
 * @class   vtkTyndallErrorObserver
 * @brief   collects the error messages of VTK objects as one-line texts, for programs
 *
 * Tyndall's programs report a failure as one line on stderr, and
 * vtkVolumeFileReader reports an inner reader's failure as its own. Watch()
 * an object and its vtkErrorMacro messages ("ERROR: In file, line N\nclass
 * (0x...): text\n\n") are kept as "text" (GetMessages()) instead of being
 * printed. Not wrapped (Python has its own error handling).
 */

#ifndef vtkTyndallErrorObserver_h
#define vtkTyndallErrorObserver_h

#include "TyndallCoreModule.h" // For export macro
#include "vtkCommand.h"

#include <string> // For std::string
#include <vector> // For std::vector

class TYNDALLCORE_EXPORT vtkTyndallErrorObserver : public vtkCommand
{
public:
  static vtkTyndallErrorObserver* New();
  vtkBaseTypeMacro(vtkTyndallErrorObserver, vtkCommand);

  /// Collects `object`'s errors from now on.
  void Watch(vtkObject* object);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override;

  /// The messages collected so far, oldest first.
  const std::vector<std::string>& GetMessages() const { return this->Messages; }
  bool HasErrors() const { return !this->Messages.empty(); }
  void Clear() { this->Messages.clear(); }

  /// "ERROR: In file, line N\nclass (0x...): text\n\n" -> "text".
  static std::string Simplify(const std::string& message);

protected:
  vtkTyndallErrorObserver() = default;
  ~vtkTyndallErrorObserver() override = default;

private:
  vtkTyndallErrorObserver(const vtkTyndallErrorObserver&) = delete;
  void operator=(const vtkTyndallErrorObserver&) = delete;

  std::vector<std::string> Messages;
};

#endif
