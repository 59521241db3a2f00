#pragma once
// The plugins of this build (SKETCHLAB_BUILD_PLUGIN_DIR, set by
// tests/CMakeLists.txt) loaded once per test binary: loading every plugin
// library is the slow part of a plugin test, and the host is read-only.
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::test {

inline const PluginHost& build_plugin_host() {
  static const PluginHost host = [] {
    PluginHost h;
    h.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
    return h;
  }();
  return host;
}

}  // namespace sketchlab::test
