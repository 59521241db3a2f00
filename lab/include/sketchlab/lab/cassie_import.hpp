#pragma once
// Importer for the CASSIE dataset (Yu et al., "CASSIE: Curve and Surface
// Sketching in Immersive Environments", CHI 2021; MIT licence). A session is
// two files: sketch_history/<name>.json (strokes with raw input samples,
// CASSIE's neatened control points, creation and deletion times) and
// raw_data/<name>.json (the app's action log: canvas scale, mirroring, ...).
//
// The recording it produces, events sorted by time (stable):
// - a StrokeEvent per sketch_history entry at its creation_time, in file
//   order: id = CASSIE id, layer automatic, pressure 1, identity orientation,
//   workspace_scale = the canvasScale of the last systemState at or before the
//   creation time (1 if none). CASSIE exports no sample times: they are spread
//   in proportion to arclength from the last systemState strictly before the
//   creation time (CASSIE logs nothing while a stroke is drawn, so that is a
//   lower bound on the stroke's start; 1 s before creation if there is none)
//   to the creation time. Mirrored strokes are separate entries with the same
//   creation time; both are kept.
// - right after each stroke, a ReferenceEvent, track "cassie", holding the
//   neatened curve: a line becomes make_line(a, b); a poly-Bézier becomes the
//   joined cubic poly-Bézier (joints sharp where the tangent turns by more
//   than 45°, closed when its ends coincide exactly).
// - a DeleteStrokeEvent at each deletion_time.
// - a WorkspaceEvent whenever the mirroring flag of systemStates changes
//   (scale = canvasScale at that moment).
// Header: units "m", up +y (Unity), grid from infer_grid over the neatened
// endpoints, mirror plane from infer_mirror_plane over the mirrored pairs,
// mirroring and scale from the first systemState; source = {dataset, license,
// session, system, model, interaction_mode, grid, mirror, sample_times}, plus
// import_warnings (the warnings below, "; "-joined, files named without their
// directory) when there are any.
//
// Real data has quirks; these import with a warning naming the file and the
// stroke id instead of refusing the session:
// - an input sample with a coordinate beyond ±1e6 m (what recordings hold) is
//   dropped;
// - a deletion_time before the creation_time (`flower`) is replaced by the
//   first delete-stroke action (interactionType 2) raw_data logs for the
//   stroke or its mirrored twin after its creation; without one the stroke is
//   never deleted.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sketchlab/recording/recording.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab {

struct ReferencePatch;  // teacher_forced.hpp

// Imports one session from the two files. `session` names it in the header;
// `warnings`, when given, receives the warnings above. Throws
// std::runtime_error naming the file, the stroke id and the field for a
// missing file, malformed JSON, a missing or mistyped field, a control point
// beyond ±1e6 m, a time outside [0, 1e9] s, a canvasScale outside (0, 1e6],
// or an invalid stroke (fewer than 2 samples left) or curve.
Recording import_cassie(const std::filesystem::path& sketch_history_json,
                        const std::filesystem::path& raw_data_json, const std::string& session,
                        std::vector<std::string>* warnings = nullptr);

// Imports <dataset_dir>/sketch_history/<session>.json with
// <dataset_dir>/raw_data/<session>.json.
Recording import_cassie_session(const std::filesystem::path& dataset_dir,
                                const std::string& session,
                                std::vector<std::string>* warnings = nullptr);

// What CASSIE logged for one stroke (raw_data allSketchedStrokes[], a point
// or, in newer exports, an object with its position): the
// targets of the position constraints it applied and rejected (metres), and
// its per-stroke decisions where the export has them (unset otherwise):
// `planar` (item 14's planarity applied), `closedLoop` (item 10's closure;
// newer exports only) and `onSurface` (item 20).
struct CassieConstraintLog {
  std::vector<Vec3> applied, rejected;
  // Per applied constraint, in the order of `applied`: its isIntersection
  // flag (a constraint onto a curve or a node, not a plane or grid point)
  // where the export has it; unset where it logs a bare point (older
  // exports).
  std::vector<std::optional<bool>> applied_intersection;
  std::optional<bool> planar, closed_loop, on_surface;
  bool mirrored_twin = false;  // copied from the drawn twin (CASSIE logs only that one)
};

// Reads every stroke's log from a raw_data/<session>.json, by CASSIE id.
// Throws std::runtime_error naming the file, the element and the field for
// malformed JSON or a missing/mistyped field (a flag, isIntersection
// included, must be true or false); sessions without allSketchedStrokes give
// an empty map.
std::map<StrokeId, CassieConstraintLog> read_cassie_constraint_logs(const std::filesystem::path& raw_data_json);

// CASSIE logs only the stroke drawn, not its mirrored twin (a stroke of the
// same creation time): gives each unlogged twin of `recording` (an imported
// session) its twin's log with the positions reflected in the recording's
// mirror plane (header workspace; nothing without one) and mirrored_twin set.
void add_mirrored_twin_logs(const Recording& recording, std::map<StrokeId, CassieConstraintLog>& logs);

// A patch of CASSIE's log (raw_data allCreatedPatches, with the times of its
// add-surface and delete-surface entries in systemStates, interactionType 3
// and 4, elementID = the patch id).
struct CassiePatchLog {
  std::int64_t id = 0;
  bool automatic = true;             // foundByAlgo
  std::vector<StrokeId> strokes;     // strokesID, sorted, duplicates merged
  std::optional<double> created;     // first add-surface entry (s); unset: never logged
  std::optional<double> deleted;     // first delete-surface entry (s): deleted by hand
};

// Reads the patches of a raw_data/<session>.json in allCreatedPatches order.
// Throws std::runtime_error naming the file, the element and the field for
// malformed JSON or a missing/mistyped field (foundByAlgo true or false,
// strokesID integers >= 0, a time in [0, 1e9] s); sessions without
// allCreatedPatches (older exports, Freehand/Armature) give none.
std::vector<CassiePatchLog> read_cassie_patches(const std::filesystem::path& raw_data_json);

// The patches of the log for the teacher-forced rebuild (teacher_forced.hpp):
// every one with an add-surface time (automatic and manual: CASSIE app,
// item 26), from then until deleted by hand (or, item 27, with a stroke).
std::vector<ReferencePatch> reference_patches(const std::vector<CassiePatchLog>& log);

struct GridInference {
  bool found = false;
  double spacing = 0.0;               // metres
  Vec3 origin = Vec3::Zero();         // (o, o, o)
  std::size_t matched = 0;            // points on the chosen lattice
  std::size_t total = 0;              // points examined
  std::string description;            // human-readable, for header.source
};

// Infers a snapping grid from points a system snapped (e.g. neatened curve
// endpoints): candidate lattices origin + spacing * Z^3 with spacing in
// {1, 0.5, 0.25, 0.2, 0.125, 0.1, 0.05, 0.025} m and origin (o,o,o), o in
// {0, spacing/2}. A point is on a lattice when each coordinate is within
// `tolerance` of it; free-hand points practically never are (chance ~
// (2·tolerance/spacing)^3). A lattice is accepted when at least
// max(3, 0.5 % of the points) lie on it; among those the one holding the most
// points wins, ties going to the coarser spacing, then to origin 0.
GridInference infer_grid(const std::vector<Vec3>& points, double tolerance = 1e-6);

struct MirrorInference {
  bool found = false;
  Vec3 normal = Vec3::UnitX();  // an axis
  double offset = 0.0;          // plane {x : normal·x = offset}
  std::size_t pairs = 0;        // sample pairs used
  std::string description;
};

// Infers an axis-aligned mirror plane from pairs of point sequences that are
// mirror images sample by sample (CASSIE's mirrored stroke twins): every
// pair difference must lie along one axis (other components within
// `tolerance`); the offset is the median midpoint along it. Pairs of
// different lengths are ignored; inconsistent axes give found = false.
MirrorInference infer_mirror_plane(
    const std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>>& twins,
    double tolerance = 1e-6);

}  // namespace sketchlab
