#include "sketchlab/lab/distribution.hpp"

#include <algorithm>
#include <cmath>

namespace sketchlab {

Distribution distribution(std::vector<double> v) {
  Distribution d;
  d.count = v.size();
  if (v.empty()) return d;
  std::sort(v.begin(), v.end());
  auto rank = [&](double q) {
    const auto i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, v.size() - 1)];
  };
  d.min = v.front();
  d.p25 = rank(0.25);
  d.median = rank(0.5);
  d.p75 = rank(0.75);
  d.p90 = rank(0.9);
  d.p95 = rank(0.95);
  d.max = v.back();
  return d;
}

}  // namespace sketchlab
