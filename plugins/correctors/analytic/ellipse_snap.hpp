#pragma once
// §3.2: "once a curve has been selected we check to see if it is close to an
// elliptic arc, and if so, snap it to the arc". The conic is fitted to the
// planar curve with its joints and constrained tangents as exact linear
// conditions, so the snapped arc keeps every hard constraint; it is accepted
// when it is an ellipse within `tolerance` (fraction of its major semi-axis)
// of the curve everywhere.
#include <optional>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab::analytic {

// `joints`: the curve's constrained points (in order, on the curve);
// `tangents`: per joint an optional direction to keep. The curve must be
// planar with unit normal `normal`. Returns the elliptic arc as a cubic
// poly-Bézier (pieces of at most 90°) or nullopt.
std::optional<Curve> snap_to_ellipse(const Curve& curve, const Vec3& normal,
                                     const std::vector<Vec3>& joints,
                                     const std::vector<std::optional<Vec3>>& tangents,
                                     double tolerance);

}  // namespace sketchlab::analytic
