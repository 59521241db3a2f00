// Analytic-drawing construction: the scaffold, the order and the guidelines
// a trained user of Schmidt et al. 2009 draws.
#include <catch2/catch.hpp>
#include <set>

#include "construction.hpp"
#include "models.hpp"
#include "relations.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "synthetic_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;

namespace {

bool on_any(const std::vector<GroundTruthCurve>& curves, std::size_t count, const Vec3& p) {
  for (std::size_t k = 0; k < count; ++k)
    if (closest_point(curves[k].curve, p).distance <= 1e-9) return true;
  return false;
}

int axis(const Vec3& d) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(d.normalized()[k]) - 1.0) < 1e-12) return k;
  return -1;
}

}  // namespace

TEST_CASE("circles get their square, diagonals and cross, coaxial squares are joined", "[synthetic][construction]") {
  const GroundTruthNetwork mug = make_mug(model_center, 0.3);
  const GroundTruthNetwork net = with_construction_scaffold(mug);
  // Rim and base: 4 sides + 2 diagonals + 2 diameters each, 4 box verticals;
  // each circle is split into two open halves (2 more curves).
  REQUIRE(net.curves.size() == mug.curves.size() + 22);
  int scaffold = 0;
  for (const auto& c : net.curves) {
    CHECK_FALSE(c.curve.closed);
    scaffold += c.layer == Layer::scaffold && c.curve.kind == CurveKind::line;
  }
  CHECK(scaffold == 20);
  // Every circle joint is the end of a scaffold line (the cross), so curve
  // inference finds it as a position constraint.
  for (std::size_t c : {0u, 1u})
    for (int k = 0; k < 4; ++k) {
      const Vec3 joint = evaluate(mug.curves[c].curve, k);
      bool end = false;
      for (std::size_t i = 0; i < net.curves.size(); ++i)
        if (net.curves[i].layer == Layer::scaffold)
          for (const Vec3& e : {net.curves[i].curve.control_points.front(), net.curves[i].curve.control_points.back()})
          end = end || (e - joint).norm() < 1e-12;
      CHECK(end);
    }
  // The lamp's slanted arm gets its axis path; the chair its footprint.
  const GroundTruthNetwork lamp = with_construction_scaffold(make_lamp(model_center, 0.3));
  const GroundTruthNetwork chair = with_construction_scaffold(make_chair(model_center, 0.3));
  CHECK(chair.curves.size() == make_chair(model_center, 0.3).curves.size() + 4);
  int lamp_diagonals = 0;
  for (const auto& c : lamp.curves)
    lamp_diagonals += c.curve.kind == CurveKind::line && axis(c.curve.control_points.back() - c.curve.control_points.front()) < 0;
  // The arm, 4 shade sides, 2 diagonals per circle square (3 circles), the 4
  // lines joining the coaxial shade squares' corners (a frustum's box).
  CHECK(lamp_diagonals == 1 + 4 + 6 + 4);
  // Nothing is added twice: the lamp's own base diameters are its cross.
  const GroundTruthNetwork bare_lamp = make_lamp(model_center, 0.3);
  const Curve& diameter = bare_lamp.curves[1].curve;
  int copies = 0;
  for (const auto& c : lamp.curves)
    copies += c.curve.kind == CurveKind::line &&
              ((c.curve.control_points.front() - diameter.control_points.front()).norm() < 1e-12 ||
               (c.curve.control_points.front() - diameter.control_points.back()).norm() < 1e-12) &&
              ((c.curve.control_points.back() - diameter.control_points.front()).norm() < 1e-12 ||
               (c.curve.control_points.back() - diameter.control_points.back()).norm() < 1e-12);
  CHECK(copies == 1);
}

TEST_CASE("the analytic order starts in the ground plane and builds from known points", "[synthetic][construction]") {
  for (const std::string model : {"cube", "mug", "chair", "lamp", "rounded_box"}) {
    INFO(model);
    const GroundTruthNetwork plan = plan_analytic_drawing(with_construction_scaffold(make_model(model, model_center, 0.3)));
    REQUIRE(!plan.curves.empty());
    double floor = 1e9;
    for (const auto& c : plan.curves)
      for (const Vec3& p : c.curve.control_points) floor = std::min(floor, p.y());
    const Curve& first = plan.curves.front().curve;
    CHECK(first.kind == CurveKind::line);
    CHECK(axis(first.control_points.back() - first.control_points.front()) >= 0);
    CHECK(std::abs(first.control_points.front().y() - floor) < 1e-12);
    CHECK(std::abs(first.control_points.back().y() - floor) < 1e-12);
    // Every later line starts on what is drawn, but for the lamp, whose
    // shade meets the drawing only at the arm end: none of its lines is
    // drawn before that end is; a line along no axis joins two points drawn.
    bool arm_end_drawn = false;
    const Vec3 arm_end = model_center + Vec3(0.09, 0.105, 0.0);
    for (std::size_t i = 1; i < plan.curves.size(); ++i) {
      const Curve& c = plan.curves[i].curve;
      if (c.kind != CurveKind::line) continue;
      const Vec3 a = c.control_points.front(), b = c.control_points.back();
      const bool starts_on_drawing = on_any(plan.curves, i, a);
      if (model != "lamp") CHECK(starts_on_drawing);
      else if (!starts_on_drawing) CHECK(arm_end_drawn);
      if (axis(b - a) < 0) CHECK((starts_on_drawing && on_any(plan.curves, i, b)));
      for (const Vec3& p : {a, b}) arm_end_drawn = arm_end_drawn || (p - arm_end).norm() < 1e-12;
    }
    if (model == "lamp") CHECK(arm_end_drawn);
  }
}

TEST_CASE("guidelines and ticks start from known points", "[synthetic][construction]") {
  const GroundTruthNetwork plan = plan_analytic_drawing(with_construction_scaffold(make_cube(model_center, 0.3)));
  const View camera = tablet_view(plan);
  const auto strokes = with_guidelines(plan, camera);
  std::set<std::size_t> intended;
  std::vector<GroundTruthCurve> drawn;
  std::vector<std::pair<Vec3, Vec3>> guides;  // point, unit direction
  int ticks = 0;
  auto on_guide = [&](const Vec3& p) {
    return std::any_of(guides.begin(), guides.end(),
                       [&](const auto& g) { return (p - g.first).cross(g.second).norm() < 1e-9; });
  };
  for (const PlannedStroke& s : strokes) {
    const Vec3 a = s.curve.control_points.front(), b = s.curve.control_points.back();
    if (s.intended) {
      CHECK(intended.insert(*s.intended).second);
      CHECK(s.curve.control_points == plan.curves[*s.intended].curve.control_points);
      drawn.push_back({s.curve, s.layer});
    } else if (s.layer == Layer::guide) {
      // Along an axis from a known point: on a drawn curve, or a tick (which
      // lies on a guideline, as do the ticks it transfers).
      CHECK(axis(b - a) >= 0);
      CHECK((on_any(drawn, drawn.size(), a) || on_guide(a)));
      guides.push_back({a, (b - a).normalized()});
    } else {
      // A tick: across a guideline drawn before it, at its middle (§2.3).
      ++ticks;
      CHECK(on_guide(0.5 * (a + b)));
    }
  }
  CHECK(intended.size() == plan.curves.size());
  // A cube: 3 axes from each of its 8 corners, less the lines drawn already;
  // its edges' lengths copied from the first by ticks (Figure 6).
  CHECK(guides.size() > 0);
  CHECK(guides.size() < 24);
  CHECK(ticks > 0);
}

TEST_CASE("an analytic session has no ground truth for guidelines and refuses VR", "[synthetic][construction]") {
  SynthesisParams p = support::perfect("mug", Modality::tablet);
  p.style = DrawingStyle::analytic;
  const Recording rec = synthesize_session(p);
  std::set<StrokeId> guides, intended;
  for (const auto& d : support::drawn(rec)) {
    if (d.stroke.layer == Layer::guide) guides.insert(d.stroke.id);
    else intended.insert(d.stroke.id);
  }
  CHECK(!guides.empty());
  for (const Event& e : rec.events)
    if (const auto* r = std::get_if<ReferenceEvent>(&e.payload)) CHECK(!guides.count(r->stroke));
  for (const RelationEvent& r : support::relations(rec))
    for (StrokeId s : r.strokes) CHECK(intended.count(s));
  CHECK(rec.header.source.at("style") == "analytic");
  p.modality = Modality::vr;
  CHECK_THROWS_WITH(synthesize_session(p), Catch::Contains("modality=tablet"));
}

TEST_CASE("the lamp's shade is placed by dimension ticks on guidelines (§2.3, Figure 6)", "[synthetic][construction]") {
  const GroundTruthNetwork plan = plan_analytic_drawing(with_construction_scaffold(make_lamp(model_center, 0.3)));
  const auto strokes = with_guidelines(plan, tablet_view(plan));
  std::vector<std::pair<Vec3, Vec3>> guides;  // point, unit direction
  std::vector<Vec3> ticks;
  for (const PlannedStroke& s : strokes) {
    const Vec3 a = s.curve.control_points.front(), b = s.curve.control_points.back();
    if (s.layer == Layer::guide) guides.push_back({a, (b - a).normalized()});
    if (s.intended || s.layer == Layer::guide) continue;
    const Vec3 mid = 0.5 * (a + b);
    ticks.push_back(mid);
    // A tick crosses a guideline drawn before it, at its middle.
    CHECK(std::any_of(guides.begin(), guides.end(), [&](const auto& g) {
      return (mid - g.first).cross(g.second).norm() < 1e-9;
    }));
  }
  // The shade's top square (half side 0.018 m about the arm end, the middle
  // of its side): the dimension is ticked at the square's centre on the
  // guideline through the arm end, which transfers it to both corners.
  const Vec3 arm_end = model_center + Vec3(0.09, 0.105, 0.0);
  CHECK(std::any_of(ticks.begin(), ticks.end(),
                    [&](const Vec3& t) { return (t - (arm_end + Vec3(0.018, 0, 0))).norm() < 1e-9; }));
  CHECK(ticks.size() < 30);  // a few per part (20 now), not one per point
}

TEST_CASE("a model's curve is drawn on its finished construction: a circle after its square and cross", "[synthetic][construction]") {
  for (const std::string model : {"mug", "lamp"}) {
    INFO(model);
    const GroundTruthNetwork plan = plan_analytic_drawing(with_construction_scaffold(make_model(model, model_center, 0.3)));
    int curves = 0;
    for (std::size_t i = 0; i < plan.curves.size(); ++i) {
      const Curve& c = plan.curves[i].curve;
      if (plan.curves[i].layer == Layer::scaffold || c.kind == CurveKind::line) continue;
      ++curves;
      // Every construction line through one of its joints (a side of its
      // square, tangent there; a line of its cross, ending there) comes first.
      for (std::size_t j = 0; j < plan.curves.size(); ++j) {
        const Curve& l = plan.curves[j].curve;
        if (plan.curves[j].layer != Layer::scaffold || l.kind != CurveKind::line) continue;
        bool touches = false;
        for (int k = 0; k <= c.segment_count(); ++k) touches = touches || closest_point(l, evaluate(c, k)).distance < 1e-9;
        if (touches) CHECK(j < i);
      }
    }
    CHECK(curves == (model == "mug" ? 5 : 6));  // circle halves (and the mug's handle)
  }
}

TEST_CASE("small curves are drawn zoomed in, guidelines long enough (§2, §2.2)", "[synthetic][construction]") {
  for (const std::string model : {"cube", "lamp"}) {
    INFO(model);
    const GroundTruthNetwork plan = plan_analytic_drawing(with_construction_scaffold(make_model(model, model_center, 0.3)));
    const View camera = tablet_view(plan);
    const auto strokes = with_guidelines(plan, camera);
    int zoomed = 0;
    for (const PlannedStroke& s : strokes) {
      const View& v = s.zoomed ? *s.zoomed : camera;
      const Vec3 a = world_to_pixel(v, s.curve.control_points.front()), b = world_to_pixel(v, s.curve.control_points.back());
      if (s.zoomed) {
        ++zoomed;
        // Image-space zoom: the same eye, four times the magnification, the
        // stroke on the screen.
        CHECK((eye_position(*s.zoomed) - eye_position(camera)).norm() < 1e-9);
        CHECK(s.zoomed->projection(1, 1) == Approx(4 * camera.projection(1, 1)));
        for (const Vec3& p : {a, b})
          CHECK((p.x() >= 0 && p.x() <= 1600 && p.y() >= 0 && p.y() <= 1000));
      }
      // About 1.5 in at least (the scale is taken at its start; a receding
      // line shortens on screen).
      if (s.layer == Layer::guide) CHECK((a - b).head<2>().norm() >= 0.8 * 1.5 * 96);
      if (!s.intended) continue;
      Eigen::AlignedBox2d extent;
      for (int k = 0; k <= 16; ++k)
        extent.extend(world_to_pixel(camera, evaluate(s.curve, s.curve.t_max() * k / 16.0)).head<2>());
      CHECK(s.zoomed.has_value() == (extent.diagonal().norm() < 1.5 * 96));
    }
    if (model == "cube") CHECK(zoomed == 0);
    else CHECK(zoomed > 10);
  }
}
