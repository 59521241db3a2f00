#pragma once
// Incremental comparison with CASSIE, the surfacer's counterpart of
// teacher-forced: CASSIE's own curves are replayed in their creation order
// (deletions included) through a Session whose corrector adds each curve with
// CASSIE's graph (cassie_graph_edit.hpp) and whose surfacer is this plugin;
// the patches the surfacer creates and removes, and at which event, are
// compared with CASSIE's patch log (raw_data: allCreatedPatches, foundByAlgo,
// add-surface times).
//
// Events are grouped by time: the strokes of a mirrored pair share their
// creation time, and CASSIE logs the patches a stroke event made at that
// event's time (or, rarely, just after). A CASSIE automatic patch belongs to
// the last group at or before its time; one of ours to the group of the
// event that made it. A CASSIE patch is matched along the way when we create
// a patch over the same strokes in the same group (one for one).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cassie_graph_edit.hpp"
#include "cassie_session.hpp"
#include "replay_causes.hpp"
#include "soapfilm_params.hpp"

namespace sketchlab::soapfilm {

struct ReplayOptions {
  CassieGraphParams graph;
  // Replay the user's own patch edits too: an add-patch at the hand position
  // of each manual CASSIE patch, and the deletion of ours matching a patch
  // the user deleted (same strokes). They change what later searches see
  // (a segment bounding two patches), as they did in CASSIE.
  bool user_patch_edits = true;
};

struct ReplayFigures {
  // Along the way (automatic patches only).
  int cassie_created = 0;      // CASSIE automatic patches with an add-surface time
  int ours_created = 0;        // automatic patches we created
  int matched_created = 0;     // same strokes, same event group
  int matched_elsewhere = 0;   // CASSIE's not matched, but we created those strokes at another group
  int ours_removed = 0;        // automatic patches we removed (crossed, or a boundary curve deleted)
  // CASSIE's automatic patches a later stroke broke (cassie_breaks.hpp), and
  // of those, the ones we removed over the same strokes at the same event.
  int cassie_broken = 0, matched_broken = 0;
  // At the end: CASSIE's automatic patches not deleted by hand, not broken
  // (cassie_breaks.hpp), whose strokes are all alive, vs our automatic
  // patches alive (unique stroke sets).
  int cassie_final = 0, ours_final = 0, matched_final = 0;
  // The final-network comparison (cassie_graph.hpp) on the network this
  // replay built: every segment of it searched, the cycles' stroke sets vs
  // cassie_final. Against the same figure on CASSIE's exact graph it
  // separates what the rebuilt graph costs from what the walk costs.
  int rebuilt_ours = 0, rebuilt_found = 0;
  ReplayCauses causes;  // one cause per disagreement above (replay_causes.hpp)
  double recall_created() const { return cassie_created ? double(matched_created) / cassie_created : 0.0; }
  double precision_created() const { return ours_created ? double(matched_created) / ours_created : 0.0; }
  double recall_final() const { return cassie_final ? double(matched_final) / cassie_final : 0.0; }
  double precision_final() const { return ours_final ? double(matched_final) / ours_final : 0.0; }
  ReplayFigures& operator+=(const ReplayFigures& o);
};

struct ReplayEvent {
  std::string kind;       // "stroke", "delete", "add_patch", "delete_patch"
  std::int64_t element = 0;  // CASSIE stroke or patch id
  double time = 0.0;
  std::size_t group = 0;  // index of its time group (stroke events only share groups)
  std::string error;      // what the session reported, if anything
  std::vector<StrokeSet> added, removed;  // our automatic patches (strokes)
  StrokeSet met;  // CASSIE strokes with a node this event added or replaced (its own included)
  double surfacer_wall_ms = 0.0, surfacer_cpu_ms = 0.0;  // this plugin's update/command
  int patches_meshed = 0;
  std::vector<PatchMeshTimings> meshed;  // per patch meshed: CPU ms of each stage
};

// A CASSIE patch counted "no walk closes" (MissingCycle::not_found), and
// where the walks leave it.
struct AstrayMiss {
  std::size_t group = 0;
  double time = 0.0;  // the group's event time
  StrokeSet strokes;
  AstrayDetail at;
  // The CASSIE strokes of at.taken and at.wanted, -1 for none.
  std::int64_t taken = -1, wanted = -1;
};

// One of our automatic patches CASSIE never made (ReplayCauses::extra_other),
// as it was when we made it.
struct ExtraPatch {
  std::size_t group = 0;
  double time = 0.0;
  std::string kind;            // the event that made it ("stroke", "delete", ...)
  std::int64_t element = 0;    // its CASSIE stroke
  StrokeSet strokes;
  int pieces = 0;              // graph segments of the cycle
  int sharp_nodes = 0;         // its nodes that are sharp (item 23)
  int revisited = 0;           // its nodes the cycle passes twice (item 24 allows it)
  int max_degree = 0;          // most graph segments at one of its nodes
  int broken_here = 0;         // our patches the same event removed
  std::vector<StrokeSet> cassie_here;  // CASSIE's automatic patches made at that group
  std::optional<std::size_t> removed_at;  // group where we removed it, if we did
};

// A cycle made at one event by CASSIE and at another by us (the pairs of
// ReplayCauses::miss_elsewhere and extra_elsewhere), with what happened at
// each of the two events. For each stroke set, CASSIE's unmatched creations
// and ours are paired in time order; a creation left over has no pair.
struct TimingPair {
  StrokeSet strokes;
  std::optional<std::size_t> cassie, ours;  // the two groups
  std::int64_t youngest = 0;   // the cycle's stroke created last
  std::size_t youngest_group = 0;  // the group that created it
  // At CASSIE's group: its event's strokes met a stroke of the cycle
  // (made or reused a node on it) without being in it; one of our patches
  // over these strokes was alive when it began; we removed one there;
  // CASSIE had made a patch over these strokes at an earlier group.
  bool met_at_cassie = false, ours_alive_at_cassie = false, ours_removed_at_cassie = false,
       cassie_made_before = false;
  // We made a patch over the same strokes at CASSIE's group too (matched to
  // another of CASSIE's there: two cycles over one stroke set).
  bool ours_same_event = false;
  // At our group: an earlier patch of ours over these strokes was broken by
  // a stroke (removed at a stroke event), so ours is a remake.
  bool ours_broken_before = false;
};

// One of CASSIE's breaks inferred from its log (cassie_breaks.hpp) at which
// we did not remove a patch over the same strokes (ReplayFigures::
// cassie_broken less matched_broken).
struct MissedBreak {
  StrokeSet strokes;
  std::optional<std::size_t> group;  // the group of CASSIE's break
  bool ours_alive = false;  // a patch of ours over these strokes was alive when that group began
  bool ours_ever = false;   // we made one over these strokes at some event
};

struct ReplayResult {
  std::vector<ReplayEvent> events;  // in replay order
  ReplayFigures figures;
  std::vector<AstrayMiss> astray;  // figures.causes.miss_not_found of them
  std::vector<ExtraPatch> extras;  // figures.causes.extra_other of them
  std::vector<TimingPair> timing;  // the cycles made at another event, both ways
  std::vector<MissedBreak> missed_breaks;  // figures.cassie_broken - figures.matched_broken of them
  std::vector<std::string> warnings;  // the session loader's and the replay's
  Network network;  // the replay's network at the end
};

// A two-sample stroke with id `id`: stands in for a stroke whose curve is
// given (CASSIE's, or a test's), since the session checks samples and the
// surfacer never reads them.
Stroke placeholder_stroke(StrokeId id);

// Replays `session` with a fresh surfacer of parameters `params`.
ReplayResult replay_cassie_session(const CassieSession& session, const SoapfilmParams& params,
                                   const ReplayOptions& options = {});

}  // namespace sketchlab::soapfilm
