#include "sketchlab/lab/case_result_json.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace sketchlab {
namespace {

using nlohmann::ordered_json;

ordered_json number(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

double number_of(const nlohmann::json& j, const std::string& name, const std::string& field) {
  if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!j.is_number()) throw std::runtime_error(name + ": " + field + ": not a number");
  return j.get<double>();
}

}  // namespace

std::string case_result_to_json(const CaseResult& r) {
  ordered_json metrics = ordered_json::object(), relations = ordered_json::object(),
               latencies = ordered_json::array();
  for (const auto& [k, v] : r.metrics.values) metrics[k] = number(v);
  for (const auto& [k, pr] : r.metrics.relations)
    relations[k] = {{"intended", pr.intended}, {"detected", pr.detected}, {"matched", pr.matched}};
  for (double l : r.stroke_latency_ms) latencies.push_back(number(l));
  const ordered_json root{{"ok", r.ok},           {"error", r.error},
                          {"metrics", metrics},   {"relations", relations},
                          {"stroke_latency_ms", latencies}, {"wall_ms", number(r.wall_ms)}};
  return root.dump() + "\n";
}

void case_result_from_json(std::string_view text, const std::string& name, CaseResult& r) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(name + ": not JSON: " + e.what());
  }
  const auto field = [&](const char* key, bool (nlohmann::json::*is)() const noexcept) -> const nlohmann::json& {
    if (!root.is_object() || !root.contains(key) || !(root[key].*is)())
      throw std::runtime_error(name + ": " + key + ": missing or of the wrong type");
    return root[key];
  };
  r.ok = field("ok", &nlohmann::json::is_boolean).get<bool>();
  r.error = field("error", &nlohmann::json::is_string).get<std::string>();
  r.metrics = {};
  for (const auto& [k, v] : field("metrics", &nlohmann::json::is_object).items())
    r.metrics.values[k] = number_of(v, name, "metrics." + k);
  for (const auto& [k, v] : field("relations", &nlohmann::json::is_object).items()) {
    PrecisionRecall pr;
    try {
      pr.intended = v.at("intended").get<std::size_t>();
      pr.detected = v.at("detected").get<std::size_t>();
      pr.matched = v.at("matched").get<std::size_t>();
    } catch (const nlohmann::json::exception&) {
      throw std::runtime_error(name + ": relations." + k + ": needs counts intended, detected, matched");
    }
    r.metrics.relations[k] = pr;
  }
  r.stroke_latency_ms.clear();
  for (const auto& v : field("stroke_latency_ms", &nlohmann::json::is_array))
    r.stroke_latency_ms.push_back(number_of(v, name, "stroke_latency_ms"));
  if (!root.contains("wall_ms")) throw std::runtime_error(name + ": wall_ms: missing");
  r.wall_ms = number_of(root["wall_ms"], name, "wall_ms");
}

}  // namespace sketchlab
