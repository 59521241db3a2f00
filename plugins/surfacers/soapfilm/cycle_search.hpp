#pragma once
// Local cycle search (CASSIE CHI'21 §5.1, thesis §3.3.2.1, after Stanko et
// al. 2016): from a starting half-edge, walk the graph taking at each node
// the next segment in clockwise order around the node normal, the normal's
// orientation carried from node to node by parallel transport. The rules are
// the CASSIE app's (items 23-25 of the reference, CycleDetection.DetectCycle,
// Graph.TryFindCycle): see README.md for each and where this differs.
#include <map>
#include <optional>
#include <vector>

#include "curve_graph.hpp"
#include "node_frame.hpp"

namespace sketchlab::soapfilm {

// Item 24's "closes when it returns into the start segment" read three ways
// (README.md, twelfth round): the turn takes the start half-edge again (the
// default); the turn takes the start segment either way (back along it from
// its far end: the segments walked, open at the start node, are the cycle);
// or the walk arrives back at the start node (whatever the turn there takes).
enum class CloseRule { into_start, into_start_segment, at_start_node };

// Item 25's "seeds from broken cycles first": which segments of a broken
// patch are searched first (README.md, twelfth round): one (its first
// piece's), all of them, or the cycle's segments at the node the breaking
// segment leaves.
enum class BrokenSeeds { one, all, at_break };

// A cycle whose patch the user deleted by hand (a DeletePatchEvent), found
// again while its curves stand (README.md, fourteenth round): made again
// (forget, the default); not made, read as the cycle item 25 says keeps its
// patch, so no new cycle for item 26 (not_remade); or not made and still one
// of the two cycles its segments may bound (item 24; counts). Both others
// measured worse; CASSIE's log re-makes 5 of the 65 its users deleted.
enum class HandDeleted { forget, not_remade, counts };

struct CycleSearchParams {
  NodeFrameParams frame;
  CloseRule close_rule = CloseRule::into_start;
  // Item 24 at a sharp node: the candidates (projection >= sharp_projection)
  // are ordered clockwise around the transported normal (the default), or,
  // set, in the node's own order (item 23: around its fitted normal) oriented
  // by the flip test (transported · node normal < 0 reverses it).
  bool sharp_node_order = false;
  BrokenSeeds broken_seeds = BrokenSeeds::one;
  HandDeleted hand_deleted = HandDeleted::forget;
  // Item 25's "two walks per new segment, from one end": the walk leaves the
  // start node along the segment (the default), or, set, begins by turning
  // at the start node with its own normal (the segment as the arrival) and
  // closes at the other end.
  bool start_turn = false;
  // Item 22 ("a closed stroke is one node with its segment attached
  // twice"): its seam node stays a graph node when other curves split it
  // (CurveGraph), as in CASSIE's exported graphs. Off: it makes more extra
  // patches than it matches (README.md, twelfth round).
  bool closed_seam_nodes = false;
  // Thesis §3.3.2.2 "Trim curves", item 24: when the transported normal and
  // the node normal are more than this apart (as lines, rad) the turn is
  // chosen in the plane of the transported normal. The app: π/3 (|cos| <
  // 0.5); the default π/2 turns the rule off, which agrees better with
  // CASSIE's own patches (README.md: measured).
  double trim_angle = 1.5707963267948966;  // π/2
  // Item 24: at a sharp node only segments whose unit tangent keeps at least
  // this much length projected onto the transported normal's plane are
  // candidates; in a trim turn, a tangent projecting shorter is replaced by
  // the direction towards the segment's opposite node.
  double sharp_projection = 0.7;
  // Item 23: two segments leaving a node in directions closer than this
  // (cosine) are ordered by the directions towards their opposite nodes.
  double tie_cos = 0.99;
  // Item 27: parallel-transport steps per cubic piece.
  int transport_steps = 20;
  // At a node with two segments the walk carries the transported normal
  // across (rotated from the arriving to the leaving tangent) instead of
  // taking the node's fitted normal. Not the app's rule; measured (README.md).
  bool transport_through_two = true;
  // Item 25: an existing patch breaks when a new segment leaves one of its
  // nodes into it and reaches the cycle again through at most this many
  // two-segment nodes.
  int break_reach = 5;
  // Item 25: "into it" read from the node's sorted neighbour order (the new
  // segment sits between the cycle's two consecutive segments there, on the
  // side the cycle turns through); unset (the default), from the patch's
  // mesh (the fan of triangles at that point), which agrees better with
  // CASSIE's patches (README.md: measured, eleventh round).
  bool break_by_order = false;
  // Item 24: a walk stops at a segment already bounding two patches; with
  // this unset only automatic patches count (thesis §3.3.2.2 read literally).
  bool manual_patches_count = true;
  // Item 25 ("two walks per new segment") read the other way: an old curve's
  // segments at a node the edit added on it (a new stroke crossing or ending
  // on it splits one of its segments in two) are new segments too, searched
  // after the new curves' own. Off: it also closes a cylinder's caps, which
  // CASSIE leaves to the user; a documented variant (README.md: measured).
  bool seed_split_segments = false;
  // Walks longer than this many segments are abandoned; 0: no limit (the
  // app's walk, item 24). A documented variant (README.md).
  int max_segments = 0;
  // The walk keeps the face on its left (it runs counter-clockwise around
  // the oriented normals). On an open sheet the same walk can also go round
  // the sheet's outer border, clockwise; with this set, such cycles are
  // rejected when the normals along the cycle agree on a direction. Not in
  // the app; a documented variant (README.md).
  bool reject_outer = false;
};

using Cycle = std::vector<HalfEdge>;

// What one walk did, closed or not (diagnostics: where a walk leaves the
// cycle it was expected to follow, and with which normal it got there).
struct WalkTrace {
  Cycle steps;                  // the half-edges walked, the start first
  std::vector<Vec3> arrivals;   // the normal carried to to(steps[i]), one per turn made
};

// A direction leaving a node along a segment: the unit tangent there, and
// the unit direction towards the segment's other node (zero for a loop).
struct Leaving {
  Vec3 tangent = Vec3::Zero();
  Vec3 far = Vec3::Zero();
};

// Caches node frames for one graph.
class CycleSearcher {
 public:
  CycleSearcher(CurveGraph& graph, const CycleSearchParams& params) : graph_(&graph), params_(params) {}

  const NodeFrame& frame(NodeId node);

  // Walks from `start` with oriented normal `normal` at from(start) (item
  // 24): at each node the next segment as in turn(); the walk fails at a node
  // with fewer than 2 segments or on a segment already in the cycle, and
  // closes when it turns back into `start` with at least 2 segments. A loop
  // segment is a cycle by itself (other closing rules: close_rule). Nodes may
  // be revisited.
  // `trace`, when given, receives what the walk did (WalkTrace). With
  // `normal_at_end`, `normal` is the one at to(start), where the first turn
  // takes it as it is (CycleSearchParams::start_turn).
  std::optional<Cycle> walk(HalfEdge start, const Vec3& normal, WalkTrace* trace = nullptr,
                            bool normal_at_end = false);

  // The two walks of a segment (item 25), one with each orientation of the
  // normal at its start node: node0, unless node0 is sharp (or has no
  // normal) and node1 is not. When neither node spans a plane (item 23), the
  // normal of the segment's own plane at node0 (its tangent × its chord);
  // none when that is degenerate too (a straight segment). May return the
  // same cycle twice.
  // `traces`, when given, receives the trace of each walk (see walk()).
  std::vector<Cycle> search_segment(int segment, std::vector<WalkTrace>* traces = nullptr);

  // The normals the walk carries round `cycle` (a closed chain of
  // half-edges) from `normal` at from(cycle[0]), each turn forced onto the
  // cycle's next half-edge: element i is the unit normal carried to
  // to(cycle[i]) (item 25 needs the cycle's orientation at its nodes).
  // Empty when a step is not a turn of this graph.
  std::vector<Vec3> carried(const Cycle& cycle, const Vec3& normal);

  // Whether `h`, leaving to(in), comes strictly before `out` in clockwise
  // order around `normal` from the arriving segment (item 23's order, tie
  // rule included): between the cycle segments `in` and `out` on the side
  // the cycle turns through.
  bool between(HalfEdge in, HalfEdge out, HalfEdge h, const Vec3& normal) const;

  int walks() const { return walks_; }

  // Whether a closed walk runs clockwise around the mean of the normals it
  // used (`normal_sum`, one unit normal per node): the outer border. False
  // when those normals disagree (|normal_sum| < half the node count).
  bool winds_clockwise(const Cycle& cycle, const Vec3& normal_sum) const;

 private:
  Leaving leaving(HalfEdge h) const;
  // Next half-edge at to(in) given the oriented normal carried along `in`.
  // Updates `normal` to the oriented normal leaving the node; `arrival`,
  // when given, receives the normal carried to the node.
  // With `forced` (a half-edge leaving that node) the turn takes it instead
  // of its own choice and carries the normal accordingly. With `carried`,
  // `normal` is already the one at to(in) (not transported along `in`).
  std::optional<HalfEdge> turn(HalfEdge in, Vec3& normal, Vec3* arrival = nullptr, const HalfEdge* forced = nullptr,
                               bool carried = false);

  CurveGraph* graph_;
  CycleSearchParams params_;
  std::map<NodeId, NodeFrame> frames_;
  int walks_ = 0;
};

// Index of the first of `candidates` in clockwise order around `normal`
// after `incoming` (all directions leaving the same node), or -1. Directions
// (nearly) parallel to the normal are skipped.
int next_clockwise(const Vec3& normal, const Vec3& incoming, const std::vector<Vec3>& candidates);

// The same with the app's tie rule (item 23): among candidates leaving
// within `tie_cos` of the first one found, the one whose opposite node comes
// first clockwise is taken.
int next_clockwise(const Vec3& normal, const Leaving& incoming, const std::vector<Leaving>& candidates,
                   double tie_cos);

// Canonical key of a cycle: its graph segments sorted (orientation and
// starting point ignored), for duplicate rejection.
std::vector<int> cycle_key(const Cycle& cycle);

}  // namespace sketchlab::soapfilm
