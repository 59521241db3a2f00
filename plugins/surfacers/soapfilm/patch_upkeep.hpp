#pragma once
// Patch upkeep after an edit (CASSIE thesis Appendix B, and the CASSIE app's
// Graph.TryFindAllCycles, items 25 and 27), computed from the sketch and the
// edit alone (no state kept between edits):
//  - new segments: the graph segments of added or replaced curves (and those
//    at an added node that is on no new curve);
//  - patches possibly broken: those on a replaced curve (stale geometry), and
//    those whose cycle passes through a node of a new segment and that a new
//    segment breaks (item 25, patch_break.hpp). A broken patch is removed
//    and one of its segments searched again, first;
//  - deletions: the kernel removes patches bounded by a deleted curve; the
//    segments left of those patches (broken cycles' seeds, searched first,
//    item 25) and the segments at the nodes the deleted curve touched (both
//    read from the edits in the sketch's history) are searched again;
//  - two walks per seed (CycleSearcher::search_segment); a cycle over the
//    segments of an existing patch is a duplicate, and a broken patch whose
//    cycle is found again over the same pieces of curve (split or not by the
//    edit's nodes) keeps its identity; a cycle over a
//    segment that already bounds two patches is refused (item 24; thesis
//    §3.3.2.2).
// The cost is local: the graph (CurveGraph) is built lazily for the curves the
// seeds and walks reach, and the patches on a curve come from the kernel's
// Network::patches_on, so neither the curve list nor the patch list is
// scanned (only a deletion reads the history, back to the deleted curves'
// creation; with CycleSearchParams::hand_deleted set, an edit whose walks
// closed reads the history's patch deletions by hand).
#include <map>
#include <string>
#include <vector>

#include "cycle_search.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::soapfilm {

struct UpkeepResult {
  std::vector<std::vector<OrientedSegment>> cycles_added;  // in discovery order
  std::vector<PatchId> patches_removed;                    // ascending
  int seeds = 0;           // segments searched
  int walks = 0;           // walks started
  int cycles_found = 0;    // walks that closed (before duplicate rejection)
  int rejected_duplicate = 0, rejected_manifold = 0;
  int patches_broken = 0;  // existing patches crossed by a new segment
  double walk_ms = 0.0;  // wall time of the walks (not deterministic; statistics only)
};

UpkeepResult patch_upkeep(const Sketch& sketch, const Edit& last, const CycleSearchParams& params);

// Cycles found when every graph segment of the network is searched, in
// (curve id, t) order: the detection run on a whole network (used to
// compare with CASSIE's own patches). Existing patches are ignored.
std::vector<std::vector<OrientedSegment>> detect_all_cycles(const Network& network,
                                                            const CycleSearchParams& params,
                                                            UpkeepResult* stats = nullptr);

// The graph segments (sorted, as indices into `graph`) a patch boundary
// covers; empty when a piece no longer matches the graph.
std::vector<int> boundary_key(CurveGraph& graph, const std::vector<OrientedSegment>& boundary);

}  // namespace sketchlab::soapfilm
