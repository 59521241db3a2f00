#include "justdrawit_corrector.hpp"

// The pipeline for one stroke; its steps live in stroke_scene (the curves in
// view), candidates and choice (what the stroke may do, and which),
// apply_decision (the new points), new_curve_placement (§5.1 surfaces) and
// curve_edit (the resulting edit).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "apply_decision.hpp"
#include "sketchlab/camera.hpp"
#include "candidates.hpp"
#include "choice.hpp"
#include "curve_edit.hpp"
#include "inference_context.hpp"
#include "network_curves.hpp"
#include "new_curve_placement.hpp"
#include "scratch.hpp"
#include "sketchlab/draw_plane.hpp"
#include "sketchlab/network_diff.hpp"
#include "stroke_scene.hpp"

namespace sketchlab::justdrawit {

namespace {

CurveId last_edited_curve(const std::vector<HistoryEntry>& done, std::size_t count) {
  for (std::size_t k = count; k-- > 0;) {
    const HistoryEntry& e = done[k];
    if (e.action != "stroke") continue;
    for (const HistoryStep& s : e.steps) {
      if (!s.forward.curves_replaced.empty()) return s.forward.curves_replaced.front().id;
      if (!s.forward.curves_added.empty()) return s.forward.curves_added.front().id;
    }
    return 0;
  }
  return 0;
}

// The analysis, choice and application for a prepared stroke on `net`.
Outcome process(const Points2& s2, const Stroke& stroke, const Sketch& sketch, const Network& net,
                CurveId last, const Ctx& ctx) {
  Outcome o;
  const Scene scene = build_scene(net, ctx.cam, s2, ctx.d, true);
  const auto cum = cumulative(s2);
  const std::vector<Candidate> cands = gather_candidates(scene, s2, cum, ctx);
  const int chosen = choose(cands, last);
  o.stats.extra["candidates"] = static_cast<double>(cands.size());
  o.stats.extra["curves_analysed"] = static_cast<double>(scene.items.size());
  // Runners-up by score.
  std::vector<int> order(cands.size());
  for (std::size_t i = 0; i < cands.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cands[a].q < cands[b].q; });
  int rank = 0;
  for (int i : order) {
    if (i == chosen || rank >= 3) continue;
    ++rank;
    const std::string k = "runner_up_" + std::to_string(rank) + "_";
    o.stats.outcomes[k + "decision"] = to_string(cands[i].decision);
    o.stats.extra[k + "score"] = cands[i].q;
    o.stats.extra[k + "curve"] = static_cast<double>(cands[i].curve);
  }

  const SceneItem* item_a = nullptr;
  const SceneItem* item_b = nullptr;
  auto find_item = [&](CurveId id) -> const SceneItem* {
    for (const SceneItem& it : scene.items)
      if (it.id == id) return &it;
    return nullptr;
  };
  Built built;
  Decision decision = Decision::new_curve;
  double score = 0;
  std::string surface_used;
  if (chosen >= 0 && cands[chosen].decision != Decision::new_closed_curve) {
    const Candidate& c = cands[chosen];
    decision = c.decision;
    score = c.q;
    item_a = find_item(c.curve);
    if (c.decision == Decision::combine) {
      item_b = find_item(c.curve2);
      built = apply_combine(c, *item_a, *item_b, s2, ctx);
    } else {
      built = apply_single(c, *item_a, s2, ctx);
    }
  }
  if (chosen < 0 || cands[chosen].decision == Decision::new_closed_curve || !built.error.empty()) {
    if (!built.error.empty()) o.stats.extra["fallback_to_new_curve"] = 1;
    item_a = item_b = nullptr;
    auto placed = place_new(s2, stroke, sketch, net, last, ctx, surface_used);
    if (!placed) {
      o.error = "stroke " + std::to_string(stroke.id) + ": no drawing surface under the stroke";
      return o;
    }
    built = Built{};
    built.pts = std::move(*placed);
    decision = Decision::new_curve;
    if (chosen >= 0 && cands[chosen].decision == Decision::new_closed_curve) {
      const Candidate& c = cands[chosen];
      decision = Decision::new_closed_curve;
      score = c.q;
      close_new_curve(built, c, cum, ctx);
    }
  }
  o.stats.outcomes["decision"] = to_string(decision);
  o.stats.extra["score"] = score;
  if (item_a) o.stats.extra["curve"] = static_cast<double>(item_a->id);

  add_edit(o, built, decision, item_a, item_b, surface_used, stroke, net, ctx);
  return o;
}

}  // namespace

Points2 prepare_stroke(const Stroke& stroke, const JdiParams& p) {
  Points2 pts = dedupe(pixels(stroke), 1e-9);
  if (pts.size() < 2 || !(length(pts) > 1e-6)) return pts;
  // §4.5: at least 10 samples per d, then N rounds of smoothing.
  pts = resample(pts, stroke_spacing(pts, p.d));
  smooth(pts, p.smoothing);
  if (p.scratch) {
    pts = unfold_stroke(pts, p.d);
    if (pts.size() >= 2 && length(pts) > 1e-6) pts = resample(pts, stroke_spacing(pts, p.d));
  }
  return pts;
}

Correction justdrawit_correct(const Stroke& stroke, const Sketch& sketch, const JdiParams& p) {
  Correction out;
  if (!stroke.is_2d()) {
    out.error = "stroke " + std::to_string(stroke.id) +
                ": JustDrawIt needs 2D strokes (pixels plus a View); this stroke is 3D";
    return out;
  }
  const Camera cam(*stroke.view);
  Stroke kept = stroke;
  std::erase_if(kept.samples, [&](const Sample& s) {
    return !on_screen(s.position.head<2>(), stroke.view->viewport);
  });
  const std::size_t glitches = stroke.samples.size() - kept.samples.size();
  if (stroke.draw_plane) {
    // As for world-space correctors (kernel lift_to_draw_plane): a ray that
    // misses the plane, or grazes it, puts the stroke absurdly far away.
    std::string miss;
    lift_to_draw_plane(kept, miss);
    if (!miss.empty()) {
      out.error = miss;
      return out;
    }
  }
  Points2 s2 = prepare_stroke(stroke, p);
  if (s2.size() < 2 || !(length(s2) > 1e-6)) {
    out.error = "stroke " + std::to_string(stroke.id) + " has zero length" +
                (glitches ? " once its " + std::to_string(glitches) +
                                " samples far off screen (more than a viewport outside it) are left out"
                          : "");
    return out;
  }
  if (p.surface == SurfaceKind::inflation && stroke.layer == Layer::guide) {
    // Guide strokes only define the inflation surface (§5.1).
    out.stats.extra["guide"] = 1;
    return out;
  }
  std::optional<Plane> draw_plane;
  const auto& done = sketch.history.done;

  // §4.1 / §4.3 (4): a stroke overlapping the previous stroke(s) by > 90 % is
  // blended with them; the result replaces what they did.
  std::size_t keep = done.size();
  std::vector<Points2> chain;
  while (keep > 0 && chain.size() < 8) {
    const HistoryEntry& e = done[keep - 1];
    if (e.action != "stroke" || !e.stroke) break;
    const auto it = sketch.strokes.find(*e.stroke);
    if (it == sketch.strokes.end() || !it->second.is_2d() || !(*it->second.view == *stroke.view))
      break;
    Points2 prev = prepare_stroke(it->second, p);
    if (prev.size() < 2 || overlap_fraction(s2, prev, p.d) <= 0.9) break;
    chain.push_back(std::move(prev));
    --keep;
  }
  const CurveId last = last_edited_curve(done, keep);
  Network base;
  const Network* net = &sketch.network;
  if (!chain.empty()) {
    base = sketch.network;
    for (std::size_t k = done.size(); k-- > keep;)
      for (auto st = done[k].steps.rbegin(); st != done[k].steps.rend(); ++st) base.apply(st->inverse);
    std::vector<Points2> sections(chain.rbegin(), chain.rend());
    sections.push_back(s2);
    const Points2 blended = blend_sections(std::move(sections), p.d);
    s2 = resample(blended, stroke_spacing(blended, p.d));
    net = &base;
  }
  if (stroke.draw_plane) {
    draw_plane = plane_from_coefficients(*stroke.draw_plane);
  } else if (p.surface == SurfaceKind::draw_plane) {
    draw_plane = draw_plane_from(p, *net, last);
  }
  const Ctx ctx{p, cam, p.d, draw_plane};
  Outcome o = process(s2, stroke, sketch, *net, last, ctx);
  if (!o.error.empty()) {
    out.error = o.error;
    return out;
  }
  o.stats.extra["blended_strokes"] = static_cast<double>(chain.size());
  if (glitches) o.stats.extra["offscreen_samples_dropped"] = static_cast<double>(glitches);
  if (!chain.empty()) {
    Network next = base;
    next.apply(o.edit);
    o.edit = edit_between(sketch.network, next);
  }
  out.edit = std::move(o.edit);
  out.constraints = std::move(o.constraints);
  out.stats = std::move(o.stats);
  return out;
}

}  // namespace sketchlab::justdrawit
