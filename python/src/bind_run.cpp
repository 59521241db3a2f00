// Stacks, sessions (one event at a time, with undo), replays, experiments and
// the teacher-forced comparison. Every call that runs plugins releases the GIL
// (a Python corrector takes it back for its own calls).
#include "bindings.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/experiment_runner.hpp"
#include "sketchlab/lab/live_session.hpp"
#include "sketchlab/lab/metrics.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/plugin/recording_input.hpp"

namespace sketchlab::python {
namespace {

using ParamMap = std::map<std::string, ParamValue>;

// Overrides as the command line takes them ("stacks.0.corrector.params.delta=0.03").
std::vector<Override> parse_overrides(const std::vector<std::string>& texts) {
  std::vector<Override> out;
  for (const auto& text : texts) out.push_back(parse_override(text));
  return out;
}

// A stack from plugin names and parameters: the StackConfig a YAML file
// would give, instantiated the same way (same parameter checks and errors).
StackInstance make_stack(const PluginHost& host, const std::string& corrector, const ParamMap& params,
                         const std::optional<std::string>& surfacer, const ParamMap& surfacer_params,
                         const std::optional<std::string>& name, std::optional<double> time_budget) {
  StackConfig config;
  config.name = name ? *name : corrector;
  config.corrector.plugin = corrector;
  config.corrector.params = params;
  config.corrector.location.file = "<python>";
  if (surfacer) {
    config.surfacer = PluginChoice{};
    config.surfacer->plugin = *surfacer;
    config.surfacer->params = surfacer_params;
    config.surfacer->location.file = "<python>";
  }
  config.time_budget = time_budget;
  config.location.file = "<python>";
  return instantiate_stack(config, host);
}

void bind_stacks(py::module_& m) {
  py::class_<StackConfig>(m, "StackConfig")
      .def_readwrite("name", &StackConfig::name)
      .def_property_readonly("corrector", [](const StackConfig& s) { return s.corrector.plugin; })
      .def_property_readonly("corrector_params", [](const StackConfig& s) { return s.corrector.params; })
      .def_property_readonly("surfacer", [](const StackConfig& s) {
        return s.surfacer ? std::optional<std::string>(s.surfacer->plugin) : std::nullopt;
      })
      .def("to_yaml", [](const StackConfig& s) { return stack_to_yaml(s); });
  m.def("load_stack", [](const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    return load_stack(file, parse_overrides(overrides));
  }, py::arg("file"), py::arg("overrides") = std::vector<std::string>{},
        "A stack YAML file; overrides as on the command line ('corrector.params.delta=0.03')");

  py::class_<StackInstance>(m, "Stack", "Live plugin objects of a stack")
      .def_readonly("name", &StackInstance::name)
      .def_readonly("corrector", &StackInstance::corrector)
      .def_readonly("surfacer", &StackInstance::surfacer)
      .def_readonly("time_budget_s", &StackInstance::time_budget_s);
  m.def("instantiate_stack", &instantiate_stack, py::arg("config"), py::arg("host"));
  m.def("make_stack", &make_stack, py::arg("host"), py::arg("corrector"), py::arg("params") = ParamMap{},
        py::arg("surfacer") = py::none(), py::arg("surfacer_params") = ParamMap{}, py::arg("name") = py::none(),
        py::arg("time_budget") = py::none());
}

void bind_sessions(py::module_& m) {
  py::class_<StepReport>(m, "StepReport")
      .def_property_readonly("event", [](const StepReport& r) { return std::string(to_string(r.event)); },
                             "the event's kind as recordings name it (\"stroke\", \"undo\", ...)")
      .def_readonly("time", &StepReport::time)
      .def_readonly("stroke", &StepReport::stroke)
      .def_readonly("latency_ms", &StepReport::latency_ms)
      .def_readonly("corrected", &StepReport::corrected)
      .def_readonly("stats", &StepReport::stats)
      .def_readonly("constraints", &StepReport::constraints)
      .def_readonly("curves_added", &StepReport::curves_added)
      .def_readonly("curves_removed", &StepReport::curves_removed)
      .def_readonly("curves_replaced", &StepReport::curves_replaced)
      .def_readonly("patches_added", &StepReport::patches_added)
      .def_readonly("patches_removed", &StepReport::patches_removed)
      .def_readonly("error", &StepReport::error);

  py::class_<Session>(m, "Session", "Folds events through a stack into a sketch (in memory)")
      .def(py::init([](const StackInstance& s, const Workspace& ws) {
             return Session(ws, s.corrector, s.surfacer, {}, s.time_budget_s);
           }),
           py::arg("stack"), py::arg("workspace") = Workspace{})
      .def("handle", &Session::handle, py::arg("event"), py::call_guard<py::gil_scoped_release>())
      .def("revert_last", &Session::revert_last, py::call_guard<py::gil_scoped_release>(),
           "Takes back the last handled event exactly; False when none is left")
      .def_property_readonly("events_handled", &Session::events_handled)
      .def_property_readonly("sketch", &Session::sketch, py::return_value_policy::reference_internal)
      .def_property_readonly("references", &Session::references)
      .def("to_json", [](const Session& s) { return sketch_to_json(s.sketch()); },
           "The sketch file (DESIGN.md 'Formats'), as `sketchlab run` writes it");

  py::class_<LiveSession>(m, "LiveSession",
                          "A recorded session: each event is appended to the recording, then folded "
                          "through every stack")
      .def(py::init<const RecordingHeader&, std::vector<StackInstance>, const std::filesystem::path&, bool>(),
           py::arg("header"), py::arg("stacks"), py::arg("recording"), py::arg("overwrite") = false)
      .def("handle", &LiveSession::handle, py::arg("event"), py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("stack_count", &LiveSession::stack_count)
      .def("session", &LiveSession::session, py::arg("index"), py::return_value_policy::reference_internal)
      .def_property_readonly("recording_path", &LiveSession::recording_path)
      .def_property_readonly("events_recorded", &LiveSession::events_recorded)
      .def("close", &LiveSession::close);

  py::class_<ReplayResult>(m, "ReplayResult")
      .def_readonly("stack", &ReplayResult::stack)
      .def_readonly("header", &ReplayResult::header)
      .def_readonly("session", &ReplayResult::session)
      .def_readonly("steps", &ReplayResult::steps)
      .def_property_readonly("sketch", [](const ReplayResult& r) -> const Sketch& { return r.session.sketch(); },
                             py::return_value_policy::reference_internal)
      .def("to_json", [](const ReplayResult& r) { return sketch_to_json(r.session.sketch(), &r.steps); },
           "The sketch file with each stroke's constraints, byte-identical to `sketchlab run`'s sketch.json")
      .def("metrics", [](const ReplayResult& r) { return compute_metrics(r).values; },
           "The case's summary metrics by name (run/metrics.hpp)");
  m.def("replay", [](const Recording& recording, const StackInstance& stack) {
    py::gil_scoped_release release;
    RecordingInput input(recording);
    return replay(input, stack);
  }, py::arg("recording"), py::arg("stack"), "Folds every event of the recording through a new session");
}

void bind_experiments(py::module_& m) {
  py::class_<PrecisionRecall>(m, "PrecisionRecall")
      .def_readonly("intended", &PrecisionRecall::intended)
      .def_readonly("detected", &PrecisionRecall::detected)
      .def_readonly("matched", &PrecisionRecall::matched)
      .def_property_readonly("precision", &PrecisionRecall::precision)
      .def_property_readonly("recall", &PrecisionRecall::recall);
  py::class_<ExperimentConfig>(m, "ExperimentConfig")
      .def_readonly("name", &ExperimentConfig::name)
      .def_readonly("file", &ExperimentConfig::file)
      .def_readonly("recordings", &ExperimentConfig::recordings)
      .def_readonly("stacks", &ExperimentConfig::stacks)
      .def_readonly("resolved_yaml", &ExperimentConfig::resolved_yaml);
  m.def("load_experiment", [](const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    return load_experiment(file, parse_overrides(overrides));
  }, py::arg("file"), py::arg("overrides") = std::vector<std::string>{},
        "An experiment YAML file; overrides as `sketchlab run --set` takes them");
  py::class_<CaseResult>(m, "CaseResult")
      .def_readonly("recording", &CaseResult::recording)
      .def_property_readonly("stack", [](const CaseResult& c) { return c.variant.stack.name; })
      .def_readonly("dir", &CaseResult::dir)
      .def_readonly("ok", &CaseResult::ok)
      .def_readonly("error", &CaseResult::error)
      .def_property_readonly("metrics", [](const CaseResult& c) { return c.metrics.values; })
      .def_property_readonly("relations", [](const CaseResult& c) { return c.metrics.relations; })
      .def_readonly("stroke_latency_ms", &CaseResult::stroke_latency_ms)
      .def_readonly("wall_ms", &CaseResult::wall_ms);
  py::class_<RunSummary>(m, "RunSummary")
      .def_readonly("run_dir", &RunSummary::run_dir)
      .def_readonly("cases", &RunSummary::cases)
      .def_readonly("wall_s", &RunSummary::wall_s)
      .def_property_readonly("failed", &RunSummary::failed);
  m.def("run_experiment", [](const ExperimentConfig& config, const PluginHost& host, int jobs, bool timings) {
    py::gil_scoped_release release;
    RunOptions options;
    options.jobs = jobs;
    options.timings = timings;
    return run_experiment(config, host, options);
  }, py::arg("config"), py::arg("host"), py::arg("jobs") = 0, py::arg("timings") = true,
        "Runs every case (outputs as `sketchlab run` writes them)");
}

void bind_teacher_forced(py::module_& m) {
  py::class_<Distribution>(m, "Distribution")
      .def_readonly("count", &Distribution::count)
      .def_readonly("median", &Distribution::median)
      .def_readonly("p90", &Distribution::p90)
      .def_readonly("p95", &Distribution::p95)
      .def_readonly("max", &Distribution::max);
  py::class_<TeacherForcedStroke>(m, "TeacherForcedStroke")
      .def_readonly("stroke", &TeacherForcedStroke::stroke)
      .def_readonly("time", &TeacherForcedStroke::time)
      .def_readonly("corrected", &TeacherForcedStroke::corrected)
      .def_readonly("compared", &TeacherForcedStroke::compared)
      .def_readonly("error", &TeacherForcedStroke::error)
      .def_readonly("reference_line", &TeacherForcedStroke::reference_line)
      .def_readonly("output_line", &TeacherForcedStroke::output_line)
      .def_readonly("endpoint_distance", &TeacherForcedStroke::endpoint_distance)
      .def_readonly("mean_deviation", &TeacherForcedStroke::mean_deviation)
      .def_readonly("max_deviation", &TeacherForcedStroke::max_deviation)
      .def_readonly("output_stroke_distance", &TeacherForcedStroke::output_stroke_distance)
      .def_readonly("reference_stroke_distance", &TeacherForcedStroke::reference_stroke_distance)
      .def_readonly("reference_snap", &TeacherForcedStroke::reference_snap)
      .def_readonly("output_snap", &TeacherForcedStroke::output_snap)
      .def_readonly("reversed", &TeacherForcedStroke::reversed)
      .def_readonly("reference_end", &TeacherForcedStroke::reference_end, "the reference curve's two ends (m)")
      .def_readonly("output_end", &TeacherForcedStroke::output_end,
                    "the output curve's ends matched to reference_end[0], [1] (m)")
      .def_readonly("reference_curve", &TeacherForcedStroke::reference_curve)
      .def_readonly("output_curve", &TeacherForcedStroke::output_curve)
      .def_readonly("constraints", &TeacherForcedStroke::constraints)
      .def_readonly("constraints_considered", &TeacherForcedStroke::constraints_considered)
      .def_readonly("constraints_enforced", &TeacherForcedStroke::constraints_enforced)
      .def_readonly("stats", &TeacherForcedStroke::stats)
      .def_readonly("latency_ms", &TeacherForcedStroke::latency_ms);
  py::class_<TeacherForcedSummary>(m, "TeacherForcedSummary")
      .def_readonly("strokes", &TeacherForcedSummary::strokes)
      .def_readonly("compared", &TeacherForcedSummary::compared)
      .def_readonly("errors", &TeacherForcedSummary::errors)
      .def_readonly("endpoint_distance", &TeacherForcedSummary::endpoint_distance)
      .def_readonly("mean_deviation", &TeacherForcedSummary::mean_deviation)
      .def_readonly("max_deviation", &TeacherForcedSummary::max_deviation)
      .def_readonly("output_stroke_distance", &TeacherForcedSummary::output_stroke_distance)
      .def_readonly("reference_stroke_distance", &TeacherForcedSummary::reference_stroke_distance)
      .def_readonly("latency_ms", &TeacherForcedSummary::latency_ms)
      .def_property_readonly("snap_agreement", &TeacherForcedSummary::snap_agreement)
      .def_property_readonly("snap_kind_agreement", &TeacherForcedSummary::snap_kind_agreement)
      .def_property_readonly("snap_recall", &TeacherForcedSummary::snap_recall)
      .def_property_readonly("snap_precision", &TeacherForcedSummary::snap_precision)
      .def_property_readonly("line_agreement", &TeacherForcedSummary::line_agreement);
  m.def("teacher_forced", [](const Recording& recording, Corrector& corrector, const std::string& track,
                             double snap_tolerance, int resample) {
    py::gil_scoped_release release;
    return teacher_forced(recording, corrector, TeacherForcedOptions{track, snap_tolerance, resample});
  }, py::arg("recording"), py::arg("corrector"), py::arg("track") = "cassie", py::arg("snap_tolerance") = 1e-4,
        py::arg("resample") = 32, "Per-stroke comparison with a reference track (`sketchlab teacher-forced`)");
  m.def("summarize", &summarize, py::arg("strokes"));
  m.def("teacher_forced_csv", &teacher_forced_csv, py::arg("strokes"));
}

}  // namespace

void bind_run(py::module_& m) {
  bind_stacks(m);
  bind_sessions(m);
  bind_experiments(m);
  bind_teacher_forced(m);
}

}  // namespace sketchlab::python
