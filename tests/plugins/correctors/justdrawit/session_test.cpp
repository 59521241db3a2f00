// Whole synthetic tablet sessions (sketchlab synth --modality tablet) folded
// through the corrector: every stroke handled without error, every curve
// valid and finite, exported normals unit and perpendicular to the curve.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "choice.hpp"
#include "jdi_fixture.hpp"
#include "sketchlab/recording/recording_reader.hpp"

using namespace jdi_test;

TEST_CASE("Synthetic tablet sessions fold without errors", "[justdrawit][slow]") {
  const std::string model = GENERATE(std::string("cube"), std::string("mug"));
  const auto dir = std::filesystem::temp_directory_path() / "sketchlab_jdi_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / (model + "_tablet.jsonl");
  const std::string cmd = std::string(SKETCHLAB_CLI) + " synth " + model +
                          " --modality tablet --seed 3 --overwrite -o " + path.string() + " > /dev/null";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const Recording rec = read_recording(path);
  Session session(rec.header.workspace, std::make_shared<TestCorrector>(JdiParams{}), nullptr);
  std::map<std::string, int> decisions;
  int strokes = 0;
  for (const Event& e : rec.events) {
    const StepReport r = session.handle(e);
    if (r.event != EventKind::stroke) continue;
    ++strokes;
    INFO("stroke " << (r.stroke ? *r.stroke : 0));
    CHECK(r.error.empty());
    const auto decision = r.stats.outcomes.find("decision");
    if (decision != r.stats.outcomes.end()) CHECK(decision_from_string(decision->second).has_value());
    ++decisions[decision != r.stats.outcomes.end() ? decision->second : "none"];
  }
  REQUIRE(strokes > 5);
  const Network& net = session.sketch().network;
  CHECK(!net.curves().empty());
  for (const auto& [id, nc] : net.curves()) {
    CHECK(validate(nc.curve).empty());
    const Points3 pts = curve_points(nc.curve, 1e-3);
    for (const CurveNormal& cn : nc.normals) {
      const auto i = static_cast<std::size_t>(cn.t);
      // Central differences, across the seam of a closed curve.
      const bool wrap = nc.curve.closed && pts.size() > 3;
      const Vec3 next = i + 1 < pts.size() ? pts[i + 1] : (wrap ? pts[1] : pts[i]);
      const Vec3 prev = i > 0 ? pts[i - 1] : (wrap ? pts[pts.size() - 2] : pts[i]);
      const Vec3 t = (next - prev).normalized();
      CHECK(std::abs(cn.normal.norm() - 1) < 1e-9);
      CHECK(std::abs(cn.normal.dot(t)) < 1e-9);
    }
  }
  std::string summary;
  for (const auto& [k, n] : decisions)
    summary += k + "=" + std::to_string(n) + " ";
  WARN(model << ": " << strokes << " strokes -> " << net.curves().size() << " curves; " << summary);
}
