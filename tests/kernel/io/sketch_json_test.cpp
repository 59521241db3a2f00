#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/network_curve.hpp"
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

TEST_CASE("sketch JSON: a recording given for a sketch is named as one", "[io][sketch_json]") {
  // It used to fail as malformed JSON at line 2 (the recording's first event).
  const std::string recording = test::source_path("tests/fixtures/reliability/H1b_huge_range_mix.jsonl");
  try {
    (void)read_sketch_json(recording);
    FAIL("a recording read as a sketch");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == recording + ": a sketchlab recording (one event per line), not a sketch (format "
                                               "\"sketchlab-sketch\"); replay it first: `sketchlab run` writes "
                                               "each case's sketch.json");
  }
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

TEST_CASE("sketch JSON: patch meshes keep their vertex normals, files without them still read",
          "[io][sketch_json]") {
  Sketch sketch;
  Edit edit;
  edit.curves_added.push_back(make_network_curve(1, make_line(Vec3(0, 0, 0), Vec3(1, 0, 0)), Layer::shape));
  Patch shaded;
  shaded.id = 1;
  shaded.boundary = {OrientedSegment{1, 0.0, 1.0, 1, 1}};
  shaded.mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0.1)};
  shaded.mesh.faces = {{0, 1, 2}};
  shaded.mesh.normals = {Vec3(0, 0, 1), Vec3(0.1, 0, 1).normalized(), Vec3(0, -0.1, 1).normalized()};
  Patch flat = shaded;
  flat.id = 2;
  flat.mesh.normals.clear();
  edit.patches_added = {shaded, flat};
  sketch.network.apply(edit);
  const std::string text = sketch_to_json(sketch);
  const Sketch back = parse_sketch_json(text, "s.json");
  CHECK(back.network == sketch.network);  // normals included, to the last bit
  CHECK(back.network.patches().at(1).mesh.normals == shaded.mesh.normals);
  CHECK(back.network.patches().at(2).mesh.normals.empty());
  const auto j = nlohmann::json::parse(text);
  CHECK(j.at("patches")[0].at("mesh").at("normals").size() == 3);
  CHECK_FALSE(j.at("patches")[1].at("mesh").contains("normals"));  // as files were before normals

  // Not one normal per vertex, or not a vector: the patch and field named.
  auto edited = j;
  edited["patches"][0]["mesh"]["normals"].erase(2);
  CHECK(error_parsing(edited.dump()) ==
        "s.json: patch 1.normals: 2 normals for 3 vertices (one per vertex, or the key left out)");
  edited = j;
  edited["patches"][0]["mesh"]["normals"][1] = nlohmann::json::array({0, 1});
  CHECK(error_parsing(edited.dump()) == "s.json: patch 1.normals: expected [x, y, z]");
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

TEST_CASE("sketch JSON: nodes, workspace, raw stroke ids and each stroke's constraints, equal sketches, equal bytes",
          "[io][sketch_json]") {
  Sketch sketch;
  sketch.workspace.grid_enabled = true;
  sketch.workspace.grid_spacing = 0.1;
  sketch.workspace.mirror_enabled = true;
  sketch.workspace.mirror_normal = Vec3(0, 0, 1);
  sketch.workspace.mirror_offset = 0.05;
  Edit edit;
  for (CurveId id : {1, 2}) {
    NetworkCurve c;
    c.id = id;
    c.curve = id == 1 ? make_line(Vec3(0, 0, 0), Vec3(0.4, 0, 0)) : make_line(Vec3(0.2, -0.2, 0), Vec3(0.2, 0.2, 0));
    c.keypoints = default_keypoints(c.curve);
    c.source_stroke = 10 + id;
    edit.curves_added.push_back(c);
  }
  // The two lines cross at their midpoints (t = 0.5 on each).
  edit.nodes_added.push_back(Node{1, Vec3(0.2, 0, 0), {{1, 0.5}, {2, 0.5}}});
  sketch.network.apply(edit);
  sketch.strokes[11].id = 11;
  sketch.strokes[12].id = 12;

  StepReport step;
  step.event = EventKind::stroke;
  step.stroke = 12;
  Constraint c;
  c.kind = ConstraintKind::intersection;
  c.references = {{ConstraintRef::Kind::stroke, 12, 0.5}, {ConstraintRef::Kind::curve, 1, 0.5}};
  c.target = Vec3(0.2, 0, 0);
  c.enforced = true;
  c.residual = 1e-12;
  step.constraints = {c};
  StepReport undo = step;  // constraints of anything but a stroke are not written
  undo.event = EventKind::undo;
  const std::vector<StepReport> steps{step, undo};

  const std::string text = sketch_to_json(sketch, &steps);
  const auto j = nlohmann::json::parse(text);
  CHECK(j.at("strokes") == nlohmann::json::array({11, 12}));
  REQUIRE(j.at("constraints").size() == 1);
  CHECK(j.at("constraints")[0].at("stroke") == 12);
  CHECK(j.at("constraints")[0].at("constraints")[0].at("kind") == "intersection");
  CHECK(j.at("constraints")[0].at("constraints")[0].at("residual") == 1e-12);
  CHECK(j.at("segments").empty());  // segments run between nodes: one node per curve makes none

  Sketch back = parse_sketch_json(text, "s.json");
  CHECK(back.network == sketch.network);
  CHECK(back.workspace == sketch.workspace);
  CHECK(back.strokes.empty());  // the file keeps the strokes' ids, not their samples
  back.strokes = sketch.strokes;
  CHECK(sketch_to_json(back, &steps) == text);
}
