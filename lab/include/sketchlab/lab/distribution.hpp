#pragma once
// Summary of a sample of values (latencies, distances) by nearest-rank
// percentiles, as reported by benchmarks, metrics and comparisons.
#include <cstddef>
#include <vector>

namespace sketchlab {

struct Distribution {
  std::size_t count = 0;
  double min = 0.0, p25 = 0.0, median = 0.0, p75 = 0.0, p90 = 0.0, p95 = 0.0, max = 0.0;
};

// Nearest-rank percentiles; zeros for an empty input.
Distribution distribution(std::vector<double> values);

}  // namespace sketchlab
