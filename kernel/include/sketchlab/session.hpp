#pragma once
// A session folds input events through a plugin stack into a Sketch.
//
// Invariant: sketch() is exactly the fold of the events handled so far; the
// same events through the same stack (same plugins, parameters and build)
// give the same sketch bit for bit. Undo applies the inverse edits of the
// last history entry, which equals folding one edit fewer because correctors
// keep no hidden state between strokes.
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "sketchlab/constraint.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/plugin/budget.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/plugin/surfacer.hpp"
#include "sketchlab/preprocess/preprocess.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab {

// What handling one event did, for statistics and viewers.
struct StepReport {
  EventKind event = EventKind::stroke;
  double time = 0.0;               // event time (s)
  std::optional<StrokeId> stroke;  // for stroke events
  double latency_ms = 0.0;         // wall time of the corrector + surfacer (not deterministic)
  bool corrected = false;          // the corrector ran (correction on, stroke accepted)
  CorrectionStats stats;
  std::vector<Constraint> constraints;  // what the corrector considered
  int curves_added = 0, curves_removed = 0, curves_replaced = 0;
  int patches_added = 0, patches_removed = 0;
  // Non-empty when something was refused or failed (invalid stroke, plugin
  // error, nothing to undo). The event is still part of the session.
  std::string error;
};

// Strokes with more samples are refused (StepReport::error): 100 s of input
// at 1 kHz, 500 times the longest bundled stroke. Some of the correctors'
// stroke-sized passes grow faster than linearly with the sample count.
inline constexpr std::size_t max_stroke_samples = 100000;

class Session {
 public:
  // `corrector` must not be null; `surfacer` may be. Fallback fitting (used
  // when correction is toggled off) uses `fallback` preprocessing parameters.
  // Each event gets `time_budget_s` seconds (> 0) of corrector and surfacer
  // time (plugin/budget.hpp).
  Session(const Workspace& workspace, std::shared_ptr<Corrector> corrector,
          std::shared_ptr<Surfacer> surfacer, PreprocessParams fallback = {},
          double time_budget_s = default_time_budget_s);

  // Never throws for anything a plugin or an event does: an invalid stroke, a
  // camera that cannot map its pixels, a plugin error or exception, an
  // exceeded time budget all become report.error, and the session goes on
  // (a refused stroke's raw samples stay recorded when it reached the
  // corrector).
  StepReport handle(const Event& event);

  // Takes back the last handled event, exactly: afterwards sketch(),
  // references() and relations() equal those of a session that handled one
  // event fewer (history, redo stack and id counters included). Stepping
  // back in a replay is this, so it runs through the inverse edits (an undone
  // stroke's edits are not recomputed). Returns false when no event is left.
  bool revert_last();
  // Events handled and not reverted.
  std::size_t events_handled() const { return journal_.size(); }

  const Sketch& sketch() const { return sketch_; }
  // Reference curves by track then stroke (from ReferenceEvents).
  const std::map<std::string, std::map<StrokeId, Curve>>& references() const { return references_; }
  // Intended relations by track, in event order (from RelationEvents).
  const std::map<std::string, std::vector<RelationEvent>>& relations() const { return relations_; }

 private:
  StepReport handle_stroke(const Stroke& stroke, StepReport report);
  void apply_surfacer(const SurfaceUpdate& update, HistoryEntry& entry, StepReport& report);
  void apply_step(const Edit& edit, HistoryEntry& entry, StepReport& report);
  void commit(HistoryEntry entry);
  void surfacer_command(const SurfaceCommand& command, const std::string& action, StepReport& report);
  StepReport remove_curves(const std::vector<CurveId>& curves, const std::string& action,
                           StepReport report);

  // What revert_last() needs to take one event back: the values it
  // overwrote and the history moves it made (network changes are all in the
  // history entries, with their inverses).
  struct Reversal {
    Workspace workspace;
    Layer mode = Layer::automatic;
    bool correction_enabled = true;
    std::optional<StrokeId> stroke_added;
    bool committed = false;                  // pushed an entry onto history.done
    std::vector<HistoryEntry> cleared_redo;  // what that commit cleared
    enum class Move { none, undo, redo } moved = Move::none;
    // The moved entry as it was: undoing recomputes its forward edits (and
    // redoing its inverses), which can differ in form from the originals.
    std::optional<HistoryEntry> moved_entry;
    std::optional<std::pair<std::string, StrokeId>> reference;  // track, stroke
    std::optional<Curve> previous_reference;
    std::optional<std::string> relation_track;
  };
  static void undo_entry(Network& network, HistoryEntry& entry, StepReport* report);
  static void redo_entry(Network& network, HistoryEntry& entry, StepReport* report);

  Sketch sketch_;
  std::vector<Reversal> journal_;  // one per handled event
  std::vector<HistoryEntry> last_cleared_;
  bool last_committed_ = false;
  std::shared_ptr<Corrector> corrector_;
  std::shared_ptr<Surfacer> surfacer_;
  PreprocessParams fallback_;
  double time_budget_s_;
  std::map<std::string, std::map<StrokeId, Curve>> references_;
  std::map<std::string, std::vector<RelationEvent>> relations_;
};

// The edit that adds `stroke` as one fitted curve (preprocessing only, no
// constraints): the papers' no-auto-correct baseline, shared by the freehand
// corrector and by sessions with correction toggled off. 2D strokes are fitted
// in pixel space (z = 0).
Edit freehand_edit(const Stroke& stroke, const Sketch& sketch, const PreprocessParams& params);

}  // namespace sketchlab
