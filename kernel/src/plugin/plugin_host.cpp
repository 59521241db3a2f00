#include "sketchlab/plugin/plugin_host.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <boost/dll/shared_library.hpp>
#include <cstdlib>
#include <optional>
#include <set>
#include <system_error>

#include "elf_check.hpp"
#include "plugin_probe.hpp"

#ifndef SKETCHLAB_PLUGIN_SUBDIR
#define SKETCHLAB_PLUGIN_SUBDIR "lib/sketchlab/plugins"
#endif

namespace sketchlab {

namespace fs = std::filesystem;

namespace {

constexpr const char* entry_symbol = "sketchlab_plugin_entry";

struct FileName {
  PluginKind kind;
  std::string name;
};

// sketchlab_<kind>_<name>.so -> (kind, name); nullopt for any other name.
std::optional<FileName> parse_file_name(const fs::path& file) {
  const std::string prefix = "sketchlab_";
  if (file.extension() != ".so") return std::nullopt;
  std::string stem = file.stem().string();
  if (stem.rfind(prefix, 0) != 0) return std::nullopt;
  stem = stem.substr(prefix.size());
  auto underscore = stem.find('_');
  if (underscore == std::string::npos || underscore + 1 == stem.size()) return std::nullopt;
  try {
    return FileName{plugin_kind_from_string(stem.substr(0, underscore)),
                    stem.substr(underscore + 1)};
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

// Empty when the descriptor is usable for a library named after `expected`.
std::string check_descriptor(const PluginDescriptor& d, const FileName& expected) {
  if (d.kind != expected.kind || d.name != expected.name) {
    return "file name says " + std::string(to_string(expected.kind)) + " '" + expected.name +
           "' but the plugin describes itself as " + std::string(to_string(d.kind)) + " '" +
           d.name + "'";
  }
  const bool has_factory = (d.kind == PluginKind::corrector && d.make_corrector) ||
                           (d.kind == PluginKind::surfacer && d.make_surfacer) ||
                           (d.kind == PluginKind::input && d.make_input);
  if (!has_factory) {
    return "descriptor has no factory for its kind (" + std::string(to_string(d.kind)) + ")";
  }
  if (d.make_pointer_input && d.kind != PluginKind::input) return "a pointer input factory on a non-input plugin";
  if (d.make_controller_input && d.kind != PluginKind::input)
    return "a controller input factory on a non-input plugin";
  if (!d.recording_param.empty()) {
    const auto spec = std::find_if(d.params.begin(), d.params.end(),
                                   [&](const ParamSpec& s) { return s.name == d.recording_param; });
    if (d.kind != PluginKind::input || spec == d.params.end() || spec->type != ParamType::string)
      return "recording_param '" + d.recording_param + "' is not a string parameter of an input";
  }
  std::set<std::string> names;
  for (const auto& spec : d.params) {
    if (spec.name.empty()) return "a parameter has an empty name";
    if (!names.insert(spec.name).second) {
      return "parameter '" + spec.name + "' is declared twice";
    }
    if (spec.type == ParamType::choice && spec.choices.empty()) {
      return "choice parameter '" + spec.name + "' has no choices";
    }
    try {
      validate_param(spec, spec.default_value);
    } catch (const ParamError& e) {
      return std::string("invalid default: ") + e.what();
    }
  }
  return {};
}

void add_existing_dir(std::vector<fs::path>& dirs, std::set<fs::path>& seen, const fs::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  fs::path canonical = fs::canonical(dir, ec);
  if (ec) return;
  if (seen.insert(canonical).second) dirs.push_back(canonical);
}

std::string list_names(const std::vector<LoadedPlugin>& plugins, PluginKind kind) {
  std::vector<std::string> names;
  for (const auto& p : plugins) {
    if (p.descriptor->kind == kind) names.push_back(p.descriptor->name);
  }
  std::sort(names.begin(), names.end());
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

}  // namespace

PluginLoadOptions PluginLoadOptions::from_environment() {
  PluginLoadOptions options;
  const char* probe = std::getenv("SKETCHLAB_PLUGIN_PROBE");
  options.probe = probe && std::string_view(probe) == "1";
  return options;
}

namespace {
// The directory of this libsketchlab: <build>/lib in a build tree,
// <prefix>/lib once installed; empty if unknown.
fs::path kernel_library_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&kernel_library_dir), &info) == 0 || !info.dli_fname) return {};
  return fs::path(info.dli_fname).parent_path();
}
}  // namespace

std::vector<fs::path> PluginHost::default_search_paths() {
  std::vector<fs::path> dirs;
  std::set<fs::path> seen;
  // The user's directories first: the first copy of a name wins, so a
  // plugin there overrides a bundled one.
  if (const char* env = std::getenv("SKETCHLAB_PLUGIN_PATH")) {
    std::string list = env;
    std::size_t start = 0;
    while (start <= list.size()) {
      std::size_t end = list.find(':', start);
      if (end == std::string::npos) end = list.size();
      add_existing_dir(dirs, seen, list.substr(start, end - start));
      start = end + 1;
    }
  }
  // Then the plugins of the tree the executable belongs to (the install
  // tree, or the build tree for a binary run from it; never a build tree's
  // compiled-in path). Only a program outside any sketchlab tree (python3
  // with the module) falls back to the tree of the kernel library it loaded.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path exe_plugins = ec ? fs::path() : exe.parent_path() / ".." / SKETCHLAB_PLUGIN_SUBDIR;
  if (!exe_plugins.empty() && fs::is_directory(exe_plugins, ec)) {
    add_existing_dir(dirs, seen, exe_plugins);
  } else if (const fs::path lib = kernel_library_dir(); !lib.empty()) {
    add_existing_dir(dirs, seen, lib / ".." / SKETCHLAB_PLUGIN_SUBDIR);
  }
  return dirs;
}

void PluginHost::load_directories(const std::vector<fs::path>& dirs) {
  for (const auto& dir : dirs) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
      errors_.push_back({dir, "not a directory"});
      continue;
    }
    std::vector<fs::path> files;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const auto name = it->path().filename().string();
      // Directories and other non-files so named are passed on: load_file
      // reports them instead of skipping them silently.
      if (name.rfind("sketchlab_", 0) == 0 && it->path().extension() == ".so")
        files.push_back(it->path());
    }
    if (ec) {
      errors_.push_back({dir, "cannot list directory: " + ec.message()});
      continue;
    }
    std::sort(files.begin(), files.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
    for (const auto& file : files) load_file(file);
  }
}

bool PluginHost::load_file(const fs::path& file) {
  auto fail = [&](std::string reason) {
    errors_.push_back({file, std::move(reason)});
    return false;
  };

  // The file name is checked before loading so that no code runs from a
  // library the host would reject anyway (and a duplicate is never loaded).
  const auto expected = parse_file_name(file);
  if (!expected) {
    return fail("file name is not sketchlab_<kind>_<name>.so with kind corrector, surfacer or "
                "input");
  }
  if (const LoadedPlugin* earlier = find(expected->kind, expected->name)) {
    return fail(std::string(to_string(expected->kind)) + " '" + expected->name +
                "' is already loaded from " + earlier->path.string() + "; this copy is ignored");
  }

  if (auto problem = plugin_detail::check_elf_library(file); !problem.empty()) return fail(problem);
  if (options_.probe) {
    if (auto problem = plugin_detail::probe_in_child(file, entry_symbol, options_.probe_timeout);
        !problem.empty())
      return fail(problem);
  }

  // RTLD_NOW: an unresolved symbol is reported here, with its name, instead
  // of aborting the process on the first call that needs it.
  auto library = std::make_shared<boost::dll::shared_library>();
  boost::system::error_code ec;
  ::dlerror();  // clear any stale message
  library->load(boost::dll::fs::path(file.string()),
                boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local, ec);
  if (ec || !library->is_loaded()) {
    const char* dl_message = ::dlerror();
    return fail("cannot load library: " + (dl_message ? std::string(dl_message) : ec.message()));
  }
  if (!library->has(entry_symbol)) {
    return fail(std::string("no entry point '") + entry_symbol + "' (not a sketchlab plugin?)");
  }

  const PluginHeader* header = nullptr;
  try {
    header = library->get<const PluginHeader*()>(entry_symbol)();
  } catch (const std::exception& e) {
    return fail(std::string("entry point threw: ") + e.what());
  } catch (...) {
    return fail("entry point threw an unknown exception");
  }
  if (!header) return fail("entry point returned no header");
  if (header->abi_version != plugin_abi_version) {
    return fail("built for ABI " + std::to_string(header->abi_version) + ", host has " +
                std::to_string(plugin_abi_version));
  }
  if (!header->fingerprint) return fail("header has no build fingerprint");
  if (std::string_view(header->fingerprint) != build_fingerprint()) {
    return fail(std::string("plugin built with ") + header->fingerprint + ", host is " +
                build_fingerprint());
  }
  if (!header->descriptor) return fail("header has no descriptor");

  const auto* descriptor = static_cast<const PluginDescriptor*>(header->descriptor);
  if (auto problem = check_descriptor(*descriptor, *expected); !problem.empty()) {
    return fail(problem);
  }
  plugins_.push_back({file, descriptor, std::shared_ptr<void>(library, library.get())});
  return true;
}

const LoadedPlugin* PluginHost::find(PluginKind kind, const std::string& name) const {
  for (const auto& p : plugins_) {
    if (p.descriptor->kind == kind && p.descriptor->name == name) return &p;
  }
  return nullptr;
}

namespace {

// The plugin `name` of `kind`; throws PluginError naming why it is missing
// (a copy that did not load) and the plugins of that kind that are loaded.
const LoadedPlugin& require_plugin(const PluginHost& host, PluginKind kind, const std::string& name) {
  const LoadedPlugin* plugin = host.find(kind, name);
  if (!plugin) {
    std::string message = "unknown " + std::string(to_string(kind)) + " '" + name + "'";
    const std::string file = "sketchlab_" + std::string(to_string(kind)) + "_" + name + ".so";
    for (const auto& error : host.errors()) {
      if (error.path.filename() == file) {
        message += " (" + error.path.string() + " did not load: " + error.reason + ")";
        break;
      }
    }
    const std::string available = list_names(host.plugins(), kind);
    message += available.empty() ? "; no " + std::string(to_string(kind)) + " plugins are loaded"
                                 : "; available: " + available;
    throw PluginError(message);
  }
  return *plugin;
}

template <class T>
std::shared_ptr<T> make_object(const PluginHost& host, PluginKind kind, const std::string& name,
                               const std::map<std::string, ParamValue>& given,
                               Factory<T> PluginDescriptor::*factory) {
  const LoadedPlugin* plugin = &require_plugin(host, kind, name);

  // ParamError propagates unchanged: callers map its parameter name back to
  // the config line that set it.
  const Params params = validate_params(plugin->descriptor->params, given);

  std::string error;
  std::unique_ptr<T> object;
  try {
    object = (plugin->descriptor->*factory)(params, error);
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown exception";
  }
  if (!object) {
    throw PluginError("plugin '" + name + "' failed to start: " +
                      (error.empty() ? std::string("no reason given") : error));
  }
  // The deleter owns a reference to the library: the object's code (its
  // destructor included) stays mapped until the object is gone, whatever
  // happens to the host.
  return std::shared_ptr<T>(object.release(),
                            [library = plugin->library](T* p) { delete p; });
}

}  // namespace

Params PluginHost::resolve_params(PluginKind kind, const std::string& name,
                                  const std::map<std::string, ParamValue>& params) const {
  return validate_params(require_plugin(*this, kind, name).descriptor->params, params);
}

std::shared_ptr<Corrector> PluginHost::make_corrector(
    const std::string& name, const std::map<std::string, ParamValue>& params) const {
  return make_object<Corrector>(*this, PluginKind::corrector, name, params,
                                &PluginDescriptor::make_corrector);
}

std::shared_ptr<Surfacer> PluginHost::make_surfacer(
    const std::string& name, const std::map<std::string, ParamValue>& params) const {
  return make_object<Surfacer>(*this, PluginKind::surfacer, name, params,
                               &PluginDescriptor::make_surfacer);
}

std::shared_ptr<Input> PluginHost::make_input(const std::string& name,
                                              const std::map<std::string, ParamValue>& params) const {
  return make_object<Input>(*this, PluginKind::input, name, params, &PluginDescriptor::make_input);
}

namespace {

// The loaded input plugins whose descriptors set `factory`, in name order.
template <class T>
std::vector<std::string> input_names_with(const std::vector<LoadedPlugin>& plugins,
                                          Factory<T> PluginDescriptor::*factory) {
  std::vector<std::string> names;
  for (const auto& p : plugins)
    if (p.descriptor->kind == PluginKind::input && p.descriptor->*factory) names.push_back(p.descriptor->name);
  std::sort(names.begin(), names.end());
  return names;
}

// An input of a typed kind (`what`: "pointer", "controller"); refuses, naming
// the plugins that make one, an input plugin that does not.
template <class T>
std::shared_ptr<T> make_typed_input(const PluginHost& host, const std::string& name,
                                    const std::map<std::string, ParamValue>& params,
                                    Factory<T> PluginDescriptor::*factory, const std::string& what) {
  if (const LoadedPlugin* plugin = host.find(PluginKind::input, name); plugin && !(plugin->descriptor->*factory)) {
    std::string known;
    for (const auto& n : input_names_with(host.plugins(), factory)) known += (known.empty() ? "" : ", ") + n;
    throw PluginError("input '" + name + "' is not a " + what + " input; " + what + " inputs: " +
                      (known.empty() ? std::string("none loaded") : known));
  }
  return make_object<T>(host, PluginKind::input, name, params, factory);
}

}  // namespace

std::vector<std::string> PluginHost::pointer_input_names() const {
  return input_names_with(plugins_, &PluginDescriptor::make_pointer_input);
}

std::shared_ptr<PointerInput> PluginHost::make_pointer_input(
    const std::string& name, const std::map<std::string, ParamValue>& params) const {
  return make_typed_input(*this, name, params, &PluginDescriptor::make_pointer_input, "pointer");
}

std::vector<std::string> PluginHost::controller_input_names() const {
  return input_names_with(plugins_, &PluginDescriptor::make_controller_input);
}

std::shared_ptr<ControllerInput> PluginHost::make_controller_input(
    const std::string& name, const std::map<std::string, ParamValue>& params) const {
  return make_typed_input(*this, name, params, &PluginDescriptor::make_controller_input, "controller");
}

}  // namespace sketchlab
