#pragma once
// The curve network as a graph for cycle search (CASSIE thesis §3.3.1):
// nodes are the network nodes where curves meet, edges are the pieces of
// curves between them. The kernel derives segments from every node; here a
// node that only continues one curve (all incidences on one curve at one t,
// e.g. what is left where a deleted curve used to meet it) is not a graph
// node, so the two pieces on either side merge back into one edge.
//
// Built lazily from a Network: only the curves a search touches are read,
// so a local search costs the same in a sketch of 100 or 10,000 curves.
#include <map>
#include <optional>
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

// A graph edge: curve piece [t0, t1] between graph nodes (t0 >= t1 wraps
// across the seam of a closed curve; t0 == t1 there is the whole loop).
struct GraphSegment {
  CurveId curve = 0;
  double t0 = 0.0, t1 = 0.0;
  NodeId node0 = 0, node1 = 0;
};

// A graph edge traversed from node0 to node1 (forward) or back.
struct HalfEdge {
  int segment = -1;  // index into CurveGraph::segment()
  bool forward = true;
  bool operator==(const HalfEdge&) const = default;
  HalfEdge reversed() const { return {segment, !forward}; }
};

class CurveGraph {
 public:
  // `closed_seam_nodes`: a closed curve's node at t = 0 stays a graph node
  // when other curves split the curve (CASSIE app, item 22: "a closed stroke
  // is one node", which its split keeps as a two-segment node; README.md,
  // twelfth round); unset, such a node is not a graph node.
  explicit CurveGraph(const Network& network, bool closed_seam_nodes = false)
      : network_(&network), closed_seam_nodes_(closed_seam_nodes) {}

  const Network& network() const { return *network_; }

  // Indices of the graph segments of `curve` in t order (empty for an
  // unknown curve or one with no graph node).
  const std::vector<int>& segments_of(CurveId curve);
  const GraphSegment& segment(int index) const { return segments_.at(static_cast<std::size_t>(index)); }

  // Whether `node` is a graph node (see above). False for unknown nodes.
  bool is_graph_node(NodeId node) const;

  // Half-edges leaving `node`, in (curve, t, direction) order.
  std::vector<HalfEdge> outgoing(NodeId node);

  NodeId from(HalfEdge h) const { return h.forward ? segment(h.segment).node0 : segment(h.segment).node1; }
  NodeId to(HalfEdge h) const { return h.forward ? segment(h.segment).node1 : segment(h.segment).node0; }
  const Curve& curve_of(HalfEdge h) const;

  // Unit tangent leaving from(h) into the segment (one-sided at joints).
  Vec3 direction(HalfEdge h) const;
  // to(h) minus from(h) positions (the segment's "main direction", thesis
  // Fig. 3.18c).
  Vec3 chord(HalfEdge h) const;
  // n >= 2 parameters along h from its start to its end (wrapping the seam).
  std::vector<double> parameters(HalfEdge h, int n) const;
  // Parameter span |t1 - t0| (wrapped) of a segment.
  double span(int segment) const;

  OrientedSegment oriented(HalfEdge h) const;

  // The graph segment of `curve` containing parameter t (closest one if t
  // is on none), or -1 when the curve has no graph segment.
  int segment_at(CurveId curve, double t);

  // Graph segments a kernel oriented segment (a patch boundary piece) lies
  // on, in t order: those it is a union of (stored under a coarser node set:
  // a curve crossed it since), else the one holding it (stored under a finer
  // node set: a deletion merged segments since). `wraps`, when given, tells
  // whether a piece of a closed curve is read across the seam.
  std::vector<int> covered_by(const OrientedSegment& piece, bool* wraps = nullptr);

 private:
  const Network* network_;
  bool closed_seam_nodes_ = false;
  std::vector<GraphSegment> segments_;
  std::map<CurveId, std::vector<int>> by_curve_;
};

// Position on the curve of a graph segment at fraction u in [0, 1] of its
// parameter span.
double wrap_parameter(const Curve& curve, double t);

}  // namespace sketchlab::soapfilm
