#pragma once
// Running the `sketchlab` binary from tests (SKETCHLAB_CLI is set by
// tests/CMakeLists.txt) in scratch folders of the build tree.
#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_paths.hpp"

namespace sketchlab::test {

// <build>/tests/tmp/<name>, emptied.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = binary_path("tests/tmp/" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `sketchlab <args>` with stdout and stderr to `log`; the exit status.
inline int run_cli(const std::string& args, const std::filesystem::path& log) {
  return std::system((std::string(SKETCHLAB_CLI) + " " + args + " >" + log.string() + " 2>&1").c_str());
}

}  // namespace sketchlab::test
