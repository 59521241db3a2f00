#pragma once
// Run folders that never collide: two runs started in the same second, in
// one process or in two, each get their own, and nothing that exists is
// reused or overwritten.
#include <filesystem>
#include <string>

namespace sketchlab {

// Creates and returns <parent>/<name>, or <parent>/<name>-2, -3, ... when
// that exists (a file or a folder), creating `parent` first. Each candidate
// is claimed with one mkdir, which fails when another process got there
// first, so concurrent callers never share a folder. Throws
// std::runtime_error naming the folder when it cannot be created.
std::filesystem::path create_unique_folder(const std::filesystem::path& parent, const std::string& name);

}  // namespace sketchlab
