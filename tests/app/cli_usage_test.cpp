// What the CLI prints for people: the plugin table, its errors, usage lines,
// and teacher-forced refusing a recording it cannot compare, and rebuilding
// CASSIE's patches from its logs.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>

#include "cli_helpers.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

std::string cli() { return SKETCHLAB_CLI; }

}  // namespace

TEST_CASE("plugins aligns each plugin's columns and shows angles in degrees with units", "[app][cli]") {
  const auto r = test::run_captured(cli() + " plugins cassie");
  REQUIRE(r.status == 0);
  std::istringstream in(r.output);
  std::size_t eq_column = std::string::npos, rows = 0;
  bool angle = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  ", 0) != 0 || line.rfind("      ", 0) == 0 || line.rfind("  file:", 0) == 0) continue;
    const std::size_t eq = line.find(" = ");
    REQUIRE(eq != std::string::npos);
    if (eq_column == std::string::npos) eq_column = eq;
    INFO(line);
    CHECK(eq == eq_column);
    ++rows;
    if (line.find(" rad = ") != std::string::npos && line.find("°") != std::string::npos) angle = true;
  }
  CHECK(rows > 10);
  CHECK(angle);
  // No 16-digit radians (1.5707963267948966) anywhere.
  CHECK_FALSE(std::regex_search(r.output, std::regex(R"(\d\.\d{9,})")));
  CHECK_THAT(r.output, Catch::Contains("angle") && Catch::Contains("rad = "));
}

TEST_CASE("plugins NAME for a name that does not exist lists those that do", "[app][cli]") {
  const auto r = test::run_captured(cli() + " plugins nosuch");
  CHECK(r.status != 0);
  CHECK_THAT(r.output, Catch::Contains("no plugin named 'nosuch'") && Catch::Contains("freehand") &&
                           Catch::Contains("cassie") && Catch::Contains("replay"));
}

TEST_CASE("teacher-forced without the requested track fails naming the tracks the recording has", "[app][cli]") {
  const fs::path dir = test::fresh_dir("teacher_forced_track");
  const auto wrong = test::run_captured(cli() + " teacher-forced " + test::source_path("data/recordings/hat.jsonl") +
                                        " --corrector freehand --track nosuch");
  CHECK(wrong.status != 0);
  CHECK_THAT(wrong.output, Catch::Contains("hat.jsonl") && Catch::Contains("no reference curves on track 'nosuch'") &&
                               Catch::Contains("the recording has: cassie"));
  CHECK_THAT(wrong.output, !Catch::Contains("compared"));

  const fs::path synth = dir / "cube.jsonl";
  REQUIRE(test::run_cli("synth cube --seed 1 -o " + synth.string(), dir / "synth.txt") == 0);
  const auto synthetic = test::run_captured(cli() + " teacher-forced " + synth.string() + " --corrector freehand");
  CHECK(synthetic.status != 0);
  CHECK_THAT(synthetic.output, Catch::Contains("track 'cassie'") && Catch::Contains("ground_truth"));
  // With the track it has, it compares.
  const auto right =
      test::run_captured(cli() + " teacher-forced " + synth.string() + " --corrector freehand --track ground_truth");
  CHECK(right.status == 0);
  CHECK_THAT(right.output, Catch::Contains("compared "));
}

TEST_CASE("teacher-forced --cassie-logs rebuilds CASSIE's patches unless --no-patches", "[app][cli]") {
  const std::string base = cli() + " teacher-forced " + test::source_path("data/recordings/flower.jsonl") +
                           " --corrector cassie --param mirror=plane --cassie-logs " +
                           test::source_path("data/cassie/raw_data");
  const auto with = test::run_captured(base);
  REQUIRE(with.status == 0);
  CHECK_THAT(with.output, Catch::Contains("patches 93\n") && Catch::Contains("patches_left_out 0\n"));
  const auto without = test::run_captured(base + " --no-patches");
  REQUIRE(without.status == 0);
  CHECK_THAT(without.output, !Catch::Contains("patches "));
  const auto missing = test::run_captured(base + "/nowhere");
  CHECK(missing.status != 0);
  CHECK_THAT(missing.output, Catch::Contains("nowhere/flower.json"));
  // A sibling export given by mistake used to print "patches 0" silently.
  const auto graphs = test::run_captured(cli() + " teacher-forced " + test::source_path("data/recordings/flower.jsonl") +
                                         " --corrector cassie --param mirror=plane --cassie-logs " +
                                         test::source_path("data/cassie/sketch_graph"));
  CHECK(graphs.status == 0);
  CHECK_THAT(graphs.output, Catch::Contains("sketch_graph/flower.json: no stroke log (allSketchedStrokes), so the "
                                            "session is compared without CASSIE's patches; does --cassie-logs name "
                                            "CASSIE's raw_data folder?"));
}

TEST_CASE("view takes overrides as positional key.path=value, as run and vr do", "[app][cli]") {
  const auto help = test::run_captured(cli() + " view --help");
  if (help.status != 0) {
    // A build without the desktop viewer has no `view`.
    CHECK_THAT(help.output, Catch::Contains("view"));
    return;
  }
  CHECK_THAT(help.output, !Catch::Contains("(0x)") && !Catch::Contains("--set"));
  CHECK_THAT(help.output, Catch::Contains("key.path=value"));
  const auto missing = test::run_captured("env -u DISPLAY " + cli() + " view /nonexistent/exp.yaml");
  CHECK(missing.status != 0);
  CHECK_THAT(missing.output, Catch::Contains("/nonexistent/exp.yaml") && Catch::Contains("no such file"));
}

TEST_CASE("a plugin in SKETCHLAB_PLUGIN_PATH overrides the bundled one of the same name", "[app][cli]") {
  const fs::path dir = test::fresh_dir("plugin_path_first");
  const fs::path mine = dir / "sketchlab_corrector_freehand.so";
  fs::copy_file(fs::path(SKETCHLAB_BUILD_PLUGIN_DIR) / "sketchlab_corrector_freehand.so", mine);
  const auto r = test::run_captured("SKETCHLAB_PLUGIN_PATH=" + dir.string() + " " + cli() + " plugins freehand");
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("file: " + fs::canonical(mine).string()));
  // The bundled copy is the one skipped, and said to be.
  CHECK_THAT(r.output, Catch::Contains("already loaded from " + fs::canonical(mine).string()));
}
