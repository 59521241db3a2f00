// python: a corrector whose work is done by a Python class, so a corrector
// can be prototyped in Python and run in any stack, the experiment runner,
// the teacher-forced comparison and the viewers beside the C++ ones
// (README.md). The class gets the kernel's own types through the `sketchlab`
// module: correct(stroke: sketchlab.Stroke, sketch: sketchlab.Sketch) returns
// a sketchlab.Correction or a sketchlab.Edit. A Python exception, or a return
// value of another type, becomes the stroke's error (Correction::error): the
// session records the raw stroke and goes on.
#include <pybind11/embed.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "python_interpreter.hpp"
#include "sketchlab/plugin/param_table.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;
namespace py = pybind11;

// `module` is a Python file (ends in .py or names an existing file) or an
// importable module name.
py::object load_module(const std::string& module) {
  std::error_code ec;
  if (module.ends_with(".py") || std::filesystem::is_regular_file(module, ec)) {
    if (!std::filesystem::is_regular_file(module, ec))
      throw std::runtime_error("python corrector: module: no such file '" + module + "'");
    const py::module_ util = py::module_::import("importlib.util");
    const std::string name = "sketchlab_user." + std::filesystem::path(module).stem().string();
    py::object spec = util.attr("spec_from_file_location")(name, module);
    py::object mod = util.attr("module_from_spec")(spec);
    spec.attr("loader").attr("exec_module")(mod);
    return mod;
  }
  return py::module_::import("importlib").attr("import_module")(module);
}

// One line: "ValueError: message (file.py:12)", the innermost frame of the
// traceback (pybind11's what() appends the whole stack on further lines).
std::string describe(const py::error_already_set& e) {
  std::string text = py::str(e.type().attr("__name__")).cast<std::string>();
  if (const std::string value = py::str(e.value()).cast<std::string>(); !value.empty()) text += ": " + value;
  py::handle tb = e.trace();
  if (tb) {
    while (py::hasattr(tb, "tb_next") && !tb.attr("tb_next").is_none()) tb = tb.attr("tb_next");
    const std::string file = py::str(tb.attr("tb_frame").attr("f_code").attr("co_filename")).cast<std::string>();
    text += " (" + std::filesystem::path(file).filename().string() + ":" +
            py::str(tb.attr("tb_lineno")).cast<std::string>() + ")";
  }
  return text;
}

struct PythonSettings {
  std::string module = "sketchlab.snap_ends";
  std::string class_name = "SnapEnds";
  std::string kwargs_json = "{}";
};

const ParamTable<PythonSettings>& parameters() {
  using S = PythonSettings;
  static const auto table =
      ParamTable<S>()
          .string("module", &S::module,
                  "the Python corrector: a .py file (relative to the working directory) or an importable module name "
                  "(default: the example bundled with the sketchlab package)")
          .string("class", &S::class_name,
                  "the class in it; instantiated once per stack with `params` as keyword arguments")
          .string("params", &S::kwargs_json, "JSON object of keyword arguments for the class");
  return table;
}

class PythonCorrector : public Corrector {
 public:
  explicit PythonCorrector(const Params& p) : PythonCorrector(parameters().read(p)) {}
  explicit PythonCorrector(const PythonSettings& p) : label_(p.module + ":" + p.class_name) {
    if (p.module.empty())
      throw ParamError("module", "python corrector: parameter 'module' is empty: give a .py file or a module name");
    python_corrector::ensure_interpreter();
    py::gil_scoped_acquire gil;
    try {
      const py::object cls = load_module(p.module).attr(p.class_name.c_str());
      const py::object kwargs = py::module_::import("json").attr("loads")(p.kwargs_json);
      if (!py::isinstance<py::dict>(kwargs))
        throw ParamError("params", "python corrector " + label_ +
                                       ": parameter 'params' must be a JSON object (keyword arguments of the class)");
      object_ = cls(**kwargs);
      if (!py::hasattr(object_, "correct"))
        throw std::runtime_error("python corrector " + label_ + ": the class has no correct(stroke, sketch) method");
    } catch (py::error_already_set& e) {
      throw std::runtime_error("python corrector " + label_ + ": " + describe(e));
    }
  }

  ~PythonCorrector() override {
    // At the exit of a Python process the interpreter may be gone first:
    // then the reference is left to it.
    if (!Py_IsInitialized()) {
      object_.release();
      return;
    }
    py::gil_scoped_acquire gil;
    object_ = py::object();
  }

  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    py::gil_scoped_acquire gil;
    try {
      // The sketch is passed by reference: valid during the call only.
      const py::object result =
          object_.attr("correct")(py::cast(stroke), py::cast(&sketch, py::return_value_policy::reference));
      if (py::isinstance<Edit>(result)) return Correction{result.cast<Edit>(), {}, {}, {}};
      if (py::isinstance<Correction>(result)) return result.cast<Correction>();
      Correction c;
      c.error = "python corrector " + label_ + ": correct() returned " +
                py::str(py::type::of(result).attr("__name__")).cast<std::string>() +
                "; expected sketchlab.Correction or sketchlab.Edit";
      return c;
    } catch (py::error_already_set& e) {
      Correction c;
      c.error = "python corrector " + label_ + ": " + describe(e);
      return c;
    }
  }

 private:
  std::string label_;
  py::object object_;
};

PluginDescriptor describe() {
  return corrector_descriptor<PythonCorrector>(
      "python", "1.0", "Runs a Python class as a corrector (correct(stroke, sketch) -> Correction or Edit)",
      parameters().specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
