#include "shape_keypoints.hpp"

#include <algorithm>
#include <cmath>

#include "scaffold_candidates.hpp"

namespace sketchlab::scaffoldsketch {
namespace {

constexpr double same_point = 1e-9;  // m: keypoints closer than this are one keypoint

Vec3 safe_direction(const Vec3& v, const Vec3& fallback) {
  const double n = v.norm();
  return n > 1e-15 ? Vec3(v / n) : fallback;
}

}  // namespace

ShapeKeypoints select_shape_keypoints(const std::vector<Vec3>& samples, const Network& network,
                                      const ShapeParams& params, double scale) {
  ShapeKeypoints out;
  const std::size_t n = samples.size();
  if (n == 0) return out;
  const double radius = scaled_threshold(params.keypoint_distance, scale);

  struct Pick {
    Vec3 position;
    CurveId curve;
    double t;
    std::size_t sample;  // the closest sample
    double distance;
    std::size_t first, last;  // the samples that selected it
  };
  std::vector<Pick> picks;
  for (std::size_t i = 0; i < n; ++i) {
    for (const KeypointHit& hit : network.keypoints_near(samples[i], radius)) {
      const NetworkCurve* c = network.find_curve(hit.curve);
      if (!c || !is_scaffold_line(*c)) continue;
      const double t = c->keypoints[static_cast<std::size_t>(hit.keypoint)].t;
      if (!picks.empty() && (picks.back().position - hit.position).norm() <= same_point) {
        picks.back().last = i;
        if (hit.distance < picks.back().distance) {  // same keypoint: keep the closest sample
          picks.back().sample = i;
          picks.back().distance = hit.distance;
        }
      } else {
        picks.push_back({hit.position, hit.curve, t, i, hit.distance, i, i});
      }
      break;  // the nearest scaffold keypoint only
    }
  }

  const Vec3 overall = safe_direction(samples.back() - samples.front(), Vec3::UnitX());
  auto forward_at = [&](std::size_t i) {
    return n < 2       ? overall
           : i + 1 < n ? safe_direction(samples[i + 1] - samples[i], overall)
                       : safe_direction(samples[i] - samples[i - 1], overall);
  };
  const double cos_limit = std::cos(params.tangent_angle);
  for (const Pick& pick : picks) {
    const std::size_t i = pick.sample;
    const std::size_t lo = i >= 2 ? i - 2 : 0, hi = std::min(i + 2, n - 1);
    const Vec3 local = safe_direction(samples[hi] - samples[lo], forward_at(i));

    std::vector<CurveHit> through = network.curves_near(pick.position, same_point);
    std::sort(through.begin(), through.end(),
              [](const CurveHit& l, const CurveHit& r) { return l.curve < r.curve; });
    Vec3 tangent = local;
    CurveId tangent_curve = 0;
    double best = cos_limit;
    const std::size_t from = params.tangent_sample == TangentSample::best ? pick.first : i;
    const std::size_t to = params.tangent_sample == TangentSample::best ? pick.last : i;
    for (std::size_t j = from; j <= to; ++j) {
      const Vec3 forward = forward_at(j);
      for (const CurveHit& h : through) {
        const NetworkCurve* c = network.find_curve(h.curve);
        if (!c || !is_scaffold_line(*c)) continue;
        const Vec3 e = safe_direction(
            c->curve.control_points.back() - c->curve.control_points.front(), Vec3::Zero());
        if (e.isZero()) continue;
        const double cosine = std::abs(e.dot(forward));
        if (cosine > best) {  // angle below tangent_angle and the smallest so far
          best = cosine;
          tangent = e.dot(forward) >= 0 ? e : Vec3(-e);
          tangent_curve = h.curve;
        }
      }
    }
    out.points.push_back(pick.position);
    out.tangents.push_back(tangent);
    out.keypoint_curve.push_back(pick.curve);
    out.keypoint_t.push_back(pick.t);
    out.tangent_curve.push_back(tangent_curve);
    out.sample.push_back(i);
  }
  const std::size_t m = out.points.size();
  if (m >= 4 && (out.points.front() - out.points.back()).norm() <= same_point) {
    out.closed = true;
    out.tangents.back() = out.tangents.front();  // one tangent at the seam
    out.tangent_curve.back() = out.tangent_curve.front();
  }
  return out;
}

}  // namespace sketchlab::scaffoldsketch
