#pragma once
// Small sweeps for the tests of distributed and resumed runs, written as
// <dir>/sweep.yaml with outputs in `runs` relative to where the run starts,
// so runs started in sibling folders give the same bytes.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "test_paths.hpp"

namespace sketchlab::test {

// <dir>/sweep.yaml over hat and chair (the first 20 events of each) with
// the `stacks` given as "name: corrector" entries and one `sweep` axis.
inline std::filesystem::path write_sweep_of(const std::filesystem::path& dir,
                                            const std::vector<std::pair<std::string, std::string>>& stacks,
                                            const std::string& sweep) {
  const std::filesystem::path file = dir / "sweep.yaml";
  std::ofstream out(file);
  out << "experiment: sweep\nrecordings: [" << source_path("data/recordings/hat.jsonl") << ", "
      << source_path("data/recordings/chair.jsonl") << "]\nstacks:\n";
  for (const auto& [name, corrector] : stacks)
    out << "  - name: " << name << "\n    input: {plugin: replay, params: {max_events: 20}}\n"
        << "    corrector: " << corrector << "\n";
  out << "sweep:\n  " << sweep << "\noutputs: {dir: runs, timestamp: false, pictures: false}\n";
  return file;
}

// 2 recordings x (freehand at 3 fit errors + CASSIE) = 8 cases.
inline std::filesystem::path write_sweep(const std::filesystem::path& dir) {
  return write_sweep_of(dir,
                        {{"free", "{plugin: freehand}"}, {"cassie", "{plugin: cassie, params: {mirror: plane}}"}},
                        "stacks.0.corrector.params.fit_error: [0.25, 0.5, 1.0]");
}

// The fixture corrector that crashes its process when SKETCHLAB_FIXTURE_CRASH
// is set (tests/fixtures/plugins/correct_crashes.cpp), for SKETCHLAB_PLUGIN_PATH.
inline std::string crash_plugin_dir() { return std::string(SKETCHLAB_FIXTURE_PLUGIN_DIR) + "/correct_crashes"; }

// 2 recordings x (freehand at 2 fit errors, the crashing corrector, freehand
// again) = 8 cases; per recording (chair first) the third case crashes.
inline std::filesystem::path write_crash_sweep(const std::filesystem::path& dir) {
  return write_sweep_of(dir,
                        {{"free", "{plugin: freehand}"},
                         {"crash", "{plugin: correct_crashes}"},
                         {"late", "{plugin: freehand, params: {fit_error: 1.0}}"}},
                        "stacks.0.corrector.params.fit_error: [0.25, 0.5]");
}

// Cases of a run folder with a record (case_result.json): finished ones.
inline int finished_cases(const std::filesystem::path& run) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(run))
    n += e.path().filename() == "case_result.json";
  return n;
}

}  // namespace sketchlab::test
