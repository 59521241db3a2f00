#include "replay_causes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "patch_upkeep.hpp"

namespace sketchlab::soapfilm {
namespace {

// Whether the graph segments `segments` of the curves in `stroke_of` can hold
// a closed path through every one of those curves: their 2-core (segments
// left after repeatedly removing those with an end no other segment of the
// set meets) is connected and covers every curve. Necessary for a cycle
// over exactly these strokes, whatever the walk does.
bool closes_over(const CurveGraph& graph, const std::map<CurveId, std::int64_t>& stroke_of,
                 const std::set<int>& segments) {
  std::set<int> core = segments;
  std::map<NodeId, int> degree;
  for (int s : core) {
    ++degree[graph.segment(s).node0];
    ++degree[graph.segment(s).node1];
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (auto it = core.begin(); it != core.end();) {
      const GraphSegment& g = graph.segment(*it);
      if (degree[g.node0] >= 2 && degree[g.node1] >= 2) {
        ++it;
        continue;
      }
      --degree[g.node0];
      --degree[g.node1];
      it = core.erase(it);
      changed = true;
    }
  }
  // Connected, by a union-find over the nodes.
  std::map<NodeId, NodeId> parent;
  const auto root = [&](NodeId n) {
    while (parent.count(n) && parent[n] != n) n = parent[n];
    return n;
  };
  for (int s : core) {
    const NodeId a = root(graph.segment(s).node0), b = root(graph.segment(s).node1);
    parent.try_emplace(a, a);
    parent.try_emplace(b, b);
    if (a != b) parent[a] = b;
  }
  std::set<CurveId> covered;
  std::set<NodeId> components;
  for (int s : core) {
    covered.insert(graph.segment(s).curve);
    components.insert(root(graph.segment(s).node0));
  }
  return covered.size() == stroke_of.size() && components.size() == 1;
}

// The cycles over `segments` (both directions, every start) through every
// curve of `curves`, at most `cap` of them: node-simple ones, or with
// `revisit` closed walks using each segment once and passing nodes more
// than once (item 24 allows revisits). A depth-first search; the patch's
// curves hold few segments.
std::vector<Cycle> cycles_over(CurveGraph& graph, const std::set<int>& segments, std::size_t curves, std::size_t cap,
                               bool revisit) {
  std::map<NodeId, std::vector<HalfEdge>> out_of;
  for (int s : segments) {
    out_of[graph.segment(s).node0].push_back({s, true});
    out_of[graph.segment(s).node1].push_back({s, false});
  }
  std::vector<Cycle> found;
  Cycle path;
  std::set<NodeId> nodes_on_path;
  std::set<int> segments_on_path;
  NodeId origin = 0;
  int budget = 100000;  // search steps, against a combinatorial blow-up
  const auto extend = [&](const auto& self, NodeId at) -> void {
    for (const HalfEdge& h : out_of[at]) {
      if (found.size() >= cap || --budget < 0) return;
      if (segments_on_path.count(h.segment)) continue;
      const NodeId next = graph.to(h);
      path.push_back(h);
      segments_on_path.insert(h.segment);
      if (next == origin) {
        std::set<CurveId> covered;
        for (const HalfEdge& e : path) covered.insert(graph.segment(e.segment).curve);
        if (covered.size() == curves) found.push_back(path);
      }
      if (next != origin || revisit) {
        if (revisit || nodes_on_path.insert(next).second) {
          self(self, next);
          if (!revisit) nodes_on_path.erase(next);
        }
      }
      segments_on_path.erase(h.segment);
      path.pop_back();
    }
  };
  for (const auto& [node, unused] : out_of) {
    origin = node;
    nodes_on_path = {node};
    extend(extend, node);
  }
  return found;
}

// Where our walks leave the cycles CASSIE may have walked over the patch's
// segments `seeds` (Departure).
AstrayDetail departure(CurveGraph& graph, CycleSearcher& searcher, const std::set<int>& seeds, std::size_t curves,
                       const CycleSearchParams& params) {
  AstrayDetail out;
  std::vector<Cycle> targets = cycles_over(graph, seeds, curves, 64, false);
  if (targets.empty()) targets = cycles_over(graph, seeds, curves, 64, true);
  if (targets.empty()) {
    out.where = Departure::no_cycle;
    return out;
  }
  std::map<int, std::vector<WalkTrace>> walked;
  const WalkTrace* best = nullptr;
  const Cycle* best_target = nullptr;
  std::size_t best_start = 0, best_len = 0;
  for (const Cycle& c : targets)
    for (std::size_t j = 0; j < c.size(); ++j) {
      auto it = walked.find(c[j].segment);
      if (it == walked.end()) {
        it = walked.emplace(c[j].segment, std::vector<WalkTrace>{}).first;
        searcher.search_segment(c[j].segment, &it->second);
      }
      for (const WalkTrace& t : it->second) {
        std::size_t m = 0;
        while (m < t.steps.size() && m < c.size() && t.steps[m] == c[(j + m) % c.size()]) ++m;
        if (m > best_len) best_len = m, best = &t, best_target = &c, best_start = j;
      }
    }
  out.length = best_target ? static_cast<int>(best_target->size()) : static_cast<int>(targets.front().size());
  out.followed = static_cast<int>(best_len);
  if (!best) {
    out.where = Departure::no_start;
    return out;
  }
  const Cycle& c = *best_target;
  const HalfEdge wanted = c[(best_start + best_len) % c.size()];
  const NodeId node = graph.from(wanted);
  out.node = node;
  if (const Node* n = graph.network().find_node(node)) out.position = n->position;
  out.segments = static_cast<int>(graph.outgoing(node).size());
  out.wanted = graph.segment(wanted.segment).curve;
  const NodeFrame& f = searcher.frame(node);
  out.max_offset = f.max_offset;
  const Vec3 carried = best_len - 1 < best->arrivals.size() ? best->arrivals[best_len - 1] : Vec3::Zero();
  if (f.defined && carried.norm() > 0.0) out.agreement = f.normal.dot(carried.normalized());
  const bool took = best_len < best->steps.size();
  const double cos_apart = took ? graph.direction(best->steps[best_len]).dot(graph.direction(wanted)) : 1.0;
  if (took) {
    out.taken = graph.segment(best->steps[best_len].segment).curve;
    out.apart = std::acos(std::clamp(cos_apart, -1.0, 1.0));
  }
  if (took && cos_apart > params.tie_cos)
    out.where = Departure::near_tie;
  else if (out.segments == 2)
    out.where = Departure::at_two;
  else if (!f.defined)
    out.where = Departure::at_undefined;
  else if (f.sharp)
    out.where = Departure::at_sharp;
  else if (std::abs(out.agreement) < std::cos(std::numbers::pi / 3))  // item 24's |cos| < 0.5
    out.where = Departure::at_crossing;
  else
    out.where = Departure::at_smooth;
  return out;
}

}  // namespace

MissingCycle classify_missing(const Network& network, const std::map<std::int64_t, CurveId>& curve_of,
                              const StrokeSet& strokes, const CycleSearchParams& params, AstrayDetail* astray) {
  if (astray) *astray = {};
  std::map<CurveId, std::int64_t> stroke_of;
  for (std::int64_t s : strokes) {
    const auto it = curve_of.find(s);
    if (it == curve_of.end() || !network.find_curve(it->second)) return MissingCycle::curve_absent;
    stroke_of[it->second] = s;
  }
  CurveGraph graph(network, params.closed_seam_nodes);
  CycleSearcher searcher(graph, params);
  std::set<int> seeds;
  for (const auto& [curve, s] : stroke_of)
    for (int seg : graph.segments_of(curve)) seeds.insert(seg);
  if (!closes_over(graph, stroke_of, seeds)) return MissingCycle::not_closed;
  std::optional<Cycle> found;
  for (int seed : seeds) {
    for (const Cycle& c : searcher.search_segment(seed)) {
      StrokeSet over;
      bool outside = false;
      for (const HalfEdge& h : c) {
        const auto it = stroke_of.find(graph.segment(h.segment).curve);
        if (it == stroke_of.end()) {
          outside = true;
          break;
        }
        over.insert(it->second);
      }
      if (!outside && over == strokes) found = c;
      if (found) break;
    }
    if (found) break;
  }
  if (!found) {
    if (astray) *astray = departure(graph, searcher, seeds, stroke_of.size(), params);
    return MissingCycle::not_found;
  }
  // Item 24: a segment already bounding two patches refuses the cycle (the
  // surfacer's default counts manual patches too).
  std::map<int, int> bounding;
  std::set<PatchId> patches;
  for (const HalfEdge& h : *found)
    for (PatchId p : network.patches_on(graph.segment(h.segment).curve)) patches.insert(p);
  for (PatchId p : patches) {
    const Patch& patch = network.patches().at(p);
    if (!patch.automatic && !params.manual_patches_count) continue;
    for (int seg : boundary_key(graph, patch.boundary)) ++bounding[seg];
  }
  for (const HalfEdge& h : *found)
    if (bounding[h.segment] >= 2) return MissingCycle::refused_two;
  return MissingCycle::not_searched;
}

ReplayCauses& ReplayCauses::operator+=(const ReplayCauses& o) {
  miss_elsewhere += o.miss_elsewhere;
  miss_curve_absent += o.miss_curve_absent;
  miss_not_closed += o.miss_not_closed;
  astray_near_tie += o.astray_near_tie;
  astray_at_two += o.astray_at_two;
  astray_at_undefined += o.astray_at_undefined;
  astray_at_sharp += o.astray_at_sharp;
  astray_at_crossing += o.astray_at_crossing;
  astray_at_smooth += o.astray_at_smooth;
  astray_no_start += o.astray_no_start;
  astray_no_cycle += o.astray_no_cycle;
  miss_not_found += o.miss_not_found;
  miss_refused_two += o.miss_refused_two;
  miss_not_searched += o.miss_not_searched;
  extra_elsewhere += o.extra_elsewhere;
  extra_by_hand += o.extra_by_hand;
  extra_other += o.extra_other;
  end_removed_by_crossing += o.end_removed_by_crossing;
  end_removed_other += o.end_removed_other;
  end_never_created += o.end_never_created;
  end_extra_by_hand += o.end_extra_by_hand;
  end_extra_cassie_gone += o.end_extra_cassie_gone;
  end_extra_other += o.end_extra_other;
  return *this;
}

}  // namespace sketchlab::soapfilm
