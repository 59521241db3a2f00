#include "construction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "relations.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/bounding_box.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/geometry/split.hpp"

namespace sketchlab::synthetic {
namespace {

struct Circle {
  Vec3 c, u, v;
  double r = 0.0;
  std::size_t curve = 0;
  Vec3 normal() const { return u.cross(v); }
  // Corner k of the circumscribed square: between joints k and k + 1.
  Vec3 corner(int k) const {
    const std::array<Vec3, 4> d{u, v, -u, -v};
    return c + r * (d[static_cast<std::size_t>(k % 4)] + d[static_cast<std::size_t>((k + 1) % 4)]);
  }
};

// A make_circle circle: closed, four cubic segments whose joints are the ends
// of two perpendicular equal radii (t = 0: c + r u, t = 1: c + r v, ...).
std::optional<Circle> as_circle(const Curve& curve, std::size_t index, double tol) {
  if (!curve.closed || curve.segment_count() != 4) return std::nullopt;
  std::array<Vec3, 4> j;
  for (int k = 0; k < 4; ++k) j[static_cast<std::size_t>(k)] = evaluate(curve, k);
  const Vec3 c = 0.25 * (j[0] + j[1] + j[2] + j[3]);
  const double r = (j[0] - c).norm();
  if (!(r > tol)) return std::nullopt;
  Circle out{c, (j[0] - c) / r, (j[1] - c) / r, r, index};
  if (std::abs((j[1] - c).norm() - r) > tol || (j[2] - (c - r * out.u)).norm() > tol ||
      (j[3] - (c - r * out.v)).norm() > tol || std::abs(out.u.dot(out.v)) > 1e-9)
    return std::nullopt;
  return out;
}

// Index of the coordinate axis d runs along, or -1.
int axis_of(const Vec3& d) {
  const double n = d.norm();
  if (!(n > 0.0)) return -1;
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(d[k]) / n - 1.0) <= 1e-12) return k;
  return -1;
}

bool is_line(const Curve& c) { return c.kind == CurveKind::line; }
Vec3 start(const Curve& c) { return c.control_points.front(); }
Vec3 end(const Curve& c) { return c.control_points.back(); }

class ScaffoldBuilder {
 public:
  ScaffoldBuilder(GroundTruthNetwork& net, double tol) : net_(net), tol_(tol) {}
  void line(const Vec3& a, const Vec3& b) {
    if ((a - b).norm() <= tol_) return;
    for (const auto& gc : net_.curves) {
      if (!is_line(gc.curve)) continue;
      const Vec3 p = start(gc.curve), q = end(gc.curve);
      if (((p - a).norm() <= tol_ && (q - b).norm() <= tol_) || ((p - b).norm() <= tol_ && (q - a).norm() <= tol_))
        return;
    }
    net_.curves.push_back({make_line(a, b), Layer::scaffold});
  }

 private:
  GroundTruthNetwork& net_;
  double tol_;
};

// Joints of a curve (the ends of each segment; closed curves once each).
std::vector<Vec3> joints(const Curve& c) {
  std::vector<Vec3> out;
  const int n = c.segment_count() + (c.closed ? 0 : 1);
  for (int k = 0; k < n; ++k) out.push_back(evaluate(c, k));
  return out;
}

}  // namespace

GroundTruthNetwork with_construction_scaffold(const GroundTruthNetwork& net) {
  const double tol = 1e-9 * network_scale(net);
  GroundTruthNetwork out = net;
  ScaffoldBuilder add(out, tol);

  std::vector<Circle> circles;
  for (std::size_t i = 0; i < net.curves.size(); ++i)
    if (auto c = as_circle(net.curves[i].curve, i, tol)) circles.push_back(*c);
  for (const Circle& c : circles) {
    for (int k = 0; k < 4; ++k) add.line(c.corner(k), c.corner(k + 1));
    add.line(c.corner(0), c.corner(2));
    add.line(c.corner(1), c.corner(3));
    add.line(c.c + c.r * c.u, c.c - c.r * c.u);
    add.line(c.c + c.r * c.v, c.c - c.r * c.v);
  }
  for (std::size_t a = 0; a < circles.size(); ++a)
    for (std::size_t b = a + 1; b < circles.size(); ++b) {
      const Circle &p = circles[a], &q = circles[b];
      const Vec3 n = p.normal();
      if (n.cross(q.normal()).norm() > 1e-9 || (p.u - q.u).norm() > 1e-9 ||
          n.cross(q.c - p.c).norm() > tol)
        continue;
      for (int k = 0; k < 4; ++k) add.line(p.corner(k), q.corner(k));
    }

  auto on_circle = [&](const Vec3& x) {
    return std::any_of(circles.begin(), circles.end(), [&](const Circle& c) {
      return closest_point(net.curves[c.curve].curve, x).distance <= tol;
    });
  };
  for (const auto& gc : net.curves) {
    const Curve& l = gc.curve;
    if (!is_line(l) || axis_of(end(l) - start(l)) >= 0 || (on_circle(start(l)) && on_circle(end(l))))
      continue;
    // The edges of its bounding box from start to end: horizontal, then up.
    Vec3 at = start(l);
    for (int k : {0, 2, 1}) {
      Vec3 next = at;
      next[k] = end(l)[k];
      add.line(at, next);
      at = next;
    }
  }

  double floor = std::numeric_limits<double>::infinity();
  for (const auto& gc : out.curves)
    for (const Vec3& p : gc.curve.control_points) floor = std::min(floor, p.y());
  const bool ground_line = std::any_of(out.curves.begin(), out.curves.end(), [&](const GroundTruthCurve& gc) {
    return is_line(gc.curve) && axis_of(end(gc.curve) - start(gc.curve)) >= 0 &&
           std::abs(start(gc.curve).y() - floor) <= tol &&
           std::abs(end(gc.curve).y() - floor) <= tol;
  });
  if (!ground_line) {
    Box3 feet;
    for (const auto& gc : net.curves)
      if (!gc.curve.closed)
        for (const Vec3& p : {start(gc.curve), end(gc.curve)})
          if (std::abs(p.y() - floor) <= tol) feet.extend(p);
    if (!feet.isEmpty() && feet.sizes().x() > tol && feet.sizes().z() > tol) {
      const Vec3 lo = feet.min(), hi = feet.max();
      const std::array<Vec3, 4> q{Vec3(lo.x(), floor, hi.z()), Vec3(hi.x(), floor, hi.z()),
                                  Vec3(hi.x(), floor, lo.z()), Vec3(lo.x(), floor, lo.z())};
      for (std::size_t k = 0; k < 4; ++k) add.line(q[k], q[(k + 1) % 4]);
    }
  }
  for (std::size_t i = 0; i < out.curves.size(); ++i) {
    const Curve c = out.curves[i].curve;
    if (!c.closed || c.segment_count() < 2) continue;
    const double half = static_cast<double>(c.segment_count() / 2);
    out.curves[i].curve = sub_curve(c, 0.0, half);
    out.curves.insert(out.curves.begin() + static_cast<std::ptrdiff_t>(i + 1),
                      {sub_curve(c, half, c.t_max()), out.curves[i].layer});
    ++i;
  }
  return out;
}

GroundTruthNetwork plan_analytic_drawing(const GroundTruthNetwork& net) {
  const double tol = 1e-9 * network_scale(net);
  const std::size_t n = net.curves.size();
  GroundTruthNetwork out{net.name, {}};
  if (n == 0) return out;
  std::vector<double> length(n);
  for (std::size_t i = 0; i < n; ++i) length[i] = arclength(net.curves[i].curve);
  std::vector<bool> drawn(n, false);

  auto on_drawing = [&](const Vec3& p) {
    return std::any_of(out.curves.begin(), out.curves.end(), [&](const GroundTruthCurve& d) {
      return closest_point(d.curve, p).distance <= tol;
    });
  };
  auto take = [&](std::size_t i) {
    drawn[i] = true;
    GroundTruthCurve c = net.curves[i];
    if (!c.curve.closed && !on_drawing(start(c.curve)) && on_drawing(end(c.curve))) c.curve = reversed(c.curve);
    out.curves.push_back(std::move(c));
  };

  // Fig. 3a: the first stroke lies in the ground plane.
  double floor = std::numeric_limits<double>::infinity();
  for (const auto& gc : net.curves)
    for (const Vec3& p : gc.curve.control_points) floor = std::min(floor, p.y());
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < n; ++i) {
    const Curve& c = net.curves[i].curve;
    // An axis-aligned edge: it defines the primary vanishing directions.
    if (net.curves[i].layer == Layer::scaffold && is_line(c) && axis_of(end(c) - start(c)) >= 0 &&
        std::abs(start(c).y() - floor) <= tol &&
        std::abs(end(c).y() - floor) <= tol && (!first || length[i] > length[*first]))
      first = i;
  }
  if (first) take(*first);

  for (Layer group : {Layer::scaffold, Layer::shape}) {
    while (true) {
      std::optional<std::size_t> best;
      int best_ends = -1;
      for (std::size_t i = 0; i < n; ++i) {
        if (drawn[i] || (net.curves[i].layer == Layer::scaffold) != (group == Layer::scaffold)) continue;
        const Curve& c = net.curves[i].curve;
        int ends = 0;
        if (c.closed) {
          for (const Vec3& j : joints(c)) ends += on_drawing(j);
          ends = std::min(ends, 2);
        } else {
          ends = on_drawing(start(c)) + on_drawing(end(c));
        }
        if (!best || ends > best_ends || (ends == best_ends && length[i] > length[*best])) {
          best = i;
          best_ends = ends;
        }
      }
      if (!best) break;
      take(*best);
    }
  }
  return out;
}

std::vector<PlannedStroke> with_guidelines(const GroundTruthNetwork& plan, const View& camera) {
  const double tol = 1e-9 * network_scale(plan);
  const Vec3 eye = eye_position(camera);
  // OpenGL eye space looks along -z: the optical axis is minus the third row.
  const Vec3 forward = -camera.view.block<1, 3>(2, 0).transpose().normalized();
  std::vector<PlannedStroke> out;
  // Lines drawn so far: ends, unit direction, whether it is a guideline.
  struct DrawnLine {
    Vec3 a, b, d;
    bool guide;
  };
  std::vector<DrawnLine> drawn_lines;
  auto on_line = [&](const DrawnLine& l, const Vec3& x) { return (x - l.a).cross(l.d).norm() <= tol; };
  auto covered = [&](const Vec3& p, const Vec3& d) {
    return std::any_of(drawn_lines.begin(), drawn_lines.end(),
                       [&](const DrawnLine& l) { return l.d.cross(d).norm() <= 1e-9 && on_line(l, p); });
  };
  // A guideline from `from` along ±d (the sense toward the vanishing point).
  auto guideline = [&](const Vec3& from, Vec3 d, double length) {
    drawn_lines.push_back({from, from + length * d, d, true});
    if (d.dot(forward) < 0) d = -d;
    out.push_back({make_line(from, from + 1.25 * length * d), Layer::guide, std::nullopt});
  };
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    if (!is_line(gc.curve) && !gc.curve.closed) {
      for (const Vec3& x : {start(gc.curve), end(gc.curve)}) {
        const auto line = std::find_if(drawn_lines.begin(), drawn_lines.end(), [&](const DrawnLine& l) {
          return !l.guide && on_line(l, x) && (x - l.a).norm() > tol && (x - l.b).norm() > tol &&
                 (x - l.a).dot(x - l.b) < 0;
        });
        if (line == drawn_lines.end()) continue;
        // The guideline along that line from its end nearer the eye, so that
        // it runs toward the vanishing point across x; then the tick.
        const DrawnLine l = *line;
        const Vec3 from = (l.a - eye).dot(forward) <= (l.b - eye).dot(forward) ? l.a : l.b;
        guideline(from, (from == l.a ? l.b - l.a : l.a - l.b).normalized(), (l.b - l.a).norm());
        const Vec3 across = l.d.cross(x - eye).normalized();
        const double half = 12.0 * 2.0 * (x - eye).dot(forward) / (camera.projection(1, 1) * camera.viewport[3]);
        out.push_back({make_line(x - half * across, x + half * across), Layer::scaffold, std::nullopt});
      }
    }
    out.push_back({gc.curve, gc.layer, i});
    if (!is_line(gc.curve)) continue;
    const Vec3 a = start(gc.curve), b = end(gc.curve);
    drawn_lines.push_back({a, b, (b - a).normalized(), false});
    for (const Vec3& vertex : {a, b}) {
      for (std::size_t j = i + 1; j < plan.curves.size(); ++j) {
        const Curve& next = plan.curves[j].curve;
        if (!is_line(next)) continue;
        Vec3 far;
        if ((start(next) - vertex).norm() <= tol) far = end(next);
        else if ((end(next) - vertex).norm() <= tol) far = start(next);
        else continue;
        const Vec3 d = (far - vertex).normalized();
        if (axis_of(d) >= 0 && !covered(vertex, d)) guideline(vertex, d, (far - vertex).norm());
      }
    }
  }
  return out;
}

}  // namespace sketchlab::synthetic
