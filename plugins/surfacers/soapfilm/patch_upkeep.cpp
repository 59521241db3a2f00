#include "patch_upkeep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

#include "patch_break.hpp"

namespace sketchlab::soapfilm {
namespace {

std::vector<OrientedSegment> to_boundary(const CurveGraph& graph, const Cycle& cycle) {
  std::vector<OrientedSegment> out;
  for (const HalfEdge& h : cycle) out.push_back(graph.oriented(h));
  return out;
}

// What deleting the `removed` curves took away, read from the edits in the
// history (and the current one), which name every node incidence and every
// patch the surfacer added: the nodes that had an incidence on a removed
// curve, and the boundaries of the patches on one (the kernel removed those
// with the curves). The history is read backwards and only as far back as
// the edit that added each removed curve (incidences and patches on a curve
// are never older than the curve), so the cost follows the age of the
// deleted curves, not the size of the sketch.
struct Deleted {
  std::set<NodeId> nodes;
  std::vector<std::vector<OrientedSegment>> patches;
};

Deleted deleted_with(const Sketch& sketch, const Edit& last, const std::set<CurveId>& removed) {
  Deleted out;
  std::set<CurveId> open = removed;  // curves whose adding edit is not reached yet
  std::set<PatchId> later;           // patches removed or replaced after the point reached
  const auto on_removed = [&](const OrientedSegment& piece) { return removed.count(piece.curve) > 0; };
  auto scan = [&](const Edit& e) {
    for (const auto* list : {&e.nodes_added, &e.nodes_replaced})
      for (const Node& n : *list)
        for (const NodeIncidence& inc : n.incidences)
          if (removed.count(inc.curve)) out.nodes.insert(n.id);
    // Backwards through an edit: its patches were removed, then added.
    for (const Patch& p : e.patches_added) {
      if (!later.insert(p.id).second) continue;
      // Alive until now: its curves were all there (a patch the kernel
      // removed with an earlier deleted curve is listed nowhere).
      const bool alive = std::all_of(p.boundary.begin(), p.boundary.end(), [&](const OrientedSegment& piece) {
        return on_removed(piece) || sketch.network.find_curve(piece.curve);
      });
      if (alive && std::any_of(p.boundary.begin(), p.boundary.end(), on_removed)) out.patches.push_back(p.boundary);
    }
    later.insert(e.patches_removed.begin(), e.patches_removed.end());
  };
  scan(last);
  const auto& done = sketch.history.done;
  for (auto entry = done.rbegin(); entry != done.rend() && !open.empty(); ++entry)
    for (auto step = entry->steps.rbegin(); step != entry->steps.rend(); ++step) {
      scan(step->forward);
      for (const NetworkCurve& c : step->forward.curves_added) open.erase(c.id);
    }
  return out;
}

// Patches with a boundary piece on one of `curves`, ascending ids, from the
// kernel's curve -> patches map (no scan of the patch list).
std::set<PatchId> patches_on_any(const Network& net, const std::set<CurveId>& curves) {
  std::set<PatchId> out;
  for (CurveId c : curves)
    for (PatchId p : net.patches_on(c)) out.insert(p);
  return out;
}

// The boundaries of the patches the user deleted by hand (the history's
// delete_patch entries; their inverse steps hold the patches) whose curves
// all still stand. Read only when a walk closed, since it scans the history.
std::vector<std::vector<OrientedSegment>> deleted_by_hand(const Sketch& sketch) {
  std::vector<std::vector<OrientedSegment>> out;
  for (const HistoryEntry& entry : sketch.history.done) {
    if (entry.action != "delete_patch") continue;
    for (const HistoryStep& step : entry.steps)
      for (const Patch& p : step.inverse.patches_added)
        if (std::all_of(p.boundary.begin(), p.boundary.end(),
                        [&](const OrientedSegment& piece) { return sketch.network.find_curve(piece.curve); }))
          out.push_back(p.boundary);
  }
  return out;
}

// Seeds in (curve, t0) order.
std::vector<int> ordered(const CurveGraph& graph, const std::set<int>& seeds) {
  std::vector<int> out(seeds.begin(), seeds.end());
  std::sort(out.begin(), out.end(), [&](int a, int b) {
    const GraphSegment &sa = graph.segment(a), &sb = graph.segment(b);
    if (sa.curve != sb.curve) return sa.curve < sb.curve;
    return sa.t0 < sb.t0;
  });
  return out;
}

// Which found cycles become patches (Appendix B, item 24): not a duplicate of
// an existing cycle (same segments), and no segment already bounding two.
class CycleFilter {
 public:
  void add(std::vector<int> key, bool counts) {
    if (counts)
      for (int s : key) ++bounding_[s];
    existing_.insert(std::move(key));
  }
  bool duplicate(const std::vector<int>& key) const { return existing_.count(key) > 0; }
  bool full(const std::vector<int>& key) const {
    return std::any_of(key.begin(), key.end(), [&](int s) {
      const auto it = bounding_.find(s);
      return it != bounding_.end() && it->second >= 2;
    });
  }

 private:
  std::set<std::vector<int>> existing_;
  std::map<int, int> bounding_;  // segment -> patches it bounds
};

}  // namespace

std::vector<int> boundary_key(CurveGraph& graph, const std::vector<OrientedSegment>& boundary) {
  std::vector<int> key;
  for (const OrientedSegment& piece : boundary) {
    const std::vector<int> cover = graph.covered_by(piece);
    if (cover.empty()) return {};
    key.insert(key.end(), cover.begin(), cover.end());
  }
  // Pieces stored under a finer node set share the segment holding them.
  std::sort(key.begin(), key.end());
  key.erase(std::unique(key.begin(), key.end()), key.end());
  return key;
}

UpkeepResult patch_upkeep(const Sketch& sketch, const Edit& last, const CycleSearchParams& params) {
  UpkeepResult result;
  const Network& net = sketch.network;
  CurveGraph graph(net, params.closed_seam_nodes);
  CycleSearcher searcher(graph, params);

  std::set<CurveId> replaced;
  for (const NetworkCurve& c : last.curves_replaced)
    if (net.find_curve(c.id)) replaced.insert(c.id);
  std::set<CurveId> new_curves = replaced;
  for (const NetworkCurve& c : last.curves_added)
    if (net.find_curve(c.id)) new_curves.insert(c.id);

  // New segments: the new curves' (Appendix B), and those at an added node
  // joining existing curves only.
  std::set<int> fresh;
  for (CurveId c : new_curves)
    for (int s : graph.segments_of(c)) fresh.insert(s);
  for (const Node& n : last.nodes_added) {
    const Node* node = net.find_node(n.id);
    if (!node || std::any_of(node->incidences.begin(), node->incidences.end(),
                             [&](const NodeIncidence& i) { return new_curves.count(i.curve); }))
      continue;
    for (const HalfEdge& h : graph.outgoing(n.id)) fresh.insert(h.segment);
  }

  // Patches possibly broken: through a node of a new segment, or on a
  // replaced curve.
  std::set<CurveId> around = replaced;
  for (int s : fresh)
    for (NodeId x : {graph.segment(s).node0, graph.segment(s).node1})
      if (const Node* node = net.find_node(x))
        for (const NodeIncidence& inc : node->incidences) around.insert(inc.curve);
  std::vector<int> first_seeds;  // one segment of each broken patch, searched first (item 25)
  std::map<PatchId, std::vector<int>> broken;  // -> key, when it still matches the graph
  for (PatchId id : patches_on_any(net, around)) {
    const Patch& patch = net.patches().at(id);
    const bool on_replaced = std::any_of(patch.boundary.begin(), patch.boundary.end(),
                                         [&](const OrientedSegment& p) { return replaced.count(p.curve); });
    const std::vector<int> key = boundary_key(graph, patch.boundary);
    std::vector<int> at_break;
    if (!on_replaced && !key.empty() && !broken_by(graph, searcher, patch, key, fresh, params, &at_break)) continue;
    // Found again over the same pieces of curve, it keeps its identity
    // (item 25), also where this edit's nodes split a piece: CASSIE logs no
    // new patch for such a cycle (0 of the 26 the former rule remade at a
    // stroke event in the bundled sessions; README, ninth round).
    broken[id] = on_replaced ? std::vector<int>{} : key;
    if (params.broken_seeds == BrokenSeeds::at_break && !at_break.empty()) {
      first_seeds.insert(first_seeds.end(), at_break.begin(), at_break.end());
      continue;
    }
    for (const OrientedSegment& piece : patch.boundary) {
      if (!net.find_curve(piece.curve)) continue;
      if (const std::vector<int> cover = graph.covered_by(piece); !cover.empty()) {
        if (params.broken_seeds != BrokenSeeds::all) {
          first_seeds.push_back(cover.front());
          break;
        }
        first_seeds.insert(first_seeds.end(), cover.begin(), cover.end());
      }
    }
  }
  result.patches_broken = static_cast<int>(broken.size());

  // Deletions: search again around the nodes the deleted curves touched,
  // and first the segments left of the patches they took away (broken
  // cycles, item 25; a patch is deleted when a boundary segment is removed,
  // item 27).
  std::set<int> around_deleted, of_deleted;
  std::set<CurveId> removed(last.curves_removed.begin(), last.curves_removed.end());
  if (!removed.empty()) {
    const Deleted gone = deleted_with(sketch, last, removed);
    for (NodeId n : gone.nodes) {
      const Node* node = net.find_node(n);
      if (!node) continue;
      for (const HalfEdge& h : graph.outgoing(n)) around_deleted.insert(h.segment);
      for (const NodeIncidence& inc : node->incidences)
        if (int s = graph.segment_at(inc.curve, inc.t); s >= 0) around_deleted.insert(s);
    }
    for (const std::vector<OrientedSegment>& boundary : gone.patches)
      for (const OrientedSegment& piece : boundary)
        if (net.find_curve(piece.curve))
          for (int s : graph.covered_by(piece)) of_deleted.insert(s);
  }

  // Item 25 read the other way (seed_split_segments, off by default): old
  // curves' segments split by a node this edit added on them.
  std::set<int> split;
  if (params.seed_split_segments)
    for (const Node& n : last.nodes_added)
      if (net.find_node(n.id))
        for (const HalfEdge& h : graph.outgoing(n.id))
          if (!new_curves.count(graph.segment(h.segment).curve)) split.insert(h.segment);

  std::vector<int> seeds;
  std::set<int> seen;
  auto push = [&](int s) {
    if (seen.insert(s).second) seeds.push_back(s);
  };
  for (int s : first_seeds) push(s);
  for (int s : ordered(graph, of_deleted)) push(s);
  for (int s : ordered(graph, fresh)) push(s);
  for (int s : ordered(graph, split)) push(s);
  for (int s : ordered(graph, around_deleted)) push(s);

  // Walk first, then read only the patches on the curves the walks reached.
  const auto walk_start = std::chrono::steady_clock::now();
  std::vector<std::vector<Cycle>> walked;
  std::set<CurveId> reached;
  for (int seed : seeds) {
    std::vector<Cycle> found = searcher.search_segment(seed);
    for (const Cycle& c : found)
      for (const HalfEdge& h : c) reached.insert(graph.segment(h.segment).curve);
    walked.push_back(std::move(found));
  }
  result.walk_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - walk_start).count();
  CycleFilter filter;
  for (PatchId id : patches_on_any(net, reached)) {
    if (broken.count(id)) continue;
    const Patch& patch = net.patches().at(id);
    filter.add(boundary_key(graph, patch.boundary), patch.automatic || params.manual_patches_count);
  }
  // A cycle the user deleted the patch of is no new cycle (item 26), and
  // with `counts` still one its segments bound (item 24).
  const bool any_found = std::any_of(walked.begin(), walked.end(), [](const auto& f) { return !f.empty(); });
  if (params.hand_deleted != HandDeleted::forget && any_found)
    for (const std::vector<OrientedSegment>& boundary : deleted_by_hand(sketch))
      if (std::vector<int> key = boundary_key(graph, boundary); !key.empty() && !filter.duplicate(key))
        filter.add(std::move(key), params.hand_deleted == HandDeleted::counts);
  std::map<std::vector<int>, PatchId> kept_if_found;
  for (const auto& [id, key] : broken)
    if (!key.empty()) kept_if_found[key] = id;
  for (std::vector<Cycle>& found : walked) {
    ++result.seeds;
    for (Cycle& c : found) {
      ++result.cycles_found;
      std::vector<int> key = cycle_key(c);
      if (filter.duplicate(key)) {
        ++result.rejected_duplicate;
        continue;
      }
      if (auto it = kept_if_found.find(key); it != kept_if_found.end()) {
        // Found again over the same segments: the broken patch stays.
        broken.erase(it->second);
        filter.add(std::move(key), true);
        continue;
      }
      if (filter.full(key)) {
        ++result.rejected_manifold;
        continue;
      }
      filter.add(std::move(key), true);
      result.cycles_added.push_back(to_boundary(graph, c));
    }
  }
  result.walks = searcher.walks();
  for (const auto& [id, key] : broken) result.patches_removed.push_back(id);
  return result;
}

std::vector<std::vector<OrientedSegment>> detect_all_cycles(const Network& network,
                                                            const CycleSearchParams& params,
                                                            UpkeepResult* stats) {
  CurveGraph graph(network, params.closed_seam_nodes);
  CycleSearcher searcher(graph, params);
  std::set<int> all;
  for (const auto& [id, curve] : network.curves())
    for (int s : graph.segments_of(id)) all.insert(s);
  UpkeepResult local;
  CycleFilter filter;
  std::vector<std::vector<OrientedSegment>> out;
  for (int seed : ordered(graph, all)) {
    ++local.seeds;
    for (const Cycle& c : searcher.search_segment(seed)) {
      ++local.cycles_found;
      std::vector<int> key = cycle_key(c);
      if (filter.duplicate(key)) {
        ++local.rejected_duplicate;
      } else if (filter.full(key)) {
        ++local.rejected_manifold;
      } else {
        filter.add(std::move(key), true);
        out.push_back(to_boundary(graph, c));
      }
    }
  }
  local.walks = searcher.walks();
  if (stats) *stats = local;
  return out;
}

}  // namespace sketchlab::soapfilm
