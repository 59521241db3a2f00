// The experiment runner in-process: pictures are drawn from the sketches the
// runner holds, so they need neither sketch.json nor the recording on disk
// (they used to be skipped silently without sketch.json).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "build_plugin_host.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/experiment_runner.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

TEST_CASE("experiment runner: pictures from the final sketches, also without sketch.json", "[lab][experiment]") {
  const fs::path dir = fs::temp_directory_path() / "sketchlab_experiment_runner_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "exp.yaml")
      << "experiment: pics\nrecordings: [" << test::source_path("data/recordings/hat.jsonl") << "]\n"
      << "stacks:\n"
         "  - name: free\n"
         "    input: {plugin: replay, params: {max_events: 20}}\n"
         "    corrector: {plugin: freehand}\n"
         "  - name: coarse\n"
         "    input: {plugin: replay, params: {max_events: 20}}\n"
         "    corrector: {plugin: freehand, params: {fit_error: 2.0}}\n"
      << "outputs: {dir: " << (dir / "runs").string()
      << ", timestamp: false, sketch_json: false, stroke_csv: false, pictures: true}\n";
  const ExperimentConfig config = load_experiment(dir / "exp.yaml");

  std::vector<std::pair<fs::path, std::vector<std::string>>> drawn;
  std::vector<std::string> drawn_json;  // each panel's sketch, as sketch.json would hold it
  std::size_t raw_strokes = 0;
  RunOptions options;
  options.jobs = 2;
  options.timings = false;
  options.renderer = [&](const fs::path& png, const std::vector<std::pair<std::string, const Sketch*>>& panels) {
    std::vector<std::string> titles;
    for (const auto& [title, sketch] : panels) {
      titles.push_back(title);
      drawn_json.push_back(sketch_to_json(*sketch));
      raw_strokes += sketch->strokes.size();
      for (const auto& [id, stroke] : sketch->strokes) CHECK(!stroke.samples.empty());
    }
    drawn.emplace_back(png, titles);
  };
  const RunSummary summary = run_experiment(config, test::build_plugin_host(), options);
  REQUIRE(summary.failed() == 0);
  CHECK(!fs::exists(summary.run_dir / "hat" / "free" / "sketch.json"));
  REQUIRE(drawn.size() == 1);
  CHECK(drawn[0].first == summary.run_dir / "hat" / "side_by_side.png");
  CHECK(drawn[0].second == std::vector<std::string>{"free", "coarse"});
  CHECK(raw_strokes > 0);

  // The panels hold the cases' networks: the same as a rerun writing sketch.json.
  ExperimentConfig with_json = config;
  with_json.outputs.sketch_json = true;
  with_json.outputs.pictures = false;
  with_json.outputs.dir = dir / "runs_json";
  const RunSummary again = run_experiment(with_json, test::build_plugin_host(), options);
  REQUIRE(again.failed() == 0);
  for (std::size_t i = 0; i < 2; ++i) {
    const Sketch written = read_sketch_json(again.cases[i].dir / "sketch.json");
    CHECK(sketch_to_json(written) == sketch_to_json(parse_sketch_json(drawn_json[i], "panel")));
  }
}

TEST_CASE("experiment runner: a glitch sample kilometres away neither fails the case nor floods its exports",
          "[lab][experiment][reliability]") {
  // The freehand corrector keeps every raw sample (CASSIE's Freehand system),
  // so a 10 km glitch makes a curve 35 km long and the 10^6 m line one of
  // 2,236 km. Before the exports were bounded, the first wrote 630 MB of
  // curves.ply and sketch.obj and the second failed its case in the curve
  // export ("needs more than 1e7 samples"), after the replay had succeeded.
  const fs::path dir = fs::temp_directory_path() / "sketchlab_experiment_runner_glitch_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "exp.yaml")
      << "experiment: glitch\nrecordings: ["
      << test::source_path("tests/fixtures/reliability/H1_glitch_sample_10000m.jsonl") << ", "
      << test::source_path("tests/fixtures/reliability/H1b_huge_range_mix.jsonl") << "]\n"
      << "stacks: [{corrector: freehand}]\n"
      << "outputs: {dir: " << (dir / "runs").string() << ", timestamp: false, pictures: false}\n";
  RunOptions options;
  options.jobs = 1;
  options.timings = false;
  const RunSummary summary = run_experiment(load_experiment(dir / "exp.yaml"), test::build_plugin_host(), options);
  REQUIRE(summary.cases.size() == 2);
  for (const CaseResult& c : summary.cases) {
    INFO(c.dir << ": " << c.error);
    CHECK(c.ok);
    CHECK(c.metrics.values.at("curves") >= 3);
    for (const char* file : {"curves.ply", "sketch.obj", "sketch.json"}) {
      INFO(file);
      REQUIRE(fs::exists(c.dir / file));
      CHECK(fs::file_size(c.dir / file) < 4'000'000);
    }
  }
}
