#include "curve_graph.hpp"

#include <algorithm>
#include <cmath>

#include "curve_tangent.hpp"
#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::soapfilm {
namespace {

constexpr double t_eps = 1e-9;

bool same_t(const Curve& c, double a, double b) {
  if (std::abs(a - b) <= t_eps) return true;
  return c.closed && std::abs(std::abs(a - b) - c.t_max()) <= t_eps;
}

}  // namespace

double wrap_parameter(const Curve& curve, double t) {
  const double T = curve.t_max();
  if (!curve.closed) return std::clamp(t, 0.0, T);
  while (t > T) t -= T;
  while (t < 0.0) t += T;
  return t;
}

bool CurveGraph::is_graph_node(NodeId id) const {
  const Node* node = network_->find_node(id);
  if (!node || node->incidences.empty()) return false;
  const NodeIncidence& first = node->incidences.front();
  const NetworkCurve* nc = network_->find_curve(first.curve);
  if (!nc) return false;
  for (const NodeIncidence& inc : node->incidences)
    if (inc.curve != first.curve || !same_t(nc->curve, inc.t, first.t)) return true;
  // One curve passing through: a graph node only at an open curve's end.
  const Curve& c = nc->curve;
  // A closed curve's seam, with closed_seam_nodes.
  const bool at_end = first.t <= t_eps || first.t >= c.t_max() - t_eps;
  return at_end && (!c.closed || closed_seam_nodes_);
}

const std::vector<int>& CurveGraph::segments_of(CurveId curve) {
  if (auto it = by_curve_.find(curve); it != by_curve_.end()) return it->second;
  std::vector<int>& out = by_curve_[curve];
  const NetworkCurve* nc = network_->find_curve(curve);
  if (!nc) return out;
  std::vector<Segment> pieces = network_->segments_of(curve);
  if (pieces.empty()) return out;
  const std::size_t n = pieces.size();
  const Curve& c = nc->curve;
  // Nodes at one parameter are one point of the curve (CASSIE app, item 22:
  // one node per meeting point). Nodes deleted curves left (not graph nodes)
  // can share a parameter with each other or with a later meeting's node;
  // the kernel has no piece between them, so each piece end there stands for
  // the graph node at that parameter if there is one, and pieces meeting at
  // one parameter are contiguous.
  std::vector<std::pair<double, NodeId>> graph_nodes;
  for (const Segment& p : pieces)
    for (const auto& [t, id] : {std::pair{p.t0, p.node0}, std::pair{p.t1, p.node1}})
      if (is_graph_node(id)) graph_nodes.emplace_back(t, id);
  const auto stand_in = [&](double t, NodeId id) {
    if (is_graph_node(id)) return id;
    for (const auto& [tg, g] : graph_nodes)
      if (same_t(c, tg, t)) return g;
    return id;
  };
  for (Segment& p : pieces) {
    p.node0 = stand_in(p.t0, p.node0);
    p.node1 = stand_in(p.t1, p.node1);
  }
  // Start at a piece beginning at a graph node (closed curves may start
  // anywhere in the list); merge pieces across non-graph nodes.
  std::size_t start = 0;
  if (c.closed) {
    while (start < n && !is_graph_node(pieces[start].node0)) ++start;
    // A closed curve meeting nothing is one loop at its first node (CASSIE
    // app, item 22: a closed stroke is one node with its segment attached
    // twice); the pieces merge into it.
    if (start == n) start = 0;
  }
  std::size_t i = start;
  const std::size_t count = c.closed ? n : n - start;
  std::size_t done = 0;
  while (done < count) {
    GraphSegment g{curve, pieces[i].t0, pieces[i].t1, pieces[i].node0, pieces[i].node1};
    ++done;
    // Open curves: pieces are contiguous only when they share a node or a
    // parameter (see above).
    while (done < count && !is_graph_node(g.node1)) {
      const Segment& next = pieces[(i + 1) % n];
      if (next.node0 != g.node1 && !same_t(c, next.t0, g.t1)) break;
      i = (i + 1) % n;
      g.t1 = next.t1;
      g.node1 = next.node1;
      ++done;
    }
    i = (i + 1) % n;
    out.push_back(static_cast<int>(segments_.size()));
    segments_.push_back(g);
  }
  return out;
}

std::vector<HalfEdge> CurveGraph::outgoing(NodeId id) {
  std::vector<HalfEdge> out;
  const Node* node = network_->find_node(id);
  if (!node) return out;
  std::vector<CurveId> curves;
  for (const NodeIncidence& inc : node->incidences) curves.push_back(inc.curve);
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  for (CurveId c : curves)
    for (int s : segments_of(c)) {
      const GraphSegment& g = segment(s);
      if (g.node0 == id) out.push_back({s, true});
      if (g.node1 == id) out.push_back({s, false});
    }
  return out;
}

const Curve& CurveGraph::curve_of(HalfEdge h) const {
  return network_->find_curve(segment(h.segment).curve)->curve;
}

double CurveGraph::span(int s) const {
  const GraphSegment& g = segment(s);
  const Curve& c = network_->find_curve(g.curve)->curve;
  if (g.t1 > g.t0) return g.t1 - g.t0;
  return c.closed ? g.t1 - g.t0 + c.t_max() : 0.0;
}

Vec3 CurveGraph::direction(HalfEdge h) const {
  const GraphSegment& g = segment(h.segment);
  const Curve& c = curve_of(h);
  if (h.forward) return one_sided_tangent(c, g.t0, true);
  double t1 = g.t1;
  if (c.closed && t1 <= 0.0) t1 = c.t_max();
  return -one_sided_tangent(c, t1, false);
}

Vec3 CurveGraph::chord(HalfEdge h) const {
  return network_->find_node(to(h))->position - network_->find_node(from(h))->position;
}

std::vector<double> CurveGraph::parameters(HalfEdge h, int n) const {
  n = std::max(n, 2);
  const GraphSegment& g = segment(h.segment);
  const Curve& c = curve_of(h);
  const double len = span(h.segment);
  std::vector<double> t(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(h.forward ? i : n - 1 - i) / (n - 1);
    double v = g.t0 + u * len;
    if (c.closed && v > c.t_max()) v -= c.t_max();
    t[static_cast<std::size_t>(i)] = std::clamp(v, 0.0, c.t_max());
  }
  // Exact ends (the nodes' own parameters).
  t.front() = h.forward ? g.t0 : g.t1;
  t.back() = h.forward ? g.t1 : g.t0;
  return t;
}

OrientedSegment CurveGraph::oriented(HalfEdge h) const {
  const GraphSegment& g = segment(h.segment);
  return h.forward ? OrientedSegment{g.curve, g.t0, g.t1, g.node0, g.node1}
                   : OrientedSegment{g.curve, g.t1, g.t0, g.node1, g.node0};
}

int CurveGraph::segment_at(CurveId curve, double t) {
  const std::vector<int>& segs = segments_of(curve);
  if (segs.empty()) return -1;
  const Curve& c = network_->find_curve(curve)->curve;
  int best = segs.front();
  double best_d = INFINITY;
  for (int s : segs) {
    const GraphSegment& g = segment(s);
    const double len = span(s);
    double rel = t - g.t0;
    if (c.closed && rel < 0.0) rel += c.t_max();
    if (rel >= -t_eps && rel <= len + t_eps) return s;
    const double d = std::min(std::abs(rel), std::abs(rel - len));
    if (d < best_d) best_d = d, best = s;
  }
  return best;
}

std::vector<int> CurveGraph::covered_by(const OrientedSegment& piece, bool* wraps) {
  if (wraps) *wraps = false;
  const NetworkCurve* nc = network_->find_curve(piece.curve);
  if (!nc) return {};
  const Curve& c = nc->curve;
  const double T = c.t_max();
  const std::vector<int>& segs = segments_of(piece.curve);
  // Interval [lo, lo + len] in unwrapped parameter: the graph segments inside
  // it, and whether they cover it exactly.
  auto collect = [&](double lo, double len) {
    std::vector<int> hit;
    double covered = 0.0;
    for (int s : segs) {
      const GraphSegment& g = segment(s);
      double rel = g.t0 - lo;
      if (c.closed && rel < -t_eps) rel += T;
      const double sl = span(s);
      if (rel >= -t_eps && rel + sl <= len + t_eps) {
        hit.push_back(s);
        covered += sl;
      }
    }
    return std::make_pair(hit, !hit.empty() && std::abs(covered - len) <= 1e-7 * std::max(1.0, T));
  };
  // The graph segment holding all of [lo, lo + len], or -1.
  auto containing = [&](double lo, double len) {
    for (int s : segs) {
      double rel = lo - segment(s).t0;
      if (c.closed && rel < -t_eps) rel += T;
      if (rel >= -t_eps && rel + len <= span(s) + t_eps) return s;
    }
    return -1;
  };
  const double a = std::min(piece.t_from, piece.t_to), b = std::max(piece.t_from, piece.t_to);
  if (!c.closed) {
    if (auto direct = collect(a, b - a); direct.second) return direct.first;
    if (const int s = containing(a, b - a); s >= 0) return {s};
    return collect(a, b - a).first;
  }
  if (a == b) return collect(a, T).first;
  // On a closed curve a piece and its complement share their end parameters:
  // it is read the way that is an exact union of graph segments, else the
  // way one graph segment holds it.
  auto direct = collect(a, b - a);
  auto wrapped = collect(b, a + T - b);
  if (direct.second) return direct.first;
  if (wrapped.second) {
    if (wraps) *wraps = true;
    return wrapped.first;
  }
  if (const int s = containing(a, b - a); s >= 0) return {s};
  if (const int s = containing(b, a + T - b); s >= 0) {
    if (wraps) *wraps = true;
    return {s};
  }
  if (wraps) *wraps = wrapped.first.size() > direct.first.size();
  return direct.first.size() >= wrapped.first.size() ? direct.first : wrapped.first;
}

}  // namespace sketchlab::soapfilm
