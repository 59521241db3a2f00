#include "sketchlab/session.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sketchlab/draw_plane.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/recording/event_json.hpp"

namespace sketchlab {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

void count_edit(const Edit& e, StepReport& r) {
  r.curves_added += static_cast<int>(e.curves_added.size());
  r.curves_removed += static_cast<int>(e.curves_removed.size());
  r.curves_replaced += static_cast<int>(e.curves_replaced.size());
  r.patches_added += static_cast<int>(e.patches_added.size());
  r.patches_removed += static_cast<int>(e.patches_removed.size());
}

// A surfacer may only touch patches; anything else would bypass the corrector.
std::string check_patch_only(const Edit& e) {
  if (!e.curves_added.empty() || !e.curves_replaced.empty() || !e.curves_removed.empty() ||
      !e.nodes_added.empty() || !e.nodes_replaced.empty() || !e.nodes_removed.empty() ||
      e.counters)
    return "surfacer returned an edit that changes curves or nodes; only patches are allowed";
  return {};
}

// Empty when every sample of `s` is within the recording format's bounds
// (event_json.hpp), else the reason naming the first one beyond them. Some
// stroke-sized passes step through a stroke in fixed increments: at 1e12 m
// they never finish.
std::string beyond_bounds(const Stroke& s, const char* what) {
  for (std::size_t i = 0; i < s.samples.size(); ++i) {
    const double x = s.samples[i].position.cwiseAbs().maxCoeff();
    const bool far = x > recording_max_coordinate;
    if (far || std::abs(s.samples[i].time) > recording_max_time) {
      std::ostringstream text;
      text << "stroke " << s.id << " sample " << i << what
           << (far ? " has a coordinate of magnitude " : " has time ")
           << (far ? x : s.samples[i].time) << "; strokes are limited to "
           << (far ? recording_max_coordinate : recording_max_time)
           << (far ? (s.samples_are_pixels ? " px" : " m") : " s") << ", as recordings are";
      return text.str();
    }
  }
  return {};
}

// A surfacer call that cannot throw: whatever escapes it (a plugin built
// without the wrappers of plugin_api.hpp) becomes the update's error.
template <class F>
SurfaceUpdate guarded_surfacer(F&& call) {
  SurfaceUpdate failed;
  try {
    return call();
  } catch (const BudgetExceeded& e) {
    failed.error = e.message();
  } catch (const std::exception& e) {
    failed.error = e.what();
  } catch (...) {
    failed.error = "unknown exception";
  }
  return failed;
}

}  // namespace

Edit freehand_edit(const Stroke& stroke, const Sketch& sketch, const PreprocessParams& params) {
  Edit edit;
  edit.curves_added.push_back(make_network_curve(sketch.network.next_curve_id(),
                                                 preprocess_stroke(stroke, params).curve,
                                                 curve_layer(stroke.layer), stroke.id));
  return edit;
}

Session::Session(const Workspace& workspace, std::shared_ptr<Corrector> corrector,
                 std::shared_ptr<Surfacer> surfacer, PreprocessParams fallback,
                 double time_budget_s)
    : corrector_(std::move(corrector)),
      surfacer_(std::move(surfacer)),
      fallback_(fallback),
      time_budget_s_(time_budget_s) {
  if (!corrector_) throw std::invalid_argument("Session: a corrector is required");
  if (!(time_budget_s_ > 0.0))
    throw std::invalid_argument("Session: the time budget must be > 0 seconds");
  sketch_.workspace = workspace;
}

void Session::apply_step(const Edit& edit, HistoryEntry& entry, StepReport& report) {
  if (edit.empty()) return;
  Edit inverse = sketch_.network.apply(edit);
  count_edit(edit, report);
  entry.steps.push_back({edit, std::move(inverse)});
}

void Session::apply_surfacer(const SurfaceUpdate& update, HistoryEntry& entry, StepReport& report) {
  if (!update.error.empty()) {
    report.error = "surfacer: " + update.error;
    return;
  }
  if (auto why = check_patch_only(update.edit); !why.empty()) {
    report.error = why;
    return;
  }
  try {
    apply_step(update.edit, entry, report);
  } catch (const std::invalid_argument& e) {
    report.error = std::string("surfacer returned an invalid edit: ") + e.what();
  }
}

void Session::commit(HistoryEntry entry) {
  if (entry.steps.empty()) return;
  sketch_.history.done.push_back(std::move(entry));
  last_cleared_ = std::move(sketch_.history.undone);
  sketch_.history.undone.clear();
  last_committed_ = true;
}

void Session::undo_entry(Network& network, HistoryEntry& entry, StepReport* report) {
  for (auto it = entry.steps.rbegin(); it != entry.steps.rend(); ++it) {
    if (report) count_edit(it->inverse, *report);
    it->forward = network.apply(it->inverse);
  }
}

void Session::redo_entry(Network& network, HistoryEntry& entry, StepReport* report) {
  for (auto& step : entry.steps) {
    if (report) count_edit(step.forward, *report);
    step.inverse = network.apply(step.forward);
  }
}

StepReport Session::handle_stroke(const Stroke& input, StepReport report) {
  report.stroke = input.id;
  if (auto why = validate(input); !why.empty()) {
    report.error = why;
    return report;
  }
  if (input.samples.size() > max_stroke_samples) {
    report.error = "stroke " + std::to_string(input.id) + " has " + std::to_string(input.samples.size()) +
                   " samples; a stroke may have at most " + std::to_string(max_stroke_samples);
    return report;
  }
  if (auto why = beyond_bounds(input, ""); !why.empty()) {
    report.error = why;
    return report;
  }
  if (sketch_.strokes.count(input.id)) {
    report.error = "stroke id " + std::to_string(input.id) + " was already used in this session";
    return report;
  }
  // A 2D stroke is lifted (or corrected) through its camera's rays: a
  // singular camera would make every ray computation throw.
  if (input.is_2d()) {
    if (auto why = view_problem(*input.view); !why.empty()) {
      report.error = "stroke " + std::to_string(input.id) + ": " + why;
      return report;
    }
  }
  Stroke stroke = input;
  if (stroke.layer == Layer::automatic) stroke.layer = sketch_.mode;
  sketch_.strokes.emplace(stroke.id, stroke);

  HistoryEntry entry{"stroke", stroke.id, {}};
  const auto start = std::chrono::steady_clock::now();
  // The sketch keeps the stroke as recorded; world-space fitting gets a 2D
  // stroke drawn on a plane lifted onto it.
  Edit edit;
  // Nothing below may escape: the stroke stays recorded and its error names
  // what went wrong.
  try {
    std::string lift_error;
    const bool pixels_wanted =
        sketch_.correction_enabled && corrector_->stroke_space() == StrokeSpace::pixels;
    const Stroke world = pixels_wanted ? stroke : lift_to_draw_plane(stroke, lift_error);
    if (lift_error.empty()) lift_error = beyond_bounds(world, " lifted onto its draw plane");
    if (!lift_error.empty()) {
      report.error = lift_error;
      return report;
    }
    if (sketch_.correction_enabled) {
      Correction c = corrector_->correct(world, sketch_);
      report.corrected = true;
      report.stats = std::move(c.stats);
      report.constraints = std::move(c.constraints);
      if (!c.error.empty()) {
        report.error = "corrector: " + c.error;
        return report;
      }
      edit = std::move(c.edit);
    } else {
      edit = freehand_edit(world, sketch_, fallback_);
    }
  } catch (const BudgetExceeded& e) {
    report.error = "stroke " + std::to_string(stroke.id) + ": " + e.message();
    return report;
  } catch (const std::exception& e) {
    report.error = e.what();
    return report;
  }
  try {
    apply_step(edit, entry, report);
  } catch (const std::invalid_argument& e) {
    report.error = std::string("corrector returned an invalid edit: ") + e.what();
    return report;
  }
  if (surfacer_ && !entry.steps.empty())
    apply_surfacer(guarded_surfacer([&] { return surfacer_->update(sketch_, entry.steps.back().forward); }),
                   entry, report);
  report.latency_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  commit(std::move(entry));
  return report;
}

StepReport Session::remove_curves(const std::vector<CurveId>& curves, const std::string& action,
                                  StepReport report) {
  if (curves.empty()) {
    report.error = action + ": no curve to delete";
    return report;
  }
  HistoryEntry entry{action, std::nullopt, {}};
  Edit edit;
  edit.curves_removed = curves;
  apply_step(edit, entry, report);
  if (surfacer_)
    apply_surfacer(guarded_surfacer([&] { return surfacer_->update(sketch_, edit); }), entry, report);
  commit(std::move(entry));
  return report;
}

void Session::surfacer_command(const SurfaceCommand& command, const std::string& action,
                               StepReport& report) {
  if (!surfacer_) {
    report.error = action + ": this stack has no surfacer";
    return;
  }
  HistoryEntry entry{action, std::nullopt, {}};
  apply_surfacer(guarded_surfacer([&] { return surfacer_->command(sketch_, command); }), entry, report);
  commit(std::move(entry));
}

StepReport Session::handle(const Event& event) {
  StepReport report;
  report.event = event_kind(event.payload);
  report.time = event.time;
  Reversal reversal{sketch_.workspace, sketch_.mode, sketch_.correction_enabled};
  const BudgetScope budget(time_budget_s_);
  const std::size_t strokes_before = sketch_.strokes.size();
  last_committed_ = false;
  auto undo_redo = [&](std::vector<HistoryEntry>& from, std::vector<HistoryEntry>& to, bool undo) {
    if (from.empty()) {
      report.error = undo ? "nothing to undo" : "nothing to redo";
      return;
    }
    reversal.moved_entry = from.back();
    HistoryEntry entry = std::move(from.back());
    from.pop_back();
    if (undo)
      undo_entry(sketch_.network, entry, &report);
    else
      redo_entry(sketch_.network, entry, &report);
    report.stroke = entry.stroke;
    to.push_back(std::move(entry));
    reversal.moved = undo ? Reversal::Move::undo : Reversal::Move::redo;
  };

  std::visit(
      Overloaded{
          [&](const StrokeEvent& e) { report = handle_stroke(e.stroke, std::move(report)); },
          [&](const UndoEvent&) { undo_redo(sketch_.history.done, sketch_.history.undone, true); },
          [&](const RedoEvent&) { undo_redo(sketch_.history.undone, sketch_.history.done, false); },
          [&](const DeleteNearEvent& e) {
            auto hits = sketch_.network.curves_near(e.point, e.radius);
            std::vector<CurveId> ids;
            if (!hits.empty()) ids.push_back(hits.front().curve);
            report = remove_curves(ids, "delete", std::move(report));
          },
          [&](const DeleteStrokeEvent& e) {
            report.stroke = e.stroke;
            report = remove_curves(curves_of_stroke(sketch_, e.stroke), "delete", std::move(report));
          },
          [&](const ModeEvent& e) { sketch_.mode = e.mode; },
          [&](const WorkspaceEvent& e) {
            if (!(e.workspace.scale > 0.0) || !std::isfinite(e.workspace.scale))
              report.error = "workspace scale must be a finite number > 0";
            else
              sketch_.workspace = e.workspace;
          },
          [&](const CorrectionEvent& e) { sketch_.correction_enabled = e.enabled; },
          [&](const AddPatchEvent& e) { surfacer_command(e, "add_patch", report); },
          [&](const DeletePatchEvent& e) { surfacer_command(e, "delete_patch", report); },
          [&](const RecomputeSurfaceEvent&) {
            if (!surfacer_) {
              report.error = "recompute_surface: this stack has no surfacer";
              return;
            }
            HistoryEntry entry{"recompute_surface", std::nullopt, {}};
            const auto start = std::chrono::steady_clock::now();
            const SurfaceUpdate update = guarded_surfacer([&] { return surfacer_->recompute(sketch_); });
            report.latency_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            // The surfacer's figures (constraints, residuals, times) travel with the step.
            for (const auto& [name, value] : update.stats) report.stats.extra["surfacer." + name] = value;
            apply_surfacer(update, entry, report);
            commit(std::move(entry));
          },
          [&](const ReferenceEvent& e) {
            auto& slot = references_[e.track];
            reversal.reference = {e.track, e.stroke};
            if (auto it = slot.find(e.stroke); it != slot.end()) reversal.previous_reference = it->second;
            slot[e.stroke] = e.curve;
          },
          [&](const RelationEvent& e) {
            relations_[e.track].push_back(e);
            reversal.relation_track = e.track;
          },
      },
      event.payload);
  if (sketch_.strokes.size() != strokes_before) reversal.stroke_added = report.stroke;
  if (last_committed_) {
    reversal.committed = true;
    reversal.cleared_redo = std::move(last_cleared_);
  }
  last_cleared_.clear();
  journal_.push_back(std::move(reversal));
  return report;
}

bool Session::revert_last() {
  if (journal_.empty()) return false;
  Reversal r = std::move(journal_.back());
  journal_.pop_back();
  auto& history = sketch_.history;
  if (r.committed) {
    undo_entry(sketch_.network, history.done.back(), nullptr);
    history.done.pop_back();
    history.undone = std::move(r.cleared_redo);
  }
  if (r.moved == Reversal::Move::undo) {
    redo_entry(sketch_.network, history.undone.back(), nullptr);
    history.undone.pop_back();
    history.done.push_back(std::move(*r.moved_entry));
  } else if (r.moved == Reversal::Move::redo) {
    undo_entry(sketch_.network, history.done.back(), nullptr);
    history.done.pop_back();
    history.undone.push_back(std::move(*r.moved_entry));
  }
  if (r.stroke_added) sketch_.strokes.erase(*r.stroke_added);
  if (r.reference) {
    auto& slot = references_[r.reference->first];
    if (r.previous_reference)
      slot[r.reference->second] = std::move(*r.previous_reference);
    else
      slot.erase(r.reference->second);
    if (slot.empty()) references_.erase(r.reference->first);
  }
  if (r.relation_track) {
    auto& list = relations_[*r.relation_track];
    list.pop_back();
    if (list.empty()) relations_.erase(*r.relation_track);
  }
  sketch_.workspace = r.workspace;
  sketch_.mode = r.mode;
  sketch_.correction_enabled = r.correction_enabled;
  return true;
}

}  // namespace sketchlab
