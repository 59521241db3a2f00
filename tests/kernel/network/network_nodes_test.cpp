// connect_point: the node a new curve makes where it meets the network.
#include <catch2/catch.hpp>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/network_nodes.hpp"

using namespace sketchlab;

namespace {

// Curve 1 along x, curve 2 along y crossing it at the origin, and a node
// there; curve 3, a guide along z through (0.5, 0, 0).
Network crossing() {
  Network net;
  Edit e;
  e.curves_added.push_back(make_network_curve(1, make_line(Vec3(-1, 0, 0), Vec3(1, 0, 0)), Layer::shape));
  e.curves_added.push_back(make_network_curve(2, make_line(Vec3(0, -1, 0), Vec3(0, 1, 0)), Layer::shape));
  e.curves_added.push_back(make_network_curve(3, make_line(Vec3(0.5, 0, -1), Vec3(0.5, 0, 1)), Layer::guide));
  e.nodes_added.push_back(Node{1, Vec3::Zero(), {{1, 0.5}, {2, 0.5}}});
  net.apply(e);
  return net;
}

}  // namespace

TEST_CASE("connect_point adds a node where the new curve meets a curve", "[network][nodes]") {
  const Network net = crossing();
  Edit e;
  NodeId next = net.next_node_id();
  REQUIRE(next == 2);
  const Vec3 p(-0.5, 0.0, 1e-4);  // on curve 1 (t = 0.25), within the tolerance
  connect_point(net, p, 9, 0.0, 1e-3, e, next);
  CHECK(next == 3);
  CHECK(e.nodes_replaced.empty());
  REQUIRE(e.nodes_added.size() == 1);
  const Node& n = e.nodes_added[0];
  CHECK(n.id == 2);
  CHECK(n.position == p);
  // Sorted by curve: the existing curve at its closest parameter, then ours.
  REQUIRE(n.incidences.size() == 2);
  CHECK(n.incidences[0].curve == 1);
  CHECK(n.incidences[0].t == Approx(0.25).margin(1e-9));
  CHECK(n.incidences[1] == NodeIncidence{9, 0.0});
}

TEST_CASE("connect_point joins an existing node, and a node of the edit", "[network][nodes]") {
  const Network net = crossing();
  Edit e;
  NodeId next = net.next_node_id();
  // The new curve 9 starts at the crossing: node 1 gets its incidence.
  connect_point(net, Vec3(0, 0, 2e-4), 9, 0.0, 1e-3, e, next);
  CHECK(e.nodes_added.empty());
  REQUIRE(e.nodes_replaced.size() == 1);
  CHECK(e.nodes_replaced[0].id == 1);
  CHECK(e.nodes_replaced[0].position == Vec3::Zero());
  const auto& inc = e.nodes_replaced[0].incidences;
  REQUIRE(inc.size() == 3);
  CHECK(inc[0] == NodeIncidence{1, 0.5});
  CHECK(inc[1] == NodeIncidence{2, 0.5});
  CHECK(inc[2] == NodeIncidence{9, 0.0});
  // Its other end closes the loop there (a closed curve's seam): the same
  // node, one more incidence, no second node; repeating a call adds nothing.
  connect_point(net, Vec3(0, 0, -2e-4), 9, 3.0, 1e-3, e, next);
  connect_point(net, Vec3(0, 0, -2e-4), 9, 3.0, 1e-3, e, next);
  CHECK(e.nodes_added.empty());
  REQUIRE(e.nodes_replaced.size() == 1);
  CHECK(e.nodes_replaced[0].incidences.size() == 4);
  CHECK(e.nodes_replaced[0].incidences[3] == NodeIncidence{9, 3.0});
  CHECK(next == net.next_node_id());

  // Both ends of the new curve at one point of curve 2: one new node.
  Edit f;
  connect_point(net, Vec3(0, 0.5, 0), 9, 0.0, 1e-3, f, next);
  connect_point(net, Vec3(0, 0.5, 0), 9, 1.0, 1e-3, f, next);
  REQUIRE(f.nodes_added.size() == 1);
  CHECK(f.nodes_added[0].incidences.size() == 3);
  CHECK(next == net.next_node_id() + 1);
}

TEST_CASE("connect_point leaves out ignored, removed and distant curves", "[network][nodes]") {
  const Network net = crossing();
  NodeId next = net.next_node_id();
  const Vec3 on_guide(0.5, 0.0005, 0.5);  // 0.5 m from curve 1, on guide 3
  Edit e;
  connect_point(net, on_guide, 9, 0.0, 1e-3, e, next,
                [&](CurveId c) { return net.find_curve(c)->layer == Layer::guide; });
  CHECK(e.empty());
  connect_point(net, on_guide, 9, 0.0, 1e-3, e, next);
  REQUIRE(e.nodes_added.size() == 1);
  CHECK(e.nodes_added[0].incidences[0].curve == 3);

  // A curve the edit removes, or the new curve itself, is no partner.
  Edit removing;
  removing.curves_removed = {1};
  connect_point(net, Vec3(-0.5, 0, 0), 9, 0.0, 1e-3, removing, next);
  CHECK(removing.nodes_added.empty());
  Edit self;
  connect_point(net, Vec3(-0.5, 0, 0), 1, 0.25, 1e-3, self, next);
  CHECK(self.empty());

  Edit far;
  connect_point(net, Vec3(-0.5, 0.01, 0), 9, 0.0, 1e-3, far, next);
  connect_point(net, Vec3(std::nan(""), 0, 0), 9, 0.0, 1e-3, far, next);
  CHECK(far.empty());
}
