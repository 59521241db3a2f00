#include "sketchlab/stroke.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sketchlab {

namespace {
constexpr std::array<std::pair<Layer, std::string_view>, 5> layer_names{{
    {Layer::scaffold, "scaffold"},
    {Layer::shape, "shape"},
    {Layer::free, "free"},
    {Layer::guide, "guide"},
    {Layer::automatic, "auto"},
}};
}  // namespace

std::string_view to_string(Layer layer) {
  for (const auto& [l, name] : layer_names) {
    if (l == layer) return name;
  }
  throw std::invalid_argument("invalid Layer value " + std::to_string(static_cast<int>(layer)));
}

Layer layer_from_string(std::string_view name) {
  std::string allowed;
  for (const auto& [l, n] : layer_names) {
    if (n == name) return l;
    allowed += (allowed.empty() ? "" : ", ") + std::string(n);
  }
  throw std::invalid_argument("unknown layer '" + std::string(name) + "' (allowed: " + allowed +
                              ")");
}

std::vector<Vec3> positions(const Stroke& stroke) {
  std::vector<Vec3> out;
  out.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples) out.push_back(s.position);
  return out;
}

std::string validate(const Stroke& stroke) {
  const std::string who = "stroke " + std::to_string(stroke.id);
  const std::size_t n = stroke.samples.size();
  if (n == 0) return who + " has no samples";
  if (n < 2) return who + " has 1 sample; at least 2 are needed";
  for (std::size_t i = 0; i < n; ++i) {
    const Sample& s = stroke.samples[i];
    const std::string where = who + " sample " + std::to_string(i);
    if (!s.position.allFinite()) return where + " has a non-finite position";
    if (!std::isfinite(s.time)) return where + " has a non-finite time";
    if (!std::isfinite(s.pressure)) return where + " has a non-finite pressure";
    if (!s.orientation.coeffs().allFinite()) return where + " has a non-finite orientation";
  }
  bool moved = false;
  for (std::size_t i = 1; i < n && !moved; ++i) {
    moved = stroke.samples[i].position != stroke.samples[0].position;
  }
  if (!moved) return who + " has zero length (all samples at the same position)";
  if (stroke.samples_are_pixels && !stroke.view) {
    return who + " is a 2D stroke (pixel samples) without a view";
  }
  if (stroke.draw_plane) {
    const Vec4& p = *stroke.draw_plane;
    if (!p.allFinite() || std::abs(p.head<3>().norm() - 1.0) > 1e-6)
      return who + " has a draw plane that is not finite or whose normal is not unit length";
    if (!stroke.samples_are_pixels) return who + " has a draw plane but no pixel samples";
  }
  if (!std::isfinite(stroke.workspace_scale) || stroke.workspace_scale <= 0.0) {
    return who + " has workspace scale " + std::to_string(stroke.workspace_scale) +
           "; it must be finite and > 0";
  }
  return {};
}

}  // namespace sketchlab
