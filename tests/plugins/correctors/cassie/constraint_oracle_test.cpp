// The oracle restricting the constraint search to a reference's applied
// constraints (constraint_oracle.hpp, issue #15).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "cassie_corrector.hpp"
#include "constraint_oracle.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "synthetic.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::add_curve;
using sketchlab::test::make_stroke;

namespace {

// A stroke crossing two curves 4 mm off its path: the search enforces both.
struct TwoCrossings {
  Sketch sketch;
  Stroke stroke;
  TwoCrossings() {
    add_curve(sketch, make_line({-0.05, -0.2, 0.004}, {-0.05, 0.2, 0.004}));  // curve 1
    add_curve(sketch, make_line({0.05, -0.2, -0.004}, {0.05, 0.2, -0.004}));  // curve 2
    stroke = make_stroke(9, 80, [](double u) {
      const double x = -0.3 + 0.6 * u;
      return Vec3(x, 0.06 * (1 - std::pow(2 * u - 1, 2)), 0.0);
    });
  }
};

const Constraint& crossing(const Correction& c, CurveId curve) {
  for (const Constraint& k : c.constraints)
    if (k.kind == ConstraintKind::intersection && k.references.size() == 2 && k.references[1].id == curve) return k;
  FAIL("no intersection constraint with curve " << curve);
  throw;
}

double gap(const Correction& c, const Vec3& p) {
  REQUIRE(c.edit.curves_added.size() == 1);
  return (closest_point(c.edit.curves_added[0].curve, p).point - p).norm();
}

}  // namespace

TEST_CASE("With an oracle the stroke enforces exactly the constraints the reference applied", "[cassie]") {
  TwoCrossings f;
  CassieParams p;
  p.planarity = false;
  const Correction searched = correct_stroke(f.stroke, f.sketch, p);
  REQUIRE(searched.error.empty());
  const Constraint& one = crossing(searched, 1);
  const Constraint& two = crossing(searched, 2);
  // Without the oracle the search keeps both: the property below fails.
  REQUIRE(one.enforced);
  REQUIRE(two.enforced);
  CHECK(gap(searched, two.target) < 1e-9);
  CHECK(searched.stats.extra.count("oracle") == 0);

  // The reference applied the first only, logged 3 mm from our target (within δ/2).
  const std::vector<Vec3> applied{one.target + Vec3(0.0, 0.003, 0.0)};
  const Correction c = correct_stroke(f.stroke, f.sketch, p, &applied);
  REQUIRE(c.error.empty());
  CHECK(crossing(c, 1).enforced);
  CHECK(crossing(c, 1).residual < 1e-9);
  CHECK(gap(c, crossing(c, 1).target) < 1e-9);
  CHECK_FALSE(crossing(c, 2).enforced);
  CHECK(gap(c, crossing(c, 2).target) > 1e-3);  // free: the stroke passes 4 mm off, as drawn
  CHECK(c.stats.subsets_tried == 1);            // no search
  CHECK(c.stats.extra.at("oracle") == 1);
  CHECK(c.stats.extra.at("oracle_matched") == 1);

  // With oracle_positions the curve passes through the logged target itself.
  CassieParams at_log = p;
  at_log.oracle_positions = true;
  const Correction logged = correct_stroke(f.stroke, f.sketch, at_log, &applied);
  REQUIRE(crossing(logged, 1).enforced);
  CHECK((crossing(logged, 1).target - applied[0]).norm() < 1e-12);
  CHECK(gap(logged, applied[0]) < 1e-9);
  CHECK(gap(c, applied[0]) > 1e-3);  // without it, at our own target 3 mm away
  CHECK_FALSE(crossing(logged, 2).enforced);

  // Beyond oracle_radius (δ/2 = 1 cm) nothing matches: both free.
  const std::vector<Vec3> far{one.target + Vec3(0.0, 0.015, 0.0)};
  const Correction none = correct_stroke(f.stroke, f.sketch, p, &far);
  CHECK_FALSE(crossing(none, 1).enforced);
  CHECK_FALSE(crossing(none, 2).enforced);
}

TEST_CASE("oracle_matches takes the nearest constraint to each applied target", "[cassie]") {
  std::vector<Candidate> cands(3);
  cands[0].target = Vec3(0, 0, 0);
  cands[1].target = Vec3(0.004, 0, 0);
  cands[2].target = Vec3(0.5, 0, 0);
  CHECK(oracle_matches(cands, {Vec3(0.003, 0, 0)}, 0.01) == std::vector<bool>{false, true, false});
  CHECK(oracle_matches(cands, {Vec3(0.002, 0, 0)}, 0.01) == std::vector<bool>{true, false, false});  // tie: first
  CHECK(oracle_matches(cands, {Vec3(0.3, 0, 0)}, 0.01) == std::vector<bool>(3, false));
  CHECK(oracle_matches(cands, {}, 0.01) == std::vector<bool>(3, false));
}

TEST_CASE("The cassie plugin reads its oracle file and names what is wrong in it", "[cassie][plugin]") {
  const std::filesystem::path dir = test::binary_path("tests/tmp/cassie_oracle");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TwoCrossings f;
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  const Correction searched =
      host.make_corrector("cassie", {{"planarity", false}})->correct(f.stroke, f.sketch);
  const Vec3 a = crossing(searched, 2).target;
  {
    std::ofstream(dir / "oracle.txt") << "# applied targets\n\n3 0 0 0 # another stroke\n9 " << a.x() << ' ' << a.y()
                                      << ' ' << a.z() << "\n";
  }
  const Correction c = host.make_corrector("cassie", {{"planarity", false}, {"oracle", (dir / "oracle.txt").string()}})
                           ->correct(f.stroke, f.sketch);
  CHECK_FALSE(crossing(c, 1).enforced);
  CHECK(crossing(c, 2).enforced);
  // A stroke the file does not list is searched as usual.
  Stroke other = f.stroke;
  other.id = 10;
  const Correction unlisted =
      host.make_corrector("cassie", {{"planarity", false}, {"oracle", (dir / "oracle.txt").string()}})
          ->correct(other, f.sketch);
  CHECK(crossing(unlisted, 1).enforced);
  CHECK(crossing(unlisted, 2).enforced);

  const auto rejects = [&](const std::string& text, const std::string& what) {
    std::ofstream(dir / "bad.txt") << text;
    try {
      read_constraint_oracle(dir / "bad.txt");
      FAIL("accepted: " << text);
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      CHECK(m.find((dir / "bad.txt").string() + ":2: ") != std::string::npos);
      CHECK(m.find(what) != std::string::npos);
    }
  };
  rejects("1 0 0 0\n2 0 0\n", "not a multiple of 3");
  rejects("1\n-4 0 0 0\n", "stroke id '-4'");
  rejects("1\nx 0 0 0\n", "stroke id 'x'");
  rejects("1\n2 0 nan 0\n", "coordinate 'nan'");
  rejects("1\n1 0 0 0\n", "listed twice");
  CHECK_THROWS_WITH(read_constraint_oracle(dir / "missing.txt"), Catch::Contains("missing.txt"));
  CHECK(read_constraint_oracle(dir / "oracle.txt").at(9).size() == 1);
}
