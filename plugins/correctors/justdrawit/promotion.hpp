#pragma once
// Promotion of a 2D stroke to 3D (§4.4.1) and the 3D Hermite join of the
// promoted stroke into a curve (§4.4.2).
#include <optional>

#include "plane_depth.hpp"
#include "point_list.hpp"

namespace sketchlab::justdrawit {

// Depths for every stroke point: known values kept, gaps between known
// values interpolated linearly in 2D arclength, the parts before the first /
// after the last known value extrapolated with the given slopes (depth
// change per pixel walking away from the known part; 0 puts the stroke on
// the reference plane). No known value at all: every depth is 0.
std::vector<double> fill_depths(const std::vector<double>& cum2,
                                const std::vector<std::optional<double>>& known,
                                double slope_before, double slope_after);

// Average depth change per pixel walking from `from` to `to` (2D
// arclengths) over the known depths: the extrapolation slope of §4.4.1.
double depth_slope(const std::vector<double>& cum2, const std::vector<double>& depth, double from,
                   double to);

// 3D points on the rays through the stroke pixels at the given depths from
// the plane, then `rounds` (2 + N) rounds of smoothing, each re-projecting
// the averaged points onto their rays (§4.5). Nothing when a ray misses the
// plane.
std::optional<Points3> lift(const Camera& cam, const Plane& plane, const Points2& stroke,
                            const std::vector<double>& depth, int rounds);

// §4.4.2 join of two point lists: keeps head[0..k], a Hermite curve, then
// tail[m..]. k and m are searched within `radius` (3D arclength) of k0 and
// m0, minimising 0.8 α_d + 0.2 α_t for a merge and 0.2 α_d + 0.8 α_t for a
// join; tangent lengths 1.5 x the join length, 0.5 x when it zig-zags
// (⟨v×v_s, v×v_c⟩ < 0). Hermite samples are `spacing` apart.
struct Splice {
  Points3 pts;
  std::size_t join_begin = 0, join_end = 0;  // the Hermite's range in pts
  double objective = 0;
  std::size_t k = 0, m = 0;  // chosen indices
};
Splice splice(const Points3& head, std::size_t k0, const Points3& tail, std::size_t m0,
              double radius, bool merge, double spacing, double tangent_window);
// The same join closing a list on itself: pts[m..k] then a Hermite from
// pts[k] back to pts[m] (k searched near k0, m near m0 < k0). The result's
// last point equals its first.
Splice close_splice(const Points3& pts, std::size_t k0, std::size_t m0, double radius, bool merge,
                    double spacing, double tangent_window);

// 1 + N + 40 q rounds of smoothing (§4.5) over [first, last] widened by
// `margin` points either side (ends of open lists stay).
void smooth_join(Points3& pts, std::size_t first, std::size_t last, std::size_t margin, int rounds,
                 bool closed);

}  // namespace sketchlab::justdrawit
