#include "sketchlab/lab/metric_glossary.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace sketchlab {
namespace {

bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }
bool ends_with(const std::string& s, const std::string& p) {
  return s.size() >= p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

// Group ranks: the order of column groups in every table.
enum Rank { latency = 100, network = 200, input = 300, reference = 400, truth = 500, relations = 600,
            enforced = 700, other = 900 };

MetricInfo length(std::string group, std::string label, std::string description, int rank) {
  return {std::move(group), std::move(label), "mm", 1000.0, std::move(description), rank};
}
MetricInfo percent(std::string group, std::string label, std::string description, int rank) {
  return {std::move(group), std::move(label), "%", 100.0, std::move(description), rank};
}
MetricInfo count(std::string group, std::string label, std::string description, int rank) {
  return {std::move(group), std::move(label), "", 1.0, std::move(description), rank};
}

const std::map<std::string, MetricInfo>& fixed() {
  static const std::map<std::string, MetricInfo> m = {
      {"latency_p50_ms", {"latency", "p50", "ms", 1.0, "Median time the corrector and surfacer took per corrected stroke (thread CPU of the correction step).", latency + 1}},
      {"latency_p95_ms", {"latency", "p95", "ms", 1.0, "95th percentile of the time per corrected stroke.", latency + 2}},
      {"latency_max_ms", {"latency", "max", "ms", 1.0, "Longest time of a corrected stroke.", latency + 3}},
      {"strokes", count("network", "strokes", "Live strokes that have a curve in the final sketch.", network + 1)},
      {"curves", count("network", "curves", "Curves of the final network.", network + 2)},
      {"nodes", count("network", "nodes", "Nodes (shared curve ends and intersections) of the final network.", network + 3)},
      {"patches", count("network", "patches", "Surface patches of the final network.", network + 4)},
      {"dangling_endpoint_ratio", percent("network", "dangling", "Curve ends not at a node over all network nodes plus dangling ends (CASSIE, CHI 2021, §6.4.2). Counts the network's nodes: a corrector that joins curves only on request (JustDrawIt: the user's Pin, §2) scores 1 even where its curves meet in 3D; gt_coincident_point_recall measures that meeting.", network + 5)},
      {"events_refused", count("network", "refused", "Events the corrector or surfacer refused with an error.", network + 6)},
      {"input_deviation_mean_m", length("vs input", "dev. mean", "Mean distance from each live 3D stroke's samples to its curve.", input + 1)},
      {"input_deviation_max_m", length("vs input", "dev. max", "Largest distance from a live 3D stroke's sample to its curve.", input + 2)},
      {"input_hausdorff_mean_m", length("vs input", "Hausdorff mean", "Mean over strokes of the two-sided (Hausdorff) distance between stroke and curve.", input + 3)},
      {"input_hausdorff_max_m", length("vs input", "Hausdorff max", "Largest two-sided distance between a stroke and its curve.", input + 4)},
      {"gt_distance_mean_m", length("vs ground truth", "dist. mean (raw)", "Raw: mean distance of the output curves to the intended (ground-truth) curves, with no alignment: the figure for 3D input and for 2D input whose views fix the scale (two views, or draw planes placed in the world).", truth + 1)},
      {"gt_distance_max_m", length("vs ground truth", "dist. max (raw)", "Raw: largest distance of an output curve to its intended curve.", truth + 2)},
      {"gt_distance_mean_aligned_eye_scale_m", length("vs ground truth", "dist. mean (aligned)", "Aligned: mean distance after the best uniform scaling about the camera eye: the scale one view cannot fix (analytic drawing fixes it by its first ground-plane stroke, §2). Written only when every stroke of the session (kept or not) is 2D and drawn from one eye.", truth + 3)},
      {"gt_distance_max_aligned_eye_scale_m", length("vs ground truth", "dist. max (aligned)", "Aligned: largest distance after that scaling.", truth + 4)},
      {"gt_shape_distance_mean_m", length("vs ground truth", "shape dist. (raw)", "Raw: mean distance of the output curves to the nearest intended curve of any stroke: a curve a corrector built from several strokes (JustDrawIt's extension of a curve by one drawn in line, §4.2) is scored against all of them, where dist. mean (raw) takes its last stroke's only.", truth + 6)},
      {"gt_shape_coverage_mean_m", length("vs ground truth", "shape coverage (raw)", "Raw: mean distance of the intended curves to the nearest output curve: what the output misses (a curve not made, or made short) counts here.", truth + 7)},
      {"gt_shape_distance_mean_aligned_eye_scale_m", length("vs ground truth", "shape dist. (aligned)", "Aligned: the shape distance after the eye-scale alignment of dist. mean (aligned) (single-view 2D input).", truth + 8)},
      {"gt_shape_coverage_mean_aligned_eye_scale_m", length("vs ground truth", "shape coverage (aligned)", "Aligned: the shape coverage after that alignment.", truth + 9)},
      {"gt_eye_scale", {"vs ground truth", "eye scale", "×", 1.0, "The scaling factor about the eye used for the aligned distances.", truth + 5}},
  };
  return m;
}

std::string between(const std::string& s, std::size_t from, std::size_t tail) {
  return s.substr(from, s.size() - from - tail);
}

}  // namespace

MetricInfo metric_info(const std::string& name) {
  if (auto it = fixed().find(name); it != fixed().end()) return it->second;
  // ref_<track>_{endpoint_mean_m,control_mean_m,snap_agreement,compared}
  if (starts_with(name, "ref_")) {
    struct Tail { const char* suffix; const char* label; int kind; const char* what; };
    static const Tail tails[] = {
        {"_endpoint_mean_m", "endpoints", 0, "Mean distance of the curves' end points to the reference curves' (matched by source stroke)."},
        {"_control_mean_m", "control pts", 0, "Mean distance of the curves' control points to the reference curves'."},
        {"_snap_agreement", "snap agree", 1, "Curve ends snapped (or not) as the reference's are."},
        {"_compared", "compared", 2, "Strokes compared with the reference (both have a curve)."}};
    for (int i = 0; i < 4; ++i) {
      const Tail& t = tails[i];
      if (!ends_with(name, t.suffix)) continue;
      const std::string track = between(name, 4, std::string(t.suffix).size());
      const std::string group = "vs " + track;
      const std::string what = std::string(t.what) + " Reference track: " + track + ".";
      if (t.kind == 0) return length(group, t.label, what, reference + i + 1);
      if (t.kind == 1) return percent(group, t.label, what, reference + i + 1);
      return count(group, t.label, what, reference + i + 1);
    }
  }
  // gt_<kind>_{precision,recall}
  if (starts_with(name, "gt_") && (ends_with(name, "_precision") || ends_with(name, "_recall"))) {
    const bool recall = ends_with(name, "_recall");
    const std::string kind = between(name, 3, recall ? 7 : 10);
    return percent("relations", kind + (recall ? " R" : " P"),
                   std::string(recall ? "Recall" : "Precision") + " of the ground truth's " + kind +
                       " relations against those measured on the output (distances on the eye-scaled output where the session is one view).",
                   relations);
  }
  if (starts_with(name, "enforced_") && ends_with(name, "_residual_mean")) {
    const std::string kind = between(name, 9, 14);
    return {"enforced", kind, "", 1.0,
            "Mean residual of the enforced " + kind + " constraints (in the constraint's own measure).", enforced};
  }
  MetricInfo info{"other", name, "", 1.0, "", other};
  if (ends_with(name, "_m")) info.unit = "mm", info.scale = 1000.0;
  else if (ends_with(name, "_ms")) info.unit = "ms";
  return info;
}

std::string format_displayed(double v) {
  if (!std::isfinite(v)) return "–";
  char buf[64];
  const double a = std::abs(v);
  if (a == 0.0) return "0";
  if (a >= 1e6 || a < 1e-3) std::snprintf(buf, sizeof buf, "%.2g", v);
  else if (a >= 100.0) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace sketchlab
