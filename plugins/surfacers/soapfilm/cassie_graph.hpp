#pragma once
// Fidelity to the original: rebuild a session's final curve network from
// CASSIE's own sketch_graph export (data/cassie/sketch_graph/<session>.json),
// run this plugin's cycle detection on it, and compare the cycles with the
// patches CASSIE created (cassie_session.hpp), by their bounding strokes.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cassie_json.hpp"
#include "cassie_session.hpp"
#include "replay_causes.hpp"
#include "cycle_search.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct CassieNetwork {
  Network network;                            // curve id = stroke id + 1, node id = graph node id + 1
  std::map<CurveId, std::int64_t> stroke_of;  // curve -> CASSIE stroke id
  std::vector<std::string> warnings;          // data quirks skipped (file, element, what)
};

// Curves are each stroke's segments joined in order (cubic pieces), nodes
// the graph nodes with an incidence at every segment end they bound. A
// stroke listed without segments (real data: 02-2-1, hmd_sutherland) is
// skipped with a warning. Throws CassieFormatError naming the file and the
// element (stroke, segment, node, piece, field) on malformed input: a missing
// field, an unknown or repeated id, a piece of neither 2 nor 4 points, a
// non-finite coordinate, consecutive segments that do not meet (1 mm).
CassieNetwork load_cassie_network(const std::filesystem::path& sketch_graph_json);

struct FidelityReport {
  int cassie_automatic = 0;  // CASSIE's automatic patches (unique stroke sets) on the final network
  int cassie_manual = 0;     // the same for the patches its users added by hand
  int ours = 0;              // cycles found by this plugin (unique stroke sets)
  int found = 0;             // ours ∩ CASSIE automatic
  int missed = 0;            // CASSIE automatic not found
  // Of the missed, on this (CASSIE's exact) graph: no closed path through
  // their strokes at all, or one no walk follows (replay_causes.hpp).
  int missed_not_closed = 0, missed_not_found = 0;
  int extra = 0;             // ours not among CASSIE automatic
  int extra_matching_manual = 0;  // of the extras, patches the CASSIE user added by hand
  std::vector<std::string> warnings;
  FidelityReport& operator+=(const FidelityReport& o);
};

// CASSIE's set: the automatic patches (foundByAlgo) of `session` not deleted
// by hand, not broken by a later stroke as far as its log tells
// (cassie_breaks.hpp), whose strokes all are in the final network. It may
// still over-count what CASSIE showed at the end: a patch broken without
// both halves made keeps its strokes alive (CASSIE logs no automatic
// deletion).
FidelityReport compare_with_cassie(const std::filesystem::path& sketch_graph_json, const CassieSession& session,
                                   const CycleSearchParams& params);

// Where a rebuilt network's nodes are against CASSIE's exported graph: each
// side's nodes with a node of the other within `tolerance` (m). CASSIE's
// side counts every exported node, ours the graph nodes (curve_graph.hpp:
// not what a deleted curve left inside another). Measures the replay's
// graph rule (item 22) on the final networks, independently of the walk.
struct NodeAgreement {
  int cassie = 0, ours = 0;                  // nodes
  int cassie_matched = 0, ours_matched = 0;  // of those, with one of the other side that close
  NodeAgreement& operator+=(const NodeAgreement& o);
};
NodeAgreement compare_graph_nodes(const Network& cassie, const Network& ours, double tolerance = 1e-3);

}  // namespace sketchlab::soapfilm
