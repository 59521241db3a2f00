#pragma once
// What a run was made from, recorded with its results: the sketchlab build
// (version, git commit, build fingerprint), the plugins each case used with
// their versions and files, and the SHA-256 of every input file. Written as
// <run>/provenance.yaml, in the head of each case.yaml, and as a section of
// report.html. Paths are relative to the run folder.
#include <filesystem>
#include <string>
#include <vector>

#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/build_info.hpp"
#include "sketchlab/lab/file_hash.hpp"
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab {

struct PluginProvenance {
  std::string kind, name, version;
  std::filesystem::path file;  // the library loaded (absolute)
};

struct InputProvenance {
  std::filesystem::path file;  // absolute
  FileHash hash;
};

struct RunProvenance {
  BuildInfo build;
  std::string started_utc;                // ISO 8601, e.g. "2026-12-02T08:15:00Z"
  InputProvenance experiment;             // the experiment YAML as read
  std::vector<InputProvenance> recordings;
  std::vector<PluginProvenance> plugins;  // those the stacks use, in kind/name order
  // Things the user must know about the outputs (e.g. why there are no
  // pictures); also printed on the terminal.
  std::vector<std::string> notes;
};

// The plugins `stacks` (resolved: resolve_stack) use, as loaded in `host`,
// and the hashes of the experiment file and recordings. Throws
// std::runtime_error naming a file that cannot be read.
RunProvenance collect_provenance(const ExperimentConfig& config, const std::vector<StackConfig>& stacks,
                                 const PluginHost& host);

// The plugins of one stack, as "kind name version" entries of `run`.
std::vector<PluginProvenance> plugins_of(const StackConfig& stack, const RunProvenance& run);

// <run>/provenance.yaml: build, start time, experiment file, recordings and
// plugins, paths relative to `run_dir`.
std::string provenance_yaml(const RunProvenance& run, const std::filesystem::path& run_dir);

// The "# ..." lines heading a case.yaml: sketchlab version and commit, the
// recording (relative to `case_dir`) with its SHA-256, and the stack's
// plugins with their versions. Comments, so case.yaml still loads as a stack.
std::string case_provenance_comment(const RunProvenance& run, const StackConfig& stack,
                                    const std::filesystem::path& recording,
                                    const std::filesystem::path& case_dir);

// The resolved experiment (config.resolved_yaml) with its recordings
// relative to `dir`: <run>/config.yaml, which repeats the run from there
// (`sketchlab run <run>/config.yaml`) as long as the run folder keeps its
// place relative to the recordings.
std::string experiment_yaml_relative_to(const ExperimentConfig& config, const std::filesystem::path& dir);

// The report's provenance section (<h2>Provenance</h2> and a table).
std::string provenance_html(const RunProvenance& run, const std::filesystem::path& run_dir);

}  // namespace sketchlab
