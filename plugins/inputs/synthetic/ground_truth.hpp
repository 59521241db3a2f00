#pragma once
// A ground-truth curve network: the curves a synthetic user means to draw,
// and the relations among them. Units: metres, workspace space.
#include <cstddef>
#include <string>
#include <vector>

#include "sketchlab/constraint.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::synthetic {

struct GroundTruthCurve {
  Curve curve;
  Layer layer = Layer::shape;  // scaffold or shape
};

// A relation among curves (indices into the network's curves). `parameters`
// holds one curve parameter per curve where the relation holds (coincident
// point, intersection); it is empty for parallel, perpendicular, equal
// length and planar.
struct GroundTruthRelation {
  ConstraintKind kind = ConstraintKind::coincident_point;
  std::vector<std::size_t> curves;
  std::vector<double> parameters;
};

struct GroundTruthNetwork {
  std::string name;
  std::vector<GroundTruthCurve> curves;
};

}  // namespace sketchlab::synthetic
