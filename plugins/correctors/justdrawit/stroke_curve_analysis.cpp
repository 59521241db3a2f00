#include "stroke_curve_analysis.hpp"

#include <cmath>
#include <numbers>

namespace sketchlab::justdrawit {

namespace {
constexpr double pi = std::numbers::pi;
constexpr double max_merge_angle = 0.75 * pi;  // §4.2: 3/4 π
constexpr double max_travel_angle = 0.3;       // rad, eq. 2's α_t bound: not in the paper, see README

struct WalkPoint {
  std::size_t index;
  double inward;  // stroke arclength from the end being tested
  Projection<Vec2> proj;
  Vec2 tangent;   // stroke tangent in the walking direction
};

std::vector<WalkPoint> walk(const Points2& stroke, const std::vector<double>& cum,
                            const Projected& curve, bool at_end, double limit, double d) {
  std::vector<WalkPoint> out;
  const double l = cum.back();
  const std::size_t n = stroke.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = at_end ? n - 1 - k : k;
    const double inward = at_end ? l - cum[i] : cum[i];
    if (inward > limit) break;
    Vec2 t = tangent_at(stroke, cum, cum[i], 0.5 * d);
    if (at_end) t = -t;
    out.push_back({i, inward, project(curve.pts, curve.cum, stroke[i]), t});
  }
  return out;
}

bool off_end(const Projected& c, const Projection<Vec2>& p) {
  return !c.closed && (p.at_start || p.at_end);
}

}  // namespace

double curve_step(const Projected& c, double from, double to) {
  double delta = to - from;
  if (c.closed && c.length() > 0) {
    const double l = c.length();
    while (delta > 0.5 * l) delta -= l;
    while (delta < -0.5 * l) delta += l;
  }
  return delta;
}

double merge_middle(const Projected& c, const EndMatch& m) {
  const double mid = m.curve_at_s0 + 0.5 * curve_step(c, m.curve_at_s0, m.curve_at_s1);
  if (!c.closed || !(c.length() > 0)) return mid;
  const double l = c.length();
  return std::fmod(std::fmod(mid, l) + l, l);
}

Projected make_projected(Points2 pts, bool closed) {
  Projected p;
  p.pts = std::move(pts);
  p.cum = cumulative(p.pts);
  p.closed = closed;
  return p;
}

double join_score(double alpha_d, double alpha_t, double d_j, double d) {
  // §4.3 eq. 3–5 (the paper's "α_a" in q_a is the total angle α_t).
  const double q_a = (alpha_d / 0.2) / 4 + 3 * (alpha_t / 0.3) / 4;
  const double q_l = d_j / (8 * d);
  if (q_l > 0.75) return (1 + (q_l - 0.75) / 0.25) * q_a;
  if (q_l < 0.25) return (1 + q_l / 0.25) * q_a;
  return q_a;
}

std::optional<EndMatch> merge_test(const Points2& stroke, const std::vector<double>& cum,
                                   const Projected& curve, bool at_end, double d) {
  if (stroke.size() < 2 || curve.pts.size() < 2 || !(curve.length() > 0)) return std::nullopt;
  const double l = cum.back();
  // s_e: 1/3 of the stroke or 3d along it, whichever is smaller (§4.2).
  const double limit = std::min(l / 3, 3 * d);
  const std::vector<WalkPoint> w = walk(stroke, cum, curve, at_end, limit, d);
  if (w.size() < 2) return std::nullopt;
  double votes = 0;
  for (const WalkPoint& p : w)
    if (p.proj.distance < 1.5 * d)
      votes += p.tangent.dot(tangent_at(curve.pts, curve.cum, p.proj.s, 0.5 * d));
  if (votes == 0) return std::nullopt;
  const int dir_walk = votes > 0 ? 1 : -1;

  // Largest contiguous region of s_e that is within 1.5d, does not fold back
  // on the curve, does not project off its end, and meets it at < 3/4 π.
  std::vector<double> angle(w.size());
  std::vector<bool> ok(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Vec2 tc = dir_walk * tangent_at(curve.pts, curve.cum, w[k].proj.s, 0.5 * d);
    angle[k] = clamp_angle(w[k].tangent.dot(tc));
    ok[k] = w[k].proj.distance < 1.5 * d && !off_end(curve, w[k].proj) && angle[k] < max_merge_angle;
  }
  std::size_t best_a = 0, best_b = 0;
  double best_len = -1;
  for (std::size_t a = 0; a < w.size();) {
    if (!ok[a]) {
      ++a;
      continue;
    }
    std::size_t b = a;
    while (b + 1 < w.size() && ok[b + 1] &&
           dir_walk * curve_step(curve, w[b].proj.s, w[b + 1].proj.s) >= -0.05 * d)
      ++b;
    if (w[b].inward - w[a].inward > best_len) {
      best_len = w[b].inward - w[a].inward;
      best_a = a;
      best_b = b;
    }
    a = b + 1;
  }
  if (best_len <= 0) return std::nullopt;
  double d_a = 0, alpha_a = 0, s_c = 0;
  for (std::size_t k = best_a; k <= best_b; ++k) {
    d_a += w[k].proj.distance;
    alpha_a += angle[k];
    if (k > best_a) s_c += curve_step(curve, w[k - 1].proj.s, w[k].proj.s);
  }
  const double count = static_cast<double>(best_b - best_a + 1);
  d_a /= count;
  alpha_a /= count;
  s_c = std::abs(s_c);
  const double s_s = best_len;
  // Eq. 1: not a merge if any holds.
  if (s_s < 0.25 * d && d_a < 0.1 * d) return std::nullopt;
  if (s_s < 0.75 * d && d_a < 0.2 * d) return std::nullopt;
  if (d_a > 1.1 * d || alpha_a > max_merge_angle) return std::nullopt;
  if (s_s == 0 || s_s < s_c / 2) return std::nullopt;
  // A merge "travels along" the curve (§4.2 definition): it runs on average
  // within 0.3 rad of it (the smoothness bound of the join test, eq. 2) and
  // moves along it by at least cos 0.3 of the way it moves, else it leaves
  // the curve at an angle. The way it moves is the chord of s_s, not its
  // arclength: the pen's wobble lengthens the arclength (3d of a noisy
  // stroke retracing the end of the curve it continues moved 42.1 px along
  // it for 44.3 px of arclength, at α_a = 0.11).
  const double moved = (stroke[w[best_b].index] - stroke[w[best_a].index]).norm();
  if (alpha_a >= max_travel_angle || s_c < std::cos(max_travel_angle) * moved) return std::nullopt;

  EndMatch m;
  m.kind = EndKind::merge;
  m.dir = at_end ? -dir_walk : dir_walk;
  const WalkPoint& near = w[best_a];  // nearest the stroke end
  const WalkPoint& far = w[best_b];
  const double s_near = cum[near.index], s_far = cum[far.index];
  m.stroke_s0 = std::min(s_near, s_far);
  m.stroke_s1 = std::max(s_near, s_far);
  m.curve_at_s0 = at_end ? far.proj.s : near.proj.s;
  m.curve_at_s1 = at_end ? near.proj.s : far.proj.s;
  m.d_a = d_a;
  m.alpha_a = alpha_a;
  m.score = 0.7 * d_a / d + 0.3 * alpha_a / max_merge_angle;  // §4.3
  // Overhang: walking on without back-tracking, the stroke runs off the end.
  if (!curve.closed) {
    const std::vector<WalkPoint> all = walk(stroke, cum, curve, at_end, l, d);
    double last = near.proj.s;
    for (std::size_t k = best_a; k < all.size(); ++k) {
      const auto& p = all[k].proj;
      if (dir_walk * (p.s - last) < -0.5 * d) break;  // back-tracks
      if ((dir_walk > 0 && p.at_end) || (dir_walk < 0 && p.at_start)) {
        m.overhang = p.distance < 1.5 * d || k > best_b;
        break;
      }
      if (p.distance > 1.5 * d) break;  // left the curve sideways
      last = dir_walk > 0 ? std::max(last, p.s) : std::min(last, p.s);
    }
  }
  return m;
}

std::optional<EndMatch> join_test(const Points2& stroke, const std::vector<double>& cum,
                                  const Projected& curve, bool at_end, double d) {
  if (curve.closed || stroke.size() < 2 || curve.pts.size() < 2) return std::nullopt;
  const double l = cum.back(), lc = curve.length();
  const double stride = 0.25 * d;
  std::optional<EndMatch> best;
  double best_score = 0;
  for (double u = 0; u <= std::min(2 * d, l) + 1e-12; u += stride) {
    const double ss = at_end ? l - u : u;
    const Vec2 ps = point_at(stroke, cum, ss);
    Vec2 vs = tangent_at(stroke, cum, ss, 0.5 * d);
    if (!at_end) vs = -vs;  // outward
    for (int ce = 0; ce < 2; ++ce) {
      for (double uc = 0; uc <= std::min(2 * d, lc) + 1e-12; uc += stride) {
        const double sc = ce ? lc - uc : uc;
        const Vec2 pc = point_at(curve.pts, curve.cum, sc);
        Vec2 vc = tangent_at(curve.pts, curve.cum, sc, 0.5 * d);
        if (!ce) vc = -vc;  // outward
        const double dj = (pc - ps).norm();
        if (!(dj > 0) || dj >= 8 * d) continue;  // eq. 2: 0 < d_j < 8d
        const Vec2 v = (pc - ps) / dj;
        const double as = clamp_angle(v.dot(vs)), ac = clamp_angle((-v).dot(vc));
        // α_d: deviation of each angle from their mean (the balance term).
        const double ad = 0.5 * std::abs(ac - as), at = ac + as;
        if (!(ad < 0.2 && at < 0.3)) continue;
        const double score = 0.2 * ad + 0.8 * at;
        // Any join with α_c < π/2 out-scores one with α_c > π/2 (§4.2).
        bool better = true;
        if (best && (ac < pi / 2) != (best->alpha_c < pi / 2)) better = ac < pi / 2;
        else if (best) better = score < best_score;
        if (!better) continue;
        EndMatch m;
        m.kind = EndKind::join;
        m.stroke_s = ss;
        m.curve_s = sc;
        m.at_curve_start = ce == 0;
        m.d_j = dj;
        m.alpha_d = ad;
        m.alpha_t = at;
        m.alpha_c = ac;
        // Walking the stroke forward: from a curve end onwards (+1 at the
        // curve's end, -1 at its start), or into the curve at its end.
        m.dir = at_end ? (ce ? -1 : 1) : (ce ? 1 : -1);
        m.score = join_score(ad, at, dj, d);
        best = m;
        best_score = score;
      }
    }
  }
  return best;
}

EndMatch classify_end(const Points2& stroke, const std::vector<double>& cum,
                      const Projected& curve, bool at_end, double d) {
  if (auto m = merge_test(stroke, cum, curve, at_end, d)) return *m;
  if (auto j = join_test(stroke, cum, curve, at_end, d)) return *j;
  return {};
}

const char* to_string(MatchType t) {
  switch (t) {
    case MatchType::oversketch: return "oversketch";
    case MatchType::extend: return "extend";
    case MatchType::partial_oversketch: return "partial_oversketch";
    case MatchType::extend_close: return "extend_close";
  }
  return "?";
}

std::optional<CurveMatch> match_type(const EndMatch& start, const EndMatch& end,
                                     const Projected& curve, double /*d*/) {
  const bool hs = start.kind != EndKind::none, he = end.kind != EndKind::none;
  if (!hs && !he) return std::nullopt;
  CurveMatch m;
  m.start = start;
  m.end = end;
  if (hs && he) {
    // Topology: oriented by the start, the other end must run the same way.
    if (start.dir != end.dir) return std::nullopt;
    m.q_m = 0.5 * (start.score + end.score);
    const int dir = start.dir;
    if (start.kind == EndKind::merge && end.kind == EndKind::merge) {
      if (curve.closed) {
        m.type = MatchType::oversketch;
        return m;
      }
      const bool ordered =
          dir > 0 ? start.curve_at_s0 < end.curve_at_s1 : start.curve_at_s0 > end.curve_at_s1;
      if (ordered && !start.overhang && !end.overhang) {
        m.type = MatchType::oversketch;
        return m;
      }
      if (!ordered && start.overhang && end.overhang) {
        m.type = MatchType::extend_close;
        return m;
      }
      return std::nullopt;
    }
    const bool sa = start.kind == EndKind::join || start.overhang;
    const bool ea = end.kind == EndKind::join || end.overhang;
    if (!curve.closed && sa && ea) {
      m.type = MatchType::extend_close;
      return m;
    }
    return std::nullopt;
  }
  const EndMatch& e = hs ? start : end;
  m.q_m = e.score;
  if (e.kind == EndKind::join || e.overhang) {
    m.type = MatchType::extend;
    return m;
  }
  if (curve.closed) return std::nullopt;
  m.type = MatchType::partial_oversketch;
  return m;
}

std::optional<CurveMatch> analyze(const Points2& stroke, const Projected& curve, double d) {
  if (stroke.size() < 2 || curve.pts.size() < 2) return std::nullopt;
  const auto cum = cumulative(stroke);
  const EndMatch s = classify_end(stroke, cum, curve, false, d);
  const EndMatch e = classify_end(stroke, cum, curve, true, d);
  return match_type(s, e, curve, d);
}

std::optional<EndMatch> closes_on_itself(const Points2& stroke, double d) {
  if (stroke.size() < 4) return std::nullopt;
  const auto cum = cumulative(stroke);
  const double l = cum.back();
  if (!(l > 4 * d)) return std::nullopt;
  // "Check if each end of the stroke merges or joins with the other end"
  // (§4.3 (1)): the end against the first third, the start against the last
  // third, each running on along it; q_m averages the two (§4.3, final score).
  const auto meets = [&](double from, double to, bool at_end) -> std::optional<EndMatch> {
    const Projected part = make_projected(slice(stroke, cum, from, to), false);
    if (auto m = merge_test(stroke, cum, part, at_end, d); m && m->dir > 0) return m;
    if (auto j = join_test(stroke, cum, part, at_end, d); j && j->at_curve_start == at_end) return j;
    return std::nullopt;
  };
  std::optional<EndMatch> end = meets(0.0, l / 3, true);
  if (!end) return std::nullopt;
  const std::optional<EndMatch> start = meets(2 * l / 3, l, false);
  if (!start) return std::nullopt;
  end->score = 0.5 * (end->score + start->score);
  return end;
}

}  // namespace sketchlab::justdrawit
