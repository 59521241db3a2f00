// The analytic corrector on the bundled analytic-style tablet sessions
// (data/synthetic/tablet/MODEL_analytic.jsonl, `sketchlab synth MODEL
// --modality tablet --param style=analytic --seed 1`): the 3D scaffold it
// recovers after the alignment one view leaves open, the intended relations,
// the nodes, next to the freehand baseline. The bounds are the figures
// reached (README "Tablet sessions") with a small margin, so a regression
// fails.
#include <catch2/catch.hpp>
#include <map>

#include "tablet_experiment.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;
using sketchlab::test::fresh_dir;
using sketchlab::test::metric;
using sketchlab::test::run_cli;
using sketchlab::test::run_tablet_experiment;
using sketchlab::test::source_path;

namespace {

std::map<std::pair<std::string, std::string>, nlohmann::json> run_tablet(const std::string& name,
                                                                         const std::vector<fs::path>& recordings) {
  return run_tablet_experiment(name, recordings, {"freehand", "analytic"});
}

struct Figures {
  double aligned_max;  // m, gt_distance_mean_aligned_eye_scale_m
  double parallel_min, perpendicular_min, coincident_min;  // recall
  double dangling_max;
};

}  // namespace

TEST_CASE("analytic recovers the scaffold of the bundled analytic-style tablet sessions", "[analytic][tablet][slow]") {
  // Figures reached at seed 1, default noise (README), with a margin.
  const std::map<std::string, Figures> expected{
      // Since f_vanishing = 2 an edge between two ticked corners follows its
      // vanishing direction and may miss the far tick (coincident 1 → 0.83).
      {"cube_analytic", {0.0045, 0.95, 0.80, 0.80, 0.83}},
      {"chair_analytic", {0.0022, 0.95, 0.95, 0.95, 0.76}},
      // The handle takes a third constraint point at another depth (README).
      {"mug_analytic", {0.0065, 0.80, 0.70, 0.85, 0.76}},
      // The shade is placed by dimension ticks from the arm end (before
      // them: 61 mm, worse than freehand's 42 mm), its circles on their
      // finished squares, its small parts zoomed in (before: 16 mm); the
      // base's diameters between joints placed by eye stay on their
      // vanishing directions (before f_vanishing = 2: parallel 0.33; README).
      {"lamp_analytic", {0.0040, 0.70, 0.50, 0.80, 0.66}},
  };
  std::vector<fs::path> recordings;
  for (const auto& [name, f] : expected) recordings.push_back(source_path("data/synthetic/tablet/" + name + ".jsonl"));
  const auto cases = run_tablet("analytic_tablet_figures", recordings);
  for (const auto& [name, f] : expected) {
    INFO(name);
    const auto& a = cases.at({name, "analytic"});
    const auto& freehand = cases.at({name, "freehand"});
    const double aligned = metric(a, "gt_distance_mean_aligned_eye_scale_m");
    CHECK(aligned < f.aligned_max);
    CHECK(metric(a, "gt_parallel_recall") >= f.parallel_min);
    CHECK(metric(a, "gt_perpendicular_recall") >= f.perpendicular_min);
    CHECK(metric(a, "gt_coincident_point_recall") >= f.coincident_min);
    // Nodes where the inferred curves meet (the baseline has none).
    CHECK(metric(a, "nodes") > 0);
    CHECK(metric(a, "dangling_endpoint_ratio") <= f.dangling_max);
    CHECK(metric(freehand, "dangling_endpoint_ratio") == 1.0);
    WARN(name << ": analytic aligned " << aligned << " m, freehand aligned "
              << metric(freehand, "gt_distance_mean_aligned_eye_scale_m") << " m");
  }
}

TEST_CASE("analytic is exact on noise-free analytic-style sessions of boxes", "[analytic][tablet][slow]") {
  const fs::path dir = fresh_dir("analytic_tablet_exact_data");
  const std::vector<std::string> models{"cube", "chair", "mug", "lamp"};
  std::vector<fs::path> recordings;
  for (const std::string& model : models) {
    const fs::path rec = dir / (model + ".jsonl");
    REQUIRE(run_cli("synth " + model + " --modality tablet --param style=analytic --noise 0 -o " + rec.string(),
                    dir / (model + ".txt")) == 0);
    recordings.push_back(rec);
  }
  const auto cases = run_tablet("analytic_tablet_exact", recordings);
  // Aligned mean distance reached (README): the cube exactly; the chair's
  // arched rail and the mug's handle take tangents close to, not equal to,
  // the intended ones; the lamp's circles, each drawn on its finished
  // square and cross, take the intended joints and tangents. No stroke is
  // cut as hooked (a curve's tight bend is no hook).
  const std::map<std::string, double> mean_max{{"chair", 1.2e-4}, {"mug", 4e-4}, {"lamp", 1e-4}};
  for (const std::string& model : models) {
    INFO(model);
    const auto& a = cases.at({model, "analytic"});
    if (model == "cube") CHECK(metric(a, "gt_distance_max_aligned_eye_scale_m") < 1e-9);
    else CHECK(metric(a, "gt_distance_mean_aligned_eye_scale_m") < mean_max.at(model));
    for (const char* kind : {"parallel", "perpendicular", "coincident_point"})
      CHECK(metric(a, std::string("gt_") + kind + "_recall") >= 1.0);
  }
}
