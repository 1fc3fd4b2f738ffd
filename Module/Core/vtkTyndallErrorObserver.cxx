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
  std::string message = text;
  const auto newline = message.find('\n');
  if (message.rfind("ERROR: In ", 0) == 0 && newline != std::string::npos)
  {
    message = message.substr(newline + 1);
    const auto colon = message.find("): ");
    if (colon != std::string::npos)
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
