#pragma once
// Runs `sketchlab run` on tablet recordings through named correctors and
// reads the cases' metrics back: the figures the tablet experiment reports
// (configs/tablet.yaml), for tests that assert them.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_helpers.hpp"
#include "sketchlab/io/text_file.hpp"
#include "test_paths.hpp"

namespace sketchlab::test {

// metrics.json of every (recording stem, corrector) case; each corrector is a
// stack of the same name with default parameters.
inline std::map<std::pair<std::string, std::string>, nlohmann::json> run_tablet_experiment(
    const std::string& name, const std::vector<std::filesystem::path>& recordings,
    const std::vector<std::string>& correctors) {
  const std::filesystem::path dir = fresh_dir(name);
  const std::filesystem::path exp = dir / "exp.yaml";
  std::ofstream out(exp);
  out << "experiment: " << name << "\nrecordings:\n";
  for (const auto& r : recordings) out << "  - " << r.string() << "\n";
  out << "stacks:\n";
  for (const auto& c : correctors) out << "  - {name: " << c << ", corrector: {plugin: " << c << "}}\n";
  out << "outputs: {dir: " << (dir / "runs").string()
      << ", timestamp: false, report: true, ply: false, obj: false, mlp: false, pictures: false}\n";
  out.close();
  REQUIRE(run_cli("run " + exp.string(), dir / "run.txt") == 0);
  const auto j = nlohmann::json::parse(read_text_file(dir / "runs" / name / "metrics.json"));
  std::map<std::pair<std::string, std::string>, nlohmann::json> cases;
  for (const auto& c : j["cases"]) cases[{c["recording"].get<std::string>(), c["stack"].get<std::string>()}] = c["metrics"];
  return cases;
}

// A metric of a case, required to be there.
inline double metric(const nlohmann::json& m, const std::string& key) {
  INFO(key);
  REQUIRE(m.contains(key));
  return m[key].get<double>();
}

}  // namespace sketchlab::test
