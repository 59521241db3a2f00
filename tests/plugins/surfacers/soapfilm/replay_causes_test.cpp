// The replay's cause of a missing CASSIE patch (replay_causes.hpp), on a cube
// drawn through the surfacer: each cause is reached by exactly the situation
// it names.
#include <catch2/catch.hpp>

#include "replay_causes.hpp"
#include "soapfilm_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm_test;

TEST_CASE("a missing CASSIE patch is classified by what stops it on our network", "[soapfilm]") {
  const auto edges = cube_edges(0.2);
  PreparedSession s(edges);
  s.draw_all(edges.size());
  REQUIRE(s.network().patches().size() == 6);
  // Stroke k (1..12) drew the cube edge edges[k-1]; the replay knows curves by
  // CASSIE stroke id the same way.
  std::map<std::int64_t, CurveId> curve_of;
  for (const auto& [id, c] : s.network().curves()) curve_of[c.source_stroke] = id;
  // The bottom (z = 0) and top faces: the edges with both ends at that z.
  soapfilm::StrokeSet bottom, top;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const Curve& c = edges[k].curve;
    const double z0 = c.control_points.front().z(), z1 = c.control_points.back().z();
    if (z0 == 0.0 && z1 == 0.0) bottom.insert(static_cast<std::int64_t>(k + 1));
    if (z0 > 0.1 && z1 > 0.1) top.insert(static_cast<std::int64_t>(k + 1));
  }
  REQUIRE(bottom.size() == 4);
  REQUIRE(top.size() == 4);
  const soapfilm::CycleSearchParams params;
  using soapfilm::MissingCycle;

  // Every edge of the face already bounds two patches (the face and a side).
  CHECK(soapfilm::classify_missing(s.network(), curve_of, bottom, params) == MissingCycle::refused_two);

  // A stroke with no curve of ours.
  soapfilm::StrokeSet with_unknown = bottom;
  with_unknown.insert(99);
  CHECK(soapfilm::classify_missing(s.network(), curve_of, with_unknown, params) == MissingCycle::curve_absent);

  // Two bottom and two top edges hold no closed path at all.
  const soapfilm::StrokeSet not_a_face = {*bottom.begin(), *std::next(bottom.begin()), *top.begin(),
                                          *std::next(top.begin())};
  CHECK(soapfilm::classify_missing(s.network(), curve_of, not_a_face, params) == MissingCycle::not_closed);

  // The belt of six edges round the cube (corners 0-1-3-7-6-4, bits x, y, z)
  // is a closed path but no face: the walks never close over it.
  const auto corners = cube_corners(0.2);
  auto edge = [&](int i, int j) {
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const Curve& c = edges[k].curve;
      const Vec3 a = c.control_points.front(), b = c.control_points.back();
      const Vec3 p = corners[static_cast<std::size_t>(i)], q = corners[static_cast<std::size_t>(j)];
      if (((a - p).norm() < 1e-12 && (b - q).norm() < 1e-12) || ((a - q).norm() < 1e-12 && (b - p).norm() < 1e-12))
        return static_cast<std::int64_t>(k + 1);
    }
    return std::int64_t{-1};
  };
  const soapfilm::StrokeSet belt = {edge(0, 1), edge(1, 3), edge(3, 7), edge(7, 6), edge(6, 4), edge(4, 0)};
  REQUIRE(belt.size() == 6);
  REQUIRE(!belt.count(-1));
  soapfilm::AstrayDetail astray;
  CHECK(soapfilm::classify_missing(s.network(), curve_of, belt, params, &astray) == MissingCycle::not_found);
  // Every corner is a sharp three-edge corner (item 23: |n·t| = 0.577); the
  // belt shares two consecutive edges with each face it borders, so the walk
  // following it longest turns into that face after two of its edges.
  CHECK(astray.where == soapfilm::Departure::at_sharp);
  CHECK(astray.segments == 3);
  CHECK(astray.max_offset == Approx(1.0 / std::sqrt(3.0)));
  CHECK(astray.length == 6);
  CHECK(astray.followed == 2);
  REQUIRE(astray.taken);
  REQUIRE(astray.wanted);
  CHECK(*astray.taken != *astray.wanted);

  // The bottom face deleted by hand: its edges bound one patch each, a walk
  // closes over it and nothing refuses it.
  s.handle(DeletePatchEvent{Vec3(0.1, 0.1, 0.0)});
  REQUIRE(s.network().patches().size() == 5);
  CHECK(soapfilm::classify_missing(s.network(), curve_of, bottom, params) == MissingCycle::not_searched);
}
