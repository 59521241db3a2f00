#pragma once
// What this sketchlab binary is: version, the git commit it was built from
// and the build settings, for the provenance of every run (provenance.hpp).
#include <string>

namespace sketchlab {

struct BuildInfo {
  std::string version;      // SKETCHLAB_KERNEL_VERSION, e.g. "0.1.0"
  std::string git_commit;   // full hash, "-dirty" appended when tracked files had
                            // changes; "unknown" when not built from a checkout
  std::string fingerprint;  // the plugin ABI fingerprint (sketchlab/version.hpp)
  std::string build_type;   // CMAKE_BUILD_TYPE ("Release", "RelWithDebInfo", ...)
  std::string compiler;     // compiler id and version, e.g. "GNU 12.2.0"
  std::string flags;        // CMAKE_CXX_FLAGS with those of the build type
};

// Baked in at build time (cmake/write_build_info.cmake).
BuildInfo build_info();

namespace lab_detail {
// Defined in the generated build_info_values.cpp.
const char* git_commit();
const char* build_type();
const char* compiler();
const char* compile_flags();
}  // namespace lab_detail

}  // namespace sketchlab
