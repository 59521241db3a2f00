#include "cycle_search.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "parallel_transport.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::soapfilm {
namespace {

// Transport samples per unit of curve parameter (one cubic piece).
constexpr int samples_per_piece = 8;

}  // namespace

int next_clockwise(const Vec3& normal, const Vec3& incoming, const std::vector<Vec3>& candidates) {
  const Vec3 n = normal.normalized();
  const Vec3 in = incoming - n.dot(incoming) * n;
  if (in.norm() < 1e-9) return -1;
  int best = -1;
  double best_angle = INFINITY;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Vec3 d = candidates[i] - n.dot(candidates[i]) * n;
    if (d.norm() < 1e-9 * std::max(1.0, candidates[i].norm())) continue;
    // Counter-clockwise angle from `in` to d around n, then clockwise.
    const double ccw = std::atan2(n.dot(in.cross(d)), in.dot(d));
    double cw = -ccw;
    if (cw <= 1e-12) cw += 2.0 * std::numbers::pi;
    if (cw < best_angle) best_angle = cw, best = static_cast<int>(i);
  }
  return best;
}

std::vector<int> cycle_key(const Cycle& cycle) {
  std::vector<int> key;
  for (const HalfEdge& h : cycle) key.push_back(h.segment);
  std::sort(key.begin(), key.end());
  return key;
}

const NodeFrame& CycleSearcher::frame(NodeId node) {
  if (auto it = frames_.find(node); it != frames_.end()) return it->second;
  std::vector<Vec3> dirs;
  for (const HalfEdge& h : graph_->outgoing(node)) dirs.push_back(graph_->direction(h));
  return frames_.emplace(node, fit_node_frame(dirs, params_.frame)).first->second;
}

std::optional<HalfEdge> CycleSearcher::turn(HalfEdge in, Vec3& normal) {
  const NodeId b = graph_->to(in);
  // Carry the normal to b along the segment (Bishop frame).
  const int n = std::max(2, static_cast<int>(std::ceil(graph_->span(in.segment) * samples_per_piece)) + 1);
  const Vec3 transported =
      parallel_transport(graph_->curve_of(in), graph_->parameters(in, n), in.forward, normal).normalized();
  std::vector<HalfEdge> cands;
  for (const HalfEdge& h : graph_->outgoing(b))
    if (!(h == in.reversed())) cands.push_back(h);
  if (cands.empty()) return std::nullopt;
  const Vec3 incoming = graph_->direction(in.reversed());
  std::vector<Vec3> dirs;
  for (const HalfEdge& h : cands) dirs.push_back(graph_->direction(h));

  const NodeFrame& f = frame(b);
  if (!f.defined || f.sharp) {
    // Sharp node (§3.3.2.2, Fig. 3.16): sort around the transported normal,
    // excluding segments far from its plane.
    const double limit = std::cos(0.5 * std::numbers::pi - params_.frame.sharp_angle);
    std::vector<HalfEdge> kept;
    std::vector<Vec3> kept_dirs;
    for (std::size_t i = 0; i < cands.size(); ++i)
      if (!f.sharp || std::abs(transported.dot(dirs[i])) <= limit) {
        kept.push_back(cands[i]);
        kept_dirs.push_back(dirs[i]);
      }
    const int pick = next_clockwise(transported, incoming, kept_dirs);
    if (pick < 0) return std::nullopt;
    normal = transported;
    return kept[static_cast<std::size_t>(pick)];
  }

  const double agreement = f.normal.dot(transported);
  if (std::abs(agreement) < std::cos(params_.trim_angle)) {
    // Trim curve (§3.3.2.2, Fig. 3.18c): the transported normal says nothing
    // about the orientation at b; choose the turn from the segments' main
    // directions projected on the plane of the transported normal, then
    // orient the node normal so that its clockwise order agrees.
    std::vector<Vec3> chords;
    for (const HalfEdge& h : cands) chords.push_back(graph_->chord(h));
    const int pick = next_clockwise(transported, graph_->chord(in.reversed()), chords);
    if (pick >= 0) {
      const int plus = next_clockwise(f.normal, incoming, dirs);
      const int minus = next_clockwise(-f.normal, incoming, dirs);
      if (plus == pick && minus != pick) {
        normal = f.normal;
        return cands[static_cast<std::size_t>(pick)];
      }
      if (minus == pick && plus != pick) {
        normal = -f.normal;
        return cands[static_cast<std::size_t>(pick)];
      }
    }
  }
  // Smooth node (Fig. 3.15): flip the node normal to agree with the
  // transported one, then take the next segment clockwise.
  normal = agreement < 0.0 ? Vec3(-f.normal) : f.normal;
  const int pick = next_clockwise(normal, incoming, dirs);
  if (pick < 0) return std::nullopt;
  return cands[static_cast<std::size_t>(pick)];
}

std::optional<Cycle> CycleSearcher::walk(HalfEdge start, const Vec3& start_normal, bool check_start) {
  ++walks_;
  const NodeId a = graph_->from(start);
  Cycle cycle{start};
  std::set<NodeId> visited{a};
  std::set<int> used{start.segment};
  Vec3 normal = start_normal;
  Vec3 normal_sum = start_normal.normalized();
  HalfEdge cur = start;
  while (true) {
    check_budget();  // issue 17: the per-event time budget
    const NodeId b = graph_->to(cur);
    if (b == a) {
      if (check_start) {
        Vec3 n = normal;
        const auto next = turn(cur, n);
        if (!next || !(*next == start)) return std::nullopt;
      }
      if (params_.reject_outer && winds_clockwise(cycle, normal_sum)) return std::nullopt;
      return cycle;
    }
    if (!visited.insert(b).second) return std::nullopt;
    if (static_cast<int>(cycle.size()) >= params_.max_segments) return std::nullopt;
    const auto next = turn(cur, normal);
    if (!next || !used.insert(next->segment).second) return std::nullopt;
    cycle.push_back(*next);
    normal_sum += normal.normalized();
    cur = *next;
  }
}

bool CycleSearcher::winds_clockwise(const Cycle& cycle, const Vec3& normal_sum) const {
  // Normals that disagree (a tube's cap: radial normals all round) give no
  // reference direction; nothing is rejected then.
  if (normal_sum.norm() < 0.5 * static_cast<double>(cycle.size())) return false;
  Vec3 area = Vec3::Zero();
  std::vector<Vec3> pts;
  for (const HalfEdge& h : cycle) {
    const Curve& c = graph_->curve_of(h);
    const std::vector<double> t = graph_->parameters(h, 5);
    for (std::size_t i = 0; i + 1 < t.size(); ++i) pts.push_back(evaluate(c, t[i]));
  }
  for (std::size_t i = 0; i < pts.size(); ++i) area += pts[i].cross(pts[(i + 1) % pts.size()]);
  return area.dot(normal_sum) < 0.0;
}

std::vector<std::pair<Vec3, bool>> CycleSearcher::start_normals(HalfEdge start) {
  std::vector<std::pair<Vec3, bool>> out;
  const NodeId a = graph_->from(start);
  const NodeFrame& f = frame(a);
  if (f.defined && !f.sharp) {
    out.emplace_back(f.normal, true);
    out.emplace_back(-f.normal, true);
    return out;
  }
  // Sharp start (CHI'21 §5.1, Fig. 8): sort the segments around the best-fit
  // normal; for the pairs (start, neighbour) the starting normal is their
  // cross product, oriented so that the cycle turns from start to neighbour.
  const std::vector<HalfEdge> all = graph_->outgoing(a);
  const Vec3 d0 = graph_->direction(start);
  std::vector<Vec3> others;
  for (const HalfEdge& h : all)
    if (!(h == start)) others.push_back(graph_->direction(h));
  if (others.empty()) return out;
  // At a corner whose tangents fill space the best-fit plane is ill defined
  // (a cube corner: any plane fits equally); the mean tangent direction then
  // gives a better axis to order the segments around.
  Vec3 axis = f.defined ? f.normal : Vec3::Zero();
  Vec3 mean = d0;
  for (const Vec3& d : others) mean += d;
  mean /= static_cast<double>(others.size() + 1);
  if (mean.norm() > 0.3) axis = mean.normalized();
  if (axis.norm() == 0.0) {
    for (const Vec3& d : others)
      if (d0.cross(d).norm() > 1e-6) {
        axis = d0.cross(d).normalized();
        break;
      }
  }
  if (axis.norm() == 0.0) return out;
  // Clockwise and counter-clockwise neighbours of `start` around the axis.
  const int cw = next_clockwise(axis, d0, others);
  const int ccw = next_clockwise(-axis, d0, others);
  std::vector<int> pairs{cw, ccw};
  // Degenerate order (both neighbours the same, or none): pair with all.
  if (cw < 0 || ccw < 0 || cw == ccw) {
    pairs.clear();
    for (std::size_t i = 0; i < others.size(); ++i) pairs.push_back(static_cast<int>(i));
  }
  for (int idx : pairs) {
    if (idx < 0) continue;
    const Vec3 c = d0.cross(others[static_cast<std::size_t>(idx)]);
    if (c.norm() < 1e-6) continue;
    // The walk turns clockwise around its normal, i.e. the cycle runs
    // counter-clockwise: leaving along d0 and closing through the neighbour
    // means turning from d0 towards it counter-clockwise, so normal d0 × d.
    out.emplace_back(c.normalized(), false);
  }
  return out;
}

std::vector<Cycle> CycleSearcher::search_segment(int segment) {
  std::vector<Cycle> out;
  for (bool forward : {true, false}) {
    const HalfEdge start{segment, forward};
    for (const auto& [normal, check] : start_normals(start))
      if (auto c = walk(start, normal, check)) out.push_back(std::move(*c));
  }
  return out;
}

}  // namespace sketchlab::soapfilm
