#include "sketchlab/viewer/png_image.hpp"

#include <stdexcept>
#include <string>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

namespace sketchlab::viewer {

RgbImage read_png(const std::filesystem::path& png) {
  if (!std::filesystem::is_regular_file(png))
    throw std::runtime_error(png.string() + ": no such file");
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(png.string().c_str()))
    throw std::runtime_error(png.string() + ": not a PNG file");
  reader->SetFileName(png.string().c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  image->GetDimensions(dims);
  const int channels = image->GetNumberOfScalarComponents();
  if (dims[0] <= 0 || dims[1] <= 0 || channels < 1 || channels > 4 ||
      image->GetScalarType() != VTK_UNSIGNED_CHAR)
    throw std::runtime_error(png.string() + ": unsupported PNG (need 8-bit grey/RGB/RGBA)");

  RgbImage out;
  out.width = dims[0];
  out.height = dims[1];
  out.pixels.resize(3 * static_cast<std::size_t>(out.width) * out.height);
  const auto* src = static_cast<const unsigned char*>(image->GetScalarPointer());
  // VTK images start at the bottom row.
  for (int y = 0; y < out.height; ++y) {
    const int vtk_row = out.height - 1 - y;
    for (int x = 0; x < out.width; ++x) {
      const unsigned char* p =
          src + channels * (static_cast<std::size_t>(vtk_row) * out.width + x);
      std::uint8_t* q = out.pixels.data() + 3 * (static_cast<std::size_t>(y) * out.width + x);
      if (channels >= 3) {
        q[0] = p[0], q[1] = p[1], q[2] = p[2];
      } else {
        q[0] = q[1] = q[2] = p[0];
      }
    }
  }
  return out;
}

}  // namespace sketchlab::viewer
