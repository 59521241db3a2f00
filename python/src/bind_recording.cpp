// Strokes (samples as numpy arrays), events and recordings. Events other than
// strokes are reached through their recording-format JSON (event_json.hpp),
// which `Event.to_dict()` parses: one description of every payload, the
// format's.
#include <optional>

#include "bindings.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::python {
namespace {

using Values = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<double> column(const Values& v, std::size_t n, const char* what) {
  if (v.ndim() != 1 || static_cast<std::size_t>(v.shape(0)) != n)
    throw py::value_error(std::string("Stroke: ") + what + " must have shape (" + std::to_string(n) +
                          ",), one value per point");
  return {v.data(), v.data() + n};
}

Stroke make_stroke(StrokeId id, const Points& points, const std::optional<Values>& times,
                   const std::optional<Values>& pressures, Layer layer, double workspace_scale) {
  Stroke s;
  s.id = id;
  s.layer = layer;
  s.workspace_scale = workspace_scale;
  const std::vector<Vec3> p = from_array(points, "Stroke.points");
  std::vector<double> t(p.size()), pr(p.size(), 1.0);
  if (times) t = column(*times, p.size(), "times");
  else
    for (std::size_t i = 0; i < p.size(); ++i) t[i] = 0.01 * static_cast<double>(i);  // 100 Hz
  if (pressures) pr = column(*pressures, p.size(), "pressures");
  s.samples.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) s.samples[i] = {p[i], t[i], pr[i], Quat::Identity()};
  if (const std::string why = validate(s); !why.empty()) throw py::value_error(why);
  return s;
}

template <class F>
py::array_t<double> sample_column(const Stroke& s, F f) {
  py::array_t<double> a(static_cast<py::ssize_t>(s.samples.size()));
  double* d = a.mutable_data();
  for (const Sample& x : s.samples) *d++ = f(x);
  return a;
}

void bind_strokes(py::module_& m) {
  py::class_<View>(m, "View")
      .def(py::init<>())
      .def_readwrite("view", &View::view)
      .def_readwrite("projection", &View::projection)
      .def_readwrite("viewport", &View::viewport)
      .def_readwrite("dpi", &View::dpi);
  py::class_<Stroke>(m, "Stroke", "One input stroke: samples in metres (VR) or pixels of `view` (2D)")
      .def(py::init(&make_stroke), py::arg("id"), py::arg("points"), py::arg("times") = py::none(),
           py::arg("pressures") = py::none(), py::arg("layer") = Layer::automatic,
           py::arg("workspace_scale") = 1.0,
           "points (n, 3); times (n,) seconds, default 100 Hz from 0; pressures (n,) in [0, 1], "
           "default 1. Raises ValueError for a stroke the kernel refuses (validate()).")
      .def_readwrite("id", &Stroke::id)
      .def_readwrite("layer", &Stroke::layer)
      .def_readwrite("workspace_scale", &Stroke::workspace_scale)
      .def_readwrite("view", &Stroke::view)
      .def_readwrite("samples_are_pixels", &Stroke::samples_are_pixels)
      .def_readwrite("draw_plane", &Stroke::draw_plane)
      .def_property_readonly("points", [](const Stroke& s) { return to_array(positions(s)); }, "(n, 3)")
      .def_property_readonly("times", [](const Stroke& s) { return sample_column(s, [](const Sample& x) { return x.time; }); })
      .def_property_readonly("pressures",
                             [](const Stroke& s) { return sample_column(s, [](const Sample& x) { return x.pressure; }); })
      .def_property_readonly("orientations", [](const Stroke& s) {
        py::array_t<double> a({static_cast<py::ssize_t>(s.samples.size()), py::ssize_t{4}});
        auto r = a.mutable_unchecked<2>();
        for (std::size_t i = 0; i < s.samples.size(); ++i) {
          const Quat& q = s.samples[i].orientation;
          const double c[4] = {q.w(), q.x(), q.y(), q.z()};
          for (int j = 0; j < 4; ++j) r(static_cast<py::ssize_t>(i), j) = c[j];
        }
        return a;
      }, "(n, 4) unit quaternions w, x, y, z")
      .def("__len__", [](const Stroke& s) { return s.samples.size(); })
      .def("validate", [](const Stroke& s) { return validate(s); })
      .def(py::self == py::self);
}

void bind_events(py::module_& m) {
  py::class_<Event>(m, "Event", "One recording event: time (s), type name, payload")
      .def_readwrite("time", &Event::time)
      .def_property_readonly("type", [](const Event& e) { return std::string(event_type_name(e.payload)); })
      .def_property_readonly("stroke", [](const Event& e) -> std::optional<Stroke> {
        if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) return s->stroke;
        return std::nullopt;
      }, "The stroke of a stroke event, else None")
      .def("to_json", [](const Event& e) { return to_json_line(e); }, "The event's line in a recording")
      .def_static("from_json", [](const std::string& line) { return event_from_json_line(line); }, py::arg("line"))
      .def_static("of_stroke", [](const Stroke& s, std::optional<double> t) {
        return Event{t ? *t : (s.samples.empty() ? 0.0 : s.samples.back().time), StrokeEvent{s}};
      }, py::arg("stroke"), py::arg("time") = py::none(), "A stroke event, at the stroke's last sample time by default")
      .def_static("undo", [](double t) { return Event{t, UndoEvent{}}; }, py::arg("time"))
      .def_static("redo", [](double t) { return Event{t, RedoEvent{}}; }, py::arg("time"))
      .def_static("recompute_surface", [](double t) { return Event{t, RecomputeSurfaceEvent{}}; }, py::arg("time"))
      .def(py::self == py::self);

  py::class_<RecordingHeader>(m, "RecordingHeader")
      .def(py::init<>())
      .def_readwrite("version", &RecordingHeader::version)
      .def_readwrite("units", &RecordingHeader::units)
      .def_readwrite("workspace", &RecordingHeader::workspace)
      .def_readwrite("source", &RecordingHeader::source)
      .def("to_json", [](const RecordingHeader& h) { return to_json_line(h); });
  py::class_<Recording>(m, "Recording")
      .def(py::init<>())
      .def_readwrite("header", &Recording::header)
      .def_readwrite("events", &Recording::events)
      .def("__len__", [](const Recording& r) { return r.events.size(); })
      .def("__iter__", [](const Recording& r) { return py::make_iterator(r.events.begin(), r.events.end()); },
           py::keep_alive<0, 1>())
      .def("strokes", [](const Recording& r) {
        std::vector<Stroke> out;
        for (const Event& e : r.events)
          if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) out.push_back(s->stroke);
        return out;
      }, "The strokes of the stroke events, in order")
      .def(py::self == py::self);

  m.def("read_recording", [](const std::filesystem::path& path, bool refuse_truncated) {
    py::gil_scoped_release release;
    return read_recording(path, RecordingReadOptions{refuse_truncated});
  }, py::arg("path"), py::arg("refuse_truncated") = false,
        "Reads a .jsonl recording; RecordingError 'file:line: reason' on bad input");
  m.def("write_recording", [](const std::filesystem::path& path, const Recording& r, bool overwrite) {
    py::gil_scoped_release release;
    write_recording(path, r, overwrite);
  }, py::arg("path"), py::arg("recording"), py::arg("overwrite") = false);
}

}  // namespace

void bind_recording(py::module_& m) {
  bind_strokes(m);
  bind_events(m);
}

}  // namespace sketchlab::python
