#pragma once
// Experiment report, written into the run folder:
//   metrics.csv, metrics.json  one row/object per case, stored values (SI
//                              units, ratios in [0, 1])
//   report.html                a summary per stack across recordings (median
//                              and quartiles), the latency per stroke as
//                              distribution functions, per recording the
//                              side-by-side picture with its legend, the
//                              interactive 3D views and the metrics, sweep
//                              plots, and a glossary of every metric with its
//                              unit (metric_glossary.hpp); plots are SVG
//                              (svg_plot.hpp), so it opens offline and prints
//   report_web/sketchlab_report.js, <case>/scene.gltf.js
//                              when cases have a scene.gltf (RunOptions::
//                              scene_exporter): the 3D viewer (three.js,
//                              lab/report_web/) and each scene as a script,
//                              since a page opened from file:// may not fetch
// `host` (may be null) names sweep axes as the plugins declare their
// parameters (name and unit). Throws what write_text_file throws.
#include <string>
#include <vector>

#include "sketchlab/lab/experiment_runner.hpp"

namespace sketchlab {

class PluginHost;

void write_report(const RunSummary& summary, const ExperimentConfig& config, const PluginHost* host = nullptr);

}  // namespace sketchlab
