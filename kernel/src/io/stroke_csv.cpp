#include "sketchlab/io/stroke_csv.hpp"

#include <array>
#include <sstream>

namespace sketchlab {
namespace {

// Errors are free text: quote them as RFC 4180 asks.
std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string steps_to_csv(const std::vector<StepReport>& steps, bool timings) {
  // Per-kind columns only for kinds that occur, in enum order, so files stay
  // narrow and deterministic.
  std::array<bool, constraint_kind_count> seen{};
  for (const auto& s : steps)
    for (const auto& c : s.constraints) seen[static_cast<int>(c.kind)] = true;

  std::ostringstream out;
  out.precision(17);
  out << "index,time_s,event,stroke,latency_ms,corrected,iterations,subsets_tried,"
         "constraints_considered,constraints_enforced";
  for (int k = 0; k < constraint_kind_count; ++k)
    if (seen[k]) {
      const auto name = to_string(static_cast<ConstraintKind>(k));
      out << "," << name << "_considered," << name << "_enforced";
    }
  out << ",curves_added,curves_removed,curves_replaced,patches_added,patches_removed,error\n";

  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto& s = steps[i];
    std::array<int, constraint_kind_count> considered{}, enforced{};
    int enforced_total = 0;
    for (const auto& c : s.constraints) {
      ++considered[static_cast<int>(c.kind)];
      if (c.enforced) {
        ++enforced[static_cast<int>(c.kind)];
        ++enforced_total;
      }
    }
    out << i << "," << s.time << "," << to_string(s.event) << ",";
    if (s.stroke) out << *s.stroke;
    out << "," << (timings ? s.latency_ms : 0.0) << "," << (s.corrected ? 1 : 0) << ","
        << s.stats.iterations << "," << s.stats.subsets_tried << "," << s.constraints.size() << ","
        << enforced_total;
    for (int k = 0; k < constraint_kind_count; ++k)
      if (seen[k]) out << "," << considered[k] << "," << enforced[k];
    out << "," << s.curves_added << "," << s.curves_removed << "," << s.curves_replaced << ","
        << s.patches_added << "," << s.patches_removed << "," << csv_quote(s.error) << "\n";
  }
  return out.str();
}

}  // namespace sketchlab
