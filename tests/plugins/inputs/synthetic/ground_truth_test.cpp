// Noise-free sessions reproduce their ground truth exactly, and the
// ground-truth relations hold exactly.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <set>

#include "models.hpp"
#include "relations.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;
using namespace sketchlab::synthetic::support;

namespace {

Vec3 line_direction(const Curve& c) { return c.control_points.back() - c.control_points.front(); }

// Smallest pixel distance between `pixel` and the projection of the curve:
// dense scan, then golden-section refinement around the best parameter.
double pixel_distance_to_projection(const View& view, const Curve& c, const Vec3& pixel) {
  auto dist = [&](double t) {
    const Vec3 p = world_to_pixel(view, evaluate(c, t));
    return std::hypot(p.x() - pixel.x(), p.y() - pixel.y());
  };
  const int n = 400 * c.segment_count();
  double best_t = 0.0, best = dist(0.0);
  for (int i = 1; i <= n; ++i) {
    const double t = c.t_max() * i / n;
    if (const double d = dist(t); d < best) best = d, best_t = t;
  }
  auto refine = [&](double around) {
    double a = std::max(0.0, around - c.t_max() / n), b = std::min(c.t_max(), around + c.t_max() / n);
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 200; ++it) {
      const double x1 = b - g * (b - a), x2 = a + g * (b - a);
      if (dist(x1) < dist(x2)) b = x2; else a = x1;
    }
    return dist(0.5 * (a + b));
  };
  best = std::min(best, refine(best_t));
  // On a closed curve t = 0 and t = t_max are the same point: look on both sides.
  if (c.closed && (best_t == 0.0 || best_t == c.t_max()))
    best = std::min(best, refine(c.t_max() - best_t));
  return best;
}

void check_relations_exact(const Recording& rec) {
  const auto strokes = drawn(rec);
  std::map<StrokeId, Curve> truth;
  for (const auto& d : strokes) truth[d.stroke.id] = d.truth;
  for (const RelationEvent& r : relations(rec)) {
    INFO("relation " << to_string(r.kind));
    CHECK(r.track == "ground_truth");
    for (StrokeId id : r.strokes) REQUIRE(truth.count(id));
    switch (r.kind) {
      case ConstraintKind::coincident_point:
      case ConstraintKind::intersection: {
        REQUIRE(r.strokes.size() == 2);
        REQUIRE(r.parameters.size() == 2);
        const Vec3 a = evaluate(truth[r.strokes[0]], r.parameters[0]);
        const Vec3 b = evaluate(truth[r.strokes[1]], r.parameters[1]);
        CHECK((a - b).norm() <= (r.kind == ConstraintKind::coincident_point ? 1e-12 : 1e-9));
        break;
      }
      case ConstraintKind::parallel:
      case ConstraintKind::perpendicular:
      case ConstraintKind::equal_length: {
        REQUIRE(r.strokes.size() == 2);
        CHECK(r.parameters.empty());
        const Curve& a = truth[r.strokes[0]];
        const Curve& b = truth[r.strokes[1]];
        REQUIRE(a.kind == CurveKind::line);
        REQUIRE(b.kind == CurveKind::line);
        const Vec3 da = line_direction(a).normalized(), db = line_direction(b).normalized();
        if (r.kind == ConstraintKind::parallel) CHECK(da.cross(db).norm() <= 1e-12);
        if (r.kind == ConstraintKind::perpendicular) CHECK(std::abs(da.dot(db)) <= 1e-12);
        if (r.kind == ConstraintKind::equal_length)
          CHECK(std::abs(line_direction(a).norm() - line_direction(b).norm()) <= 1e-12);
        break;
      }
      case ConstraintKind::planar: {
        REQUIRE(r.strokes.size() == 1);
        const auto& cp = truth[r.strokes[0]].control_points;
        const Vec3 n = (cp[1] - cp[0]).cross(cp[2] - cp[0]).normalized();
        for (const Vec3& p : cp) CHECK(std::abs(n.dot(p - cp[0])) <= 1e-12);
        break;
      }
      default:
        FAIL("unexpected relation kind");
    }
  }
}

}  // namespace

TEST_CASE("noise-free VR strokes lie on their ground-truth curves", "[synthetic][ground_truth]") {
  for (const std::string& model : model_names()) {
    INFO(model);
    const Recording rec = synthesize_session(perfect(model));
    CHECK(rec.header.units == "m");
    const auto strokes = drawn(rec);
    REQUIRE(!strokes.empty());
    for (const auto& d : strokes) {
      REQUIRE(validate(d.truth).empty());
      CHECK_FALSE(d.stroke.samples_are_pixels);
      double worst = 0.0;
      for (const Sample& s : d.stroke.samples)
        worst = std::max(worst, closest_point(d.truth, s.position).distance);
      CHECK(worst <= 1e-9);
      // The stroke covers the whole curve: it starts and ends at its ends.
      CHECK((d.stroke.samples.front().position - d.truth.control_points.front()).norm() <= 1e-12);
      CHECK((d.stroke.samples.back().position - d.truth.control_points.back()).norm() <= 1e-12);
    }
  }
}

TEST_CASE("noise-free tablet strokes are exact projections of the ground truth", "[synthetic][ground_truth]") {
  for (const std::string& model : {std::string("cube"), std::string("mug")}) {
    INFO(model);
    const Recording rec = synthesize_session(perfect(model, Modality::tablet));
    CHECK(rec.header.units == "px");
    for (const auto& d : drawn(rec)) {
      REQUIRE(d.stroke.view.has_value());
      CHECK(d.stroke.samples_are_pixels);
      CHECK(d.stroke.is_2d());
      double worst = 0.0;
      for (const Sample& s : d.stroke.samples) {
        CHECK(s.position.z() == 0.0);
        const Vec3 px = s.position;
        CHECK(px.x() >= 0.0);
        CHECK(px.x() <= 1600.0);
        CHECK(px.y() >= 0.0);
        CHECK(px.y() <= 1000.0);
        worst = std::max(worst, pixel_distance_to_projection(*d.stroke.view, d.truth, px));
      }
      CHECK(worst <= 1e-6);
      const Vec3 start = world_to_pixel(*d.stroke.view, d.truth.control_points.front());
      CHECK((d.stroke.samples.front().position.head<2>() - start.head<2>()).norm() <= 1e-9);
    }
  }
}

TEST_CASE("ground-truth relations hold exactly", "[synthetic][ground_truth][relations]") {
  for (const std::string& model : model_names()) {
    INFO(model);
    check_relations_exact(synthesize_session(perfect(model)));
  }
}

TEST_CASE("the cube's relations are the expected ones", "[synthetic][relations]") {
  const auto n = count_by_kind(relations(synthesize_session(perfect("cube"))));
  // 8 corners × 3 edge pairs meet at right angles; 3 directions × 3 links to
  // the first edge of each direction; 11 links to the first edge's length.
  CHECK(n.at(ConstraintKind::coincident_point) == 24);
  CHECK(n.at(ConstraintKind::perpendicular) == 24);
  CHECK(n.at(ConstraintKind::parallel) == 9);
  CHECK(n.at(ConstraintKind::equal_length) == 11);
  CHECK(n.count(ConstraintKind::intersection) == 0);
  CHECK(n.count(ConstraintKind::planar) == 0);
}

TEST_CASE("the mug's relations are the expected ones", "[synthetic][relations]") {
  const auto rels = relations(synthesize_session(perfect("mug")));
  const auto n = count_by_kind(rels);
  // Side k meets each circle at joint k: k = 0 is the circles' start
  // (coincident), k = 1..3 interior joints (intersections); the handle's two
  // ends lie on a side.
  CHECK(n.at(ConstraintKind::coincident_point) == 2);
  CHECK(n.at(ConstraintKind::intersection) == 8);
  CHECK(n.at(ConstraintKind::planar) == 3);
  CHECK(n.at(ConstraintKind::parallel) == 3);
  CHECK(n.at(ConstraintKind::equal_length) == 3);
  // Circle joints are hit at exact integer parameters.
  for (const auto& r : rels)
    if (r.kind == ConstraintKind::intersection || r.kind == ConstraintKind::coincident_point)
      for (double t : r.parameters) CHECK((t == std::round(t) || (t > 0.2 && t < 0.8)));
}

TEST_CASE("relations follow the last stroke they involve and name earlier strokes only", "[synthetic][relations]") {
  const Recording rec = synthesize_session(perfect("lamp"));
  std::set<StrokeId> seen;
  StrokeId last = 0;
  for (const Event& e : rec.events) {
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
      seen.insert(s->stroke.id);
      last = s->stroke.id;
    }
    if (const auto* r = std::get_if<RelationEvent>(&e.payload)) {
      for (StrokeId id : r->strokes) CHECK(seen.count(id));
      CHECK(std::find(r->strokes.begin(), r->strokes.end(), last) != r->strokes.end());
    }
  }
  const auto n = count_by_kind(relations(rec));
  // The two base diameters cross, and the stem starts on both.
  CHECK(n.at(ConstraintKind::intersection) >= 3);
}

TEST_CASE("strokes are planned: scaffold first, longest first, connected next", "[synthetic][plan]") {
  const GroundTruthNetwork plan = plan_drawing(make_rounded_box(Vec3::Zero(), 0.3));
  REQUIRE(plan.curves.size() == 18);
  for (std::size_t i = 0; i < 12; ++i) CHECK(plan.curves[i].layer == Layer::scaffold);
  for (std::size_t i = 12; i < 18; ++i) CHECK(plan.curves[i].layer == Layer::shape);
  // The first stroke is one of the longest edges (0.3 m along x).
  CHECK(line_direction(plan.curves[0].curve).norm() == Approx(0.3));
  // Every later scaffold edge touches an earlier one (the cube is connected).
  const double tol = 1e-9;
  for (std::size_t i = 1; i < 12; ++i) {
    bool touches = false;
    for (std::size_t j = 0; j < i; ++j)
      touches = touches || !contacts(plan.curves[j].curve, plan.curves[i].curve, tol).empty();
    CHECK(touches);
    // Drawn from the connection: the start touches the drawing.
    bool start_touches = false;
    for (std::size_t j = 0; j < i; ++j)
      start_touches = start_touches ||
                      closest_point(plan.curves[j].curve, plan.curves[i].curve.control_points.front()).distance <= tol;
    CHECK(start_touches);
  }
}

TEST_CASE("stroke events carry ids, layers and the head view", "[synthetic]") {
  const Recording rec = synthesize_session(perfect("chair"));
  const auto strokes = drawn(rec);
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    CHECK(strokes[i].stroke.id == i + 1);
    CHECK(strokes[i].stroke.layer == Layer::shape);
    REQUIRE(strokes[i].stroke.view.has_value());
    CHECK((eye_position(*strokes[i].stroke.view) - vr_head_position).norm() < 1e-12);
  }
  double t = 0.0;
  for (const Event& e : rec.events) {
    CHECK(e.time >= t);
    t = e.time;
  }
}
