// CASSIE's graph rebuilt while its curves are replayed (cassie_graph_edit.hpp,
// CASSIE app item 22).
#include <algorithm>

#include <catch2/catch.hpp>

#include "cassie_graph.hpp"
#include "cassie_graph_edit.hpp"
#include "curve_graph.hpp"
#include "cycle_search.hpp"

using namespace sketchlab;

namespace {

Curve straight(const Vec3& a, const Vec3& b) {
  Curve c;
  c.control_points = {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b};
  c.sharp = {false, false};
  return c;
}

// The node where the curve of `stroke` starts, when it is one segment.
const Node* start_node(const Network& net, StrokeId stroke) {
  for (const auto& [id, c] : net.curves())
    if (c.source_stroke == stroke) {
      const std::vector<Segment> pieces = net.segments_of(id);
      return pieces.size() == 1 ? net.find_node(pieces.front().node0) : nullptr;
    }
  return nullptr;
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
  const Node* start = start_node(net, 2);
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
    const Node* start = start_node(net, 4);
    REQUIRE(start != nullptr);
    CHECK((start->position - Vec3(right ? 0.523 : 0.5, 0, 0)).norm() < 1e-12);
    CHECK(start->incidences.size() == 3);  // A, the curve that made it, B
  }
}

TEST_CASE("a node a deleted curve left inside another is reused only with reuse_left_over", "[soapfilm]") {
  // A, then C ending on A at x = 0.5 (a node there), then C deleted: the node
  // stays on A alone, no graph node. B then ends on A 7 mm from it (within δ,
  // beyond 0.5δ), as teapot's stroke 94 next to what strokes 44/45 left.
  auto build = [](bool reuse_left_over) {
    soapfilm::CassieGraphParams params;
    params.reuse_left_over = reuse_left_over;
    Network net;
    net.apply(soapfilm::cassie_graph_edit(net, {{1, straight({0, 0, 0}, {1, 0, 0})}}, params));
    net.apply(soapfilm::cassie_graph_edit(net, {{2, straight({0.5, 0, 0}, {0.5, 1, 0})}}, params));
    Edit del;
    for (const auto& [id, c] : net.curves())
      if (c.source_stroke == 2) del.curves_removed.push_back(id);
    net.apply(del);
    net.apply(soapfilm::cassie_graph_edit(net, {{3, straight({0.507, 0, 0}, {0.507, -1, 0})}}, params));
    return net;
  };
  // CASSIE's graph: the node where B meets A (its exported final graphs).
  Network cassie;
  cassie.apply(soapfilm::cassie_graph_edit(cassie, {{1, straight({0, 0, 0}, {1, 0, 0})}}));
  cassie.apply(soapfilm::cassie_graph_edit(cassie, {{3, straight({0.507, 0, 0}, {0.507, -1, 0})}}));
  REQUIRE(cassie.nodes().size() == 4);

  const Network reused = build(true);
  const Node* n = start_node(reused, 3);
  REQUIRE(n != nullptr);
  CHECK((n->position - Vec3(0.5, 0, 0)).norm() < 1e-12);
  CHECK(n->incidences.size() == 2);  // A and B
  soapfilm::NodeAgreement a = soapfilm::compare_graph_nodes(cassie, reused);
  CHECK(a.cassie == 4);
  CHECK(a.ours == 4);
  CHECK(a.cassie_matched == 3);
  CHECK(a.ours_matched == 3);

  const Network fresh = build(false);
  n = start_node(fresh, 3);
  REQUIRE(n != nullptr);
  CHECK((n->position - Vec3(0.507, 0, 0)).norm() < 1e-12);
  CHECK(n->incidences.size() == 2);
  CHECK(fresh.nodes().size() == 5);  // the left-over one stays, no graph node
  a = soapfilm::compare_graph_nodes(cassie, fresh);
  CHECK(a.ours == 4);
  CHECK(a.cassie_matched == 4);
  CHECK(a.ours_matched == 4);
}

TEST_CASE("a meeting reuses the new curve's node within 0.5 delta before the old curve's within delta",
          "[soapfilm]") {
  // CASSIE app, item 22: "an intersection reuses a node within 0.5δ on the
  // new stroke, within δ on the old one". A runs along x with node M at
  // x = 0.5 (where D starts); C passes 8 mm above A's line, along z. B, two
  // cubic pieces, meets C at its joint t = 1 (a new node N there) and ends
  // on A at x = 0.506: 8.9 mm from N (within 0.5δ = 1 cm) and 6 mm from M
  // (within δ). Both are candidates; the order decides which node B's end
  // joins.
  for (const bool new_first : {true, false}) {
    soapfilm::CassieGraphParams params;
    params.reuse_new_first = new_first;
    Network net;
    net.apply(soapfilm::cassie_graph_edit(net, {{1, straight({0, 0, 0}, {1, 0, 0})}}, params));
    net.apply(soapfilm::cassie_graph_edit(net, {{2, straight({0.5, 0, 0}, {0.5, -1, 0})}}, params));
    net.apply(soapfilm::cassie_graph_edit(net, {{3, straight({0.51, 0.008, -0.5}, {0.51, 0.008, 0.5})}}, params));
    REQUIRE(net.nodes().size() == 6);  // A's ends, M, D's far end, C's ends (C meets nothing)
    Curve b;
    const Vec3 p0(0.51, 0.5, 0), p1(0.51, 0.008, 0), p2(0.506, 0, 0);
    b.control_points = {p0, p0 + (p1 - p0) / 3.0, p0 + 2.0 * (p1 - p0) / 3.0, p1,
                        p1 + (p2 - p1) / 3.0, p1 + 2.0 * (p2 - p1) / 3.0, p2};
    b.sharp = {false, false, false};
    net.apply(soapfilm::cassie_graph_edit(net, {{4, b}}, params));
    const NetworkCurve* a = nullptr;
    const NetworkCurve* bc = nullptr;
    for (const auto& [id, c] : net.curves()) {
      if (c.source_stroke == 1) a = &c;
      if (c.source_stroke == 4) bc = &c;
    }
    REQUIRE(a != nullptr);
    REQUIRE(bc != nullptr);
    const auto node_near = [&](const Vec3& p) -> const Node* {
      const std::vector<NodeHit> hits = net.nodes_near(p, 1e-9);
      return hits.size() == 1 ? net.find_node(hits.front().node) : nullptr;
    };
    const Node* m = node_near({0.5, 0, 0});
    const Node* n = node_near(p1);
    REQUIRE(m != nullptr);
    REQUIRE(n != nullptr);
    const auto on = [](const Node* x, CurveId c) {
      return std::any_of(x->incidences.begin(), x->incidences.end(), [&](const NodeIncidence& i) { return i.curve == c; });
    };
    CHECK(net.nodes().size() == 8);  // and B's start and N
    // New first: N joins A too (B's end has no node of its own: N is within
    // 0.5δ of it); old first: B's end is M.
    CHECK(on(n, a->id) == new_first);
    CHECK(on(m, bc->id) == !new_first);
    CHECK(n->incidences.size() == (new_first ? 3u : 2u));
    CHECK(m->incidences.size() == (new_first ? 2u : 3u));
  }
}

TEST_CASE("a joint near a logged applied intersection meets the old curve 0.5 mm off it", "[soapfilm]") {
  // CASSIE app, items 21–22: the graph's intersections are the intersection
  // constraints the solve applied, though it may leave the end off the old
  // curve (vintage_car's stroke 530, 0.73 mm). A, then B from A's start, then
  // C from B's end to 0.5 mm above A at x = 0.7: with C's log holding an
  // applied intersection at (0.7, 0, 0) and logged_meets, C's end splits A
  // and closes the triangle; unlogged, or logged as no intersection, or with
  // logged_meets off, C's end hangs free and nothing closes.
  const Curve a = straight({0, 0, 0}, {1, 0, 0}), b = straight({0, 0, 0}, {0.7, 0.5, 0}),
              c = straight({0.7, 0.5, 0}, {0.7, 0.0005, 0});
  auto cycles_through_c = [&](const CassieConstraintLog* log, double logged_meets, bool logged_only) {
    soapfilm::CassieGraphParams params;
    params.logged_meets = logged_meets;
    params.logged_only = logged_only;
    Network net;
    net.apply(soapfilm::cassie_graph_edit(net, {{1, a}}, params));
    net.apply(soapfilm::cassie_graph_edit(net, {{2, b}}, params));
    net.apply(soapfilm::cassie_graph_edit(net, {{3, c, 1.0, log}}, params));
    soapfilm::CurveGraph graph(net);
    soapfilm::CycleSearcher searcher(graph, {});
    std::size_t found = 0;
    for (const auto& [id, curve] : net.curves())
      if (curve.source_stroke == 3)
        for (int s : graph.segments_of(id)) found += searcher.search_segment(s).size();
    return found;
  };
  CassieConstraintLog logged;
  logged.applied = {Vec3(0.7, 0, 0), Vec3(0.7, 0.5, 0)};
  logged.applied_intersection = {true, true};
  CHECK(cycles_through_c(&logged, 0.5, false) > 0);
  CHECK(cycles_through_c(&logged, 0.5, true) > 0);  // C's start is logged too
  CHECK(cycles_through_c(&logged, 0.0, false) == 0);
  CHECK(cycles_through_c(nullptr, 0.5, false) == 0);
  CassieConstraintLog plane = logged;  // a plane or grid constraint there
  plane.applied_intersection = {false, true};
  CHECK(cycles_through_c(&plane, 0.5, false) == 0);
  CassieConstraintLog bare = logged;  // an older export: a bare point on A is an intersection
  bare.applied_intersection = {std::nullopt, std::nullopt};
  CHECK(cycles_through_c(&bare, 0.5, false) > 0);
  CassieConstraintLog elsewhere = logged;  // logged 2 cm along A: too far from C's end
  elsewhere.applied[0] = Vec3(0.72, 0, 0);
  CHECK(cycles_through_c(&elsewhere, 0.5, false) == 0);
  // logged_only: C's start, on B's end node, meets B only where it is logged.
  CassieConstraintLog end_only = logged;
  end_only.applied = {Vec3(0.7, 0, 0)};
  end_only.applied_intersection = {true};
  CHECK(cycles_through_c(&end_only, 0.5, false) > 0);
  CHECK(cycles_through_c(&end_only, 0.5, true) == 0);
}
