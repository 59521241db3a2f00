#pragma once
// Local cycle search (CASSIE CHI'21 §5.1, thesis §3.3.2.1, after Stanko et
// al. 2016): from a starting half-edge, walk the graph taking at each node
// the next segment in clockwise order around the node normal, the normal's
// orientation carried from node to node by parallel transport.
#include <map>
#include <optional>
#include <vector>

#include "curve_graph.hpp"
#include "node_frame.hpp"

namespace sketchlab::soapfilm {

struct CycleSearchParams {
  NodeFrameParams frame;
  // Thesis §3.3.2.2 "Trim curves": when the transported normal and the node
  // normal are this far apart (as lines, rad) the segment is taken for a trim
  // curve and the turn is decided by the segments' main directions.
  double trim_angle = 1.0471975511965976;  // π/3
  // Walks longer than this many segments are abandoned (keeps the search
  // local; CASSIE's walk is local by construction).
  int max_segments = 12;
  // The walk keeps the face on its left (it runs counter-clockwise around
  // the oriented normals). On an open sheet the same walk can also go round
  // the sheet's outer border, clockwise; such cycles are rejected when the
  // normals along the cycle agree on a direction (see README.md).
  bool reject_outer = true;
};

using Cycle = std::vector<HalfEdge>;

// Caches node frames for one graph.
class CycleSearcher {
 public:
  CycleSearcher(CurveGraph& graph, const CycleSearchParams& params) : graph_(&graph), params_(params) {}

  const NodeFrame& frame(NodeId node);

  // Walks from `start` with oriented normal `normal` at from(start). With
  // `check_start`, the cycle is accepted only if the turn at the start node
  // leads back into `start` (not done when the start node is sharp).
  std::optional<Cycle> walk(HalfEdge start, const Vec3& normal, bool check_start);

  // Cycles on both sides of a segment, searched from both of its end nodes
  // (Appendix B), in a fixed order; may contain the same cycle twice.
  std::vector<Cycle> search_segment(int segment);

  int walks() const { return walks_; }

 private:
  // Start normals for leaving along `start`: ± the node normal, or at a sharp
  // node the cross products with the neighbouring segments (CHI'21 §5.1).
  std::vector<std::pair<Vec3, bool>> start_normals(HalfEdge start);
  // Next half-edge at to(in) given the oriented normal carried along `in`.
  // Updates `normal` to the oriented normal at the node.
  std::optional<HalfEdge> turn(HalfEdge in, Vec3& normal);
  // Whether a closed walk runs clockwise around the mean of the normals it
  // used (`normal_sum`, one unit normal per node): the outer border.
  bool winds_clockwise(const Cycle& cycle, const Vec3& normal_sum) const;

  CurveGraph* graph_;
  CycleSearchParams params_;
  std::map<NodeId, NodeFrame> frames_;
  int walks_ = 0;
};

// Index of the first of `candidates` in clockwise order around `normal`
// after `incoming` (all directions leaving the same node), or -1. Directions
// (nearly) parallel to the normal are skipped.
int next_clockwise(const Vec3& normal, const Vec3& incoming, const std::vector<Vec3>& candidates);

// Canonical key of a cycle: its graph segments sorted (orientation and
// starting point ignored), for duplicate rejection.
std::vector<int> cycle_key(const Cycle& cycle);

}  // namespace sketchlab::soapfilm
