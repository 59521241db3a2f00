#include "replay_causes.hpp"

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

}  // namespace

MissingCycle classify_missing(const Network& network, const std::map<std::int64_t, CurveId>& curve_of,
                              const StrokeSet& strokes, const CycleSearchParams& params, Departure* departure) {
  if (departure) *departure = Departure::none;
  std::map<CurveId, std::int64_t> stroke_of;
  for (std::int64_t s : strokes) {
    const auto it = curve_of.find(s);
    if (it == curve_of.end() || !network.find_curve(it->second)) return MissingCycle::curve_absent;
    stroke_of[it->second] = s;
  }
  CurveGraph graph(network);
  CycleSearcher searcher(graph, params);
  std::set<int> seeds;
  for (const auto& [curve, s] : stroke_of)
    for (int seg : graph.segments_of(curve)) seeds.insert(seg);
  if (!closes_over(graph, stroke_of, seeds)) return MissingCycle::not_closed;
  std::optional<Cycle> found;
  // The longest stay on the patch's curves of the walks that do not close.
  std::size_t best_stay = 0;
  std::optional<NodeId> left_at;
  for (int seed : seeds) {
    std::vector<Cycle> traces;
    const std::vector<Cycle> closed = searcher.search_segment(seed, departure ? &traces : nullptr);
    for (const Cycle& t : traces) {
      std::size_t i = 0;
      while (i < t.size() && seeds.count(t[i].segment)) ++i;
      if (i < best_stay || (i == best_stay && left_at)) continue;
      best_stay = i;
      left_at = i < t.size() ? std::optional<NodeId>(graph.from(t[i])) : std::nullopt;
    }
    for (const Cycle& c : closed) {
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
    if (departure) {
      *departure = Departure::inside;
      if (left_at) {
        const NodeFrame& f = searcher.frame(*left_at);
        *departure = graph.outgoing(*left_at).size() == 2 ? Departure::at_two
                     : !f.defined                         ? Departure::at_undefined
                     : f.sharp                            ? Departure::at_sharp
                                                          : Departure::at_smooth;
      }
    }
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
  astray_at_two += o.astray_at_two;
  astray_at_sharp += o.astray_at_sharp;
  astray_at_smooth += o.astray_at_smooth;
  astray_at_undefined += o.astray_at_undefined;
  astray_inside += o.astray_inside;
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
