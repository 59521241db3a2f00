#include "hand_menu.hpp"

#include <cmath>

namespace sketchlab::openxr {
namespace {

constexpr int rows = static_cast<int>((menu_item_count + menu_columns - 1) / menu_columns);
const Vec3 panel_offset(0.0, 0.04 + 0.5 * rows * menu_cell, 0.0);  // hand frame: above the controller

// Item centre in the hand's frame.
Vec3 local_centre(std::size_t index) {
  const int row = static_cast<int>(index) / menu_columns, col = static_cast<int>(index) % menu_columns;
  return panel_offset + menu_cell * Vec3(col - 0.5 * (menu_columns - 1), 0.5 * (rows - 1) - row, 0.0);
}

}  // namespace

std::string_view menu_label(MenuItem item) {
  static constexpr std::array<std::string_view, menu_item_count> labels{
      "scaffold", "shape", "free", "patch", "erase", "correct", "undo", "redo", "stack", "compare", "raw", "rejected"};
  return labels[static_cast<std::size_t>(item)];
}

Vec3 menu_item_centre(const RigidPose& hand, MenuItem item) {
  return hand.position + hand.orientation * local_centre(static_cast<std::size_t>(item));
}

Vec3 menu_centre(const RigidPose& hand) { return hand.position + hand.orientation * panel_offset; }

Vec2 menu_half_size() { return {0.5 * menu_columns * menu_cell, 0.5 * rows * menu_cell}; }

std::optional<MenuItem> menu_item_at(const RigidPose& hand, const Vec3& tip) {
  const Vec3 local = hand.orientation.conjugate() * (tip - hand.position) - panel_offset;
  if (!local.allFinite() || std::abs(local.z()) > 0.5 * menu_cell) return std::nullopt;
  const double col = std::floor(local.x() / menu_cell + 0.5 * menu_columns);
  const double row = std::floor(0.5 * rows - local.y() / menu_cell);
  if (col < 0 || col >= menu_columns || row < 0 || row >= rows) return std::nullopt;
  const auto index = static_cast<std::size_t>(row) * menu_columns + static_cast<std::size_t>(col);
  if (index >= menu_item_count) return std::nullopt;
  return static_cast<MenuItem>(index);
}

}  // namespace sketchlab::openxr
