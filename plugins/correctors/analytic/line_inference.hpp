#pragma once
// Line-segment inference (Schmidt et al. 2009 §3.1): enumerate constraint
// triplets {C°, Cᵈ, Cᵗ} near the stroke's endpoints, score the unique segments
// they define by F = S·G·ΣC (eq. 1–5) and pick the segment that wins most
// often over strokes perturbed within the uncertainty radius δ.
#include <optional>
#include <string>
#include <vector>

#include "analytic_params.hpp"
#include "sketchlab/camera.hpp"
#include "scaffold.hpp"
#include "sketchlab/constraint.hpp"
#include "stroke_2d.hpp"

namespace sketchlab::analytic {

// A stroke endpoint: pixel, uncertainty radius δ (pixels), and its ray.
struct StrokeEnd {
  Vec2 pixel = Vec2::Zero();
  double delta = 1.0;
  Ray ray{Vec3::Zero(), Vec3::UnitZ()};
};

struct PointConstraint {
  // curve_intersection: where the stroke's image line crosses a curve's
  // projection (Figure 7c); p is the curve's 3D point there.
  enum class Type { vertex, intersection, on_line, curve_intersection } type = Type::vertex;
  Vec3 p = Vec3::Zero();  // vertex / intersection / curve_intersection
  int vertex = -1;        // vertex index
  int line = -1, line2 = -1;
  int curve = -1;         // curve_intersection: index into Scaffold::curves
  double curve_t = 0.0;   // curve_intersection: global curve parameter
  double f = 1.0;
};

struct DirectionConstraint {
  enum class Type { vanishing, through_vertex, perpendicular, perpendicular_pair } type =
      Type::vanishing;
  Vec3 d = Vec3::UnitX();  // vanishing / pair: fixed direction
  int vertex = -1;         // through_vertex
  int line = -1;           // perpendicular: the line it is perpendicular to
  int line2 = -1;
  double f = 1.0;
};

struct DistanceConstraint {
  enum class Type { point, on_line, free } type = Type::free;
  int point = -1;  // index into the other end's point constraints
  double f = 1.0;
};

struct Triplet {
  int origin = 0;  // 0: stroke start, 1: stroke end
  int point = 0;   // into points[origin]
  DirectionConstraint direction;
  DistanceConstraint distance;
  double weight() const;  // eq. 5: f(C°) f(Cᵈ) f(Cᵗ)
};

struct LineCandidates {
  std::vector<PointConstraint> points[2];
  std::vector<Triplet> triplets;
};

// Collects the constraints within collect_factor·δ of each endpoint and
// enumerates every triplet (§3.1, Figure 7).
LineCandidates collect_line_candidates(const Scaffold& scaffold, const Camera& camera,
                                       const Stroke2d& stroke, const StrokeEnd ends[2],
                                       const AnalyticParams& p);

// The segment (stroke-start end first) a triplet defines for these endpoint
// rays; nullopt when the constraints are inconsistent or degenerate.
std::optional<std::pair<Vec3, Vec3>> evaluate_triplet(const Triplet& t, const LineCandidates& c,
                                                      const Scaffold& scaffold,
                                                      const Camera& camera, const StrokeEnd ends[2]);

// Eq. 3: product of Gaussians of the projected-endpoint distances.
double endpoint_score(const Camera& camera, const std::pair<Vec3, Vec3>& seg, const StrokeEnd ends[2]);
// Eq. 4's direction term: mean direction Gaussian over the scaffold's
// segments (0 with none); `direction` unit, unsigned.
double direction_prior(const Scaffold& scaffold, const Vec3& direction, const AnalyticParams& p);
// Eq. 4: 1 + mean length Gaussian + mean direction Gaussian over the scaffold's segments.
double geometry_prior(const Scaffold& scaffold, const std::pair<Vec3, Vec3>& seg,
                      const AnalyticParams& p);

struct LineChoice {
  std::pair<Vec3, Vec3> segment;
  Triplet triplet;  // the constraint set that defines it (lowest index of its group)
  std::vector<Triplet> satisfied;  // every triplet giving the same segment
  double fitness = 0.0;
};

struct LineInference {
  std::optional<LineChoice> best, runner_up;
  double confidence = 0.0;   // F(l1)/F(l0), 0 without a runner-up
  double agreement = 0.0;    // fraction of perturbed strokes choosing `best`
  int combinations = 0;      // triplets enumerated
  int consistent = 0;        // triplets defining a segment on the stroke itself
  int unique_segments = 0;   // on the unperturbed stroke
  LineCandidates candidates;
};

// The whole of §3.1. Deterministic for a given seed.
LineInference infer_line(const Scaffold& scaffold, const Camera& camera, const Stroke2d& stroke,
                         const AnalyticParams& p, std::uint64_t seed);

// The first stroke lies in the ground plane {x : up·x = up·origin} (§2).
std::optional<std::pair<Vec3, Vec3>> ground_plane_segment(const Camera& camera, const StrokeEnd ends[2],
                                                          const Vec3& up, const Vec3& origin);

// Endpoints of a 2D stroke with their rays.
void stroke_ends(const Camera& camera, const Stroke2d& stroke, StrokeEnd ends[2]);

// Kernel constraints describing a triplet (enforced as given).
std::vector<Constraint> describe_triplet(const Triplet& t, const LineCandidates& c,
                                         const Scaffold& scaffold, StrokeId stroke,
                                         const std::pair<Vec3, Vec3>& seg, bool enforced);

}  // namespace sketchlab::analytic
