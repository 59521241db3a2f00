// Network::apply: inverse edits restore exactly; invalid edits throw and
// change nothing.
#include <catch2/catch.hpp>
#include <limits>
#include <random>
#include <string>

#include "kernel/network/random_network.hpp"
#include "sketchlab/network.hpp"

using namespace sketchlab;
using namespace sketchlab::test;

namespace {

// The documented invariants, checked from the public interface.
void check_invariants(const Network& net) {
  for (const auto& [id, node] : net.nodes()) {
    REQUIRE(node.id == id);
    REQUIRE(id < net.counters().next_node);
    REQUIRE_FALSE(node.incidences.empty());
    for (const NodeIncidence& inc : node.incidences) {
      const NetworkCurve* c = net.find_curve(inc.curve);
      REQUIRE(c != nullptr);
      REQUIRE(inc.t >= 0.0);
      REQUIRE(inc.t <= c->curve.t_max());
    }
  }
  for (const auto& [id, patch] : net.patches()) {
    REQUIRE(id < net.counters().next_patch);
    for (const OrientedSegment& s : patch.boundary) REQUIRE(net.find_curve(s.curve) != nullptr);
  }
  for (const auto& [id, c] : net.curves()) {
    REQUIRE(c.id == id);
    REQUIRE(id < net.counters().next_curve);
    // Every keypoint is found by the index at its own position.
    for (std::size_t k = 0; k < c.keypoints.size(); ++k) {
      bool found = false;
      for (const KeypointHit& h : net.keypoints_near(c.keypoints[k].position, 0.0))
        found = found || (h.curve == id && h.keypoint == static_cast<int>(k));
      REQUIRE(found);
    }
  }
}

void require_invalid(Network& net, const Edit& edit, const std::string& expect1, const std::string& expect2) {
  const Network before = net;
  try {
    net.apply(edit);
    FAIL("edit was accepted; expected an error mentioning " << expect1 << " and " << expect2);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK(what.find(expect1) != std::string::npos);
    CHECK(what.find(expect2) != std::string::npos);
  }
  REQUIRE(net == before);
  // The index was rolled back too: queries still see exactly the old state.
  for (const auto& [id, c] : before.curves())
    for (const Keypoint& k : c.keypoints) {
      const auto a = net.keypoints_near(k.position, 0.05);
      const auto b = before.keypoints_near(k.position, 0.05);
      REQUIRE(a.size() == b.size());
      const auto ca = net.curves_near(k.position, 0.05);
      const auto cb = before.curves_near(k.position, 0.05);
      REQUIRE(ca.size() == cb.size());
      for (std::size_t i = 0; i < ca.size(); ++i) REQUIRE(ca[i].curve == cb[i].curve);
    }
}

}  // namespace

TEST_CASE("apply then inverse restores the network exactly", "[network][apply]") {
  std::mt19937_64 rng(20240611);
  Network net = random_network(rng, 40);
  int nontrivial = 0, stripped = 0;
  for (int step = 0; step < 300; ++step) {
    const Network before = net;
    const Edit edit = random_edit(rng, net);
    const Edit inverse = net.apply(edit);
    check_invariants(net);
    REQUIRE(inverse.counters == before.counters());
    if (!(net == before)) ++nontrivial;
    if (net.nodes().size() + edit.nodes_removed.size() < before.nodes().size() + edit.nodes_added.size()) ++stripped;
    const Network after = net;
    const Edit redo = net.apply(inverse);
    REQUIRE(net == before);
    check_invariants(net);
    // The inverse of the inverse redoes the edit.
    net.apply(redo);
    REQUIRE(net == after);
  }
  // The generator really exercised changes and the implied node removals.
  CHECK(nontrivial > 250);
  CHECK(stripped > 10);
}

TEST_CASE("undoing a whole sequence in reverse restores every state", "[network][apply]") {
  std::mt19937_64 rng(777);
  for (int trial = 0; trial < 5; ++trial) {
    Network net;
    std::vector<Network> states{net};
    std::vector<Edit> inverses;
    for (int step = 0; step < 60; ++step) {
      inverses.push_back(net.apply(random_edit(rng, net)));
      states.push_back(net);
    }
    for (int step = 59; step >= 0; --step) {
      net.apply(inverses[static_cast<std::size_t>(step)]);
      REQUIRE(net == states[static_cast<std::size_t>(step)]);
    }
    REQUIRE(net.curves().empty());
    REQUIRE(net.counters() == IdCounters{});
    // Undo then a fresh edit allocates the same ids as the first time.
    std::mt19937_64 rng2(trial);
    const Edit e = random_edit(rng2, net);
    REQUIRE(net.next_curve_id() == 1);
    net.apply(e);
    check_invariants(net);
  }
}

TEST_CASE("removing a curve strips incidences, orphaned nodes and patches", "[network][apply]") {
  Network net;
  Edit add;
  for (CurveId id = 1; id <= 3; ++id) {
    NetworkCurve c;
    c.id = id;
    c.curve = make_line(Vec3(0, 0, 0.1 * id), Vec3(1, 0, 0.1 * id));
    add.curves_added.push_back(c);
  }
  add.nodes_added.push_back(Node{1, Vec3(0.5, 0, 0.1), {{1, 0.5}, {2, 0.5}}});
  add.nodes_added.push_back(Node{2, Vec3(0.2, 0, 0.1), {{1, 0.2}}});
  add.nodes_added.push_back(Node{3, Vec3(0.7, 0, 0.2), {{2, 0.7}, {3, 0.7}}});
  Patch p;
  p.id = 1;
  p.boundary = {{1, 0.2, 0.5, 2, 1}, {2, 0.5, 0.7, 1, 3}};
  add.patches_added.push_back(p);
  Patch q;
  q.id = 2;
  q.boundary = {{3, 0.0, 1.0, 3, 3}};
  add.patches_added.push_back(q);
  net.apply(add);
  REQUIRE(net.counters() == IdCounters{4, 4, 3});
  const Network before = net;

  Edit remove;
  remove.curves_removed = {1};
  const Edit inverse = net.apply(remove);
  REQUIRE(net.find_curve(1) == nullptr);
  REQUIRE(net.find_node(2) == nullptr);  // only on curve 1
  REQUIRE(net.find_node(1) != nullptr);
  REQUIRE(net.find_node(1)->incidences == std::vector<NodeIncidence>{{2, 0.5}});
  REQUIRE(net.patches().count(1) == 0);
  REQUIRE(net.patches().count(2) == 1);
  REQUIRE(net.counters() == before.counters());
  net.apply(inverse);
  REQUIRE(net == before);
}

TEST_CASE("invalid edits throw, name the field and id, and change nothing", "[network][apply]") {
  std::mt19937_64 rng(99);
  Network net = random_network(rng, 30);
  net.apply(random_edit(rng, net));
  const CurveId some_curve = net.curves().begin()->first;
  const CurveId missing = net.next_curve_id() + 10;
  const NodeId some_node = net.nodes().begin()->first;

  {
    Edit e;
    e.curves_removed = {some_curve, missing};
    require_invalid(net, e, "curves_removed[1]", std::to_string(missing));
  }
  {
    Edit e;
    e.curves_removed = {some_curve, some_curve};
    require_invalid(net, e, "curves_removed[1]", "listed twice");
  }
  {
    Edit e;
    e.curves_added.push_back(random_network_curve(rng, some_curve));
    require_invalid(net, e, "curves_added[0]", "already exists");
  }
  {
    Edit e;
    e.curves_added.push_back(random_network_curve(rng, 0));
    require_invalid(net, e, "curves_added[0]", "id 0");
  }
  {
    Edit e;
    e.curves_added.push_back(random_network_curve(rng, net.next_curve_id()));
    NetworkCurve bad = random_network_curve(rng, net.next_curve_id() + 1);
    bad.curve.control_points.pop_back();
    e.curves_added.push_back(bad);
    require_invalid(net, e, "curves_added[1]", "control points");
  }
  {
    Edit e;
    e.curves_removed = {some_curve};
    NetworkCurve bad = random_network_curve(rng, net.next_curve_id());
    bad.curve.control_points[1].x() = std::numeric_limits<double>::quiet_NaN();
    e.curves_added.push_back(bad);
    require_invalid(net, e, "curves_added[0]", "not finite");
  }
  {
    Edit e;
    e.curves_replaced.push_back(random_network_curve(rng, missing));
    require_invalid(net, e, "curves_replaced[0]", std::to_string(missing));
  }
  {
    Edit e;
    e.curves_removed = {some_curve};
    e.curves_replaced.push_back(random_network_curve(rng, some_curve));
    require_invalid(net, e, "curves_replaced[0]", "does not exist");
  }
  {
    Edit e;
    NetworkCurve c = random_network_curve(rng, net.next_curve_id());
    c.keypoints[0].t = c.curve.t_max() + 1.0;
    e.curves_added.push_back(c);
    require_invalid(net, e, "curves_added[0]", "keypoints[0].t");
  }
  {
    Edit e;
    e.nodes_added.push_back(Node{net.next_node_id(), Vec3(0, 0, 0), {{missing, 0.0}}});
    require_invalid(net, e, "nodes_added[0]", std::to_string(missing));
  }
  {
    Edit e;
    const NetworkCurve& c = net.curves().begin()->second;
    e.nodes_added.push_back(Node{net.next_node_id(), Vec3(0, 0, 0), {{c.id, c.curve.t_max() + 0.5}}});
    require_invalid(net, e, "nodes_added[0]", "outside");
  }
  {
    Edit e;
    e.nodes_added.push_back(Node{net.next_node_id(), Vec3(0, 0, 0), {}});
    require_invalid(net, e, "nodes_added[0]", "incidence");
  }
  {
    Edit e;
    e.nodes_added.push_back(Node{some_node, Vec3(0, 0, 0), {{some_curve, 0.0}}});
    require_invalid(net, e, "nodes_added[0]", "already exists");
  }
  {
    Edit e;
    e.nodes_replaced.push_back(Node{net.next_node_id() + 5, Vec3(0, 0, 0), {{some_curve, 0.0}}});
    require_invalid(net, e, "nodes_replaced[0]", std::to_string(net.next_node_id() + 5));
  }
  {
    Edit e;
    e.nodes_removed = {net.next_node_id()};
    require_invalid(net, e, "nodes_removed[0]", std::to_string(net.next_node_id()));
  }
  {
    // A replacement that shortens a curve under an existing node.
    const Node& node = net.nodes().begin()->second;
    NodeIncidence far{};
    bool have = false;
    for (const auto& [id, n] : net.nodes())
      for (const NodeIncidence& inc : n.incidences)
        if (!have && inc.t > 1.0) {
          far = inc;
          have = true;
        }
    (void)node;
    if (have) {
      Edit e;
      NetworkCurve shorter = random_network_curve(rng, far.curve, 1);
      e.curves_replaced.push_back(shorter);
      require_invalid(net, e, "curves_replaced[0]", "outside");
    }
  }
  {
    Edit e;
    Patch p;
    p.id = net.next_patch_id();
    p.boundary = {{missing, 0.0, 1.0, 1, 1}};
    e.patches_added.push_back(p);
    require_invalid(net, e, "patches_added[0]", std::to_string(missing));
  }
  {
    Edit e;
    Patch p;
    p.id = net.next_patch_id();
    p.boundary = {{some_curve, 0.0, 0.5, 1, 1}};
    p.mesh.vertices = {Vec3::Zero()};
    p.mesh.faces = {{0, 1, 2}};
    e.patches_added.push_back(p);
    require_invalid(net, e, "patches_added[0]", "face 0");
  }
  {
    Edit e;
    e.patches_removed = {net.next_patch_id() + 3};
    require_invalid(net, e, "patches_removed[0]", std::to_string(net.next_patch_id() + 3));
  }
  {
    Edit e;
    e.curves_removed = {some_curve};
    e.counters = IdCounters{1, 1, 1};
    require_invalid(net, e, "counters.next_curve", "not above");
  }
  {
    // A valid edit that fails only in its last part leaves no trace.
    Edit e = random_edit(rng, net);
    e.patches_added.push_back(Patch{0, {}, {}, true});
    require_invalid(net, e, "patches_added[" + std::to_string(e.patches_added.size() - 1) + "]", "id 0");
  }
  check_invariants(net);
}
