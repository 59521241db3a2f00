#pragma once
// Runs the real `sketchlab view` window under the test's X display and
// drives it with xdotool (XTEST: real X input events, not mocks).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "../xvfb.hpp"

namespace sketchlab::test {

// A private X server for this test process even when $DISPLAY is set:
// xdotool's pointer and keyboard are per display, so tests running in
// parallel on one shared display would steer each other's windows.
inline void ensure_private_display() {
  static const bool cleared = (unsetenv("DISPLAY"), true);
  static Xvfb server;
  (void)cleared;
}

// Output of a shell command (stdout), and its exit status.
inline std::pair<int, std::string> shell(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return {-1, out};
  char buf[256];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

inline bool wait_for(const std::function<bool()>& done, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

// The viewer process; killed at destruction if still running.
class ViewerProcess {
 public:
  ViewerProcess(const std::vector<std::string>& args, const std::filesystem::path& log) {
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      std::FILE* f = std::fopen(log.c_str(), "w");
      if (f) dup2(fileno(f), STDOUT_FILENO), dup2(fileno(f), STDERR_FILENO);
      std::vector<char*> argv;
      argv.push_back(const_cast<char*>(SKETCHLAB_CLI));
      for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      execv(SKETCHLAB_CLI, argv.data());
      _exit(127);
    }
    // The window, by name, once mapped.
    const auto [rc, out] = shell("timeout 60 xdotool search --sync --onlyvisible --name '^sketchlab view$' | head -1");
    window_ = out.substr(0, out.find('\n'));
    if (rc != 0 || window_.empty()) throw std::runtime_error("the viewer window did not appear");
  }
  ~ViewerProcess() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  const std::string& window() const { return window_; }

  // Runs `xdotool <args>`; true on success.
  bool xdotool(const std::string& args) const { return shell("xdotool " + args).first == 0; }
  void key(const std::string& k) const {
    xdotool("mousemove --window " + window_ + " 5 60");  // keys go to the window under focus
    xdotool("key --clearmodifiers " + k);
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
  }
  // A left-button drag through `points` (window pixels, origin top-left),
  // 20 ms a step at the least: a hand's pace, not a burst (the cassie stack
  // ends a curve 0.02 s of motion before its last sample).
  void drag(const std::vector<std::pair<int, int>>& points) const {
    auto move = [&](std::pair<int, int> p) {
      xdotool("mousemove --window " + window_ + " " + std::to_string(p.first) + " " +
              std::to_string(p.second));
    };
    move(points.front());
    xdotool("mousedown 1");
    for (std::size_t i = 1; i < points.size(); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      move(points[i]);
    }
    xdotool("mouseup 1");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  // Exit status once the process ends within `seconds`, else -1.
  int wait_exit(double seconds) {
    int status = 0;
    const bool ok = wait_for([&] { return waitpid(pid_, &status, WNOHANG) == pid_; }, seconds);
    if (!ok) return -1;
    exited_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  std::string window_;
};

}  // namespace sketchlab::test
