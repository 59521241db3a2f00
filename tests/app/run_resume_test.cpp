// `sketchlab run --resume RUN_DIR`: a run ended half-way (here by a case
// that crashes the process) is finished by running only the cases without a
// result, and the folder is then byte for byte the uninterrupted run's.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_helpers.hpp"
#include "run_sweeps.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

TEST_CASE("run --resume runs only the cases without a result and completes the run byte for byte", "[app][resume]") {
  const fs::path base = test::fresh_dir("run_resume");
  const fs::path experiment = test::write_crash_sweep(base);
  const std::string env = "SKETCHLAB_PLUGIN_PATH=" + test::crash_plugin_dir() + " ";
  const std::string cli = std::string(SKETCHLAB_CLI) + " run --no-timings ";
  fs::create_directories(base / "reference");
  fs::create_directories(base / "resumed");
  const auto whole = test::run_captured("cd " + (base / "reference").string() + " && " + env + cli + "-j 2 ../" +
                                        experiment.filename().string());
  INFO(whole.output);
  REQUIRE(whole.status == 0);

  // -j 1 runs the cases in order (chair first): the two before the
  // crashing one finish.
  const auto ended = test::run_captured("cd " + (base / "resumed").string() + " && " + env +
                                        "SKETCHLAB_FIXTURE_CRASH=1 " + cli + "-j 1 ../" +
                                        experiment.filename().string());
  INFO(ended.output);
  REQUIRE(ended.status != 0);
  const fs::path run = base / "resumed/runs/sweep";
  CHECK(test::finished_cases(run) == 2);
  CHECK_FALSE(fs::exists(run / "metrics.csv"));

  const auto resumed = test::run_captured("cd " + (base / "resumed").string() + " && " + env + cli +
                                          "--resume runs/sweep ../" + experiment.filename().string());
  INFO(resumed.output);
  REQUIRE(resumed.status == 0);
  // One progress line per case run (stderr is not a terminal here).
  const std::regex done_line("done: ");
  CHECK(std::distance(std::sregex_iterator(resumed.output.begin(), resumed.output.end(), done_line),
                      std::sregex_iterator()) == 6);
  CHECK(resumed.output.find("done: chair x free@fit_error=0.25") == std::string::npos);
  CHECK(test::finished_cases(run) == 8);
  CHECK(test::differing_files(base / "reference/runs/sweep", run).empty());
}

TEST_CASE("run --resume refuses a run folder made from another experiment", "[app][resume]") {
  const fs::path base = test::fresh_dir("run_resume_other");
  const fs::path experiment = test::write_crash_sweep(base);
  const std::string env = "cd " + base.string() + " && SKETCHLAB_PLUGIN_PATH=" + test::crash_plugin_dir() + " " +
                          SKETCHLAB_CLI + " run --no-timings ";
  REQUIRE(test::run_captured(env + experiment.string()).status == 0);
  const auto other = test::run_captured(env + "--resume runs/sweep " + experiment.string() +
                                        " stacks.2.corrector.params.fit_error=2");
  CHECK(other.status != 0);
  CHECK(other.output.find("made from another experiment") != std::string::npos);
  // Nothing was rerun: every case keeps its record, and nothing else came.
  const auto again = test::run_captured(env + "--resume runs/sweep");
  INFO(again.output);
  CHECK(again.status == 0);
  CHECK(again.output.find("done: ") == std::string::npos);
}
