#include "sketchlab/event.hpp"

#include <array>

namespace sketchlab {

namespace {
constexpr std::size_t event_kinds = std::variant_size_v<EventPayload>;
static_assert(static_cast<std::size_t>(EventKind::recompute_surface) + 1 == event_kinds,
              "one EventKind per EventPayload alternative");
}  // namespace

EventKind event_kind(const EventPayload& payload) { return static_cast<EventKind>(payload.index()); }

std::string_view to_string(EventKind kind) {
  // Indexed by the kind; keep in the order of EventPayload.
  static constexpr std::array<std::string_view, event_kinds> names{
      "stroke",     "undo",      "redo",      "delete_near",  "delete_stroke", "mode",
      "workspace",  "correction", "add_patch", "delete_patch", "reference",
      "relation",   "recompute_surface",
  };
  return names[static_cast<std::size_t>(kind)];
}

std::string_view event_type_name(const EventPayload& payload) { return to_string(event_kind(payload)); }

}  // namespace sketchlab
