#pragma once
// Breakdown of the ends where a corrector's snap kind differs from the
// reference's (`sketchlab fidelity --causes`), by the first cause that
// applies, so the largest differences can be traced to a rule.
#include <array>
#include <map>
#include <string>
#include <vector>

#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/lab/teacher_forced.hpp"

namespace sketchlab::cli {

// Cause of the disagreement at reference end k (0 or 1) of a compared stroke,
// or "" when the snap kinds agree. `log` is CASSIE's constraint log of the
// stroke (nullptr if unknown); `near` (m) is how close a constraint target
// must be to an end to count as that end's. Causes, first that applies:
//   line vs Bezier; we closed, CASSIE open; CASSIE closed, we open;
//   both snapped, other kind (naming both);
//   CASSIE snapped, we free: we detected none within `near` / we rejected
//     the one there / we enforced one there, our end is off it;
//   we snapped, CASSIE free: CASSIE rejected one within `near` / CASSIE
//     applied one there, its end is off it / CASSIE logged none there.
// "Our (its) end is off it" rows say when a hook was cut at that end of our
// curve (the corrector's statistics hook_cut_start / hook_cut_end, which the
// cassie corrector reports).
std::string mismatch_cause(const TeacherForcedStroke& r, int k, const CassieConstraintLog* log, double near);

struct CauseCount {
  std::size_t ends = 0;             // ends with that cause
  std::size_t snap_disagreements = 0;  // of which snapped in one curve only
};

// Adds the causes of every compared stroke's two ends.
void count_causes(const std::vector<TeacherForcedStroke>& strokes,
                  const std::map<StrokeId, CassieConstraintLog>* logs, double near,
                  std::map<std::string, CauseCount>& counts);

// An aligned table: cause, ends, snap disagreements, % of `endpoints`,
// largest first.
std::string cause_table(const std::map<std::string, CauseCount>& counts, std::size_t endpoints);

// Where the endpoint distance comes from (issue #15: the ends land mm away
// from CASSIE's even when both snap the same way): per end, the distance (m)
// from the reference end to the output end matched to it, and from each of
// them to the raw stroke's end there (first or last sample: who moved the
// end), grouped by the pair of snap kinds ("CASSIE curve, we curve", "free"
// for none), lines apart, and for ends free in both by whether a hook was cut
// at our end (the cassie corrector's hook_cut_start / hook_cut_end).
struct EndDistances {
  std::vector<double> to_reference, reference_to_raw, output_to_raw;
};

// `raw_ends`: each stroke's first and last sample; strokes missing from it
// add no raw distances.
void add_end_distances(const std::vector<TeacherForcedStroke>& strokes,
                       const std::map<StrokeId, std::array<Vec3, 2>>& raw_ends,
                       std::map<std::string, EndDistances>& distances);

// The first and last sample of every stroke of the recording.
std::map<StrokeId, std::array<Vec3, 2>> raw_stroke_ends(const Recording& recording);

// An aligned table: group, ends, then median and p90 (mm) of the three
// distances, largest group first.
std::string end_distance_table(const std::map<std::string, EndDistances>& distances);

// Per-stroke decisions of a corrector, from the constraints it returned:
// a planarity soft term (`planar` / `axis_plane`, item 14), an enforced
// `closure` (item 10), an `on_surface` term (item 20).
struct StrokeDecisions {
  bool planar = false, closed = false, on_surface = false;
};
StrokeDecisions output_decisions(const TeacherForcedStroke& r);

// A confusion table of one decision: CASSIE's flag (raw_data) against ours.
struct DecisionCount {
  std::size_t both = 0, cassie_only = 0, ours_only = 0, neither = 0;
  std::size_t strokes() const { return both + cassie_only + ours_only + neither; }
  double agreement() const { return strokes() ? double(both + neither) / double(strokes()) : 0.0; }
};
struct DecisionCounts {
  DecisionCount planar, closed, on_surface;
  std::array<DecisionCount, 3> twins;  // the same, for mirrored twins (their twin's flags)
  // Strokes planar in both: how closely each curve follows the plane of our
  // E_planar term (m, plane_residual of its control points with our normal).
  std::vector<double> ours_to_plane, cassie_to_plane;
};

// Adds every compared stroke whose log has the flag: CASSIE's `planar`
// against ours for strokes that are poly-Béziers in both (CASSIE flags no
// line planar), `closedLoop` and `onSurface` for all. Strokes with a
// mirrored twin's log count in `twins` only.
void count_decisions(const std::vector<TeacherForcedStroke>& strokes,
                     const std::map<StrokeId, CassieConstraintLog>& logs, DecisionCounts& counts);

// An aligned table: decision, strokes, the four cells, agreement; a
// decision no stroke has a flag for is left out. Then the median and p90 of
// the two curves' distances to our plane.
std::string decision_table(const DecisionCounts& counts);

}  // namespace sketchlab::cli
