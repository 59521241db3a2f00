#include "sketchlab/network_diff.hpp"

namespace sketchlab {

Edit edit_between(const Network& from, const Network& to) {
  Edit e;
  for (const auto& [id, c] : to.curves()) {
    const NetworkCurve* old = from.find_curve(id);
    if (!old) e.curves_added.push_back(c);
    else if (!(*old == c)) e.curves_replaced.push_back(c);
  }
  for (const auto& [id, c] : from.curves())
    if (!to.find_curve(id)) e.curves_removed.push_back(id);
  for (const auto& [id, n] : to.nodes()) {
    const Node* old = from.find_node(id);
    if (!old) e.nodes_added.push_back(n);
    else if (!(*old == n)) e.nodes_replaced.push_back(n);
  }
  for (const auto& [id, n] : from.nodes())
    if (!to.find_node(id)) e.nodes_removed.push_back(id);
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
