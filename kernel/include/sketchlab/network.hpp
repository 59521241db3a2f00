#pragma once
// The curve network: curves, nodes where they meet, the segments between
// nodes, and patches bounded by segment cycles.
//
// Invariants (kept by apply, which is the only mutator):
//  - every node incidence references an existing curve, with t in [0, t_max];
//  - every patch boundary references existing curves;
//  - ids are unique and below the counters;
//  - the spatial index covers exactly the current curves, nodes and keypoints.
#include <map>
#include <memory>
#include <vector>

#include "sketchlab/edit.hpp"
#include "sketchlab/network_types.hpp"

namespace sketchlab {

class SpatialIndex;

struct CurveHit {
  CurveId curve = 0;
  double t = 0.0;     // closest parameter on the curve
  Vec3 point;         // closest point on the curve
  double distance = 0.0;
};

struct KeypointHit {
  CurveId curve = 0;
  int keypoint = 0;  // index into NetworkCurve::keypoints
  Vec3 position;
  double distance = 0.0;
};

struct NodeHit {
  NodeId node = 0;
  double distance = 0.0;
};

class Network {
 public:
  Network();
  ~Network();
  Network(const Network&);
  Network& operator=(const Network&);
  Network(Network&&) noexcept;
  Network& operator=(Network&&) noexcept;

  const std::map<CurveId, NetworkCurve>& curves() const { return curves_; }
  const std::map<NodeId, Node>& nodes() const { return nodes_; }
  const std::map<PatchId, Patch>& patches() const { return patches_; }
  const IdCounters& counters() const { return counters_; }

  const NetworkCurve* find_curve(CurveId id) const;
  const Node* find_node(NodeId id) const;

  // Ids a new edit should use (the i-th new curve gets next_curve_id() + i).
  CurveId next_curve_id() const { return counters_.next_curve; }
  NodeId next_node_id() const { return counters_.next_node; }
  PatchId next_patch_id() const { return counters_.next_patch; }

  // Applies `edit` and returns its inverse: apply(inverse) restores this
  // network exactly (operator== holds, counters included).
  // Order: patches removed, nodes removed, curves removed (their incidences
  // are stripped from nodes, nodes left without incidence are removed, and
  // patches bounded by them are removed), curves replaced, curves added,
  // nodes replaced, nodes added, patches added.
  // Throws std::invalid_argument (network unchanged) when the edit references
  // a missing id, reuses an existing one, or holds an invalid curve.
  Edit apply(const Edit& edit);

  // Segments: the pieces of each curve between consecutive nodes on it, in
  // (curve id, t) order. Pieces between a curve end and its first node are
  // not segments (they are dangling).
  std::vector<Segment> segments() const;
  std::vector<Segment> segments_of(CurveId curve) const;

  // Proximity queries, answered from a spatial index (not a scan). Results
  // hold every item within distance r (inclusive), sorted by distance, ties by
  // id. Distances are exact (closest point on the curve), r >= 0 in metres.
  std::vector<CurveHit> curves_near(const Vec3& p, double r) const;
  // Curves with some point within r of the polyline; the hit is the closest
  // pair (t on the curve).
  std::vector<CurveHit> curves_near_polyline(const std::vector<Vec3>& polyline, double r) const;
  std::vector<KeypointHit> keypoints_near(const Vec3& p, double r) const;
  std::vector<NodeHit> nodes_near(const Vec3& p, double r) const;

  // Structural equality (curves, nodes, patches, counters).
  bool operator==(const Network& other) const;

 private:
  std::map<CurveId, NetworkCurve> curves_;
  std::map<NodeId, Node> nodes_;
  std::map<PatchId, Patch> patches_;
  IdCounters counters_;
  std::unique_ptr<SpatialIndex> index_;
};

}  // namespace sketchlab
