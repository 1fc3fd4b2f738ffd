#include "vtkTyndallFrameSequence.h"

#include "vtkObjectFactory.h"

#include <cctype>
#include <cstdio>

vtkStandardNewMacro(vtkTyndallFrameSequence);

namespace
{
// The frame number starting at pattern[i] == '%': its length (the '%' to
// the 'd'), 0 for "%%", -1 for anything else.
int FrameNumberLength(const std::string& pattern, size_t i)
{
  size_t j = i + 1;
  if (j < pattern.size() && pattern[j] == '%')
  {
    return 0;
  }
  while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && j - i <= 2)
  {
    ++j;
  }
  return j < pattern.size() && pattern[j] == 'd' ? static_cast<int>(j - i + 1) : -1;
}
}

//------------------------------------------------------------------------------
bool vtkTyndallFrameSequence::IsFourDimensional(const std::string& path)
{
  std::string lower = path;
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  auto endsWith = [&lower](const std::string& end)
  {
    return lower.size() >= end.size() &&
      lower.compare(lower.size() - end.size(), end.size(), end) == 0;
  };
  return endsWith(".nii") || endsWith(".nii.gz");
}

//------------------------------------------------------------------------------
int vtkTyndallFrameSequence::CountFrameNumbers(const std::string& pattern, std::string& error)
{
  int count = 0;
  for (size_t i = 0; i < pattern.size(); ++i)
  {
    if (pattern[i] != '%')
    {
      continue;
    }
    const int length = FrameNumberLength(pattern, i);
    if (length < 0)
    {
      error = "'" + pattern + "' has a '%' that is no frame number (%d, %4d or %04d: at most " +
        "2 digits) and no '%%'";
      return -1;
    }
    count += length > 0 ? 1 : 0;
    i += length > 0 ? length - 1 : 1;
  }
  return count;
}

//------------------------------------------------------------------------------
std::string vtkTyndallFrameSequence::Format(const std::string& pattern, int frame)
{
  std::string out;
  for (size_t i = 0; i < pattern.size(); ++i)
  {
    const int length = pattern[i] == '%' ? FrameNumberLength(pattern, i) : -1;
    if (length > 0)
    {
      char number[128]; // a width of at most 99
      std::snprintf(number, sizeof(number), pattern.substr(i, length).c_str(), frame);
      out += number;
      i += length - 1;
    }
    else if (length == 0)
    {
      out += '%';
      ++i;
    }
    else
    {
      out += pattern[i];
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::string vtkTyndallFrameSequence::DefaultOutput(const std::string& picture)
{
  std::string error;
  if (CountFrameNumbers(picture, error) > 0)
  {
    return picture;
  }
  const size_t dot = picture.find_last_of('.');
  const size_t slash = picture.find_last_of('/');
  const bool extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return extension ? picture.substr(0, dot) + "_%04d" + picture.substr(dot) : picture + "_%04d";
}

//------------------------------------------------------------------------------
bool vtkTyndallFrameSequence::SetUp(
  const std::string& input, const std::string& output, int first, int last)
{
  this->ErrorMessage.clear();
  std::string error;
  const int inputNumbers = CountFrameNumbers(input, error);
  const int outputNumbers = inputNumbers < 0 ? 0 : CountFrameNumbers(output, error);
  if (inputNumbers < 0 || outputNumbers < 0)
  {
    this->ErrorMessage = error;
    return false;
  }
  if (inputNumbers > 1 || outputNumbers > 1)
  {
    this->ErrorMessage = "'" + (inputNumbers > 1 ? input : output) +
      "' has more than one frame number; a sequence's names have one";
    return false;
  }
  if (!this->CheckOutput(output, outputNumbers))
  {
    return false;
  }
  if (inputNumbers == 0 && !IsFourDimensional(input))
  {
    this->ErrorMessage = "'" + input +
      "' has no frame number (e.g. smoke_%04d.vdb for numbered files) and is no file with time "
      "frames (NIfTI: .nii, .nii.gz)";
    return false;
  }
  if (last < first)
  {
    this->ErrorMessage = "the sequence's last frame (" + std::to_string(last) +
      ") comes before its first (" + std::to_string(first) + ")";
    return false;
  }
  this->Input = input;
  this->Output = output;
  this->First = first;
  this->Last = last;
  this->NumberedFiles = inputNumbers == 1;
  this->Still = false;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallFrameSequence::CheckOutput(const std::string& output, int numbers)
{
  if (numbers == 0 && !output.empty())
  {
    this->ErrorMessage = "the pictures of a sequence need a frame number in their name: '" +
      output + "' has none (e.g. " + DefaultOutput(output) + ")";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTyndallFrameSequence::SetUpStill(const std::string& output, int count)
{
  this->ErrorMessage.clear();
  std::string error;
  const int numbers = CountFrameNumbers(output, error);
  if (numbers < 0 || numbers > 1)
  {
    this->ErrorMessage = numbers < 0
      ? error
      : "'" + output + "' has more than one frame number; a sequence's names have one";
    return false;
  }
  if (!this->CheckOutput(output, numbers))
  {
    return false;
  }
  if (count < 1)
  {
    this->ErrorMessage = "a sequence has at least one picture (" + std::to_string(count) + ")";
    return false;
  }
  this->Input.clear();
  this->Output = output;
  this->First = 0;
  this->Last = count - 1;
  this->NumberedFiles = false;
  this->Still = true;
  return true;
}

//------------------------------------------------------------------------------
double vtkTyndallFrameSequence::GetAzimuth(int frame) const
{
  return this->OrbitDegrees * (frame - this->First) / (this->Last - this->First + 1);
}

//------------------------------------------------------------------------------
std::string vtkTyndallFrameSequence::GetInputPath(int frame) const
{
  if (this->Still)
  {
    return std::string();
  }
  return this->NumberedFiles ? Format(this->Input, frame) : Format(this->Input, 0);
}

//------------------------------------------------------------------------------
int vtkTyndallFrameSequence::GetInputFrame(int frame) const
{
  return this->NumberedFiles ? 0 : frame;
}

//------------------------------------------------------------------------------
std::string vtkTyndallFrameSequence::GetOutputPath(int frame) const
{
  return Format(this->Output, frame);
}

//------------------------------------------------------------------------------
void vtkTyndallFrameSequence::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input << "\n";
  os << indent << "Output: " << this->Output << "\n";
  os << indent << "First: " << this->First << "\n";
  os << indent << "Last: " << this->Last << "\n";
  os << indent << "NumberedFiles: " << this->NumberedFiles << "\n";
  os << indent << "Still: " << this->Still << "\n";
  os << indent << "OrbitDegrees: " << this->OrbitDegrees << "\n";
}
