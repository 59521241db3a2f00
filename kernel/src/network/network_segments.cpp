// Segments: the pieces of a curve between consecutive nodes on it.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "sketchlab/network.hpp"

namespace sketchlab {

std::vector<Segment> Network::segments_of(CurveId curve_id) const {
  const NetworkCurve* nc = find_curve(curve_id);
  if (!nc) throw std::invalid_argument("Network::segments_of: curve " + std::to_string(curve_id) + " does not exist");
  std::vector<Segment> out;
  auto on = nodes_on_curve_.find(curve_id);
  if (on == nodes_on_curve_.end()) return out;

  const bool closed = nc->curve.closed;
  const double t_max = nc->curve.t_max();
  // (t, node) for every incidence on this curve; a node can meet a curve
  // several times (a self-intersection).
  std::vector<std::pair<double, NodeId>> stops;
  for (NodeId n : on->second)
    for (const NodeIncidence& inc : nodes_.at(n).incidences)
      if (inc.curve == curve_id) stops.emplace_back(closed && inc.t == t_max ? 0.0 : inc.t, n);
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());

  for (std::size_t i = 0; i + 1 < stops.size(); ++i)
    if (stops[i].first < stops[i + 1].first)
      out.push_back(Segment{curve_id, stops[i].first, stops[i + 1].first, stops[i].second, stops[i + 1].second});
  if (closed && !stops.empty()) {
    const auto& last = stops.back();
    const auto& first = stops.front();
    // A wrap ending exactly at the seam is the ordinary piece [t_last, t_max].
    const double t1 = first.first == 0.0 ? t_max : first.first;
    out.push_back(Segment{curve_id, last.first, t1, last.second, first.second});
  }
  return out;
}

std::vector<Segment> Network::segments() const {
  std::vector<Segment> out;
  for (const auto& entry : curves_) {
    const std::vector<Segment> s = segments_of(entry.first);
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

}  // namespace sketchlab
