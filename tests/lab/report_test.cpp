// The experiment report on its own (it was tested only through `sketchlab
// run`): metrics.csv columns and quoting, metrics.json, the HTML tables and
// the SVG plots, from a RunSummary built by hand.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <cmath>
#include <string>

#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/metric_glossary.hpp"
#include "sketchlab/lab/report.hpp"
#include "sketchlab/lab/svg_plot.hpp"

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

TEST_CASE("report: metrics.csv puts the headline metrics first, then the rest by name, empty where absent",
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
  CHECK_THAT(html, Catch::Contains("Latency per stroke: hat"));
  CHECK_THAT(html, Catch::Contains("cassie@delta=0.02 (3 strokes)"));  // per stroke, not per event
  CHECK_THAT(html, Catch::Contains("2 cases, 1 failed, 1.5 s."));
}

TEST_CASE("report: the summary gives per stack the median and quartiles over recordings, in display units",
          "[lab][report]") {
  const fs::path dir = fresh_dir("summary");
  ExperimentConfig config;
  config.name = "exp";
  RunSummary s;
  s.run_dir = dir;
  int k = 0;
  for (const char* rec : {"a", "b", "c"}) {
    config.recordings.push_back(std::string("/data/") + rec + ".jsonl");
    CaseResult c;
    c.recording = config.recordings.back();
    c.variant.stack.name = "freehand";
    c.dir = dir / rec / "freehand";
    c.ok = true;
    // curves 3, 5, 7; deviation 1, 2, 3 mm (stored in metres).
    c.metrics.values = {{"curves", 3.0 + 2 * k}, {"input_deviation_mean_m", 0.001 * (k + 1)}};
    ++k;
    s.cases.push_back(c);
  }
  write_report(s, config);
  const std::string html = read_text_file(dir / "report.html");
  const auto summary = html.substr(html.find("<section id=\"summary\">"));
  // Nearest-rank quartiles of {3, 5, 7}: 3 and 7.
  CHECK_THAT(summary, Catch::Contains("<td>5 <span class=\"iqr\">[3, 7]</span> <span class=\"n\">n=3</span></td>"));
  CHECK_THAT(summary, Catch::Contains("<td>2 <span class=\"iqr\">[1, 3]</span> <span class=\"n\">n=3</span></td>"));
  // Grouped rows, units in the headers, each linked to the glossary.
  CHECK_THAT(summary, Catch::Contains("<tr class=\"group\"><th colspan=\"2\">vs input</th></tr>"));
  CHECK_THAT(summary, Catch::Contains("dev. mean <span class=\"unit\">(mm)</span>"));
  CHECK_THAT(html, Catch::Contains("<tr id=\"metric-input_deviation_mean_m\"><td>vs input</td><td>dev. mean</td><td>mm</td>"));
  // Network counts come before deviations (glossary order).
  CHECK(summary.find(">network<") < summary.find(">vs input<"));
}

TEST_CASE("report: cases with a scene.gltf get 3D views, their scene scripts and the viewer bundle",
          "[lab][report]") {
  const fs::path dir = fresh_dir("scenes");
  ExperimentConfig config;
  RunSummary s = two_cases(dir, config);
  fs::create_directories(s.cases[0].dir);
  write_text_file(s.cases[0].dir / "scene.gltf", "{\"asset\": {\"version\": \"2.0\"}}");
  write_report(s, config);
  const std::string html = read_text_file(dir / "report.html");
  CHECK_THAT(html, Catch::Contains("<div class=\"scene\" data-scene=\"hat/cassie@delta=0.02/scene.gltf\" "
                                   "data-title=\"cassie@delta=0.02\"></div>"));
  CHECK_THAT(html, Catch::Contains("<script src=\"hat/cassie@delta=0.02/scene.gltf.js\"></script>\n"
                                   "<script src=\"report_web/sketchlab_report.js\"></script>"));
  CHECK(read_text_file(s.cases[0].dir / "scene.gltf.js") ==
        "(window.sketchlabScenes = window.sketchlabScenes || {})[\"hat/cassie@delta=0.02/scene.gltf\"] = "
        "{\"asset\":{\"version\":\"2.0\"}};\n");
  // The bundled three.js viewer, compiled in, reads that table.
  const std::string bundle = read_text_file(dir / "report_web/sketchlab_report.js");
  CHECK(bundle.size() > 100000);
  CHECK_THAT(bundle, Catch::Contains("sketchlabScenes"));

  // A scene.gltf that is not JSON gives no view (the numbers still come).
  write_text_file(s.cases[0].dir / "scene.gltf", "not json");
  write_report(s, config);
  CHECK_THAT(read_text_file(dir / "report.html"), !Catch::Contains("data-scene="));
}

TEST_CASE("report: sweep plots name the parameter as the stack declares it, with markers and units",
          "[lab][report]") {
  const fs::path dir = fresh_dir("sweep");
  ExperimentConfig config;
  config.name = "exp";
  config.recordings = {"/data/hat.jsonl"};
  StackConfig stack;
  stack.name = "cassie";
  stack.corrector.plugin = "cassie";
  config.stacks = {stack};
  config.sweep = {SweepAxis{{"stacks", "0", "corrector", "params", "delta"}, {"0.01", "0.02"}}};
  RunSummary s;
  s.run_dir = dir;
  for (const char* v : {"0.01", "0.02"}) {
    CaseResult c;
    c.recording = "/data/hat.jsonl";
    c.variant.stack.name = std::string("cassie@delta=") + v;
    c.variant.point = {{"stacks.0.corrector.params.delta", v}};
    c.dir = dir / "hat" / c.variant.stack.name;
    c.ok = true;
    c.metrics.values = {{"input_deviation_mean_m", std::stod(v)}};
    s.cases.push_back(c);
  }
  write_report(s, config);
  const std::string html = read_text_file(dir / "report.html");
  const auto sweep = html.substr(html.find("<section id=\"sweep\">"));
  CHECK_THAT(sweep, Catch::Contains(">delta, cassie corrector parameter</text>"));
  CHECK_THAT(sweep, Catch::Contains(">dev. mean (mm), mean over recordings</text>"));
  CHECK_THAT(sweep, Catch::Contains("<circle"));
}

TEST_CASE("svg plot: data map onto the plot area, ticks are round, markers mark each point", "[lab][report]") {
  const std::string svg = svg_plot({PlotSeries{"a", {{0.0, 0.0}, {2.0, 4.0}}}}, PlotOptions{});
  // Plot area x in [70, 540], y in [30, 310] (720 x 360, margins 70/180/30/50):
  // (0, 0) is the lower left corner, (2, 4) the upper right one.
  CHECK_THAT(svg, Catch::Contains("points=\"70,310 540,30 \""));
  CHECK_THAT(svg, Catch::Contains("<circle cx=\"70\" cy=\"310\""));
  CHECK_THAT(svg, Catch::Contains(">a</text>"));
  CHECK_THAT(svg, Catch::Contains(">1.5</text>"));  // an x tick (step 0.5)
  // A single point (empty ranges) still gives finite coordinates.
  const std::string one = svg_plot({PlotSeries{"b", {{5.0, 0.0}}}}, PlotOptions{});
  CHECK_THAT(one, !Catch::Contains("nan"));
  CHECK_THAT(one, !Catch::Contains("inf"));
  // Steps: each point is reached horizontally first.
  PlotOptions steps;
  steps.steps = true;
  const std::string cdf = svg_plot({PlotSeries{"c", {{0.0, 0.0}, {2.0, 4.0}}}}, steps);
  CHECK_THAT(cdf, Catch::Contains("points=\"70,310 540,310 540,30 \""));
  // Log x: non-positive x are dropped, decades are labelled.
  PlotOptions log;
  log.log_x = true;
  const std::string lg = svg_plot({PlotSeries{"d", {{-1.0, 1.0}, {1.0, 1.0}, {1000.0, 2.0}}}}, log);
  CHECK_THAT(lg, Catch::Contains(">1000</text>"));
  CHECK_THAT(lg, Catch::Contains("(log scale)"));
  CHECK_THAT(lg, !Catch::Contains("nan"));
}

TEST_CASE("svg plot helpers: round ticks and the empirical distribution function", "[lab][report]") {
  CHECK(nice_ticks(0.13, 0.87) == std::vector<double>{0.2, 0.4, 0.6, 0.8});
  CHECK(nice_ticks(0.0, 10.0) == std::vector<double>{0, 2, 4, 6, 8, 10});
  CHECK(nice_ticks(3.0, 3.0) == std::vector<double>{3.0});
  const auto cdf = empirical_cdf({3.0, 1.0, std::nan(""), 2.0});
  REQUIRE(cdf.size() == 3);
  CHECK(cdf[0] == std::pair<double, double>{1.0, 1.0 / 3});
  CHECK(cdf[1] == std::pair<double, double>{2.0, 2.0 / 3});
  CHECK(cdf[2] == std::pair<double, double>{3.0, 1.0});
}

TEST_CASE("metric glossary: families, display units and readable numbers", "[lab][report]") {
  const MetricInfo dev = metric_info("input_deviation_mean_m");
  CHECK(dev.group == "vs input");
  CHECK(dev.unit == "mm");
  CHECK(dev.scale == 1000.0);
  const MetricInfo snap = metric_info("ref_cassie_snap_agreement");
  CHECK(snap.group == "vs cassie");
  CHECK(snap.unit == "%");
  CHECK(metric_info("ref_cassie_endpoint_mean_m").unit == "mm");
  CHECK(metric_info("ref_cassie_compared").unit.empty());
  const MetricInfo recall = metric_info("gt_parallel_recall");
  CHECK(recall.group == "relations");
  CHECK(recall.label == "parallel R");
  CHECK(metric_info("gt_equal_length_precision").label == "equal_length P");
  // Issue 19: the report says which ground-truth distance is raw and which aligned.
  CHECK(metric_info("gt_distance_mean_m").label == "dist. mean (raw)");
  CHECK(metric_info("gt_distance_mean_aligned_eye_scale_m").label == "dist. mean (aligned)");
  CHECK(metric_info("gt_shape_distance_mean_aligned_eye_scale_m").label == "shape dist. (aligned)");
  CHECK(metric_info("enforced_coincident_residual_mean").label == "coincident");
  CHECK(metric_info("latency_p95_ms").unit == "ms");
  const MetricInfo unknown = metric_info("new_thing_m");
  CHECK(unknown.group == "other");
  CHECK(unknown.unit == "mm");
  CHECK(metric_info("latency_p50_ms").rank < metric_info("curves").rank);

  CHECK(format_displayed(0.00123) == "0.00123");
  CHECK(format_displayed(12.345) == "12.3");
  CHECK(format_displayed(1234.4) == "1234");
  CHECK(format_displayed(1.2e-5) == "1.2e-05");
  CHECK(format_displayed(0.0) == "0");
  CHECK(format_displayed(std::nan("")) == "–");
}
