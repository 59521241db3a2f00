// default_keypoints, make_network_curve, curves_of_stroke, live_strokes.
#include <catch2/catch.hpp>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/sketch.hpp"

using namespace sketchlab;

TEST_CASE("default keypoints are the ends and the arclength midpoint", "[network][keypoints]") {
  Curve c;
  // Uneven parameterisation: the midpoint by arclength is not at t = 1.
  c.control_points = {{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  c.sharp = {false, false, false};
  const std::vector<Keypoint> k = default_keypoints(c);
  REQUIRE(k.size() == 3);
  CHECK(k[0].kind == Keypoint::Kind::start);
  CHECK(k[0].t == 0.0);
  CHECK(k[0].position == Vec3(0, 0, 0));
  CHECK(k[1].kind == Keypoint::Kind::end);
  CHECK(k[1].t == 2.0);
  CHECK(k[1].position == Vec3(3, 0, 0));
  CHECK(k[2].kind == Keypoint::Kind::midpoint);
  CHECK(arclength(c, 0.0, k[2].t) == Approx(1.5).epsilon(1e-7));
  CHECK(k[2].position.x() == Approx(1.5).epsilon(1e-7));
  CHECK((evaluate(c, k[2].t) - k[2].position).norm() < 1e-12);

  Curve bad;
  bad.control_points = {{0, 0, 0}};
  CHECK_THROWS_AS(default_keypoints(bad), std::invalid_argument);
}

TEST_CASE("make_network_curve and curve_layer", "[network][keypoints]") {
  const Curve c = make_line(Vec3(0, 0, 0), Vec3(0, 2, 0));
  const NetworkCurve nc = make_network_curve(5, c, Layer::scaffold, 12);
  CHECK(nc.id == 5);
  CHECK(nc.curve == c);
  CHECK(nc.layer == Layer::scaffold);
  CHECK(nc.source_stroke == 12);
  CHECK(nc.keypoints == default_keypoints(c));
  CHECK(nc.normals.empty());
  CHECK(make_network_curve(1, c, Layer::free).source_stroke == 0);
  Curve bad;
  bad.control_points = {{0, 0, 0}};
  CHECK_THROWS_AS(make_network_curve(1, bad, Layer::free), std::invalid_argument);

  CHECK(curve_layer(Layer::automatic) == Layer::free);
  for (Layer l : {Layer::scaffold, Layer::shape, Layer::free, Layer::guide}) CHECK(curve_layer(l) == l);
}

TEST_CASE("curves_of_stroke and live_strokes", "[network][sketch]") {
  Sketch sketch;
  Edit e;
  const StrokeId sources[] = {7, 3, 7, 9};
  for (int i = 0; i < 4; ++i) {
    NetworkCurve c;
    c.id = static_cast<CurveId>(4 - i);  // added out of id order
    c.curve = make_line(Vec3(0, 0, i), Vec3(1, 0, i));
    c.source_stroke = sources[i];
    e.curves_added.push_back(c);
  }
  sketch.network.apply(e);
  CHECK(curves_of_stroke(sketch, 7) == std::vector<CurveId>{2, 4});
  CHECK(curves_of_stroke(sketch, 3) == std::vector<CurveId>{3});
  CHECK(curves_of_stroke(sketch, 5).empty());

  auto entry = [](std::optional<StrokeId> s) { return HistoryEntry{"stroke", s, {}}; };
  sketch.history.done = {entry(5), entry(std::nullopt), entry(2), entry(5), entry(8)};
  sketch.history.undone = {entry(11)};
  CHECK(live_strokes(sketch) == std::vector<StrokeId>{5, 2, 8});

  // Of the live strokes only those with curves; 7, 3 and 9 made curves but
  // are not in the history, 5, 2 and 8 are live but made none.
  sketch.history.done.push_back(entry(7));
  sketch.history.done.push_back(entry(9));
  CHECK(strokes_with_curves(sketch) == std::vector<StrokeId>{7, 9});
}
