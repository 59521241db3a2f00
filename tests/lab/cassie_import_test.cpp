#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "sketchlab/workspace.hpp"
#include "test_paths.hpp"

using namespace sketchlab;
using nlohmann::json;

namespace {

// Every bundled session: six showcase sketches and every session of two study
// participants in the three systems (data/cassie/README.md).
const char* const sessions[] = {"hat",    "chair",  "flower", "teapot", "vintage_car", "hmd_sutherland",
                                "01-0-1", "01-0-2", "01-1-1", "01-1-2", "01-2-1",      "01-2-2",
                                "02-0-1", "02-0-2", "02-1-1", "02-1-2", "02-2-1",      "02-2-2"};

std::filesystem::path cassie_dir() { return test::source_path("data/cassie"); }

json load(const std::string& rel) {
  std::ifstream in(cassie_dir() / rel);
  return json::parse(in);
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Vec3 vec(const json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

}  // namespace

// The bundled recordings are the importer's output; set
// SKETCHLAB_REGENERATE_RECORDINGS=1 to rewrite them after a deliberate change.
TEST_CASE("importing the bundled CASSIE sessions reproduces data/recordings byte for byte",
          "[recording][cassie]") {
  const bool regenerate = std::getenv("SKETCHLAB_REGENERATE_RECORDINGS") != nullptr;
  for (const char* name : sessions) {
    INFO(name);
    const Recording r = import_cassie_session(cassie_dir(), name);
    std::ostringstream os;
    write_recording(os, r);
    const std::filesystem::path bundled =
        test::source_path("data/recordings/" + std::string(name) + ".jsonl");
    if (regenerate) write_recording(bundled, r, /*overwrite=*/true);
    CHECK(os.str() == slurp(bundled));
    CHECK(read_recording(bundled) == r);
  }
}

TEST_CASE("CASSIE import: strokes, deletions and reference curves match the history",
          "[recording][cassie]") {
  for (const char* name : sessions) {
    INFO(name);
    const json history = load("sketch_history/" + std::string(name) + ".json");
    const Recording r = import_cassie_session(cassie_dir(), name);

    std::vector<const Stroke*> strokes;
    std::map<StrokeId, double> deletions;
    std::map<StrokeId, const ReferenceEvent*> refs;
    double last_time = -1.0;
    for (std::size_t i = 0; i < r.events.size(); ++i) {
      const Event& e = r.events[i];
      CHECK(e.time >= last_time);
      last_time = e.time;
      if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
        strokes.push_back(&s->stroke);
        // The reference curve comes right after its stroke.
        REQUIRE(i + 1 < r.events.size());
        const auto* ref = std::get_if<ReferenceEvent>(&r.events[i + 1].payload);
        REQUIRE(ref);
        CHECK(ref->stroke == s->stroke.id);
        CHECK(ref->track == "cassie");
        refs[ref->stroke] = ref;
      } else if (const auto* d = std::get_if<DeleteStrokeEvent>(&e.payload)) {
        CHECK(deletions.emplace(d->stroke, e.time).second);
      }
    }
    REQUIRE(strokes.size() == history.size());
    std::size_t deleted = 0;
    for (std::size_t i = 0; i < history.size(); ++i) {
      const json& h = history[i];
      const Stroke& s = *strokes[i];
      CHECK(s.id == h["id"].get<StrokeId>());
      CHECK(s.layer == Layer::automatic);
      REQUIRE(s.samples.size() == h["input_samples"].size());
      for (std::size_t k = 0; k < s.samples.size(); ++k) {
        CHECK(s.samples[k].position == vec(h["input_samples"][k]));
        CHECK(s.samples[k].pressure == 1.0);
        if (k > 0) CHECK(s.samples[k].time >= s.samples[k - 1].time);
      }
      CHECK(s.samples.back().time == h["creation_time"].get<double>());
      CHECK(s.samples.front().time < s.samples.back().time);
      CHECK(s.workspace_scale >= 1.0);
      CHECK(s.workspace_scale <= 3.0);
      if (h["deletion_time"].is_null()) {
        CHECK(deletions.count(s.id) == 0);
      } else if (h["deletion_time"].get<double>() < h["creation_time"].get<double>()) {
        // flower's quirk: the delete action raw_data logged after creation.
        ++deleted;
        REQUIRE(deletions.count(s.id) == 1);
        CHECK(deletions.at(s.id) > h["creation_time"].get<double>());
      } else {
        ++deleted;
        REQUIRE(deletions.count(s.id) == 1);
        CHECK(deletions.at(s.id) == h["deletion_time"].get<double>());
      }
      // Reference curve = CASSIE's ctrl_pts joined.
      const Curve& c = refs.at(s.id)->curve;
      const json& ctrl = h["ctrl_pts"];
      if (h["curve_type"] == "line") {
        CHECK(c.kind == CurveKind::line);
        CHECK(c.control_points.front() == vec(ctrl[0][0]));
        CHECK(c.control_points.back() == vec(ctrl[0][1]));
      } else {
        CHECK(c.kind == CurveKind::bezier);
        REQUIRE(c.segment_count() == static_cast<int>(ctrl.size()));
        for (std::size_t k = 0; k < ctrl.size(); ++k) {
          for (std::size_t m = 0; m < 4; ++m) CHECK(c.control_points[3 * k + m] == vec(ctrl[k][m]));
        }
      }
    }
    CHECK(deleted == deletions.size());
  }
}

TEST_CASE("CASSIE import: canvas scale and mirroring come from raw_data", "[recording][cassie]") {
  for (const char* name : sessions) {
    INFO(name);
    const json raw = load("raw_data/" + std::string(name) + ".json");
    const Recording r = import_cassie_session(cassie_dir(), name);
    const json& states = raw["systemStates"];
    CHECK(r.header.workspace.mirror_enabled == states[0]["mirroring"].get<bool>());
    std::size_t toggles = 0;
    for (std::size_t i = 1; i < states.size(); ++i) {
      toggles += states[i]["mirroring"] != states[i - 1]["mirroring"];
    }
    bool mirror = r.header.workspace.mirror_enabled;
    std::size_t workspace_events = 0;
    for (const Event& e : r.events) {
      if (const auto* w = std::get_if<WorkspaceEvent>(&e.payload)) {
        ++workspace_events;
        CHECK(w->workspace.mirror_enabled != mirror);
        mirror = w->workspace.mirror_enabled;
      }
      if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
        // The canvas scale in force at creation: the last state at or before it.
        double scale = 1.0;
        for (const json& st : states) {
          if (st["time"].get<double>() <= e.time) scale = st["canvasScale"].get<double>();
        }
        CHECK(s->stroke.workspace_scale == scale);
      }
    }
    CHECK(workspace_events == toggles);
    CHECK(r.header.source.at("session") == name);
    CHECK(r.header.source.at("dataset") == "CASSIE (Yu et al., CHI 2021)");
    CHECK(r.header.source.at("license") == "MIT");
  }
  // 01-2-1 zooms in to almost 3x.
  const Recording lamp = import_cassie_session(cassie_dir(), "01-2-1");
  double max_scale = 0.0;
  for (const Event& e : lamp.events) {
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) max_scale = std::max(max_scale, s->stroke.workspace_scale);
  }
  CHECK(max_scale > 2.9);
}

TEST_CASE("CASSIE import infers the grid for hat and chair only", "[recording][cassie]") {
  for (const char* name : {"hat", "chair"}) {
    const Recording r = import_cassie_session(cassie_dir(), name);
    INFO(name << ": " << r.header.source.at("grid"));
    CHECK(r.header.workspace.grid_enabled);
    CHECK(r.header.workspace.grid_spacing == 0.25);
    CHECK(r.header.workspace.grid_origin == Vec3::Constant(0.125));
    CHECK_THAT(r.header.source.at("grid"), Catch::StartsWith("spacing 0.25 m, origin (0.125"));
    // Mirror planes inferred from the mirrored twins: x = 0.125 in both.
    CHECK(r.header.workspace.mirror_normal == Vec3::UnitX());
    CHECK(r.header.workspace.mirror_offset == 0.125);
  }
  for (const char* name : {"01-2-1", "02-1-2"}) {
    const Recording r = import_cassie_session(cassie_dir(), name);
    INFO(name << ": " << r.header.source.at("grid"));
    CHECK_FALSE(r.header.workspace.grid_enabled);
    CHECK_THAT(r.header.source.at("grid"), Catch::StartsWith("none"));
  }
  const Recording lamp = import_cassie_session(cassie_dir(), "01-2-1");
  CHECK(lamp.header.workspace.mirror_normal == Vec3::UnitZ());
  CHECK(lamp.header.workspace.mirror_offset == 0.75);
  CHECK(lamp.header.source.at("system") == "patch");
  const Recording shoe = import_cassie_session(cassie_dir(), "02-1-2");
  CHECK(shoe.header.workspace.mirror_offset == 0.0);
  CHECK(shoe.header.source.at("system") == "armature");
}

TEST_CASE("infer_grid finds a planted lattice and ignores free-hand points", "[recording][cassie]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int i = 0; i < 200; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  GridInference none = infer_grid(pts);
  CHECK_FALSE(none.found);
  CHECK(none.total == 200);
  // Two snapped points are not enough evidence.
  pts.emplace_back(0.1, 0.3, -0.5);
  pts.emplace_back(0.7, 0.1, 0.1);
  CHECK_FALSE(infer_grid(pts).found);
  for (int i = 0; i < 5; ++i) pts.emplace_back(0.1 + 0.2 * i, -0.1, 0.3 + 1e-7);
  const GridInference g = infer_grid(pts);
  CHECK(g.found);
  CHECK(g.spacing == 0.2);
  CHECK(g.origin == Vec3::Constant(0.1));
  CHECK(g.matched == 7);
}

TEST_CASE("infer_mirror_plane recovers an axis plane and rejects oblique twins", "[recording][cassie]") {
  std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> twins(1);
  for (int i = 0; i < 5; ++i) {
    const Vec3 p(0.1 * i, 0.3, 0.9 + 0.05 * i);
    twins[0].first.push_back(p);
    twins[0].second.push_back(Vec3(p.x(), p.y(), 1.5 - p.z()));
  }
  const MirrorInference m = infer_mirror_plane(twins);
  CHECK(m.found);
  CHECK(m.normal == Vec3::UnitZ());
  CHECK(m.offset == Approx(0.75).margin(1e-15));
  twins[0].second[2].x() += 0.01;
  CHECK_FALSE(infer_mirror_plane(twins).found);
  CHECK_FALSE(infer_mirror_plane({}).found);
}

TEST_CASE("CASSIE import: flower's stroke deleted before its creation imports with a warning",
          "[recording][cassie]") {
  std::vector<std::string> warnings;
  const Recording r = import_cassie_session(cassie_dir(), "flower", &warnings);
  // Strokes 10 and 11 (mirrored twins, created at 81.19431) have
  // deletion_time 73.35294; raw_data logs "delete stroke 10" at 95.20064.
  REQUIRE(warnings.size() == 2);
  CHECK_THAT(warnings[0], Catch::Contains("flower.json") && Catch::Contains("stroke id 10") &&
                              Catch::Contains("before creation_time") && Catch::Contains("95.20064"));
  CHECK_THAT(warnings[1], Catch::Contains("stroke id 11"));
  CHECK_THAT(r.header.source.at("import_warnings"), Catch::Contains("stroke id 10"));
  std::map<StrokeId, double> created, deleted;
  for (const Event& e : r.events) {
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) created[s->stroke.id] = e.time;
    if (const auto* d = std::get_if<DeleteStrokeEvent>(&e.payload)) deleted[d->stroke] = e.time;
  }
  CHECK(created.size() == 131);
  for (StrokeId id : {StrokeId{10}, StrokeId{11}}) {
    CHECK(created.at(id) == 81.19431);
    CHECK(deleted.at(id) == 95.20064);
  }
  // Sessions without quirks import silently.
  import_cassie_session(cassie_dir(), "hat", &warnings);
  CHECK(warnings.empty());
  CHECK(import_cassie_session(cassie_dir(), "hat").header.source.count("import_warnings") == 0);
}

TEST_CASE("CASSIE import errors name the file and the field", "[recording][cassie]") {
  const std::filesystem::path dir = test::binary_path("tests/scratch/cassie_errors");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "sketch_history");
  std::filesystem::create_directories(dir / "raw_data");
  const std::filesystem::path raw = cassie_dir() / "raw_data" / "hat.json";
  std::filesystem::copy_file(raw, dir / "raw_data" / "s.json");
  auto write = [&](const std::string& text) {
    std::ofstream(dir / "sketch_history" / "s.json", std::ios::trunc) << text;
  };
  const std::string hist = (dir / "sketch_history" / "s.json").string();

  CHECK_THROWS_WITH(import_cassie_session(dir, "missing"),
                    Catch::Contains("missing.json") && Catch::Contains("cannot open"));
  write("[{\"id\": 0,");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"),
                    Catch::Contains(hist) && Catch::Contains("malformed JSON"));
  write(R"([{"id":0,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"),
                    Catch::Contains(hist) && Catch::Contains("missing field 'creation_time'"));
  write(R"([{"id":0,"input_samples":[[0,0,0],[1,null,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains("input_samples[1][1]"));
  write(R"([{"id":0,"input_samples":[[0,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains("at least 2"));
  write(R"([{"id":0,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"spline","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains("curve_type"));
  write(R"([{"id":0,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  const Recording ok = import_cassie_session(dir, "s");
  CHECK(ok.events.size() == 2 + 3);  // stroke, reference, 3 mirror toggles of hat's raw data

  // Absurd values (issue #17, D9): what the recording format cannot hold is
  // refused here, naming the file and the stroke, not later by the writer.
  write(R"([{"id":7,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,2e20]]],"creation_time":20,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"),
                    Catch::Contains(hist) && Catch::Contains("id 7") && Catch::Contains("ctrl_pts[0][1]") &&
                        Catch::Contains("absurd"));
  write(R"([{"id":7,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":-5,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains(hist) && Catch::Contains("id 7") &&
                                                         Catch::Contains("creation_time") &&
                                                         Catch::Contains("outside [0, 1e9] s"));
  write(R"([{"id":7,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":2e9,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains("id 7") && Catch::Contains("creation_time"));
  write(R"([{"id":7,"input_samples":[[0,0,0],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":3e9}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"), Catch::Contains("id 7") && Catch::Contains("deletion_time"));
  // A glitch sample (the reproducer's 1.8e20 m) is dropped with a warning.
  write(R"([{"id":7,"input_samples":[[0,0,0],[0.5,0,1.8446744073709552e20],[1,0,0]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  std::vector<std::string> warnings;
  const Recording glitch = import_cassie_session(dir, "s", &warnings);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains(hist) && Catch::Contains("id 7") &&
                              Catch::Contains("input_samples[1]") && Catch::Contains("dropped"));
  for (const Event& e : glitch.events)
    if (const auto* st = std::get_if<StrokeEvent>(&e.payload)) CHECK(st->stroke.samples.size() == 2);
  std::ostringstream os;
  CHECK_NOTHROW(write_recording(os, glitch));  // the writer accepts what the importer made
  // ... unless too few samples are left.
  write(R"([{"id":7,"input_samples":[[0,0,0],[0.5,0,1.8446744073709552e20]],"curve_type":"line","ctrl_pts":[[[0,0,0],[1,0,0]]],"creation_time":20,"deletion_time":null}])");
  CHECK_THROWS_WITH(import_cassie_session(dir, "s"),
                    Catch::Contains(hist) && Catch::Contains("stroke id 7") && Catch::Contains("at least 2"));
}

TEST_CASE("CASSIE's constraint logs are read per stroke from raw_data", "[recording][cassie]") {
  const auto logs = read_cassie_constraint_logs(cassie_dir() / "raw_data" / "chair.json");
  CHECK(logs.size() == 174);
  std::size_t applied = 0, rejected = 0;
  for (const auto& [id, log] : logs) applied += log.applied.size(), rejected += log.rejected.size();
  CHECK(applied == 257);
  CHECK(rejected == 45);
  const CassieConstraintLog& s4 = logs.at(4);
  REQUIRE(s4.applied.size() == 2);
  CHECK(s4.applied[0].isApprox(Vec3(0.125, 1.375, 0.375)));
  REQUIRE(s4.rejected.size() == 1);
  CHECK(s4.rejected[0].isApprox(Vec3(0.125, 1.35890317, 0.354969263)));
  // Per-stroke flags: chair's export has planar and onSurface, not closedLoop.
  std::size_t planar = 0, flagged = 0;
  for (const auto& [id, log] : logs) {
    flagged += log.planar.has_value() && log.on_surface.has_value() && !log.closed_loop && !log.mirrored_twin;
    planar += log.planar.value_or(false);
  }
  CHECK(flagged == 174);
  CHECK(planar == 165);
  // chair's older export logs bare points: no isIntersection flag.
  for (const auto& [id, log] : logs) {
    REQUIRE(log.applied_intersection.size() == log.applied.size());
    for (const std::optional<bool>& f : log.applied_intersection) CHECK_FALSE(f.has_value());
  }
  const auto car = read_cassie_constraint_logs(cassie_dir() / "raw_data" / "vintage_car.json");
  std::size_t closed = 0, car_applied = 0, intersections = 0;
  for (const auto& [id, log] : car) {
    closed += log.closed_loop.value_or(false);
    car_applied += log.applied.size();
    REQUIRE(log.applied_intersection.size() == log.applied.size());
    for (const std::optional<bool>& f : log.applied_intersection) intersections += f.value();
  }
  CHECK(closed == 6);
  CHECK(car_applied == 766);
  CHECK(intersections == 666);

  const std::filesystem::path dir = test::binary_path("tests/scratch/cassie_logs");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.json", std::ios::trunc)
      << R"({"allSketchedStrokes":[{"id":3,"appliedPositionConstraints":[{"x":1,"y":"a","z":0}]}]})";
  CHECK_THROWS_WITH(read_cassie_constraint_logs(dir / "bad.json"),
                    Catch::Contains("bad.json") && Catch::Contains("appliedPositionConstraints[0]") &&
                        Catch::Contains("'y'"));
  std::ofstream(dir / "flag.json", std::ios::trunc) << R"({"allSketchedStrokes":[{"id":3,"planar":"yes"}]})";
  CHECK_THROWS_WITH(read_cassie_constraint_logs(dir / "flag.json"),
                    Catch::Contains("flag.json") && Catch::Contains("allSketchedStrokes[0]") &&
                        Catch::Contains("'planar' must be true or false"));
  std::ofstream(dir / "cross.json", std::ios::trunc)
      << R"({"allSketchedStrokes":[{"id":3,"appliedPositionConstraints":[{"position":{"x":1,"y":0,"z":0},"isIntersection":1}]}]})";
  CHECK_THROWS_WITH(read_cassie_constraint_logs(dir / "cross.json"),
                    Catch::Contains("cross.json") && Catch::Contains("appliedPositionConstraints[0]") &&
                        Catch::Contains("'isIntersection' must be true or false"));
}

TEST_CASE("a mirrored twin gets its drawn twin's log reflected in the mirror plane", "[recording][cassie]") {
  const Recording rec = import_cassie_session(cassie_dir(), "vintage_car");
  REQUIRE(rec.header.workspace.mirror_normal.norm() > 0);
  const auto drawn = read_cassie_constraint_logs(cassie_dir() / "raw_data" / "vintage_car.json");
  auto logs = drawn;
  add_mirrored_twin_logs(rec, logs);
  std::size_t twins = 0;
  for (const auto& [id, log] : logs) {
    if (!log.mirrored_twin) {
      CHECK(drawn.count(id) == 1);
      continue;
    }
    ++twins;
    CHECK(drawn.count(id) == 0);
    // Its drawn twin: the logged stroke whose reflected positions these are.
    const auto twin = std::find_if(drawn.begin(), drawn.end(), [&](const auto& d) {
      if (d.second.applied.size() != log.applied.size() || d.second.applied.empty()) return false;
      for (std::size_t i = 0; i < log.applied.size(); ++i)
        if ((mirror_point(rec.header.workspace, d.second.applied[i]) - log.applied[i]).norm() > 1e-12) return false;
      return true;
    });
    if (!log.applied.empty()) {
      REQUIRE(twin != drawn.end());
      CHECK(twin->second.applied_intersection == log.applied_intersection);
    }
  }
  CHECK(twins > 100);
}

TEST_CASE("CASSIE's patch log is read from raw_data", "[recording][cassie]") {
  const auto patches = read_cassie_patches(cassie_dir() / "raw_data" / "02-2-1.json");
  REQUIRE(patches.size() == 49);
  std::size_t automatic = 0, created = 0;
  for (const CassiePatchLog& p : patches) automatic += p.automatic, created += p.created.has_value();
  CHECK(automatic == 42);
  CHECK(created == 49);
  CHECK(patches[1].id == 1);
  CHECK(patches[1].strokes == std::vector<StrokeId>{0, 1, 2, 3, 4, 5});  // sorted
  CHECK(patches[1].created == Approx(531.73175));
  CHECK(!patches[1].deleted);
  CHECK(read_cassie_patches(cassie_dir() / "raw_data" / "01-0-1.json").empty());  // Freehand: none

  const std::filesystem::path dir = test::binary_path("tests/scratch/cassie_patches");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.json", std::ios::trunc)
      << R"({"allCreatedPatches":[{"id":0,"foundByAlgo":1,"strokesID":[0]}]})";
  CHECK_THROWS_WITH(read_cassie_patches(dir / "bad.json"),
                    Catch::Contains("bad.json") && Catch::Contains("allCreatedPatches[0]") &&
                        Catch::Contains("'foundByAlgo' must be true or false"));
  std::ofstream(dir / "deleted.json", std::ios::trunc)
      << R"({"allCreatedPatches":[{"id":5,"foundByAlgo":false,"strokesID":[2,1,2]}],
            "systemStates":[{"interactionType":3,"elementID":5,"time":2.0},
                            {"interactionType":4,"elementID":5,"time":3.5}]})";
  const auto d = read_cassie_patches(dir / "deleted.json");
  REQUIRE(d.size() == 1);
  CHECK(!d[0].automatic);
  CHECK(d[0].strokes == std::vector<StrokeId>{1, 2});
  CHECK(d[0].created == 2.0);
  CHECK(d[0].deleted == 3.5);
}
