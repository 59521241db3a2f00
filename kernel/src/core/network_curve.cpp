#include "sketchlab/network_curve.hpp"

#include <utility>

namespace sketchlab {

Layer curve_layer(Layer stroke_layer) {
  return stroke_layer == Layer::automatic ? Layer::free : stroke_layer;
}

NetworkCurve make_network_curve(CurveId id, Curve curve, Layer layer, StrokeId source_stroke) {
  NetworkCurve nc;
  nc.id = id;
  nc.keypoints = default_keypoints(curve);
  nc.curve = std::move(curve);
  nc.layer = layer;
  nc.source_stroke = source_stroke;
  return nc;
}

}  // namespace sketchlab
