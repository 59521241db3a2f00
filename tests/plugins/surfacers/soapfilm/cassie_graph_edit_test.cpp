// CASSIE's graph rebuilt while its curves are replayed (cassie_graph_edit.hpp,
// CASSIE app item 22).
#include <catch2/catch.hpp>

#include "cassie_graph_edit.hpp"

using namespace sketchlab;

namespace {

Curve straight(const Vec3& a, const Vec3& b) {
  Curve c;
  c.control_points = {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b};
  c.sharp = {false, false};
  return c;
}

}  // namespace

TEST_CASE("a curve ending on an old curve near its node has one node there, connected", "[soapfilm]") {
  Network net;
  net.apply(soapfilm::cassie_graph_edit(net, {{1, straight({0, 0, 0}, {1, 0, 0})}}));
  REQUIRE(net.nodes().size() == 2);
  // B starts on A, 1.2 cm from A's end node: within δ (2 cm) of it, so the
  // meeting reuses that node, but farther than 0.5δ from it. The reused node
  // is B's end node; a second node at B's t = 0 would leave no segment
  // between the two and cut B off from A (the replay's missing cycles).
  net.apply(soapfilm::cassie_graph_edit(net, {{2, straight({0.012, 0, 0}, {0.012, 1, 0})}}));
  CHECK(net.nodes().size() == 3);
  CurveId b = 0;
  for (const auto& [id, c] : net.curves())
    if (c.source_stroke == 2) b = id;
  const std::vector<Segment> pieces = net.segments_of(b);
  REQUIRE(pieces.size() == 1);
  const Node* start = net.find_node(pieces.front().node0);
  REQUIRE(start != nullptr);
  CHECK(start->position.norm() < 1e-12);  // A's end node, where A starts
  CHECK(start->incidences.size() == 2);
}

TEST_CASE("a curve meeting an old curve reuses the nearest of its nodes within delta", "[soapfilm]") {
  // CASSIE app, item 22: the node reused on the old curve is within δ (2 cm)
  // of the meeting; with two there, the nearer one, whichever was made first.
  for (const bool right : {false, true}) {
    Network net;
    net.apply(soapfilm::cassie_graph_edit(net, {{1, straight({0, 0, 0}, {1, 0, 0})}}));
    // Two nodes on A, 2.3 cm apart (beyond δ: the second gets its own node).
    net.apply(soapfilm::cassie_graph_edit(net, {{2, straight({0.5, 0, 0}, {0.5, 1, 0})}}));
    net.apply(soapfilm::cassie_graph_edit(net, {{3, straight({0.523, 0, 0}, {0.523, 1, 0})}}));
    REQUIRE(net.nodes().size() == 6);
    // B starts on A 0.8 cm from the first node and 1.5 cm from the second,
    // or 1.6 cm and 0.7 cm.
    const double x = right ? 0.516 : 0.508;
    net.apply(soapfilm::cassie_graph_edit(net, {{4, straight({x, 0, 0}, {x, -1, 0})}}));
    CHECK(net.nodes().size() == 7);  // B's far end only
    CurveId b = 0;
    for (const auto& [id, c] : net.curves())
      if (c.source_stroke == 4) b = id;
    const std::vector<Segment> pieces = net.segments_of(b);
    REQUIRE(pieces.size() == 1);
    const Node* start = net.find_node(pieces.front().node0);
    REQUIRE(start != nullptr);
    CHECK((start->position - Vec3(right ? 0.523 : 0.5, 0, 0)).norm() < 1e-12);
    CHECK(start->incidences.size() == 3);  // A, the curve that made it, B
  }
}
