#pragma once
// A CASSIE session as the surfacer comparison needs it (dataset of Yu et al.,
// CHI 2021, MIT): CASSIE's own neatened curves with their creation and
// deletion times (sketch_history/<name>.json) and the patch log of the app
// (raw_data/<name>.json: allCreatedPatches with foundByAlgo, and the
// add/delete-surface entries of systemStates with their times and the hand
// position).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/lab/cassie_import.hpp"

namespace sketchlab::soapfilm {

using StrokeSet = std::set<std::int64_t>;  // CASSIE stroke ids

struct CassieStroke {
  std::int64_t id = 0;          // CASSIE stroke id (>= 0)
  Curve curve;                  // neatened curve (line or joined cubic pieces)
  double created = 0.0;         // s
  std::optional<double> deleted;  // s; absent while alive at the end
  double canvas_scale = 1.0;    // zoom s at creation (δ is δ/s in canvas units)
};

struct CassiePatch {
  std::int64_t id = 0;
  bool automatic = true;        // foundByAlgo
  StrokeSet strokes;            // strokesID (duplicates merged)
  std::optional<double> created;          // time of its add-surface entry
  std::optional<double> deleted_by_hand;  // time of its delete-surface entry
  // Primary hand position in canvas coordinates at creation (a manual patch
  // is made at the hand: CASSIE app, item 26): R⁻¹(hand − canvasPos) / scale.
  std::optional<Vec3> hand;
};

struct CassieSession {
  std::string name;
  int system = 0;  // sketchSystem: 0 freehand, 1 armature, 2 patch
  std::vector<CassieStroke> strokes;  // sketch_history order
  std::vector<CassiePatch> patches;   // allCreatedPatches order
  // CASSIE's constraint log per stroke id (raw_data allSketchedStrokes:
  // the position constraints it applied, CASSIE app, item 21), each mirrored
  // twin given its drawn twin's reflected (lab's add_mirrored_twin_logs);
  // empty unless asked for (load_cassie_session) and for sessions that log
  // none.
  std::map<StrokeId, CassieConstraintLog> logs;
  std::vector<std::string> warnings;  // data quirks handled (file, element, what was done)
};

// Loads <dir>/sketch_history/<name>.json and <dir>/raw_data/<name>.json.
// With `constraint_logs` (only the replay's logged_meets reads them), also
// the logs, with the lab's CASSIE importer: read_cassie_constraint_logs, and
// import_cassie for the mirror plane and twins, which parses both files
// again; a history it refuses, e.g. without input samples, is a warning and
// leaves the twins without logs.
// Quirks of real data are warnings: a stroke deleted before it was created
// (flower: its id was deleted, then re-created) takes the first delete-stroke
// entry of raw_data after its creation, or stays alive if there is none.
// Throws CassieFormatError naming the file and element (stroke, patch,
// system state, field) for anything else malformed.
CassieSession load_cassie_session(const std::filesystem::path& dir, const std::string& name,
                                  bool constraint_logs = false);

}  // namespace sketchlab::soapfilm
