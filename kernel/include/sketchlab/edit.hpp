#pragma once
// A change to a Network. Correctors and surfacers return edits; only
// Network::apply changes a network, and it returns the inverse edit.
#include <optional>
#include <vector>

#include "sketchlab/network_types.hpp"

namespace sketchlab {

// Next ids a network hands out; restored by inverse edits so that undo then a
// new stroke allocates exactly the ids a fresh fold would.
struct IdCounters {
  CurveId next_curve = 1;
  NodeId next_node = 1;
  PatchId next_patch = 1;
  bool operator==(const IdCounters&) const = default;
};

struct Edit {
  std::vector<NetworkCurve> curves_added;     // ids not in the network
  std::vector<NetworkCurve> curves_replaced;  // ids in the network (oversketch, extend, merge)
  std::vector<CurveId> curves_removed;
  std::vector<Node> nodes_added;  // intersections
  std::vector<Node> nodes_replaced;
  std::vector<NodeId> nodes_removed;
  std::vector<Patch> patches_added;
  std::vector<PatchId> patches_removed;
  std::optional<IdCounters> counters;  // set on inverse edits

  bool empty() const {
    return curves_added.empty() && curves_replaced.empty() && curves_removed.empty() &&
           nodes_added.empty() && nodes_replaced.empty() && nodes_removed.empty() &&
           patches_added.empty() && patches_removed.empty() && !counters;
  }
  bool operator==(const Edit&) const = default;
};

}  // namespace sketchlab
