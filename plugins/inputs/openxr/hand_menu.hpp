#pragma once
// The hand menu of `sketchlab vr` (issue #25): a palette of items held
// upright above the non-dominant controller, facing the user, picked by
// touching an item with the dominant hand's brush tip and pulling the draw
// trigger (as Open Brush / Gravity Sketch palettes are picked: no extra
// buttons, so it works on every interaction profile).
//
// The layout is a pure function of the holding hand's aim pose, so the
// interpreter (hit test) and the viewer (drawing) agree by construction.
#include <array>
#include <optional>
#include <string_view>

#include "controller_frame.hpp"

namespace sketchlab::openxr {

enum class MenuItem {
  scaffold, shape, free,          // drawing modes (ModeEvent)
  patch, erase,                   // tools: the trigger adds a patch / deletes the nearest curve
  correction, undo, redo,         // CorrectionEvent, UndoEvent, RedoEvent
  next_stack, compare,            // view: shown stack, second stack overlaid
  raw_strokes, rejected,          // view: raw strokes faint, rejected candidates
};
inline constexpr std::size_t menu_item_count = 12;
inline constexpr int menu_columns = 3;
// Side of one item's square, metres (stage; the menu does not zoom).
inline constexpr double menu_cell = 0.035;

std::string_view menu_label(MenuItem item);

// Centre of `item` in stage space: rows of `menu_columns` from the top,
// the panel's centre 9 cm above the controller in its aim frame (x right,
// y up, the panel's normal +z towards the user, who points with -z).
Vec3 menu_item_centre(const RigidPose& hand, MenuItem item);
// Centre of the whole panel (stage) and its half extents along the hand's
// x and y axes.
Vec3 menu_centre(const RigidPose& hand);
Vec2 menu_half_size();

// The item whose square contains `tip` projected onto the panel, when `tip`
// is within `menu_cell` / 2 of the panel's plane; nullopt otherwise.
std::optional<MenuItem> menu_item_at(const RigidPose& hand, const Vec3& tip);

}  // namespace sketchlab::openxr
