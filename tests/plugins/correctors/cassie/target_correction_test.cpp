// Item 11's weights and tangent alignment (`assign_weights`).
#include <catch2/catch.hpp>

#include "cassie_params.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic.hpp"
#include "target_correction.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;
using sketchlab::test::add_curve;
using sketchlab::test::straight;

namespace {

// A constraint of `kind` on curve 1 at its end (t = 1), the origin.
std::vector<Candidate> at_origin(TargetKind kind, const Curve& stroke) {
  Candidate c;
  c.kind = kind;
  c.curve = 1;
  c.t_curve = 1.0;
  c.target = Vec3::Zero();
  std::vector<Candidate> out{c};
  place_on_stroke(out, stroke);
  return out;
}

}  // namespace

TEST_CASE("Item 11: at a node the tangents align when the curves' tangents point opposite ways",
          "[cassie][weights]") {
  Sketch sketch;
  add_curve(sketch, straight({-0.3, 0, 0}, {0, 0, 0}, 1));  // curve 1 ends at the origin along +x
  const Curve onward = straight({0, 0, 0}, {0.3, 0, 0}, 1);     // starts there, along +x (cos = +1)
  const Curve head_on = straight({0.3, 0, 0}, {0, 0, 0}, 1);    // ends there, along −x (cos = −1)
  CassieParams p;
  REQUIRE(p.node_alignment == NodeAlignment::opposite);
  const Thresholds th = thresholds(p, 1.0);
  SECTION("default (CASSIE's logs): the head-on stroke aligns, the onward one does not") {
    auto c = at_origin(TargetKind::node, onward);
    assign_weights(c, onward, sketch.network, sketch.workspace, p, th);
    CHECK_FALSE(c[0].tangent);
    CHECK(c[0].weight == 2.0);
    c = at_origin(TargetKind::node, head_on);
    assign_weights(c, head_on, sketch.network, sketch.workspace, p, th);
    REQUIRE(c[0].tangent);
    CHECK((*c[0].tangent - Vec3(-1, 0, 0)).norm() < 1e-12);  // along the stroke
    CHECK(c[0].weight == 2.5);
  }
  SECTION("node_alignment = same: the other way round") {
    p.node_alignment = NodeAlignment::same;
    auto c = at_origin(TargetKind::node, onward);
    assign_weights(c, onward, sketch.network, sketch.workspace, p, th);
    REQUIRE(c[0].tangent);
    CHECK((*c[0].tangent - Vec3(1, 0, 0)).norm() < 1e-12);
    CHECK(c[0].weight == 2.5);
    c = at_origin(TargetKind::node, head_on);
    assign_weights(c, head_on, sketch.network, sketch.workspace, p, th);
    CHECK_FALSE(c[0].tangent);
  }
  SECTION("on a curve (not a node) either sense aligns; the endpoint weight 1.25 does not lower 1.5") {
    for (const Curve* s : {&onward, &head_on}) {
      auto c = at_origin(TargetKind::curve, *s);
      assign_weights(c, *s, sketch.network, sketch.workspace, p, th);
      CHECK(c[0].tangent);
      CHECK(c[0].weight == 2.0);
    }
  }
}

TEST_CASE("Item 8: the 6 points replace the detected target, correction_keeps_target keeps it when nearest",
          "[cassie]") {
  Sketch sketch;
  add_curve(sketch, straight({0, -0.3, 0}, {0, 0.3, 0}, 1));  // curve 1 along y through the origin
  const Curve fitted = straight({-0.3, 0, 0.002}, {0.3, 0, 0.002}, 1);  // the new stroke crosses it 2 mm above
  Candidate c;
  c.kind = TargetKind::curve;
  c.curve = 1;
  c.t_curve = 0.5;
  c.target = Vec3::Zero();  // the crossing itself
  std::vector<Candidate> six{c}, seven{c};
  correct_targets(six, fitted, sketch.network, 0.01, 6);
  // The six points are ±2, ±6, ±10 mm along y: the nearest is 2 mm off the crossing.
  CHECK(std::abs(six[0].target.norm() - 0.002) < 1e-6);
  correct_targets(seven, fitted, sketch.network, 0.01, 6, true);
  CHECK(seven[0].target.norm() < 1e-12);
  CHECK(seven[0].t_curve == 0.5);
}
