#pragma once
// When a new segment breaks an existing patch (CASSIE app, item 25: "a patch
// breaks only if a new segment sits between two consecutive cycle segments
// at a node and reaches the cycle again within 5 two-segment nodes").
#include <set>
#include <vector>

#include "cycle_search.hpp"
#include "sketchlab/network_types.hpp"

namespace sketchlab::soapfilm {

// A patch boundary as a closed chain of half-edges of `graph`, in its order
// and direction (pieces split by later nodes give their graph segments in
// turn; pieces a deletion merged since give their one segment once). Empty
// when a piece has no graph segment or the half-edges do not chain.
Cycle cycle_of(CurveGraph& graph, const std::vector<OrientedSegment>& boundary);

// Item 25: whether one of the `fresh` graph segments (the edit's new ones)
// breaks `patch`, whose boundary covers the graph segments `key` (sorted,
// boundary_key). It must leave a node of the cycle on the patch's side and
// reach the cycle again through at most `params.break_reach` two-segment
// nodes. The side, with `params.break_by_order`: the new segment sits
// between the cycle's two consecutive segments at that node in the node's
// sorted order (item 23: clockwise around its normal, CycleSearcher::between)
// with the normal oriented by the cycle there. That orientation is the
// normal the walk carries round the cycle (CycleSearcher::carried) from the
// one of its start node's two normals for which more of the cycle's nodes
// have no older segment between the cycle's two (the walk that made it took
// the next one); on a tie, the one the cycle runs counter-clockwise around
// (the walk keeps its face on its left); and flipped at a node where only
// the flipped one has no older segment between. Without `break_by_order`
// (the default): it leaves into the fan of mesh triangles at the node
// (enters_patch). False when the boundary is no cycle of `graph`.
// `searcher` walks `graph`. `at`, when given and the patch is broken,
// receives the cycle's segments at the node the breaking segment leaves.
bool broken_by(CurveGraph& graph, CycleSearcher& searcher, const Patch& patch, const std::vector<int>& key,
               const std::set<int>& fresh, const CycleSearchParams& params, std::vector<int>* at = nullptr);

// Whether direction `d` leaving the boundary point `at` of a patch points
// into it: inside the corner, at the mesh vertex nearest `at`, of one of the
// triangles there (their union is the patch's side at that point). True for
// a patch without a mesh.
bool enters_patch(const Mesh& mesh, const Vec3& at, const Vec3& d);

}  // namespace sketchlab::soapfilm
