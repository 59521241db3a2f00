#include "sketchlab/version.hpp"

namespace sketchlab {

// Compiled into the kernel so a plugin's fingerprint (expanded in the plugin's
// own translation unit) is compared against the host build, not against the
// header the plugin happened to include.
const char* build_fingerprint() { return SKETCHLAB_BUILD_FINGERPRINT; }

}  // namespace sketchlab
