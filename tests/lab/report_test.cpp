// The experiment report on its own (it was tested only through `sketchlab
// run`): metrics.csv columns and quoting, metrics.json, the HTML tables and
// the SVG plots, from a RunSummary built by hand.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/report.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "sketchlab_report_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Two cases of one recording on a one-axis sweep: one done, one failed with
// an error that needs CSV quoting and HTML escaping.
RunSummary two_cases(const fs::path& run_dir, ExperimentConfig& config) {
  config.name = "exp";
  config.recordings = {"/data/hat.jsonl"};
  config.sweep = {SweepAxis{{"stacks", "0", "delta"}, {"0.02", "0.04"}}};
  RunSummary s;
  s.run_dir = run_dir;
  CaseResult ok;
  ok.recording = "/data/hat.jsonl";
  ok.variant.stack.name = "cassie@delta=0.02";
  ok.variant.point = {{"stacks.0.delta", "0.02"}};
  ok.dir = run_dir / "hat" / "cassie@delta=0.02";
  ok.ok = true;
  ok.metrics.values = {{"zeta", 2.5}, {"curves", 3}, {"latency_p50_ms", 0.25}};
  ok.metrics.relations["parallel"] = PrecisionRecall{4, 2, 1};
  ok.stroke_latency_ms = {1.0, 2.0, 3.0};
  ok.wall_ms = 12.5;
  CaseResult bad;
  bad.recording = "/data/hat.jsonl";
  bad.variant.stack.name = "cassie@delta=0.04";
  bad.variant.point = {{"stacks.0.delta", "0.04"}};
  bad.dir = run_dir / "hat" / "cassie@delta=0.04";
  bad.error = "plugin said \"no\", <twice>";
  s.cases = {ok, bad};
  s.wall_s = 1.5;
  return s;
}

}  // namespace

TEST_CASE("report: metrics.csv puts the headline metrics first, then the rest by name; empty where absent",
          "[lab][report]") {
  const fs::path dir = fresh_dir("csv");
  ExperimentConfig config;
  write_report(two_cases(dir, config), config);
  CHECK(read_text_file(dir / "metrics.csv") ==
        "recording,stack,stacks.0.delta,ok,error,wall_ms,latency_p50_ms,curves,zeta\n"
        "hat,cassie@delta=0.02,0.02,1,,12.5,0.25,3,2.5\n"
        "hat,cassie@delta=0.04,0.04,0,\"plugin said \"\"no\"\", <twice>\",0,,,\n");
}

TEST_CASE("report: metrics.json holds every case with its sweep point, metrics and relations", "[lab][report]") {
  const fs::path dir = fresh_dir("json");
  ExperimentConfig config;
  write_report(two_cases(dir, config), config);
  const auto j = nlohmann::json::parse(read_text_file(dir / "metrics.json"));
  CHECK(j.at("run_dir") == "json");
  CHECK(j.at("wall_s") == 1.5);
  REQUIRE(j.at("cases").size() == 2);
  const auto& c = j.at("cases")[0];
  CHECK(c.at("recording") == "hat");
  CHECK(c.at("dir") == "hat/cassie@delta=0.02");
  CHECK(c.at("sweep_point").at("stacks.0.delta") == "0.02");
  CHECK(c.at("metrics").at("curves") == 3.0);
  CHECK(c.at("relations").at("parallel") == nlohmann::json{{"intended", 4}, {"detected", 2}, {"matched", 1}});
  CHECK(j.at("cases")[1].at("ok") == false);
  CHECK(j.at("cases")[1].at("error") == "plugin said \"no\", <twice>");
}

TEST_CASE("report: report.html escapes errors, links what exists and plots latency per stroke",
          "[lab][report]") {
  const fs::path dir = fresh_dir("html");
  ExperimentConfig config;
  const RunSummary s = two_cases(dir, config);
  fs::create_directories(dir / "hat");
  write_text_file(dir / "hat" / "hat.mlp", "");
  write_report(s, config);
  const std::string html = read_text_file(dir / "report.html");
  CHECK_THAT(html, Catch::Contains("failed: plugin said &quot;no&quot;, &lt;twice&gt;"));
  CHECK_THAT(html, Catch::Contains("<a href=\"hat/hat.mlp\">"));
  CHECK_THAT(html, !Catch::Contains("side_by_side.png"));  // no picture was written
  CHECK_THAT(html, Catch::Contains("latency per stroke: hat"));
  CHECK_THAT(html, Catch::Contains("2 cases, 1 failed, 1.5 s."));
}

TEST_CASE("report: an SVG line plot maps the data range onto the axes", "[lab][report]") {
  const std::string svg = svg_line_plot("t", "x", "y", {PlotSeries{"a", {{0.0, 0.0}, {2.0, 4.0}}}});
  // Plot area x in [70, 480], y in [30, 255] (640 x 300, margins 70/160/30/45):
  // (0, 0) is the lower left corner, (2, 4) the upper right one.
  CHECK_THAT(svg, Catch::Contains("points=\"70,255 480,30 \""));
  CHECK_THAT(svg, Catch::Contains(">a</text>"));
  // A single point (empty ranges) still gives finite coordinates.
  const std::string one = svg_line_plot("t", "x", "y", {PlotSeries{"b", {{5.0, 0.0}}}});
  CHECK_THAT(one, Catch::Contains("points=\"70,255 \""));
  CHECK_THAT(one, !Catch::Contains("nan"));
}
