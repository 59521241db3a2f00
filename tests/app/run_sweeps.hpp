#pragma once
// Small sweeps for the tests of distributed and resumed runs, written as
// <dir>/sweep.yaml with outputs in `runs` relative to where the run starts,
// so runs started in sibling folders give the same bytes.
#include <filesystem>
#include <fstream>
#include <string>

#include "test_paths.hpp"

namespace sketchlab::test {

// 2 recordings x (freehand at 3 fit errors + CASSIE) = 8 cases.
inline std::filesystem::path write_sweep(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "sweep.yaml";
  std::ofstream(file) << "experiment: sweep\n"
                      << "recordings: [" << source_path("data/recordings/hat.jsonl") << ", "
                      << source_path("data/recordings/chair.jsonl") << "]\n"
                      << "stacks:\n"
                      << "  - name: free\n    input: {plugin: replay, params: {max_events: 20}}\n"
                      << "    corrector: {plugin: freehand}\n"
                      << "  - name: cassie\n    input: {plugin: replay, params: {max_events: 20}}\n"
                      << "    corrector: {plugin: cassie, params: {mirror: plane}}\n"
                      << "sweep:\n  stacks.0.corrector.params.fit_error: [0.25, 0.5, 1.0]\n"
                      << "outputs: {dir: runs, timestamp: false, pictures: false}\n";
  return file;
}

// The fixture corrector that crashes its process when SKETCHLAB_FIXTURE_CRASH
// is set (tests/fixtures/plugins/correct_crashes.cpp), for SKETCHLAB_PLUGIN_PATH.
inline std::string crash_plugin_dir() { return std::string(SKETCHLAB_FIXTURE_PLUGIN_DIR) + "/correct_crashes"; }

// 2 recordings x (freehand at 2 fit errors, the crashing corrector, freehand
// again) = 8 cases; per recording (chair first) the third case crashes.
inline std::filesystem::path write_crash_sweep(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "sweep.yaml";
  std::ofstream(file) << "experiment: sweep\n"
                      << "recordings: [" << source_path("data/recordings/hat.jsonl") << ", "
                      << source_path("data/recordings/chair.jsonl") << "]\n"
                      << "stacks:\n"
                      << "  - name: free\n    input: {plugin: replay, params: {max_events: 12}}\n"
                      << "    corrector: {plugin: freehand}\n"
                      << "  - name: crash\n    input: {plugin: replay, params: {max_events: 12}}\n"
                      << "    corrector: {plugin: correct_crashes}\n"
                      << "  - name: late\n    input: {plugin: replay, params: {max_events: 12}}\n"
                      << "    corrector: {plugin: freehand, params: {fit_error: 1.0}}\n"
                      << "sweep:\n  stacks.0.corrector.params.fit_error: [0.25, 0.5]\n"
                      << "outputs: {dir: runs, timestamp: false, pictures: false}\n";
  return file;
}

// Cases of a run folder with a record (case_result.json): finished ones.
inline int finished_cases(const std::filesystem::path& run) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(run))
    n += e.path().filename() == "case_result.json";
  return n;
}

}  // namespace sketchlab::test
