#include "curve_edit.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "default_normals.hpp"
#include "network_curves.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::justdrawit {

namespace {

// Default normals (§6) sampled along the curve, with pins at nodes.
std::vector<CurveNormal> export_normals(const Points3& pts, bool closed, CurveId id,
                                        const Network& net, const std::vector<Node>& nodes,
                                        const Vec3& fallback) {
  std::vector<NormalPin> pins;
  for (const Node& n : nodes) {
    const NodeIncidence* mine = nullptr;
    const NodeIncidence* other = nullptr;
    for (const NodeIncidence& inc : n.incidences) {
      if (inc.curve == id && !mine) mine = &inc;
      else if (inc.curve != id && !other) other = &inc;
    }
    if (!mine || !other) continue;
    const NetworkCurve* oc = net.find_curve(other->curve);
    if (!oc) continue;
    const Points3 op = curve_points(oc->curve, 1e-3);
    const auto ia = static_cast<std::size_t>(std::clamp(std::lround(mine->t), 0L, static_cast<long>(pts.size()) - 1));
    const auto oc_cum = cumulative(op);
    const auto pr = project(op, oc_cum, n.position);
    pins.push_back({ia, pin_normal(pts, ia, op, pr.index)});
  }
  Box3 box;
  for (const Vec3& q : pts) box.extend(q);
  const auto normals = default_normals(pts, closed, pins, 0.01 * box.diagonal().norm(), fallback);
  std::vector<CurveNormal> out;
  const std::size_t step = std::max<std::size_t>(1, pts.size() / 64);
  for (std::size_t i = 0; i < pts.size(); i += step) out.push_back({static_cast<double>(i), normals[i]});
  if ((pts.size() - 1) % step != 0) out.push_back({static_cast<double>(pts.size() - 1), normals.back()});
  return out;
}

}  // namespace

void add_edit(Outcome& o, const Built& built, Decision decision, const SceneItem* item_a,
              const SceneItem* item_b, const std::string& surface_used, const Stroke& stroke,
              const Network& net, const Ctx& ctx) {
  const double d = ctx.d;
  // The edit: a new curve, or the replacement of one curve (and removal of
  // the second when two are combined).
  const NetworkCurve* old = item_a ? net.find_curve(item_a->id) : nullptr;
  NetworkCurve nc = make_network_curve(old ? old->id : net.next_curve_id(),
                                       polyline_curve(built.pts, built.closed),
                                       old ? old->layer : curve_layer(stroke.layer), stroke.id);
  const Points3 final_pts = curve_points(nc.curve, 1.0);
  std::vector<Node> kept_nodes;
  if (item_a) {
    // Nodes on the edited curves follow the new curve when still on it
    // (within d3), else lose that incidence; patches on them are dropped.
    const double d3 = d * ctx.cam.world_per_pixel(item_a->centroid);
    const auto fcum = cumulative(final_pts);
    std::set<NodeId> seen;
    for (CurveId cid : {item_a->id, item_b ? item_b->id : CurveId{0}}) {
      if (!cid) continue;
      for (PatchId pid : net.patches_on(cid))
        if (std::find(o.edit.patches_removed.begin(), o.edit.patches_removed.end(), pid) ==
            o.edit.patches_removed.end())
          o.edit.patches_removed.push_back(pid);
    }
    for (const auto& [nid, node] : net.nodes()) {
      bool touches = false;
      for (const NodeIncidence& inc : node.incidences)
        touches = touches || inc.curve == item_a->id || (item_b && inc.curve == item_b->id);
      if (!touches) continue;
      Node n = node;
      n.incidences.clear();
      bool on_new = false;
      for (const NodeIncidence& inc : node.incidences) {
        if (item_b && inc.curve == item_b->id) continue;
        if (inc.curve == item_a->id) {
          if (on_new) continue;
          const auto pr = project(final_pts, fcum, node.position);
          if (pr.distance > d3) continue;
          on_new = true;
          n.incidences.push_back({nc.id, static_cast<double>(pr.index) + pr.u});
          continue;
        }
        n.incidences.push_back(inc);
      }
      if (n.incidences.empty()) o.edit.nodes_removed.push_back(nid);
      else {
        o.edit.nodes_replaced.push_back(n);
        kept_nodes.push_back(n);
      }
    }
    std::sort(o.edit.patches_removed.begin(), o.edit.patches_removed.end());
  }
  if (ctx.p.normals) {
    const Vec3 fallback = -ctx.cam.forward();
    nc.normals = export_normals(final_pts, nc.curve.closed, nc.id, net, kept_nodes, fallback);
  }
  if (item_a) o.edit.curves_replaced.push_back(nc);
  else o.edit.curves_added.push_back(nc);
  if (item_b) o.edit.curves_removed.push_back(item_b->id);

  // What was considered: the joins (tangent continuity, objective as the
  // residual angle), closure, and the drawing surface.
  const std::vector<CurveId> targets{item_a ? item_a->id : CurveId{0}, item_b ? item_b->id : CurveId{0}};
  for (std::size_t j = 0; j < built.objectives.size(); ++j) {
    Constraint c;
    c.kind = ConstraintKind::tangent;
    c.references.push_back({ConstraintRef::Kind::stroke, stroke.id, 0.0});
    const CurveId t = decision == Decision::combine && j == 1 ? targets[1] : targets[0];
    c.references.push_back({ConstraintRef::Kind::curve, t ? t : nc.id, 0.0});
    c.enforced = true;
    c.residual = built.objectives[j];
    o.constraints.push_back(c);
  }
  if (nc.curve.closed) {
    Constraint c;
    c.kind = ConstraintKind::closure;
    c.references.push_back({ConstraintRef::Kind::curve, nc.id, 0.0});
    c.enforced = true;
    c.residual = (nc.curve.control_points.front() - nc.curve.control_points.back()).norm();
    o.constraints.push_back(c);
  }
  if (!surface_used.empty()) {
    Constraint c;
    c.kind = ConstraintKind::on_surface;
    c.references.push_back({ConstraintRef::Kind::stroke, stroke.id, 0.0});
    c.enforced = true;
    o.constraints.push_back(c);
    o.stats.extra["surface"] = surface_used == "view_plane"   ? 0
                               : surface_used == "draw_plane" ? 1
                               : surface_used == "extrusion"  ? 2
                                                              : 3;
  }
}

}  // namespace sketchlab::justdrawit
