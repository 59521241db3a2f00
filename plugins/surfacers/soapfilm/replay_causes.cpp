#include "replay_causes.hpp"

#include <set>

#include "patch_upkeep.hpp"

namespace sketchlab::soapfilm {

MissingCycle classify_missing(const Network& network, const std::map<std::int64_t, CurveId>& curve_of,
                              const StrokeSet& strokes, const CycleSearchParams& params) {
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
  if (!found) return MissingCycle::not_found;
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
