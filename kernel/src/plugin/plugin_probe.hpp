#pragma once
// Private to the plugin host: loading a plugin in a throw-away child process
// first (PluginLoadOptions::probe). Whatever the library's load-time code does
// there (static constructors, ELF init functions, the entry point) cannot
// take the host down: a crash or a hang becomes the library's load error.
#include <chrono>
#include <filesystem>
#include <string>

namespace sketchlab::plugin_detail {

// Forks; the child dlopen()s `file` (RTLD_NOW), calls its entry point
// `entry_symbol` and exits. Empty when the child did so and exited normally,
// else the reason ("loading it killed the probe process with signal 7 (Bus
// error)", "loading it did not finish within 10 s"). The child is killed
// after `timeout`. Only the child runs the library's code.
std::string probe_in_child(const std::filesystem::path& file, const char* entry_symbol,
                           std::chrono::milliseconds timeout);

}  // namespace sketchlab::plugin_detail
