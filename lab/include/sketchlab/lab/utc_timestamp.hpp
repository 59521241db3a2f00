#pragma once
// The tools' timestamps of the current time, UTC: one place for both forms.
#include <string>

namespace sketchlab {

// "YYYYMMDD-HHMMSS": file and folder names the tools choose (run folders,
// live and VR recordings).
std::string utc_timestamp();

// "YYYY-MM-DDTHH:MM:SSZ" (ISO 8601): times written into records such as
// provenance.yaml.
std::string utc_iso8601();

}  // namespace sketchlab
