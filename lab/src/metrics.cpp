#include "sketchlab/lab/metrics.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <set>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/bounding_box.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/geometry/hausdorff.hpp"
#include "sketchlab/lab/distribution.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab {
namespace {

const Curve* first_curve(const Network& net, const Sketch& sketch, StrokeId stroke) {
  const auto ids = curves_of_stroke(sketch, stroke);
  return ids.empty() ? nullptr : &net.find_curve(ids.front())->curve;
}

bool is_straight(const Curve& c) {
  if (c.kind == CurveKind::line) return true;
  const double len = arclength(c);
  return len > 0 && (c.control_points.back() - c.control_points.front()).norm() > 0.999 * len;
}

Vec3 chord(const Curve& c) { return c.control_points.back() - c.control_points.front(); }

// Mean distance of arclength-resampled points, in the better orientation.
double resampled_deviation(const Curve& a, const Curve& b, int n) {
  const auto pa = sample_by_arclength(a, n), pb = sample_by_arclength(b, n);
  double fwd = 0, bwd = 0;
  for (int i = 0; i < n; ++i) {
    fwd += (pa[i] - pb[i]).norm();
    bwd += (pa[i] - pb[n - 1 - i]).norm();
  }
  return std::min(fwd, bwd) / n;
}

double endpoint_deviation(const Curve& a, const Curve& b) {
  const Vec3 a0 = a.control_points.front(), a1 = a.control_points.back();
  const Vec3 b0 = b.control_points.front(), b1 = b.control_points.back();
  return std::min((a0 - b0).norm() + (a1 - b1).norm(), (a0 - b1).norm() + (a1 - b0).norm()) / 2;
}

// Smallest distance between two curves, and where it is on each.
struct Touch {
  double distance;
  double ta, tb;
};
Touch touch(const Curve& a, const Curve& b) {
  // 5 mm, but at most 2,001 points: curves in pixel units (2D strokes fitted
  // without a draw plane) would otherwise take minutes.
  const auto pa = sample_with_spacing(a, 0.005, 2001);
  const ClosestPoint onb = closest_point_to_polyline(b, pa);
  const ClosestPoint ona = closest_point(a, onb.point);
  return {ona.distance, ona.t, onb.t};
}

bool at_end(const Curve& c, double t) {
  return c.closed ? false : (t < 1e-6 || t > c.t_max() - 1e-6);
}

double plane_error(const Curve& c, int n) {
  const auto pts = sample_by_arclength(c, n);
  Vec3 mean = Vec3::Zero();
  for (const auto& p : pts) mean += p;
  mean /= n;
  Mat3 cov = Mat3::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);
  const Vec3 normal = eig.eigenvectors().col(0);
  double err = 0;
  for (const auto& p : pts) err = std::max(err, std::abs(normal.dot(p - mean)));
  return err;
}

void latency_metrics(const ReplayResult& r, CaseMetrics& m) {
  std::vector<double> latency;
  int refused = 0;
  for (const auto& s : r.steps) {
    refused += !s.error.empty();
    if (s.event == EventKind::stroke && s.corrected && s.error.empty()) latency.push_back(s.latency_ms);
  }
  m.values["events_refused"] = refused;
  if (latency.empty()) return;
  const Distribution d = distribution(std::move(latency));
  m.values["latency_p50_ms"] = d.median;
  m.values["latency_p95_ms"] = d.p95;
  m.values["latency_max_ms"] = d.max;
}

void network_metrics(const Sketch& sketch, CaseMetrics& m) {
  const Network& net = sketch.network;
  m.values["strokes"] = static_cast<double>(strokes_with_curves(sketch).size());
  m.values["curves"] = static_cast<double>(net.curves().size());
  m.values["nodes"] = static_cast<double>(net.nodes().size());
  m.values["patches"] = static_cast<double>(net.patches().size());

  // Dangling endpoints: open curve ends with no node incidence there.
  std::map<CurveId, std::vector<double>> node_params;
  for (const auto& [id, n] : net.nodes())
    for (const auto& i : n.incidences) node_params[i.curve].push_back(i.t);
  std::size_t dangling = 0;
  for (const auto& [id, c] : net.curves()) {
    if (c.curve.closed) continue;
    for (double end : {0.0, c.curve.t_max()}) {
      const auto& ts = node_params[id];
      dangling += std::none_of(ts.begin(), ts.end(), [&](double t) { return std::abs(t - end) < 1e-6; });
    }
  }
  const std::size_t total = dangling + net.nodes().size();
  if (total) m.values["dangling_endpoint_ratio"] = double(dangling) / double(total);
}

// The cubic pieces of a stroke's curves with their boxes, for the exact
// distance from every sample: a piece whose box is farther than the best
// distance so far cannot be closer, so a sample costs one box test per piece
// and a closest-point search on the few near it, instead of a search on every
// piece (a 10^5-sample stroke fitted with 10^3 pieces took minutes; issue 17).
class Pieces {
 public:
  void add(const Curve& c) {
    for (int k = 0; k < c.segment_count(); ++k) {
      Curve piece;
      const auto p = segment_points(c, k);
      piece.control_points.assign(p.begin(), p.end());
      piece.sharp = {false, false};
      pieces_.push_back({std::move(piece), bounding_box(c, k, k + 1)});
    }
  }
  bool empty() const { return pieces_.empty(); }
  // `hint`: the nearest piece of the previous sample (consecutive samples
  // are near each other, so it bounds the search well from the start).
  double distance(const Vec3& p, std::size_t& hint) const {
    double best = closest_point(pieces_[hint].curve, p).distance;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
      if (i == hint || pieces_[i].box.exteriorDistance(p) >= best) continue;
      const double d = closest_point(pieces_[i].curve, p).distance;
      if (d < best) {
        best = d;
        hint = i;
      }
    }
    return best;
  }

 private:
  struct Piece {
    Curve curve;
    Box3 box;
  };
  std::vector<Piece> pieces_;
};

void input_deviation(const Sketch& sketch, CaseMetrics& m) {
  double sum = 0, max = 0;
  std::size_t count = 0;
  for (StrokeId s : strokes_with_curves(sketch)) {
    const Stroke& stroke = sketch.strokes.at(s);
    if (stroke.samples_are_pixels) continue;
    Pieces pieces;
    for (CurveId id : curves_of_stroke(sketch, s)) pieces.add(sketch.network.find_curve(id)->curve);
    if (pieces.empty()) continue;
    std::size_t hint = 0;
    for (const auto& sample : stroke.samples) {
      const double d = pieces.distance(sample.position, hint);
      sum += d;
      max = std::max(max, d);
      ++count;
    }
  }
  if (!count) return;
  m.values["input_deviation_mean_m"] = sum / double(count);
  m.values["input_deviation_max_m"] = max;
}

// Two-sided distance of each live 3D stroke to its curve: the curve it made
// (the closest of its curves; a mirrored copy is farther), both ways.
void input_hausdorff(const Sketch& sketch, CaseMetrics& m) {
  double sum = 0, max = 0;
  std::size_t count = 0;
  for (StrokeId s : strokes_with_curves(sketch)) {
    const Stroke& stroke = sketch.strokes.at(s);
    if (stroke.samples_are_pixels || stroke.samples.empty()) continue;
    std::vector<Vec3> polyline;
    for (const auto& sample : stroke.samples) polyline.push_back(sample.position);
    double d = std::numeric_limits<double>::infinity();
    for (CurveId id : curves_of_stroke(sketch, s))
      d = std::min(d, hausdorff_distance(sketch.network.find_curve(id)->curve, polyline).max());
    if (!std::isfinite(d)) continue;
    sum += d;
    max = std::max(max, d);
    ++count;
  }
  if (!count) return;
  m.values["input_hausdorff_mean_m"] = sum / double(count);
  m.values["input_hausdorff_max_m"] = max;
}

void enforced_residuals(const ReplayResult& r, CaseMetrics& m) {
  std::map<std::string, std::pair<double, int>> acc;
  for (const auto& s : r.steps)
    for (const auto& c : s.constraints)
      if (c.enforced) {
        auto& a = acc[std::string(to_string(c.kind))];
        a.first += c.residual;
        ++a.second;
      }
  for (const auto& [kind, a] : acc) m.values["enforced_" + kind + "_residual_mean"] = a.first / a.second;
}

// A curve end "snaps" when another curve of the same set passes within tol.
bool end_snapped(const Network& net, CurveId self_stroke_curve, StrokeId self, const Vec3& p, double tol) {
  for (const auto& hit : net.curves_near(p, tol))
    if (hit.curve != self_stroke_curve && net.find_curve(hit.curve)->source_stroke != self) return true;
  return false;
}

void reference_metrics(const ReplayResult& r, const MetricsOptions& o, CaseMetrics& m) {
  const Sketch& sketch = r.session.sketch();
  for (const auto& [track, curves] : r.session.references()) {
    if (track == "ground_truth") continue;
    // The reference curves of the strokes alive in the output, as a network
    // so that snap tests use the same spatial queries on both sides.
    Network ref;
    Edit add;
    std::map<StrokeId, CurveId> ref_id;
    for (StrokeId s : strokes_with_curves(sketch)) {
      auto it = curves.find(s);
      if (it == curves.end()) continue;
      const CurveId id = ref.next_curve_id() + add.curves_added.size();
      ref_id[s] = id;
      add.curves_added.push_back(make_network_curve(id, it->second, Layer::free, s));
    }
    ref.apply(add);
    double endpoint = 0, control = 0;
    std::size_t compared = 0, agree = 0;
    for (const auto& [s, rid] : ref_id) {
      const auto ids = curves_of_stroke(sketch, s);
      if (ids.empty()) continue;
      const Curve& ours = sketch.network.find_curve(ids.front())->curve;
      const Curve& theirs = ref.find_curve(rid)->curve;
      endpoint += endpoint_deviation(ours, theirs);
      control += resampled_deviation(ours, theirs, o.resample);
      ++compared;
      const bool flip = (ours.control_points.front() - theirs.control_points.front()).norm() >
                        (ours.control_points.front() - theirs.control_points.back()).norm();
      for (int e = 0; e < 2; ++e) {
        const Vec3& po = e ? ours.control_points.back() : ours.control_points.front();
        const Vec3& pr = (e != flip) ? theirs.control_points.back() : theirs.control_points.front();
        agree += end_snapped(sketch.network, ids.front(), s, po, o.distance_tolerance) ==
                 end_snapped(ref, rid, s, pr, o.distance_tolerance);
      }
    }
    if (!compared) continue;
    const std::string p = "ref_" + track + "_";
    m.values[p + "compared"] = double(compared);
    m.values[p + "endpoint_mean_m"] = endpoint / double(compared);
    m.values[p + "control_mean_m"] = control / double(compared);
    m.values[p + "snap_agreement"] = double(agree) / double(2 * compared);
  }
}

// The camera eye shared by every stroke in `strokes`, when they are all 2D
// strokes (pixels of a View) seen from one eye position; else none.
std::optional<Vec3> single_eye(const Sketch& sketch, const std::vector<StrokeId>& strokes) {
  std::optional<Vec3> eye;
  for (StrokeId s : strokes) {
    const Stroke& stroke = sketch.strokes.at(s);
    if (!stroke.samples_are_pixels || !stroke.view) return std::nullopt;
    const Vec3 e = eye_position(*stroke.view);
    if (!e.allFinite()) return std::nullopt;
    if (!eye) eye = e;
    else if ((e - *eye).norm() > 1e-9 * std::max(1.0, eye->norm())) return std::nullopt;
  }
  return eye;
}

// Distance to the ground truth after the alignment one view cannot fix: a
// perspective image is unchanged when the scene is scaled about the eye, so
// from a single view 3D is determined only up to that scale (Schmidt et al.
// 2009 §2 fix it by putting the first stroke in the ground plane; JustDrawIt
// §2 by creating curves on the view plane centred at the origin). The scale s minimising the
// squared distances of e + s(p − e) to the intended curves is found by
// alternating closest points and the closed-form s = Σ(p−e)·(q−e) / Σ|p−e|²
// (an ICP restricted to this one-parameter group), started from the ratio of
// the mean distances to the eye. Returns the eye and the scale when they
// were written.
struct EyeScale {
  Vec3 eye;
  double scale;
};
std::optional<EyeScale> eye_scale_aligned_distance(const Sketch& sketch, const std::map<StrokeId, Curve>& truth,
                                                   const std::vector<StrokeId>& strokes, const MetricsOptions& o,
                                                   CaseMetrics& m) {
  // Every stroke of the session, not only those whose curve is kept: a curve
  // taken over by an oversketch from a second view (JustDrawIt §4.4) keeps
  // that view's stroke only, yet the first view still fixed the scale.
  std::vector<StrokeId> drawn;
  for (const auto& [id, stroke] : sketch.strokes) drawn.push_back(id);
  const auto eye = single_eye(sketch, drawn);
  if (!eye || strokes.empty()) return std::nullopt;
  std::vector<std::pair<Vec3, const Curve*>> points;  // output sample - eye, its intended curve
  double ours_range = 0, truth_range = 0;
  for (StrokeId s : strokes) {
    const Curve& gt = truth.at(s);
    for (const Vec3& p : sample_by_arclength(*first_curve(sketch.network, sketch, s), o.resample)) {
      points.push_back({p - *eye, &gt});
      ours_range += (p - *eye).norm();
    }
    for (const Vec3& q : sample_by_arclength(gt, o.resample)) truth_range += (q - *eye).norm();
  }
  if (!(ours_range > 0) || !std::isfinite(ours_range)) return std::nullopt;
  double scale = truth_range / ours_range;
  for (int iteration = 0; iteration < 50; ++iteration) {
    double num = 0, den = 0;
    for (const auto& [d, gt] : points) {
      const Vec3 q = closest_point(*gt, *eye + scale * d).point - *eye;
      num += d.dot(q);
      den += d.squaredNorm();
    }
    const double next = num / den;
    const bool converged = std::abs(next - scale) <= 1e-12 * std::abs(scale);
    scale = next;
    if (converged) break;
  }
  double sum = 0, max = 0;
  for (const auto& [d, gt] : points) {
    const double dist = closest_point(*gt, *eye + scale * d).distance;
    sum += dist;
    max = std::max(max, dist);
  }
  m.values["gt_distance_mean_aligned_eye_scale_m"] = sum / double(points.size());
  m.values["gt_distance_max_aligned_eye_scale_m"] = max;
  m.values["gt_eye_scale"] = scale;
  return EyeScale{*eye, scale};
}

// The output against the intended shape as a whole (a Chamfer pair), for
// correctors that build one curve from several strokes: JustDrawIt extends a
// curve with a stroke that continues it (§4.2), so one curve may cover two
// intended curves drawn in line, and gt_distance_mean_m scores it against its
// last stroke's only. Accuracy: each output sample to the nearest intended
// curve of any live stroke; coverage: each intended sample to the nearest
// output curve, so that a missing or short curve still counts. With
// `aligned`, the output scaled about the eye first (as the eye-scaled
// distance), a Bézier curve being scaled with its control points.
void ground_truth_shape_metrics(const Sketch& sketch, const std::map<StrokeId, Curve>& truth,
                                const MetricsOptions& o, const std::optional<EyeScale>& aligned, CaseMetrics& m) {
  std::vector<const Curve*> intended, output;
  std::vector<Curve> scaled;
  for (StrokeId s : live_strokes(sketch))
    if (auto it = truth.find(s); it != truth.end()) intended.push_back(&it->second);
  for (const auto& [id, c] : sketch.network.curves())
    if (truth.count(c.source_stroke)) {
      if (!aligned) {
        output.push_back(&c.curve);
        continue;
      }
      Curve& copy = scaled.emplace_back(c.curve);
      for (Vec3& p : copy.control_points) p = aligned->eye + aligned->scale * (p - aligned->eye);
    }
  for (const Curve& c : scaled) output.push_back(&c);
  if (intended.empty() || output.empty()) return;
  const auto mean_distance = [&](const std::vector<const Curve*>& from, const std::vector<const Curve*>& to) {
    double sum = 0;
    std::size_t count = 0;
    for (const Curve* c : from)
      for (const Vec3& p : sample_by_arclength(*c, o.resample)) {
        double d = std::numeric_limits<double>::infinity();
        for (const Curve* t : to) d = std::min(d, closest_point(*t, p).distance);
        sum += d;
        ++count;
      }
    return count ? sum / double(count) : 0.0;
  };
  const std::string unit = aligned ? "_aligned_eye_scale_m" : "_m";
  m.values["gt_shape_distance_mean" + unit] = mean_distance(output, intended);
  m.values["gt_shape_coverage_mean" + unit] = mean_distance(intended, output);
}

void ground_truth_metrics(const ReplayResult& r, const MetricsOptions& o, CaseMetrics& m) {
  const Sketch& sketch = r.session.sketch();
  const Network& net = sketch.network;
  const auto refs = r.session.references().find("ground_truth");
  if (refs == r.session.references().end()) return;

  double sum = 0, max = 0;
  std::size_t count = 0;
  std::vector<StrokeId> strokes;
  for (StrokeId s : strokes_with_curves(sketch)) {
    const Curve* ours = first_curve(net, sketch, s);
    auto gt = refs->second.find(s);
    if (!ours || gt == refs->second.end()) continue;
    strokes.push_back(s);
    for (const Vec3& p : sample_by_arclength(*ours, o.resample)) {
      const double d = closest_point(gt->second, p).distance;
      sum += d;
      max = std::max(max, d);
      ++count;
    }
  }
  if (count) {
    m.values["gt_distance_mean_m"] = sum / double(count);
    m.values["gt_distance_max_m"] = max;
  }
  const auto aligned = eye_scale_aligned_distance(sketch, refs->second, strokes, o, m);
  ground_truth_shape_metrics(sketch, refs->second, o, std::nullopt, m);
  if (aligned) ground_truth_shape_metrics(sketch, refs->second, o, aligned, m);

  // Relations: intended ones from the track, detected ones measured on the
  // output over every pair (or single stroke for planarity).
  using Key = std::pair<StrokeId, StrokeId>;
  std::map<std::string, std::set<Key>> intended, detected;
  const std::set<StrokeId> alive(strokes.begin(), strokes.end());
  // A stroke whose curve a later stroke took over (a curve drawn in several
  // strokes or oversketched, JustDrawIt §1 and §4.4, keeps one curve for the
  // last stroke) stands for the same intended curve as the live stroke with
  // its ground truth: its relations are scored on that stroke.
  const auto live_stroke_for = [&](StrokeId s) -> std::optional<StrokeId> {
    if (alive.count(s)) return s;
    const auto gt = refs->second.find(s);
    if (gt == refs->second.end()) return std::nullopt;
    for (StrokeId live : strokes)
      if (refs->second.at(live) == gt->second) return live;
    return std::nullopt;
  };
  auto rel = r.session.relations().find("ground_truth");
  if (rel != r.session.relations().end())
    for (const auto& e : rel->second) {
      if (e.strokes.empty()) continue;
      const auto a = live_stroke_for(e.strokes.front());
      const auto b = e.strokes.size() > 1 ? live_stroke_for(e.strokes[1]) : a;
      if (!a || !b || (e.strokes.size() > 1 && *a == *b)) continue;
      intended[std::string(to_string(e.kind))].insert({std::min(*a, *b), std::max(*a, *b)});
    }
  // Distances are judged at the scale of the intended shape: where one view
  // leaves the scale open (eye-scaled alignment above), the output's
  // distances count multiplied by that scale, so a scene recovered twice as
  // large is not held to half the tolerance. Angles need no alignment.
  const double tolerance = aligned && aligned->scale > 0 ? o.distance_tolerance / aligned->scale
                                                         : o.distance_tolerance;
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const Curve& a = *first_curve(net, sketch, strokes[i]);
    if (!is_straight(a) && plane_error(a, o.resample) < tolerance)
      detected["planar"].insert({strokes[i], strokes[i]});
    for (std::size_t j = i + 1; j < strokes.size(); ++j) {
      const Curve& b = *first_curve(net, sketch, strokes[j]);
      const Key key{strokes[i], strokes[j]};
      const Box3 ba = bounding_box(a), bb = bounding_box(b);
      bool touching = false;
      if (ba.exteriorDistance(bb) <= tolerance) {
        const Touch t = touch(a, b);
        touching = t.distance <= tolerance;
        if (touching)
          detected[at_end(a, t.ta) && at_end(b, t.tb) ? "coincident_point" : "intersection"].insert(key);
      }
      if (is_straight(a) && is_straight(b)) {
        const double la = chord(a).norm(), lb = chord(b).norm();
        const double cosang = std::clamp(std::abs(chord(a).dot(chord(b))) / (la * lb), 0.0, 1.0);
        const double angle = std::acos(cosang);
        if (angle < o.angle_tolerance) detected["parallel"].insert(key);
        if (touching && std::abs(angle - std::acos(0.0)) < o.angle_tolerance)
          detected["perpendicular"].insert(key);
        if (std::abs(la - lb) < o.length_tolerance * std::max(la, lb)) detected["equal_length"].insert(key);
      }
    }
  }
  // Parallelism and equal length are equivalence relations: ground truth may
  // list a spanning set (each line to the first of its class); compare the
  // closures.
  for (const char* kind : {"parallel", "equal_length"}) {
    auto it = intended.find(kind);
    if (it == intended.end()) continue;
    std::map<StrokeId, StrokeId> parent;
    const std::function<StrokeId(StrokeId)> find = [&](StrokeId x) {
      auto p = parent.try_emplace(x, x).first;
      return p->second == x ? x : p->second = find(p->second);
    };
    for (const auto& [a, b] : it->second) parent[find(a)] = find(b);
    std::map<StrokeId, std::vector<StrokeId>> classes;
    for (const auto& [x, p] : parent) classes[find(x)].push_back(x);
    for (const auto& [root, members] : classes)
      for (std::size_t i = 0; i < members.size(); ++i)
        for (std::size_t j = i + 1; j < members.size(); ++j)
          it->second.insert({std::min(members[i], members[j]), std::max(members[i], members[j])});
  }
  for (const auto& [kind, want] : intended) {
    PrecisionRecall pr;
    const auto& got = detected[kind];
    pr.intended = want.size();
    pr.detected = got.size();
    for (const auto& k : got) pr.matched += want.count(k);
    m.relations[kind] = pr;
    if (pr.detected) m.values["gt_" + kind + "_precision"] = pr.precision();
    m.values["gt_" + kind + "_recall"] = pr.recall();
  }
}

}  // namespace

CaseMetrics compute_metrics(const ReplayResult& result, const MetricsOptions& options) {
  CaseMetrics m;
  const Sketch& sketch = result.session.sketch();
  latency_metrics(result, m);
  network_metrics(sketch, m);
  input_deviation(sketch, m);
  input_hausdorff(sketch, m);
  enforced_residuals(result, m);
  reference_metrics(result, options, m);
  ground_truth_metrics(result, options, m);
  return m;
}

}  // namespace sketchlab
