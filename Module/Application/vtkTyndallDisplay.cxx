#include "vtkTyndallDisplay.h"

#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"

#include <chrono>
#include <cstdlib>
#include <thread>

#ifdef TYNDALL_HAVE_X11
#include <X11/Xlib.h>
#endif

vtkStandardNewMacro(vtkTyndallDisplay);

//------------------------------------------------------------------------------
vtkTyndallDisplay::~vtkTyndallDisplay()
{
#ifdef TYNDALL_HAVE_X11
  if (this->Connection)
  {
    XCloseDisplay(static_cast<Display*>(this->Connection));
  }
#endif
}

//------------------------------------------------------------------------------
bool vtkTyndallDisplay::Open()
{
  this->ErrorMessage.clear();
  this->Attempts = 0;
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    this->ErrorMessage = "no X display (DISPLAY is not set); Debian's VTK renders through GLX: "
                         "run under xvfb-run -a -s \"-screen 0 1280x1024x24\"";
    return false;
  }
#ifdef TYNDALL_HAVE_X11
  if (this->Connection)
  {
    return true;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  do
  {
    ++this->Attempts;
    this->Connection = XOpenDisplay(nullptr);
    if (!this->Connection)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  } while (!this->Connection && std::chrono::steady_clock::now() < deadline);
  if (!this->Connection)
  {
    this->ErrorMessage = std::string("cannot connect to the X display '") + name + "' (" +
      std::to_string(this->Attempts) + " attempts in 2 s)";
    return false;
  }
  return true;
#else
  this->ErrorMessage = "this build has no X11 support";
  return false;
#endif
}

//------------------------------------------------------------------------------
void vtkTyndallDisplay::Attach(vtkRenderWindow* window)
{
  if (window && this->Connection)
  {
    window->SetDisplayId(this->Connection);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallDisplay::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Connected: " << (this->Connection ? "yes" : "no") << "\n";
  os << indent << "Attempts: " << this->Attempts << "\n";
}
