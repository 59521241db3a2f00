// `sketchlab run` as an experiment runner: outputs, report, sweeps, failures,
// determinism.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "sketchlab/config/config.hpp"
#include "sketchlab/io/text_file.hpp"
#include "cli_helpers.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;
using test::fresh_dir;
using test::run_cli;

namespace {

// A short recording (first events of hat) keeps these tests fast.
const char* stacks_yaml =
    "stacks:\n"
    "  - name: free\n"
    "    input: {plugin: replay, params: {max_events: 40}}\n"
    "    corrector: {plugin: freehand}\n"
    "  - name: coarse\n"
    "    input: {plugin: replay, params: {max_events: 40}}\n"
    "    corrector: {plugin: freehand, params: {fit_error: 2.0}}\n";

fs::path write_file(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

std::string outputs_yaml(const fs::path& dir) {
  return "outputs: {dir: " + (dir / "runs").string() +
         ", timestamp: false, ply: true, obj: true, mlp: true, report: true, pictures: false}\n";
}

}  // namespace

TEST_CASE("a two-stack experiment writes every output", "[app][experiment]") {
  const fs::path dir = fresh_dir("experiment_outputs");
  const fs::path exp = write_file(dir / "two.yaml", "experiment: two\nrecordings: [" +
                                                        test::source_path("data/recordings/hat.jsonl") +
                                                        "]\n" + stacks_yaml + outputs_yaml(dir));
  REQUIRE(run_cli("run " + exp.string(), dir / "log.txt") == 0);
  const fs::path run = dir / "runs/two";
  for (const char* f : {"config.yaml", "metrics.csv", "metrics.json", "report.html", "hat/hat.mlp"})
    CHECK(fs::exists(run / f));
  for (const char* stack : {"free", "coarse"})
    for (const char* f : {"case.yaml", "sketch.json", "strokes.csv", "curves.ply", "raw_strokes.ply",
                          "nodes.ply", "patches.ply", "sketch.obj"}) {
      INFO(stack << "/" << f);
      CHECK(fs::exists(run / "hat" / stack / f));
    }

  // The resolved config repeats the experiment.
  const ExperimentConfig again = load_experiment(run / "config.yaml");
  CHECK(again.stacks.size() == 2);
  CHECK(again.recordings.size() == 1);

  // The MeshLab project names existing PLY files (structural check; MeshLab
  // itself is not required).
  const std::string mlp = read_text_file(run / "hat/hat.mlp");
  const std::regex file_re("filename=\"([^\"]+)\"");
  int layers = 0;
  for (std::sregex_iterator it(mlp.begin(), mlp.end(), file_re), end; it != end; ++it, ++layers) {
    const fs::path ply = run / "hat" / (*it)[1].str();
    INFO(ply);
    REQUIRE(fs::exists(ply));
    CHECK(read_text_file(ply).rfind("ply\nformat ascii 1.0\n", 0) == 0);
  }
  CHECK(layers == 4);  // raw strokes and curves of both stacks (no nodes, no patches)

  // The report references only files that exist, and links only to
  // anchors it has.
  const std::string html = read_text_file(run / "report.html");
  const std::regex ref_re("(?:href|src)=\"([^\"#][^\"]*)\"");
  int refs = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), ref_re), end; it != end; ++it, ++refs) {
    INFO((*it)[1].str());
    CHECK(fs::exists(run / (*it)[1].str()));
  }
  CHECK(refs >= 4);
  const std::regex anchor_re("href=\"#([^\"]+)\"");
  int anchors = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), anchor_re), end; it != end; ++it, ++anchors) {
    INFO((*it)[1].str());
    CHECK_THAT(html, Catch::Contains("id=\"" + (*it)[1].str() + "\""));
  }
  CHECK(anchors > 10);  // contents, and each metric to its glossary entry
  CHECK_THAT(html, Catch::Contains("<svg"));

  const auto metrics = nlohmann::json::parse(read_text_file(run / "metrics.json"));
  REQUIRE(metrics["cases"].size() == 2);
  for (const auto& c : metrics["cases"]) {
    CHECK(c["ok"].get<bool>());
    CHECK(c["metrics"]["curves"].get<double>() > 0);
    CHECK(c["metrics"]["dangling_endpoint_ratio"].get<double>() == 1.0);  // freehand makes no nodes
    CHECK(c["metrics"].contains("ref_cassie_endpoint_mean_m"));
  }
}

TEST_CASE("a sweep of three values gives three cases with distinct resolved parameters",
          "[app][experiment]") {
  const fs::path dir = fresh_dir("experiment_sweep");
  const fs::path exp = write_file(
      dir / "sweep.yaml", "experiment: sweep\nrecordings: [" + test::source_path("data/recordings/hat.jsonl") +
                              "]\n" + stacks_yaml + "sweep:\n  stacks.0.corrector.params.fit_error: [0.25, 0.5, 1.0]\n" +
                              outputs_yaml(dir));
  REQUIRE(run_cli("run " + exp.string(), dir / "log.txt") == 0);
  const fs::path run = dir / "runs/sweep/hat";
  std::set<std::string> values;
  for (const char* v : {"0.25", "0.5", "1"}) {
    const fs::path case_dir = run / ("free@fit_error=" + std::string(v == std::string("1") ? "1.0" : v));
    INFO(case_dir);
    REQUIRE(fs::exists(case_dir / "case.yaml"));
    const StackConfig stack = load_stack(case_dir / "case.yaml");
    values.insert(format_value(stack.corrector.params.at("fit_error")));
  }
  CHECK(values.size() == 3);
  CHECK(fs::exists(run / "coarse/case.yaml"));  // the other stack runs once
  const auto metrics = nlohmann::json::parse(read_text_file(dir / "runs/sweep/metrics.json"));
  CHECK(metrics["cases"].size() == 4);
}

TEST_CASE("a failing case is reported and the others complete", "[app][experiment]") {
  const fs::path dir = fresh_dir("experiment_failure");
  const fs::path broken = write_file(dir / "broken.jsonl", "{\"format\":\"sketchlab-recording\",\"version\":99}\n");
  const fs::path exp = write_file(dir / "fail.yaml", "experiment: fail\nrecordings: [" +
                                                         test::source_path("data/recordings/hat.jsonl") + ", " +
                                                         broken.string() + "]\n" + stacks_yaml + outputs_yaml(dir));
  CHECK(run_cli("run " + exp.string(), dir / "log.txt") != 0);
  const std::string log = read_text_file(dir / "log.txt");
  CHECK_THAT(log, Catch::Contains("FAILED broken x free"));
  CHECK_THAT(log, Catch::Contains("broken.jsonl:1"));
  CHECK_THAT(log, Catch::Contains("2 of 4 cases done, 2 failed"));
  CHECK(fs::exists(dir / "runs/fail/hat/free/sketch.json"));
  CHECK(fs::exists(dir / "runs/fail/hat/coarse/sketch.json"));
  CHECK_THAT(read_text_file(dir / "runs/fail/report.html"), Catch::Contains("failed: "));
}

TEST_CASE("the same experiment twice gives byte-identical results", "[app][experiment]") {
  const fs::path dir = fresh_dir("experiment_determinism");
  const fs::path exp = write_file(dir / "det.yaml", "experiment: det\nrecordings: [" +
                                                        test::source_path("data/recordings/hat.jsonl") +
                                                        "]\n" + stacks_yaml + outputs_yaml(dir));
  REQUIRE(run_cli("run --no-timings -j 2 " + exp.string() + " outputs.dir=" + (dir / "a").string(), dir / "a.txt") == 0);
  REQUIRE(run_cli("run --no-timings -j 1 " + exp.string() + " outputs.dir=" + (dir / "b").string(), dir / "b.txt") == 0);
  for (const char* f : {"metrics.csv", "metrics.json", "report.html", "hat/hat.mlp", "hat/free/sketch.json",
                        "hat/coarse/strokes.csv", "hat/coarse/curves.ply"}) {
    INFO(f);
    CHECK(read_text_file(dir / "a/det" / f) == read_text_file(dir / "b/det" / f));
  }
}
