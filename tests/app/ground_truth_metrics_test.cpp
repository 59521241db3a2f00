// Ground-truth metrics on synthetic sketches: perfect for freehand without
// noise, worse as noise grows.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "sketchlab/io/text_file.hpp"
#include "cli_helpers.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;
using test::fresh_dir;
using test::run_cli;

namespace {

// Metrics of freehand on a synthetic cube drawn with the given noise scale.
nlohmann::json cube_metrics(const fs::path& dir, double noise) {
  const std::string tag = "noise" + std::to_string(static_cast<int>(noise * 100));
  const fs::path rec = dir / (tag + ".jsonl");
  REQUIRE(run_cli("synth cube --seed 5 --noise " + std::to_string(noise) + " -o " + rec.string(),
                  dir / (tag + "_synth.txt")) == 0);
  const fs::path exp = dir / (tag + ".yaml");
  std::ofstream(exp) << "experiment: " << tag << "\nrecordings: [" << rec.string() << "]\n"
                     << "stacks: [{name: freehand, corrector: {plugin: freehand, params: {rules: sketchlab}}}]\n"
                     << "outputs: {dir: " << (dir / "runs").string()
                     << ", timestamp: false, report: true, ply: false, obj: false, mlp: false, pictures: false}\n";
  REQUIRE(run_cli("run " + exp.string(), dir / (tag + "_run.txt")) == 0);
  const auto j = nlohmann::json::parse(read_text_file(dir / "runs" / tag / "metrics.json"));
  return j["cases"][0]["metrics"];
}

}  // namespace

TEST_CASE("freehand on a noise-free synthetic cube is perfect, noise degrades the metrics",
          "[app][metrics]") {
  const fs::path dir = test::binary_path("tests/tmp/ground_truth");
  fs::remove_all(dir);
  fs::create_directories(dir);

  const auto perfect = cube_metrics(dir, 0.0);
  CHECK(perfect["gt_distance_max_m"].get<double>() < 1e-9);
  for (const char* kind : {"coincident_point", "parallel", "perpendicular", "equal_length"}) {
    INFO(kind);
    REQUIRE(perfect.contains(std::string("gt_") + kind + "_recall"));
    CHECK(perfect[std::string("gt_") + kind + "_recall"].get<double>() == 1.0);
    CHECK(perfect[std::string("gt_") + kind + "_precision"].get<double>() == 1.0);
  }

  double last_distance = perfect["gt_distance_mean_m"].get<double>();
  double last_recall = perfect["gt_coincident_point_recall"].get<double>();
  for (double noise : {0.5, 1.0, 2.0}) {
    INFO("noise " << noise);
    const auto m = cube_metrics(dir, noise);
    const double distance = m["gt_distance_mean_m"].get<double>();
    const double recall = m["gt_coincident_point_recall"].get<double>();
    CHECK(distance > last_distance);
    CHECK(recall <= last_recall);
    last_distance = distance;
    last_recall = recall;
  }
  CHECK(last_recall < 1.0);
}
