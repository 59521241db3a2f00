#pragma once
// Candidate constraints of a new stroke (CHI §4.4 "Intersections",
// "Tangent alignment", "Planarity"; thesis §3.2.3.2).
#include <optional>
#include <vector>

#include "cassie_params.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::cassie {

enum class TargetKind { curve, node, grid, mirror, closure };

// One candidate hard intersection constraint.
struct Candidate {
  TargetKind kind = TargetKind::curve;
  Vec3 target = Vec3::Zero();  // where the stroke must pass (unused for closure)
  double t_stroke = 0.0;       // closest parameter on the fitted stroke (eq. 3.3)
  double distance = 0.0;       // m, stroke to target before correction
  CurveId curve = 0;           // existing curve (curve and node kinds)
  double t_curve = 0.0;        // its parameter at the target
  NodeId node = 0;             // existing node (node kind)
  double weight = 1.0;         // CHI eq. 3 weight w_i
  std::optional<Vec3> tangent;  // unit target direction when tangents align within θ
};

struct Thresholds {
  double delta = 0.02;      // δ(s) = δ/s
  double proximity = 0.04;  // r_detect
  double reuse = 0.02;
  double mirror = 0.025;
  double surface = 0.05;
};
Thresholds thresholds(const CassieParams& p, double workspace_scale);

// Intersections of `stroke` (the fitted curve) with existing curves (snapped to
// an existing node within δ, else to an existing curve end within δ), grid
// nodes, the mirror plane (crossings, and endpoints within 1.25δ), and the
// closure of its own ends; sorted by stroke parameter, at most
// params.max_candidates (the closest). `mirror` tells whether the plane is used.
std::vector<Candidate> detect_candidates(const Curve& stroke, const Sketch& sketch,
                                         const CassieParams& params, const Thresholds& th,
                                         bool mirror, bool allow_closure);

struct PlaneFit {
  bool planar = false;  // farthest control point within r_detect of the plane
  Vec3 normal = Vec3::UnitZ();
  Vec3 centroid = Vec3::Zero();
  double max_distance = 0.0;
  int axis = -1;  // 0,1,2 when the normal was snapped to that axis (within θ)
};

// Least-squares plane through the control points (thesis §3.2.3.2).
PlaneFit fit_plane(const std::vector<Vec3>& points, double max_distance, double angle);

// Largest distance of the points to the plane through their centroid with
// normal n.
double plane_residual(const std::vector<Vec3>& points, const Vec3& n);

}  // namespace sketchlab::cassie
