#pragma once
// Corrector plugins map (stroke, current sketch) to an edit plus the
// constraints they considered (DESIGN.md, "Correctors are functions"). A
// corrector never mutates the sketch and keeps no state between strokes
// other than caches.
#include <map>
#include <string>
#include <vector>

#include "sketchlab/constraint.hpp"
#include "sketchlab/edit.hpp"
#include "sketchlab/sketch.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab {

struct CorrectionStats {
  int iterations = 0;     // solver iterations (IRLS rounds, Newton steps...)
  int subsets_tried = 0;  // constraint subsets evaluated (CASSIE)
  // Anything else a corrector measures, by name (e.g. "confidence").
  std::map<std::string, double> extra;
  // Which of its alternatives a corrector took, by name, as the plugin names
  // it (e.g. JustDrawIt's "decision": "extend"; ScaffoldSketch's "mode").
  std::map<std::string, std::string> outcomes;
  bool operator==(const CorrectionStats&) const = default;
};

struct Correction {
  Edit edit;  // ids from sketch.network.next_*_id() upwards
  std::vector<Constraint> constraints;  // considered; `enforced` tells which held
  CorrectionStats stats;
  // Non-empty when the corrector failed on this stroke; the edit is then
  // ignored and the raw stroke stays recorded.
  std::string error;
};

// Which strokes a corrector wants. `world`: 3D strokes in workspace metres; a
// 2D stroke with a draw plane arrives lifted onto it (draw_plane.hpp).
// `pixels`: 2D-native correctors (analytic drawing, JustDrawIt) get 2D
// strokes as recorded, pixels plus View (and the draw plane, if any).
enum class StrokeSpace { world, pixels };

class Corrector {
 public:
  virtual ~Corrector() = default;
  // `stroke` passed validate(); for 2D strokes stroke.view is set.
  virtual Correction correct(const Stroke& stroke, const Sketch& sketch) = 0;
  virtual StrokeSpace stroke_space() const { return StrokeSpace::world; }
};

}  // namespace sketchlab
