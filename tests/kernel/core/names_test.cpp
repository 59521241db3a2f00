#include <catch2/catch.hpp>
#include <set>
#include <stdexcept>
#include <string>

#include "sketchlab/constraint.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/stroke.hpp"

using namespace sketchlab;

TEST_CASE("layer names round trip and unknown names list the allowed ones", "[stroke]") {
  for (Layer l : {Layer::scaffold, Layer::shape, Layer::free, Layer::guide, Layer::automatic}) {
    CHECK(layer_from_string(to_string(l)) == l);
  }
  CHECK(to_string(Layer::automatic) == "auto");
  try {
    layer_from_string("curvy");
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    CHECK(msg.find("curvy") != std::string::npos);
    CHECK(msg.find("scaffold, shape, free, guide, auto") != std::string::npos);
  }
}

TEST_CASE("constraint kind names are distinct snake_case and round trip", "[constraint]") {
  std::set<std::string> seen;
  for (int i = 0; i < constraint_kind_count; ++i) {
    const auto k = static_cast<ConstraintKind>(i);
    const std::string name(to_string(k));
    CHECK(seen.insert(name).second);
    for (char c : name) CHECK(((c >= 'a' && c <= 'z') || c == '_'));
    CHECK(constraint_kind_from_string(name) == k);
  }
  CHECK(to_string(ConstraintKind::point_on_curve) == "point_on_curve");
  CHECK_THROWS_WITH(constraint_kind_from_string("Tangent"),
                    Catch::Contains("Tangent") && Catch::Contains("coincident_point"));
}

TEST_CASE("event type names follow the payload alternative", "[event]") {
  CHECK(event_type_name(StrokeEvent{}) == "stroke");
  CHECK(event_type_name(UndoEvent{}) == "undo");
  CHECK(event_type_name(RedoEvent{}) == "redo");
  CHECK(event_type_name(DeleteNearEvent{}) == "delete_near");
  CHECK(event_type_name(DeleteStrokeEvent{}) == "delete_stroke");
  CHECK(event_type_name(ModeEvent{}) == "mode");
  CHECK(event_type_name(WorkspaceEvent{}) == "workspace");
  CHECK(event_type_name(CorrectionEvent{}) == "correction");
  CHECK(event_type_name(AddPatchEvent{}) == "add_patch");
  CHECK(event_type_name(DeletePatchEvent{}) == "delete_patch");
  CHECK(event_type_name(ReferenceEvent{}) == "reference");
  CHECK(event_type_name(RecomputeSurfaceEvent{}) == "recompute_surface");
}
