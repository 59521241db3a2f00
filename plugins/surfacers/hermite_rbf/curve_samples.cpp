#include "curve_samples.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::hermite_rbf {

std::vector<CurveSamples> sample_curves(const Network& network, const SamplingParams& params) {
  std::vector<std::pair<const NetworkCurve*, double>> curves;
  double total = 0.0;
  for (const auto& [id, nc] : network.curves()) {
    const double length = arclength(nc.curve);
    if (!(length > 1e-12) || !std::isfinite(length)) continue;
    curves.emplace_back(&nc, length);
    total += length;
  }
  const double spacing = std::max(params.sample_spacing, total / std::max(1, params.max_samples));
  std::vector<CurveSamples> out;
  for (const auto& [nc, length] : curves) {
    CurveSamples s;
    s.curve = nc->id;
    s.closed = nc->curve.closed;
    s.t_max = nc->curve.t_max();
    const int intervals = std::max(s.closed ? 3 : 1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
    s.t = arclength_parameters(nc->curve, intervals + 1);
    if (s.closed) s.t.pop_back();
    s.spacing = length / intervals;
    for (double t : s.t) {
      s.points.push_back(evaluate(nc->curve, t));
      s.tangents.push_back(tangent(nc->curve, t));
    }
    s.normals.assign(s.t.size(), Vec3::Zero());
    out.push_back(std::move(s));
  }
  return out;
}

int nearest_sample(const CurveSamples& samples, double t) {
  const auto it = std::lower_bound(samples.t.begin(), samples.t.end(), t);
  if (it == samples.t.begin()) return 0;
  if (it == samples.t.end()) {
    // Past the last sample of a closed curve lies the seam, i.e. sample 0 at t_max.
    const int last = static_cast<int>(samples.t.size()) - 1;
    if (samples.closed && samples.t.size() > 1) {
      return samples.t_max - t < t - samples.t.back() ? 0 : last;
    }
    return last;
  }
  const int i = static_cast<int>(it - samples.t.begin());
  return t - samples.t[static_cast<std::size_t>(i - 1)] <= *it - t ? i - 1 : i;
}

}  // namespace sketchlab::hermite_rbf
