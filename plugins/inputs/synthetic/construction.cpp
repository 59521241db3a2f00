#include "construction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

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

// Points a construction step can name: the ends of the network's curves and
// the crossings of its lines (a circle's centre, where its cross meets).
std::vector<Vec3> points_of_interest(const GroundTruthNetwork& net, double tol) {
  std::vector<Vec3> out;
  auto add = [&](const Vec3& p) {
    if (std::none_of(out.begin(), out.end(), [&](const Vec3& q) { return (q - p).norm() <= tol; }))
      out.push_back(p);
  };
  for (const auto& gc : net.curves)
    for (const Vec3& p : {start(gc.curve), end(gc.curve)}) add(p);
  for (std::size_t i = 0; i < net.curves.size(); ++i)
    for (std::size_t j = i + 1; j < net.curves.size(); ++j) {
      const Curve &a = net.curves[i].curve, &b = net.curves[j].curve;
      if (!is_line(a) || !is_line(b)) continue;
      const Vec3 u = end(a) - start(a), v = end(b) - start(b), w = start(b) - start(a);
      const Vec3 n = u.cross(v);
      if (!(n.squaredNorm() > 1e-18 * u.squaredNorm() * v.squaredNorm()) || std::abs(w.dot(n)) > tol * n.norm())
        continue;
      const double s = w.cross(v).dot(n) / n.squaredNorm(), t = w.cross(u).dot(n) / n.squaredNorm();
      if (s > -1e-12 && s < 1 + 1e-12 && t > -1e-12 && t < 1 + 1e-12) add(start(a) + s * u);
    }
  return out;
}

// The shortest chain of axis-aligned steps between points of interest from a
// point `known` accepts to `target` (breadth-first): {a, ..., target}, a
// known; {target} when it is known itself; empty when none reaches it.
template <class Known>
std::vector<Vec3> axis_chain(const std::vector<Vec3>& pois, const Known& known, const Vec3& target) {
  if (known(target)) return {target};
  std::vector<Vec3> nodes{target};
  for (const Vec3& p : pois)
    if ((p - target).norm() > 0) nodes.push_back(p);
  std::vector<int> from(nodes.size(), -1);
  std::vector<std::size_t> queue{0};
  from[0] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t at = queue[head];
    for (std::size_t next = 0; next < nodes.size(); ++next) {
      if (from[next] >= 0 || axis_of(nodes[next] - nodes[at]) < 0) continue;
      from[next] = static_cast<int>(at);
      if (known(nodes[next])) {
        std::vector<Vec3> chain;
        for (std::size_t k = next; k != 0; k = static_cast<std::size_t>(from[k])) chain.push_back(nodes[k]);
        chain.push_back(target);
        return chain;
      }
      queue.push_back(next);
    }
  }
  return {};
}

// Detail zoom (a choice; the paper gives no figures): a curve whose
// projection spans less than 1.5 in (three times eq. 3's widest uncertainty
// radius δ_max) is drawn zoomed in 4 times.
constexpr double zoom_below = 1.5;  // inches on screen
constexpr double zoom_factor = 4.0;

// The view magnified k times about the pixel `at` (moved to the viewport's
// centre): the image-space zoom of §2's interface. The eye stays, so the
// 3D scene a stroke means is the same; only the pen's pixels shrink in it.
View zoomed_view(const View& v, double k, const Vec2& at) {
  View out = v;
  const Vec4& vp = v.viewport;
  const double ax = 2.0 * (at.x() - vp[0]) / vp[2] - 1.0, ay = 2.0 * (at.y() - vp[1]) / vp[3] - 1.0;
  out.projection.row(0) = k * (v.projection.row(0) - ax * v.projection.row(3));
  out.projection.row(1) = k * (v.projection.row(1) - ay * v.projection.row(3));
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

  const std::vector<Vec3> pois = points_of_interest(net, tol);
  // A construction line touching a curve (not a line) of the model: a
  // square's side tangent at a circle's joint, a cross line ending there.
  // The circle is inscribed in its square through the ends of its cross, so
  // the curve waits for them (the paper's figures: the scaffold first, the
  // curves sketched over it, Fig. 1a-b, Fig. 9d-e).
  auto touches = [&](const Curve& line, const Curve& c) {
    const std::vector<Vec3> js = joints(c);
    return closest_point(c, start(line)).distance <= tol || closest_point(c, end(line)).distance <= tol ||
           std::any_of(js.begin(), js.end(), [&](const Vec3& j) { return closest_point(line, j).distance <= tol; });
  };
  std::vector<std::vector<std::size_t>> construction_of(n);
  for (std::size_t i = 0; i < n; ++i)
    if (net.curves[i].layer != Layer::scaffold && !is_line(net.curves[i].curve))
      for (std::size_t j = 0; j < n; ++j)
        if (net.curves[j].layer == Layer::scaffold && is_line(net.curves[j].curve) &&
            touches(net.curves[j].curve, net.curves[i].curve))
          construction_of[i].push_back(j);
  // Order of preference: its construction drawn; on what is drawn;
  // construction (scaffold) before the model's curves; more ends on it;
  // fewer dimension ticks to reach its start (with_guidelines places them);
  // longer.
  auto rank = [&](std::size_t i) {
    const Curve& c = net.curves[i].curve;
    const bool waits = std::any_of(construction_of[i].begin(), construction_of[i].end(),
                                   [&](std::size_t j) { return !drawn[j]; });
    int ends = 0;
    if (c.closed) {
      for (const Vec3& j : joints(c)) ends += on_drawing(j);
      ends = std::min(ends, 2);
    } else {
      ends = on_drawing(start(c)) + on_drawing(end(c));
    }
    // A line along no axis has no guideline to trace: it joins two points
    // already there.
    if (is_line(c) && axis_of(end(c) - start(c)) < 0 && ends < 2) ends = -1;
    const std::size_t steps = ends == 0 ? axis_chain(pois, on_drawing, start(c)).size() - 1 : 0;
    return std::make_tuple(waits ? 2 : ends > 0 ? 0 : 1, net.curves[i].layer == Layer::scaffold ? 0 : 1, -ends,
                           steps, -length[i]);
  };
  while (true) {
    std::optional<std::size_t> best;
    decltype(rank(0)) best_rank;
    for (std::size_t i = 0; i < n; ++i) {
      if (drawn[i]) continue;
      const auto r = rank(i);
      if (!best || r < best_rank) {
        best = i;
        best_rank = r;
      }
    }
    if (!best) break;
    take(*best);
  }
  return out;
}

std::vector<PlannedStroke> with_guidelines(const GroundTruthNetwork& plan, const View& camera) {
  const double tol = 1e-9 * network_scale(plan);
  const Vec3 eye = eye_position(camera);
  // OpenGL eye space looks along -z: the optical axis is minus the third row.
  const Vec3 forward = -camera.view.block<1, 3>(2, 0).transpose().normalized();
  const std::vector<Vec3> pois = points_of_interest(plan, tol);
  std::vector<PlannedStroke> out;
  // The view the current curve and its aids are drawn in: the tablet's, or
  // zoomed in on a small curve (see the header).
  std::optional<View> zoom;
  auto on_screen = [&](const View& v, const Vec3& x) {
    const Vec3 px = world_to_pixel(v, x);
    return px.z() >= 0 && px.x() >= v.viewport[0] && px.y() >= v.viewport[1] &&
           px.x() <= v.viewport[0] + v.viewport[2] && px.y() <= v.viewport[1] + v.viewport[3];
  };
  // The stroke `make` draws in a view, drawn zoomed in when it fits the
  // zoomed screen (a guideline from a point far off is drawn before zooming
  // in); `make` sizes it for the view it is drawn in.
  auto emit = [&](const auto& make, Layer layer, std::optional<std::size_t> intended = std::nullopt) {
    PlannedStroke s{make(zoom ? *zoom : camera), layer, intended};
    if (zoom && on_screen(*zoom, s.curve.control_points.front()) && on_screen(*zoom, s.curve.control_points.back()))
      s.zoomed = zoom;
    else if (zoom)
      s.curve = make(camera);
    out.push_back(std::move(s));
  };
  // Lines drawn so far: ends, unit direction, whether it is a guideline (a
  // ray from a through b, as the corrector stores it).
  struct DrawnLine {
    Vec3 a, b, d;
    bool guide;
  };
  std::vector<DrawnLine> drawn_lines;
  // Vertices the corrector holds: ends of drawn curves and ticks.
  std::vector<Vec3> vertices;
  auto on_line = [&](const DrawnLine& l, const Vec3& x) { return (x - l.a).cross(l.d).norm() <= tol; };
  auto on_drawn = [&](const DrawnLine& l, const Vec3& x) {
    const double t = (x - l.a).dot(l.d);
    return on_line(l, x) && t >= -tol && (l.guide || t <= (l.b - l.a).norm() + tol);
  };
  auto covered = [&](const Vec3& p, const Vec3& d) {
    return std::any_of(drawn_lines.begin(), drawn_lines.end(),
                       [&](const DrawnLine& l) { return l.d.cross(d).norm() <= 1e-9 && on_line(l, p); });
  };
  // A known point (§2.2, Fig. 7a, b): a vertex, or where two drawn lines meet.
  auto known = [&](const Vec3& p) {
    if (std::any_of(vertices.begin(), vertices.end(), [&](const Vec3& v) { return (v - p).norm() <= tol; }))
      return true;
    for (std::size_t i = 0; i < drawn_lines.size(); ++i)
      for (std::size_t j = i + 1; j < drawn_lines.size(); ++j)
        if (drawn_lines[i].d.cross(drawn_lines[j].d).norm() > 1e-9 && on_drawn(drawn_lines[i], p) &&
            on_drawn(drawn_lines[j], p))
          return true;
    return false;
  };
  // The guideline stroke from `from` along d: 1.25× the length it serves
  // and at least `zoom_below` on screen (a direction is drawn by a long,
  // confident stroke toward its vanishing point, §2.2, Fig. 3b; a short one
  // would fix it only to the pen's error over its length), in the zoomed
  // view when it fits there.
  auto guide_stroke = [&](const Vec3& from, const Vec3& d, double length) {
    emit(
        [&](const View& v) {
          const double px_per_m =
              (world_to_pixel(v, from + 1e-3 * d) - world_to_pixel(v, from)).head<2>().norm() / 1e-3;
          return make_line(from, from + std::max(1.25 * length, zoom_below * v.dpi / px_per_m) * d);
        },
        Layer::guide);
  };
  // A guideline from `from` along ±d (the sense toward the vanishing point).
  auto guideline = [&](const Vec3& from, Vec3 d, double length) {
    if (d.dot(forward) < 0) d = -d;
    drawn_lines.push_back({from, from + length * d, d, true});
    guide_stroke(from, d, length);
  };
  // A guideline through `from` that reaches `to`: one already drawn, else
  // one drawn from `from` toward `to` (every vanishing point of the tablet
  // view is off screen, where §2.2 takes either sense).
  auto guideline_to = [&](const Vec3& from, const Vec3& to) -> const DrawnLine& {
    const Vec3 d = (to - from).normalized();
    for (const DrawnLine& l : drawn_lines)
      if (l.guide && l.d.cross(d).norm() <= 1e-9 && on_drawn(l, from) && on_drawn(l, to)) return l;
    drawn_lines.push_back({from, to, d, true});
    guide_stroke(from, d, (to - from).norm());
    return drawn_lines.back();
  };
  // A 24 px tick mark across the line l at x (§2.3). The corrector locates
  // it on the guideline and transfers |x − y| to every other guideline
  // crossing this one at y, both ways (Fig. 6): those points become known
  // too.
  auto tick = [&](const DrawnLine& l, const Vec3& x) {
    const Vec3 across = l.d.cross(x - eye).normalized();
    emit(
        [&](const View& v) {
          const double half = 12.0 * 2.0 * (x - eye).dot(forward) / (v.projection(1, 1) * v.viewport[3]);
          return make_line(x - half * across, x + half * across);
        },
        Layer::scaffold);
    if (!l.guide) return;
    vertices.push_back(x);
    for (const DrawnLine& o : drawn_lines) {
      if (!o.guide || o.d.cross(l.d).norm() <= 1e-9) continue;
      const Vec3 n = l.d.cross(o.d);
      if (std::abs((o.a - l.a).dot(n)) > tol * n.norm()) continue;
      const Vec3 y = o.a + ((l.a - o.a).cross(l.d).dot(n) / n.squaredNorm()) * o.d;
      const double A = (x - y).norm();
      if (A > tol) vertices.insert(vertices.end(), {y + A * o.d, y - A * o.d});
    }
  };
  auto is_poi = [&](const Vec3& x) {
    return std::any_of(pois.begin(), pois.end(), [&](const Vec3& q) { return (q - x).norm() <= tol; });
  };
  // Makes p a known point by the fewest ticks (§2.3), unless it lies on a
  // drawn line: along a chain of axis-aligned steps between points of
  // interest from a known point, each step a guideline and a tick at its far
  // end. Figure 6's transfer replaces that tick where it can: a tick at the
  // step's length A on a guideline through the step's start along another
  // axis puts ticks at ±A on the step's guideline, when that tick lies over
  // a vertex (copying a dimension drawn already) or, the step's point
  // mirrored through its start being a point of interest too (a square's
  // corners about the middle of its side, a circle's joints about its
  // centre), on a point of interest (one eyeballed dimension for both).
  auto make_known = [&](const Vec3& p) {
    // A point on a drawn line is the nearest point on it already (Fig. 7d).
    if (std::any_of(drawn_lines.begin(), drawn_lines.end(),
                    [&](const DrawnLine& l) { return !l.guide && on_drawn(l, p); }))
      return;
    const std::vector<Vec3> chain = axis_chain(pois, known, p);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const Vec3 a = chain[k], b = chain[k + 1];
      if (known(b)) continue;
      const Vec3 d = (b - a).normalized();
      const double A = (b - a).norm();
      const DrawnLine along = guideline_to(a, b);
      const bool mirrored = is_poi(a - A * d);
      std::optional<Vec3> via;
      for (int pass = 0; pass < 2 && !via; ++pass)
        for (int axis = 0; axis < 3 && !via; ++axis) {
          const Vec3 e = Vec3::Unit(axis);
          if (std::abs(e.dot(d)) > 0.5) continue;
          for (double sense : {1.0, -1.0}) {
            const Vec3 x = a + sense * A * e;
            if (!via && (pass == 0 ? known(x) : mirrored && is_poi(x))) via = x;
          }
        }
      if (via) {
        tick(guideline_to(a, *via), *via);
        if (known(b)) continue;
      }
      tick(along, b);
    }
  };
  for (std::size_t i = 0; i < plan.curves.size(); ++i) {
    const GroundTruthCurve& gc = plan.curves[i];
    // A curve smaller on screen than `zoom_below` is drawn, with its aids,
    // zoomed in `zoom_factor` times about its middle.
    Eigen::AlignedBox2d extent;
    for (int k = 0; k <= 16; ++k)
      extent.extend(world_to_pixel(camera, evaluate(gc.curve, gc.curve.t_max() * k / 16.0)).head<2>());
    zoom.reset();
    if (extent.diagonal().norm() < zoom_below * camera.dpi)
      zoom = zoomed_view(camera, zoom_factor, extent.center());
    const bool axis_line = is_line(gc.curve) && axis_of(end(gc.curve) - start(gc.curve)) >= 0;
    make_known(start(gc.curve));
    // Its length by a tick too (the paper's cube "required our guideline
    // ticks", §4), unless a drawn line or guideline across it meets its far
    // end (Fig. 3e: a guideline intersection).
    const Vec3 dir = (end(gc.curve) - start(gc.curve)).normalized();
    if (!axis_line || std::none_of(drawn_lines.begin(), drawn_lines.end(), [&](const DrawnLine& l) {
          return l.d.cross(dir).norm() > 1e-9 && on_drawn(l, end(gc.curve));
        }))
      make_known(end(gc.curve));
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
        tick(drawn_lines.back(), x);
      }
    }
    emit([&](const View&) { return gc.curve; }, gc.layer, i);
    vertices.push_back(start(gc.curve));
    vertices.push_back(end(gc.curve));
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
