#pragma once
// The one timestamp format of file and folder names the tools choose
// (run folders, live and VR recordings): UTC, "YYYYMMDD-HHMMSS".
#include <string>

namespace sketchlab {

std::string utc_timestamp();

}  // namespace sketchlab
