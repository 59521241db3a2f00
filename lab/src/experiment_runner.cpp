#include "sketchlab/lab/experiment_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>

#include "sketchlab/io/mesh_export.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/stroke_csv.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/lab/case_result_json.hpp"
#include "sketchlab/lab/report.hpp"
#include "sketchlab/lab/run_folder.hpp"
#include "sketchlab/lab/utc_timestamp.hpp"

namespace sketchlab {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Stack names become folder names: keep them readable but safe.
std::string folder_name(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && std::string("._-@=,+").find(c) == std::string::npos)
      c = '_';
  return out;
}

std::vector<Vec3> positions_of(const Stroke& s) {
  std::vector<Vec3> p;
  for (const auto& sample : s.samples) p.push_back(sample.position);
  return p;
}

void write_case_outputs(const OutputsConfig& out, const ReplayResult& r, bool timings, const fs::path& dir) {
  const Sketch& sketch = r.session.sketch();
  if (out.sketch_json) write_text_file(dir / "sketch.json", sketch_to_json(sketch, &r.steps));
  if (out.stroke_csv) write_text_file(dir / "strokes.csv", steps_to_csv(r.steps, timings));
  if (out.obj) write_text_file(dir / "sketch.obj", network_to_obj(sketch.network));
  if (out.ply || out.mlp) {
    std::vector<std::vector<Vec3>> raw;
    for (StrokeId s : strokes_with_curves(sketch))
      if (!sketch.strokes.at(s).samples_are_pixels) raw.push_back(positions_of(sketch.strokes.at(s)));
    std::vector<Vec3> nodes;
    for (const auto& [id, n] : sketch.network.nodes()) nodes.push_back(n.position);
    std::vector<const Mesh*> patches;
    for (const auto& [id, p] : sketch.network.patches()) patches.push_back(&p.mesh);
    write_text_file(dir / "curves.ply", polylines_to_ply(curve_polylines(sketch.network)));
    write_text_file(dir / "raw_strokes.ply", polylines_to_ply(raw));
    write_text_file(dir / "nodes.ply", points_to_ply(nodes));
    write_text_file(dir / "patches.ply", meshes_to_ply(patches));
  }
}

// The layers MeshLab can open (empty PLY files make it complain).
void write_meshlab_project(const fs::path& recording_dir, const std::vector<const CaseResult*>& cases) {
  std::vector<MeshLabLayer> layers;
  for (const CaseResult* c : cases) {
    if (!c->ok) continue;
    const std::string stack = c->dir.filename().string();
    const auto& v = c->metrics.values;
    const auto count = [&](const char* k) { auto it = v.find(k); return it == v.end() ? 0.0 : it->second; };
    if (count("strokes") > 0) layers.push_back({stack + " raw strokes", stack + "/raw_strokes.ply"});
    if (count("curves") > 0) layers.push_back({stack + " curves", stack + "/curves.ply"});
    if (count("nodes") > 0) layers.push_back({stack + " nodes", stack + "/nodes.ply"});
    if (count("patches") > 0) layers.push_back({stack + " patches", stack + "/patches.ply"});
  }
  write_text_file(recording_dir / (recording_dir.filename().string() + ".mlp"), meshlab_project(layers));
}

// What a picture shows of a case's final sketch: the workspace, the network
// and the raw strokes that still have curves.
Sketch pictured(const Sketch& sketch) {
  Sketch s;
  s.workspace = sketch.workspace;
  s.network = sketch.network;
  for (StrokeId id : strokes_with_curves(sketch)) s.strokes.emplace(id, sketch.strokes.at(id));
  return s;
}

// `sketches[i]` belongs to `cases[i]` (empty when the case failed).
void render_recording(const Renderer& renderer, const fs::path& recording_dir,
                      const std::vector<const CaseResult*>& cases,
                      const std::vector<const std::optional<Sketch>*>& sketches) {
  std::vector<std::pair<std::string, const Sketch*>> panels;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (cases[i]->ok && *sketches[i]) panels.emplace_back(cases[i]->variant.stack.name, &**sketches[i]);
  if (!panels.empty()) renderer(recording_dir / "side_by_side.png", panels);
}

}  // namespace

std::size_t RunSummary::failed() const {
  return static_cast<std::size_t>(std::count_if(cases.begin(), cases.end(), [](const CaseResult& c) { return !c.ok; }));
}

namespace {

std::string case_label(const CaseResult& c) { return c.recording.stem().string() + " x " + c.variant.stack.name; }

// The case's scene.gltf (or scene.error.txt): one case at a time, since the
// exporter's VTK objects are not thread-safe.
void write_scene(const SceneExporter& exporter, const Sketch& sketch, const fs::path& dir) {
  static std::mutex one_at_a_time;
  std::string text, error;
  try {
    std::lock_guard lock(one_at_a_time);
    text = exporter(sketch);
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (error.empty())
    write_text_file(dir / "scene.gltf", text);
  else
    write_text_file(dir / "scene.error.txt", error + "\n");
}

}  // namespace

RunPlan plan_run(const ExperimentConfig& config, const PluginHost& host, const RunOptions& options, bool create,
                 const fs::path& run_dir) {
  RunPlan plan;
  plan.config = config;
  std::vector<SweepCase> variants = expand_sweep(config);
  // Everything that can be checked without running is checked before the
  // run folder exists.
  std::vector<StackConfig> resolved;
  for (auto& v : variants) resolved.push_back(v.stack = resolve_stack(v.stack, host));

  RunSummary& summary = plan.summary;
  summary.provenance = collect_provenance(config, resolved, host);
  if (!options.timings) summary.provenance.started_utc.clear();  // byte-identical reruns
  const bool resume = !options.resume_dir.empty();
  if (!create) {
    summary.run_dir = run_dir;
  } else if (resume) {
    summary.run_dir = options.resume_dir;
    const fs::path recorded = summary.run_dir / "config.yaml";
    if (!fs::is_regular_file(recorded))
      throw std::runtime_error(summary.run_dir.string() + ": not a run folder (it has no config.yaml)");
    // The same experiment, or the folder's own config.yaml (whose recordings
    // and outputs.dir are written relative to it, so the text may differ).
    std::error_code ec;
    if (!fs::equivalent(config.file, recorded, ec) &&
        read_text_file(recorded) != experiment_yaml_relative_to(config, summary.run_dir))
      throw std::runtime_error(summary.run_dir.string() +
                               ": made from another experiment (its config.yaml differs): resume with the "
                               "same experiment and overrides, or with no experiment at all");
  } else {
    summary.run_dir = create_unique_folder(
        config.outputs.dir, config.outputs.timestamp ? config.name + "-" + utc_timestamp() : config.name);
    write_text_file(summary.run_dir / "config.yaml", experiment_yaml_relative_to(config, summary.run_dir));
  }

  for (const auto& rec : config.recordings)
    for (const auto& v : variants) {
      CaseResult c;
      c.recording = rec;
      c.variant = v;
      c.dir = summary.run_dir / rec.stem() / folder_name(v.stack.name);
      const fs::path record = c.dir / case_result_file;
      if (create && resume && fs::exists(record))
        case_result_from_json(read_text_file(record), record.string(), c);
      else
        plan.pending.push_back(summary.cases.size());
      summary.cases.push_back(std::move(c));
    }

  plan.pictures = config.outputs.pictures && options.renderer && options.pictures_unavailable.empty();
  if (config.outputs.pictures && !plan.pictures)
    summary.provenance.notes.push_back(
        "no pictures: " + (options.pictures_unavailable.empty() ? std::string("no renderer in this build")
                                                                : options.pictures_unavailable));
  plan.scenes = config.outputs.report && options.scene_exporter;
  return plan;
}

CaseResult run_case(const RunPlan& plan, std::size_t index, const PluginHost& host, const RunOptions& options,
                    std::optional<Sketch>* final_sketch) {
  CaseResult c = plan.summary.cases.at(index);
  const auto t0 = Clock::now();
  try {
    const StackInstance stack = instantiate_stack(c.variant.stack, host);
    auto input = instantiate_input(c.variant.stack, host, c.recording);
    const ReplayResult r = replay(*input, stack);
    write_case_outputs(plan.config.outputs, r, options.timings, c.dir);
    if (plan.scenes || (final_sketch && plan.pictures)) {
      Sketch shown = pictured(r.session.sketch());
      if (plan.scenes) write_scene(options.scene_exporter, shown, c.dir);
      if (final_sketch && plan.pictures) *final_sketch = std::move(shown);
    }
    std::string header = case_provenance_comment(plan.summary.provenance, c.variant.stack, c.recording, c.dir);
    for (const auto& [path, value] : c.variant.point) header += "# sweep: " + path + " = " + value + "\n";
    write_text_file(c.dir / "case.yaml", header + stack_to_yaml(c.variant.stack));
    c.metrics = compute_metrics(r);
    for (const auto& s : r.steps)
      if (s.event == EventKind::stroke && s.corrected && s.error.empty())
        c.stroke_latency_ms.push_back(options.timings ? s.latency_ms : 0.0);
    if (!options.timings)
      for (auto& [k, v] : c.metrics.values)
        if (k.rfind("latency_", 0) == 0) v = 0.0;
    c.ok = true;
  } catch (const std::exception& e) {
    c.error = e.what();
  }
  c.wall_ms = options.timings ? seconds_since(t0) * 1000.0 : 0.0;
  try {
    // Whole or not at all (write_text_file renames a temporary over it): a
    // process killed mid-write leaves no half record.
    write_text_file(c.dir / case_result_file, case_result_to_json(c));
  } catch (const std::exception& e) {
    // Without its record the case is run again by --resume; say why.
    if (c.ok) c.error = std::string("cannot write ") + case_result_file + ": " + e.what();
    c.ok = false;
  }
  return c;
}

void set_case_result(RunPlan& plan, std::size_t index, CaseResult result) {
  CaseResult& c = plan.summary.cases.at(index);
  c.ok = result.ok;
  c.error = std::move(result.error);
  c.metrics = std::move(result.metrics);
  c.stroke_latency_ms = std::move(result.stroke_latency_ms);
  c.wall_ms = result.wall_ms;
}

RunSummary finish_run(RunPlan plan, std::vector<std::optional<Sketch>> sketches, const PluginHost& host,
                      const RunOptions& options, double wall_s) {
  RunSummary& summary = plan.summary;
  const ExperimentConfig& config = plan.config;
  sketches.resize(summary.cases.size());
  // Cases finished before a --resume: their pictures from sketch.json, which
  // does not store the raw strokes.
  bool without_strokes = false;
  if (plan.pictures)
    for (std::size_t i = 0; i < summary.cases.size(); ++i) {
      const fs::path file = summary.cases[i].dir / "sketch.json";
      if (!summary.cases[i].ok || sketches[i] || !fs::exists(file)) continue;
      try {
        sketches[i] = read_sketch_json(file);
        without_strokes = true;
      } catch (const std::exception& e) {
        summary.provenance.notes.push_back("no picture of " + case_label(summary.cases[i]) + ": " + e.what());
      }
    }
  if (without_strokes)
    summary.provenance.notes.push_back(
        "resumed run: the pictures show the cases finished before the resume without their raw strokes "
        "(read back from sketch.json)");
  for (const auto& rec : config.recordings) {
    std::vector<const CaseResult*> cases;
    std::vector<const std::optional<Sketch>*> recording_sketches;
    for (std::size_t i = 0; i < summary.cases.size(); ++i)
      if (summary.cases[i].recording == rec) {
        cases.push_back(&summary.cases[i]);
        recording_sketches.push_back(&sketches[i]);
      }
    const fs::path dir = summary.run_dir / rec.stem();
    fs::create_directories(dir);
    if (config.outputs.mlp) write_meshlab_project(dir, cases);
    if (plan.pictures) {
      try {
        render_recording(options.renderer, dir, cases, recording_sketches);
      } catch (const std::exception& e) {
        // A failed picture must not lose the numbers: note it and go on.
        write_text_file(dir / "side_by_side.error.txt", std::string(e.what()) + "\n");
        summary.provenance.notes.push_back("no picture of " + rec.stem().string() + ": " + e.what());
      }
    }
  }
  summary.wall_s = options.timings ? wall_s : 0.0;
  if (config.outputs.report) write_report(summary, config, &host);
  write_text_file(summary.run_dir / "provenance.yaml", provenance_yaml(summary.provenance, summary.run_dir));
  return std::move(summary);
}

RunSummary run_experiment(const ExperimentConfig& config, const PluginHost& host, const RunOptions& options) {
  const auto start = Clock::now();
  RunPlan plan = plan_run(config, host, options);
  const std::size_t total = plan.summary.cases.size(), resumed = total - plan.pending.size();
  // The final sketch of each case, kept for the pictures drawn per recording
  // once every case has run.
  std::vector<std::optional<Sketch>> final_sketches(total);

  std::mutex progress_mutex;
  std::size_t done = resumed, failed = plan.summary.failed() - plan.pending.size();
  auto report = [&](const std::string& label, const CaseResult* finished) {
    if (!options.progress) return;
    std::lock_guard lock(progress_mutex);
    if (finished) {
      ++done;
      failed += !finished->ok;
    }
    options.progress({done, total, failed, resumed, label, seconds_since(start)});
  };

  std::atomic<std::size_t> next{0};
  std::vector<CaseResult> results(plan.pending.size());
  auto worker = [&] {
    for (std::size_t k = next++; k < plan.pending.size(); k = next++) {
      const std::size_t i = plan.pending[k];
      const std::string label = case_label(plan.summary.cases[i]);
      report(label, nullptr);
      results[k] = run_case(plan, i, host, options, &final_sketches[i]);
      report(label, &results[k]);
    }
  };
  const int jobs = std::max(1, options.jobs > 0 ? options.jobs
                                                : static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int j = 1; j < std::min<int>(jobs, static_cast<int>(plan.pending.size())); ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  for (std::size_t k = 0; k < plan.pending.size(); ++k) set_case_result(plan, plan.pending[k], std::move(results[k]));
  return finish_run(std::move(plan), std::move(final_sketches), host, options, seconds_since(start));
}

}  // namespace sketchlab
