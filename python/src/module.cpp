// sketchlab._sketchlab: the kernel's C++ API for Python (docs/python.md).
// Kernel exceptions become Python exceptions carrying the same message the
// command line prints after "sketchlab: ".
#include "bindings.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording.hpp"
#include "sketchlab/version.hpp"

namespace sketchlab::python {

py::array_t<double> to_array(const std::vector<Vec3>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int j = 0; j < 3; ++j) r(static_cast<py::ssize_t>(i), j) = points[i][j];
  return a;
}

py::array_t<double> to_array(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

std::vector<Vec3> from_array(const Points& points, const char* what) {
  if (points.ndim() != 2 || points.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < points.ndim(); ++i)
      shape += (i ? ", " : "") + std::to_string(points.shape(i));
    throw py::value_error(std::string(what) + ": need an array of shape (n, 3), got shape " +
                          shape + (points.ndim() == 1 ? ",)" : ")"));
  }
  auto r = points.unchecked<2>();
  std::vector<Vec3> out(static_cast<std::size_t>(points.shape(0)));
  for (py::ssize_t i = 0; i < points.shape(0); ++i) out[static_cast<std::size_t>(i)] = {r(i, 0), r(i, 1), r(i, 2)};
  return out;
}

}  // namespace sketchlab::python

PYBIND11_MODULE(_sketchlab, m) {
  using namespace sketchlab;
  using namespace sketchlab::python;
  m.doc() = "sketchlab kernel bindings (docs/python.md)";
  m.attr("__version__") = SKETCHLAB_KERNEL_VERSION;
  m.attr("build_fingerprint") = build_fingerprint();

  // Most specific first is irrelevant (each catches its own type); all derive
  // from RuntimeError so `except RuntimeError` catches every kernel error.
  py::register_exception<ConfigError>(m, "ConfigError", PyExc_RuntimeError);
  py::register_exception<RecordingError>(m, "RecordingError", PyExc_RuntimeError);
  py::register_exception<PluginError>(m, "PluginError", PyExc_RuntimeError);
  py::register_exception<ParamError>(m, "ParamError", PyExc_ValueError);

  bind_geometry(m);
  bind_recording(m);
  bind_plugins(m);
  bind_run(m);
}
