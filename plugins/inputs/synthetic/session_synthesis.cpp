#include "session_synthesis.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "construction.hpp"
#include "models.hpp"
#include "multi_view.hpp"
#include "relations.hpp"
#include "sketchlab/draw_plane.hpp"

namespace sketchlab::synthetic {
namespace {

// Shortest text that reads back to v.
std::string format_number(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

GroundTruthNetwork build_network(const SynthesisParams& p) {
  if (!(p.size > 0.0) || !std::isfinite(p.size))
    throw std::invalid_argument("synthetic: size must be a finite number > 0");
  if (p.model == "mesh") {
    if (p.mesh.empty()) throw std::invalid_argument("synthetic: model 'mesh' needs the 'mesh' parameter (an OFF or PLY file)");
    return feature_network(mesh_feature_polylines(p.mesh, p.mesh_features), model_center, p.size,
                           std::filesystem::path(p.mesh).filename().string());
  }
  return make_model(p.model, model_center, p.size);
}

View vr_head_view() {
  View v;
  v.view = look_at(vr_head_position, model_center, Vec3::UnitY());
  v.projection = perspective(100.0 * std::numbers::pi / 180.0, 1440.0 / 1600.0, 0.05, 100.0);
  v.viewport = Vec4(0, 0, 1440, 1600);
  return v;
}

namespace {

View tablet_view_from(const GroundTruthNetwork& net, const Vec3& dir) {
  View v;
  const double distance = 2.0 * network_scale(net);
  v.view = look_at(model_center + distance * dir, model_center, Vec3::UnitY());
  v.projection = perspective(35.0 * std::numbers::pi / 180.0, 1.6, 0.01, 100.0);
  v.viewport = Vec4(0, 0, 1600, 1000);
  v.dpi = 96.0;
  return v;
}

const Vec3 tablet_direction = Vec3(0.55, 0.45, 1.0).normalized();

}  // namespace

View tablet_view(const GroundTruthNetwork& net) { return tablet_view_from(net, tablet_direction); }

View second_tablet_view(const GroundTruthNetwork& net) {
  return tablet_view_from(net, Eigen::AngleAxisd(-std::numbers::pi / 3.0, Vec3::UnitY()) * tablet_direction);
}

Recording synthesize_session(const SynthesisParams& p) {
  if (!(p.noise >= 0.0) || !std::isfinite(p.noise))
    throw std::invalid_argument("synthetic: noise must be a finite number >= 0");
  const bool vr = p.modality == Modality::vr;
  const bool analytic = p.style == DrawingStyle::analytic;
  if (p.style != DrawingStyle::plain && vr)
    throw std::invalid_argument(std::string("synthetic: style '") + (analytic ? "analytic" : "justdrawit") +
                                "' draws on a tablet (set modality=tablet)");
  const GroundTruthNetwork plan = analytic ? plan_analytic_drawing(with_construction_scaffold(build_network(p)))
                                           : plan_drawing(build_network(p));
  if (plan.curves.empty()) throw std::invalid_argument("synthetic: the model has no curves");
  const auto relations = infer_relations(plan);
  const View camera = tablet_view(plan);
  std::vector<PlannedStroke> strokes;
  if (analytic) {
    strokes = with_guidelines(plan, camera);
  } else if (p.style == DrawingStyle::justdrawit) {
    strokes = justdrawit_strokes(plan, p.draw_planes ? std::optional<Vec3>(eye_position(camera)) : std::nullopt);
  } else {
    for (std::size_t i = 0; i < plan.curves.size(); ++i)
      strokes.push_back({plan.curves[i].curve, plan.curves[i].layer, i});
  }

  Recording rec;
  rec.header.units = vr ? "m" : "px";
  rec.header.source = {
      {"generator", "sketchlab synthetic input 1.0"},
      {"model", plan.name},
      {"seed", std::to_string(p.seed)},
      {"modality", vr ? "vr" : "tablet"},
      {"noise", format_number(p.noise)},
      {"size", format_number(p.size)},
      {"ground_truth", "track ground_truth: intended curves (workspace metres) and relations"},
  };
  if (p.style != DrawingStyle::plain) rec.header.source["style"] = analytic ? "analytic" : "justdrawit";
  if (p.style == DrawingStyle::justdrawit && !p.draw_planes) rec.header.source["draw_planes"] = "false";
  const View head = vr_head_view();
  const View second = second_tablet_view(plan);
  const Vec4 view_plane =
      plane_through(model_center, (eye_position(camera) - model_center).normalized());
  const NoiseModel noise = scaled(vr ? p.vr_noise : p.tablet_noise, p.noise);
  const MotionModel& motion = vr ? p.vr_motion : p.tablet_motion;

  Rng session_rng(mix_seed(p.seed, 0xFFFFFFFFull));
  double time = 0.5;
  std::size_t next_relation = 0;
  std::vector<StrokeId> stroke_of(plan.curves.size(), 0);  // plan index -> stroke id
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const PlannedStroke& planned = strokes[i];
    const StrokeId id = static_cast<StrokeId>(i + 1);
    Rng rng(mix_seed(p.seed, i));
    Stroke s;
    s.id = id;
    s.layer = planned.layer;
    if (vr) {
      s.samples = synthesize_vr_stroke(planned.curve, vr_head_position, noise, motion, time, rng);
      s.view = head;
    } else {
      const View& v = planned.zoomed ? *planned.zoomed : planned.view == 0 ? camera : second;
      s.samples = synthesize_tablet_stroke(planned.curve, v, noise, motion, time, rng);
      s.view = v;
      s.samples_are_pixels = true;
      // The plane placed for the stroke, else the view plane through the model
      // centre (the desktop viewer's default draw plane): world-space
      // correctors get the stroke lifted onto it.
      s.draw_plane = planned.draw_plane    ? *planned.draw_plane
                     : planned.view == 0 ? view_plane
                                         : plane_through(model_center, (eye_position(v) - model_center).normalized());
    }
    const double end = s.samples.back().time;
    rec.events.push_back({end, StrokeEvent{std::move(s)}});
    if (planned.intended) {
      const std::size_t c = *planned.intended;
      if (!stroke_of[c]) stroke_of[c] = id;
      rec.events.push_back({end, ReferenceEvent{id, "ground_truth", plan.curves[c].curve}});
      for (; next_relation < relations.size(); ++next_relation) {
        const GroundTruthRelation& r = relations[next_relation];
        if (*std::max_element(r.curves.begin(), r.curves.end()) != c) break;
        RelationEvent e{"ground_truth", r.kind, {}, r.parameters};
        for (std::size_t k : r.curves) e.strokes.push_back(stroke_of[k]);
        rec.events.push_back({end, std::move(e)});
      }
    }
    time = end + p.pause * session_rng.uniform(0.6, 1.4);
  }
  return rec;
}

}  // namespace sketchlab::synthetic
