// JustDrawIt on the bundled JustDrawIt-style tablet sessions
// (data/synthetic/tablet/MODEL_justdrawit.jsonl, `sketchlab synth MODEL
// --modality tablet --param style=justdrawit --seed 1`: multi-stroke curves
// on placed draw planes, oversketched from a second view): the distance of
// its curves to the intended ones, raw (two views and draw planes placed in
// the world leave no scale open), next to the freehand baseline. The bounds
// are the figures reached (README "Ground truth on the tablet experiment")
// with a small margin, so a regression fails.
#include <catch2/catch.hpp>
#include <map>

#include "tablet_experiment.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;
using test::metric;

namespace {

struct Figures {
  double distance_max;        // m, gt_distance_mean_m
  double shape_distance_max;  // m, gt_shape_distance_mean_m
  double coverage_max;        // m, gt_shape_coverage_mean_m
  double curves_max;
};

}  // namespace

TEST_CASE("JustDrawIt places the curves of the bundled JustDrawIt-style tablet sessions near the intended ones",
          "[justdrawit][tablet][slow]") {
  // Figures reached at seed 1, default noise (README), with a margin. The
  // intended curves are 12, 12, 7 and 11: a few strokes stay apart or two
  // curves are combined (README).
  // The chair's back legs continue its uprights in line, so each extends
  // its upright (§4.2): 10.5 mm against the leg alone, 1.2 mm against the
  // intended shape.
  const std::map<std::string, Figures> expected{{"cube_justdrawit", {0.005, 0.0046, 0.0018, 14}},
                                                {"chair_justdrawit", {0.0115, 0.0014, 0.0012, 10}},
                                                {"mug_justdrawit", {0.0016, 0.0013, 0.0012, 7}},
                                                {"lamp_justdrawit", {0.002, 0.0017, 0.0013, 12}}};
  std::vector<fs::path> recordings;
  for (const auto& [name, f] : expected)
    recordings.push_back(test::source_path("data/synthetic/tablet/" + name + ".jsonl"));
  const auto cases = test::run_tablet_experiment("jdi_tablet_figures", recordings, {"freehand", "justdrawit"});
  for (const auto& [name, f] : expected) {
    INFO(name);
    const auto& j = cases.at({name, "justdrawit"});
    const auto& freehand = cases.at({name, "freehand"});
    CHECK(metric(j, "events_refused") == 0);
    CHECK(metric(j, "gt_distance_mean_m") < f.distance_max);
    CHECK(metric(j, "gt_shape_distance_mean_m") < f.shape_distance_max);
    CHECK(metric(j, "gt_shape_coverage_mean_m") < f.coverage_max);
    // The strokes of a curve and its oversketch mostly edit one curve
    // (freehand makes a curve per stroke).
    CHECK(metric(j, "curves") <= f.curves_max);
    CHECK(metric(freehand, "curves") > 1.4 * f.curves_max);
    WARN(name << ": justdrawit " << metric(j, "gt_distance_mean_m") << " m, freehand "
              << metric(freehand, "gt_distance_mean_m") << " m");
  }
}

TEST_CASE("JustDrawIt closes and oversketches the noise-free mug's and lamp's loops", "[justdrawit][tablet][slow]") {
  // README: each loop drawn from a free stretch and on over its start closes
  // (§4.3 (1)), and its oversketch from the second view, starting at the
  // curve's seam, keeps the whole loop. The lamp's 12th curve is the shade's
  // 95 px wide top ellipse oversketched from the second view, too small at
  // d = 15 px for eq. 1 to merge it.
  const fs::path dir = test::fresh_dir("jdi_tablet_loops_data");
  std::vector<fs::path> recordings;
  for (const std::string model : {"mug", "lamp"}) {
    recordings.push_back(dir / (model + ".jsonl"));
    REQUIRE(test::run_cli("synth " + model + " --modality tablet --param style=justdrawit --noise 0 -o " +
                              recordings.back().string(),
                          dir / ("synth_" + model + ".txt")) == 0);
  }
  const auto cases = test::run_tablet_experiment("jdi_tablet_loops", recordings, {"justdrawit"});
  const auto& mug = cases.at({"mug", "justdrawit"});
  const auto& lamp = cases.at({"lamp", "justdrawit"});
  CHECK(metric(mug, "curves") == 7);
  CHECK(metric(mug, "gt_distance_mean_m") < 5e-5);  // 14 µm
  CHECK(metric(lamp, "curves") <= 12);
  CHECK(metric(lamp, "gt_distance_mean_m") < 3e-4);  // 0.17 mm
}

TEST_CASE("JustDrawIt's depth comes from the placed draw planes", "[justdrawit][tablet][slow]") {
  const fs::path dir = test::fresh_dir("jdi_tablet_planes_data");
  std::vector<fs::path> recordings;
  for (const std::string planes : {"true", "false"}) {
    recordings.push_back(dir / ("cube_planes_" + planes + ".jsonl"));
    REQUIRE(test::run_cli("synth cube --modality tablet --param style=justdrawit --noise 0 --param draw_planes=" +
                              planes + " -o " + recordings.back().string(),
                          dir / ("synth_" + planes + ".txt")) == 0);
  }
  const auto cases = test::run_tablet_experiment("jdi_tablet_planes", recordings, {"justdrawit"});
  const auto& on_planes = cases.at({"cube_planes_true", "justdrawit"});
  // Noise-free on draw planes: the 12 edges, each from its two strokes and
  // its oversketch, within 6 µm (README); on view planes 91 mm off.
  CHECK(metric(on_planes, "curves") == 12);
  CHECK(metric(on_planes, "gt_distance_max_m") < 1e-5);
  CHECK(metric(cases.at({"cube_planes_false", "justdrawit"}), "gt_distance_mean_m") > 0.05);
}
