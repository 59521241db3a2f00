// Binding constraints to anchors (CASSIE app item 12) and the energy over
// the bound ones (item 13).
#include <catch2/catch.hpp>
#include <cmath>

#include "anchor_binding.hpp"
#include "subset_search.hpp"
#include "synthetic.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::straight;

namespace {

Candidate target(const Vec3& p, double w = 1.5) {
  Candidate c;
  c.target = p;
  c.weight = w;
  return c;
}

}  // namespace

TEST_CASE("Item 12: near an anchor the anchor is reused, elsewhere the curve is split", "[cassie][binding]") {
  const Curve fitted = straight({0, 0, 0}, {0.4, 0, 0}, 2);  // joints at x = 0, 0.2, 0.4
  // In order along the stroke: 1 cm from the start joint, mid-segment, 1.5 cm from the middle joint.
  const std::vector<Candidate> c{target({0.01, 0.005, 0}), target({0.1, 0.003, 0}), target({0.215, 0.004, 0})};
  const Binding b = bind_to_anchors(fitted, c, 0.02);
  REQUIRE(b.curve.segment_count() == 3);  // one split, at x = 0.1
  CHECK(b.anchor[0] == 0);
  CHECK(b.anchor[1] == 3);
  CHECK((b.curve.control_points[3] - Vec3(0.1, 0, 0)).norm() < 1e-12);
  CHECK(b.anchor[2] == 6);  // the old middle joint, shifted by the split
  CHECK((b.curve.control_points[6] - Vec3(0.2, 0, 0)).norm() < 1e-12);
}

TEST_CASE("Item 12: two constraints on one anchor: the closer to the curve wins, the other is dropped",
          "[cassie][binding]") {
  const Curve fitted = straight({0, 0, 0}, {0.4, 0, 0}, 2);
  // Both within δ of the end joint; the second is closer to the curve.
  const std::vector<Candidate> c{target({0.385, 0.012, 0}, 2.0), target({0.392, 0.004, 0}, 1.0)};
  const Binding b = bind_to_anchors(fitted, c, 0.02);
  CHECK(b.anchor[0] == -1);
  CHECK(b.anchor[1] == 6);
  // Item 13: the dropped one counts nowhere, not even in Σ all weights.
  CHECK(connectivity_energy(c, b, {1}, false) == Approx(std::exp(-1.0)));
  CHECK(connectivity_energy(c, b, {}, false) == Approx(1.0));
  // Thesis eq. 3.12: the total is over every detected constraint, weights
  // 2 + 1, so the bound one alone gives exp(−(1/3)²).
  CHECK(connectivity_energy(c, b, {1}, true) == Approx(std::exp(-1.0 / 9.0)));
  CHECK(connectivity_energy(c, b, {}, true) == Approx(1.0));
  // The search only sees the bound one.
  SearchSettings st;
  st.planarity_weight = 0.0;
  st.fidelity = {0.04, 0.5};
  const SearchResult r = greedy_search(b, c, st);
  REQUIRE(r.best.feasible);
  for (int i : r.best.subset) CHECK(i == 1);
}

TEST_CASE("Item 13: the app's fidelity, positions over (2δ)² and halves", "[cassie][binding]") {
  const std::vector<Vec3> in{{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}};
  std::vector<Vec3> moved = in;
  moved[3].y() += 0.04;  // one point by 2δ
  // 0.5/4·(0.04/0.04)² + 0.5/3·(0.04/0.1)²
  CHECK(fidelity_energy(in, moved, 1e-9, {0.04, 0.5}) == Approx(0.125 + 0.5 / 3 * 0.16));
  // Thesis eq. 3.2: positions over the span L = 0.3 m, no halves.
  CHECK(fidelity_energy(in, moved, 1e-9) == Approx(0.0016 / (4 * 0.09) + 0.16 / 3));
}
