#include "brush_detection.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "node_snap.hpp"
#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab::cassie {
namespace {

int rank(TargetKind k) {
  switch (k) {
    case TargetKind::node: return 2;
    case TargetKind::curve: return 1;
    case TargetKind::grid:
    case TargetKind::mirror: return 0;
  }
  return 0;
}

struct Plane {
  Vec3 normal = Vec3::UnitX();  // unit
  double offset = 0.0;
  double side(const Vec3& p) const { return normal.dot(p) - offset; }
  Vec3 project(const Vec3& p) const { return p - side(p) * normal; }
};

Candidate curve_constraint(const Network& net, const CurveHit& hit, double time, const Vec3& brush,
                           const Thresholds& th) {
  Candidate c;
  c.kind = TargetKind::curve;
  c.curve = hit.curve;
  c.t_curve = hit.t;
  c.target = hit.point;
  c.time = time;
  c.brush = brush;
  const Curve& old = net.curves().at(hit.curve).curve;
  c.at_curve_end = hit.t <= 0.0 || hit.t >= old.t_max();
  snap_to_node(c, net, th);  // item 8
  return c;
}

// A curve lies in the plane when its control points do (within `tol`).
bool lies_in(const Curve& curve, const Plane& plane, double tol) {
  return std::all_of(curve.control_points.begin(), curve.control_points.end(),
                     [&](const Vec3& p) { return std::abs(plane.side(p)) <= tol; });
}

// Brush positions: t0 + k·step before the last sample's time (item 6), by
// linear interpolation of the samples; each sample when the stroke has no
// duration.
std::vector<std::pair<double, Vec3>> brush_positions(const Stroke& s, double step) {
  std::vector<std::pair<double, Vec3>> out;
  const auto& smp = s.samples;
  const double t0 = smp.front().time, t1 = smp.back().time;
  if (!(t1 > t0)) {
    for (const Sample& x : smp) out.push_back({x.time, x.position});
    return out;
  }
  std::size_t i = 0;
  for (long k = 0;; ++k) {
    const double t = t0 + static_cast<double>(k) * step;
    if (k > 0 && t >= t1) break;
    while (i + 1 < smp.size() && smp[i + 1].time <= t) ++i;
    if (i + 1 >= smp.size()) {
      out.push_back({t, smp.back().position});
      break;
    }
    const double span = smp[i + 1].time - smp[i].time;
    const double u = span > 0 ? (t - smp[i].time) / span : 0.0;
    out.push_back({t, (1.0 - u) * smp[i].position + u * smp[i + 1].position});
  }
  return out;
}

}  // namespace

void add_constraint(std::vector<Candidate>& list, const Candidate& c, const Thresholds& th) {
  if (list.empty()) {
    list.push_back(c);
    return;
  }
  Candidate& prev = list.back();
  const double d = (c.target - prev.target).norm();
  if (c.kind == TargetKind::mirror && prev.kind == TargetKind::mirror && d <= th.plane_merge) {
    prev = c;
    return;
  }
  if (d > th.merge) {
    list.push_back(c);
    return;
  }
  if (rank(c.kind) >= rank(prev.kind)) prev = c;  // equal rank: the newer wins
}

std::vector<Candidate> detect_constraints(const Stroke& stroke, const Sketch& sketch,
                                          const Thresholds& th, double brush_step, bool mirror,
                                          DetectionStats& stats) {
  const Network& net = sketch.network;
  const Workspace& ws = sketch.workspace;
  struct Event {
    double time;
    int order;  // brush steps before samples at equal times
    Candidate c;
  };
  std::vector<Event> events;
  std::optional<Plane> plane;
  if (mirror && ws.mirror_enabled && ws.mirror_normal.norm() > 0)
    plane = Plane{ws.mirror_normal.normalized(), ws.mirror_offset / ws.mirror_normal.norm()};

  // Item 6: curves entered by the brush; item 18: the plane entered.
  std::map<CurveId, bool> inside;
  bool in_plane = false;
  for (const auto& [time, b] : brush_positions(stroke, brush_step)) {
    ++stats.brush_queries;
    const std::vector<CurveHit> hits = net.curves_near(b, th.contact);
    stats.curve_contacts += static_cast<int>(hits.size());
    std::map<CurveId, bool> now;
    bool planar_curve = false;
    for (const CurveHit& h : hits) {
      now[h.curve] = true;
      if (plane && lies_in(net.curves().at(h.curve).curve, *plane, th.on_plane)) planar_curve = true;
    }
    for (const CurveHit& h : hits) {
      if (!inside.count(h.curve)) events.push_back({time, 0, curve_constraint(net, h, time, b, th)});
    }
    inside = std::move(now);
    if (plane) {
      const bool touching = std::abs(plane->side(b)) <= th.brush;
      if (touching && !in_plane && !planar_curve) {
        Candidate c;
        c.kind = TargetKind::mirror;
        c.target = plane->project(b);
        c.time = time;
        c.brush = b;
        events.push_back({time, 0, c});
      }
      in_plane = touching;
    }
  }
  // Item 19: the grid, at each raw sample.
  if (ws.grid_enabled && ws.grid_spacing > 0) {
    for (const Sample& smp : stroke.samples) {
      ++stats.grid_queries;
      const Vec3 g = nearest_grid_point(ws, smp.position);
      if ((g - smp.position).norm() > th.grid) continue;
      Candidate c;
      c.kind = TargetKind::grid;
      c.target = g;
      c.time = smp.time;
      c.brush = smp.position;
      const std::vector<CurveHit> near = net.curves_near(g, th.grid);
      if (!near.empty()) {
        c = curve_constraint(net, near.front(), smp.time, smp.position, th);
      } else if (plane && std::abs(plane->side(g)) <= th.grid) {
        c.kind = TargetKind::mirror;
        c.target = plane->project(g);
      }
      events.push_back({smp.time, 1, c});
    }
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    return a.time != b.time ? a.time < b.time : a.order < b.order;
  });
  std::vector<Candidate> out;
  for (const Event& e : events) add_constraint(out, e.c, th);
  return out;
}

}  // namespace sketchlab::cassie
