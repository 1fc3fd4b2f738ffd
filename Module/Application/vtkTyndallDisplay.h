/**
 * @class   vtkTyndallDisplay
 * @brief   an X display connection for a program's render windows, opened patiently
 *
 * Debian's VTK renders through GLX: a vtkXOpenGLRenderWindow opens its own
 * X connection and calls abort() when that fails ("bad X server
 * connection"), a crash for the user. A busy X server (Xvfb under load,
 * many clients connecting at once) does refuse connections for a moment:
 * connect() fails with EAGAIN while its listen queue is full. Open() tries
 * for up to two seconds before it gives up with a clear message, and
 * Attach() gives the connection to a render window, which then does not
 * open its own. The connection is closed when this object is deleted: keep
 * it alive longer than the windows (finalize them first).
 *
 * Not wrapped (a program-level helper). Without X11 at build time Open()
 * fails with a message.
 */

#ifndef vtkTyndallDisplay_h
#define vtkTyndallDisplay_h

#include "TyndallApplicationModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class vtkRenderWindow;

class TYNDALLAPPLICATION_EXPORT vtkTyndallDisplay : public vtkObject
{
public:
  static vtkTyndallDisplay* New();
  vtkTypeMacro(vtkTyndallDisplay, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Connects to $DISPLAY, retrying for up to two seconds. False with
   * GetErrorMessage() set when there is no display or it refuses.
   */
  bool Open();

  /// Gives the connection to `window` (a vtkXOpenGLRenderWindow).
  void Attach(vtkRenderWindow* window);

  const char* GetErrorMessage() { return this->ErrorMessage.c_str(); }

  /// How many attempts the last Open() needed.
  vtkGetMacro(Attempts, int);

protected:
  vtkTyndallDisplay() = default;
  ~vtkTyndallDisplay() override;

private:
  vtkTyndallDisplay(const vtkTyndallDisplay&) = delete;
  void operator=(const vtkTyndallDisplay&) = delete;

  void* Connection = nullptr;
  std::string ErrorMessage;
  int Attempts = 0;
};

#endif
