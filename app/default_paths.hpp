#pragma once
#include <filesystem>

namespace sketchlab::cli {

// configs/default.yaml: next to the installed binary
// (<prefix>/share/sketchlab/configs) or, in a build tree, in the source tree.
std::filesystem::path default_experiment();

}  // namespace sketchlab::cli
