#pragma once
// Running the `sketchlab` binary from tests (SKETCHLAB_CLI is set by
// tests/CMakeLists.txt) in scratch folders of the build tree.
#include <catch2/catch.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

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

// Runs `command` ("VAR=value ... program args", no other shell syntax) in the
// background through env(1), exec'd so that the signal reaches the program
// itself, with its output in `log`; waits until `log` contains
// `ready` (at most `timeout_s`), sends `signal` and waits for the end.
// status: the exit status, -1 when it did not exit normally (killed,
// crashed) or never became ready (it is then killed).
inline CliRun run_until_then_signal(const std::string& command, const std::filesystem::path& log,
                                    const std::string& ready, int signal, double timeout_s = 60.0) {
  CliRun r;
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const std::string line = "exec env " + command + " >" + log.string() + " 2>&1";
    execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto read_log = [&] {
    std::ifstream in(log);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  bool seen = false, ended = false;
  int status = 0;
  for (double waited = 0; waited < timeout_s && !seen && !ended; waited += 0.02) {
    usleep(20000);
    seen = read_log().find(ready) != std::string::npos;
    ended = !seen && waitpid(pid, &status, WNOHANG) == pid;  // ended before being ready
  }
  if (!ended) {
    kill(pid, seen ? signal : SIGKILL);
    waitpid(pid, &status, 0);
  }
  r.output = read_log();
  r.status = seen && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The files of two folder trees that differ: present in one only, or with
// other bytes (relative paths, sorted); empty when the trees are the same.
inline std::vector<std::string> differing_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  const auto files = [](const std::filesystem::path& root) {
    std::map<std::string, std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(root))
      if (e.is_regular_file()) {
        std::ifstream in(e.path(), std::ios::binary);
        out[std::filesystem::relative(e.path(), root).string()] = std::string(std::istreambuf_iterator<char>(in), {});
      }
    return out;
  };
  const auto fa = files(a), fb = files(b);
  std::set<std::string> names;
  for (const auto& [n, bytes] : fa) names.insert(n);
  for (const auto& [n, bytes] : fb) names.insert(n);
  std::vector<std::string> out;
  for (const auto& n : names)
    if (!fa.count(n) || !fb.count(n) || fa.at(n) != fb.at(n)) out.push_back(n);
  return out;
}

}  // namespace sketchlab::test
