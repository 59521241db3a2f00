#include "sketchlab/event.hpp"

#include <array>

namespace sketchlab {

std::string_view event_type_name(const EventPayload& payload) {
  // Indexed by the variant alternative; keep in the order of EventPayload.
  static constexpr std::array<std::string_view, std::variant_size_v<EventPayload>> names{
      "stroke",     "undo",      "redo",      "delete_near",  "delete_stroke", "mode",
      "workspace",  "correction", "add_patch", "delete_patch", "reference",
      "relation",   "recompute_surface",
  };
  return names[payload.index()];
}

}  // namespace sketchlab
