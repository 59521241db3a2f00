#pragma once
// Plain records stored in a Network.
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/mesh.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab {

struct Keypoint {
  enum class Kind { start, end, midpoint, tick, other } kind = Kind::other;
  double t = 0.0;  // curve parameter
  Vec3 position = Vec3::Zero();
  bool operator==(const Keypoint&) const = default;
};

// A normal attached to a curve at parameter t (exported by correctors such as
// JustDrawIt; used by surfacers).
struct CurveNormal {
  double t = 0.0;
  Vec3 normal = Vec3::UnitZ();
  bool operator==(const CurveNormal&) const = default;
};

struct NetworkCurve {
  CurveId id = 0;
  Curve curve;
  Layer layer = Layer::free;
  StrokeId source_stroke = 0;
  std::vector<Keypoint> keypoints;  // ends, midpoint, ticks...
  std::vector<CurveNormal> normals;
  bool operator==(const NetworkCurve&) const = default;
};

// Start, end and midpoint keypoints of a curve (by arclength for the midpoint).
std::vector<Keypoint> default_keypoints(const Curve& curve);

struct NodeIncidence {
  CurveId curve = 0;
  double t = 0.0;
  bool operator==(const NodeIncidence&) const = default;
};

// A point where curves meet (or a curve meets the grid / mirror plane).
struct Node {
  NodeId id = 0;
  Vec3 position = Vec3::Zero();
  std::vector<NodeIncidence> incidences;
  bool operator==(const Node&) const = default;
};

// A piece of a curve between two consecutive nodes on it (derived data).
struct Segment {
  CurveId curve = 0;
  double t0 = 0.0, t1 = 0.0;  // t0 < t1, except across the seam of a closed curve
  NodeId node0 = 0, node1 = 0;
  bool operator==(const Segment&) const = default;
};

// A segment traversed in a direction (from t_from to t_to).
struct OrientedSegment {
  CurveId curve = 0;
  double t_from = 0.0, t_to = 0.0;
  NodeId node_from = 0, node_to = 0;
  bool operator==(const OrientedSegment&) const = default;
};

struct Patch {
  PatchId id = 0;
  std::vector<OrientedSegment> boundary;  // a closed cycle, in order
  Mesh mesh;
  bool automatic = true;  // found by cycle detection (false: user asked)
  bool operator==(const Patch&) const = default;
};

}  // namespace sketchlab
