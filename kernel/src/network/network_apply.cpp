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

Edit Network::apply(const Edit& edit) {
  if (!index_) index_ = std::make_unique<SpatialIndex>();

  // Journal: state of each touched item before this edit (nullopt: absent).
  std::map<CurveId, std::optional<NetworkCurve>> old_curves;
  std::map<NodeId, std::optional<Node>> old_nodes;
  std::map<PatchId, std::optional<Patch>> old_patches;
  const IdCounters old_counters = counters_;
  // Where each explicitly given node / patch came from, for error messages.
  std::map<NodeId, std::string> node_origin;
  std::map<PatchId, std::string> patch_origin;
  std::map<CurveId, std::string> curve_origin;

  auto touch_curve = [&](CurveId id) {
    if (old_curves.count(id)) return;
    const NetworkCurve* c = find_curve(id);
    old_curves.emplace(id, c ? std::optional<NetworkCurve>(*c) : std::nullopt);
  };
  auto touch_node = [&](NodeId id) {
    if (old_nodes.count(id)) return;
    const Node* n = find_node(id);
    old_nodes.emplace(id, n ? std::optional<Node>(*n) : std::nullopt);
  };
  auto touch_patch = [&](PatchId id) {
    if (old_patches.count(id)) return;
    auto it = patches_.find(id);
    old_patches.emplace(id, it == patches_.end() ? std::nullopt : std::optional<Patch>(it->second));
  };
  bool index_touched = false;

  try {
    // 1. Patches removed.
    for (std::size_t i = 0; i < edit.patches_removed.size(); ++i) {
      const PatchId id = edit.patches_removed[i];
      if (!patches_.count(id))
        fail(where("patches_removed", i) + ": patch " + std::to_string(id) +
             (old_patches.count(id) ? " is listed twice" : " does not exist"));
      touch_patch(id);
      erase_patch(id);
    }
    // 2. Nodes removed.
    for (std::size_t i = 0; i < edit.nodes_removed.size(); ++i) {
      const NodeId id = edit.nodes_removed[i];
      if (!nodes_.count(id))
        fail(where("nodes_removed", i) + ": node " + std::to_string(id) +
             (old_nodes.count(id) ? " is listed twice" : " does not exist"));
      touch_node(id);
      erase_node(id);
    }
    // 3. Curves removed, with their incidences, orphaned nodes and patches.
    for (std::size_t i = 0; i < edit.curves_removed.size(); ++i) {
      const CurveId id = edit.curves_removed[i];
      if (!curves_.count(id))
        fail(where("curves_removed", i) + ": curve " + std::to_string(id) +
             (old_curves.count(id) ? " is listed twice" : " does not exist"));
      if (auto it = nodes_on_curve_.find(id); it != nodes_on_curve_.end()) {
        const std::set<NodeId> on_curve = it->second;
        for (NodeId n : on_curve) {
          touch_node(n);
          Node node = nodes_.at(n);
          std::erase_if(node.incidences, [&](const NodeIncidence& inc) { return inc.curve == id; });
          if (node.incidences.empty())
            erase_node(n);
          else
            put_node(node);
        }
      }
      if (auto it = patches_on_curve_.find(id); it != patches_on_curve_.end()) {
        const std::set<PatchId> on_curve = it->second;
        for (PatchId p : on_curve) {
          touch_patch(p);
          erase_patch(p);
        }
      }
      touch_curve(id);
      erase_curve(id);
    }
    // 4. Curves replaced.
    for (std::size_t i = 0; i < edit.curves_replaced.size(); ++i) {
      const NetworkCurve& nc = edit.curves_replaced[i];
      const std::string at = where("curves_replaced", i);
      if (nc.id != 0 && !curves_.count(nc.id))
        fail(at + ": curve " + std::to_string(nc.id) + " does not exist");
      check_curve(nc, at);
      if (curve_origin.count(nc.id)) fail(at + ": curve " + std::to_string(nc.id) + " is listed twice");
      curve_origin[nc.id] = at;
      touch_curve(nc.id);
      put_curve(nc);
    }
    // 5. Curves added.
    for (std::size_t i = 0; i < edit.curves_added.size(); ++i) {
      const NetworkCurve& nc = edit.curves_added[i];
      const std::string at = where("curves_added", i);
      check_curve(nc, at);
      if (curves_.count(nc.id)) fail(at + ": curve " + std::to_string(nc.id) + " already exists");
      curve_origin[nc.id] = at;
      touch_curve(nc.id);
      put_curve(nc);
    }
    // 6. Nodes replaced.
    for (std::size_t i = 0; i < edit.nodes_replaced.size(); ++i) {
      const Node& node = edit.nodes_replaced[i];
      const std::string at = where("nodes_replaced", i);
      if (node.id != 0 && !nodes_.count(node.id))
        fail(at + ": node " + std::to_string(node.id) + " does not exist");
      check_node_record(node, at);
      if (node_origin.count(node.id)) fail(at + ": node " + std::to_string(node.id) + " is listed twice");
      node_origin[node.id] = at;
      touch_node(node.id);
      put_node(node);
    }
    // 7. Nodes added.
    for (std::size_t i = 0; i < edit.nodes_added.size(); ++i) {
      const Node& node = edit.nodes_added[i];
      const std::string at = where("nodes_added", i);
      check_node_record(node, at);
      if (nodes_.count(node.id)) fail(at + ": node " + std::to_string(node.id) + " already exists");
      node_origin[node.id] = at;
      touch_node(node.id);
      put_node(node);
    }
    // 8. Patches added.
    for (std::size_t i = 0; i < edit.patches_added.size(); ++i) {
      const Patch& patch = edit.patches_added[i];
      const std::string at = where("patches_added", i);
      check_patch_record(patch, at);
      if (patches_.count(patch.id)) fail(at + ": patch " + std::to_string(patch.id) + " already exists");
      patch_origin[patch.id] = at;
      touch_patch(patch.id);
      put_patch(patch);
    }

    // Invariants of the result, checked on what this edit could have broken:
    // incidences and boundaries of touched nodes and patches, and those lying
    // on touched curves (a replacement may shorten a curve).
    // `at` names the edit field (and item) to blame.
    auto check_incidence = [&](const NodeIncidence& inc, const std::string& at) {
      const NetworkCurve* c = find_curve(inc.curve);
      if (!c) fail(at + ": incidence on curve " + std::to_string(inc.curve) + ", which does not exist");
      if (!in_range(inc.t, c->curve.t_max()))
        fail(at + ": incidence on curve " + std::to_string(inc.curve) + " at t = " + num(inc.t) +
             " is outside [0, " + num(c->curve.t_max()) + "]");
    };
    auto check_boundary = [&](const OrientedSegment& s, const std::string& at) {
      const NetworkCurve* c = find_curve(s.curve);
      if (!c) fail(at + ": boundary uses curve " + std::to_string(s.curve) + ", which does not exist");
      if (!in_range(s.t_from, c->curve.t_max()) || !in_range(s.t_to, c->curve.t_max()))
        fail(at + ": boundary piece [" + num(s.t_from) + ", " + num(s.t_to) + "] on curve " +
             std::to_string(s.curve) + " is outside [0, " + num(c->curve.t_max()) + "]");
    };
    for (const auto& [id, at] : node_origin)
      for (const NodeIncidence& inc : nodes_.at(id).incidences)
        check_incidence(inc, at + " (node " + std::to_string(id) + ")");
    for (const auto& [id, at] : patch_origin)
      for (const OrientedSegment& s : patches_.at(id).boundary)
        check_boundary(s, at + " (patch " + std::to_string(id) + ")");
    for (const auto& [cid, at] : curve_origin) {
      const std::string blame = at + " (curve " + std::to_string(cid) + ") leaves ";
      if (auto it = nodes_on_curve_.find(cid); it != nodes_on_curve_.end())
        for (NodeId n : it->second)
          for (const NodeIncidence& inc : nodes_.at(n).incidences)
            if (inc.curve == cid) check_incidence(inc, blame + "node " + std::to_string(n) + " invalid");
      if (auto it = patches_on_curve_.find(cid); it != patches_on_curve_.end())
        for (PatchId p : it->second)
          for (const OrientedSegment& s : patches_.at(p).boundary)
            if (s.curve == cid) check_boundary(s, blame + "patch " + std::to_string(p) + " invalid");
    }

    // Counters: restored verbatim by inverse edits, else advanced past every
    // id added.
    if (edit.counters) {
      const IdCounters& c = *edit.counters;
      if (!curves_.empty() && curves_.rbegin()->first >= c.next_curve)
        fail("counters.next_curve = " + std::to_string(c.next_curve) + " is not above curve " +
             std::to_string(curves_.rbegin()->first));
      if (!nodes_.empty() && nodes_.rbegin()->first >= c.next_node)
        fail("counters.next_node = " + std::to_string(c.next_node) + " is not above node " +
             std::to_string(nodes_.rbegin()->first));
      if (!patches_.empty() && patches_.rbegin()->first >= c.next_patch)
        fail("counters.next_patch = " + std::to_string(c.next_patch) + " is not above patch " +
             std::to_string(patches_.rbegin()->first));
      counters_ = c;
    } else {
      for (const NetworkCurve& c : edit.curves_added) counters_.next_curve = std::max(counters_.next_curve, c.id + 1);
      for (const Node& n : edit.nodes_added) counters_.next_node = std::max(counters_.next_node, n.id + 1);
      for (const Patch& p : edit.patches_added) counters_.next_patch = std::max(counters_.next_patch, p.id + 1);
    }

    index_touched = true;
    for (const auto& [id, old] : old_curves) index_curve(id, old);
    for (const auto& [id, old] : old_nodes) index_node(id, old);
    if (index_->needs_rebuild()) index_->rebuild(curves_, nodes_);
  } catch (...) {
    for (const auto& [id, old] : old_patches) old ? put_patch(*old) : erase_patch(id);
    for (const auto& [id, old] : old_nodes) old ? put_node(*old) : erase_node(id);
    for (const auto& [id, old] : old_curves) old ? put_curve(*old) : erase_curve(id);
    counters_ = old_counters;
    if (index_touched) index_->rebuild(curves_, nodes_);
    throw;
  }

  // The inverse, in the same step order, applied to the new state:
  //  1. remove patches that are new or changed;  2. remove nodes that are new,
  //  or changed but would be orphaned by step 3;  3. remove new curves (only
  //  changed/new nodes and patches can reference them, and those are handled
  //  explicitly);  4-5. restore replaced and removed curves;  6-7. restore
  //  changed and removed nodes;  8. restore changed and removed patches.
  Edit inverse;
  inverse.counters = old_counters;
  std::set<CurveId> new_curves;
  for (const auto& [id, old] : old_curves) {
    const NetworkCurve* now = find_curve(id);
    if (!old && now) {
      inverse.curves_removed.push_back(id);
      new_curves.insert(id);
    } else if (old && now && *old != *now) {
      inverse.curves_replaced.push_back(*old);
    } else if (old && !now) {
      inverse.curves_added.push_back(*old);
    }
  }
  for (const auto& [id, old] : old_nodes) {
    const Node* now = find_node(id);
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
  for (const auto& [id, old] : old_patches) {
    auto it = patches_.find(id);
    const Patch* now = it == patches_.end() ? nullptr : &it->second;
    if (now && (!old || *old != *now)) inverse.patches_removed.push_back(id);
    if (old && (!now || *old != *now)) inverse.patches_added.push_back(*old);
  }
  return inverse;
}

}  // namespace sketchlab
