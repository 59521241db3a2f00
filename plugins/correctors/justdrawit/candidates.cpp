#include "candidates.hpp"

#include <optional>

#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::justdrawit {

std::vector<Candidate> gather_candidates(const Scene& scene, const Points2& s2, const std::vector<double>& cum,
                                         const Ctx& ctx) {
  const double d = ctx.d;
  std::vector<Candidate> cands;
  struct Ends {
    EndMatch s, e;
  };
  std::vector<Ends> ends(scene.items.size());
  for (std::size_t i = 0; i < scene.items.size(); ++i) {
    check_budget();  // issue 17: the per-event time budget
    const SceneItem& it = scene.items[i];
    // Nothing behind a visible draw plane (§4.3). A curve drawn on the plane
    // is not behind it: depths within the stroke's reach d (in world units
    // at the curve) count as on the plane, else rounding (~1e-16 m) hides
    // the curve a multi-stroke curve's next stroke continues.
    if (ctx.draw_plane) {
      const double on_plane = d * ctx.cam.world_per_pixel(it.centroid);
      bool behind = true;
      for (const Vec3& q : it.pts3) {
        const auto z = plane_depth(ctx.cam, *ctx.draw_plane, q);
        if (!z || *z <= on_plane) {
          behind = false;
          break;
        }
      }
      if (behind) continue;
    }
    ends[i].s = classify_end(s2, cum, it.proj, false, d);
    ends[i].e = classify_end(s2, cum, it.proj, true, d);
    const auto m = match_type(ends[i].s, ends[i].e, it.proj, d);
    if (!m) continue;
    Candidate c;
    c.curve = it.id;
    c.match = *m;
    c.decision = m->type == MatchType::oversketch       ? Decision::oversketch
                 : m->type == MatchType::extend         ? Decision::extend
                 : m->type == MatchType::extend_close   ? Decision::extend_close
                                                        : Decision::partial_oversketch;
    const bool join = m->start.kind == EndKind::join || m->end.kind == EndKind::join;
    c.q_m = m->q_m;
    c.q_d = depth_score(it.z_min, it.z_max, scene.Z_min, scene.Z_max, m->type == MatchType::oversketch, join);
    c.q = final_score(c.q_d, c.q_m);
    cands.push_back(c);
  }
  // Combining two curves (§4.3 (2)): the stroke leaves one curve's end and
  // enters another's.
  auto attaches = [](const EndMatch& m) {
    return m.kind == EndKind::join || (m.kind == EndKind::merge && m.overhang);
  };
  for (std::size_t i = 0; i < scene.items.size(); ++i) {
    check_budget();  // issue 17: the per-event time budget
    if (!attaches(ends[i].s) || scene.items[i].proj.closed) continue;
    for (std::size_t j = 0; j < scene.items.size(); ++j) {
      if (j == i || !attaches(ends[j].e) || scene.items[j].proj.closed) continue;
      Candidate c;
      c.decision = Decision::combine;
      c.curve = scene.items[i].id;
      c.curve2 = scene.items[j].id;
      c.match.start = ends[i].s;
      c.match.end = ends[j].e;
      c.q_m = 0.5 * (ends[i].s.score + ends[j].e.score);
      const auto qd = [&](const SceneItem& it, const EndMatch& m) {
        return depth_score(it.z_min, it.z_max, scene.Z_min, scene.Z_max, false, m.kind == EndKind::join);
      };
      c.q_d = 0.5 * (qd(scene.items[i], ends[i].s) + qd(scene.items[j], ends[j].e));
      c.q = final_score(c.q_d, c.q_m);
      cands.push_back(c);
    }
  }
  std::optional<EndMatch> self = closes_on_itself(s2, d);
  if (self) {
    Candidate c;
    c.decision = Decision::new_closed_curve;
    c.self = *self;
    c.q_m = self->score;
    c.q = final_score(0, c.q_m);
    cands.push_back(c);
  }
  return cands;
}

}  // namespace sketchlab::justdrawit
