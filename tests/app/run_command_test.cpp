// End to end: the `sketchlab` binary with the real plugins on bundled data.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "sketchlab/io/text_file.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "cli_helpers.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;
using test::fresh_dir;
using test::run_cli;

namespace {

fs::path write_experiment(const fs::path& dir, const std::string& recording) {
  const fs::path file = dir / "experiment.yaml";
  std::ofstream(file) << "experiment: e2e\n"
                      << "recordings: [" << recording << "]\n"
                      << "stacks:\n  - name: freehand\n    corrector: {plugin: freehand}\n"
                      << "outputs: {dir: " << (dir / "runs").string() << ", timestamp: false, pictures: false}\n";
  return file;
}

}  // namespace

TEST_CASE("replaying hat through freehand gives one curve per stroke alive at the end",
          "[app][slow]") {
  const fs::path dir = fresh_dir("run_hat");
  const std::string recording = test::source_path("data/recordings/hat.jsonl");
  REQUIRE(run_cli("run " + write_experiment(dir, recording).string(), dir / "log.txt") == 0);

  // Alive strokes: every stroke not deleted by a delete_stroke event.
  std::set<StrokeId> alive;
  for (const auto& e : read_recording(recording).events) {
    if (auto* s = std::get_if<StrokeEvent>(&e.payload)) alive.insert(s->stroke.id);
    if (auto* d = std::get_if<DeleteStrokeEvent>(&e.payload)) alive.erase(d->stroke);
  }
  REQUIRE(alive.size() > 50);

  const fs::path out = dir / "runs/e2e/hat/freehand";
  const auto sketch = nlohmann::json::parse(read_text_file(out / "sketch.json"));
  std::multiset<StrokeId> sources;
  for (const auto& c : sketch["curves"]) sources.insert(c["source_stroke"].get<StrokeId>());
  CHECK(sources.size() == alive.size());
  CHECK(std::set<StrokeId>(sources.begin(), sources.end()) == alive);
  CHECK(fs::file_size(out / "curves.ply") > 0);
  CHECK(fs::file_size(out / "sketch.obj") > 0);
  CHECK(fs::file_size(out / "strokes.csv") > 0);
}

TEST_CASE("replaying twice gives byte-identical output", "[app][slow]") {
  const fs::path dir = fresh_dir("run_twice");
  const fs::path exp = write_experiment(dir, test::source_path("data/recordings/hat.jsonl"));
  REQUIRE(run_cli("run --no-timings " + exp.string() + " outputs.dir=" + (dir / "a").string(),
                  dir / "a.txt") == 0);
  REQUIRE(run_cli("run --no-timings " + exp.string() + " outputs.dir=" + (dir / "b").string(),
                  dir / "b.txt") == 0);
  for (const char* f : {"sketch.json", "strokes.csv", "curves.ply", "sketch.obj"}) {
    INFO(f);
    CHECK(read_text_file(dir / "a/e2e/hat/freehand" / f) ==
          read_text_file(dir / "b/e2e/hat/freehand" / f));
  }
}

TEST_CASE("convert exports a sketch that reads back to the same network", "[app]") {
  const fs::path dir = fresh_dir("convert");
  const fs::path exp = write_experiment(dir, test::source_path("data/recordings/chair.jsonl"));
  REQUIRE(run_cli("run " + exp.string(), dir / "run.txt") == 0);
  const fs::path sketch = dir / "runs/e2e/chair/freehand/sketch.json";
  REQUIRE(run_cli("convert export " + sketch.string() + " -o " + (dir / "c.obj").string(),
                  dir / "obj.txt") == 0);
  REQUIRE(run_cli("convert export " + sketch.string() + " -o " + (dir / "c.ply").string(),
                  dir / "ply.txt") == 0);
  const std::string obj = read_text_file(dir / "c.obj");
  const auto curves = nlohmann::json::parse(read_text_file(sketch))["curves"].size();
  std::size_t lines = 0;
  for (std::size_t p = obj.find("\nl "); p != std::string::npos; p = obj.find("\nl ", p + 1)) ++lines;
  CHECK(lines == curves);
  CHECK(read_text_file(dir / "c.ply").rfind("ply\nformat ascii 1.0\n", 0) == 0);
  CHECK(run_cli("convert export " + sketch.string() + " -o " + (dir / "c.stl").string(),
                dir / "stl.txt") != 0);
  CHECK_THAT(read_text_file(dir / "stl.txt"), Catch::Contains(".ply or .obj"));
}

TEST_CASE("convert cassie reproduces the bundled recording byte for byte", "[app]") {
  const fs::path dir = fresh_dir("convert_cassie");
  const fs::path out = dir / "hat.jsonl";
  REQUIRE(run_cli("convert cassie " + test::source_path("data/cassie/sketch_history/hat.json") +
                      " -o " + out.string(),
                  dir / "log.txt") == 0);
  CHECK(read_text_file(out) == read_text_file(test::source_path("data/recordings/hat.jsonl")));
  CHECK(run_cli("convert cassie " + test::source_path("data/cassie/sketch_history/hat.json") +
                    " -o " + out.string(),
                dir / "again.txt") != 0);
  CHECK_THAT(read_text_file(dir / "again.txt"), Catch::Contains("--overwrite"));
}

TEST_CASE("run reports config errors with file and line", "[app]") {
  const fs::path dir = fresh_dir("bad_config");
  const fs::path file = dir / "bad.yaml";
  std::ofstream(file) << "experiment: bad\nrecordings: [" << test::source_path("data/recordings/hat.jsonl")
                      << "]\nstacks:\n  - corrector:\n      plugin: freehand\n      params: {delta: 7.0}\n";
  CHECK(run_cli("run " + file.string(), dir / "log.txt") != 0);
  const std::string log = read_text_file(dir / "log.txt");
  CHECK_THAT(log, Catch::Contains("bad.yaml:6"));
  CHECK_THAT(log, Catch::Contains("delta"));
  CHECK_THAT(log, Catch::Contains("[0.001, 0.5]"));
}

TEST_CASE("plugins lists replay and freehand with their parameters", "[app]") {
  const fs::path dir = fresh_dir("plugins");
  REQUIRE(run_cli("plugins", dir / "log.txt") == 0);
  const std::string log = read_text_file(dir / "log.txt");
  CHECK_THAT(log, Catch::Contains("input replay"));
  CHECK_THAT(log, Catch::Contains("corrector freehand"));
  CHECK_THAT(log, Catch::Contains("fit_error"));
  CHECK(run_cli("plugins nosuchplugin", dir / "none.txt") != 0);
}
