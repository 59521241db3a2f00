// The surfacer's graph over a network (curve_graph.hpp) where nodes deleted
// curves left share a parameter of a surviving curve: one point of the curve,
// so its graph segments must not be cut there (CASSIE app, item 22).
#include <catch2/catch.hpp>

#include "curve_graph.hpp"
#include "sketchlab/network_curve.hpp"

using namespace sketchlab;
using soapfilm::CurveGraph;
using soapfilm::GraphSegment;

namespace {

Node node(NodeId id, const Vec3& p, std::vector<NodeIncidence> incidences) {
  Node n;
  n.id = id;
  n.position = p;
  n.incidences = std::move(incidences);
  return n;
}

// Curve 1 along x from 0 to 1 m with its end nodes 1 and 2, plus `extra`.
Network line_with(std::vector<Node> extra, std::vector<NetworkCurve> more = {}) {
  Edit e;
  e.curves_added.push_back(make_network_curve(1, make_line(Vec3(0, 0, 0), Vec3(1, 0, 0)), Layer::shape));
  for (NetworkCurve& c : more) e.curves_added.push_back(std::move(c));
  e.nodes_added = {node(1, Vec3(0, 0, 0), {{1, 0.0}}), node(2, Vec3(1, 0, 0), {{1, 1.0}})};
  for (Node& n : extra) e.nodes_added.push_back(std::move(n));
  Network net;
  net.apply(e);
  return net;
}

}  // namespace

TEST_CASE("curve graph: nodes deleted curves left at one parameter do not cut the curve", "[soapfilm]") {
  // Two one-incidence nodes at t = 0.5 (vintage_car's stroke 660 after
  // strokes 716 and 718 ended on it and were deleted).
  const Network net = line_with({node(3, Vec3(0.5, 0, 0), {{1, 0.5}}), node(4, Vec3(0.5, 0, 0), {{1, 0.5}})});
  REQUIRE(net.segments_of(1).size() == 2);  // the kernel has no piece between nodes 3 and 4
  CurveGraph graph(net);
  CHECK_FALSE(graph.is_graph_node(3));
  CHECK_FALSE(graph.is_graph_node(4));
  const std::vector<int>& segs = graph.segments_of(1);
  REQUIRE(segs.size() == 1);
  const GraphSegment& g = graph.segment(segs.front());
  CHECK(g.node0 == 1);
  CHECK(g.node1 == 2);
  CHECK(g.t0 == 0.0);
  CHECK(g.t1 == 1.0);
}

TEST_CASE("curve graph: a left-over node at a meeting's parameter stands for the meeting node", "[soapfilm]") {
  // Curve 2 crosses curve 1 at x = 0.5 (node 5); node 3 is one a deleted
  // curve left at the same parameter of curve 1, and its id orders it first
  // or last among the two, so both orders are checked.
  for (const NodeId left : {NodeId{3}, NodeId{6}}) {
    const Network net =
        line_with({node(left, Vec3(0.5, 0, 0), {{1, 0.5}}), node(5, Vec3(0.5, 0, 0), {{1, 0.5}, {2, 0.5}}),
                   node(7, Vec3(0.5, -0.5, 0), {{2, 0.0}}), node(8, Vec3(0.5, 0.5, 0), {{2, 1.0}})},
                  {make_network_curve(2, make_line(Vec3(0.5, -0.5, 0), Vec3(0.5, 0.5, 0)), Layer::shape)});
    CurveGraph graph(net);
    CHECK(graph.is_graph_node(5));
    CHECK_FALSE(graph.is_graph_node(left));
    const std::vector<int>& segs = graph.segments_of(1);
    REQUIRE(segs.size() == 2);
    CHECK(graph.segment(segs[0]).node0 == 1);
    CHECK(graph.segment(segs[0]).node1 == 5);
    CHECK(graph.segment(segs[1]).node0 == 5);
    CHECK(graph.segment(segs[1]).node1 == 2);
    // Node 5 has all four half-edges (both curves, both ways).
    CHECK(graph.outgoing(5).size() == 4);
  }
}

TEST_CASE("curve graph: a closed curve's seam stays a node when split, with closed_seam_nodes", "[soapfilm]") {
  // CASSIE app, item 22: "a closed stroke is one node with its segment
  // attached twice". A closed curve (a square of four lines, seam node 1 at
  // t = 0) crossed at t = 2 by curve 2 (node 3): without the option the seam
  // is no graph node and the closed curve is one loop at node 3; with it,
  // two segments 3 -> 1 -> 3 and the seam a two-segment node.
  Curve square;
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const Vec3 &a = corners[k], &b = corners[k + 1];
    if (k == 0) square.control_points.push_back(a);
    square.control_points.insert(square.control_points.end(), {a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
  }
  square.sharp.assign(5, false);
  square.closed = true;
  Edit e;
  e.curves_added = {make_network_curve(1, square, Layer::shape),
                    make_network_curve(2, make_line(Vec3(1, 1, 0), Vec3(2, 2, 0)), Layer::shape)};
  e.nodes_added = {node(1, Vec3(0, 0, 0), {{1, 0.0}}), node(3, Vec3(1, 1, 0), {{1, 2.0}, {2, 0.0}}),
                   node(4, Vec3(2, 2, 0), {{2, 1.0}})};
  Network net;
  net.apply(e);

  CurveGraph plain(net);
  CHECK_FALSE(plain.is_graph_node(1));
  const std::vector<int>& loop = plain.segments_of(1);
  REQUIRE(loop.size() == 1);
  CHECK(plain.segment(loop.front()).node0 == 3);
  CHECK(plain.segment(loop.front()).node1 == 3);

  CurveGraph seams(net, true);
  CHECK(seams.is_graph_node(1));
  const std::vector<int>& halves = seams.segments_of(1);
  REQUIRE(halves.size() == 2);
  CHECK(seams.segment(halves[0]).node0 == 1);
  CHECK(seams.segment(halves[0]).node1 == 3);
  CHECK(seams.segment(halves[1]).node0 == 3);
  CHECK(seams.segment(halves[1]).node1 == 1);
  CHECK(seams.outgoing(1).size() == 2);
  CHECK(seams.outgoing(3).size() == 3);
}
