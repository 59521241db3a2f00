#pragma once
// Input events: what a recording stores and what inputs produce. A session is
// the fold of its events through a plugin stack (session.hpp).
#include <map>
#include <string>
#include <variant>

#include <vector>

#include "sketchlab/constraint.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab {

struct StrokeEvent { Stroke stroke; bool operator==(const StrokeEvent&) const = default; };
struct UndoEvent { bool operator==(const UndoEvent&) const = default; };
struct RedoEvent { bool operator==(const RedoEvent&) const = default; };
// Delete the curve nearest to `point` within `radius` metres.
struct DeleteNearEvent {
  Vec3 point = Vec3::Zero();
  double radius = 0.05;
  bool operator==(const DeleteNearEvent&) const = default;
};
// Delete every curve a stroke produced (imported sessions know the stroke).
struct DeleteStrokeEvent { StrokeId stroke = 0; bool operator==(const DeleteStrokeEvent&) const = default; };
struct ModeEvent { Layer mode = Layer::automatic; bool operator==(const ModeEvent&) const = default; };
// The whole workspace after a change (zoom, mirror, grid).
struct WorkspaceEvent { Workspace workspace; bool operator==(const WorkspaceEvent&) const = default; };
struct CorrectionEvent { bool enabled = true; bool operator==(const CorrectionEvent&) const = default; };
struct AddPatchEvent { Vec3 point = Vec3::Zero(); bool operator==(const AddPatchEvent&) const = default; };
struct DeletePatchEvent { Vec3 point = Vec3::Zero(); bool operator==(const DeletePatchEvent&) const = default; };
// Ask the surfacer for a global recompute (Surfacer::recompute): surfacers too
// slow to follow every stroke (e.g. Hermite RBF) update only on request and at
// the end of a replay.
struct RecomputeSurfaceEvent { bool operator==(const RecomputeSurfaceEvent&) const = default; };
// A curve another system produced for a stroke (e.g. CASSIE's own output),
// kept for comparison; it does not change the sketch.
struct ReferenceEvent {
  StrokeId stroke = 0;
  std::string track;  // "cassie", "ground_truth", ...
  Curve curve;
  bool operator==(const ReferenceEvent&) const = default;
};

// A relation the strokes were meant to satisfy (e.g. synthetic ground truth):
// `parameters` are the curve parameters t where it holds, one per stroke, on
// each stroke's reference curve of the same track (intersection, coincident
// point); empty for kinds without a location (parallel, planar, ...). Like a
// reference, it does not change the sketch.
struct RelationEvent {
  std::string track;  // "ground_truth", ...
  ConstraintKind kind = ConstraintKind::coincident_point;
  std::vector<StrokeId> strokes;
  std::vector<double> parameters;
  bool operator==(const RelationEvent&) const = default;
};

using EventPayload = std::variant<StrokeEvent, UndoEvent, RedoEvent, DeleteNearEvent,
                                  DeleteStrokeEvent, ModeEvent, WorkspaceEvent,
                                  CorrectionEvent, AddPatchEvent, DeletePatchEvent,
                                  ReferenceEvent, RelationEvent, RecomputeSurfaceEvent>;

struct Event {
  double time = 0.0;  // seconds since the session started
  EventPayload payload;
  bool operator==(const Event&) const = default;
};

// The kind of an event: one per EventPayload alternative, in its order.
enum class EventKind {
  stroke, undo, redo, delete_near, delete_stroke, mode, workspace, correction,
  add_patch, delete_patch, reference, relation, recompute_surface,
};
EventKind event_kind(const EventPayload& payload);
// The kind's name as written in recordings and statistics ("stroke", "undo", ...).
std::string_view to_string(EventKind kind);
// to_string(event_kind(payload)).
std::string_view event_type_name(const EventPayload& payload);

// First line of a recording.
struct RecordingHeader {
  int version = 1;
  std::string units = "m";  // "m" for VR sessions, "px" for 2D ones
  Workspace workspace;
  std::map<std::string, std::string> source;  // free-form provenance
  bool operator==(const RecordingHeader&) const = default;
};

inline constexpr int recording_format_version = 1;

}  // namespace sketchlab
