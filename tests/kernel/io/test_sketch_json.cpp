#include <catch2/catch.hpp>
#include <string>

#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/session.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

std::string error_reading(const std::string& fixture) {
  try {
    read_sketch_json(test::source_path("tests/fixtures/reliability/" + fixture));
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    return what.substr(what.find(fixture) + fixture.size());
  }
  return "no error";
}

std::string error_parsing(const std::string& text) {
  try {
    parse_sketch_json(text, "s.json");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

const std::string workspace =
    R"("workspace":{"up":[0,1,0],"grid_enabled":false,"grid_spacing":0.25,"grid_origin":[0,0,0],)"
    R"("mirror_enabled":false,"mirror_normal":[1,0,0],"mirror_offset":0,"scale":1})";

}  // namespace

TEST_CASE("sketch JSON: integers out of range or fractional are errors, never conversions",
          "[io][sketch_json][reliability]") {
  // Issue 17, D7: these were converted with undefined behaviour (UBSan
  // float-cast-overflow) or silently rounded (version 1.5 read as 1).
  CHECK(error_reading("S1_version_1e300.json") ==
        ": sketch.version: expected an integer in [-9223372036854775808, 9223372036854775807], got 1e+300");
  CHECK(error_reading("S1b.json") ==
        ": sketch.version: expected an integer in [-9223372036854775808, 9223372036854775807], got 1.5");
  CHECK(error_reading("S2_curve_id_negative_fraction.json") ==
        ": curve -1.5.id: expected an integer in [0, 18446744073709551615], got -1.5");
  CHECK(error_reading("S3_fuzzer_curve_id_1.7e24.json") ==
        ": curve 1.6666666666666666e+24.id: expected an integer in [0, 18446744073709551615], got "
        "1.6666666666666666e+24");
  const std::string head = R"({"format":"sketchlab-sketch","version":1,)" + workspace;
  CHECK(error_parsing(head + R"(,"curves":[{"id":-1}]})") ==
        "s.json: curve -1.id: expected an integer in [0, 18446744073709551615], got -1");
  CHECK(error_parsing(R"({"format":"sketchlab-sketch","version":2})") == "s.json: version: only version 1 is supported");
  CHECK(error_parsing(head + R"(,"curves":{}})") == "s.json: sketch.curves: expected a list");
  CHECK(error_parsing(R"([1,2])") == R"(s.json: format: expected "sketchlab-sketch")");
}

TEST_CASE("sketch JSON: patch faces must name vertices of their mesh", "[io][sketch_json][reliability]") {
  const std::string head = R"({"format":"sketchlab-sketch","version":1,)" + workspace +
                           R"(,"counters":{"next_curve":1,"next_node":1,"next_patch":2},"curves":[],"nodes":[],)";
  const auto patch = [&](const std::string& faces) {
    return head + R"("patches":[{"id":1,"automatic":true,"boundary":[],"mesh":{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"faces":)" +
           faces + "}}]}";
  };
  CHECK(error_parsing(patch("[[0,1,3]]")) == "s.json: patch 1.faces: vertex index 3 outside [0, 3)");
  CHECK(error_parsing(patch("[[0,1,-1]]")) == "s.json: patch 1.faces: vertex index -1 outside [0, 3)");
  CHECK_THAT(error_parsing(patch("[[0,1,1e10]]")), Catch::Contains("expected an integer in [-2147483648, 2147483647]"));
}

TEST_CASE("sketch JSON: what sketch_to_json writes reads back", "[io][sketch_json]") {
  Sketch sketch;
  Edit edit;
  NetworkCurve c;
  c.id = 1;
  c.curve = make_line(Vec3(0, 0, 0), Vec3(0.3, 0.1, 0));
  c.keypoints = default_keypoints(c.curve);
  c.source_stroke = 7;
  edit.curves_added.push_back(c);
  sketch.network.apply(edit);
  const std::string text = sketch_to_json(sketch);
  const Sketch back = parse_sketch_json(text, "s.json");
  CHECK(back.network == sketch.network);
  CHECK(sketch_to_json(back) == text);
}
