#include "cycle_search.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "parallel_transport.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::soapfilm {
namespace {

// Clockwise angle in (0, 2π] from `from` to `to` around the unit normal n,
// both projected onto its plane; -1 when either projects to (nearly) zero.
double cw_angle(const Vec3& n, const Vec3& from, const Vec3& to) {
  const Vec3 a = from - n.dot(from) * n, b = to - n.dot(to) * n;
  if (a.norm() < 1e-9 || b.norm() < 1e-9 * std::max(1.0, to.norm())) return -1.0;
  double cw = -std::atan2(n.dot(a.cross(b)), a.dot(b));
  if (cw <= 1e-12) cw += 2.0 * std::numbers::pi;
  return cw;
}

Vec3 project(const Vec3& n, const Vec3& v) { return v - n.dot(v) * n; }

// A segment from a node back to itself (item 24: a cycle by itself).
bool is_loop(const GraphSegment& g) { return g.node0 == g.node1; }

}  // namespace

int next_clockwise(const Vec3& normal, const Vec3& incoming, const std::vector<Vec3>& candidates) {
  const Vec3 n = normal.normalized();
  int best = -1;
  double best_angle = INFINITY;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double a = cw_angle(n, incoming, candidates[i]);
    if (a >= 0.0 && a < best_angle) best_angle = a, best = static_cast<int>(i);
  }
  return best;
}

int next_clockwise(const Vec3& normal, const Leaving& incoming, const std::vector<Leaving>& candidates,
                   double tie_cos) {
  const Vec3 n = normal.normalized();
  const Vec3 ref = project(n, incoming.tangent).norm() > 1e-9 ? incoming.tangent : incoming.far;
  int best = -1;
  double best_angle = INFINITY;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const double a = cw_angle(n, ref, candidates[i].tangent);
    if (a >= 0.0 && a < best_angle) best_angle = a, best = static_cast<int>(i);
  }
  if (best < 0) return best;
  // Candidates leaving (nearly) along the best one: ordered by where they go.
  const Leaving& b = candidates[static_cast<std::size_t>(best)];
  if (b.far.norm() == 0.0) return best;
  int tied = best;
  double tied_angle = cw_angle(n, ref, b.far);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Leaving& c = candidates[i];
    if (static_cast<int>(i) == best || c.tangent.dot(b.tangent) <= tie_cos || c.far.norm() == 0.0) continue;
    const double a = cw_angle(n, ref, c.far);
    if (a >= 0.0 && (tied_angle < 0.0 || a < tied_angle)) tied_angle = a, tied = static_cast<int>(i);
  }
  return tied;
}

std::vector<int> cycle_key(const Cycle& cycle) {
  std::vector<int> key;
  for (const HalfEdge& h : cycle) key.push_back(h.segment);
  std::sort(key.begin(), key.end());
  return key;
}

Leaving CycleSearcher::leaving(HalfEdge h) const {
  const Vec3 chord = graph_->chord(h);
  return {graph_->direction(h), chord.norm() > 1e-12 ? Vec3(chord.normalized()) : Vec3::Zero()};
}

const NodeFrame& CycleSearcher::frame(NodeId node) {
  if (auto it = frames_.find(node); it != frames_.end()) return it->second;
  std::vector<Vec3> tangents, opposite;
  for (const HalfEdge& h : graph_->outgoing(node)) {
    const Leaving l = leaving(h);
    tangents.push_back(l.tangent);
    opposite.push_back(l.far);
  }
  return frames_.emplace(node, fit_node_frame(tangents, opposite, params_.frame)).first->second;
}

std::optional<HalfEdge> CycleSearcher::turn(HalfEdge in, Vec3& normal, Vec3* arrival, const HalfEdge* forced,
                                            bool carried) {
  const NodeId b = graph_->to(in);
  const std::vector<HalfEdge> outs = graph_->outgoing(b);
  if (outs.size() < 2) return std::nullopt;  // a dangling end (item 24)
  // Carry the normal to b along the segment (Bishop frame).
  const int n = std::max(2, static_cast<int>(std::ceil(graph_->span(in.segment) * params_.transport_steps)) + 1);
  const Vec3 transported =
      carried ? Vec3(normal.normalized())
              : parallel_transport(graph_->curve_of(in), graph_->parameters(in, n), in.forward, normal).normalized();
  if (arrival) *arrival = transported;
  std::vector<HalfEdge> cands;
  std::vector<Leaving> dirs;
  int forced_at = -1;
  for (const HalfEdge& h : outs)
    if (!(h == in.reversed())) {
      if (forced && h == *forced) forced_at = static_cast<int>(cands.size());
      cands.push_back(h);
      dirs.push_back(leaving(h));
    }
  if (forced && forced_at < 0) return std::nullopt;
  // The walk's own choice, or the forced one.
  const auto choose = [&](int pick) { return forced ? forced_at : pick; };
  const Leaving incoming = leaving(in.reversed());
  const NodeFrame& f = frame(b);
  if (params_.transport_through_two && outs.size() == 2) {
    // A node continuing one segment into one other (where two strokes meet
    // end to end): no choice, and its fitted normal is unreliable (with
    // collinear tangents it is the curves' binormal, across the surface).
    // The transported normal is carried across it. Not the app's rule
    // (README.md: measured).
    const std::size_t chosen = static_cast<std::size_t>(choose(0));
    normal = Eigen::Quaterniond::FromTwoVectors(-incoming.tangent, dirs[chosen].tangent) * transported;
    return cands[chosen];
  }
  if (!f.defined || f.sharp) {
    // Sharp node (§3.3.2.2, Fig. 3.16; item 24): sort around the transported
    // normal among the segments close to its plane (the best one if none
    // is), then carry the normal across the node by the rotation taking the
    // arriving direction to the leaving one.
    std::vector<std::size_t> kept;
    std::size_t closest = 0;
    double closest_len = -1.0;
    for (std::size_t i = 0; i < cands.size(); ++i) {
      const double len = project(transported, dirs[i].tangent).norm();
      if (!f.defined || len >= params_.sharp_projection) kept.push_back(i);
      if (len > closest_len) closest_len = len, closest = i;
    }
    if (kept.empty()) kept.push_back(closest);
    std::vector<Leaving> kept_dirs;
    for (std::size_t i : kept) kept_dirs.push_back(dirs[i]);
    // Item 23's order is around the node's normal; item 24's flip orients it.
    const Vec3 around = params_.sharp_node_order && f.defined
                            ? (f.normal.dot(transported) < 0.0 ? Vec3(-f.normal) : f.normal)
                            : transported;
    const int pick = next_clockwise(around, incoming, kept_dirs, params_.tie_cos);
    if (pick < 0 && !forced) return std::nullopt;
    const std::size_t chosen = forced ? static_cast<std::size_t>(forced_at) : kept[static_cast<std::size_t>(pick)];
    normal = Eigen::Quaterniond::FromTwoVectors(-incoming.tangent, dirs[chosen].tangent) * transported;
    return cands[chosen];
  }

  // Smooth node (Fig. 3.15): the node normal, flipped to agree with the
  // transported one.
  const double agreement = f.normal.dot(transported);
  normal = agreement < 0.0 ? Vec3(-f.normal) : f.normal;
  if (std::abs(agreement) < std::cos(params_.trim_angle)) {
    // Trim curve (§3.3.2.2, Fig. 3.18c; item 24): the node normal says little
    // about the way round; turn in the transported normal's plane, by the
    // tangents, or by the directions to the opposite nodes where a tangent
    // projects short.
    auto in_plane = [&](const Leaving& l) {
      Leaving p = l;
      if (project(transported, l.tangent).norm() < params_.sharp_projection && l.far.norm() > 0.0) p.tangent = l.far;
      return p;
    };
    std::vector<Leaving> planar;
    for (const Leaving& l : dirs) planar.push_back(in_plane(l));
    const int pick = choose(next_clockwise(transported, in_plane(incoming), planar, params_.tie_cos));
    if (pick < 0) return std::nullopt;
    // The node normal is oriented the way its own clockwise order makes the
    // same turn; when both ways do (or neither), it says nothing and the
    // transported normal goes on.
    const bool plus = next_clockwise(f.normal, incoming, dirs, params_.tie_cos) == pick;
    const bool minus = next_clockwise(-f.normal, incoming, dirs, params_.tie_cos) == pick;
    normal = plus == minus ? transported : plus ? f.normal : Vec3(-f.normal);
    return cands[static_cast<std::size_t>(pick)];
  }
  const int pick = choose(next_clockwise(normal, incoming, dirs, params_.tie_cos));
  if (pick < 0) return std::nullopt;
  return cands[static_cast<std::size_t>(pick)];
}

std::optional<Cycle> CycleSearcher::walk(HalfEdge start, const Vec3& start_normal, WalkTrace* trace,
                                         bool normal_at_end) {
  ++walks_;
  if (trace) *trace = {{start}, {}};
  if (is_loop(graph_->segment(start.segment))) return Cycle{start};
  Cycle cycle{start};
  std::set<int> used{start.segment};
  Vec3 normal = start_normal;
  Vec3 normal_sum = start_normal.normalized();
  HalfEdge cur = start;
  bool carried = normal_at_end;  // the first turn's normal is given at its node
  while (true) {
    check_budget();  // issue 17: the per-event time budget
    if (params_.close_rule == CloseRule::at_start_node && cycle.size() >= 2 && graph_->to(cur) == graph_->from(start))
      return cycle;
    Vec3 arrival = Vec3::Zero();
    const auto next = turn(cur, normal, trace ? &arrival : nullptr, nullptr, carried);
    carried = false;
    if (trace) trace->arrivals.push_back(arrival);
    if (!next) return std::nullopt;
    if (trace && !(*next == start)) trace->steps.push_back(*next);
    if (*next == start) {
      if (cycle.size() < 2) return std::nullopt;
      if (params_.reject_outer && winds_clockwise(cycle, normal_sum)) return std::nullopt;
      return cycle;
    }
    if (params_.close_rule == CloseRule::into_start_segment && next->segment == start.segment) {
      if (cycle.size() < 2) return std::nullopt;
      return cycle;
    }
    if (!used.insert(next->segment).second) return std::nullopt;
    if (params_.max_segments > 0 && static_cast<int>(cycle.size()) >= params_.max_segments) return std::nullopt;
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

std::vector<Cycle> CycleSearcher::search_segment(int segment, std::vector<WalkTrace>* traces) {
  std::vector<Cycle> out;
  WalkTrace trace;
  WalkTrace* t = traces ? &trace : nullptr;
  // A copy: frame() below may split more curves into graph segments, which
  // reallocates the graph's segment storage (ASan: heap-use-after-free).
  const GraphSegment g = graph_->segment(segment);
  if (is_loop(g)) {
    if (auto c = walk({segment, true}, Vec3::UnitZ(), t)) out.push_back(std::move(*c));
    if (traces) traces->push_back(trace);
    return out;
  }
  // From node0 unless it is sharp (or has no normal) and node1 is not.
  const NodeFrame& f0 = frame(g.node0);
  const NodeFrame f1 = frame(g.node1);
  const bool smooth0 = f0.defined && !f0.sharp, smooth1 = f1.defined && !f1.sharp;
  const bool from1 = (!smooth0 && smooth1) || (!f0.defined && f1.defined);
  // start_turn: the first turn is at the start node, with its normal as is.
  const HalfEdge start{segment, params_.start_turn ? from1 : !from1};
  const NodeFrame& f = from1 ? f1 : f0;
  Vec3 normal = f.normal;
  if (!f.defined) {
    // Neither end spans a plane (item 23), e.g. two curves closing a loop
    // through two smooth nodes. CASSIE's plane fit still gives one and its
    // walks close such loops; the segment's own plane (its tangent and its
    // chord at the start node) stands in for it.
    const Leaving l = leaving(HalfEdge{segment, !from1});
    normal = l.tangent.cross(l.far);
    if (normal.norm() < 1e-9) return out;
    normal.normalize();
  }
  for (const Vec3& n : {normal, Vec3(-normal)}) {
    if (auto c = walk(start, n, t, params_.start_turn)) out.push_back(std::move(*c));
    if (traces) traces->push_back(trace);
  }
  return out;
}

std::vector<Vec3> CycleSearcher::carried(const Cycle& cycle, const Vec3& start_normal) {
  std::vector<Vec3> out;
  Vec3 normal = start_normal;
  for (std::size_t i = 0; i < cycle.size(); ++i) {
    const HalfEdge& next = cycle[(i + 1) % cycle.size()];
    Vec3 arrival = Vec3::Zero();
    if (graph_->to(cycle[i]) != graph_->from(next) || !turn(cycle[i], normal, &arrival, &next)) return {};
    out.push_back(arrival);
  }
  return out;
}

bool CycleSearcher::between(HalfEdge in, HalfEdge out, HalfEdge h, const Vec3& normal) const {
  return next_clockwise(normal, leaving(in.reversed()), {leaving(out), leaving(h)}, params_.tie_cos) == 1;
}

}  // namespace sketchlab::soapfilm
