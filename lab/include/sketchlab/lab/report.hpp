#pragma once
// Experiment report: metrics.csv and metrics.json (one row/object per case)
// and report.html (side-by-side pictures, a metrics table per recording,
// SVG plots of latency per stroke and of metrics against sweep values).
#include <string>
#include <vector>

#include "sketchlab/lab/experiment_runner.hpp"

namespace sketchlab {

void write_report(const RunSummary& summary, const ExperimentConfig& config);

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // (x, y), drawn in order
};
// A self-contained SVG line plot (axes with min/max labels, legend).
std::string svg_line_plot(const std::string& title, const std::string& x_label,
                          const std::string& y_label, const std::vector<PlotSeries>& series);

}  // namespace sketchlab
