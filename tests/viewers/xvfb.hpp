#pragma once
// Gives a test an X display: when $DISPLAY is unset, starts a private Xvfb
// (Debian's VTK renders offscreen through X) and stops it at the end, so
// `ctest` works without xvfb-run. Xvfb picks a free display number itself
// and reports it on a pipe once it accepts connections (-displayfd).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace sketchlab::test {

class Xvfb {
 public:
  Xvfb() {
    if (const char* d = std::getenv("DISPLAY"); d && *d) return;  // use the caller's display
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("Xvfb: pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("Xvfb: fork failed");
    if (pid_ == 0) {
      close(fds[0]);
      // Dies with the test process even when that one crashes or aborts.
      prctl(PR_SET_PDEATHSIG, SIGTERM);
      const std::string fd = std::to_string(fds[1]);
      // No -noreset, as with xvfb-run: the renderer must cope with resets.
      // Quiet: Xvfb's informational messages go to /dev/null.
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) dup2(null, STDERR_FILENO), dup2(null, STDOUT_FILENO);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24",
             "-nolisten", "tcp", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    // Up to 20 s: the machine may be loaded.
    for (int waited = 0; waited < 200; ++waited) {
      if (poll(&p, 1, 100) > 0) {
        char c;
        const ssize_t r = read(fds[0], &c, 1);
        if (r <= 0 || c == '\n') break;
        number.push_back(c);
      }
    }
    close(fds[0]);
    if (number.empty()) {
      stop();
      throw std::runtime_error("Xvfb did not start (is the xvfb package installed?)");
    }
    display_ = ":" + number;
    setenv("DISPLAY", display_.c_str(), 1);
  }
  ~Xvfb() {
    if (pid_ > 0) unsetenv("DISPLAY");
    stop();
  }
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;

  // The display started here (empty when $DISPLAY was already set).
  const std::string& started_display() const { return display_; }

 private:
  void stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  pid_t pid_ = -1;
  std::string display_;
};

// One Xvfb for the whole test executable, started on first use.
inline void ensure_display() {
  static Xvfb server;
  (void)server;
}

}  // namespace sketchlab::test
