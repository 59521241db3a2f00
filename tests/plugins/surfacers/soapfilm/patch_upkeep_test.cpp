// Patch upkeep after a deletion (patch_upkeep.hpp): the segments at the
// nodes the deleted curve touched, and the segments left of the patches it
// took away (broken cycles' seeds, CASSIE app items 25 and 27), are searched
// again; both are read from the sketch's history, without state in the plugin.
#include <catch2/catch.hpp>

#include "patch_upkeep.hpp"
#include "soapfilm_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm_test;

namespace {

// The upkeep of the last edit (a deletion) run again on the sketch as it is.
soapfilm::UpkeepResult upkeep_of_last(const PreparedSession& s) {
  const Sketch& sketch = s.session.sketch();
  return soapfilm::patch_upkeep(sketch, sketch.history.done.back().steps.front().forward, {});
}

}  // namespace

TEST_CASE("a deletion searches the segments left of the patches it took away", "[soapfilm]") {
  const auto edges = cube_edges(0.2);
  PreparedSession s(edges);
  s.draw_all(edges.size());
  REQUIRE(s.network().patches().size() == 6);
  // Edge 1 bounds two faces. Its two corners keep two edges each (4
  // segments); the two faces keep three edges each, of which the far edge
  // of each is at neither corner: 6 seeds.
  REQUIRE(s.handle(DeleteStrokeEvent{1}).error == "");
  CHECK(upkeep_of_last(s).seeds == 6);
}

TEST_CASE("a patch removed before its curve is deleted is not a seed then", "[soapfilm]") {
  const auto edges = cube_edges(0.2);
  PreparedSession s(edges);
  s.draw_all(edges.size());
  // One of edge 1's faces deleted by hand first (the history's surfacer
  // step removes it), then edge 1: only the other face is taken away with
  // the curve, so its far edge is the one seed added to the 4 at the
  // corners.
  std::set<PatchId> on_edge_1;
  for (const auto& [id, p] : s.network().patches())
    for (const auto& piece : p.boundary)
      if (piece.curve == 1) on_edge_1.insert(id);
  REQUIRE(on_edge_1.size() == 2);
  const Mesh& face = s.network().patches().at(*on_edge_1.begin()).mesh;
  REQUIRE(!face.faces.empty());
  const auto& f = face.faces.front();
  const Vec3 inside = (face.vertices[f[0]] + face.vertices[f[1]] + face.vertices[f[2]]) / 3.0;
  REQUIRE(s.handle(DeletePatchEvent{inside}).patches_removed == 1);
  REQUIRE(!s.network().patches().count(*on_edge_1.begin()));
  REQUIRE(s.handle(DeleteStrokeEvent{1}).error == "");
  CHECK(upkeep_of_last(s).seeds == 5);
}
