#include "session_synthesis.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "models.hpp"
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

View tablet_view(const GroundTruthNetwork& net) {
  View v;
  const Vec3 dir = Vec3(0.55, 0.45, 1.0).normalized();
  const double distance = 2.0 * network_scale(net);
  v.view = look_at(model_center + distance * dir, model_center, Vec3::UnitY());
  v.projection = perspective(35.0 * std::numbers::pi / 180.0, 1.6, 0.01, 100.0);
  v.viewport = Vec4(0, 0, 1600, 1000);
  v.dpi = 96.0;
  return v;
}

Recording synthesize_session(const SynthesisParams& p) {
  if (!(p.noise >= 0.0) || !std::isfinite(p.noise))
    throw std::invalid_argument("synthetic: noise must be a finite number >= 0");
  const GroundTruthNetwork plan = plan_drawing(build_network(p));
  if (plan.curves.empty()) throw std::invalid_argument("synthetic: the model has no curves");
  const auto relations = infer_relations(plan);
  const bool vr = p.modality == Modality::vr;

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
  const View head = vr_head_view();
  const View camera = tablet_view(plan);
  const Vec4 view_plane =
      plane_through(model_center, (eye_position(camera) - model_center).normalized());
  const NoiseModel noise = scaled(vr ? p.vr_noise : p.tablet_noise, p.noise);
  const MotionModel& motion = vr ? p.vr_motion : p.tablet_motion;

  Rng session_rng(mix_seed(p.seed, 0xFFFFFFFFull));
  double time = 0.5;
  std::size_t next_relation = 0;
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    Rng rng(mix_seed(p.seed, i));
    Stroke s;
    s.id = static_cast<StrokeId>(i + 1);
    s.layer = gc.layer;
    if (vr) {
      s.samples = synthesize_vr_stroke(gc.curve, vr_head_position, noise, motion, time, rng);
      s.view = head;
    } else {
      s.samples = synthesize_tablet_stroke(gc.curve, camera, noise, motion, time, rng);
      s.view = camera;
      s.samples_are_pixels = true;
      // The view plane through the model centre, the desktop viewer's default
      // draw plane: world-space correctors get the stroke lifted onto it.
      s.draw_plane = view_plane;
    }
    const double end = s.samples.back().time;
    rec.events.push_back({end, StrokeEvent{std::move(s)}});
    rec.events.push_back({end, ReferenceEvent{static_cast<StrokeId>(i + 1), "ground_truth", gc.curve}});
    for (; next_relation < relations.size(); ++next_relation) {
      const GroundTruthRelation& r = relations[next_relation];
      if (*std::max_element(r.curves.begin(), r.curves.end()) != i) break;
      RelationEvent e{"ground_truth", r.kind, {}, r.parameters};
      for (std::size_t c : r.curves) e.strokes.push_back(static_cast<StrokeId>(c + 1));
      rec.events.push_back({end, std::move(e)});
    }
    time = end + p.pause * session_rng.uniform(0.6, 1.4);
  }
  return rec;
}

}  // namespace sketchlab::synthetic
