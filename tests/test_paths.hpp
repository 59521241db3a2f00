#pragma once
// Paths of the source and build trees, set by tests/CMakeLists.txt.
#include <string>

namespace sketchlab::test {
inline std::string source_path(const std::string& rel) { return std::string(SKETCHLAB_SOURCE_DIR) + "/" + rel; }
inline std::string binary_path(const std::string& rel) { return std::string(SKETCHLAB_BINARY_DIR) + "/" + rel; }
}  // namespace sketchlab::test
