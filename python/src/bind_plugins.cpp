// The plugin host, parameter specs, correctors and what they return. A
// Correction is a plain value so a Python corrector (plugins/correctors/python)
// can build one; the kernel's freehand fit is exposed for the same reason.
#include "bindings.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab::python {
namespace {

void bind_params(py::module_& m) {
  py::enum_<ParamType>(m, "ParamType")
      .value("boolean", ParamType::boolean).value("integer", ParamType::integer)
      .value("real", ParamType::real).value("string", ParamType::string)
      .value("choice", ParamType::choice);
  py::class_<ParamSpec>(m, "ParamSpec")
      .def_readonly("name", &ParamSpec::name)
      .def_readonly("type", &ParamSpec::type)
      .def_readonly("default", &ParamSpec::default_value)
      .def_readonly("min", &ParamSpec::min)
      .def_readonly("max", &ParamSpec::max)
      .def_readonly("choices", &ParamSpec::choices)
      .def_readonly("unit", &ParamSpec::unit)
      .def_readonly("doc", &ParamSpec::doc)
      .def_property_readonly("allowed", [](const ParamSpec& s) { return describe_allowed(s); })
      .def("__repr__", [](const ParamSpec& s) {
        return "<ParamSpec " + s.name + " = " + format_value(s.default_value) + ": " + describe_allowed(s) + ">";
      });
}

void bind_host(py::module_& m) {
  py::enum_<PluginKind>(m, "PluginKind")
      .value("corrector", PluginKind::corrector).value("surfacer", PluginKind::surfacer)
      .value("input", PluginKind::input);
  py::class_<LoadedPlugin>(m, "Plugin")
      .def_readonly("path", &LoadedPlugin::path)
      .def_property_readonly("kind", [](const LoadedPlugin& p) { return p.descriptor->kind; })
      .def_property_readonly("name", [](const LoadedPlugin& p) { return p.descriptor->name; })
      .def_property_readonly("version", [](const LoadedPlugin& p) { return p.descriptor->version; })
      .def_property_readonly("summary", [](const LoadedPlugin& p) { return p.descriptor->summary; })
      .def_property_readonly("params", [](const LoadedPlugin& p) { return p.descriptor->params; })
      .def("__repr__", [](const LoadedPlugin& p) {
        return "<Plugin " + std::string(to_string(p.descriptor->kind)) + " " + p.descriptor->name + ">";
      });
  py::class_<PluginLoadError>(m, "PluginLoadError")
      .def_readonly("path", &PluginLoadError::path)
      .def_readonly("reason", &PluginLoadError::reason);

  py::class_<PluginHost, std::shared_ptr<PluginHost>>(m, "PluginHost",
                                                      "Loads plugin libraries (sketchlab_<kind>_<name>.so)")
      .def(py::init<>())
      .def_static("default_search_paths", &PluginHost::default_search_paths)
      .def("load_directories", &PluginHost::load_directories, py::arg("dirs"),
           py::call_guard<py::gil_scoped_release>())
      .def("load_file", &PluginHost::load_file, py::arg("file"), py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("plugins", &PluginHost::plugins, py::return_value_policy::reference_internal)
      .def_property_readonly("errors", &PluginHost::errors)
      .def("find", &PluginHost::find, py::arg("kind"), py::arg("name"), py::return_value_policy::reference_internal)
      .def("make_corrector", &PluginHost::make_corrector, py::arg("name"),
           py::arg("params") = std::map<std::string, ParamValue>{})
      .def("make_surfacer", &PluginHost::make_surfacer, py::arg("name"),
           py::arg("params") = std::map<std::string, ParamValue>{});
}

void bind_correctors(py::module_& m) {
  py::class_<CorrectionStats>(m, "CorrectionStats")
      .def(py::init<>())
      .def_readwrite("iterations", &CorrectionStats::iterations)
      .def_readwrite("subsets_tried", &CorrectionStats::subsets_tried)
      .def_readwrite("extra", &CorrectionStats::extra)
      .def_readwrite("outcomes", &CorrectionStats::outcomes);
  py::class_<Correction>(m, "Correction", "What a corrector returns for one stroke")
      .def(py::init<>())
      .def(py::init([](Edit edit, std::vector<Constraint> constraints, CorrectionStats stats, std::string error) {
             return Correction{std::move(edit), std::move(constraints), std::move(stats), std::move(error)};
           }),
           py::arg("edit"), py::arg("constraints") = std::vector<Constraint>{},
           py::arg("stats") = CorrectionStats{}, py::arg("error") = "")
      .def_readwrite("edit", &Correction::edit)
      .def_readwrite("constraints", &Correction::constraints)
      .def_readwrite("stats", &Correction::stats)
      .def_readwrite("error", &Correction::error);
  py::enum_<StrokeSpace>(m, "StrokeSpace").value("world", StrokeSpace::world).value("pixels", StrokeSpace::pixels);
  py::class_<Corrector, std::shared_ptr<Corrector>>(m, "Corrector", "A corrector plugin object")
      .def("correct", &Corrector::correct, py::arg("stroke"), py::arg("sketch"),
           py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("stroke_space", &Corrector::stroke_space);
  py::class_<Surfacer, std::shared_ptr<Surfacer>>(m, "Surfacer", "A surfacer plugin object");

  py::class_<PreprocessParams>(m, "PreprocessParams")
      .def(py::init<>())
      .def_readwrite("delta", &PreprocessParams::delta)
      .def_readwrite("fit_error_factor", &PreprocessParams::fit_error_factor)
      .def_readwrite("max_g1_angle", &PreprocessParams::max_g1_angle)
      .def_readwrite("detect_lines", &PreprocessParams::detect_lines)
      .def_readwrite("remove_hooks", &PreprocessParams::remove_hooks);
  m.def("cassie_app_preprocess", &cassie_app_preprocess,
        "The CASSIE app's preprocessing parameters (reference items 1-4)");
  m.def("freehand_edit", &freehand_edit, py::arg("stroke"), py::arg("sketch"), py::arg("params"),
        "The edit adding the stroke as one fitted curve (the freehand baseline)");
}

}  // namespace

void bind_plugins(py::module_& m) {
  bind_params(m);
  bind_host(m);
  bind_correctors(m);
}

}  // namespace sketchlab::python
