#include <catch2/catch.hpp>
#include <cmath>

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

TEST_CASE("KKT solve: the range-space and sparse LU methods give one solution", "[cassie][kkt]") {
  // A stroke across 30 curves: a target at every interior joint, a tangent,
  // a plane and the closure (the many-constraint case kSparseLuRows picks
  // the sparse LU for).
  SolveProblem p;
  const int k_count = 30;
  for (int i = 0; i <= 3 * k_count; ++i)
    p.input.control_points.push_back(Vec3(0.01 * i, 0.003 * std::sin(0.7 * i), 0.0005 * i * i / k_count));
  p.input.sharp.assign(k_count + 1, false);
  p.input.sharp[10] = true;
  for (int k = 1; k < k_count; k += 2) p.points.push_back({3 * k, p.input.control_points[3 * k] + Vec3(0, 0.004, -0.002)});
  p.tangents.push_back({6, Vec3(1, 0.1, 0).normalized(), 2.0});
  p.plane_normal = Vec3(0.1, 0.2, 1).normalized();
  p.closure = true;
  p.fidelity = {0.04, 0.5};
  p.method = KktMethod::range_space;
  const SolveResult dense = solve_constrained(p);
  p.method = KktMethod::sparse_lu;
  const SolveResult sparse = solve_constrained(p);
  REQUIRE(dense.ok);
  REQUIRE(sparse.ok);
  CHECK(sparse.max_constraint_residual < 1e-9);
  double gap = 0.0;
  for (std::size_t i = 0; i < dense.control_points.size(); ++i)
    gap = std::max(gap, (dense.control_points[i] - sparse.control_points[i]).norm());
  CHECK(gap < 1e-12);
  CHECK(sparse.fidelity == Approx(dense.fidelity).epsilon(1e-12));
  CHECK((sparse.control_points.front() - sparse.control_points.back()).norm() == 0.0);
  // G1 at a smooth joint with a target, kept by the sparse LU too.
  const Vec3 in = sparse.control_points[9] - sparse.control_points[8];
  const Vec3 out = sparse.control_points[10] - sparse.control_points[9];
  CHECK(in.normalized().cross(out.normalized()).norm() < 1e-9);
  // Singular: two targets pulling one joint apart fail either way.
  p.points.push_back({3, p.input.control_points[3] + Vec3(0.01, 0, 0)});
  p.points.push_back({3, p.input.control_points[3] - Vec3(0.01, 0, 0)});
  for (KktMethod m : {KktMethod::range_space, KktMethod::sparse_lu}) {
    p.method = m;
    CHECK_FALSE(solve_constrained(p).ok);
  }
}
