#include "python_interpreter.hpp"

#include <dlfcn.h>
#include <pybind11/embed.h>

#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

namespace sketchlab::python_corrector {
namespace {

namespace py = pybind11;
namespace fs = std::filesystem;

// The directory this plugin library was loaded from.
fs::path plugin_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&plugin_dir), &info) == 0 || !info.dli_fname) return {};
  return fs::path(info.dli_fname).parent_path();
}

void start_embedded() {
  // The host loads plugins with RTLD_LOCAL, which hides libpython's symbols
  // from the extension modules Python imports (numpy's do not link
  // libpython): make them global, as a python3 process has them.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&Py_IsInitialized), &info) != 0 && info.dli_fname)
    dlopen(info.dli_fname, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD);
  // The interpreter is never finalised, so it outlives the host's unloading
  // of this plugin while holding pybind11's state and functions in it: the
  // plugin stays mapped (and LeakSanitizer can name it, tests/lsan.supp).
  if (dladdr(reinterpret_cast<void*>(&start_embedded), &info) != 0 && info.dli_fname)
    dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);

  PyConfig config;
  PyConfig_InitPythonConfig(&config);
  config.install_signal_handlers = 0;  // the host owns SIGINT/SIGTERM (run/stop_signals.hpp)
  config.parse_argv = 0;
  // The interpreter the module was built for: its prefix gives sys.path
  // (not whichever python3 comes first on PATH).
  PyStatus status = PyConfig_SetBytesString(&config, &config.program_name, SKETCHLAB_PYTHON_EXECUTABLE);
  if (!PyStatus_Exception(status)) status = Py_InitializeFromConfig(&config);
  PyConfig_Clear(&config);
  if (PyStatus_Exception(status))
    throw std::runtime_error(std::string("python corrector: cannot start Python (") +
                             SKETCHLAB_PYTHON_EXECUTABLE + "): " + (status.err_msg ? status.err_msg : "unknown error"));
}

// The `sketchlab` package for an interpreter started here: the install
// tree's (this plugin is in <prefix>/SKETCHLAB_PLUGIN_SUBDIR, the package in
// <prefix>/SKETCHLAB_PYTHON_INSTALL_DIR), then the build tree's.
void add_package_paths() {
  fs::path prefix = plugin_dir();
  for (const auto& part : fs::path(SKETCHLAB_PLUGIN_SUBDIR)) {
    (void)part;
    prefix = prefix.parent_path();
  }
  py::list path = py::module_::import("sys").attr("path");
  for (const fs::path& dir : {prefix / SKETCHLAB_PYTHON_INSTALL_DIR, fs::path(SKETCHLAB_PYTHON_BUILD_DIR)}) {
    std::error_code ec;
    if (fs::is_directory(dir / "sketchlab", ec)) path.append(fs::weakly_canonical(dir, ec).string());
  }
}

}  // namespace

void ensure_interpreter() {
  static std::once_flag once;
  static bool started_here = false;
  std::call_once(once, [] {
    if (Py_IsInitialized()) return;
    start_embedded();
    started_here = true;
    PyEval_SaveThread();  // free the GIL for gil_scoped_acquire in any thread
  });
  py::gil_scoped_acquire gil;
  try {
    static std::once_flag paths;
    if (started_here) std::call_once(paths, add_package_paths);
    // Registers the kernel types the class receives and returns.
    py::module_::import("sketchlab");
  } catch (py::error_already_set& e) {
    throw std::runtime_error(std::string("python corrector: cannot import sketchlab: ") + e.what());
  }
}

}  // namespace sketchlab::python_corrector
