#include "fidelity_causes.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "sketchlab/geometry/plane.hpp"
#include "sketchlab/lab/distribution.hpp"

namespace sketchlab::cli {
namespace {

bool any_within(const std::vector<Vec3>& points, const Vec3& p, double d) {
  return std::any_of(points.begin(), points.end(), [&](const Vec3& q) { return (q - p).norm() <= d; });
}

}  // namespace

std::string mismatch_cause(const TeacherForcedStroke& r, int k, const CassieConstraintLog* log, double near) {
  if (!r.compared || r.reference_snap[k] == r.output_snap[k]) return "";
  if (r.reference_line != r.output_line) return "line vs Bezier";
  if (r.output_closed && !r.reference_closed) return "we closed, CASSIE open";
  if (r.reference_closed && !r.output_closed) return "CASSIE closed, we open";
  const bool ref_snapped = !r.reference_snap[k].empty(), out_snapped = !r.output_snap[k].empty();
  if (ref_snapped && out_snapped)
    return "both snapped, other kind: CASSIE " + r.reference_snap[k] + ", we " + r.output_snap[k];
  const int out_end = r.reversed ? 1 - k : k;  // the output curve starts where the stroke does
  const auto hook = r.stats.extra.find(out_end == 0 ? "hook_cut_start" : "hook_cut_end");
  const std::string moved = hook != r.stats.extra.end() && hook->second != 0.0 ? " (a hook was cut there)" : "";
  if (ref_snapped) {
    if (r.candidate_distance[k] > near) return "CASSIE snapped, we free: we detected none there";
    return r.candidate_enforced[k] ? "CASSIE snapped, we free: we enforced one there, our end is off it" + moved
                                   : "CASSIE snapped, we free: we rejected the one there";
  }
  if (!log) return "we snapped, CASSIE free: (no log of the stroke)";
  if (any_within(log->rejected, r.output_end[k], near)) return "we snapped, CASSIE free: CASSIE rejected it";
  if (any_within(log->applied, r.output_end[k], near))
    return "we snapped, CASSIE free: CASSIE applied one there, its end is off it" + moved;
  return "we snapped, CASSIE free: CASSIE logged none there";
}

void count_causes(const std::vector<TeacherForcedStroke>& strokes,
                  const std::map<StrokeId, CassieConstraintLog>* logs, double near,
                  std::map<std::string, CauseCount>& counts) {
  for (const TeacherForcedStroke& r : strokes) {
    const CassieConstraintLog* log = nullptr;
    if (logs)
      if (const auto it = logs->find(r.stroke); it != logs->end()) log = &it->second;
    for (int k = 0; k < 2; ++k) {
      const std::string cause = mismatch_cause(r, k, log, near);
      if (cause.empty()) continue;
      CauseCount& c = counts[cause];
      ++c.ends;
      c.snap_disagreements += r.reference_snap[k].empty() != r.output_snap[k].empty();
    }
  }
}

std::string cause_table(const std::map<std::string, CauseCount>& counts, std::size_t endpoints) {
  std::vector<std::pair<std::string, CauseCount>> rows(counts.begin(), counts.end());
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second.ends > b.second.ends; });
  std::size_t width = 5, total = 0, total_snap = 0;
  for (const auto& [name, c] : rows) width = std::max(width, name.size()), total += c.ends, total_snap += c.snap_disagreements;
  std::ostringstream o;
  auto line = [&](const std::string& name, std::size_t ends, std::size_t snap) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "  %6zu  %6zu  %5.1f %%\n", ends, snap,
                  endpoints ? 100.0 * double(ends) / double(endpoints) : 0.0);
    o << name << std::string(width - name.size(), ' ') << buf;
  };
  o << "cause" << std::string(width - 5, ' ') << "    ends    snap  of ends\n";
  for (const auto& [name, c] : rows) line(name, c.ends, c.snap_disagreements);
  line("total", total, total_snap);
  return o.str();
}

void add_end_distances(const std::vector<TeacherForcedStroke>& strokes,
                       const std::map<StrokeId, std::array<Vec3, 2>>& raw_ends,
                       std::map<std::string, EndDistances>& distances) {
  const auto kind = [](const std::string& k) { return k.empty() ? std::string("free") : k; };
  for (const TeacherForcedStroke& r : strokes) {
    if (!r.compared) continue;
    const auto raw = raw_ends.find(r.stroke);
    for (int k = 0; k < 2; ++k) {
      const int out_end = r.reversed ? 1 - k : k;  // the output curve starts where the stroke does
      std::string group = r.reference_line != r.output_line ? "line vs Bezier"
                          : std::string(r.reference_line ? "line: " : "") + "CASSIE " +
                                kind(r.reference_snap[k]) + ", we " + kind(r.output_snap[k]);
      if (r.reference_line == r.output_line && r.reference_snap[k].empty() && r.output_snap[k].empty()) {
        const auto hook = r.stats.extra.find(out_end == 0 ? "hook_cut_start" : "hook_cut_end");
        if (hook != r.stats.extra.end()) group += hook->second != 0.0 ? " (hook cut)" : " (no hook cut)";
      }
      EndDistances& d = distances[group];
      d.to_reference.push_back((r.reference_end[k] - r.output_end[k]).norm());
      if (raw == raw_ends.end()) continue;
      const Vec3& end = raw->second[static_cast<std::size_t>(out_end)];
      d.reference_to_raw.push_back((r.reference_end[k] - end).norm());
      d.output_to_raw.push_back((r.output_end[k] - end).norm());
    }
  }
}

std::map<StrokeId, std::array<Vec3, 2>> raw_stroke_ends(const Recording& recording) {
  std::map<StrokeId, std::array<Vec3, 2>> out;
  for (const Event& e : recording.events)
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload); s && !s->stroke.samples.empty())
      out[s->stroke.id] = {s->stroke.samples.front().position, s->stroke.samples.back().position};
  return out;
}

StrokeDecisions output_decisions(const TeacherForcedStroke& r) {
  StrokeDecisions d;
  for (const Constraint& c : r.constraints) {
    d.planar |= c.kind == ConstraintKind::planar || c.kind == ConstraintKind::axis_plane;
    d.closed |= c.kind == ConstraintKind::closure && c.enforced;
    d.on_surface |= c.kind == ConstraintKind::on_surface;
  }
  return d;
}

void count_decisions(const std::vector<TeacherForcedStroke>& strokes,
                     const std::map<StrokeId, CassieConstraintLog>& logs, DecisionCounts& counts) {
  for (const TeacherForcedStroke& r : strokes) {
    const auto it = logs.find(r.stroke);
    if (!r.compared || it == logs.end()) continue;
    const CassieConstraintLog& log = it->second;
    const StrokeDecisions ours = output_decisions(r);
    // CASSIE flags no line planar (lines have no planarity term, item 17).
    const bool bezier = !r.reference_line && !r.output_line;
    const auto add = [&](int k, DecisionCount& c, const std::optional<bool>& cassie, bool our) {
      if (!cassie) return;
      DecisionCount& n = log.mirrored_twin ? counts.twins[static_cast<std::size_t>(k)] : c;
      ++(*cassie ? (our ? n.both : n.cassie_only) : (our ? n.ours_only : n.neither));
    };
    if (bezier) add(0, counts.planar, log.planar, ours.planar);
    if (bezier && !log.mirrored_twin && log.planar.value_or(false))
      for (const Constraint& c : r.constraints)
        if (c.kind == ConstraintKind::planar || c.kind == ConstraintKind::axis_plane) {
          counts.ours_to_plane.push_back(plane_residual(r.output_curve.control_points, c.target));
          counts.cassie_to_plane.push_back(plane_residual(r.reference_curve.control_points, c.target));
        }
    add(1, counts.closed, log.closed_loop, ours.closed);
    add(2, counts.on_surface, log.on_surface, ours.on_surface);
  }
}

std::string decision_table(const DecisionCounts& counts) {
  std::ostringstream o;
  o << "decision              strokes    both  CASSIE only  ours only  neither  agreement\n";
  const auto line = [&](const char* name, const DecisionCount& c) {
    if (c.strokes() == 0) return;  // the export has no such flag
    char buf[160];
    std::snprintf(buf, sizeof buf, "%-20s  %7zu  %6zu  %11zu  %9zu  %7zu  %7.1f %%\n", name, c.strokes(), c.both,
                  c.cassie_only, c.ours_only, c.neither, 100 * c.agreement());
    o << buf;
  };
  line("planar (Béziers)", counts.planar);
  line("closed", counts.closed);
  line("on surface", counts.on_surface);
  line("planar, twins", counts.twins[0]);
  line("closed, twins", counts.twins[1]);
  line("on surface, twins", counts.twins[2]);
  if (!counts.ours_to_plane.empty()) {
    const Distribution ours = distribution(counts.ours_to_plane), cassie = distribution(counts.cassie_to_plane);
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "planar in both (%zu): control points to our plane, median / p90: ours %.2f / %.2f mm, CASSIE's "
                  "%.2f / %.2f mm\n",
                  ours.count, 1000 * ours.median, 1000 * ours.p90, 1000 * cassie.median, 1000 * cassie.p90);
    o << buf;
  }
  return o.str();
}

std::string end_distance_table(const std::map<std::string, EndDistances>& distances) {
  struct Row {
    std::string name;
    Distribution ours, reference_raw, output_raw;
  };
  std::vector<Row> rows;
  std::size_t width = 4;
  for (const auto& [name, d] : distances) {
    rows.push_back({name, distribution(d.to_reference), distribution(d.reference_to_raw), distribution(d.output_to_raw)});
    width = std::max(width, name.size());
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.ours.count > b.ours.count; });
  std::ostringstream o;
  o << "ends" << std::string(width - 4, ' ')
    << "   count  ours-CASSIE median/p90 mm  CASSIE-raw end  ours-raw end\n";
  for (const Row& r : rows) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "  %6zu  %13.2f / %6.2f  %6.2f / %5.2f  %5.2f / %5.2f\n", r.ours.count,
                  1000 * r.ours.median, 1000 * r.ours.p90, 1000 * r.reference_raw.median, 1000 * r.reference_raw.p90,
                  1000 * r.output_raw.median, 1000 * r.output_raw.p90);
    o << r.name << std::string(width - r.name.size(), ' ') << buf;
  }
  return o.str();
}

}  // namespace sketchlab::cli
