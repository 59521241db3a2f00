#pragma once
#include <filesystem>
#include <string>

namespace sketchlab {

// Writes `content` to `file` (parents created), replacing it atomically: the
// content goes to a temporary file in the same directory which is renamed
// over the target, so readers never see half a file. Throws
// std::runtime_error naming the file on failure.
void write_text_file(const std::filesystem::path& file, const std::string& content);

// Whole file as a string; throws std::runtime_error naming the file.
std::string read_text_file(const std::filesystem::path& file);

}  // namespace sketchlab
