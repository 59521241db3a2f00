#pragma once
// How the report shows each metric of compute_metrics (metrics.hpp): its
// column group, a short header, the unit it is displayed in (stored values
// are SI or plain ratios; lengths are shown in mm, ratios in %) and one
// sentence for the report's glossary. One place for it, so the summary, the
// per-recording tables, the plots and the glossary agree.
#include <string>

namespace sketchlab {

struct MetricInfo {
  std::string group;        // column group, e.g. "latency", "vs input"
  std::string label;        // short header within the group, e.g. "p50"
  std::string unit;         // displayed unit: "ms", "mm", "%", "×", "" (a count)
  double scale = 1.0;       // displayed value = stored value × scale
  std::string description;  // what it measures (glossary)
  int rank = 0;             // order: groups by rank / 100 then group name, rows by rank
};

// Any name: the families of metrics.hpp (ref_<track>_*, gt_<kind>_*,
// enforced_<kind>_residual_mean) are recognised; an unknown name falls in
// group "other" with its full name as label and the unit its suffix says
// (_m: mm, _ms: ms, else none).
MetricInfo metric_info(const std::string& name);

// A displayed value with three significant digits and no exponent between
// 1e-3 and 1e6 ("0.00123", "12.3", "1234", "1.2e-05"); "–" for NaN/inf.
std::string format_displayed(double value);

}  // namespace sketchlab
