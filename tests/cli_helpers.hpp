#pragma once
// Running the `sketchlab` binary from tests (SKETCHLAB_CLI is set by
// tests/CMakeLists.txt) in scratch folders of the build tree.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdio>
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

// What run_captured saw: the exit status (-1 when the command did not exit
// normally, e.g. a crash) and stdout and stderr interleaved.
struct CliRun {
  int status = -1;
  std::string output;
};

// Runs a shell `command` (env prefixes, `cd ... &&` allowed) and captures its
// output, for tests that assert on what the CLI prints rather than on a log.
inline CliRun run_captured(const std::string& command) {
  CliRun r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe);
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace sketchlab::test
