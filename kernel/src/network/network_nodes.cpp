#include "sketchlab/network_nodes.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab {
namespace {

void add_incidence(Node& node, CurveId curve, double t) {
  const bool present = std::any_of(node.incidences.begin(), node.incidences.end(),
                                   [&](const NodeIncidence& i) {
                                     return i.curve == curve && std::abs(i.t - t) <= 1e-9;
                                   });
  if (present) return;
  node.incidences.push_back({curve, t});
  std::sort(node.incidences.begin(), node.incidences.end(),
            [](const NodeIncidence& l, const NodeIncidence& r) {
              return l.curve != r.curve ? l.curve < r.curve : l.t < r.t;
            });
}

Node* node_within(std::vector<Node>& nodes, const Vec3& p, double tolerance) {
  for (Node& n : nodes)
    if ((n.position - p).norm() <= tolerance) return &n;
  return nullptr;
}

}  // namespace

void connect_point(const Network& network, const Vec3& p, CurveId curve, double t,
                   double tolerance, Edit& edit, NodeId& next_node,
                   const std::function<bool(CurveId)>& ignore) {
  if (!p.allFinite()) return;
  std::vector<CurveHit> hits = network.curves_near(p, tolerance);
  std::erase_if(hits, [&](const CurveHit& h) {
    return h.curve == curve || (ignore && ignore(h.curve)) ||
           std::find(edit.curves_removed.begin(), edit.curves_removed.end(), h.curve) !=
               edit.curves_removed.end();
  });
  if (hits.empty()) return;

  Node* node = node_within(edit.nodes_added, p, tolerance);
  if (!node) node = node_within(edit.nodes_replaced, p, tolerance);
  if (!node) {
    const auto existing = network.nodes_near(p, tolerance);
    if (!existing.empty()) {
      edit.nodes_replaced.push_back(*network.find_node(existing.front().node));
      node = &edit.nodes_replaced.back();
    }
  }
  if (!node) {
    Node fresh;
    fresh.id = next_node++;
    fresh.position = p;
    edit.nodes_added.push_back(fresh);
    node = &edit.nodes_added.back();
  }
  add_incidence(*node, curve, t);
  for (const CurveHit& h : hits) add_incidence(*node, h.curve, h.t);
}

}  // namespace sketchlab
