#include "cassie_breaks.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <vector>

namespace sketchlab::soapfilm {

std::map<std::int64_t, double> inferred_breaks(const CassieSession& session) {
  std::vector<double> events;  // stroke creations and deletions, the replay's groups
  std::map<double, std::set<std::int64_t>> created_at;
  for (const CassieStroke& s : session.strokes) {
    events.push_back(s.created);
    created_at[s.created].insert(s.id);
    if (s.deleted) events.push_back(*s.deleted);
  }
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  auto event_of = [&](double t) -> std::optional<double> {
    const auto it = std::upper_bound(events.begin(), events.end(), t + 1e-4);
    if (it == events.begin()) return std::nullopt;
    return *(it - 1);
  };
  // A half: an automatic patch over the event's new strokes and old ones.
  struct Half {
    double event;
    StrokeSet old;
  };
  std::vector<Half> halves;
  for (const CassiePatch& q : session.patches) {
    if (!q.automatic || !q.created) continue;
    const auto e = event_of(*q.created);
    if (!e) continue;
    const auto fresh = created_at.find(*e);
    Half h{*e, {}};
    bool has_new = false;
    for (std::int64_t s : q.strokes) {
      if (fresh != created_at.end() && fresh->second.count(s))
        has_new = true;
      else
        h.old.insert(s);
    }
    if (has_new && !h.old.empty()) halves.push_back(std::move(h));
  }
  std::map<std::int64_t, double> out;
  for (const CassiePatch& p : session.patches) {
    if (!p.automatic || !p.created || p.strokes.empty()) continue;
    const auto made = event_of(*p.created);
    std::map<double, std::pair<int, StrokeSet>> at;  // event -> halves inside p, their old strokes
    for (const Half& h : halves) {
      if (made && h.event <= *made) continue;
      if (!std::includes(p.strokes.begin(), p.strokes.end(), h.old.begin(), h.old.end())) continue;
      auto& [count, used] = at[h.event];
      ++count;
      used.insert(h.old.begin(), h.old.end());
    }
    for (const auto& [event, halves_here] : at)
      if (halves_here.first >= 2 && halves_here.second == p.strokes) {
        out[p.id] = event;
        break;
      }
  }
  return out;
}

}  // namespace sketchlab::soapfilm
