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
#include <optional>
#include <set>
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
  // Each step is checked against the state the previous steps left (so a
  // curve removed in step 3 may be re-added under its id in step 5), and the
  // result must keep the invariants above: incidences and patch boundaries
  // (including existing ones on a replaced curve) within [0, t_max] of an
  // existing curve, keypoint and normal t within range, finite positions,
  // mesh faces indexing existing vertices. Ids are >= 1; a node has at least
  // one incidence. The message names the edit field, index and id
  // ("Network::apply: curves_removed[1]: curve 17 does not exist").
  // Counters: set to edit.counters when present (inverse edits; must exceed
  // every id left), else advanced to max(id)+1 of the items added. The
  // returned inverse always carries the old counters.
  Edit apply(const Edit& edit);

  // Segments: the pieces of each curve between consecutive nodes on it, in
  // (curve id, t) order. Pieces between a curve end and its first node are
  // not segments (they are dangling), and neither are zero-length pieces
  // between two nodes at the same t. On a closed curve t_max is the same
  // point as 0 (a node there is listed at t = 0) and the last segment wraps
  // from the last node across the seam to the first: t0 >= t1, and t0 == t1
  // when a single node (or several at one t) closes the whole loop; a wrap
  // that ends exactly at the seam is stored as [t0, t_max] instead.
  // segments_of throws std::invalid_argument for an unknown curve.
  std::vector<Segment> segments() const;
  std::vector<Segment> segments_of(CurveId curve) const;

  // Patches with at least one boundary piece on `curve`, ascending ids; empty
  // for an unknown curve or one that bounds no patch. Answered from a map kept
  // by apply (cost O(log curves + result), not a scan of the patches).
  std::vector<PatchId> patches_on(CurveId curve) const;

  // Proximity queries, answered from a spatial index (not a scan). Results
  // hold every item within distance r (inclusive), sorted by distance, ties by
  // id. Distances are exact (closest point on the curve), r >= 0 in metres.
  // Throw std::invalid_argument for a negative or non-finite r, a
  // non-finite point, or an empty polyline.
  std::vector<CurveHit> curves_near(const Vec3& p, double r) const;
  // Curves with some point within r of the polyline; the hit is the closest
  // pair (t on the curve).
  std::vector<CurveHit> curves_near_polyline(const std::vector<Vec3>& polyline, double r) const;
  std::vector<KeypointHit> keypoints_near(const Vec3& p, double r) const;
  std::vector<NodeHit> nodes_near(const Vec3& p, double r) const;

  // Structural equality (curves, nodes, patches, counters).
  bool operator==(const Network& other) const;

 private:
  // The stages of apply() (network_apply.cpp), one private function per step.
  friend class NetworkApplier;
  // Mutators keeping the reverse maps below in sync (apply and its rollback
  // are their only callers).
  void put_curve(const NetworkCurve& curve);
  void erase_curve(CurveId id);
  void put_node(const Node& node);
  void erase_node(NodeId id);
  void put_patch(const Patch& patch);
  void erase_patch(PatchId id);
  void index_curve(CurveId id, const std::optional<NetworkCurve>& old_curve);
  void index_node(NodeId id, const std::optional<Node>& old_node);

  std::map<CurveId, NetworkCurve> curves_;
  std::map<NodeId, Node> nodes_;
  std::map<PatchId, Patch> patches_;
  IdCounters counters_;
  // Derived: which nodes have an incidence on a curve, which patches have a
  // boundary piece on it (so removing or replacing a curve does not scan).
  std::map<CurveId, std::set<NodeId>> nodes_on_curve_;
  std::map<CurveId, std::set<PatchId>> patches_on_curve_;
  std::unique_ptr<SpatialIndex> index_;
};

}  // namespace sketchlab
