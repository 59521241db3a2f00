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
