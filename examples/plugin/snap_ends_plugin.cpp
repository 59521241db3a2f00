// snap_ends: the smallest corrector that does something a user sees. Each
// stroke is fitted as the freehand baseline fits it (kernel freehand_edit with
// the CASSIE app's preprocessing, reference items 1-4), then each end of the
// curve lying within `radius`/s of an existing curve (s: the workspace zoom
// the stroke was drawn at, CASSIE CHI 2021 §4.2's δ/s rule) moves onto the
// closest point of the nearest such curve, and a node joins the two curves
// there. A Bézier end drags its tangent handle along (the end segment's shape
// is kept); a line stays a line between its moved ends.
//
// It is the example of docs/plugin-authoring.md (built out of tree against
// the installed SDK), and the C++ reference the Python snap_ends corrector
// (python/sketchlab/snap_ends.py) must reproduce bit for bit.
#include "sketchlab/plugin/param_table.hpp"
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/session.hpp"

namespace {

using namespace sketchlab;

struct SnapEndsSettings {
  double radius = 0.02;  // m at zoom 1
};

const ParamTable<SnapEndsSettings>& parameters() {
  static const auto table = ParamTable<SnapEndsSettings>().real(
      "radius", &SnapEndsSettings::radius, 1e-4, 1.0, "m",
      "snap distance at zoom 1 (CASSIE's δ = 0.02); divided by the stroke's workspace zoom");
  return table;
}

class SnapEndsCorrector : public Corrector {
 public:
  explicit SnapEndsCorrector(const Params& p) : radius_(parameters().read(p).radius) {}

  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c;
    c.edit = freehand_edit(stroke, sketch, cassie_app_preprocess());
    NetworkCurve& added = c.edit.curves_added.front();
    Curve& curve = added.curve;
    if (curve.closed) return c;  // a closed curve has no free ends

    const double r = radius_ / stroke.workspace_scale;
    const std::size_t last = curve.control_points.size() - 1;
    const std::size_t end_index[2] = {0, last};
    const std::size_t handle_index[2] = {1, last - 1};
    Vec3 ends[2] = {curve.control_points[0], curve.control_points[last]};
    NodeId next_node = sketch.network.next_node_id();
    int snapped = 0;
    for (int e = 0; e < 2; ++e) {
      const auto hits = sketch.network.curves_near(ends[e], r);
      if (hits.empty()) continue;
      const CurveHit& hit = hits.front();  // nearest, ties by id
      const Vec3 offset = hit.point - ends[e];
      ends[e] = hit.point;
      if (curve.kind == CurveKind::bezier) {
        curve.control_points[end_index[e]] += offset;
        curve.control_points[handle_index[e]] += offset;
      }
      const double t = e == 0 ? 0.0 : curve.t_max();
      c.edit.nodes_added.push_back({next_node++, hit.point, {{added.id, t}, {hit.curve, hit.t}}});
      c.constraints.push_back({ConstraintKind::point_on_curve,
                               {{ConstraintRef::Kind::stroke, stroke.id, double(e)},
                                {ConstraintRef::Kind::curve, hit.curve, hit.t}},
                               hit.point, 1.0, true, true, 0.0});
      ++snapped;
    }
    if (snapped > 0 && curve.kind == CurveKind::line) curve = make_line(ends[0], ends[1]);
    added.keypoints = default_keypoints(curve);
    c.stats.extra["ends_snapped"] = snapped;
    return c;
  }

 private:
  double radius_;
};

PluginDescriptor describe() {
  return corrector_descriptor<SnapEndsCorrector>(
      "snap_ends", "1.0", "Freehand fit, then each end within radius of a curve snaps onto it",
      parameters().specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
