#pragma once
// Self-contained SVG plots for the report (vector figures that print and
// paste into a paper as they are; no script needed to see them): axes with
// round-numbered ticks and grid, optional log x axis, a marker per point,
// step drawing for distribution functions, and a legend.
#include <string>
#include <utility>
#include <vector>

namespace sketchlab {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in order
};

struct PlotOptions {
  std::string title;
  std::string x_label, y_label;  // with the unit, e.g. "latency per stroke (ms)"
  bool log_x = false;            // log10 x axis; points with x <= 0 are dropped
  bool markers = true;           // a circle at each point
  bool steps = false;            // horizontal-then-vertical steps (a CDF)
  double width = 720, height = 360;  // SVG user units (scaled to the page)
};

// Plot area: x in [left, width - right], y in [top, height - bottom] with
// left 70, right 180 (legend), top 30, bottom 50. Non-finite points are
// dropped; an empty or one-point range is widened so coordinates stay finite.
std::string svg_plot(const std::vector<PlotSeries>& series, const PlotOptions& options);

// The empirical distribution function of `values` (non-finite ones
// dropped): (v_(i), (i + 1) / n) for the sorted values, to draw with steps.
std::vector<std::pair<double, double>> empirical_cdf(std::vector<double> values);

// Round tick values covering [lo, hi] (about `target` of them, step 1, 2 or
// 5 × 10^k); lo <= hi, both finite.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);

}  // namespace sketchlab
