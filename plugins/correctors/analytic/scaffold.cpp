#include "scaffold.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab::analytic {

namespace {

void add_vanishing(Scaffold& s, const Vec3& d) {
  if (!(d.norm() > 0.5)) return;
  for (const Vec3& e : s.vanishing)
    if (std::abs(e.dot(d)) > s.vanishing_merge_cos) return;
  s.vanishing.push_back(d);
}

int vertex_at(Scaffold& s, const Vec3& p) {
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    if ((s.vertices[i].p - p).norm() <= s.tolerance) return static_cast<int>(i);
  s.vertices.push_back({p, {}});
  return static_cast<int>(s.vertices.size()) - 1;
}

void link_vertex(Scaffold& s, int v, int line) {
  auto& l = s.vertices[static_cast<std::size_t>(v)].lines;
  if (std::find(l.begin(), l.end(), line) == l.end()) l.push_back(line);
}

void add_curve(Scaffold& s, const NetworkCurve& nc, const Vec3& up) {
  const Curve& c = nc.curve;
  if (c.segment_count() < 1) return;
  const Vec3 a = c.control_points.front(), b = c.control_points.back();
  if (c.kind == CurveKind::line) {
    if (!((b - a).norm() > s.tolerance)) return;
    const bool guide = nc.layer == Layer::guide;
    const int idx = static_cast<int>(s.lines.size());
    s.lines.push_back({nc.id, a, b, guide});
    const Vec3 d = (b - a).normalized();
    if (!guide) {
      const double len = (b - a).norm();
      s.length_sum += len;
      bool found = false;
      for (auto& [l, n] : s.length_classes)
        if (std::abs(l - len) <= 1e-9 * std::max(1.0, len)) {
          ++n;
          found = true;
          break;
        }
      if (!found) s.length_classes.push_back({len, 1});
      found = false;
      for (auto& [e, n] : s.direction_classes)
        if (std::abs(e.dot(d)) >= 1.0 - 1e-12) {
          ++n;
          found = true;
          break;
        }
      if (!found) s.direction_classes.push_back({d, 1});
    }
    if (!guide && s.segment_count() == 1) {
      add_vanishing(s, d);
      add_vanishing(s, up.cross(d).normalized());
    }
    add_vanishing(s, d);
    if (!guide) {
      link_vertex(s, vertex_at(s, a), idx);
      link_vertex(s, vertex_at(s, b), idx);
    } else {
      link_vertex(s, vertex_at(s, a), idx);
    }
    // Existing vertices lying on the new line, and the new line's ends lying
    // on existing lines, get the incidence (perpendicular and tangent options).
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
      const Vec3& p = s.vertices[v].p;
      const double t = (p - a).dot(d);
      const double len = (b - a).norm();
      if ((a + t * d - p).norm() <= s.tolerance && (guide || (t >= -s.tolerance && t <= len + s.tolerance)))
        link_vertex(s, static_cast<int>(v), idx);
    }
    std::vector<int> ends{vertex_at(s, a)};
    if (!guide) ends.push_back(vertex_at(s, b));
    for (int v : ends) {
      const Vec3 p = s.vertices[static_cast<std::size_t>(v)].p;
      for (std::size_t li = 0; li < s.lines.size(); ++li) {
        const ScaffoldLine& l = s.lines[li];
        const Vec3 e = l.direction();
        const double t = (p - l.a).dot(e);
        if ((l.a + t * e - p).norm() <= s.tolerance &&
            (l.guide || (t >= -s.tolerance && t <= (l.b - l.a).norm() + s.tolerance)))
          link_vertex(s, v, static_cast<int>(li));
      }
    }
  } else {
    s.curves.push_back({nc.id, c});
    vertex_at(s, a);
    vertex_at(s, b);
  }
  for (const Keypoint& k : nc.keypoints)
    if (k.kind == Keypoint::Kind::tick) vertex_at(s, k.position);
}

}  // namespace

int Scaffold::segment_count() const {
  return static_cast<int>(std::count_if(lines.begin(), lines.end(),
                                        [](const ScaffoldLine& l) { return !l.guide; }));
}

Scaffold build_scaffold(const Network& network, const Vec3& up, double vanishing_merge) {
  Scaffold s;
  s.vanishing_merge_cos = std::cos(vanishing_merge);
  Box3 box;
  for (const auto& [id, nc] : network.curves())
    if (nc.layer != Layer::guide)
      for (const Vec3& p : nc.curve.control_points) box.extend(p);
  s.extent = box.isEmpty() ? 1.0 : std::max(1e-3, box.diagonal().norm());
  s.tolerance = 1e-7 * s.extent;
  add_vanishing(s, up.normalized());
  for (const auto& [id, nc] : network.curves()) add_curve(s, nc, up.normalized());
  return s;
}

void add_to_scaffold(Scaffold& scaffold, const NetworkCurve& curve, const Vec3& up) {
  add_curve(scaffold, curve, up.normalized());
}

LineLineHit closest_line_line(const Vec3& p, const Vec3& u, const Vec3& q, const Vec3& v) {
  LineLineHit h;
  const Vec3 w = p - q;
  const double b = u.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = 1.0 - b * b;
  if (den < 1e-12) {
    h.parallel = true;
    h.s = 0;
    h.t = e;
  } else {
    h.s = (b * e - d) / den;
    h.t = (e - b * d) / den;
  }
  h.distance = (p + h.s * u - q - h.t * v).norm();
  return h;
}

bool within_line(const ScaffoldLine& l, double t, double tol) {
  return l.guide || (t >= -tol && t <= (l.b - l.a).norm() + tol);
}

bool lies_on_line(const ScaffoldLine& l, const Vec3& a, const Vec3& b, double tol) {
  const Vec3 u = l.direction();
  const auto off = [&](const Vec3& x) { return (x - l.a - (x - l.a).dot(u) * u).norm(); };
  return off(a) <= tol && off(b) <= tol;
}

std::optional<Vec3> scaffold_crossing(const Scaffold& s, const ScaffoldLine& a, const ScaffoldLine& b) {
  const LineLineHit h = closest_line_line(a.a, a.direction(), b.a, b.direction());
  if (h.parallel || h.distance > s.tolerance) return std::nullopt;
  if (!within_line(a, h.s, s.tolerance) || !within_line(b, h.t, s.tolerance)) return std::nullopt;
  return Vec3(a.a + h.s * a.direction());
}

}  // namespace sketchlab::analytic
