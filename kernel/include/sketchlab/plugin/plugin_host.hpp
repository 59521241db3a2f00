#pragma once
// Finds, checks and loads plugin libraries (Boost.DLL).
//
// A plugin file is a shared library named sketchlab_<kind>_<name>.so. Before
// dlopen() the host checks the file itself: a regular file holding an ELF
// shared object for this machine whose segments all lie inside the file (a
// truncated library would otherwise kill the process with SIGBUS inside the
// loader). After loading it reads the PluginHeader, checks the ABI version and
// build fingerprint before anything else, then the descriptor (kind and name
// match the file name, parameter defaults satisfy their own specs). A library
// failing any check is recorded in errors() with its path and reason; the
// others still load. Libraries are never unloaded before the host and every
// object they created are gone: objects hold a reference to their library.
//
// What the checks cannot stop: a library's load-time code (static
// constructors, ELF init functions, the entry point) runs inside the host
// with its rights, and so does every plugin call. PluginLoadOptions::probe
// runs the load-time code in a child process first, so a library that
// crashes or hangs while loading is reported instead of taking the host down;
// it is no sandbox for malicious code (README.md, "Broken and untrusted plugin files").
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sketchlab/plugin/plugin_api.hpp"

namespace sketchlab {

struct LoadedPlugin {
  std::filesystem::path path;
  const PluginDescriptor* descriptor = nullptr;  // owned by the library
  std::shared_ptr<void> library;                 // keeps the library loaded
};

struct PluginLoadError {
  std::filesystem::path path;
  std::string reason;
};

// Thrown by the make_* functions: unknown plugin (the message lists the
// available ones), invalid parameters (ParamError message), factory failure.
struct PluginError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PluginLoadOptions {
  // Load every library once in a forked child before loading it here (one
  // fork + dlopen per library; see README.md, "Broken and untrusted plugin
  // files").
  bool probe = false;
  std::chrono::milliseconds probe_timeout{10000};
  // probe = true when the environment sets SKETCHLAB_PLUGIN_PROBE=1.
  static PluginLoadOptions from_environment();
};

class PluginHost {
 public:
  explicit PluginHost(PluginLoadOptions options = PluginLoadOptions::from_environment())
      : options_(options) {}

  // Each entry of SKETCHLAB_PLUGIN_PATH (colon-separated) first, so that a
  // user's plugin overrides a bundled one of the same name; then the plugin
  // directory of the executable's tree (<exe>/../lib/sketchlab/plugins: the
  // install tree, or the build tree for a binary run from it). Only when the
  // executable has none (python3 loading the module) the one of the tree the
  // kernel library belongs to (<libdir>/../lib/sketchlab/plugins). Existing
  // directories only, without duplicates.
  static std::vector<std::filesystem::path> default_search_paths();

  // Loads every sketchlab_*.so in the directories (sorted by file name). A
  // plugin name already loaded from an earlier directory is skipped (first
  // wins) and noted in errors(), as is an entry so named that is not a
  // regular file (a directory, a FIFO).
  void load_directories(const std::vector<std::filesystem::path>& dirs);
  // Loads one library; returns false and records the reason on failure.
  bool load_file(const std::filesystem::path& file);

  const std::vector<LoadedPlugin>& plugins() const { return plugins_; }
  const std::vector<PluginLoadError>& errors() const { return errors_; }

  const LoadedPlugin* find(PluginKind kind, const std::string& name) const;

  // Every parameter of plugin `name` of `kind`, defaults filled in, validated
  // like make_*; creates nothing. Throws PluginError (unknown plugin, naming
  // the available ones) or ParamError.
  Params resolve_params(PluginKind kind, const std::string& name,
                        const std::map<std::string, ParamValue>& params) const;

  // Validates `params` against the plugin's specs and creates the object. The
  // returned pointer keeps the library loaded.
  std::shared_ptr<Corrector> make_corrector(const std::string& name,
                                            const std::map<std::string, ParamValue>& params) const;
  std::shared_ptr<Surfacer> make_surfacer(const std::string& name,
                                          const std::map<std::string, ParamValue>& params) const;
  std::shared_ptr<Input> make_input(const std::string& name,
                                    const std::map<std::string, ParamValue>& params) const;
  // A live pointer input (pointer_input.hpp); throws PluginError when the
  // input plugin `name` is not one (naming those that are).
  std::shared_ptr<PointerInput> make_pointer_input(const std::string& name,
                                                   const std::map<std::string, ParamValue>& params) const;
  // The loaded input plugins that make pointer inputs, in name order.
  std::vector<std::string> pointer_input_names() const;
  // A live controller input for an application's OpenXR session
  // (controller_input.hpp); throws PluginError when the input plugin `name`
  // is not one (naming those that are).
  std::shared_ptr<ControllerInput> make_controller_input(const std::string& name,
                                                         const std::map<std::string, ParamValue>& params) const;
  // The loaded input plugins that make controller inputs, in name order.
  std::vector<std::string> controller_input_names() const;

 private:
  PluginLoadOptions options_;
  std::vector<LoadedPlugin> plugins_;
  std::vector<PluginLoadError> errors_;
};

}  // namespace sketchlab
