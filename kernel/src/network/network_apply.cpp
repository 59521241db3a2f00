// Network::apply: the only mutator. The edit is applied step by step in the
// documented order while the first-seen state of every touched curve, node
// and patch is journaled; any failed check (or any exception) rolls the
// journal back, which gives the strong guarantee without copying the
// network. The inverse edit is the difference between the journaled and the
// final state of the touched items, so its size is that of the change.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "sketchlab/network.hpp"
#include "spatial_index.hpp"

namespace sketchlab {

namespace {

std::string where(const char* field, std::size_t index) {
  return std::string(field) + "[" + std::to_string(index) + "]";
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("Network::apply: " + what); }

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool in_range(double t, double t_max) { return std::isfinite(t) && t >= 0.0 && t <= t_max; }

// Checks what can be checked on the curve record alone.
void check_curve(const NetworkCurve& nc, const std::string& at) {
  const std::string id = " (curve " + std::to_string(nc.id) + ")";
  if (nc.id == 0) fail(at + ": curve id 0 is reserved (ids start at 1)");
  if (const std::string why = validate(nc.curve); !why.empty()) fail(at + id + ": " + why);
  const double t_max = nc.curve.t_max();
  for (std::size_t i = 0; i < nc.keypoints.size(); ++i) {
    const Keypoint& k = nc.keypoints[i];
    if (!in_range(k.t, t_max))
      fail(at + id + ": keypoints[" + std::to_string(i) + "].t = " + num(k.t) + " is outside [0, " + num(t_max) + "]");
    if (!k.position.allFinite()) fail(at + id + ": keypoints[" + std::to_string(i) + "].position is not finite");
  }
  for (std::size_t i = 0; i < nc.normals.size(); ++i) {
    const CurveNormal& n = nc.normals[i];
    if (!in_range(n.t, t_max))
      fail(at + id + ": normals[" + std::to_string(i) + "].t = " + num(n.t) + " is outside [0, " + num(t_max) + "]");
    if (!n.normal.allFinite()) fail(at + id + ": normals[" + std::to_string(i) + "].normal is not finite");
  }
}

void check_node_record(const Node& node, const std::string& at) {
  const std::string id = " (node " + std::to_string(node.id) + ")";
  if (node.id == 0) fail(at + ": node id 0 is reserved (ids start at 1)");
  if (!node.position.allFinite()) fail(at + id + ": position is not finite");
  if (node.incidences.empty()) fail(at + id + ": a node needs at least one incidence");
}

void check_patch_record(const Patch& patch, const std::string& at) {
  const std::string id = " (patch " + std::to_string(patch.id) + ")";
  if (patch.id == 0) fail(at + ": patch id 0 is reserved (ids start at 1)");
  if (patch.boundary.empty()) fail(at + id + ": boundary is empty");
  const auto n = static_cast<long>(patch.mesh.vertices.size());
  for (std::size_t i = 0; i < patch.mesh.vertices.size(); ++i)
    if (!patch.mesh.vertices[i].allFinite())
      fail(at + id + ": mesh vertex " + std::to_string(i) + " is not finite");
  for (std::size_t f = 0; f < patch.mesh.faces.size(); ++f)
    for (int v : patch.mesh.faces[f])
      if (v < 0 || v >= n)
        fail(at + id + ": mesh face " + std::to_string(f) + " indexes vertex " + std::to_string(v) + " of " +
             std::to_string(n));
  if (!patch.mesh.normals.empty() && patch.mesh.normals.size() != patch.mesh.vertices.size())
    fail(at + id + ": mesh has " + std::to_string(patch.mesh.normals.size()) + " normals for " +
         std::to_string(n) + " vertices");
}

}  // namespace

// One application of an edit: the stages of Network::apply, in the step
// order of edit.hpp, over the journal of first-seen states.
class NetworkApplier {
 public:
  NetworkApplier(Network& net, const Edit& edit) : net_(net), edit_(edit), old_counters_(net.counters_) {}

  Edit run() {
    if (!net_.index_) net_.index_ = std::make_unique<SpatialIndex>();
    try {
      remove_patches();   // 1
      remove_nodes();     // 2
      remove_curves();    // 3
      replace_curves();   // 4
      add_curves();       // 5
      replace_nodes();    // 6
      add_nodes();        // 7
      add_patches();      // 8
      check_touched();
      update_counters();
      reindex();
    } catch (...) {
      roll_back();
      throw;
    }
    return inverse();
  }

 private:
  void touch_curve(CurveId id) {
    if (old_curves_.count(id)) return;
    const NetworkCurve* c = net_.find_curve(id);
    old_curves_.emplace(id, c ? std::optional<NetworkCurve>(*c) : std::nullopt);
  }
  void touch_node(NodeId id) {
    if (old_nodes_.count(id)) return;
    const Node* n = net_.find_node(id);
    old_nodes_.emplace(id, n ? std::optional<Node>(*n) : std::nullopt);
  }
  void touch_patch(PatchId id) {
    if (old_patches_.count(id)) return;
    auto it = net_.patches_.find(id);
    old_patches_.emplace(id, it == net_.patches_.end() ? std::nullopt : std::optional<Patch>(it->second));
  }

  void remove_patches() {
    for (std::size_t i = 0; i < edit_.patches_removed.size(); ++i) {
      const PatchId id = edit_.patches_removed[i];
      if (!net_.patches_.count(id))
        fail(where("patches_removed", i) + ": patch " + std::to_string(id) +
             (old_patches_.count(id) ? " is listed twice" : " does not exist"));
      touch_patch(id);
      net_.erase_patch(id);
    }
  }

  void remove_nodes() {
    for (std::size_t i = 0; i < edit_.nodes_removed.size(); ++i) {
      const NodeId id = edit_.nodes_removed[i];
      if (!net_.nodes_.count(id))
        fail(where("nodes_removed", i) + ": node " + std::to_string(id) +
             (old_nodes_.count(id) ? " is listed twice" : " does not exist"));
      touch_node(id);
      net_.erase_node(id);
    }
  }

  // With their incidences, the nodes they orphan and the patches on them.
  void remove_curves() {
    for (std::size_t i = 0; i < edit_.curves_removed.size(); ++i) {
      const CurveId id = edit_.curves_removed[i];
      if (!net_.curves_.count(id))
        fail(where("curves_removed", i) + ": curve " + std::to_string(id) +
             (old_curves_.count(id) ? " is listed twice" : " does not exist"));
      if (auto it = net_.nodes_on_curve_.find(id); it != net_.nodes_on_curve_.end()) {
        const std::set<NodeId> on_curve = it->second;
        for (NodeId n : on_curve) {
          touch_node(n);
          Node node = net_.nodes_.at(n);
          std::erase_if(node.incidences, [&](const NodeIncidence& inc) { return inc.curve == id; });
          if (node.incidences.empty())
            net_.erase_node(n);
          else
            net_.put_node(node);
        }
      }
      if (auto it = net_.patches_on_curve_.find(id); it != net_.patches_on_curve_.end()) {
        const std::set<PatchId> on_curve = it->second;
        for (PatchId p : on_curve) {
          touch_patch(p);
          net_.erase_patch(p);
        }
      }
      touch_curve(id);
      net_.erase_curve(id);
    }
  }

  void replace_curves() {
    for (std::size_t i = 0; i < edit_.curves_replaced.size(); ++i) {
      const NetworkCurve& nc = edit_.curves_replaced[i];
      const std::string at = where("curves_replaced", i);
      if (nc.id != 0 && !net_.curves_.count(nc.id))
        fail(at + ": curve " + std::to_string(nc.id) + " does not exist");
      check_curve(nc, at);
      if (curve_origin_.count(nc.id)) fail(at + ": curve " + std::to_string(nc.id) + " is listed twice");
      curve_origin_[nc.id] = at;
      touch_curve(nc.id);
      net_.put_curve(nc);
    }
  }

  void add_curves() {
    for (std::size_t i = 0; i < edit_.curves_added.size(); ++i) {
      const NetworkCurve& nc = edit_.curves_added[i];
      const std::string at = where("curves_added", i);
      check_curve(nc, at);
      if (net_.curves_.count(nc.id)) fail(at + ": curve " + std::to_string(nc.id) + " already exists");
      curve_origin_[nc.id] = at;
      touch_curve(nc.id);
      net_.put_curve(nc);
    }
  }

  void replace_nodes() {
    for (std::size_t i = 0; i < edit_.nodes_replaced.size(); ++i) {
      const Node& node = edit_.nodes_replaced[i];
      const std::string at = where("nodes_replaced", i);
      if (node.id != 0 && !net_.nodes_.count(node.id))
        fail(at + ": node " + std::to_string(node.id) + " does not exist");
      check_node_record(node, at);
      if (node_origin_.count(node.id)) fail(at + ": node " + std::to_string(node.id) + " is listed twice");
      node_origin_[node.id] = at;
      touch_node(node.id);
      net_.put_node(node);
    }
  }

  void add_nodes() {
    for (std::size_t i = 0; i < edit_.nodes_added.size(); ++i) {
      const Node& node = edit_.nodes_added[i];
      const std::string at = where("nodes_added", i);
      check_node_record(node, at);
      if (net_.nodes_.count(node.id)) fail(at + ": node " + std::to_string(node.id) + " already exists");
      node_origin_[node.id] = at;
      touch_node(node.id);
      net_.put_node(node);
    }
  }

  void add_patches() {
    for (std::size_t i = 0; i < edit_.patches_added.size(); ++i) {
      const Patch& patch = edit_.patches_added[i];
      const std::string at = where("patches_added", i);
      check_patch_record(patch, at);
      if (net_.patches_.count(patch.id)) fail(at + ": patch " + std::to_string(patch.id) + " already exists");
      patch_origin_[patch.id] = at;
      touch_patch(patch.id);
      net_.put_patch(patch);
    }
  }

  // `at` names the edit field (and item) to blame.
  void check_incidence(const NodeIncidence& inc, const std::string& at) const {
    const NetworkCurve* c = net_.find_curve(inc.curve);
    if (!c) fail(at + ": incidence on curve " + std::to_string(inc.curve) + ", which does not exist");
    if (!in_range(inc.t, c->curve.t_max()))
      fail(at + ": incidence on curve " + std::to_string(inc.curve) + " at t = " + num(inc.t) +
           " is outside [0, " + num(c->curve.t_max()) + "]");
  }
  void check_boundary(const OrientedSegment& s, const std::string& at) const {
    const NetworkCurve* c = net_.find_curve(s.curve);
    if (!c) fail(at + ": boundary uses curve " + std::to_string(s.curve) + ", which does not exist");
    if (!in_range(s.t_from, c->curve.t_max()) || !in_range(s.t_to, c->curve.t_max()))
      fail(at + ": boundary piece [" + num(s.t_from) + ", " + num(s.t_to) + "] on curve " +
           std::to_string(s.curve) + " is outside [0, " + num(c->curve.t_max()) + "]");
  }

  // Invariants of the result, checked on what this edit could have broken:
  // incidences and boundaries of touched nodes and patches, and those lying
  // on touched curves (a replacement may shorten a curve).
  void check_touched() const {
    for (const auto& [id, at] : node_origin_)
      for (const NodeIncidence& inc : net_.nodes_.at(id).incidences)
        check_incidence(inc, at + " (node " + std::to_string(id) + ")");
    for (const auto& [id, at] : patch_origin_)
      for (const OrientedSegment& s : net_.patches_.at(id).boundary)
        check_boundary(s, at + " (patch " + std::to_string(id) + ")");
    for (const auto& [cid, at] : curve_origin_) {
      const std::string blame = at + " (curve " + std::to_string(cid) + ") leaves ";
      if (auto it = net_.nodes_on_curve_.find(cid); it != net_.nodes_on_curve_.end())
        for (NodeId n : it->second)
          for (const NodeIncidence& inc : net_.nodes_.at(n).incidences)
            if (inc.curve == cid) check_incidence(inc, blame + "node " + std::to_string(n) + " invalid");
      if (auto it = net_.patches_on_curve_.find(cid); it != net_.patches_on_curve_.end())
        for (PatchId p : it->second)
          for (const OrientedSegment& s : net_.patches_.at(p).boundary)
            if (s.curve == cid) check_boundary(s, blame + "patch " + std::to_string(p) + " invalid");
    }
  }

  // Restored verbatim by inverse edits, else advanced past every id added.
  void update_counters() {
    if (edit_.counters) {
      const IdCounters& c = *edit_.counters;
      if (!net_.curves_.empty() && net_.curves_.rbegin()->first >= c.next_curve)
        fail("counters.next_curve = " + std::to_string(c.next_curve) + " is not above curve " +
             std::to_string(net_.curves_.rbegin()->first));
      if (!net_.nodes_.empty() && net_.nodes_.rbegin()->first >= c.next_node)
        fail("counters.next_node = " + std::to_string(c.next_node) + " is not above node " +
             std::to_string(net_.nodes_.rbegin()->first));
      if (!net_.patches_.empty() && net_.patches_.rbegin()->first >= c.next_patch)
        fail("counters.next_patch = " + std::to_string(c.next_patch) + " is not above patch " +
             std::to_string(net_.patches_.rbegin()->first));
      net_.counters_ = c;
    } else {
      IdCounters& k = net_.counters_;
      for (const NetworkCurve& c : edit_.curves_added) k.next_curve = std::max(k.next_curve, c.id + 1);
      for (const Node& n : edit_.nodes_added) k.next_node = std::max(k.next_node, n.id + 1);
      for (const Patch& p : edit_.patches_added) k.next_patch = std::max(k.next_patch, p.id + 1);
    }
  }

  void reindex() {
    index_touched_ = true;
    for (const auto& [id, old] : old_curves_) net_.index_curve(id, old);
    for (const auto& [id, old] : old_nodes_) net_.index_node(id, old);
    if (net_.index_->needs_rebuild()) net_.index_->rebuild(net_.curves_, net_.nodes_);
  }

  // The strong guarantee: every journaled item back as it was.
  void roll_back() {
    for (const auto& [id, old] : old_patches_) old ? net_.put_patch(*old) : net_.erase_patch(id);
    for (const auto& [id, old] : old_nodes_) old ? net_.put_node(*old) : net_.erase_node(id);
    for (const auto& [id, old] : old_curves_) old ? net_.put_curve(*old) : net_.erase_curve(id);
    net_.counters_ = old_counters_;
    if (index_touched_) net_.index_->rebuild(net_.curves_, net_.nodes_);
  }

  // The inverse, in the same step order, applied to the new state:
  //  1. remove patches that are new or changed;  2. remove nodes that are new,
  //  or changed but would be orphaned by step 3;  3. remove new curves (only
  //  changed/new nodes and patches can reference them, and those are handled
  //  explicitly);  4-5. restore replaced and removed curves;  6-7. restore
  //  changed and removed nodes;  8. restore changed and removed patches.
  Edit inverse() const {
    Edit inverse;
    inverse.counters = old_counters_;
    std::set<CurveId> new_curves;
    for (const auto& [id, old] : old_curves_) {
      const NetworkCurve* now = net_.find_curve(id);
      if (!old && now) {
        inverse.curves_removed.push_back(id);
        new_curves.insert(id);
      } else if (old && now && *old != *now) {
        inverse.curves_replaced.push_back(*old);
      } else if (old && !now) {
        inverse.curves_added.push_back(*old);
      }
    }
    for (const auto& [id, old] : old_nodes_) {
      const Node* now = net_.find_node(id);
      if (!now) {
        if (old) inverse.nodes_added.push_back(*old);
        continue;
      }
      if (!old) {
        inverse.nodes_removed.push_back(id);
        continue;
      }
      if (*old == *now) continue;
      const bool survives = std::any_of(now->incidences.begin(), now->incidences.end(),
                                        [&](const NodeIncidence& inc) { return !new_curves.count(inc.curve); });
      if (survives) {
        inverse.nodes_replaced.push_back(*old);
      } else {
        inverse.nodes_removed.push_back(id);
        inverse.nodes_added.push_back(*old);
      }
    }
    for (const auto& [id, old] : old_patches_) {
      auto it = net_.patches_.find(id);
      const Patch* now = it == net_.patches_.end() ? nullptr : &it->second;
      if (now && (!old || *old != *now)) inverse.patches_removed.push_back(id);
      if (old && (!now || *old != *now)) inverse.patches_added.push_back(*old);
    }
    return inverse;
  }

  Network& net_;
  const Edit& edit_;
  // Journal: state of each touched item before this edit (nullopt: absent).
  std::map<CurveId, std::optional<NetworkCurve>> old_curves_;
  std::map<NodeId, std::optional<Node>> old_nodes_;
  std::map<PatchId, std::optional<Patch>> old_patches_;
  const IdCounters old_counters_;
  // Where each explicitly given curve / node / patch came from, for errors.
  std::map<CurveId, std::string> curve_origin_;
  std::map<NodeId, std::string> node_origin_;
  std::map<PatchId, std::string> patch_origin_;
  bool index_touched_ = false;
};

Edit Network::apply(const Edit& edit) { return NetworkApplier(*this, edit).run(); }

}  // namespace sketchlab
