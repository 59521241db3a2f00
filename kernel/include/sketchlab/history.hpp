#pragma once
// Undo/redo over applied edits. An entry groups the steps one user action made
// (a corrector edit then a surfacer edit, say), each with its inverse.
#include <optional>
#include <string>
#include <vector>

#include "sketchlab/edit.hpp"

namespace sketchlab {

struct HistoryStep {
  Edit forward;
  Edit inverse;
  bool operator==(const HistoryStep&) const = default;
};

struct HistoryEntry {
  std::string action;              // "stroke", "delete", "add_patch", ...
  std::optional<StrokeId> stroke;  // the stroke that caused it, if any
  std::vector<HistoryStep> steps;  // applied in order; undone in reverse
  bool operator==(const HistoryEntry&) const = default;
};

struct History {
  std::vector<HistoryEntry> done;
  std::vector<HistoryEntry> undone;  // top = next redo
  bool operator==(const History&) const = default;
};

}  // namespace sketchlab
