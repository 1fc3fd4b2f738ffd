#include "vtkTyndallErrorObserver.h"

#include "vtkObject.h"

#include <algorithm>
#include <cctype>

//------------------------------------------------------------------------------
vtkTyndallErrorObserver* vtkTyndallErrorObserver::New()
{
  return new vtkTyndallErrorObserver;
}

//------------------------------------------------------------------------------
void vtkTyndallErrorObserver::Watch(vtkObject* object)
{
  if (object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
  }
}

//------------------------------------------------------------------------------
void vtkTyndallErrorObserver::Execute(vtkObject*, unsigned long, void* callData)
{
  this->Messages.push_back(
    Simplify(callData ? static_cast<const char*>(callData) : "unknown error"));
}

//------------------------------------------------------------------------------
std::string vtkTyndallErrorObserver::Simplify(const std::string& text)
{
  // "ERROR: In file, line N", "Warning: In ...", "Generic Warning: In ...":
  // drop that line, then an object's "class (0x...): " prefix.
  std::string message = text;
  const auto newline = message.find('\n');
  if (newline != std::string::npos && message.find(": In ") < newline)
  {
    message = message.substr(newline + 1);
    const auto colon = message.find("): ");
    if (message.rfind("vtk", 0) == 0 && colon != std::string::npos &&
      message.find(" (0x") < colon && colon < message.find('\n'))
    {
      message = message.substr(colon + 3);
    }
  }
  while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
  {
    message.pop_back();
  }
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}
