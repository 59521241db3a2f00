#pragma once
// Fidelity to the original: rebuild a session's final curve network from
// CASSIE's own sketch_graph export (data/cassie/sketch_graph/<session>.json),
// run this plugin's cycle detection on it, and compare the cycles with the
// patches CASSIE created (data/cassie/raw_data/<session>.json,
// allCreatedPatches), by their bounding strokes.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cycle_search.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct CassieNetwork {
  Network network;                            // curve id = stroke id + 1, node id = graph node id + 1
  std::map<CurveId, std::int64_t> stroke_of;  // curve -> CASSIE stroke id
};

// Curves are each stroke's segments joined in order (cubic pieces), nodes
// the graph nodes with an incidence at every segment end they bound.
// Throws std::runtime_error naming the file on malformed input.
CassieNetwork load_cassie_network(const std::filesystem::path& sketch_graph_json);

using StrokeSet = std::set<std::int64_t>;

struct CassiePatches {
  std::set<StrokeSet> automatic;  // foundByAlgo, strokes all alive, not deleted by hand
  std::set<StrokeSet> manual;     // the same for patches the user added
  int created_automatic = 0;      // every automatic patch ever created
};

// `alive`: the strokes of the final network.
CassiePatches load_cassie_patches(const std::filesystem::path& raw_data_json, const std::set<std::int64_t>& alive);

struct FidelityReport {
  int cassie_automatic = 0;  // CASSIE's automatic patches (unique stroke sets) on the final network
  int cassie_manual = 0;
  int ours = 0;              // cycles found by this plugin (unique stroke sets)
  int found = 0;             // ours ∩ CASSIE automatic
  int missed = 0;            // CASSIE automatic not found
  int extra = 0;             // ours not among CASSIE automatic
  int extra_matching_manual = 0;  // of the extras, patches the CASSIE user added by hand
};

FidelityReport compare_with_cassie(const std::filesystem::path& sketch_graph_json,
                                   const std::filesystem::path& raw_data_json,
                                   const CycleSearchParams& params);

}  // namespace sketchlab::soapfilm
