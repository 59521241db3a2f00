// Reading CASSIE's files: the real networks that used to crash the loader
// load with a warning, malformed ones fail with the file and the element
// named, and the session timeline handles the flower quirk.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "cassie_graph.hpp"
#include "cassie_session.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

struct Scratch {
  explicit Scratch(const std::string& name) : dir(fs::temp_directory_path() / ("sketchlab_test_cassie_" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir / "sketch_graph");
    fs::create_directories(dir / "sketch_history");
    fs::create_directories(dir / "raw_data");
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  fs::path write(const std::string& rel, const std::string& text) const {
    std::ofstream(dir / rel) << text;
    return dir / rel;
  }
  fs::path dir;
};

// Two strokes meeting at node 1: stroke 0 = segments 0 and 1, stroke 1 = segment 2.
const char* graph_json = R"({
  "strokes": [{"id": 0, "segments": [0, 1]}, {"id": 1, "segments": [2]}],
  "segments": [
    {"id": 0, "stroke_id": 0, "ctrl_pts": [[[0,0,0],[0.1,0,0]]], "nodes": [0, 1]},
    {"id": 1, "stroke_id": 0, "ctrl_pts": [[[0.1,0,0],[0.13,0.01,0],[0.17,0.01,0],[0.2,0,0]]], "nodes": [1, 2]},
    {"id": 2, "stroke_id": 1, "ctrl_pts": [[[0.1,0,0],[0.1,0.1,0]]], "nodes": [1, 3]}],
  "nodes": [{"id": 0, "position": [0,0,0]}, {"id": 1, "position": [0.1,0,0]},
            {"id": 2, "position": [0.2,0,0]}, {"id": 3, "position": [0.1,0.1,0]}]})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

std::string load_error(const Scratch& s, const std::string& text) {
  const fs::path p = s.write("sketch_graph/bad.json", text);
  try {
    soapfilm::load_cassie_network(p);
  } catch (const soapfilm::CassieFormatError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("CASSIE graphs with a stroke without segments load, with a warning", "[soapfilm]") {
  // Both used to crash load_cassie_network (an empty control point list).
  for (const auto& [name, stroke, strokes] : {std::tuple{"02-2-1", 60, 47}, std::tuple{"hmd_sutherland", 236, 222}}) {
    const auto net = soapfilm::load_cassie_network(test::source_path("data/cassie/sketch_graph/") + name + ".json");
    CHECK(net.network.curves().size() == static_cast<std::size_t>(strokes));
    REQUIRE(net.warnings.size() == 1);
    CHECK_THAT(net.warnings[0], Catch::Contains(name) && Catch::Contains("stroke " + std::to_string(stroke)) &&
                                    Catch::Contains("no segments"));
  }
  const auto hat = soapfilm::load_cassie_network(test::source_path("data/cassie/sketch_graph/hat.json"));
  CHECK(hat.warnings.empty());
  CHECK(hat.network.curves().size() == 69);
  CHECK(hat.network.nodes().size() == 98);
  CHECK(hat.network.segments().size() == 169);  // CASSIE's graph has 169 segments
}

TEST_CASE("malformed CASSIE graphs fail naming the file and the element", "[soapfilm]") {
  Scratch s("graph");
  const auto good = soapfilm::load_cassie_network(s.write("sketch_graph/good.json", graph_json));
  CHECK(good.network.curves().size() == 2);
  CHECK(good.network.nodes().size() == 4);
  CHECK(good.network.segments().size() == 3);

  CHECK_THAT(load_error(s, "{"), Catch::Contains("bad.json"));
  CHECK_THAT(load_error(s, replace(graph_json, "[2]}]", "[7]}]")),
             Catch::Contains("bad.json") && Catch::Contains("stroke 1: segment 7 does not exist"));
  CHECK_THAT(load_error(s, replace(graph_json, "\"nodes\": [1, 3]", "\"nodes\": [1, 9]")),
             Catch::Contains("stroke 1: segment 2: node 9 does not exist"));
  CHECK_THAT(load_error(s, replace(graph_json, "[[[0,0,0],[0.1,0,0]]]", "[[[0,0,0],[0.05,0,0],[0.1,0,0]]]")),
             Catch::Contains("stroke 0: segment 0: piece 0 has 3 control points; need 4 (cubic) or 2 (line)"));
  CHECK_THAT(load_error(s, replace(graph_json, "[[[0.1,0,0],[0.1,0.1,0]]]", "[[[0.1,0,0],[0.1,\"x\",0]]]")),
             Catch::Contains("stroke 1: segment 2: piece 0, point 1: coordinate 1 is not a number"));
  CHECK_THAT(load_error(s, replace(graph_json, "[[[0.1,0,0],[0.1,0.1,0]]]", "[[[0.1,0,0],[0.1,1e300,0]]]")),
             Catch::Contains("stroke 1: segment 2: piece 0, point 1: coordinate of magnitude above 1000000 m"));
  CHECK_THAT(load_error(s, replace(graph_json, "[[[0.1,0,0],[0.13", "[[[0.3,0,0],[0.13")),
             Catch::Contains("stroke 0: segment 1 starts") && Catch::Contains("previous segment"));
  CHECK_THAT(load_error(s, replace(graph_json, "[2]}]", "[1]}]")),
             Catch::Contains("stroke 1: segment 1 already belongs to stroke 0"));
  CHECK_THAT(load_error(s, replace(graph_json, "\"strokes\"", "\"strokez\"")),
             Catch::Contains("missing field 'strokes'"));
  CHECK_THAT(load_error(s, "{\"strokes\": 5, \"segments\": [], \"nodes\": []}"),
             Catch::Contains("bad.json") && Catch::Contains("the graph: field 'strokes' is not a list"));
  CHECK_THAT(load_error(s, "{\"strokes\": [], \"segments\": {\"id\": 0}, \"nodes\": []}"),
             Catch::Contains("the graph: field 'segments' is not a list"));
  CHECK_THAT(load_error(s, replace(graph_json, "{\"id\": 1, \"segments\": [2]}", "{\"id\": 0, \"segments\": [2]}")),
             Catch::Contains("stroke 0 listed twice"));
  CHECK_THAT(load_error(s, replace(graph_json, "\"stroke_id\": 1,", "\"stroke_id\": 0,")),
             Catch::Contains("stroke 1: segment 2: its stroke_id 0 is not stroke 1, which lists it"));
  CHECK_THAT(load_error(s, replace(graph_json, "\"nodes\": [1, 3]", "\"nodes\": [1]")),
             Catch::Contains("stroke 1: segment 2: needs 2 nodes"));
}

TEST_CASE("CASSIE sessions: curves, times, patch log, the flower quirk is a warning", "[soapfilm]") {
  const auto flower = soapfilm::load_cassie_session(test::source_path("data/cassie"), "flower", true);
  CHECK(flower.system == 2);
  CHECK(flower.strokes.size() == 131);
  CHECK(flower.patches.size() == 93);
  // Strokes 10 and 11 (a mirrored pair) are deleted before they are created
  // in sketch_history; raw_data deletes stroke 10 again at 95.2 s.
  REQUIRE(flower.warnings.size() == 2);
  for (const std::int64_t id : {10, 11}) {
    const auto it = std::find_if(flower.strokes.begin(), flower.strokes.end(), [&](const auto& x) { return x.id == id; });
    REQUIRE(it != flower.strokes.end());
    const auto& st = *it;
    REQUIRE(st.deleted);
    CHECK(*st.deleted == Approx(95.20064));
    CHECK(*st.deleted > st.created);
  }
  CHECK_THAT(flower.warnings[0], Catch::Contains("flower.json") && Catch::Contains("stroke 10"));
  // Every patch has its add-surface time; manual ones a hand position.
  int automatic = 0, with_hand = 0;
  for (const auto& p : flower.patches) {
    CHECK(p.created);
    automatic += p.automatic;
    with_hand += !p.automatic && p.hand;
  }
  CHECK(automatic == 74);
  CHECK(with_hand == 19);
  // CASSIE's constraint logs (items 21–22): the drawn strokes' and, reflected,
  // their mirrored twins'.
  std::size_t twins = 0;
  for (const auto& [id, log] : flower.logs) twins += log.mirrored_twin;
  CHECK(flower.logs.size() > 124);
  CHECK(twins == flower.logs.size() - 124);

  Scratch s("session");
  s.write("raw_data/x.json", R"({"sketchSystem": 2, "systemStates": [], "allCreatedPatches": []})");
  s.write("sketch_history/x.json", R"([{"id": 0, "ctrl_pts": [[[0,0,0],[1,0,0],[2,0,0],[3,0]]], "creation_time": 1.0}])");
  CHECK_THROWS_WITH(soapfilm::load_cassie_session(s.dir, "x"),
                    Catch::Contains("x.json") && Catch::Contains("stroke 0: piece 0, point 3"));
  s.write("sketch_history/x.json", R"([{"id": 0, "ctrl_pts": [[[0,0,0],[1,0,0]]]}])");
  CHECK_THROWS_WITH(soapfilm::load_cassie_session(s.dir, "x"), Catch::Contains("stroke 0: missing field 'creation_time'"));
  s.write("sketch_history/x.json", R"([{"id": 0, "ctrl_pts": [[[0,0,0],[1,0,0]]], "creation_time": 1.0}])");
  s.write("raw_data/x.json", R"({"sketchSystem": 2, "systemStates": [{"interactionType": 3, "time": "soon", "elementID": 0}],
                               "allCreatedPatches": []})");
  CHECK_THROWS_WITH(soapfilm::load_cassie_session(s.dir, "x"),
                    Catch::Contains("raw_data") && Catch::Contains("systemStates[0]: field 'time' must be a finite number"));
  s.write("raw_data/x.json", R"({"sketchSystem": 2, "systemStates": [{"interactionType": 3, "time": 2.0, "elementID": 5}],
                               "allCreatedPatches": []})");
  const auto x = soapfilm::load_cassie_session(s.dir, "x");
  REQUIRE(x.warnings.size() == 1);
  CHECK_THAT(x.warnings[0], Catch::Contains("systemStates[0] names patch 5"));
  // A malformed constraint log is an error naming the file and the field; a
  // history without input samples (which the twins' reflection needs) only
  // leaves the twins without logs.
  s.write("raw_data/x.json", R"({"sketchSystem": 2, "systemStates": [], "allCreatedPatches": [],
      "allSketchedStrokes": [{"id": 0, "appliedPositionConstraints": [{"position": {"x": 0, "y": 0, "z": 0}, "isIntersection": "yes"}]}]})");
  CHECK_THROWS_WITH(soapfilm::load_cassie_session(s.dir, "x", true),
                    Catch::Contains("x.json") && Catch::Contains("appliedPositionConstraints[0]") &&
                        Catch::Contains("'isIntersection' must be true or false"));
  s.write("raw_data/x.json", R"({"sketchSystem": 2, "systemStates": [], "allCreatedPatches": [],
      "allSketchedStrokes": [{"id": 0, "appliedPositionConstraints": [{"position": {"x": 0, "y": 0, "z": 0}, "isIntersection": true}]}]})");
  const auto logged = soapfilm::load_cassie_session(s.dir, "x", true);
  REQUIRE(logged.logs.count(0) == 1);
  CHECK(logged.logs.at(0).applied_intersection == std::vector<std::optional<bool>>{true});
  REQUIRE(logged.warnings.size() == 1);
  CHECK_THAT(logged.warnings[0], Catch::Contains("x.json") && Catch::Contains("twins get no constraint log"));
}
