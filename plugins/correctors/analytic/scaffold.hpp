#pragma once
// The 3D scaffold the inference reads from the sketch (§2, §3): straight
// segments, guidelines (infinite lines), curves, their vertices and the
// vanishing directions in use. Built fresh for every stroke from the network
// (correctors keep no state between strokes).
#include <optional>
#include <vector>

#include "sketchlab/sketch.hpp"

namespace sketchlab::analytic {

struct ScaffoldLine {
  CurveId id = 0;
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // for a guideline: a point and a second point
  bool guide = false;                        // guidelines are infinite lines
  Vec3 direction() const { return (b - a).normalized(); }
};

struct ScaffoldVertex {
  Vec3 p = Vec3::Zero();
  std::vector<int> lines;  // indices into Scaffold::lines passing through p
};

struct ScaffoldCurve {
  CurveId id = 0;
  Curve curve;
};

struct Scaffold {
  std::vector<ScaffoldLine> lines;  // segments and guidelines
  std::vector<ScaffoldVertex> vertices;  // segment / curve ends, ticks (merged)
  std::vector<ScaffoldCurve> curves;
  std::vector<Vec3> vanishing;      // unit directions, one per parallel class
  // A segment within this angle of a vanishing direction adds none of its
  // own (cos of build_scaffold's `vanishing_merge`).
  double vanishing_merge_cos = 1.0;
  double extent = 1.0;              // bounding-box diagonal (>= 1e-3), metres
  double tolerance = 1e-9;          // "lies on" tolerance, metres (1e-7 extent)
  // Segment lengths and directions with multiplicities (equal within 1e-9
  // relative), so the mixtures of eq. 4 cost one term per class.
  std::vector<std::pair<double, int>> length_classes;
  std::vector<std::pair<Vec3, int>> direction_classes;
  double length_sum = 0.0;
  int segment_count() const;        // lines that are not guidelines
};

// Reads every curve of the network. `up` seeds the vanishing directions with
// the vertical; the first segment adds its own direction and its horizontal
// perpendicular (§2: the first stroke defines the primary vanishing points).
// Every later segment adds its direction unless it lies within
// `vanishing_merge` radians of one already there.
Scaffold build_scaffold(const Network& network, const Vec3& up, double vanishing_merge);

// Adds one curve (as build_scaffold would) so newly inferred geometry is seen
// when free strokes are re-inferred.
void add_to_scaffold(Scaffold& scaffold, const NetworkCurve& curve, const Vec3& up);

// Closest points of the lines p + s·u and q + t·v (u, v unit): (s, t, distance);
// parallel lines give s = 0.
struct LineLineHit {
  double s = 0, t = 0, distance = 0;
  bool parallel = false;
};
LineLineHit closest_line_line(const Vec3& p, const Vec3& u, const Vec3& q, const Vec3& v);

// Whether the parameter `t` along `l` (metres from l.a) lies on it within
// `tol`: guidelines are infinite, segments end at a and b.
bool within_line(const ScaffoldLine& l, double t, double tol);

// Whether the segment a–b lies on the (infinite) line of `l`: both ends
// within `tol` metres of it.
bool lies_on_line(const ScaffoldLine& l, const Vec3& a, const Vec3& b, double tol);

// Where two scaffold lines meet (closer than s.tolerance, not parallel, and
// within both segments): the point on `a`. The intersections the inference
// snaps to (Figure 7b, c) and offers as known points.
std::optional<Vec3> scaffold_crossing(const Scaffold& s, const ScaffoldLine& a, const ScaffoldLine& b);

}  // namespace sketchlab::analytic
