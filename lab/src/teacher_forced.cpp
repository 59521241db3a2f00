#include "sketchlab/lab/teacher_forced.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <time.h>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/hausdorff.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/network_nodes.hpp"

namespace sketchlab {
namespace {

struct Pending {
  StrokeId stroke = 0;
  Layer layer = Layer::automatic;
  double time = 0.0;
  Curve curve;
};

// Adds a reference curve to the sketch with nodes where its joints lie on
// alive curves (CASSIE splits a curve at each intersection, so its joints
// include every point where it meets the network).
void add_reference(Sketch& sketch, const Pending& p, std::map<StrokeId, CurveId>& curve_of) {
  constexpr double tol = 1e-5;
  Edit e;
  const CurveId id = sketch.network.next_curve_id();
  e.curves_added.push_back(make_network_curve(id, p.curve, p.layer, p.stroke));
  // Not connect_point: a joint at an existing node adds only this curve's
  // incidence there (connect_point also adds every other curve within the
  // tolerance), and two joints never share a new node. Through connect_point
  // the fidelity figures move (all: snap agreement 84.0 -> 83.9 %).
  NodeId next = sketch.network.next_node_id();
  std::map<NodeId, Node> replaced;
  for (int k = 0; k <= p.curve.segment_count(); ++k) {
    const Vec3 q = p.curve.control_points[3 * k];
    const auto hits = sketch.network.curves_near(q, tol);
    if (hits.empty()) continue;
    const auto nodes = sketch.network.nodes_near(q, tol);
    if (!nodes.empty()) {
      const NodeId n = nodes.front().node;
      if (!replaced.count(n)) replaced[n] = *sketch.network.find_node(n);
      replaced[n].incidences.push_back({id, static_cast<double>(k)});
      continue;
    }
    Node n;
    n.id = next++;
    n.position = q;
    n.incidences.push_back({id, static_cast<double>(k)});
    for (const CurveHit& h : hits) n.incidences.push_back({h.curve, h.t});
    e.nodes_added.push_back(n);
  }
  for (auto& [n, node] : replaced) e.nodes_replaced.push_back(node);
  sketch.network.apply(e);
  curve_of[p.stroke] = id;
}

// The surfacer's patch from an add-patch command on `sub` at the centroid of
// `joints`, then (a concave cycle's centroid may lie nearer a dangling
// piece) at the midpoint of each pair of them; without joints, at the
// centroid of the curves' control points (a closed curve alone).
std::optional<Patch> walk_patch(const Sketch& sub, const std::vector<Vec3>& joints, Surfacer& surfacer,
                                std::string& why) {
  std::vector<Vec3> points(1, Vec3::Zero());
  if (joints.empty()) {
    int n = 0;
    for (const auto& [id, nc] : sub.network.curves())
      for (const Vec3& q : nc.curve.control_points) points[0] += q, ++n;
    points[0] /= n;
  } else {
    for (const Vec3& q : joints) points[0] += q / static_cast<double>(joints.size());
    for (std::size_t i = 0; i < joints.size(); ++i)
      for (std::size_t j = i + 1; j < joints.size(); ++j) points.push_back((joints[i] + joints[j]) / 2);
  }
  for (const Vec3& q : points) {
    SurfaceUpdate u = surfacer.command(sub, AddPatchEvent{q});
    if (u.error.empty() && !u.edit.patches_added.empty()) return std::move(u.edit.patches_added.front());
    if (why.empty()) why = u.error.empty() ? "the surfacer made no patch" : u.error;
  }
  return std::nullopt;
}

// The reference patch over `curves`, meshed by `surfacer` (TeacherForcedOptions):
// the surfacer sees only these curves (same ids) and their nodes with the
// incidences among them, so its walk can follow no other curve; failing
// that, also with nodes where a joint of one lies within `junction` of
// another (CASSIE's graph joins curves there; add_reference does not).
// Empty with `why` set when neither gives a patch.
std::optional<Patch> mesh_reference_patch(const Sketch& sketch, const std::set<CurveId>& curves,
                                          double junction, Surfacer& surfacer, std::string& why) {
  Sketch sub;
  sub.workspace = sketch.workspace;
  Edit e;
  std::vector<Vec3> joints;
  for (CurveId c : curves) e.curves_added.push_back(*sketch.network.find_curve(c));
  for (const auto& [id, node] : sketch.network.nodes()) {
    Node kept{node};
    std::erase_if(kept.incidences, [&](const NodeIncidence& i) { return !curves.count(i.curve); });
    if (kept.incidences.size() < 2) continue;
    e.nodes_added.push_back(kept);
    joints.push_back(node.position);
  }
  sub.network.apply(e);
  if (auto patch = walk_patch(sub, joints, surfacer, why)) return patch;
  const std::size_t exact = joints.size();
  Edit near;
  NodeId next = std::max(sub.network.next_node_id(), sketch.network.next_node_id());
  for (CurveId c : curves) {
    const Curve& curve = sub.network.find_curve(c)->curve;
    for (int k = 0; k <= curve.segment_count(); ++k)
      connect_point(sub.network, curve.control_points[3 * k], c, k, junction, near, next);
  }
  if (!near.nodes_added.empty()) {
    sub.network.apply(near);
    for (const Node& n : near.nodes_added) joints.push_back(n.position);
    if (auto patch = walk_patch(sub, joints, surfacer, why)) return patch;
  }
  why += " (its " + std::to_string(curves.size()) + " curves meet at " + std::to_string(exact) + " nodes, " +
         std::to_string(joints.size() - exact) + " more within " + std::to_string(junction * 1000).substr(0, 4) +
         " mm)";
  return std::nullopt;
}

std::string snap_kind(const Sketch& sketch, const Vec3& p, double tol) {
  if (!sketch.network.nodes_near(p, tol).empty()) return "node";
  if (!sketch.network.curves_near(p, tol).empty()) return "curve";
  const Workspace& ws = sketch.workspace;
  if (ws.grid_enabled && ws.grid_spacing > 0 && (nearest_grid_point(ws, p) - p).norm() <= tol)
    return "grid";
  if (ws.mirror_enabled && ws.mirror_normal.norm() > 0 &&
      std::abs(ws.mirror_normal.normalized().dot(p) - ws.mirror_offset / ws.mirror_normal.norm()) <= tol)
    return "mirror";
  return "";
}

void compare(const Curve& ref, const Curve& out, int n, TeacherForcedStroke& r) {
  const Vec3 r0 = ref.control_points.front(), r1 = ref.control_points.back();
  const Vec3 o0 = out.control_points.front(), o1 = out.control_points.back();
  const double direct = std::max((r0 - o0).norm(), (r1 - o1).norm());
  const double reversed = std::max((r0 - o1).norm(), (r1 - o0).norm());
  const bool rev = reversed < direct;
  r.endpoint_distance = std::min(direct, reversed);
  const auto a = sample_by_arclength(ref, n);
  auto b = sample_by_arclength(out, n);
  if (rev) std::reverse(b.begin(), b.end());
  double sum = 0.0, mx = 0.0;
  for (int i = 0; i < n; ++i) {
    const double d = (a[i] - b[i]).norm();
    sum += d;
    mx = std::max(mx, d);
  }
  r.mean_deviation = sum / n;
  r.max_deviation = mx;
}

bool is_closed(const Curve& c) {
  return c.closed || (c.control_points.front() - c.control_points.back()).norm() <= 1e-9;
}

void nearest_candidate(const std::vector<Constraint>& cs, const Vec3& end, TeacherForcedStroke& r, int k) {
  r.candidate_distance[k] = std::numeric_limits<double>::infinity();
  for (const Constraint& c : cs) {
    if (c.kind != ConstraintKind::intersection && c.kind != ConstraintKind::grid_point &&
        c.kind != ConstraintKind::mirror_plane)
      continue;
    const double d = (c.target - end).norm();
    if (d < r.candidate_distance[k]) r.candidate_distance[k] = d, r.candidate_enforced[k] = c.enforced;
  }
}

}  // namespace

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::vector<std::string> reference_tracks(const Recording& rec) {
  std::set<std::string> tracks;
  for (const Event& e : rec.events)
    if (const auto* r = std::get_if<ReferenceEvent>(&e.payload)) tracks.insert(r->track);
  return {tracks.begin(), tracks.end()};
}

std::vector<TeacherForcedStroke> teacher_forced(const Recording& rec, Corrector& corrector,
                                                const TeacherForcedOptions& opt, std::vector<std::string>* warnings) {
  if (opt.resample < 2) throw std::invalid_argument("teacher_forced: resample must be >= 2");
  if (!opt.patches.empty() && !opt.surfacer)
    throw std::invalid_argument("teacher_forced: reference patches need a surfacer to mesh them");
  if (!(opt.patch_junction >= 0))
    throw std::invalid_argument("teacher_forced: patch_junction must be >= 0 (metres)");
  if (!(opt.snap_tolerance >= 0)) throw std::invalid_argument("teacher_forced: snap tolerance must be >= 0");
  std::map<StrokeId, Curve> reference;
  for (const Event& e : rec.events)
    if (const auto* r = std::get_if<ReferenceEvent>(&e.payload))
      if (r->track == opt.track && !reference.count(r->stroke)) reference[r->stroke] = r->curve;
  // Nothing to compare with: zeros would read as a result.
  if (reference.empty()) {
    const auto tracks = reference_tracks(rec);
    std::string have;
    for (const auto& t : tracks) have += (have.empty() ? "" : ", ") + t;
    throw std::invalid_argument("no reference curves on track '" + opt.track + "'; " +
                                (tracks.empty() ? std::string("the recording has no reference tracks (its "
                                                              "strokes were recorded without a reference)")
                                                : "the recording has: " + have));
  }

  Sketch sketch;
  sketch.workspace = rec.header.workspace;
  std::vector<Pending> pending;
  std::map<StrokeId, CurveId> curve_of;
  std::vector<TeacherForcedStroke> out;
  // Reference patches not made yet (by creation time) and those in the
  // sketch (reference id -> ours).
  std::vector<const ReferencePatch*> waiting;
  for (const ReferencePatch& p : opt.patches) waiting.push_back(&p);
  std::stable_sort(waiting.begin(), waiting.end(),
                   [](const ReferencePatch* a, const ReferencePatch* b) { return a->created < b->created; });
  std::map<const ReferencePatch*, PatchId> made;
  std::map<StrokeId, double> deleted;  // stroke -> deletion time
  auto warn = [&](const ReferencePatch& p, const std::string& why) {
    if (warnings) warnings->push_back("patch " + std::to_string(p.id) + ": " + why);
  };
  auto remove_patch = [&](PatchId id) {
    Edit del;
    del.patches_removed.push_back(id);
    sketch.network.apply(del);
  };
  auto flush = [&](double before) {
    std::vector<Pending> keep;
    for (const Pending& p : pending) {
      if (p.time < before) add_reference(sketch, p, curve_of);
      else keep.push_back(p);
    }
    pending = std::move(keep);
    for (auto it = made.begin(); it != made.end();) {
      if (it->first->deleted && *it->first->deleted < before) {
        remove_patch(it->second);
        it = made.erase(it);
      } else {
        ++it;
      }
    }
    std::erase_if(waiting, [&](const ReferencePatch* p) {
      if (!(p->created < before)) return false;
      if (p->deleted && *p->deleted < before) return true;  // made and deleted between two strokes
      std::set<CurveId> curves;
      for (StrokeId s : p->strokes) {
        if (const auto d = deleted.find(s); d != deleted.end()) {  // gone with it (item 27), or never had it
          if (d->second <= p->created) warn(*p, "stroke " + std::to_string(s) + " was deleted before it");
          return true;
        }
        const auto c = curve_of.find(s);
        if (c == curve_of.end()) {
          if (!reference.count(s)) return warn(*p, "stroke " + std::to_string(s) + " has no reference curve"), true;
          return false;  // its stroke's curve is still to come
        }
        curves.insert(c->second);
      }
      std::string why;
      auto patch = mesh_reference_patch(sketch, curves, opt.patch_junction, *opt.surfacer, why);
      if (!patch) return warn(*p, why), true;
      patch->id = sketch.network.next_patch_id();
      patch->automatic = p->automatic;
      Edit add;
      add.patches_added.push_back(std::move(*patch));
      sketch.network.apply(add);
      made[p] = add.patches_added.front().id;
      return true;
    });
  };
  for (const Event& e : rec.events) {
    if (const auto* w = std::get_if<WorkspaceEvent>(&e.payload)) {
      sketch.workspace = w->workspace;
    } else if (const auto* d = std::get_if<DeleteStrokeEvent>(&e.payload)) {
      std::erase_if(pending, [&](const Pending& p) { return p.stroke == d->stroke; });
      deleted.emplace(d->stroke, e.time);
      // A patch goes with any of its strokes (CASSIE app, item 27), also one
      // whose curve the surfacer's cycle did not use.
      std::erase_if(made, [&](const auto& m) {
        const auto& st = m.first->strokes;
        if (std::find(st.begin(), st.end(), d->stroke) == st.end()) return false;
        if (sketch.network.patches().count(m.second)) remove_patch(m.second);
        return true;
      });
      if (auto it = curve_of.find(d->stroke); it != curve_of.end()) {
        Edit del;
        del.curves_removed.push_back(it->second);
        sketch.network.apply(del);
        curve_of.erase(it);
      }
    } else if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) {
      const Stroke& stroke = s->stroke;
      flush(e.time);
      TeacherForcedStroke r;
      r.stroke = stroke.id;
      r.time = e.time;
      const auto ref = reference.find(stroke.id);
      if (auto why = validate(stroke); !why.empty()) {
        r.error = why;
      } else {
        sketch.workspace.scale = stroke.workspace_scale;
        r.patches = static_cast<int>(sketch.network.patches().size());
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = thread_cpu_ms();
        const Correction c = corrector.correct(stroke, sketch);
        r.cpu_ms = thread_cpu_ms() - cpu_start;
        r.corrected = true;
        r.latency_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        r.stats = c.stats;
        r.constraints_considered = static_cast<int>(c.constraints.size());
        for (const Constraint& k : c.constraints) r.constraints_enforced += k.enforced;
        const NetworkCurve* out_curve = nullptr;
        for (const NetworkCurve& nc : c.edit.curves_added)
          if (nc.source_stroke == stroke.id) {
            out_curve = &nc;
            break;
          }
        if (!c.error.empty()) r.error = c.error;
        else if (!out_curve) r.error = "corrector produced no curve";
        else if (ref == reference.end()) r.error = "no reference curve on track " + opt.track;
        if (r.error.empty()) {
          r.compared = true;
          r.reference_curve = ref->second;
          r.output_curve = out_curve->curve;
          r.constraints = c.constraints;
          r.reference_line = ref->second.kind == CurveKind::line;
          r.output_line = out_curve->curve.kind == CurveKind::line;
          compare(ref->second, out_curve->curve, opt.resample, r);
          if (!stroke.samples_are_pixels) {
            const std::vector<Vec3> samples = positions(stroke);
            r.output_stroke_distance = hausdorff_distance(out_curve->curve, samples).max();
            r.reference_stroke_distance = hausdorff_distance(ref->second, samples).max();
          }
          for (int k = 0; k < 2; ++k) {
            const Vec3 pr = k == 0 ? ref->second.control_points.front() : ref->second.control_points.back();
            r.reference_snap[k] = snap_kind(sketch, pr, opt.snap_tolerance);
          }
          // Match the output's ends to the reference's (same orientation as compare).
          const Vec3 o0 = out_curve->curve.control_points.front(), o1 = out_curve->curve.control_points.back();
          const Vec3 r0 = ref->second.control_points.front(), r1 = ref->second.control_points.back();
          const bool rev = std::max((r0 - o1).norm(), (r1 - o0).norm()) <
                           std::max((r0 - o0).norm(), (r1 - o1).norm());
          r.output_snap[0] = snap_kind(sketch, rev ? o1 : o0, opt.snap_tolerance);
          r.output_snap[1] = snap_kind(sketch, rev ? o0 : o1, opt.snap_tolerance);
          r.reversed = rev;
          r.reference_end = {r0, r1};
          r.output_end = {rev ? o1 : o0, rev ? o0 : o1};
          r.reference_closed = is_closed(ref->second);
          r.output_closed = is_closed(out_curve->curve);
          for (int k = 0; k < 2; ++k) nearest_candidate(c.constraints, r.reference_end[k], r, k);
        }
      }
      out.push_back(r);
      if (ref != reference.end()) pending.push_back({stroke.id, stroke.layer, e.time, ref->second});
    }
  }
  return out;
}

TeacherForcedSummary summarize(const std::vector<TeacherForcedStroke>& strokes) {
  TeacherForcedSummary s;
  s.strokes = strokes.size();
  std::vector<double> ep, mean, mx, out_stroke, ref_stroke, lat, cpu;
  for (const auto& r : strokes) {
    if (!r.error.empty()) ++s.errors;
    if (r.corrected) {
      lat.push_back(r.latency_ms);
      cpu.push_back(r.cpu_ms);
    }
    if (!r.compared) continue;
    ++s.compared;
    ep.push_back(r.endpoint_distance);
    mean.push_back(r.mean_deviation);
    mx.push_back(r.max_deviation);
    if (r.output_stroke_distance) out_stroke.push_back(*r.output_stroke_distance);
    if (r.reference_stroke_distance) ref_stroke.push_back(*r.reference_stroke_distance);
    s.line_agreements += r.reference_line == r.output_line;
    for (int k = 0; k < 2; ++k) {
      const bool a = !r.reference_snap[k].empty(), b = !r.output_snap[k].empty();
      ++s.endpoints;
      s.snap_agreements += a == b;
      s.snap_kind_agreements += r.reference_snap[k] == r.output_snap[k];
      s.reference_snaps += a;
      s.output_snaps += b;
      s.both_snaps += a && b;
    }
  }
  s.endpoint_distance = distribution(ep);
  s.mean_deviation = distribution(mean);
  s.max_deviation = distribution(mx);
  s.output_stroke_distance = distribution(out_stroke);
  s.reference_stroke_distance = distribution(ref_stroke);
  s.latency_ms = distribution(lat);
  s.cpu_ms = distribution(cpu);
  return s;
}

std::string fidelity_group(const RecordingHeader& header) {
  const auto field = [&](const char* k) {
    const auto it = header.source.find(k);
    return it == header.source.end() ? std::string() : it->second;
  };
  if (field("interaction_mode") == "free creation") return "showcase";
  std::string system = field("system");
  if (system.empty()) return "other";
  system[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(system[0])));
  return system;
}

namespace {

// An empty cell for a value that was not measured.
std::string optional_cell(const std::optional<double>& v) {
  if (!v) return "";
  std::ostringstream o;
  o.precision(9);
  o << *v;
  return o.str();
}

}  // namespace

std::string teacher_forced_csv(const std::vector<TeacherForcedStroke>& strokes) {
  std::ostringstream o;
  o.precision(9);
  o << "stroke,time,compared,reference_kind,output_kind,endpoint_distance,mean_deviation,"
       "max_deviation,reference_snap0,reference_snap1,output_snap0,output_snap1,"
       "constraints_considered,constraints_enforced,subsets_tried,latency_ms,cpu_ms,output_stroke_distance,"
       "reference_stroke_distance,error\n";
  for (const auto& r : strokes) {
    std::string err = r.error;
    std::replace(err.begin(), err.end(), ',', ';');
    std::replace(err.begin(), err.end(), '\n', ' ');
    o << r.stroke << ',' << r.time << ',' << r.compared << ',' << (r.reference_line ? "line" : "bezier")
      << ',' << (r.output_line ? "line" : "bezier") << ',' << r.endpoint_distance << ','
      << r.mean_deviation << ',' << r.max_deviation << ',' << r.reference_snap[0] << ','
      << r.reference_snap[1] << ',' << r.output_snap[0] << ',' << r.output_snap[1] << ','
      << r.constraints_considered << ',' << r.constraints_enforced << ',' << r.stats.subsets_tried
      << ',' << r.latency_ms << ',' << r.cpu_ms << ',' << optional_cell(r.output_stroke_distance) << ','
      << optional_cell(r.reference_stroke_distance) << ',' << err << '\n';
  }
  return o.str();
}

}  // namespace sketchlab
