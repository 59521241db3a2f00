#include "scratch.hpp"

#include <algorithm>

#include "short_straw.hpp"

namespace sketchlab::justdrawit {

namespace {

// True when `next` starts by running back over `prev` (§4.1: a fold-over is
// within d of another part of the stroke; it may extend past it).
bool lies_on(const Points2& next, const Points2& prev, double d) {
  const auto cp = cumulative(prev);
  const auto cn = cumulative(next);
  const double check = 0.5 * std::min(cn.back(), cp.back());
  if (!(check > 0)) return false;
  int reversed_votes = 0, votes = 0;
  for (std::size_t i = 0; i < next.size() && cn[i] <= check; ++i) {
    const auto pr = project(prev, cp, next[i]);
    if (pr.distance > d) return false;
    const Vec2 tn = tangent_at(next, cn, cn[i], 0.5 * d);
    const Vec2 tp = tangent_at(prev, cp, pr.s, 0.5 * d);
    ++votes;
    if (tn.dot(tp) < 0) ++reversed_votes;
  }
  return votes > 0 && 2 * reversed_votes > votes;
}

// Hermite curve from p0 (tangent m0) to p1 (tangent m1), `count` samples
// after p0.
Points2 hermite(const Vec2& p0, const Vec2& m0, const Vec2& p1, const Vec2& m1, int count) {
  Points2 out;
  for (int i = 1; i <= count; ++i) {
    const double t = static_cast<double>(i) / count, t2 = t * t, t3 = t2 * t;
    out.push_back((2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
                  (t3 - t2) * m1);
  }
  return out;
}

struct Section {
  Points2 pts;
  std::size_t ext_front = 0, ext_back = 0;  // extension points at either end
};

double move_amount(double f) {
  // §4.1: middle 50 % by arclength moves 0.25, the ends 0.75, linear between.
  const double e = std::min(f, 1.0 - f);
  return e >= 0.25 ? 0.25 : 0.75 - 0.5 * (e / 0.25);
}

}  // namespace

std::vector<Points2> fold_over_sections(const Points2& stroke, double d) {
  const Corners c = short_straw(stroke);
  std::vector<Points2> sections;
  for (std::size_t k = 1; k < c.index.size(); ++k) {
    Points2 piece(c.points.begin() + static_cast<std::ptrdiff_t>(c.index[k - 1]),
                  c.points.begin() + static_cast<std::ptrdiff_t>(c.index[k]) + 1);
    if (piece.size() < 2) continue;
    if (!sections.empty() && !lies_on(piece, sections.back(), d)) {
      sections.back().insert(sections.back().end(), piece.begin() + 1, piece.end());
      continue;
    }
    sections.push_back(std::move(piece));
  }
  if (sections.empty()) sections.push_back(stroke);
  return sections;
}

std::optional<Average> average_projection(const std::vector<Points2>& sections, const Vec2& p,
                                          double d, std::size_t exclude) {
  Vec2 sum = Vec2::Zero(), tsum = Vec2::Zero();
  double wsum = 0;
  for (std::size_t j = 0; j < sections.size(); ++j) {
    if (j == exclude || sections[j].size() < 2) continue;
    const auto cum = cumulative(sections[j]);
    const auto pr = project(sections[j], cum, p);
    if (pr.at_start || pr.at_end) continue;
    // Weighted by distance to p (§4.1); 0.1 d keeps a hit at distance 0 finite.
    const double w = 1.0 / (pr.distance + 0.1 * d);
    sum += w * pr.point;
    tsum += w * tangent_at(sections[j], cum, pr.s, 0.5 * d);
    wsum += w;
  }
  if (wsum <= 0) return std::nullopt;
  Average a{sum / wsum, tsum.norm() > 0 ? Vec2(tsum.normalized()) : Vec2::Zero()};
  return a;
}

Points2 blend_sections(std::vector<Points2> input, double d) {
  std::erase_if(input, [](const Points2& s) { return s.size() < 2; });
  if (input.empty()) return {};
  if (input.size() == 1) return input[0];
  // Orient every section like the first.
  const Vec2 dir0 = input[0].back() - input[0].front();
  for (auto& s : input)
    if ((s.back() - s.front()).dot(dir0) < 0) std::reverse(s.begin(), s.end());

  std::vector<Section> sec;
  for (auto& s : input) sec.push_back({std::move(s)});
  std::vector<Points2> plain(sec.size());
  for (std::size_t j = 0; j < sec.size(); ++j) plain[j] = sec[j].pts;

  // Extension by Hermite curves (§4.1): to the averaging of a point d along
  // the end tangent, or that point itself past the end of the average curve.
  for (std::size_t j = 0; j < sec.size(); ++j) {
    const Points2& p = plain[j];
    const auto cum = cumulative(p);
    for (int end = 0; end < 2; ++end) {
      const Vec2 p0 = end ? p.back() : p.front();
      Vec2 t0 = tangent_at(p, cum, end ? cum.back() : 0.0, 0.5 * d);
      if (!end) t0 = -t0;  // outward
      if (t0.norm() == 0) continue;
      const Vec2 q = p0 + d * t0;
      Vec2 p1 = q, t1 = t0;
      if (auto a = average_projection(plain, q, d, j)) {
        p1 = a->point;
        t1 = a->tangent.dot(t0) < 0 ? Vec2(-a->tangent) : a->tangent;
        if (t1.norm() == 0) t1 = t0;
      }
      Points2 ext = hermite(p0, d * t0, p1, d * t1, 6);
      if (end) {
        sec[j].pts.insert(sec[j].pts.end(), ext.begin(), ext.end());
        sec[j].ext_back = ext.size();
      } else {
        std::reverse(ext.begin(), ext.end());
        sec[j].pts.insert(sec[j].pts.begin(), ext.begin(), ext.end());
        sec[j].ext_front = ext.size();
      }
    }
  }

  // Three passes of the projection operator (§4.1).
  for (int pass = 0; pass < 3; ++pass) {
    for (auto& s : sec) smooth(s.pts, 1);
    std::vector<Points2> old(sec.size());
    for (std::size_t j = 0; j < sec.size(); ++j) old[j] = sec[j].pts;
    for (std::size_t j = 0; j < sec.size(); ++j) {
      const auto cum = cumulative(old[j]);
      for (std::size_t i = 0; i < old[j].size(); ++i) {
        const auto a = average_projection(old, old[j][i], d, j);
        if (!a) continue;
        const double f = cum.back() > 0 ? cum[i] / cum.back() : 0.5;
        sec[j].pts[i] = old[j][i] + move_amount(f) * (a->point - old[j][i]);
      }
    }
  }

  // Topological sort along the longest section, then down-sampling.
  std::size_t ref = 0;
  for (std::size_t j = 1; j < sec.size(); ++j)
    if (length(sec[j].pts) > length(sec[ref].pts)) ref = j;
  const Points2& r = sec[ref].pts;
  const auto rc = cumulative(r);
  std::vector<std::pair<double, Vec2>> keyed;
  for (const auto& s : sec)
    for (std::size_t i = s.ext_front; i + s.ext_back < s.pts.size(); ++i) {
      const auto pr = project(r, rc, s.pts[i]);
      double key = pr.s;
      if (pr.at_start) key -= (s.pts[i] - r.front()).norm();
      if (pr.at_end) key += (s.pts[i] - r.back()).norm();
      keyed.emplace_back(key, s.pts[i]);
    }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Points2 out;
  const double bin = 0.1 * d;
  for (std::size_t i = 0; i < keyed.size();) {
    Vec2 sum = Vec2::Zero();
    std::size_t k = i;
    for (; k < keyed.size() && keyed[k].first < keyed[i].first + bin; ++k) sum += keyed[k].second;
    out.push_back(sum / static_cast<double>(k - i));
    i = k;
  }
  out = dedupe(out, 1e-9);
  smooth(out, 1);
  return out;
}

Points2 unfold_stroke(const Points2& stroke, double d) {
  if (stroke.size() < 8) return stroke;
  auto sections = fold_over_sections(stroke, d);
  if (sections.size() < 2) return stroke;
  return blend_sections(std::move(sections), d);
}

double overlap_fraction(const Points2& a, const Points2& b, double d) {
  if (a.size() < 2 || b.size() < 2) return 0.0;
  const auto ca = cumulative(a), cb = cumulative(b);
  if (!(ca.back() > 0)) return 0.0;
  double inside = 0;
  bool prev_in = project(b, cb, a[0]).distance <= d;
  for (std::size_t i = 1; i < a.size(); ++i) {
    const bool in = project(b, cb, a[i]).distance <= d;
    if (in && prev_in) inside += ca[i] - ca[i - 1];
    else if (in || prev_in) inside += 0.5 * (ca[i] - ca[i - 1]);
    prev_in = in;
  }
  return inside / ca.back();
}

}  // namespace sketchlab::justdrawit
