#include "node_snap.hpp"

#include <algorithm>
#include <optional>
#include <utility>

namespace sketchlab::cassie {
namespace {

// Every stroke end is a node in CASSIE, so a lone end is no intersection for
// item 8; item 22 joins it within its own reach (cassie README, "A dangling
// end is joined").
std::optional<NodeId> snap_node(const Network& net, CurveId curve, double t, const Vec3& target,
                                const Thresholds& th) {
  const double reach = std::max(th.node_snap, th.dangling_snap);
  const double t_max = net.curves().at(curve).curve.t_max();
  const Node* before = nullptr;
  const Node* after = nullptr;
  double tb = -1.0, ta = 0.0;
  for (const NodeHit& h : net.nodes_near(target, reach)) {
    const Node& n = net.nodes().at(h.node);
    for (const NodeIncidence& inc : n.incidences) {
      if (inc.curve != curve) continue;
      if (inc.t <= t && (!before || inc.t > tb)) before = &n, tb = inc.t;
      if (inc.t >= t && (!after || inc.t < ta)) after = &n, ta = inc.t;
    }
  }
  const Node* best = nullptr;
  double best_d = reach;
  for (const auto& [n, tn] : {std::pair{before, tb}, std::pair{after, ta}}) {
    if (!n) continue;
    const bool at_curve_end = tn <= 0.0 || tn >= t_max;
    const double limit = n->incidences.size() >= 2 ? th.node_snap
                         : at_curve_end && th.dangling_snap > 0 ? th.dangling_snap
                                                                 : -1.0;
    const double d = (n->position - target).norm();
    if (d <= limit && d <= best_d) best = n, best_d = d;
  }
  return best ? std::optional<NodeId>(best->id) : std::nullopt;
}

}  // namespace

void snap_to_node(Candidate& c, const Network& net, const Thresholds& th) {
  if (c.kind != TargetKind::curve) return;
  const auto node = snap_node(net, c.curve, c.t_curve, c.target, th);
  if (!node) return;
  const Node& n = net.nodes().at(*node);
  c.kind = TargetKind::node;
  c.node = *node;
  c.target = n.position;
  for (const NodeIncidence& inc : n.incidences)
    if (inc.curve == c.curve) c.t_curve = inc.t;
}

}  // namespace sketchlab::cassie
