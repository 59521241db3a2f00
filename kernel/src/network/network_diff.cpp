#include "sketchlab/network_diff.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace sketchlab {
namespace {

// Items of `to` missing from `from` (added) or different (replaced), in id
// order, then ids of `from` missing from `to` (removed).
template <class Id, class Item>
void diff_items(const std::map<Id, Item>& from, const std::map<Id, Item>& to, std::vector<Item>& added,
                std::vector<Item>& replaced, std::vector<Id>& removed) {
  for (const auto& [id, item] : to) {
    const auto old = from.find(id);
    if (old == from.end()) added.push_back(item);
    else if (!(old->second == item)) replaced.push_back(item);
  }
  for (const auto& [id, item] : from)
    if (!to.count(id)) removed.push_back(id);
}

}  // namespace

Edit edit_between(const Network& from, const Network& to) {
  Edit e;
  diff_items(from.curves(), to.curves(), e.curves_added, e.curves_replaced, e.curves_removed);
  diff_items(from.nodes(), to.nodes(), e.nodes_added, e.nodes_replaced, e.nodes_removed);
  // Network::apply drops a node whose every incidence is on a removed curve
  // (before it replaces nodes): such a node of both networks is added again.
  const std::set<CurveId> gone(e.curves_removed.begin(), e.curves_removed.end());
  const auto dropped = [&](const Node& n) {
    const Node& old = *from.find_node(n.id);
    return std::all_of(old.incidences.begin(), old.incidences.end(),
                       [&](const NodeIncidence& i) { return gone.count(i.curve) > 0; });
  };
  for (auto it = e.nodes_replaced.begin(); it != e.nodes_replaced.end();) {
    if (!dropped(*it)) {
      ++it;
      continue;
    }
    const auto at = std::lower_bound(e.nodes_added.begin(), e.nodes_added.end(), it->id,
                                     [](const Node& n, NodeId id) { return n.id < id; });
    e.nodes_added.insert(at, std::move(*it));
    it = e.nodes_replaced.erase(it);
  }
  // A patch has no replacement: one that differs is removed and added again.
  for (const auto& [id, p] : from.patches()) {
    const auto it = to.patches().find(id);
    if (it == to.patches().end() || !(it->second == p)) e.patches_removed.push_back(id);
  }
  for (const auto& [id, p] : to.patches()) {
    const auto it = from.patches().find(id);
    if (it == from.patches().end() || !(it->second == p)) e.patches_added.push_back(p);
  }
  return e;
}

}  // namespace sketchlab
