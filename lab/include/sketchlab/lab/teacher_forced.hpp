#pragma once
// Teacher-forced comparison of a corrector with a reference track (e.g.
// CASSIE's own neatened curves in imported sessions), generic over
// correctors.
//
// For each stroke of a recording the sketch is rebuilt from the reference
// curves alive at that moment (strokes created strictly earlier and not yet
// deleted, each on its stroke's layer, with nodes where a reference curve's
// joints lie on earlier curves),
// the workspace of the WorkspaceEvents so far and the stroke's zoom; the
// corrector corrects the raw stroke on that sketch, and its curve is compared
// with the reference curve of the same stroke. Errors therefore never
// accumulate: every stroke starts from the reference history.
// Undo/redo/patch events are not replayed (imported CASSIE sessions have none).
// Reference curves go on their stroke's layer.
// Reference patches (options.patches, e.g. CASSIE's patch log:
// read_cassie_patches) are teacher-forced the same way: each stroke sees the
// patches the reference had when it was drawn, each meshed by a surfacer
// over the reference curves of its strokes.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sketchlab/lab/distribution.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/plugin/surfacer.hpp"
#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

// A patch of the reference system over the reference curves of `strokes`:
// in the rebuilt sketch from `created` (strictly earlier strokes do not see
// it) until `deleted` or until one of its strokes is deleted.
struct ReferencePatch {
  std::int64_t id = 0;  // the reference's own id (warnings name it)
  std::vector<StrokeId> strokes;
  double created = 0.0;
  std::optional<double> deleted;
  bool automatic = true;
};

struct TeacherForcedOptions {
  std::string track = "cassie";
  // An endpoint "snapped" when it lies within this distance (m) of another
  // alive curve, a node, a grid point (grid on) or the mirror plane (mirror
  // on). The same test is applied to reference and corrected curves.
  double snap_tolerance = 1e-4;
  int resample = 32;  // points per curve for the deviation (by arclength), >= 2
  // Reference patches and the surfacer that meshes them (not owned; both or
  // neither). A patch is meshed once, when the first stroke after its
  // creation is drawn: the surfacer gets a sketch holding only the curves of
  // its strokes (same ids, nodes where they meet each other) and an
  // AddPatchEvent at the centroid of those nodes, and the patch it adds goes
  // into the rebuilt sketch. A patch the surfacer cannot make (or one over a
  // stroke without a reference curve) is left out with a warning.
  std::vector<ReferencePatch> patches;
  Surfacer* surfacer = nullptr;
  // In that sketch, a joint of one of the patch's curves within this (m) of
  // another of them is a node too: CASSIE's graph joins curves whose ends
  // stop up to a few mm off (vintage_car: 0.2-2.6 mm), where the rebuilt
  // network, with nodes only at exact joints, does not.
  double patch_junction = 3e-3;
};

struct TeacherForcedStroke {
  StrokeId stroke = 0;
  double time = 0.0;
  bool corrected = false;  // the corrector was called (the stroke is valid)
  bool compared = false;   // both curves exist
  std::string error;       // corrector error or missing curve/reference
  bool reference_line = false, output_line = false;
  double endpoint_distance = 0.0;  // m, worse of the two ends (best orientation)
  double mean_deviation = 0.0;     // m, mean distance of arclength-resampled points
  double max_deviation = 0.0;      // m, max of the same
  // Two-sided (Hausdorff) distance (m) from each curve to the stroke's raw
  // samples (geometry/hausdorff.hpp): a curve that leaves its stroke's
  // neighbourhood, ours or a quirk of the reference's (CASSIE's vintage_car
  // stroke 436 has a control point 5 m off), shows here. Set when compared
  // and the samples are world positions (not for pixels of 2D input).
  std::optional<double> output_stroke_distance, reference_stroke_distance;
  // Snap of each end: "" (free), "curve", "node", "grid" or "mirror".
  std::array<std::string, 2> reference_snap, output_snap;
  // For the mismatch breakdown (fidelity --causes). Ends are indexed like the
  // reference's; `reversed`: output end k is the output curve's end 1 - k.
  bool reversed = false;
  bool reference_closed = false, output_closed = false;  // ends coincide (1e-9 m) or closed
  std::array<Vec3, 2> reference_end{Vec3::Zero(), Vec3::Zero()}, output_end{Vec3::Zero(), Vec3::Zero()};
  // Distance (m) from reference end k to the nearest target of the output's
  // position constraints (intersection, grid point, mirror plane; infinity if
  // none) and whether that constraint was enforced.
  std::array<double, 2> candidate_distance{0.0, 0.0};
  std::array<bool, 2> candidate_enforced{false, false};
  int constraints_considered = 0, constraints_enforced = 0;
  CorrectionStats stats;
  // The two curves compared (set when `compared`), for analyses beyond the
  // figures above (e.g. `sketchlab.teacher_forced` in Python).
  Curve reference_curve, output_curve;
  std::vector<Constraint> constraints;  // the corrector's, as it returned them
  double latency_ms = 0.0;  // wall time of Corrector::correct
  double cpu_ms = 0.0;      // CPU time of the calling thread in it (thread_cpu_ms)
  int patches = 0;          // patches in the rebuilt sketch when it was corrected
};

// CPU time consumed by the calling thread (ms, CLOCK_THREAD_CPUTIME_ID): on a
// shared machine wall time also measures other processes.
double thread_cpu_ms();

// The reference tracks of a recording (ReferenceEvent::track), sorted.
std::vector<std::string> reference_tracks(const Recording& recording);

// Throws std::invalid_argument for resample < 2, a negative tolerance, or a
// recording without reference curves on options.track (the message names
// the tracks it has), or patches without a surfacer, or a negative
// patch_junction. `warnings`, when given,
// receives one line per reference patch left out (its id and why).
std::vector<TeacherForcedStroke> teacher_forced(const Recording& recording, Corrector& corrector,
                                                const TeacherForcedOptions& options = {},
                                                std::vector<std::string>* warnings = nullptr);

struct TeacherForcedSummary {
  std::size_t strokes = 0, compared = 0, errors = 0;
  Distribution endpoint_distance, mean_deviation, max_deviation;
  Distribution output_stroke_distance, reference_stroke_distance;  // over the strokes that have them
  Distribution latency_ms, cpu_ms;   // over every corrected stroke (wall, thread CPU)
  std::size_t endpoints = 0;         // 2 per compared stroke
  std::size_t snap_agreements = 0;   // snapped in both or in neither
  std::size_t snap_kind_agreements = 0;  // same snap kind ("" = free counts as a kind)
  std::size_t reference_snaps = 0, output_snaps = 0, both_snaps = 0;
  std::size_t line_agreements = 0;   // same kind (line / poly-Bézier)
  static double ratio(std::size_t a, std::size_t b) { return b ? double(a) / double(b) : 0.0; }
  double snap_agreement() const { return ratio(snap_agreements, endpoints); }
  double snap_kind_agreement() const { return ratio(snap_kind_agreements, endpoints); }
  double snap_recall() const { return ratio(both_snaps, reference_snaps); }
  double snap_precision() const { return ratio(both_snaps, output_snaps); }
  double line_agreement() const { return ratio(line_agreements, compared); }
};
TeacherForcedSummary summarize(const std::vector<TeacherForcedStroke>& strokes);

// The fidelity-suite group of a recording (header.source of the CASSIE
// importer): "showcase" for free-creation sessions, else the CASSIE system
// capitalised ("Freehand", "Armature", "Patch"); "other" without a system.
std::string fidelity_group(const RecordingHeader& header);

// One CSV row per stroke, with a header line.
std::string teacher_forced_csv(const std::vector<TeacherForcedStroke>& strokes);

}  // namespace sketchlab
