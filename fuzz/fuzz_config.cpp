// libFuzzer harness: the experiment and stack loaders (config/config.hpp),
// overrides and sweeps. The input is a YAML file; lines "#!o key=value" at
// its top are also given as overrides. Contract: ConfigError (file:line or
// "command line", and the allowed values) or a config; nothing else escapes,
// no undefined behaviour; a loaded experiment's resolved YAML loads again.
#include <sstream>

#include "fuzz_support.hpp"
#include "sketchlab/config/config.hpp"

using namespace sketchlab;

namespace {

// Sweeps this large are the benchmark's business (bench_reliability): one
// input may not take the fuzzer's whole time slice.
constexpr double max_points_expanded = 2000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A recording for the experiments to name (recordings: [r.jsonl] or globs).
  static const auto recording = fuzz::write_file("r.jsonl", "{}\n");
  (void)recording;
  const auto file = fuzz::write_file("config.yaml", text);

  std::vector<Override> overrides;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line) && line.rfind("#!o ", 0) == 0;) {
    try {
      overrides.push_back(parse_override(line.substr(4)));
    } catch (const ConfigError&) {
    }
  }
  try {
    load_stack(file, overrides);
  } catch (const ConfigError&) {
  }
  ExperimentConfig config;
  try {
    config = load_experiment(file, overrides);
  } catch (const ConfigError&) {
    return 0;
  }
  double points = 0;
  for (std::size_t i = 0; i < config.stacks.size(); ++i) {
    double product = 1;
    for (const auto& a : config.sweep)
      if (a.path[1] == "*" || a.path[1] == std::to_string(i)) product *= static_cast<double>(a.values.size());
    points += product;
  }
  if (points <= max_points_expanded) {
    try {
      for (const SweepCase& c : expand_sweep(config)) (void)stack_to_yaml(c.stack);
    } catch (const ConfigError&) {
    }
  }
  const auto resolved = fuzz::write_file("resolved.yaml", config.resolved_yaml);
  try {
    load_experiment(resolved);
  } catch (const ConfigError& e) {
    fuzz::broken(std::string("the resolved experiment does not load again: ") + e.what());
  }
  return 0;
}
