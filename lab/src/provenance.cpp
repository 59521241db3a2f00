#include "sketchlab/lab/provenance.hpp"
#include "html_escape.hpp"
#include "sketchlab/lab/utc_timestamp.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>
#include <tuple>

namespace sketchlab {
namespace fs = std::filesystem;
namespace {

InputProvenance input(const fs::path& file) { return {fs::absolute(file), hash_file(file)}; }

std::string relative_text(const fs::path& p, const fs::path& base) {
  std::error_code ec;
  const fs::path r = fs::relative(p, base, ec);
  return ec || r.empty() ? p.string() : r.string();
}

std::vector<std::pair<PluginKind, std::string>> choices_of(const StackConfig& stack) {
  std::vector<std::pair<PluginKind, std::string>> out;
  out.emplace_back(PluginKind::input, stack.input ? stack.input->plugin : std::string(default_input_plugin));
  out.emplace_back(PluginKind::corrector, stack.corrector.plugin);
  if (stack.surfacer) out.emplace_back(PluginKind::surfacer, stack.surfacer->plugin);
  return out;
}

}  // namespace

RunProvenance collect_provenance(const ExperimentConfig& config, const std::vector<StackConfig>& stacks,
                                 const PluginHost& host) {
  RunProvenance run;
  run.build = build_info();
  run.started_utc = utc_iso8601();
  if (!config.file.empty()) run.experiment = input(config.file);
  for (const auto& r : config.recordings) run.recordings.push_back(input(r));
  std::set<std::pair<std::string, std::string>> seen;
  for (const auto& stack : stacks)
    for (const auto& [kind, name] : choices_of(stack)) {
      const LoadedPlugin* p = host.find(kind, name);
      if (!p || !seen.emplace(to_string(kind), name).second) continue;
      run.plugins.push_back({std::string(to_string(kind)), name, p->descriptor->version, p->path});
    }
  std::sort(run.plugins.begin(), run.plugins.end(), [](const PluginProvenance& a, const PluginProvenance& b) {
    return std::tie(a.kind, a.name) < std::tie(b.kind, b.name);
  });
  return run;
}

std::vector<PluginProvenance> plugins_of(const StackConfig& stack, const RunProvenance& run) {
  std::vector<PluginProvenance> out;
  for (const auto& [kind, name] : choices_of(stack))
    for (const auto& p : run.plugins)
      if (p.kind == to_string(kind) && p.name == name) out.push_back(p);
  return out;
}

std::string provenance_yaml(const RunProvenance& run, const fs::path& run_dir) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "sketchlab" << YAML::Value << YAML::BeginMap
      << YAML::Key << "version" << YAML::Value << run.build.version
      << YAML::Key << "git_commit" << YAML::Value << run.build.git_commit
      << YAML::Key << "fingerprint" << YAML::Value << run.build.fingerprint
      << YAML::Key << "build_type" << YAML::Value << run.build.build_type
      << YAML::Key << "compiler" << YAML::Value << run.build.compiler
      << YAML::Key << "flags" << YAML::Value << YAML::DoubleQuoted << run.build.flags << YAML::EndMap;
  if (!run.started_utc.empty()) out << YAML::Key << "started" << YAML::Value << run.started_utc;
  const auto file = [&](const InputProvenance& in) {
    out << YAML::BeginMap << YAML::Key << "path" << YAML::Value << relative_text(in.file, run_dir)
        << YAML::Key << "bytes" << YAML::Value << in.hash.bytes
        << YAML::Key << "sha256" << YAML::Value << in.hash.sha256 << YAML::EndMap;
  };
  if (!run.experiment.file.empty()) {
    out << YAML::Key << "experiment" << YAML::Value;
    file(run.experiment);
  }
  out << YAML::Key << "recordings" << YAML::Value << YAML::BeginSeq;
  for (const auto& r : run.recordings) file(r);
  out << YAML::EndSeq;
  out << YAML::Key << "plugins" << YAML::Value << YAML::BeginSeq;
  for (const auto& p : run.plugins)
    out << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << p.kind
        << YAML::Key << "name" << YAML::Value << p.name
        << YAML::Key << "version" << YAML::Value << YAML::DoubleQuoted << p.version
        << YAML::Key << "file" << YAML::Value << p.file.string() << YAML::EndMap;
  out << YAML::EndSeq;
  if (!run.notes.empty()) {
    out << YAML::Key << "notes" << YAML::Value << YAML::BeginSeq;
    for (const auto& n : run.notes) out << n;
    out << YAML::EndSeq;
  }
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::string case_provenance_comment(const RunProvenance& run, const StackConfig& stack,
                                    const fs::path& recording, const fs::path& case_dir) {
  std::string text = "# sketchlab " + run.build.version + ", commit " + run.build.git_commit + ", " +
                     run.build.build_type + " (" + run.build.fingerprint + ")\n";
  text += "# recording: " + relative_text(recording, case_dir);
  for (const auto& r : run.recordings)
    if (r.file == fs::absolute(recording)) text += " (sha256 " + r.hash.sha256 + ")";
  text += "\n";
  for (const auto& p : plugins_of(stack, run))
    text += "# " + p.kind + ": " + p.name + " " + p.version + " (" + p.file.string() + ")\n";
  return text;
}

std::string experiment_yaml_relative_to(const ExperimentConfig& config, const fs::path& dir) {
  YAML::Node root = YAML::Load(config.resolved_yaml);
  YAML::Node recordings(YAML::NodeType::Sequence);
  for (const auto& r : config.recordings) recordings.push_back(relative_text(r, dir));
  root["recordings"] = recordings;
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

std::string provenance_html(const RunProvenance& run, const fs::path& run_dir) {
  std::string h = "<h2>Provenance</h2>\n<table>\n";
  const auto row = [&](const std::string& k, const std::string& v) {
    h += "<tr><th style=\"text-align:left\">" + html_escape(k) + "</th><td><code>" + html_escape(v) + "</code></td></tr>\n";
  };
  row("sketchlab", run.build.version);
  row("git commit", run.build.git_commit);
  row("build", run.build.build_type + ", " + run.build.compiler + ", " + run.build.flags);
  row("fingerprint", run.build.fingerprint);
  if (!run.started_utc.empty()) row("started", run.started_utc);
  if (!run.experiment.file.empty())
    row("experiment", relative_text(run.experiment.file, run_dir) + "  sha256 " + run.experiment.hash.sha256);
  for (const auto& r : run.recordings)
    row("recording", relative_text(r.file, run_dir) + "  sha256 " + r.hash.sha256);
  for (const auto& p : run.plugins) row(p.kind, p.name + " " + p.version + "  (" + p.file.string() + ")");
  h += "</table>\n<p>Every parameter of every case, defaults included: <code>&lt;recording&gt;/&lt;stack&gt;/case.yaml</code>; "
       "the whole experiment: <code>config.yaml</code>; all of the above: <code>provenance.yaml</code>.</p>\n";
  for (const auto& n : run.notes) h += "<p><strong>Note:</strong> " + html_escape(n) + "</p>\n";
  return h;
}

}  // namespace sketchlab
