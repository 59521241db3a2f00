#include "plugin_probe.hpp"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sketchlab::plugin_detail {

namespace {

// Exit codes of the child, unlikely to be a library's own exit(status).
constexpr int child_loaded = 87;
constexpr int child_dlopen_failed = 88;
constexpr int child_no_entry = 89;

[[noreturn]] void run_child(const char* file, const char* entry_symbol) {
  // A crash ends the child with its own signal, not through the handlers it
  // inherited from the host (a sanitizer's report then abort(), a test
  // framework's failure report, the host's stop handlers).
  for (const int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGINT, SIGTERM}) ::signal(sig, SIG_DFL);
  void* handle = ::dlopen(file, RTLD_NOW | RTLD_LOCAL);
  if (!handle) ::_exit(child_dlopen_failed);
  using Entry = const void* (*)();
  auto entry = reinterpret_cast<Entry>(::dlsym(handle, entry_symbol));
  if (!entry) ::_exit(child_no_entry);
  entry();
  // _exit: no static destructors, no atexit handlers of the host copy.
  ::_exit(child_loaded);
}

}  // namespace

std::string probe_in_child(const std::filesystem::path& file, const char* entry_symbol,
                           std::chrono::milliseconds timeout) {
  // The pipe's write end closes when the child ends, however it ends: the
  // parent waits on it with a timeout instead of polling waitpid.
  int done[2];
  if (::pipe(done) != 0) return std::string("probe: pipe failed: ") + std::strerror(errno);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(done[0]);
    ::close(done[1]);
    return std::string("probe: fork failed: ") + std::strerror(errno);
  }
  if (pid == 0) {
    ::close(done[0]);
    run_child(file.c_str(), entry_symbol);
  }
  ::close(done[1]);
  pollfd fd{done[0], POLLIN, 0};
  int ready;
  do ready = ::poll(&fd, 1, static_cast<int>(timeout.count()));
  while (ready < 0 && errno == EINTR);
  ::close(done[0]);
  const bool timed_out = ready == 0;
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out)
    return "loading it in a probe process did not finish within " +
           std::to_string(timeout.count()) + " ms (load-time code hangs?)";
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return "loading it killed the probe process with signal " + std::to_string(sig) + " (" +
           ::strsignal(sig) + ")";
  }
  if (WIFEXITED(status)) {
    switch (WEXITSTATUS(status)) {
      case child_loaded: return {};
      // The host's own dlopen reports these with the loader's message.
      case child_dlopen_failed:
      case child_no_entry: return {};
      default:
        return "its load-time code exited the probe process with status " +
               std::to_string(WEXITSTATUS(status));
    }
  }
  return "the probe process ended abnormally";
}

}  // namespace sketchlab::plugin_detail
