#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "sketchlab/config/config.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

fs::path write_experiment(const std::string& name, const std::string& sweep) {
  const fs::path dir = fs::temp_directory_path() / ("sketchlab_test_sweep_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "r.jsonl") << "{}\n";
  const fs::path file = dir / "e.yaml";
  std::ofstream(file) << "experiment: s\n"                                        // 1
                      << "recordings: [r.jsonl]\n"                                // 2
                      << "stacks:\n"                                              // 3
                      << "  - {name: a, corrector: {plugin: freehand}}\n"         // 4
                      << "  - {name: b, corrector: {plugin: cassie}}\n"           // 5
                      << sweep;                                                   // 6...
  return file;
}

}  // namespace

TEST_CASE("sweeps expand to the cartesian product per stack, last axis fastest", "[config][sweep]") {
  const auto config = load_experiment(write_experiment(
      "product", "sweep:\n  stacks.0.corrector.params.delta: [0.01, 0.02]\n"
                 "  stacks.*.corrector.params.lambda: {from: 0.4, to: 0.8, step: 0.2}\n"));
  REQUIRE(config.sweep.size() == 2);
  CHECK(config.sweep[1].values == std::vector<std::string>{"0.4", "0.6000000000000001", "0.8"});
  const auto cases = expand_sweep(config);
  REQUIRE(cases.size() == 2 * 3 + 3);
  CHECK(cases[0].stack.name == "a@delta=0.01,lambda=0.4");
  CHECK(cases[1].stack.name == "a@delta=0.01,lambda=0.6000000000000001");
  CHECK(cases[3].stack.name == "a@delta=0.02,lambda=0.4");
  CHECK(std::get<double>(cases[3].stack.corrector.params.at("delta")) == 0.02);
  CHECK(std::get<double>(cases[3].stack.corrector.params.at("lambda")) == 0.4);
  CHECK(cases[6].stack.name == "b@lambda=0.4");
  CHECK(cases[6].stack.corrector.params.count("delta") == 0);
}

TEST_CASE("no sweep gives each stack once, unchanged", "[config][sweep]") {
  const auto config = load_experiment(write_experiment("none", ""));
  const auto cases = expand_sweep(config);
  REQUIRE(cases.size() == 2);
  CHECK(cases[0].stack.name == "a");
  CHECK(cases[0].point.empty());
}

TEST_CASE("bad sweeps name the file and line", "[config][sweep]") {
  const auto error_of = [](const fs::path& file) {
    try {
      load_experiment(file);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error_of(write_experiment("index", "sweep:\n  stacks.5.corrector.params.delta: [1]\n")),
             Catch::Contains("e.yaml:7") && Catch::Contains("index below 2"));
  CHECK_THAT(error_of(write_experiment("range", "sweep:\n  stacks.0.corrector.params.delta: {from: 1, to: 0, step: 1}\n")),
             Catch::Contains("e.yaml:7") && Catch::Contains("step > 0 and to >= from"));
  CHECK_THAT(error_of(write_experiment("empty", "sweep:\n  stacks.0.corrector.params.delta: []\n")),
             Catch::Contains("e.yaml:7"));
}

TEST_CASE("stack_to_yaml reads back to the same stack", "[config][sweep]") {
  const auto config = load_experiment(
      write_experiment("yaml", "sweep:\n  stacks.0.corrector.params.label: [\"true\", x]\n"));
  const auto cases = expand_sweep(config);
  const fs::path file = fs::temp_directory_path() / "sketchlab_test_sweep_yaml" / "case.yaml";
  std::ofstream(file) << stack_to_yaml(cases[0].stack);
  const StackConfig back = load_stack(file);
  CHECK(back.name == cases[0].stack.name);
  CHECK(back.corrector.plugin == "freehand");
  CHECK(std::get<std::string>(back.corrector.params.at("label")) == "true");
}

TEST_CASE("sweep errors name the sweep entry's file:line, not the command line", "[config][sweep][reliability]") {
  // Issue 17, D8 (reproducers K1, K2).
  const auto error_of = [](const fs::path& file) {
    try {
      expand_sweep(load_experiment(file));
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const fs::path k1 = write_experiment("k1", "sweep:\n  stacks.0..params.delta: [0.01, 0.02]\n");
  CHECK(error_of(k1) == k1.string() +
                            ":7: sweep key 'stacks.0..params.delta' has an empty key segment in "
                            "'stacks.0..params.delta' (expected stacks.<index or *>.<path>, e.g. "
                            "stacks.0.corrector.params.delta)");

  // An out-of-range value is found when the plugin validates it: its location
  // is the sweep entry.
  const fs::path k2 = write_experiment("k2", "sweep:\n  stacks.0.corrector.params.delta: [0.01, 7]\n");
  const auto cases = expand_sweep(load_experiment(k2));
  REQUIRE(cases.size() == 3);
  CHECK(cases[1].stack.corrector.param_locations.at("delta").to_string() == k2.string() + ":7");
  try {
    rethrow_param_error(ParamError("delta", "7 is out of range"), cases[1].stack.corrector);
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()) == k2.string() + ":7: plugin 'freehand': 7 is out of range");
  }
  // A value that breaks the structure names the entry too.
  const fs::path bad = write_experiment("structure", "sweep:\n  stacks.0.corrector.plugin: ['']\n");
  CHECK_THAT(error_of(bad), Catch::StartsWith(bad.string() + ":7: ") && Catch::Contains("non-empty string"));
  // Command-line overrides still say so.
  const auto overridden =
      load_experiment(k2, {parse_override("stacks.1.corrector.params.delta=0.05")});
  CHECK(overridden.stacks[1].corrector.param_locations.at("delta").to_string() == "command line");
}

TEST_CASE("a sweep too large to run is refused up front, naming its entries", "[config][sweep][reliability]") {
  const fs::path file = write_experiment(
      "huge", "sweep:\n  stacks.0.corrector.params.p0: {from: 0, to: 9999, step: 1}\n"
              "  stacks.0.corrector.params.p1: {from: 0, to: 9999, step: 1}\n");
  try {
    expand_sweep(load_experiment(file));
    FAIL("no error");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("sweep entries at " + file.string() + ":7, " + file.string() +
                                           ":8: the sweep has 1e+08 stack variants") &&
                             Catch::Contains("at most 1e+06"));
  }
}

TEST_CASE("stacks take a time budget per event", "[config]") {
  const fs::path dir = fs::temp_directory_path() / "sketchlab_test_sweep_budget";
  fs::create_directories(dir);
  const fs::path file = dir / "s.yaml";
  std::ofstream(file) << "corrector: freehand\ntime_budget: 2.5\n";
  CHECK(load_stack(file).time_budget == 2.5);
  CHECK(load_stack(file, {parse_override("time_budget=0.5")}).time_budget == 0.5);
  std::ofstream(dir / "r.yaml") << stack_to_yaml(load_stack(file));
  CHECK(load_stack(dir / "r.yaml").time_budget == 2.5);
  for (const char* bad : {"0", "-1", "1e9", "soon", "[1]"}) {
    INFO(bad);
    CHECK_THROWS_WITH(load_stack(file, {parse_override(std::string("time_budget=") + bad)}),
                      Catch::Contains("'time_budget' must be a number of seconds in (0, 86400]"));
  }
}
