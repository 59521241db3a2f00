// Network::patches_on(curve): the patches bounded by a curve, kept in step
// with every apply (patches added/removed, curves removed or replaced, undo).
#include <catch2/catch.hpp>
#include <random>
#include <set>

#include "kernel/network/random_network.hpp"
#include "sketchlab/network.hpp"

using namespace sketchlab;
using namespace sketchlab::test;

namespace {

// Brute force: scan every patch boundary.
std::vector<PatchId> scan_patches_on(const Network& net, CurveId curve) {
  std::set<PatchId> out;
  for (const auto& [id, patch] : net.patches())
    for (const OrientedSegment& s : patch.boundary)
      if (s.curve == curve) out.insert(id);
  return {out.begin(), out.end()};
}

void require_matches_scan(const Network& net) {
  // Every curve ever allocated, so removed curves (empty answer) are covered.
  for (CurveId c = 0; c <= net.next_curve_id(); ++c) {
    INFO("curve " << c);
    REQUIRE(net.patches_on(c) == scan_patches_on(net, c));
  }
}

}  // namespace

TEST_CASE("patches_on lists the patches bounded by a curve", "[network][patches_on]") {
  Network net;
  REQUIRE(net.patches_on(1).empty());  // unknown curve
  Edit add;
  for (CurveId id = 1; id <= 3; ++id) {
    NetworkCurve c;
    c.id = id;
    c.curve = make_line(Vec3(0, 0, 0.1 * id), Vec3(1, 0, 0.1 * id));
    add.curves_added.push_back(c);
  }
  add.nodes_added.push_back(Node{1, Vec3(0.5, 0, 0.1), {{1, 0.5}, {2, 0.5}}});
  add.nodes_added.push_back(Node{2, Vec3(0.7, 0, 0.2), {{2, 0.7}, {3, 0.7}}});
  Patch p;
  p.id = 1;
  // Two pieces on curve 2: listed once.
  p.boundary = {{1, 0.0, 0.5, 1, 1}, {2, 0.5, 0.7, 1, 2}, {2, 0.7, 1.0, 2, 2}};
  Patch q;
  q.id = 2;
  q.boundary = {{2, 0.0, 0.5, 1, 1}, {3, 0.0, 1.0, 2, 2}};
  add.patches_added = {p, q};
  net.apply(add);
  CHECK(net.patches_on(1) == std::vector<PatchId>{1});
  CHECK(net.patches_on(2) == std::vector<PatchId>{1, 2});
  CHECK(net.patches_on(3) == std::vector<PatchId>{2});
  CHECK(net.patches_on(99).empty());

  Edit remove_patch;
  remove_patch.patches_removed = {1};
  const Edit undo_patch = net.apply(remove_patch);
  CHECK(net.patches_on(1).empty());
  CHECK(net.patches_on(2) == std::vector<PatchId>{2});
  net.apply(undo_patch);
  CHECK(net.patches_on(2) == std::vector<PatchId>{1, 2});

  // Removing a curve removes the patches it bounds, from every curve's list.
  Edit remove_curve;
  remove_curve.curves_removed = {3};
  const Edit undo_curve = net.apply(remove_curve);
  CHECK(net.patches_on(3).empty());
  CHECK(net.patches_on(2) == std::vector<PatchId>{1});
  net.apply(undo_curve);
  CHECK(net.patches_on(3) == std::vector<PatchId>{2});
  CHECK(net.patches_on(2) == std::vector<PatchId>{1, 2});
}

TEST_CASE("patches_on equals a scan of the patches after random edits and undo",
          "[network][patches_on]") {
  std::mt19937_64 rng(5150);
  Network net = random_network(rng, 30);
  std::vector<Edit> inverses;
  int with_patches = 0;
  for (int step = 0; step < 200; ++step) {
    inverses.push_back(net.apply(random_edit(rng, net)));
    require_matches_scan(net);
    if (!net.patches().empty()) ++with_patches;
  }
  CHECK(with_patches > 100);  // the edits really exercised patches
  for (auto it = inverses.rbegin(); it != inverses.rend(); ++it) {
    net.apply(*it);
    require_matches_scan(net);
  }
  // Copies and moves carry the map.
  const Network copy = net;
  require_matches_scan(copy);
  Network moved = std::move(net);
  require_matches_scan(moved);
}
