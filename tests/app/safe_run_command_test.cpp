// `sketchlab run` as a user meets it: outputs on by default, a folder of its
// own for every run (also two started in the same second), nothing written
// when the experiment cannot run, and a word on the terminal when there can
// be no pictures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "cli_helpers.hpp"
#include "sketchlab/io/text_file.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

const std::string stacks =
    "stacks:\n"
    "  - name: free\n"
    "    input: {plugin: replay, params: {max_events: 12}}\n"
    "    corrector: {plugin: freehand}\n";

std::string hat() { return test::source_path("data/recordings/hat.jsonl"); }

}  // namespace

TEST_CASE("run writes every output unless the config turns it off, and says why there are no pictures",
          "[app][experiment]") {
  const fs::path dir = test::fresh_dir("run_defaults");
  std::ofstream(dir / "exp.yaml") << "experiment: defaults\nrecordings: [" << hat() << "]\n"
                                  << stacks << "outputs: {dir: " << (dir / "runs").string() << ", timestamp: false}\n";
  const auto r = test::run_captured("env -u DISPLAY " + std::string(SKETCHLAB_CLI) + " run " + (dir / "exp.yaml").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const fs::path run = dir / "runs/defaults";
  for (const char* f : {"config.yaml", "provenance.yaml", "report.html", "metrics.csv", "metrics.json", "hat/hat.mlp",
                        "hat/free/case.yaml", "hat/free/sketch.json", "hat/free/strokes.csv", "hat/free/curves.ply",
                        "hat/free/raw_strokes.ply", "hat/free/nodes.ply", "hat/free/patches.ply", "hat/free/sketch.obj"}) {
    INFO(f);
    CHECK(fs::is_regular_file(run / f));
  }
  // Without X there are no pictures (Debian's VTK 9.1 renders through X
  // only): the terminal says so before the cases run, and the report too.
  CHECK_THAT(r.output, Catch::Contains("warning: no pictures: no X display"));
  CHECK_FALSE(fs::exists(run / "hat/side_by_side.png"));
  CHECK_THAT(read_text_file(run / "report.html"), Catch::Contains("no pictures: no X display"));

  // A config turns outputs off.
  std::ofstream(dir / "off.yaml") << "experiment: off\nrecordings: [" << hat() << "]\n" << stacks
                                  << "outputs: {dir: " << (dir / "runs").string()
                                  << ", timestamp: false, ply: false, obj: false, mlp: false, report: false, pictures: false}\n";
  const auto off = test::run_captured("env -u DISPLAY " + std::string(SKETCHLAB_CLI) + " run " + (dir / "off.yaml").string());
  REQUIRE(off.status == 0);
  CHECK(fs::is_regular_file(dir / "runs/off/hat/free/sketch.json"));
  CHECK_FALSE(fs::exists(dir / "runs/off/hat/free/curves.ply"));
  CHECK_FALSE(fs::exists(dir / "runs/off/report.html"));
  CHECK_THAT(off.output, !Catch::Contains("no pictures"));
}

TEST_CASE("configs/compare.yaml writes report, metrics and meshes", "[app][experiment]") {
  const fs::path dir = test::fresh_dir("run_compare");
  const std::string overrides = " 'recordings=[" + hat() + "]' 'stacks.0.input={plugin: replay, params: {max_events: 12}}'" +
                                " 'stacks.1.input={plugin: replay, params: {max_events: 12}}' outputs.dir=" +
                                (dir / "runs").string() + " outputs.timestamp=false outputs.pictures=false";
  REQUIRE(test::run_cli("run " + test::source_path("configs/compare.yaml") + overrides, dir / "log.txt") == 0);
  for (const char* f : {"report.html", "metrics.csv", "metrics.json", "hat/hat.mlp", "hat/cassie/curves.ply",
                        "hat/freehand/sketch.obj"}) {
    INFO(f);
    CHECK(fs::is_regular_file(dir / "runs/compare" / f));
  }
}

TEST_CASE("two runs started in the same second get folders of their own", "[app][experiment]") {
  const fs::path dir = test::fresh_dir("run_same_second");
  std::ofstream(dir / "exp.yaml") << "experiment: twin\nrecordings: [" << hat() << "]\n"
                                  << stacks << "outputs: {dir: " << (dir / "runs").string() << ", pictures: false}\n";
  const std::string run = std::string(SKETCHLAB_CLI) + " run --no-timings " + (dir / "exp.yaml").string();
  // Both processes start at once; most of the time within one second, and
  // when the second has ticked in between the folders differ anyway.
  const auto r = test::run_captured("(" + run + " > " + (dir / "a.txt").string() + " 2>&1 & " + run + " > " +
                                    (dir / "b.txt").string() + " 2>&1 & wait)");
  REQUIRE(r.status == 0);
  std::set<fs::path> runs;
  for (const auto& e : fs::directory_iterator(dir / "runs")) runs.insert(e.path());
  REQUIRE(runs.size() == 2);
  for (const auto& p : runs) {
    INFO(p);
    CHECK(fs::is_regular_file(p / "config.yaml"));
    CHECK(fs::is_regular_file(p / "hat/free/sketch.json"));
    // One run's results only: one case in the metrics.
    const std::string csv = read_text_file(p / "metrics.csv");
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 2);  // the header and its case
  }
  CHECK(read_text_file(*runs.begin() / "hat/free/sketch.json") == read_text_file(*runs.rbegin() / "hat/free/sketch.json"));
  CHECK_THAT(read_text_file(dir / "a.txt") + read_text_file(dir / "b.txt"), Catch::Contains("1 of 1 cases done"));

  // A third run with the timestamp off names an existing folder: it gets -2.
  REQUIRE(test::run_cli("run --no-timings " + (dir / "exp.yaml").string() + " outputs.timestamp=false", dir / "c.txt") == 0);
  REQUIRE(test::run_cli("run --no-timings " + (dir / "exp.yaml").string() + " outputs.timestamp=false", dir / "d.txt") == 0);
  CHECK(fs::is_directory(dir / "runs/twin"));
  CHECK(fs::is_directory(dir / "runs/twin-2"));
  CHECK_THAT(read_text_file(dir / "d.txt"), Catch::Contains("runs/twin-2"));
}

TEST_CASE("run with a typo fails with the config's line and writes nothing", "[app][experiment]") {
  const fs::path dir = test::fresh_dir("run_typo");
  std::ofstream(dir / "exp.yaml") << "experiment: typo\nrecordings: [" << hat() << "]\n"
                                  << stacks << "  - name: second\n    corrector: {plugin: cassie, params: {mirorr: plane}}\n"
                                  << "outputs: {dir: " << (dir / "runs").string() << "}\n";
  const auto r = test::run_captured(std::string(SKETCHLAB_CLI) + " run " + (dir / "exp.yaml").string());
  CHECK(r.status != 0);
  CHECK_THAT(r.output, Catch::Contains("exp.yaml:8") && Catch::Contains("mirorr"));
  CHECK_FALSE(fs::exists(dir / "runs"));
}
