// Curves, the curve network, edits, constraints and the sketch. Network and
// Sketch are read-only views here (only Network::apply, called by a session,
// changes a network); edits and their records are plain mutable values, so a
// Python corrector can build one.
#include "bindings.hpp"
#include "sketchlab/constraint.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/edit.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab::python {
namespace {

py::array_t<int> faces_array(const Mesh& mesh) {
  py::array_t<int> a({static_cast<py::ssize_t>(mesh.faces.size()), py::ssize_t{3}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < mesh.faces.size(); ++i)
    for (int j = 0; j < 3; ++j) r(static_cast<py::ssize_t>(i), j) = mesh.faces[i][j];
  return a;
}

void bind_curves(py::module_& m) {
  py::enum_<CurveKind>(m, "CurveKind").value("bezier", CurveKind::bezier).value("line", CurveKind::line);

  py::class_<Curve>(m, "Curve", "Cubic poly-Bézier: 3K+1 control points (m), t in [0, K]")
      .def(py::init<>())
      .def(py::init([](const Points& points, CurveKind kind, std::vector<bool> sharp, bool closed) {
             Curve c;
             c.kind = kind;
             c.control_points = from_array(points, "Curve.control_points");
             c.sharp = sharp.empty() && c.segment_count() > 0
                           ? std::vector<bool>(static_cast<std::size_t>(c.segment_count() + 1), false)
                           : std::move(sharp);
             c.closed = closed;
             if (const std::string why = validate(c); !why.empty()) throw py::value_error("Curve: " + why);
             return c;
           }),
           py::arg("control_points"), py::arg("kind") = CurveKind::bezier,
           py::arg("sharp") = std::vector<bool>{}, py::arg("closed") = false)
      .def_readwrite("kind", &Curve::kind)
      .def_property(
          "control_points", [](const Curve& c) { return to_array(c.control_points); },
          [](Curve& c, const Points& p) { c.control_points = from_array(p, "Curve.control_points"); },
          "(3K+1, 3) array (a copy; assign to change)")
      .def_readwrite("sharp", &Curve::sharp)
      .def_readwrite("closed", &Curve::closed)
      .def_property_readonly("segment_count", &Curve::segment_count)
      .def_property_readonly("t_max", &Curve::t_max)
      .def("evaluate", [](const Curve& c, double t) { return evaluate(c, t); }, py::arg("t"))
      .def("sample", [](const Curve& c, int n) { return to_array(sample_by_arclength(c, n)); },
           py::arg("n") = 64, "n points evenly spaced by arclength, shape (n, 3)")
      .def("length", [](const Curve& c) { return arclength(c); })
      .def("validate", [](const Curve& c) { return validate(c); })
      .def(py::self == py::self);
  m.def("make_line", &make_line, py::arg("a"), py::arg("b"));

  py::enum_<Keypoint::Kind>(m, "KeypointKind")
      .value("start", Keypoint::Kind::start).value("end", Keypoint::Kind::end)
      .value("midpoint", Keypoint::Kind::midpoint).value("tick", Keypoint::Kind::tick)
      .value("other", Keypoint::Kind::other);
  py::class_<Keypoint>(m, "Keypoint")
      .def(py::init<>())
      .def_readwrite("kind", &Keypoint::kind)
      .def_readwrite("t", &Keypoint::t)
      .def_readwrite("position", &Keypoint::position);
  m.def("default_keypoints", &default_keypoints, py::arg("curve"));
  py::class_<CurveNormal>(m, "CurveNormal")
      .def(py::init<>())
      .def_readwrite("t", &CurveNormal::t)
      .def_readwrite("normal", &CurveNormal::normal);

  py::class_<NetworkCurve>(m, "NetworkCurve")
      .def(py::init<>())
      .def_readwrite("id", &NetworkCurve::id)
      .def_readwrite("curve", &NetworkCurve::curve)
      .def_readwrite("layer", &NetworkCurve::layer)
      .def_readwrite("source_stroke", &NetworkCurve::source_stroke)
      .def_readwrite("keypoints", &NetworkCurve::keypoints)
      .def_readwrite("normals", &NetworkCurve::normals)
      .def(py::self == py::self);

  py::class_<NodeIncidence>(m, "NodeIncidence")
      .def(py::init<>())
      .def(py::init([](CurveId curve, double t) { return NodeIncidence{curve, t}; }), py::arg("curve"), py::arg("t"))
      .def_readwrite("curve", &NodeIncidence::curve)
      .def_readwrite("t", &NodeIncidence::t);
  py::class_<Node>(m, "Node")
      .def(py::init<>())
      .def(py::init([](NodeId id, const Vec3& p, std::vector<NodeIncidence> inc) {
             return Node{id, p, std::move(inc)};
           }),
           py::arg("id"), py::arg("position"), py::arg("incidences"))
      .def_readwrite("id", &Node::id)
      .def_readwrite("position", &Node::position)
      .def_readwrite("incidences", &Node::incidences)
      .def(py::self == py::self);

  py::class_<Segment>(m, "Segment")
      .def_readonly("curve", &Segment::curve).def_readonly("t0", &Segment::t0)
      .def_readonly("t1", &Segment::t1).def_readonly("node0", &Segment::node0)
      .def_readonly("node1", &Segment::node1);
  py::class_<OrientedSegment>(m, "OrientedSegment")
      .def(py::init<>())
      .def_readwrite("curve", &OrientedSegment::curve).def_readwrite("t_from", &OrientedSegment::t_from)
      .def_readwrite("t_to", &OrientedSegment::t_to).def_readwrite("node_from", &OrientedSegment::node_from)
      .def_readwrite("node_to", &OrientedSegment::node_to);
  py::class_<Patch>(m, "Patch")
      .def(py::init<>())
      .def_readwrite("id", &Patch::id)
      .def_readwrite("boundary", &Patch::boundary)
      .def_readwrite("automatic", &Patch::automatic)
      .def_property_readonly("vertices", [](const Patch& p) { return to_array(p.mesh.vertices); },
                             "(n, 3) mesh vertices (m)")
      .def_property_readonly("faces", [](const Patch& p) { return faces_array(p.mesh); },
                             "(m, 3) int triangles indexing vertices, CCW");
}

void bind_constraints(py::module_& m) {
  auto kind = py::enum_<ConstraintKind>(m, "ConstraintKind");
  for (int k = 0; k < constraint_kind_count; ++k) {
    const auto c = static_cast<ConstraintKind>(k);
    kind.value(std::string(to_string(c)).c_str(), c);
  }
  py::enum_<ConstraintRef::Kind>(m, "RefKind")
      .value("stroke", ConstraintRef::Kind::stroke).value("curve", ConstraintRef::Kind::curve)
      .value("node", ConstraintRef::Kind::node).value("grid", ConstraintRef::Kind::grid)
      .value("mirror", ConstraintRef::Kind::mirror).value("axis", ConstraintRef::Kind::axis);
  py::class_<ConstraintRef>(m, "ConstraintRef")
      .def(py::init<>())
      .def(py::init([](ConstraintRef::Kind k, std::uint64_t id, double parameter) {
             return ConstraintRef{k, id, parameter};
           }),
           py::arg("kind"), py::arg("id"), py::arg("parameter") = 0.0)
      .def_readwrite("kind", &ConstraintRef::kind)
      .def_readwrite("id", &ConstraintRef::id)
      .def_readwrite("parameter", &ConstraintRef::parameter);
  py::class_<Constraint>(m, "Constraint")
      .def(py::init<>())
      .def_readwrite("kind", &Constraint::kind)
      .def_readwrite("references", &Constraint::references)
      .def_readwrite("target", &Constraint::target)
      .def_readwrite("weight", &Constraint::weight)
      .def_readwrite("hard", &Constraint::hard)
      .def_readwrite("enforced", &Constraint::enforced)
      .def_readwrite("residual", &Constraint::residual)
      .def(py::self == py::self);
}

void bind_network(py::module_& m) {
  py::class_<IdCounters>(m, "IdCounters")
      .def_readonly("next_curve", &IdCounters::next_curve)
      .def_readonly("next_node", &IdCounters::next_node)
      .def_readonly("next_patch", &IdCounters::next_patch);
  py::class_<Edit>(m, "Edit", "A change to a network; new ids from network.next_*_id upwards")
      .def(py::init<>())
      .def_readwrite("curves_added", &Edit::curves_added)
      .def_readwrite("curves_replaced", &Edit::curves_replaced)
      .def_readwrite("curves_removed", &Edit::curves_removed)
      .def_readwrite("nodes_added", &Edit::nodes_added)
      .def_readwrite("nodes_replaced", &Edit::nodes_replaced)
      .def_readwrite("nodes_removed", &Edit::nodes_removed)
      .def_readwrite("patches_added", &Edit::patches_added)
      .def_readwrite("patches_removed", &Edit::patches_removed)
      .def("empty", &Edit::empty)
      .def(py::self == py::self);

  py::class_<CurveHit>(m, "CurveHit")
      .def_readonly("curve", &CurveHit::curve).def_readonly("t", &CurveHit::t)
      .def_readonly("point", &CurveHit::point).def_readonly("distance", &CurveHit::distance);
  py::class_<NodeHit>(m, "NodeHit")
      .def_readonly("node", &NodeHit::node).def_readonly("distance", &NodeHit::distance);
  py::class_<Network>(m, "Network", "The curve network (read-only)")
      .def_property_readonly("curves", &Network::curves, py::return_value_policy::reference_internal,
                             "{curve id: NetworkCurve}")
      .def_property_readonly("nodes", &Network::nodes, py::return_value_policy::reference_internal)
      .def_property_readonly("patches", &Network::patches, py::return_value_policy::reference_internal)
      .def_property_readonly("counters", &Network::counters)
      .def("next_curve_id", &Network::next_curve_id)
      .def("next_node_id", &Network::next_node_id)
      .def("next_patch_id", &Network::next_patch_id)
      .def("segments", &Network::segments)
      .def("curves_near", &Network::curves_near, py::arg("point"), py::arg("radius"),
           "Curves within radius (m) of point, nearest first (ties by id)")
      .def("curves_near_polyline",
           [](const Network& n, const Points& p, double r) { return n.curves_near_polyline(from_array(p, "polyline"), r); },
           py::arg("polyline"), py::arg("radius"))
      .def("nodes_near", &Network::nodes_near, py::arg("point"), py::arg("radius"));
}

void bind_sketch(py::module_& m) {
  py::class_<Workspace>(m, "Workspace")
      .def(py::init<>())
      .def_readwrite("up", &Workspace::up)
      .def_readwrite("grid_enabled", &Workspace::grid_enabled)
      .def_readwrite("grid_spacing", &Workspace::grid_spacing)
      .def_readwrite("grid_origin", &Workspace::grid_origin)
      .def_readwrite("mirror_enabled", &Workspace::mirror_enabled)
      .def_readwrite("mirror_normal", &Workspace::mirror_normal)
      .def_readwrite("mirror_offset", &Workspace::mirror_offset)
      .def_readwrite("scale", &Workspace::scale)
      .def(py::self == py::self);
  py::class_<Sketch>(m, "Sketch", "What plugins read: workspace, network, raw strokes (read-only)")
      .def_readonly("workspace", &Sketch::workspace)
      .def_readonly("network", &Sketch::network)
      .def_readonly("strokes", &Sketch::strokes, "{stroke id: Stroke}, undone ones included")
      .def_readonly("correction_enabled", &Sketch::correction_enabled)
      .def_readonly("mode", &Sketch::mode)
      .def("curves_of_stroke", [](const Sketch& s, StrokeId id) { return curves_of_stroke(s, id); })
      .def("live_strokes", [](const Sketch& s) { return live_strokes(s); });
}

}  // namespace

void bind_geometry(py::module_& m) {
  // Layer first: curves and strokes use it.
  py::enum_<Layer>(m, "Layer")
      .value("scaffold", Layer::scaffold).value("shape", Layer::shape).value("free", Layer::free)
      .value("guide", Layer::guide).value("auto", Layer::automatic);
  bind_curves(m);
  bind_constraints(m);
  bind_network(m);
  bind_sketch(m);
}

}  // namespace sketchlab::python
