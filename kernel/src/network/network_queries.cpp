// Proximity queries: candidates from the spatial index, exact distances from
// geometry/closest_point.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/network.hpp"
#include "spatial_index.hpp"

namespace sketchlab {

namespace {

void check_radius(double r, const char* fn) {
  if (!std::isfinite(r) || r < 0.0)
    throw std::invalid_argument(std::string("Network::") + fn + ": radius r = " + std::to_string(r) +
                                " must be finite and >= 0 (metres)");
}

void check_point(const Vec3& p, const char* fn) {
  if (!p.allFinite()) throw std::invalid_argument(std::string("Network::") + fn + ": query point is not finite");
}

void sort_curve_hits(std::vector<CurveHit>& hits) {
  std::sort(hits.begin(), hits.end(), [](const CurveHit& a, const CurveHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.curve < b.curve;
  });
}

}  // namespace

std::vector<CurveHit> Network::curves_near(const Vec3& p, double r) const {
  check_point(p, "curves_near");
  check_radius(r, "curves_near");
  std::vector<CurveHit> hits;
  if (!index_) return hits;
  for (CurveId id : index_->curve_candidates(p, r)) {
    const ClosestPoint cp = closest_point(curves_.at(id).curve, p);
    if (cp.distance <= r) hits.push_back(CurveHit{id, cp.t, cp.point, cp.distance});
  }
  sort_curve_hits(hits);
  return hits;
}

std::vector<CurveHit> Network::curves_near_polyline(const std::vector<Vec3>& polyline, double r) const {
  if (polyline.empty()) throw std::invalid_argument("Network::curves_near_polyline: polyline has no points");
  for (std::size_t i = 0; i < polyline.size(); ++i)
    if (!polyline[i].allFinite())
      throw std::invalid_argument("Network::curves_near_polyline: polyline point " + std::to_string(i) +
                                  " is not finite");
  check_radius(r, "curves_near_polyline");
  std::vector<CurveHit> hits;
  if (!index_) return hits;
  for (CurveId id : index_->curve_candidates(polyline, r)) {
    const ClosestPoint cp = closest_point_to_polyline(curves_.at(id).curve, polyline);
    if (cp.distance <= r) hits.push_back(CurveHit{id, cp.t, cp.point, cp.distance});
  }
  sort_curve_hits(hits);
  return hits;
}

std::vector<KeypointHit> Network::keypoints_near(const Vec3& p, double r) const {
  check_point(p, "keypoints_near");
  check_radius(r, "keypoints_near");
  if (!index_) return {};
  std::vector<KeypointHit> hits = index_->keypoints_near(p, r);
  std::sort(hits.begin(), hits.end(), [](const KeypointHit& a, const KeypointHit& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.curve != b.curve ? a.curve < b.curve : a.keypoint < b.keypoint;
  });
  return hits;
}

std::vector<NodeHit> Network::nodes_near(const Vec3& p, double r) const {
  check_point(p, "nodes_near");
  check_radius(r, "nodes_near");
  if (!index_) return {};
  std::vector<NodeHit> hits = index_->nodes_near(p, r);
  std::sort(hits.begin(), hits.end(), [](const NodeHit& a, const NodeHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.node < b.node;
  });
  return hits;
}

}  // namespace sketchlab
