#include "patch_upkeep.hpp"

#include <algorithm>
#include <chrono>
#include <set>

namespace sketchlab::soapfilm {
namespace {

std::vector<OrientedSegment> to_boundary(const CurveGraph& graph, const Cycle& cycle) {
  std::vector<OrientedSegment> out;
  for (const HalfEdge& h : cycle) out.push_back(graph.oriented(h));
  return out;
}

// Nodes that had an incidence on one of `removed` curves: every node
// incidence was created by some applied edit, so the edits in the history
// (and the current one) name them all. The history is read backwards and
// only as far back as the edit that added each removed curve (incidences on
// a curve are never older than the curve), so the cost follows the age of
// the deleted curves, not the size of the sketch.
std::set<NodeId> nodes_touched_by(const Sketch& sketch, const Edit& last,
                                  const std::set<CurveId>& removed) {
  std::set<NodeId> out;
  std::set<CurveId> open = removed;  // curves whose adding edit is not reached yet
  auto scan = [&](const Edit& e) {
    for (const auto* list : {&e.nodes_added, &e.nodes_replaced})
      for (const Node& n : *list)
        for (const NodeIncidence& inc : n.incidences)
          if (removed.count(inc.curve)) out.insert(n.id);
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

// Searches the seeds in order and filters the closed walks: duplicates of
// `existing` keys or of earlier finds, and cycles over a segment that already
// bounds two automatic patches (counts in `automatic_count`), are rejected.
std::vector<Cycle> search_and_filter(CycleSearcher& searcher, const std::vector<int>& seeds,
                                     std::set<std::vector<int>>& existing,
                                     std::map<int, int>& automatic_count, UpkeepResult& stats) {
  std::vector<Cycle> accepted;
  for (int seed : seeds) {
    for (Cycle& c : searcher.search_segment(seed)) {
      ++stats.cycles_found;
      std::vector<int> key = cycle_key(c);
      if (existing.count(key)) {
        ++stats.rejected_duplicate;
        continue;
      }
      bool full = false;
      for (int s : key) full = full || automatic_count[s] >= 2;
      if (full) {
        ++stats.rejected_manifold;
        continue;
      }
      for (int s : key) ++automatic_count[s];
      existing.insert(std::move(key));
      accepted.push_back(std::move(c));
    }
  }
  stats.seeds += static_cast<int>(seeds.size());
  stats.walks = searcher.walks();
  return accepted;
}

// Seeds in (curve, t0) order without repeats.
std::vector<int> ordered_seeds(const CurveGraph& graph, const std::set<int>& seeds) {
  std::vector<int> out(seeds.begin(), seeds.end());
  std::sort(out.begin(), out.end(), [&](int a, int b) {
    const GraphSegment &sa = graph.segment(a), &sb = graph.segment(b);
    if (sa.curve != sb.curve) return sa.curve < sb.curve;
    return sa.t0 < sb.t0;
  });
  return out;
}

}  // namespace

std::vector<int> boundary_key(CurveGraph& graph, const std::vector<OrientedSegment>& boundary) {
  std::vector<int> key;
  for (const OrientedSegment& piece : boundary) {
    const std::vector<int> cover = graph.covered_by(piece);
    if (cover.empty()) return {};
    key.insert(key.end(), cover.begin(), cover.end());
  }
  std::sort(key.begin(), key.end());
  return key;
}

UpkeepResult patch_upkeep(const Sketch& sketch, const Edit& last, const CycleSearchParams& params) {
  UpkeepResult result;
  const Network& net = sketch.network;
  CurveGraph graph(net);
  CycleSearcher searcher(graph, params);

  std::set<CurveId> replaced;
  for (const NetworkCurve& c : last.curves_replaced)
    if (net.find_curve(c.id)) replaced.insert(c.id);
  std::set<CurveId> new_curves = replaced;
  for (const NetworkCurve& c : last.curves_added)
    if (net.find_curve(c.id)) new_curves.insert(c.id);
  std::set<NodeId> new_nodes;
  for (const auto* list : {&last.nodes_added, &last.nodes_replaced})
    for (const Node& n : *list)
      if (net.find_node(n.id)) new_nodes.insert(n.id);

  // New segments.
  std::set<int> fresh;
  for (CurveId c : new_curves)
    for (int s : graph.segments_of(c)) fresh.insert(s);
  std::set<CurveId> split_curves;  // curves that received a new node
  for (NodeId n : new_nodes) {
    for (const HalfEdge& h : graph.outgoing(n)) fresh.insert(h.segment);
    for (const NodeIncidence& inc : net.find_node(n)->incidences) split_curves.insert(inc.curve);
  }
  std::set<int> seeds = fresh;

  // Deletions: search again around the nodes the deleted curves touched.
  std::set<CurveId> removed(last.curves_removed.begin(), last.curves_removed.end());
  if (!removed.empty())
    for (NodeId n : nodes_touched_by(sketch, last, removed)) {
      const Node* node = net.find_node(n);
      if (!node) continue;
      for (const HalfEdge& h : graph.outgoing(n)) seeds.insert(h.segment);
      for (const NodeIncidence& inc : node->incidences)
        if (int s = graph.segment_at(inc.curve, inc.t); s >= 0) seeds.insert(s);
    }

  // Cycles possibly crossed, and patches on replaced curves (stale geometry).
  std::set<PatchId> removed_patches;
  std::set<CurveId> touched = replaced;
  touched.insert(split_curves.begin(), split_curves.end());
  for (PatchId id : patches_on_any(net, touched)) {
    const Patch& patch = net.patches().at(id);
    bool on_replaced = false, on_split = false;
    for (const OrientedSegment& piece : patch.boundary) {
      on_replaced = on_replaced || replaced.count(piece.curve);
      on_split = on_split || split_curves.count(piece.curve);
    }
    if (!on_replaced && !on_split) continue;
    const std::vector<int> key = boundary_key(graph, patch.boundary);
    bool crossed = on_replaced || key.empty();
    if (!crossed) {
      std::set<NodeId> on_boundary;
      for (int s : key) {
        on_boundary.insert(graph.segment(s).node0);
        on_boundary.insert(graph.segment(s).node1);
      }
      for (int s : fresh) {
        if (std::binary_search(key.begin(), key.end(), s)) continue;
        const GraphSegment& g = graph.segment(s);
        if (on_boundary.count(g.node0) && on_boundary.count(g.node1)) {
          crossed = true;
          break;
        }
      }
    }
    if (!crossed) continue;
    removed_patches.insert(id);
    // Search again from one of its segments (Appendix B).
    for (const OrientedSegment& piece : patch.boundary) {
      if (!net.find_curve(piece.curve)) continue;
      const std::vector<int> cover = graph.covered_by(piece);
      if (!cover.empty()) {
        seeds.insert(cover.front());
        break;
      }
    }
  }

  // Walk first, then read only the patches on the curves the walks reached.
  const auto walk_start = std::chrono::steady_clock::now();
  const std::vector<int> order = ordered_seeds(graph, seeds);
  std::vector<std::pair<int, std::vector<Cycle>>> walked;
  std::set<CurveId> reached;
  for (int seed : order) {
    std::vector<Cycle> found = searcher.search_segment(seed);
    for (const Cycle& c : found)
      for (const HalfEdge& h : c) reached.insert(graph.segment(h.segment).curve);
    walked.emplace_back(seed, std::move(found));
  }
  result.walk_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - walk_start).count();
  std::set<std::vector<int>> existing;
  std::map<int, int> automatic_count;
  for (PatchId id : patches_on_any(net, reached)) {
    if (removed_patches.count(id)) continue;
    const Patch& patch = net.patches().at(id);
    std::vector<int> key = boundary_key(graph, patch.boundary);
    if (patch.automatic)
      for (int s : key) ++automatic_count[s];
    existing.insert(std::move(key));
  }
  for (auto& [seed, found] : walked) {
    ++result.seeds;
    for (Cycle& c : found) {
      ++result.cycles_found;
      std::vector<int> key = cycle_key(c);
      if (existing.count(key)) {
        ++result.rejected_duplicate;
        continue;
      }
      bool full = false;
      for (int s : key) full = full || automatic_count[s] >= 2;
      if (full) {
        ++result.rejected_manifold;
        continue;
      }
      for (int s : key) ++automatic_count[s];
      existing.insert(std::move(key));
      result.cycles_added.push_back(to_boundary(graph, c));
    }
  }
  result.walks = searcher.walks();
  result.patches_removed.assign(removed_patches.begin(), removed_patches.end());
  return result;
}

std::vector<std::vector<OrientedSegment>> detect_all_cycles(const Network& network,
                                                            const CycleSearchParams& params,
                                                            UpkeepResult* stats) {
  CurveGraph graph(network);
  CycleSearcher searcher(graph, params);
  std::set<int> all;
  for (const auto& [id, curve] : network.curves())
    for (int s : graph.segments_of(id)) all.insert(s);
  std::set<std::vector<int>> existing;
  std::map<int, int> counts;
  UpkeepResult local;
  const std::vector<Cycle> cycles =
      search_and_filter(searcher, ordered_seeds(graph, all), existing, counts, local);
  std::vector<std::vector<OrientedSegment>> out;
  for (const Cycle& c : cycles) out.push_back(to_boundary(graph, c));
  if (stats) *stats = local;
  return out;
}

}  // namespace sketchlab::soapfilm
