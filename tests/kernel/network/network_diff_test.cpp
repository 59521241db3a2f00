// edit_between: the edit between two states of one network.
#include <catch2/catch.hpp>
#include <random>

#include "kernel/network/random_network.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/network_diff.hpp"

using namespace sketchlab;
using namespace sketchlab::test;

namespace {

bool same_items(const Network& a, const Network& b) {
  return a.curves() == b.curves() && a.nodes() == b.nodes() && a.patches() == b.patches();
}

}  // namespace

TEST_CASE("edit_between turns one network into the other", "[network][diff]") {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    CAPTURE(seed);
    std::mt19937_64 rng(seed);
    const Network from = random_network(rng, 25);
    Network to = from;
    // Several random edits: removals, replacements with other parameter
    // ranges, ids removed and added again, patches.
    for (int k = 0; k < 4; ++k) to.apply(random_edit(rng, to));
    REQUIRE_FALSE(same_items(from, to));

    const Edit e = edit_between(from, to);
    CHECK_FALSE(e.counters);
    Network back = from;
    back.apply(e);
    CHECK(same_items(back, to));
    // And the other way round.
    Network forth = to;
    forth.apply(edit_between(to, from));
    CHECK(same_items(forth, from));
  }
}

TEST_CASE("edit_between lists only what differs, in id order", "[network][diff]") {
  std::mt19937_64 rng(7);
  const Network from = random_network(rng, 12);
  CHECK(edit_between(from, from).empty());

  Network to = from;
  const NetworkCurve first = from.curves().begin()->second;
  const CurveId last = from.curves().rbegin()->first;
  Edit change;
  NetworkCurve moved = first;
  for (Vec3& p : moved.curve.control_points) p += Vec3(0, 0, 0.5);
  moved.keypoints = default_keypoints(moved.curve);
  change.curves_replaced.push_back(moved);
  change.curves_removed.push_back(last);
  change.curves_added.push_back(make_network_curve(from.next_curve_id(), make_line(Vec3(2, 2, 2), Vec3(3, 2, 2)),
                                                   Layer::shape, 4));
  Patch p;
  p.id = from.next_patch_id();
  p.boundary = {OrientedSegment{first.id, 0.0, first.curve.t_max(), 1, 1}};
  p.mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  p.mesh.faces = {{0, 1, 2}};
  change.patches_added.push_back(p);
  to.apply(change);

  const Edit e = edit_between(from, to);
  REQUIRE(e.curves_added.size() == 1);
  CHECK(e.curves_added[0] == to.curves().at(from.next_curve_id()));
  REQUIRE(e.curves_replaced.size() == 1);
  CHECK(e.curves_replaced[0] == moved);
  CHECK(e.curves_removed == std::vector<CurveId>{last});
  // Nodes: those that lost their only incidence with the removed curve are
  // removed, those that lost one of several are replaced; none is added.
  CHECK(e.nodes_added.empty());
  for (NodeId id : e.nodes_removed) CHECK(to.find_node(id) == nullptr);
  for (const Node& n : e.nodes_replaced) CHECK(n == *to.find_node(n.id));
  CHECK(std::is_sorted(e.nodes_removed.begin(), e.nodes_removed.end()));
  REQUIRE(e.patches_added.size() == 1);
  CHECK(e.patches_added[0] == p);
  CHECK(e.patches_removed.empty());

  // A patch whose mesh changed is removed and added again under its id.
  Network remeshed = to;
  Patch q = p;
  q.mesh.vertices[2] = Vec3(0, 2, 0);
  Edit swap;
  swap.patches_removed = {p.id};
  swap.patches_added = {q};
  remeshed.apply(swap);
  const Edit m = edit_between(to, remeshed);
  CHECK(m.patches_removed == std::vector<PatchId>{p.id});
  REQUIRE(m.patches_added.size() == 1);
  CHECK(m.patches_added[0] == q);
  CHECK(m.curves_added.empty());
  CHECK(m.curves_replaced.empty());
  CHECK(m.nodes_replaced.empty());
}

TEST_CASE("edit_between adds again a node that removing its curves drops", "[network][diff]") {
  Network from;
  Edit e;
  e.curves_added.push_back(make_network_curve(1, make_line(Vec3(0, 0, 0), Vec3(1, 0, 0)), Layer::shape));
  e.curves_added.push_back(make_network_curve(2, make_line(Vec3(0, 1, 0), Vec3(1, 1, 0)), Layer::shape));
  e.nodes_added.push_back(Node{5, Vec3(0.5, 0, 0), {{1, 0.5}}});
  from.apply(e);
  // The same node id ends up on curve 2 once curve 1 is gone.
  Network to = from;
  Edit change;
  change.curves_removed = {1};  // drops node 5 (its only incidence)
  change.nodes_added.push_back(Node{5, Vec3(0.5, 1, 0), {{2, 0.5}}});
  to.apply(change);

  const Edit d = edit_between(from, to);
  CHECK(d.curves_removed == std::vector<CurveId>{1});
  CHECK(d.nodes_replaced.empty());
  REQUIRE(d.nodes_added.size() == 1);
  CHECK(d.nodes_added[0] == *to.find_node(5));
  Network back = from;
  back.apply(d);  // replacing node 5 instead would throw: apply drops it first
  CHECK(same_items(back, to));
}
