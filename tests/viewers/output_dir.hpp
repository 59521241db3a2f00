#pragma once
// Where the viewer tests write their pictures (kept after the run, to look at).
#include <filesystem>

namespace sketchlab::test {

inline std::filesystem::path viewer_output_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "sketchlab_test_viewers";
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace sketchlab::test
