// Segments split curves at their nodes, in t order, wrapping closed curves.
#include <catch2/catch.hpp>

#include "sketchlab/network.hpp"

using namespace sketchlab;

namespace {

Curve closed_square() {
  Curve c;
  const Vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int k = 0; k < 4; ++k) {
    const Vec3 a = corners[k], b = corners[(k + 1) % 4];
    c.control_points.push_back(a);
    c.control_points.push_back(a + (b - a) / 3.0);
    c.control_points.push_back(a + 2.0 * (b - a) / 3.0);
  }
  c.control_points.push_back(corners[0]);
  c.sharp.assign(5, true);
  c.closed = true;
  return c;
}

NetworkCurve with_id(CurveId id, Curve c) {
  NetworkCurve nc;
  nc.id = id;
  nc.curve = std::move(c);
  return nc;
}

}  // namespace

TEST_CASE("segments split an open curve between consecutive nodes", "[network][segments]") {
  Network net;
  Edit e;
  Curve three;
  three.control_points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}, {6, 0, 0},
                          {7, 0, 0}, {8, 0, 0}, {9, 0, 0}};
  three.sharp.assign(4, false);
  e.curves_added = {with_id(1, three), with_id(2, make_line({0, 1, 0}, {0, 2, 0}))};
  // Given out of t order, and one node meeting curve 1 twice.
  e.nodes_added = {Node{5, {}, {{1, 2.5}}}, Node{3, {}, {{1, 0.5}, {2, 0.25}}}, Node{4, {}, {{1, 1.0}, {1, 2.9}}}};
  net.apply(e);

  const std::vector<Segment> expected{{1, 0.5, 1.0, 3, 4}, {1, 1.0, 2.5, 4, 5}, {1, 2.5, 2.9, 5, 4}};
  REQUIRE(net.segments_of(1) == expected);
  // Curve 2 has a single node: both pieces dangle.
  REQUIRE(net.segments_of(2).empty());
  REQUIRE(net.segments() == expected);
  REQUIRE_THROWS_AS(net.segments_of(9), std::invalid_argument);

  // Nodes at the ends bound segments; two nodes at one t give no zero-length piece.
  Edit more;
  more.nodes_added = {Node{6, {}, {{1, 0.0}}}, Node{7, {}, {{1, 3.0}}}, Node{8, {}, {{1, 1.0}}}};
  net.apply(more);
  const std::vector<Segment> expected2{{1, 0.0, 0.5, 6, 3}, {1, 0.5, 1.0, 3, 4}, {1, 1.0, 2.5, 8, 5},
                                       {1, 2.5, 2.9, 5, 4}, {1, 2.9, 3.0, 4, 7}};
  REQUIRE(net.segments_of(1) == expected2);
}

TEST_CASE("segments of a closed curve wrap across the seam", "[network][segments]") {
  Network net;
  Edit e;
  e.curves_added = {with_id(1, closed_square())};
  e.nodes_added = {Node{1, {}, {{1, 1.5}}}};
  net.apply(e);
  // One node: the whole loop from and back to it.
  REQUIRE(net.segments_of(1) == std::vector<Segment>{{1, 1.5, 1.5, 1, 1}});

  Edit two;
  two.nodes_added = {Node{2, {}, {{1, 3.25}}}, Node{3, {}, {{1, 0.5}}}};
  net.apply(two);
  REQUIRE(net.segments_of(1) ==
          std::vector<Segment>{{1, 0.5, 1.5, 3, 1}, {1, 1.5, 3.25, 1, 2}, {1, 3.25, 0.5, 2, 3}});

  // A node on the seam (given at t_max) is listed at 0; the wrap ends at t_max.
  Edit seam;
  seam.nodes_removed = {3};
  seam.nodes_added = {Node{4, {}, {{1, 4.0}}}};
  net.apply(seam);
  REQUIRE(net.segments_of(1) ==
          std::vector<Segment>{{1, 0.0, 1.5, 4, 1}, {1, 1.5, 3.25, 1, 2}, {1, 3.25, 4.0, 2, 4}});

  // Segments follow removals.
  Edit drop;
  drop.nodes_removed = {1, 2};
  net.apply(drop);
  REQUIRE(net.segments_of(1) == std::vector<Segment>{{1, 0.0, 4.0, 4, 4}});
}
