#pragma once
// Parallel transport of a vector along a curve (Bishop frame; CHI'21 §5.1,
// thesis §3.3.2.1, Hanson & Ma): the rotation-minimising motion that carries
// the tangent at one sample to the next is applied to the vector.
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab::soapfilm {

// `parameters`: the path as curve parameters in travel order (>= 2; a path
// may wrap across the seam of a closed curve); `forward`: travel in the
// direction of increasing t. Returns v transported from the first to the
// last parameter.
Vec3 parallel_transport(const Curve& curve, const std::vector<double>& parameters, bool forward,
                        const Vec3& v);

}  // namespace sketchlab::soapfilm
