#include "patch_break.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab::soapfilm {
namespace {

// Item 25: from `h` (leaving the cycle), the cycle is reached again through
// at most `reach` two-segment nodes.
bool reaches(CurveGraph& graph, HalfEdge h, const std::set<NodeId>& cycle_nodes, int reach) {
  for (int passed = 0;; ++passed) {
    const NodeId y = graph.to(h);
    if (cycle_nodes.count(y)) return true;
    const std::vector<HalfEdge> outs = graph.outgoing(y);
    if (outs.size() != 2 || passed >= reach) return false;
    h = outs[0] == h.reversed() ? outs[1] : outs[0];
  }
}

// A new half-edge leaving the cycle's node to(cycle[at]).
struct Leaver {
  std::size_t at = 0;
  HalfEdge h;
};

// The cycle's orientation at its nodes (item 25): element i is the normal of
// the node to(cycle[i]) (item 23's, around which its neighbours are sorted)
// oriented so that the cycle turns there from cycle[i] clockwise into
// cycle[i + 1]; empty if the cycle cannot be followed. See broken_by.
std::vector<Vec3> cycle_orientation(CurveGraph& graph, CycleSearcher& searcher, const Cycle& cycle,
                                    const std::set<int>& fresh) {
  // Whether no older segment sits between the cycle's two at to(cycle[i])
  // around `normal`: the walk that made the cycle could turn there so.
  const auto walkable = [&](std::size_t i, const Vec3& normal) {
    const HalfEdge &in = cycle[i], &out = cycle[(i + 1) % cycle.size()];
    const std::vector<HalfEdge> outs = graph.outgoing(graph.to(in));
    return std::none_of(outs.begin(), outs.end(), [&](const HalfEdge& h) {
      return !fresh.count(h.segment) && !(h == in.reversed()) && !(h == out) && searcher.between(in, out, h, normal);
    });
  };
  const NodeFrame& start = searcher.frame(graph.from(cycle.front()));
  const Vec3 n = start.defined ? start.normal : Vec3::UnitZ();
  std::vector<Vec3> best;
  int best_score = -1;
  Vec3 plus_sum = Vec3::Zero();
  for (const double sign : {1.0, -1.0}) {
    std::vector<Vec3> m = searcher.carried(cycle, sign * n);
    if (m.empty()) continue;
    int score = 0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
      const NodeFrame& f = searcher.frame(graph.to(cycle[i]));
      if (f.defined) m[i] = f.normal.dot(m[i]) < 0.0 ? Vec3(-f.normal) : f.normal;
      score += walkable(i, m[i]);
      if (sign > 0.0) plus_sum += m[i];
    }
    // On a tie, the minus orientation only if the cycle runs clockwise
    // around the plus one's normals (the walk keeps its face on its left).
    if (score > best_score || (score == best_score && searcher.winds_clockwise(cycle, plus_sum))) {
      best = std::move(m);
      best_score = score;
    }
  }
  // Where only the other way round is walkable, the walk turned that way.
  for (std::size_t i = 0; i < best.size(); ++i)
    if (!walkable(i, best[i]) && walkable(i, -best[i])) best[i] = -best[i];
  return best;
}

}  // namespace

Cycle cycle_of(CurveGraph& graph, const std::vector<OrientedSegment>& boundary) {
  Cycle out;
  for (const OrientedSegment& piece : boundary) {
    bool wraps = false;
    const std::vector<int> cover = graph.covered_by(piece, &wraps);
    if (cover.empty()) return {};
    const Curve& c = graph.network().find_curve(piece.curve)->curve;
    const double T = c.t_max();
    // Travelling up the parameter, or down; across the seam of a closed
    // curve the other way round; a whole loop (t_from == t_to) upwards.
    bool up = piece.t_from < piece.t_to;
    if (c.closed && wraps) up = !up;
    if (piece.t_from == piece.t_to) up = true;
    std::vector<std::pair<double, int>> along;
    for (int s : cover) {
      const GraphSegment& g = graph.segment(s);
      double offset = up ? g.t0 - piece.t_from : piece.t_from - g.t1;
      if (c.closed) {
        offset = std::fmod(offset, T);
        if (offset < -1e-9 * std::max(1.0, T)) offset += T;
      }
      along.emplace_back(offset, s);
    }
    std::sort(along.begin(), along.end());
    for (const auto& [offset, s] : along)
      if (out.empty() || !(out.back() == HalfEdge{s, up})) out.push_back({s, up});
  }
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  for (std::size_t i = 0; i < out.size(); ++i)
    if (graph.to(out[i]) != graph.from(out[(i + 1) % out.size()])) return {};
  return out;
}

bool broken_by(CurveGraph& graph, CycleSearcher& searcher, const Patch& patch, const std::vector<int>& key,
               const std::set<int>& fresh, const CycleSearchParams& params, std::vector<int>* at) {
  std::set<NodeId> cycle_nodes;
  for (int s : key) {
    cycle_nodes.insert(graph.segment(s).node0);
    cycle_nodes.insert(graph.segment(s).node1);
  }
  const auto new_leaving = [&](const HalfEdge& h) {
    return fresh.count(h.segment) && !std::binary_search(key.begin(), key.end(), h.segment);
  };
  if (!params.break_by_order) {
    for (NodeId x : cycle_nodes)
      for (const HalfEdge& h : graph.outgoing(x))
        if (new_leaving(h) && enters_patch(patch.mesh, graph.network().find_node(x)->position, graph.direction(h)) &&
            reaches(graph, h, cycle_nodes, params.break_reach)) {
          if (at)
            for (const HalfEdge& g : graph.outgoing(x))
              if (std::binary_search(key.begin(), key.end(), g.segment)) at->push_back(g.segment);
          return true;
        }
    return false;
  }
  const Cycle cycle = cycle_of(graph, patch.boundary);
  std::vector<Leaver> leavers;
  for (std::size_t i = 0; i < cycle.size(); ++i)
    for (const HalfEdge& h : graph.outgoing(graph.to(cycle[i])))
      if (new_leaving(h)) leavers.push_back({i, h});
  if (leavers.empty()) return false;
  const std::vector<Vec3> m = cycle_orientation(graph, searcher, cycle, fresh);
  if (m.empty()) return false;
  for (const Leaver& l : leavers) {
    const HalfEdge &in = cycle[l.at], &out = cycle[(l.at + 1) % cycle.size()];
    if (searcher.between(in, out, l.h, m[l.at]) && reaches(graph, l.h, cycle_nodes, params.break_reach)) {
      if (at) *at = {in.segment, out.segment};
      return true;
    }
  }
  return false;
}

bool enters_patch(const Mesh& mesh, const Vec3& at, const Vec3& d) {
  if (mesh.faces.empty() || mesh.vertices.empty()) return true;
  int v = 0;
  double best = INFINITY;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (const double dist = (mesh.vertices[i] - at).squaredNorm(); dist < best) best = dist, v = static_cast<int>(i);
  // The corners of the triangles at v, seen along their mean normal (one
  // plane for the whole fan: the fan's triangles fold, and d projected on
  // each one's own plane could fall between two of them).
  const Vec3& o = mesh.vertices[static_cast<std::size_t>(v)];
  std::vector<std::pair<Vec3, Vec3>> corners;
  Vec3 normal = Vec3::Zero();
  for (const auto& f : mesh.faces)
    for (std::size_t k = 0; k < 3; ++k)
      if (f[k] == v) {
        const Vec3 e1 = mesh.vertices[static_cast<std::size_t>(f[(k + 1) % 3])] - o;
        const Vec3 e2 = mesh.vertices[static_cast<std::size_t>(f[(k + 2) % 3])] - o;
        if (const Vec3 n = e1.cross(e2); n.norm() > 1e-15) {
          normal += n.normalized();
          corners.emplace_back(e1, e2);
        }
      }
  if (!(normal.norm() > 1e-9)) return false;
  const Vec3 n = normal.normalized();
  const Vec3 p = d - d.dot(n) * n;
  if (p.norm() < 1e-6 * d.norm()) return false;
  for (const auto& [e1, e2] : corners) {
    const Vec3 a = e1 - e1.dot(n) * n, b = e2 - e2.dot(n) * n;
    if (a.cross(p).dot(n) >= 0.0 && p.cross(b).dot(n) >= 0.0) return true;
  }
  return false;
}

}  // namespace sketchlab::soapfilm
