#include "analytic_corrector.hpp"

#include <chrono>
#include <set>
#include <stdexcept>
#include <string>

#include "sketchlab/camera.hpp"
#include "scaffold.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network_nodes.hpp"
#include "stroke_2d.hpp"
#include "stroke_analysis.hpp"

namespace sketchlab::analytic {

namespace {

// A free stroke is worth re-inferring when some new curve projects within
// the collection radius (at δ_max) of it in its own view.
bool near_new_geometry(const Stroke& stroke, const std::vector<NetworkCurve>& added, const AnalyticParams& p) {
  const Camera cam(*stroke.view);
  const Stroke2d s2 = make_stroke_2d(stroke, cam.dpi(), p);
  if (s2.points.size() < 2) return false;
  const double r = p.collect_factor * p.delta_max * cam.dpi();
  for (const NetworkCurve& nc : added)
    for (int i = 0; i <= 16 * nc.curve.segment_count(); ++i) {
      const auto q = cam.project(evaluate(nc.curve, nc.curve.t_max() * i / (16.0 * nc.curve.segment_count())));
      if (q && nearest_on_polyline(s2.points, *q).distance <= r) return true;
    }
  return false;
}

// Nodes where the new curves meet the network in 3D: the inference puts an
// end or a curve joint exactly on a vertex, a line or a curve (§3.1
// position constraints Cᵒ, §3.2 position constraints), so every joint within
// `tolerance` of an existing curve is a junction. Guidelines are construction
// aids (§2.2), not part of the curve network: they get no nodes.
void add_nodes(const Network& network, double tolerance, Edit& edit) {
  NodeId next = network.next_node_id();
  const auto guide = [&](CurveId id) {
    const NetworkCurve* nc = network.find_curve(id);
    return nc && nc->layer == Layer::guide;
  };
  for (const NetworkCurve& nc : std::vector<NetworkCurve>(edit.curves_added)) {
    if (nc.layer == Layer::guide) continue;
    const int joints = nc.curve.segment_count() + (nc.curve.closed ? 0 : 1);
    for (int j = 0; j < joints; ++j)
      connect_point(network, evaluate(nc.curve, j), nc.id, j, tolerance, edit, next, guide);
  }
}

}  // namespace

std::vector<StrokeId> free_strokes(const Sketch& sketch) {
  // A stroke whose correction was empty leaves no history entry (the session
  // commits only non-empty edits); deleted and undone strokes do.
  std::set<StrokeId> recorded;
  for (const auto* list : {&sketch.history.done, &sketch.history.undone})
    for (const HistoryEntry& e : *list)
      if (e.stroke) recorded.insert(*e.stroke);
  std::vector<StrokeId> out;
  for (const auto& [id, stroke] : sketch.strokes)
    if (stroke.is_2d() && !recorded.count(id) && curves_of_stroke(sketch, id).empty()) out.push_back(id);
  return out;
}

Correction AnalyticCorrector::correct(const Stroke& stroke, const Sketch& sketch) {
  Correction c;
  const auto start = std::chrono::steady_clock::now();
  if (!stroke.is_2d()) {
    c.error = "analytic corrector needs 2D strokes (pixel samples with a View); stroke " +
              std::to_string(stroke.id) + " is not";
    return c;
  }
  try {
    const Vec3 up = sketch.workspace.up.normalized();
    Scaffold scaffold = build_scaffold(sketch.network, up, params_.vanishing_merge);
    StrokeOutcome out = analyse_stroke(stroke, scaffold, sketch, params_, true);
    CurveId next = sketch.network.next_curve_id();
    for (NetworkCurve& nc : out.added) {
      nc.id = next++;
      c.edit.curves_added.push_back(nc);
    }
    c.edit.curves_replaced = out.replaced;
    c.constraints = std::move(out.constraints);
    for (const auto& [k, v] : out.stats) c.stats.extra[k] = v;
    c.stats.subsets_tried = static_cast<int>(out.stats.count("combinations") ? out.stats["combinations"] : 0);
    c.stats.iterations = static_cast<int>(out.stats.count("curves_fitted") ? out.stats["curves_fitted"] : 0);

    // §2.1: free strokes are re-inferred when new nearby geometry appears.
    int reinferred = 0;
    std::vector<StrokeId> still_free;
    if (params_.reinfer_free && !c.edit.curves_added.empty()) {
      std::vector<NetworkCurve> fresh = c.edit.curves_added;
      for (const NetworkCurve& nc : fresh) add_to_scaffold(scaffold, nc, up);
      for (StrokeId id : free_strokes(sketch)) {
        if (id == stroke.id) continue;
        const Stroke& old = sketch.strokes.at(id);
        if (!near_new_geometry(old, fresh, params_)) {
          still_free.push_back(id);
          continue;
        }
        StrokeOutcome again = analyse_stroke(old, scaffold, sketch, params_, false);
        if (again.kind != StrokeOutcome::Kind::line && again.kind != StrokeOutcome::Kind::curve) {
          still_free.push_back(id);
          continue;
        }
        for (NetworkCurve& nc : again.added) {
          nc.id = next++;
          add_to_scaffold(scaffold, nc, up);
          c.edit.curves_added.push_back(nc);
          fresh.push_back(nc);
        }
        c.constraints.insert(c.constraints.end(), again.constraints.begin(), again.constraints.end());
        c.stats.extra["reinferred." + std::to_string(id)] = 1;
        ++reinferred;
      }
    } else {
      for (StrokeId id : free_strokes(sketch))
        if (id != stroke.id) still_free.push_back(id);
    }
    if (out.kind == StrokeOutcome::Kind::free) still_free.push_back(stroke.id);
    add_nodes(sketch.network, 10.0 * scaffold.tolerance, c.edit);
    c.stats.extra["reinferred"] = reinferred;
    c.stats.extra["free_strokes"] = static_cast<double>(still_free.size());
  } catch (const std::exception& e) {
    c = Correction{};
    c.error = std::string("analytic: ") + e.what();
    return c;
  }
  c.stats.extra["time_ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return c;
}

}  // namespace sketchlab::analytic
