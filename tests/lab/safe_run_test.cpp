// What a run promises before and after its cases: the whole experiment is
// resolved and validated before anything is written, every parameter is
// recorded (defaults included) with the provenance of the run, and the run
// folder's config.yaml points at the recordings relative to the folder.
#include <catch2/catch.hpp>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "build_plugin_host.hpp"
#include "cli_helpers.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/experiment_runner.hpp"
#include "sketchlab/lab/file_hash.hpp"
#include "sketchlab/version.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

fs::path write_experiment(const fs::path& dir, const std::string& stacks, const std::string& outputs = "") {
  std::ofstream(dir / "exp.yaml") << "experiment: safe\nrecordings: [" << test::source_path("data/recordings/hat.jsonl")
                                  << "]\nstacks:\n"
                                  << stacks << "outputs: {dir: " << (dir / "runs").string()
                                  << ", pictures: false" << outputs << "}\n";
  return dir / "exp.yaml";
}

const std::string two_stacks =
    "  - name: free\n"
    "    input: {plugin: replay, params: {max_events: 12}}\n"
    "    corrector: {plugin: freehand, params: {fit_error: 2}}\n"
    "  - name: other\n"
    "    input: {plugin: replay, params: {max_events: 12}}\n"
    "    corrector: {plugin: freehand}\n";

RunOptions quiet() {
  RunOptions o;
  o.jobs = 1;
  o.timings = false;
  return o;
}

}  // namespace

TEST_CASE("resolve_stack writes out every parameter, defaults included", "[lab][provenance]") {
  const fs::path dir = test::fresh_dir("resolve_stack");
  std::ofstream(dir / "s.yaml") << "corrector: {plugin: freehand, params: {fit_error: 2}}\n";
  const PluginHost& host = test::build_plugin_host();
  const StackConfig s = resolve_stack(load_stack(dir / "s.yaml"), host);
  const auto& specs = host.find(PluginKind::corrector, "freehand")->descriptor->params;
  REQUIRE(s.corrector.params.size() == specs.size());
  for (const auto& spec : specs) {
    INFO(spec.name);
    if (spec.name == "fit_error")
      CHECK(std::get<double>(s.corrector.params.at("fit_error")) == 2.0);  // the integer 2 normalised
    else
      CHECK(s.corrector.params.at(spec.name) == spec.default_value);
  }
  REQUIRE(s.input);
  CHECK(s.input->plugin == "replay");
  CHECK_FALSE(s.input->params.count("path"));  // each case sets its recording
  REQUIRE(s.time_budget);
  CHECK(*s.time_budget == default_time_budget_s);
  // Written and read back (2.0 is written "2", read as an integer and
  // normalised by validation): the same resolved stack.
  write_text_file(dir / "r.yaml", stack_to_yaml(s));
  const StackConfig again = resolve_stack(load_stack(dir / "r.yaml"), host);
  CHECK(again.corrector.params == s.corrector.params);
  CHECK(again.input->params == s.input->params);
}

TEST_CASE("a typo in a plugin or parameter name fails before the run folder exists", "[lab][experiment]") {
  const fs::path dir = test::fresh_dir("safe_run_typo");
  const PluginHost& host = test::build_plugin_host();
  // The second stack is wrong: the first would have run (and written) first.
  const fs::path plugin_typo = write_experiment(dir, two_stacks + "  - name: bad\n    corrector: {plugin: freehnd}\n");
  CHECK_THROWS_WITH(run_experiment(load_experiment(plugin_typo), host, quiet()),
                    Catch::Contains("exp.yaml:11") && Catch::Contains("unknown corrector 'freehnd'") &&
                        Catch::Contains("available: ") && Catch::Contains("freehand"));
  CHECK_FALSE(fs::exists(dir / "runs"));

  const fs::path param_typo =
      write_experiment(dir, two_stacks + "  - name: bad\n    corrector: {plugin: freehand, params: {fit_eror: 1}}\n");
  CHECK_THROWS_WITH(run_experiment(load_experiment(param_typo), host, quiet()),
                    Catch::Contains("exp.yaml:11") && Catch::Contains("fit_eror"));
  CHECK_FALSE(fs::exists(dir / "runs"));

  const fs::path bad_value = write_experiment(dir, two_stacks + "sweep:\n  stacks.1.corrector.params.delta: [0.02, 9]\n");
  CHECK_THROWS_WITH(run_experiment(load_experiment(bad_value), host, quiet()),
                    Catch::Contains("exp.yaml:11") && Catch::Contains("delta") && Catch::Contains("[0.001, 0.5]"));
  CHECK_FALSE(fs::exists(dir / "runs"));
}

TEST_CASE("a run records its provenance and a config.yaml relative to its folder", "[lab][provenance]") {
  const fs::path dir = test::fresh_dir("safe_run_provenance");
  const fs::path exp = write_experiment(dir, two_stacks, ", ply: false, obj: false, mlp: false");
  const RunSummary s = run_experiment(load_experiment(exp), test::build_plugin_host(), quiet());
  REQUIRE(s.failed() == 0);
  const fs::path recording = test::source_path("data/recordings/hat.jsonl");
  const std::string sha = hash_file(recording).sha256;

  const YAML::Node p = YAML::LoadFile((s.run_dir / "provenance.yaml").string());
  CHECK(p["sketchlab"]["version"].as<std::string>() == SKETCHLAB_KERNEL_VERSION);
  const std::string commit = p["sketchlab"]["git_commit"].as<std::string>();
  CHECK((commit == "unknown" || commit.size() >= 40));
  CHECK(p["sketchlab"]["fingerprint"].as<std::string>() == build_fingerprint());
  CHECK_FALSE(p["sketchlab"]["build_type"].as<std::string>().empty());
  CHECK(p["recordings"][0]["sha256"].as<std::string>() == sha);
  CHECK(fs::weakly_canonical(s.run_dir / p["recordings"][0]["path"].as<std::string>()) ==
        fs::weakly_canonical(recording));
  CHECK(p["experiment"]["sha256"].as<std::string>() == hash_file(exp).sha256);
  std::set<std::string> plugins;
  for (const auto& e : p["plugins"]) {
    plugins.insert(e["kind"].as<std::string>() + " " + e["name"].as<std::string>());
    CHECK_FALSE(e["version"].as<std::string>().empty());
  }
  CHECK(plugins == std::set<std::string>{"corrector freehand", "input replay"});
  CHECK_FALSE(p["started"]);  // --no-timings: reruns are byte-identical

  // case.yaml: provenance in comments, every parameter, loadable as a stack.
  const std::string case_yaml = read_text_file(s.run_dir / "hat/other/case.yaml");
  CHECK_THAT(case_yaml, Catch::Contains("sha256 " + sha) && Catch::Contains("# corrector: freehand ") &&
                            Catch::Contains("# sketchlab " SKETCHLAB_KERNEL_VERSION ", commit "));
  const StackConfig c = load_stack(s.run_dir / "hat/other/case.yaml");
  CHECK(c.corrector.params.size() ==
        test::build_plugin_host().find(PluginKind::corrector, "freehand")->descriptor->params.size());
  CHECK(std::get<std::int64_t>(c.input->params.at("max_events")) == 12);

  // config.yaml names the recording relative to the run folder, and runs
  // again from anywhere to the same results.
  const YAML::Node config = YAML::LoadFile((s.run_dir / "config.yaml").string());
  const std::string rel = config["recordings"][0].as<std::string>();
  CHECK(fs::path(rel).is_relative());
  const fs::path moved = dir / "elsewhere";
  fs::create_directories(moved);
  ExperimentConfig again = load_experiment(s.run_dir / "config.yaml");
  REQUIRE(again.recordings.size() == 1);
  CHECK(fs::weakly_canonical(again.recordings[0]) == fs::weakly_canonical(recording));
  again.outputs.dir = moved;
  const RunSummary rerun = run_experiment(again, test::build_plugin_host(), quiet());
  REQUIRE(rerun.failed() == 0);
  CHECK(read_text_file(rerun.run_dir / "hat/free/sketch.json") == read_text_file(s.run_dir / "hat/free/sketch.json"));
}

TEST_CASE("pictures that cannot be drawn are a note of the run, in the report", "[lab][experiment]") {
  const fs::path dir = test::fresh_dir("safe_run_pictures");
  std::ofstream(dir / "exp.yaml") << "experiment: pics\nrecordings: [" << test::source_path("data/recordings/hat.jsonl")
                                  << "]\nstacks:\n" << two_stacks << "outputs: {dir: " << (dir / "runs").string()
                                  << ", ply: false, obj: false}\n";
  RunOptions o = quiet();
  bool called = false;
  o.renderer = [&](const fs::path&, const std::vector<std::pair<std::string, const Sketch*>>&) { called = true; };
  o.pictures_unavailable = "no X display: test";
  const RunSummary s = run_experiment(load_experiment(dir / "exp.yaml"), test::build_plugin_host(), o);
  CHECK_FALSE(called);
  REQUIRE(s.provenance.notes.size() == 1);
  CHECK(s.provenance.notes[0] == "no pictures: no X display: test");
  CHECK_THAT(read_text_file(s.run_dir / "report.html"), Catch::Contains("no pictures: no X display: test"));
  CHECK_THAT(read_text_file(s.run_dir / "provenance.yaml"), Catch::Contains("no pictures: no X display: test"));
}
