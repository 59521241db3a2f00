#include "manual_patch.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "curve_graph.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::soapfilm {
namespace {

// Distance from p to a graph segment, on a polyline of its points (8 per
// cubic piece: the comparison only ranks neighbouring segments).
double segment_distance(const CurveGraph& graph, HalfEdge h, const Vec3& p) {
  const int n = std::max(3, static_cast<int>(std::ceil(graph.span(h.segment) * 8.0)) + 1);
  const Curve& c = graph.curve_of(h);
  std::vector<Vec3> pts;
  for (double t : graph.parameters(h, n)) pts.push_back(evaluate(c, t));
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec3 d = pts[i + 1] - pts[i];
    const double len2 = d.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp((p - pts[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (pts[i] + u * d - p).norm());
  }
  return best;
}

// Whether graph segment s already bounds two patches (item 26: manifold
// first).
bool full(CurveGraph& graph, int s) {
  int count = 0;
  for (PatchId id : graph.network().patches_on(graph.segment(s).curve)) {
    const std::vector<int> key = boundary_key(graph, graph.network().patches().at(id).boundary);
    count += std::binary_search(key.begin(), key.end(), s);
  }
  return count >= 2;
}

std::optional<std::vector<OrientedSegment>> walk_towards(CurveGraph& graph, HalfEdge start, const Vec3& p,
                                                         const ManualPatchParams& params) {
  const NodeId a = graph.from(start);
  std::vector<OrientedSegment> cycle{graph.oriented(start)};
  std::set<NodeId> visited{a};
  std::set<int> used{start.segment};
  HalfEdge cur = start;
  int turns = 0;
  while (true) {
    const NodeId b = graph.to(cur);
    if (b == a) return cycle;
    if (!visited.insert(b).second || static_cast<int>(cycle.size()) >= params.max_segments) return std::nullopt;
    std::optional<HalfEdge> best;
    double best_d = INFINITY;
    bool best_full = true;
    for (const HalfEdge& h : graph.outgoing(b)) {
      if (h == cur.reversed() || used.count(h.segment)) continue;
      const double d = segment_distance(graph, h, p);
      const bool f = params.manifold_first && full(graph, h.segment);
      if (!best || (f != best_full ? !f : d < best_d)) best_d = d, best = h, best_full = f;
    }
    if (!best) return std::nullopt;
    // Item 26: a turn where the tangents differ.
    if (params.max_turns > 0 && (-graph.direction(cur.reversed())).dot(graph.direction(*best)) < params.turn_cos &&
        ++turns > params.max_turns)
      return std::nullopt;
    used.insert(best->segment);
    cycle.push_back(graph.oriented(*best));
    cur = *best;
  }
}

}  // namespace

std::optional<std::vector<OrientedSegment>> manual_cycle(const Network& network, const Vec3& point,
                                                         const ManualPatchParams& params, bool closed_seam_nodes) {
  if (!point.allFinite()) return std::nullopt;
  CurveGraph graph(network, closed_seam_nodes);
  // Nearest curve pieces first (growing radius keeps the query local).
  std::vector<CurveHit> hits;
  for (double r = 0.05; r <= params.search_radius * 2.0; r *= 4.0) {
    hits = network.curves_near(point, std::min(r, params.search_radius));
    bool any = false;
    for (const CurveHit& h : hits) any = any || graph.segment_at(h.curve, h.t) >= 0;
    if (any) break;
  }
  for (const CurveHit& hit : hits) {
    const int s = graph.segment_at(hit.curve, hit.t);
    if (s < 0) continue;
    // Both directions; keep the shorter closed walk.
    std::optional<std::vector<OrientedSegment>> best;
    for (bool forward : {true, false}) {
      auto c = walk_towards(graph, HalfEdge{s, forward}, point, params);
      if (c && (!best || c->size() < best->size())) best = std::move(c);
    }
    if (best) return best;
  }
  return std::nullopt;
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson, Real-Time Collision Detection §5.1.5.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.norm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

std::optional<PatchId> nearest_patch(const Network& network, const Vec3& point) {
  std::optional<PatchId> best;
  double best_d = INFINITY;
  for (const auto& [id, patch] : network.patches()) {
    double d = INFINITY;
    const Mesh& m = patch.mesh;
    for (const auto& f : m.faces)
      d = std::min(d, point_triangle_distance(point, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]));
    if (m.faces.empty())
      for (const OrientedSegment& s : patch.boundary)
        if (const Node* n = network.find_node(s.node_from)) d = std::min(d, (n->position - point).norm());
    if (d < best_d) best_d = d, best = id;
  }
  return best;
}

}  // namespace sketchlab::soapfilm
