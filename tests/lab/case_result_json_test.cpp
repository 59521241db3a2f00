// A case's record (case_result.json) reads back to the same values, so a
// resumed or distributed run writes the same metrics as a single one, and bad
// records are refused with the field at fault.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sketchlab/lab/case_result_json.hpp"

using namespace sketchlab;

TEST_CASE("a case record reads back bit for bit, non-finite metrics as NaN", "[lab][resume]") {
  CaseResult c;
  c.ok = true;
  c.error = "a \"quoted\"\nerror";
  c.metrics.values = {{"curves", 42.0},
                      {"input_deviation_mean_m", 0.1 + 0.2},
                      {"tiny", 4.9406564584124654e-324},
                      {"huge", 1.7976931348623157e308},
                      {"nan", std::numeric_limits<double>::quiet_NaN()}};
  c.metrics.relations["parallel"] = {7, 5, 4};
  c.stroke_latency_ms = {1.0 / 3.0, 0.0, 12.5};
  c.wall_ms = 123.456789;
  const std::string text = case_result_to_json(c);
  CaseResult back;
  case_result_from_json(text, "r.json", back);
  CHECK(back.ok);
  CHECK(back.error == c.error);
  REQUIRE(back.metrics.values.size() == c.metrics.values.size());
  for (const auto& [k, v] : c.metrics.values) {
    INFO(k);
    if (std::isnan(v))
      CHECK(std::isnan(back.metrics.values.at(k)));
    else
      CHECK(back.metrics.values.at(k) == v);  // exact: shortest round-trip digits
  }
  const auto& pr = back.metrics.relations.at("parallel");
  CHECK((pr.intended == 7 && pr.detected == 5 && pr.matched == 4));
  CHECK(back.stroke_latency_ms == c.stroke_latency_ms);
  CHECK(back.wall_ms == c.wall_ms);
  CHECK(case_result_to_json(back) == text);
}

TEST_CASE("a bad case record is refused naming the file and field", "[lab][resume]") {
  CaseResult c;
  const auto refused = [&](const std::string& text, const std::string& what) {
    INFO(text);
    CHECK_THROWS_WITH(case_result_from_json(text, "x/case_result.json", c),
                      Catch::Contains("x/case_result.json") && Catch::Contains(what));
  };
  refused("{", "not JSON");
  refused("[]", "ok");
  refused(R"({"ok":1,"error":"","metrics":{},"relations":{},"stroke_latency_ms":[],"wall_ms":0})", "ok");
  refused(R"({"ok":true,"error":"","metrics":{"a":"x"},"relations":{},"stroke_latency_ms":[],"wall_ms":0})",
          "metrics.a");
  refused(R"({"ok":true,"error":"","metrics":{},"relations":{"p":{"intended":1}},"stroke_latency_ms":[],"wall_ms":0})",
          "relations.p");
  refused(R"({"ok":true,"error":"","metrics":{},"relations":{},"stroke_latency_ms":[],"wall_ms":"slow"})", "wall_ms");
  refused(R"({"ok":true,"error":"","metrics":{},"relations":{},"stroke_latency_ms":[]})", "wall_ms");
}
