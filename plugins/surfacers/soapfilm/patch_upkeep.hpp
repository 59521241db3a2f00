#pragma once
// Patch upkeep after an edit (CASSIE thesis Appendix B), computed from the
// sketch and the edit alone (no state kept between edits):
//  - new segments: the graph segments of added or replaced curves and those
//    ending at added or replaced nodes (segments split by a new node);
//  - cycles possibly crossed: existing patches with a boundary piece on a
//    curve that received a new node inside that piece. A patch is crossed when
//    a new segment joins two nodes of its boundary without being part of it;
//    it is removed and one of its segments searched again;
//  - deletions: the kernel removes patches bounded by a deleted curve; the
//    segments at the nodes the deleted curve touched (read from the edits in
//    the sketch's history) are searched again;
//  - local cycle searches from both ends of each new segment; duplicates of
//    existing or already found cycles are rejected, and so are cycles using a
//    segment that already bounds two automatic patches (thesis §3.3.2.2).
// The cost is local: the graph (CurveGraph) is built lazily for the curves the
// seeds and walks reach, and the patches on a curve come from the kernel's
// Network::patches_on, so neither the curve list nor the patch list is
// scanned (only a deletion reads the history, back to the deleted curves'
// creation).
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
