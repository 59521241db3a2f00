#include <catch2/catch.hpp>

#include "kkt_solve.hpp"
#include "sketchlab/geometry/split.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;

namespace {
Curve two_segment_curve() {
  Curve c;
  c.control_points = {{0, 0, 0}, {0.1, 0.05, 0}, {0.2, 0.1, 0}, {0.3, 0.1, 0},
                      {0.4, 0.1, 0}, {0.5, 0.05, 0}, {0.6, 0, 0}};
  c.sharp = {false, false, false};
  return c;
}
}  // namespace

TEST_CASE("KKT solve without constraints returns the input", "[cassie][kkt]") {
  SolveProblem p;
  p.input = two_segment_curve();
  const SolveResult r = solve_constrained(p);
  REQUIRE(r.ok);
  for (std::size_t i = 0; i < r.control_points.size(); ++i)
    CHECK((r.control_points[i] - p.input.control_points[i]).norm() < 1e-12);
  CHECK(r.fidelity == Approx(0.0).margin(1e-20));
}

TEST_CASE("KKT solve meets a point target exactly and keeps G1", "[cassie][kkt]") {
  SolveProblem p;
  p.input = two_segment_curve();
  p.points.push_back({3, Vec3(0.3, 0.13, 0.01)});
  p.points.push_back({0, Vec3(0.0, -0.01, 0.0)});
  const SolveResult r = solve_constrained(p);
  REQUIRE(r.ok);
  CHECK(r.max_constraint_residual < 1e-9);
  CHECK((r.control_points[3] - Vec3(0.3, 0.13, 0.01)).norm() < 1e-12);
  // G1 at the interior joint: incoming and outgoing edges parallel.
  const Vec3 in = r.control_points[3] - r.control_points[2];
  const Vec3 out = r.control_points[4] - r.control_points[3];
  CHECK(in.normalized().cross(out.normalized()).norm() < 1e-9);
  CHECK(in.dot(out) > 0);
  CHECK(r.fidelity > 0);
}

TEST_CASE("Fidelity energy follows eq. 3.2", "[cassie][kkt]") {
  const Curve c = two_segment_curve();
  std::vector<Vec3> moved = c.control_points;
  for (Vec3& q : moved) q += Vec3(0.01, 0, 0);  // a translation: slope term 0
  const double l = 0.6, m = 7;
  CHECK(fidelity_energy(c.control_points, moved, 1e-9) == Approx(m * 1e-4 / (m * l * l)));
}

TEST_CASE("Planarity energy flattens a bent curve", "[cassie][kkt]") {
  SolveProblem p;
  p.input = two_segment_curve();
  p.input.control_points[3].z() = 0.05;
  p.plane_normal = Vec3::UnitZ();
  p.planarity_weight = 1e6;
  const SolveResult r = solve_constrained(p);
  REQUIRE(r.ok);
  double spread = 0;
  for (const Vec3& q : r.control_points) spread = std::max(spread, std::abs(q.z() - r.control_points[0].z()));
  CHECK(spread < 1e-4);
}
