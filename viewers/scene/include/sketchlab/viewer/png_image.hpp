#pragma once
// PNG pictures as plain pixels, for tests and reports that inspect what the
// renderer wrote without including VTK.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sketchlab::viewer {

struct RgbImage {
  int width = 0, height = 0;
  // Row-major from the TOP row down (as the picture is viewed), 3 bytes per
  // pixel.
  std::vector<std::uint8_t> pixels;

  const std::uint8_t* at(int x, int y) const {
    return pixels.data() + 3 * (static_cast<std::size_t>(y) * width + x);
  }
};

// Throws std::runtime_error when the file is missing or not a PNG. Grey and
// alpha channels are converted to RGB.
RgbImage read_png(const std::filesystem::path& png);

}  // namespace sketchlab::viewer
