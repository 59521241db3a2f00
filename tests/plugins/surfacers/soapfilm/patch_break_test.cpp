// Item 25's break rule (patch_break.hpp): a new segment breaks a patch only
// if it sits between two consecutive cycle segments at one of its nodes (the
// side the cycle turns through, by the cycle's orientation there) and
// reaches the cycle again.
#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "patch_break.hpp"
#include "patch_upkeep.hpp"
#include "soapfilm_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm_test;

namespace {

constexpr double a = 0.2;
const Vec3 p00(0, 0, 0), p10(a, 0, 0), p11(a, a, 0), p01(0, a, 0), p20(2 * a, 0, 0), p21(2 * a, a, 0);

// Square A = [0, a]² in z = 0, curves 1-4 (bottom, right, top, left).
std::vector<PreparedCurve> square() {
  return {{make_line(p00, p10), {0.0, 1.0}},
          {make_line(p10, p11), {0.0, 1.0}},
          {make_line(p11, p01), {0.0, 1.0}},
          {make_line(p01, p00), {0.0, 1.0}}};
}

// For each patch (by its set of curves) before the last curve was drawn:
// whether that curve breaks it.
std::map<std::set<CurveId>, bool> breaks(const std::vector<PreparedCurve>& curves, bool by_order) {
  PreparedSession s(curves);
  s.draw_all(curves.size() - 1);
  const std::map<PatchId, Patch> before = s.network().patches();
  REQUIRE(s.draw(curves.size()).error == "");
  soapfilm::CycleSearchParams params;
  params.break_by_order = by_order;
  const Network& net = s.network();
  soapfilm::CurveGraph graph(net);
  soapfilm::CycleSearcher searcher(graph, params);
  const CurveId added = net.curves().rbegin()->first;
  const std::vector<int>& fresh_list = graph.segments_of(added);
  const std::set<int> fresh(fresh_list.begin(), fresh_list.end());
  std::map<std::set<CurveId>, bool> out;
  for (const auto& [id, patch] : before) {
    std::set<CurveId> curves_of;
    for (const OrientedSegment& piece : patch.boundary) curves_of.insert(piece.curve);
    const std::vector<int> key = soapfilm::boundary_key(graph, patch.boundary);
    REQUIRE_FALSE(key.empty());
    REQUIRE(soapfilm::cycle_of(graph, patch.boundary).size() >= key.size());
    out[curves_of] = soapfilm::broken_by(graph, searcher, patch, key, fresh, params);
  }
  return out;
}

}  // namespace

TEST_CASE("a patch boundary read back as a chain of graph half-edges, split pieces in turn", "[soapfilm]") {
  // A line from corner p00 to the middle of the right edge splits curve 2.
  std::vector<PreparedCurve> curves = square();
  curves.push_back({make_line(p00, Vec3(a, a / 2, 0)), {0.0, 1.0}});
  PreparedSession s(curves);
  s.draw_all(4);
  const Patch square_patch = s.network().patches().begin()->second;
  s.draw(5);
  soapfilm::CurveGraph graph(s.network());
  const soapfilm::Cycle c = soapfilm::cycle_of(graph, square_patch.boundary);
  REQUIRE(c.size() == 5);
  std::vector<CurveId> along;
  for (std::size_t i = 0; i < c.size(); ++i) {
    CHECK(graph.to(c[i]) == graph.from(c[(i + 1) % c.size()]));
    along.push_back(graph.segment(c[i].segment).curve);
  }
  // The square's own order, curve 2 in its two pieces.
  std::vector<CurveId> expected;
  for (const OrientedSegment& piece : square_patch.boundary) {
    expected.push_back(piece.curve);
    if (piece.curve == 2) expected.push_back(2);
  }
  CHECK(along == expected);
}

TEST_CASE("item 25: a segment between two consecutive cycle segments breaks the patch, one outside does not",
          "[soapfilm]") {
  for (const bool by_order : {true, false}) {
    CAPTURE(by_order);
    // From corner p00 into the square (26.6° up from the bottom edge, inside
    // the corner's 90°) to the middle of the right edge: broken.
    std::vector<PreparedCurve> inside = square();
    inside.push_back({make_line(p00, Vec3(a, a / 2, 0)), {0.0, 1.0}});
    CHECK(breaks(inside, by_order) == std::map<std::set<CurveId>, bool>{{{1, 2, 3, 4}, true}});
    // From p00 straight down and round below the bottom edge to p10: it
    // reaches the cycle again, from outside. Not broken.
    std::vector<PreparedCurve> outside = square();
    Curve bulge;
    bulge.control_points = {p00, Vec3(0, -a / 2, 0), Vec3(a, -a / 2, 0), p10};
    bulge.sharp.assign(2, false);
    outside.push_back({bulge, {0.0, 1.0}});
    CHECK(breaks(outside, by_order) == std::map<std::set<CurveId>, bool>{{{1, 2, 3, 4}, false}});
    // Inside, but ending inside (it does not reach the cycle again).
    std::vector<PreparedCurve> dangling = square();
    dangling.push_back({make_line(p00, Vec3(a / 2, a / 4, 0)), {0.0, 1.0}});
    CHECK(breaks(dangling, by_order) == std::map<std::set<CurveId>, bool>{{{1, 2, 3, 4}, false}});
  }
}

TEST_CASE("item 25: the side is the one the cycle turns through at that node", "[soapfilm]") {
  // Squares A (curves 1-4) and B (5-7, sharing A's right edge 2) make a
  // sheet: A, B, and (the app keeps it, item 24) the sheet's outer border.
  // A line from p10, where the shared edge meets the bottom, into A to the
  // middle of A's left edge: between A's two segments at p10, outside B's
  // (the bottom edges and the shared edge: the quarter on the right), and
  // outside the outer border's there (its two are the bottom edges, and the
  // older shared edge lies on the side it does not turn through).
  std::vector<PreparedCurve> curves = square();
  curves.push_back({make_line(p10, p20), {0.0, 1.0}});
  curves.push_back({make_line(p20, p21), {0.0, 1.0}});
  curves.push_back({make_line(p21, p11), {0.0, 1.0}});
  curves.push_back({make_line(p10, Vec3(0, a / 2, 0)), {0.0, 1.0}});
  const std::set<CurveId> A{1, 2, 3, 4}, B{2, 5, 6, 7}, outer{1, 3, 4, 5, 6, 7};
  CHECK(breaks(curves, true) == std::map<std::set<CurveId>, bool>{{A, true}, {B, false}, {outer, false}});
  // The mesh's side says the same for A and B, but the outer border's mesh
  // spans both squares, so the line enters it.
  CHECK(breaks(curves, false) == std::map<std::set<CurveId>, bool>{{A, true}, {B, false}, {outer, true}});
}
