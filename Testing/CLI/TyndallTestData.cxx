#include "TyndallTestData.h"

#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace tyndall_test_data
{
namespace
{
// A minimal DICOM Part 10 writer (explicit VR little endian, one CT slice
// per file, int16 Hounsfield-like values): VTK 9.1 reads DICOM but cannot
// write it, and the tests need a series.
class DicomWriter
{
public:
  void Element(uint16_t group, uint16_t element, const char* vr, std::string value)
  {
    const bool binary = std::strcmp(vr, "OB") == 0 || std::strcmp(vr, "OW") == 0;
    if (value.size() % 2)
    {
      value += std::strcmp(vr, "UI") == 0 || binary ? '\0' : ' ';
    }
    this->U16(group);
    this->U16(element);
    this->Bytes.append(vr, 2);
    if (binary)
    {
      this->U16(0);
      this->U32(static_cast<uint32_t>(value.size()));
    }
    else
    {
      this->U16(static_cast<uint16_t>(value.size()));
    }
    this->Bytes += value;
  }
  void UnsignedShort(uint16_t group, uint16_t element, uint16_t value)
  {
    std::string v(2, '\0');
    v[0] = static_cast<char>(value & 0xff);
    v[1] = static_cast<char>(value >> 8);
    this->Element(group, element, "US", v);
  }
  void U16(uint16_t v)
  {
    this->Bytes += static_cast<char>(v & 0xff);
    this->Bytes += static_cast<char>(v >> 8);
  }
  void U32(uint32_t v)
  {
    this->U16(static_cast<uint16_t>(v & 0xffff));
    this->U16(static_cast<uint16_t>(v >> 16));
  }
  std::string Bytes;
};

}

// A 24 x 20 x 16 float blob, optionally with `components` components.
vtkSmartPointer<vtkImageData> Blob(int components)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(24, 20, 16);
  image->SetSpacing(1.0, 1.0, 1.5);
  vtkNew<vtkFloatArray> values;
  values->SetName("blob");
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  vtkIdType id = 0;
  for (int k = 0; k < 16; ++k)
  {
    for (int j = 0; j < 20; ++j)
    {
      for (int i = 0; i < 24; ++i, ++id)
      {
        const double x = (i - 11.5) / 9.0, y = (j - 9.5) / 8.0, z = (k - 7.5) / 6.0;
        const double r2 = x * x + y * y + z * z;
        for (int c = 0; c < components; ++c)
        {
          values->SetComponent(id, c, (c + 1) * 100.0 * std::exp(-2.0 * r2));
        }
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

bool WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

bool WriteSkyHdr(const std::string& path)
{
  const int width = 64, height = 32;
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
  for (int row = 0; row < height; ++row)
  {
    const int j = height - 1 - row; // from the top; j counts from the bottom
    for (int i = 0; i < width; ++i)
    {
      const bool sun = i >= 36 && i < 40 && (j == 20 || j == 21);
      const double sky[3] = { 0.3, 0.45, 0.8 };
      const double ground[3] = { 0.05, 0.04, 0.03 };
      double rgb[3];
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = sun ? 40.0 : (j >= height / 2 ? sky[c] : ground[c]);
      }
      const double v = std::max(rgb[0], std::max(rgb[1], rgb[2]));
      int e = 0;
      const double m = std::frexp(v, &e) * 256.0 / v;
      const unsigned char rgbe[4] = { static_cast<unsigned char>(rgb[0] * m),
        static_cast<unsigned char>(rgb[1] * m), static_cast<unsigned char>(rgb[2] * m),
        static_cast<unsigned char>(e + 128) };
      out.write(reinterpret_cast<const char*>(rgbe), 4);
    }
  }
  return static_cast<bool>(out);
}

std::string ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

bool WriteDicomSlice(const std::string& path, const DicomSlice& slice)
{
  const std::string sopClass = "1.2.840.10008.5.1.4.1.1.2"; // CT Image Storage
  const std::string instance = "1.2.826.0.1.3680043.9.7433.1." + std::to_string(slice.Index + 1);
  const std::string syntax = "1.2.840.10008.1.2.1"; // explicit VR little endian
  const std::string position =
    slice.Position.empty() ? "0\\0\\" + std::to_string(2 * slice.Index) : slice.Position;
  DicomWriter meta;
  meta.Element(0x0002, 0x0001, "OB", std::string("\0\1", 2));
  meta.Element(0x0002, 0x0002, "UI", sopClass);
  meta.Element(0x0002, 0x0003, "UI", instance);
  meta.Element(0x0002, 0x0010, "UI", syntax);
  DicomWriter data;
  data.Element(0x0008, 0x0016, "UI", sopClass);
  data.Element(0x0008, 0x0018, "UI", instance);
  data.Element(0x0008, 0x0060, "CS", "CT");
  data.Element(0x0010, 0x0010, "PN", "Tyndall^Blob");
  data.Element(0x0018, 0x0050, "DS", "2");
  data.Element(0x0020, 0x000D, "UI", "1.2.826.0.1.3680043.9.7433.2");
  data.Element(0x0020, 0x000E, "UI", "1.2.826.0.1.3680043.9.7433.3");
  data.Element(0x0020, 0x0013, "IS", std::to_string(slice.Index + 1));
  data.Element(0x0020, 0x0032, "DS", position);
  data.Element(0x0020, 0x0037, "DS", slice.Orientation);
  data.Element(0x0020, 0x1041, "DS", std::to_string(2 * slice.Index));
  data.UnsignedShort(0x0028, 0x0002, 1);
  data.Element(0x0028, 0x0004, "CS", "MONOCHROME2");
  data.UnsignedShort(0x0028, 0x0010, static_cast<uint16_t>(slice.Rows));
  data.UnsignedShort(0x0028, 0x0011, static_cast<uint16_t>(slice.Columns));
  data.Element(0x0028, 0x0030, "DS", slice.PixelSpacing);
  data.UnsignedShort(0x0028, 0x0100, 16);
  data.UnsignedShort(0x0028, 0x0101, 16);
  data.UnsignedShort(0x0028, 0x0102, 15);
  data.UnsignedShort(0x0028, 0x0103, 1);
  data.Element(0x0028, 0x1052, "DS", slice.Intercept);
  data.Element(0x0028, 0x1053, "DS", slice.Slope);
  std::string raw(slice.Pixels.size() * 2, '\0');
  for (size_t k = 0; k < slice.Pixels.size(); ++k)
  {
    const uint16_t v = static_cast<uint16_t>(slice.Pixels[k]);
    raw[2 * k] = static_cast<char>(v & 0xff);
    raw[2 * k + 1] = static_cast<char>(v >> 8);
  }
  data.Element(0x7FE0, 0x0010, "OW", raw);

  DicomWriter length;
  length.Element(0x0002, 0x0000, "UL", std::string(4, '\0'));
  const uint32_t metaLength = static_cast<uint32_t>(meta.Bytes.size());
  for (int b = 0; b < 4; ++b)
  {
    length.Bytes[8 + b] = static_cast<char>((metaLength >> (8 * b)) & 0xff);
  }
  std::string file = std::string(128, '\0') + "DICM" + length.Bytes + meta.Bytes + data.Bytes;
  if (slice.KeepBytes > 0 && slice.KeepBytes < file.size())
  {
    file.resize(slice.KeepBytes);
  }
  return WriteText(path, file);
}
}
