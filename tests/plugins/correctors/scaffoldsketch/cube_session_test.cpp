// ScaffoldSketch §4.1 end to end: twelve noisy cube edges drawn through the
// kernel Session become a cube (Figure 1/3 style scaffold).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>

#include "scaffoldsketch_corrector.hpp"
#include "sketchlab/session.hpp"
#include "test_helpers.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;
using namespace sketchlab::scaffoldsketch::test;

namespace {

// Samples of a hand-drawn line: ends moved by `end_noise`, a slight bow and
// millimetre jitter in between.
Stroke noisy_line(StrokeId id, const Vec3& a, const Vec3& b, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto offset = [&](double radius) {
    Vec3 v;
    do v = Vec3(unit(rng), unit(rng), unit(rng));
    while (v.norm() > 1.0 || v.norm() < 0.5);
    return Vec3(radius * v);
  };
  const Vec3 na = a + offset(0.02), nb = b + offset(0.02);
  const Vec3 bow = offset(0.004);
  Stroke s;
  s.id = id;
  s.layer = Layer::scaffold;
  const int n = 40;
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    Sample smp;
    smp.position = na + (nb - na) * u + 4 * u * (1 - u) * bow + offset(0.001);
    smp.position = i == 0 ? na : i == n ? nb : smp.position;
    smp.time = 0.01 * i;
    s.samples.push_back(smp);
  }
  return s;
}

}  // namespace

TEST_CASE("twelve noisy cube edges become a cube", "[scaffoldsketch]") {
  const double h = 0.3;
  const Vec3 o(-0.1, 1.0, 0.2);
  // Drawing order: the base, the verticals, the top (each stroke starts at a
  // corner that already exists, as people draw).
  const std::array<std::pair<int, int>, 12> edges{{{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                                   {0, 4}, {1, 5}, {2, 6}, {3, 7},
                                                   {4, 5}, {5, 6}, {6, 7}, {7, 4}}};
  const int group[12] = {0, 1, 0, 1, 2, 2, 2, 2, 0, 1, 0, 1};  // parallel classes

  for (unsigned seed = 1; seed <= 50; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    // A cube standing on the floor, turned by a random yaw about the
    // vertical axis (workspace.up = y), so no edge need be axis-aligned.
    const double yaw = std::uniform_real_distribution<double>(0.0, std::numbers::pi)(rng);
    const Mat3 turn = Eigen::AngleAxisd(yaw, Vec3::UnitY()).toRotationMatrix();
    std::array<Vec3, 8> c;
    for (int i = 0; i < 8; ++i)
      c[static_cast<std::size_t>(i)] =
          o + turn * (h * Vec3((i == 1 || i == 2 || i == 5 || i == 6), i >= 4,
                               (i == 2 || i == 3 || i == 6 || i == 7)));
    ScaffoldParams params;
    Session session(Workspace{}, std::make_shared<ScaffoldSketchCorrector>(params, ShapeParams{}),
                    nullptr);
    // The user aims at what they see: a corner already drawn is aimed at
    // where the corrected lines show it; a new corner at the drawn start plus
    // the intended edge. Each aim then misses by 1-2 cm.
    std::array<std::optional<Vec3>, 8> shown;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const auto [i, j] = edges[e];
      const Vec3 from_aim = shown[static_cast<std::size_t>(i)].value_or(c[static_cast<std::size_t>(i)]);
      const Vec3 to_aim = shown[static_cast<std::size_t>(j)].value_or(
          from_aim + c[static_cast<std::size_t>(j)] - c[static_cast<std::size_t>(i)]);
      const Stroke s = noisy_line(100 + e, from_aim, to_aim, rng);
      // The noise is the paper's user-study regime: ends a few cm off, the
      // direction within the 10° of eq. 3-4 (so every intended relation is
      // a candidate; beyond that no corrector could be asked for a cube).
      const Vec3 drawn = s.samples.back().position - s.samples.front().position;
      const Vec3 aimed = to_aim - from_aim;
      REQUIRE(std::atan2(drawn.cross(aimed).norm(), drawn.dot(aimed)) < 10 * degrees);
      REQUIRE((s.samples.front().position - from_aim).norm() <= 0.02);
      REQUIRE((s.samples.back().position - to_aim).norm() <= 0.02);
      const StepReport r = session.handle(Event{0.1 * static_cast<double>(e), StrokeEvent{s}});
      REQUIRE(r.error.empty());
      CHECK(r.stats.iterations >= (e == 0 ? 0 : 1));  // the first edge has nothing to relate to
      CHECK(r.stats.iterations <= 6);  // the paper sees 2-6 IRLS rounds
      const auto ids = curves_of_stroke(session.sketch(), 100 + e);
      REQUIRE(ids.size() == 1);
      const Curve& line = session.sketch().network.find_curve(ids[0])->curve;
      shown[static_cast<std::size_t>(i)] = line.control_points.front();
      shown[static_cast<std::size_t>(j)] = line.control_points.back();
    }
    const Sketch& sketch = session.sketch();
    REQUIRE(sketch.network.curves().size() == 12);

    std::array<Vec3, 12> from, to;
    for (std::size_t e = 0; e < 12; ++e) {
      const auto ids = curves_of_stroke(sketch, 100 + e);
      REQUIRE(ids.size() == 1);
      const Curve& line = sketch.network.find_curve(ids[0])->curve;
      CHECK(line.kind == CurveKind::line);
      from[e] = line.control_points.front();
      to[e] = line.control_points.back();
    }
    // Corners coincide (1e-6 m), parallel classes within 0.01°, equal lengths
    // within 1e-6 relative.
    for (int corner = 0; corner < 8; ++corner) {
      std::vector<Vec3> at;
      for (std::size_t e = 0; e < 12; ++e) {
        if (edges[e].first == corner) at.push_back(from[e]);
        if (edges[e].second == corner) at.push_back(to[e]);
      }
      REQUIRE(at.size() == 3);
      for (const Vec3& p : at) CHECK((p - at[0]).norm() < 1e-6);
    }
    const double length0 = (to[0] - from[0]).norm();
    for (std::size_t e = 0; e < 12; ++e) {
      CHECK(std::abs((to[e] - from[e]).norm() / length0 - 1) < 1e-6);
      for (std::size_t f = 0; f < 12; ++f) {
        if (group[e] != group[f]) continue;
        const Vec3 u = (to[e] - from[e]).normalized(), v = (to[f] - from[f]).normalized();
        const double angle = std::atan2(u.cross(v).norm(), std::abs(u.dot(v)));
        CHECK(angle < 0.01 * degrees);
      }
    }
    // Each corner is one node joining its three edges.
    CHECK(sketch.network.nodes().size() == 8);
    for (const auto& [id, node] : sketch.network.nodes()) CHECK(node.incidences.size() == 3);
  }
}
