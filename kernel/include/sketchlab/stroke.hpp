#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sketchlab/sample.hpp"
#include "sketchlab/types.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab {

// The drawing mode the user chose for a stroke.
enum class Layer { scaffold, shape, free, guide, automatic };

std::string_view to_string(Layer layer);
// Throws std::invalid_argument naming the allowed values.
Layer layer_from_string(std::string_view name);

struct Stroke {
  StrokeId id = 0;
  std::vector<Sample> samples;
  Layer layer = Layer::automatic;
  // Present for 2D input: samples are pixels in this view. For VR input it
  // may hold the head pose (view matrix) at the end of the stroke.
  std::optional<View> view;
  // Workspace zoom s when the stroke was drawn; thresholds are δ/s.
  double workspace_scale = 1.0;

  bool is_2d() const { return view.has_value() && samples_are_pixels; }
  // True when positions are pixels of `view` (2D input); false for VR input.
  bool samples_are_pixels = false;
  // 2D input only: the world plane {x : n·x = d}, stored (n, d) with |n| = 1,
  // the user drew on. Correctors working in world space get the stroke lifted
  // onto it (draw_plane.hpp); 2D-native ones get the pixels as they are.
  std::optional<Vec4> draw_plane;

  bool operator==(const Stroke&) const = default;
};

// Positions of the samples, in order (n x 3).
std::vector<Vec3> positions(const Stroke& stroke);

// Empty when the stroke is usable, else a human-readable reason
// ("stroke 12 has no samples", "stroke 12 sample 4 has a non-finite position").
std::string validate(const Stroke& stroke);

}  // namespace sketchlab
