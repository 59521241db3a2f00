#include "curve_inference.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "curve_fit.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::analytic {

namespace {

double gauss(double d, double sigma) { return std::exp(-(d * d) / (sigma * sigma)); }

void add_direction(CurvePoint& cp, const Vec3& d, int line) {
  for (const Vec3& e : cp.directions)
    if (std::abs(e.dot(d)) > 1.0 - 1e-9) return;
  cp.directions.push_back(d);
  cp.lines.push_back(line);
}

Vec2 point_at(const std::vector<Vec2>& poly, double s) {
  double acc = 0.0;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const double l = (poly[i + 1] - poly[i]).norm();
    if (acc + l >= s && l > 0) return poly[i] + (poly[i + 1] - poly[i]) * ((s - acc) / l);
    acc += l;
  }
  return poly.back();
}

struct Geometry {
  bool planar = false;
  Vec3 normal = Vec3::UnitZ();
};

// Plane of the points and constrained tangents (§3.2: planarity is enforced
// when every constraint is coplanar).
Geometry plane_of(const std::vector<Vec3>& pts, const std::vector<std::optional<Vec3>>& dirs,
                  double tol) {
  Geometry g;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : pts) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> es(cov);
  const Vec3 ev = es.eigenvalues();
  Vec3 n;
  if (ev[1] > tol * tol) {
    n = es.eigenvectors().col(0);
  } else {
    const Vec3 chord = (pts.back() - pts.front()).normalized();
    bool found = false;
    for (const auto& d : dirs)
      if (d && chord.cross(*d).norm() > 1e-6) {
        n = chord.cross(*d).normalized();
        found = true;
        break;
      }
    if (!found) return g;
  }
  for (const Vec3& p : pts)
    if (std::abs(n.dot(p - mean)) > tol) return g;
  for (const auto& d : dirs)
    if (d && std::abs(n.dot(*d)) > 1e-6) return g;
  g.planar = true;
  g.normal = n;
  return g;
}

bool points_symmetric(const std::vector<Vec3>& pts, double tol) {
  const Vec3 a = pts.front(), b = pts.back();
  const Vec3 n = (b - a).normalized();
  const Vec3 mid = 0.5 * (a + b);
  const std::size_t m = pts.size();
  for (std::size_t j = 0; j < m; ++j) {
    const Vec3 r = pts[j] - 2.0 * n.dot(pts[j] - mid) * n;
    if ((r - pts[m - 1 - j]).norm() > tol) return false;
  }
  return true;
}

bool tangents_symmetric(const std::vector<Vec3>& pts, const std::vector<std::optional<Vec3>>& dirs) {
  const Vec3 n = (pts.back() - pts.front()).normalized();
  const Mat3 R = Mat3::Identity() - 2.0 * n * n.transpose();
  const std::size_t m = pts.size();
  for (std::size_t j = 0; j < m; ++j) {
    const auto& a = dirs[j];
    const auto& b = dirs[m - 1 - j];
    if (a.has_value() != b.has_value()) return false;
    if (a && (R * *a).cross(*b).norm() > 1e-6) return false;
    if (a && j == m - 1 - j && a->cross(n).norm() > 1e-6) return false;
  }
  return true;
}

}  // namespace

std::vector<CurvePoint> collect_curve_points(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                                             const AnalyticParams& p) {
  struct Found {
    CurvePoint cp;
    double score;  // distance / radius
  };
  std::vector<Found> found;
  auto consider = [&](const Vec3& x, const std::vector<int>& lines) {
    const auto q = cam.project(x);
    if (!q) return;
    const PolylineHit h = nearest_on_polyline(stroke.points, *q);
    const double r = p.k_r * stroke.delta[static_cast<std::size_t>(h.index)];
    if (h.distance > r) return;
    for (Found& f : found)
      if ((f.cp.p - x).norm() <= 10 * s.tolerance) {
        for (int l : lines) add_direction(f.cp, s.lines[static_cast<std::size_t>(l)].direction(), l);
        return;
      }
    Found f;
    f.cp.p = x;
    f.cp.arclength = h.arclength;
    for (int l : lines) add_direction(f.cp, s.lines[static_cast<std::size_t>(l)].direction(), l);
    f.score = h.distance / r;
    found.push_back(f);
  };
  for (const ScaffoldVertex& v : s.vertices) consider(v.p, v.lines);
  for (std::size_t i = 0; i < s.lines.size(); ++i)
    for (std::size_t j = i + 1; j < s.lines.size(); ++j) {
      const ScaffoldLine& a = s.lines[i];
      const ScaffoldLine& b = s.lines[j];
      if (const std::optional<Vec3> x = scaffold_crossing(s, a, b))
        consider(*x, {static_cast<int>(i), static_cast<int>(j)});
    }
  if (static_cast<int>(found.size()) > p.max_curve_points) {
    std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.score < b.score; });
    found.resize(static_cast<std::size_t>(p.max_curve_points));
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const Found& a, const Found& b) { return a.cp.arclength < b.cp.arclength; });
  std::vector<CurvePoint> out;
  for (Found& f : found) out.push_back(std::move(f.cp));
  return out;
}

double curve_stroke_score(const Curve& curve, const Camera& cam, const Stroke2d& stroke, const AnalyticParams& p) {
  const int n = std::max(2, p.score_samples);
  double sum = 0.0;
  for (int j = 0; j < n; ++j) {
    const double t = curve.t_max() * j / (n - 1);
    const auto q = cam.project(evaluate(curve, t));
    if (!q) continue;
    const PolylineHit h = nearest_on_polyline(stroke.coarse, *q);
    sum += gauss(h.distance, p.k_r * stroke.coarse_delta[static_cast<std::size_t>(h.index)]);
  }
  return sum / n;
}

double curvature_prior(const Curve& curve, const AnalyticParams& p) {
  const int per = 32;
  const int k = curve.segment_count();
  double total_kappa = 0.0, length = 0.0;
  const double h = 1.0 / per;
  for (int i = 0; i <= per * k; ++i) {
    const double t = std::min(curve.t_max(), i * h);
    const Vec3 d1 = derivative(curve, t), d2 = second_derivative(curve, t);
    const double speed = d1.norm();
    const double w = (i == 0 || i == per * k) ? 0.5 * h : h;
    if (speed > 1e-12) total_kappa += w * d1.cross(d2).norm() / (speed * speed * speed);
    length += w * speed;
  }
  if (!(length > 0)) return 0.0;
  const double kappa_opt = std::numbers::pi * curve.t_max() / length;
  return gauss(total_kappa / kappa_opt - 1.0, p.r_kappa);
}

double combination_weight(const CurveCombination& c, const AnalyticParams& p) {
  const double n = static_cast<double>(c.points.size());
  double w = 1.0 + p.lambda * std::exp(-p.lambda * (n - 2.0));
  for (int t : c.tangents) w *= t >= 0 ? p.f_tangent_point : p.f_point;
  if (c.planar) w *= p.f_planar;
  if (c.symmetric) w *= p.f_symmetric;
  return w;
}

namespace {

// A point set of the search: a start point, interior points, an end point.
struct PointSet {
  std::vector<int> points;
  double bound = 0.0;  // C with every option at its best (S, G <= 1)
  bool coplanar = false, symmetric = false;
  double s_free = -1.0;  // S of the fit with free tangents (-1: not fitted)
  double g_free = 0.0;   // G of that fit
};

// The search of §3.2 over point sets and, within each, tangent assignments,
// in named stages: classify the candidate points by where they project,
// enumerate the point sets, fit each with free tangents, then visit the sets
// in bound order with a branch-and-bound over their tangents. Fitness F =
// S·G·C; `out` collects the best two choices and the counts.
class CurveSearch {
 public:
  CurveSearch(const Scaffold& s, const Camera& cam, const Stroke2d& stroke, const AnalyticParams& p,
              CurveInference& out)
      : cam_(cam), stroke_(stroke), p_(p), out_(out), pts_(out.points), tol_(1e-6 * s.extent) {}

  void run() {
    if (!classify_points()) return;
    enumerate_point_sets();
    fit_free_tangents();
    for (std::size_t i : visit_order()) {
      check_budget();  // issue 17: the per-event time budget
      search_tangents(i);
    }
  }

 private:
  const CurvePoint& point(int i) const { return pts_[static_cast<std::size_t>(i)]; }

  // Points projecting within k_r·δ of the stroke's start or end are its
  // possible ends; the others interior. False when an end has no candidate.
  bool classify_points() {
    for (std::size_t i = 0; i < pts_.size(); ++i) {
      const auto q = cam_.project(pts_[i].p);
      const bool at_start = (*q - stroke_.points.front()).norm() <= p_.k_r * stroke_.delta.front();
      const bool at_end = (*q - stroke_.points.back()).norm() <= p_.k_r * stroke_.delta.back();
      if (at_start && !at_end) starts_.push_back(static_cast<int>(i));
      else if (at_end && !at_start) ends_.push_back(static_cast<int>(i));
      else if (!at_start && !at_end) interior_.push_back(static_cast<int>(i));
    }
    return !starts_.empty() && !ends_.empty();
  }

  // Every (start, subset of at most 20 interior points, end), with the upper
  // bound of its family's C.
  void enumerate_point_sets() {
    const int m = std::min<int>(static_cast<int>(interior_.size()), 20);
    for (int a : starts_)
      for (int b : ends_)
        for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << m); ++mask) {
          PointSet set;
          set.points.push_back(a);
          for (int i = 0; i < m; ++i)
            if (mask >> i & 1) set.points.push_back(interior_[static_cast<std::size_t>(i)]);
          set.points.push_back(b);
          std::vector<Vec3> xs;
          for (int i : set.points) xs.push_back(point(i).p);
          if ((xs.back() - xs.front()).norm() <= tol_) continue;
          const std::vector<std::optional<Vec3>> none(xs.size());
          set.coplanar = xs.size() <= 3 || plane_of(xs, none, tol_).planar;
          set.symmetric = points_symmetric(xs, tol_);
          CurveCombination cmax;
          cmax.points = set.points;
          for (int i : set.points) cmax.tangents.push_back(point(i).directions.empty() ? -1 : 0);
          cmax.planar = set.coplanar;
          cmax.symmetric = set.symmetric;
          set.bound = combination_weight(cmax, p_);
          sets_.push_back(std::move(set));
        }
  }

  // The fit problem of a combination: its joints and tangents, and the rays
  // through the stroke between consecutive joints. False for a degenerate
  // arclength order.
  bool make_problem(const CurveCombination& c, FitProblem& pr) const {
    const std::size_t n = c.points.size();
    std::vector<double> arc;
    for (std::size_t j = 0; j < n; ++j) {
      const CurvePoint& cp = point(c.points[j]);
      pr.joints.push_back(cp.p);
      pr.tangent_dir.push_back(c.tangents[j] >= 0 ? std::optional<Vec3>(cp.directions[static_cast<std::size_t>(c.tangents[j])])
                                                  : std::nullopt);
      arc.push_back(cp.arclength);
    }
    // The curve runs from the first to the last constraint: the stroke's ends
    // beyond them are within the uncertainty radius.
    arc.front() = 0.0;
    arc.back() = stroke_.length;
    const int per = std::max(2, p_.samples_per_segment);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      if (!(arc[k + 1] > arc[k])) return false;
      std::vector<Ray> rays;
      std::vector<double> us;
      for (int i = 0; i < per; ++i) {
        const double u = (i + 0.5) / per;
        rays.push_back(cam_.ray(point_at(stroke_.points, arc[k] + u * (arc[k + 1] - arc[k]))));
        us.push_back(u);
      }
      pr.rays.push_back(std::move(rays));
      pr.u0.push_back(std::move(us));
    }
    return true;
  }

  // §3.2: discard a family whose upper bound is below the best fitness.
  bool promising(double bound) const { return p_.curve_exhaustive || bound > best_f_; }

  void consider(const CurveCombination& c, const Curve& curve, double sc, double g) {
    const double f = sc * g * c.weight;
    CurveChoice ch{c, curve, f, sc, g};
    if (!out_.best || f > out_.best->fitness) {
      if (out_.best) out_.runner_up = out_.best;
      out_.best = ch;
      best_f_ = f;
    } else if (!out_.runner_up || f > out_.runner_up->fitness) {
      out_.runner_up = ch;
    }
  }

  // The fit with free tangents bounds S for every tangent assignment of a
  // point set (§3.2), so fit those first.
  void fit_free_tangents() {
    free_fits_.resize(sets_.size());
    for (std::size_t i = 0; i < sets_.size(); ++i) {
      check_budget();  // issue 17: the per-event time budget
      PointSet& set = sets_[i];
      CurveCombination c;
      c.points = set.points;
      c.tangents.assign(set.points.size(), -1);
      FitProblem pr;
      if (!make_problem(c, pr)) continue;
      free_fits_[i] = fit_spline(pr, p_.fit_iterations);
      ++out_.fitted;
      if (!free_fits_[i].ok) continue;
      set.s_free = curve_stroke_score(free_fits_[i].curve, cam_, stroke_, p_);
      set.g_free = curvature_prior(free_fits_[i].curve, p_);
    }
  }

  // Point sets by S_free·C_max: good candidates come early and the bound
  // prunes the rest.
  std::vector<std::size_t> visit_order() const {
    std::vector<std::size_t> order(sets_.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return sets_[a].s_free * sets_[a].bound > sets_[b].s_free * sets_[b].bound;
    });
    return order;
  }

  // A child's fit starts from its parent's sample parameters (same points):
  // half the foot-point rounds suffice.
  FitResult fit_of(const CurveCombination& c, bool planar, bool symmetric,
                   const std::vector<std::vector<double>>* warm = nullptr) {
    FitProblem q;
    FitResult r;
    if (!make_problem(c, q)) return r;
    if (warm && warm->size() == q.u0.size()) q.u0 = *warm;
    const int rounds = warm ? std::max(1, p_.fit_iterations / 2) : p_.fit_iterations;
    if (planar) q.plane_normal = plane_of(q.joints, q.tangent_dir, tol_).normal;
    q.symmetric = symmetric;
    r = fit_spline(q, rounds);
    ++out_.fitted;
    return r;
  }

  // G bound of the family (README: a choice, not strictly admissible): free
  // tangents let the fit wiggle in depth (G near 0), while the scaffold's
  // tangents give the intended shape, so the larger G of the free fit and of
  // the probe fit with every point's first tangent option, times
  // curve_g_slack, stands in for the paper's G <= 1. The probe is only a
  // bound: its combination is scored when the tree reaches it.
  double g_bound(const PointSet& set) {
    double g_probe = set.g_free;
    CurveCombination probe;
    probe.points = set.points;
    for (int i : set.points) probe.tangents.push_back(point(i).directions.empty() ? -1 : 0);
    if (std::any_of(probe.tangents.begin(), probe.tangents.end(), [](int t) { return t >= 0; })) {
      FitProblem q;
      if (make_problem(probe, q)) {
        const FitResult f = fit_spline(q, p_.fit_iterations);
        ++out_.fitted;
        if (f.ok) g_probe = std::max(g_probe, curvature_prior(f.curve, p_));
      }
    }
    return std::min(1.0, p_.curve_g_slack * g_probe);
  }

  // The tangent search of one point set.
  struct TangentSearch {
    const PointSet& set;
    std::vector<Vec3> xs;      // the set's points
    double gb = 1.0;           // G bound of the family
    std::vector<int> choice;   // tangent option per point so far (-1: free)
  };

  // Within a point set, a branch-and-bound over tangent assignments, point by
  // point: constraining more tangents can only lower S, so the S of a partial
  // assignment (the rest free) times the best C of its completions bounds
  // every completion (§3.2's bound, applied at each level).
  void search_tangents(std::size_t i) {
    const PointSet& set = sets_[i];
    long long family = set.symmetric ? 2 : 1;
    for (int k : set.points) family *= 1 + static_cast<long long>(point(k).directions.size());
    out_.combinations += family;
    if (!free_fits_[i].ok || !promising(set.s_free * set.bound)) return;  // §3.2, G <= 1
    TangentSearch ts{set, {}, 1.0, std::vector<int>(set.points.size(), -1)};
    for (int k : set.points) ts.xs.push_back(point(k).p);
    if (p_.curve_g_slack > 0 && !p_.curve_exhaustive) {
      ts.gb = g_bound(set);
      if (!promising(set.s_free * ts.gb * set.bound)) return;
    }
    explore(ts, 0, free_fits_[i].curve, free_fits_[i].u, set.s_free);
  }

  void consider_in(const TangentSearch& ts, const CurveCombination& c, const Curve& curve, double sc) {
    const double g = curvature_prior(curve, p_);
    if (g > ts.gb) ++out_.g_bound_exceeded;
    consider(c, curve, sc, g);
  }

  // Best C of any completion of choice[0..j).
  double completion_bound(const TangentSearch& ts, std::size_t j) const {
    CurveCombination c;
    c.points = ts.set.points;
    c.tangents = ts.choice;
    for (std::size_t k = j; k < c.points.size(); ++k) c.tangents[k] = point(ts.set.points[k]).directions.empty() ? -1 : 0;
    c.planar = ts.set.coplanar;
    c.symmetric = ts.set.symmetric;
    return combination_weight(c, p_);
  }

  // A complete assignment: scored as fitted, refitted in its plane when
  // coplanar, and as its symmetric variant when the tangents allow one.
  void leaf(const TangentSearch& ts, const Curve& node_curve, const std::vector<std::vector<double>>& node_u,
            double node_s) {
    const std::size_t n = ts.set.points.size();
    CurveCombination c;
    c.points = ts.set.points;
    c.tangents = ts.choice;
    std::vector<std::optional<Vec3>> dirs(n);
    for (std::size_t j = 0; j < n; ++j)
      if (ts.choice[j] >= 0) dirs[j] = point(ts.set.points[j]).directions[static_cast<std::size_t>(ts.choice[j])];
    c.planar = ts.set.coplanar && plane_of(ts.xs, dirs, tol_).planar;
    c.weight = combination_weight(c, p_);
    if (!c.planar) {
      consider_in(ts, c, node_curve, node_s);
    } else if (promising(node_s * ts.gb * c.weight)) {
      const FitResult f = fit_of(c, true, false, &node_u);
      if (f.ok) consider_in(ts, c, f.curve, curve_stroke_score(f.curve, cam_, stroke_, p_));
    }
    if (ts.set.symmetric && tangents_symmetric(ts.xs, dirs)) {
      CurveCombination sym = c;
      sym.symmetric = true;
      sym.weight = combination_weight(sym, p_);
      if (promising(node_s * ts.gb * sym.weight)) {
        const FitResult f = fit_of(sym, sym.planar, true, &node_u);
        if (f.ok) consider_in(ts, sym, f.curve, curve_stroke_score(f.curve, cam_, stroke_, p_));
      }
    }
  }

  // Point j's tangent options (and free), best bound first.
  void explore(TangentSearch& ts, std::size_t j, const Curve& node_curve,
               const std::vector<std::vector<double>>& node_u, double node_s) {
    if (j == ts.set.points.size()) {
      leaf(ts, node_curve, node_u, node_s);
      return;
    }
    const CurvePoint& cp = point(ts.set.points[j]);
    struct Child {
      int option;
      Curve curve;
      std::vector<std::vector<double>> u;
      double s, bound;
    };
    std::vector<Child> children;
    for (int o = 0; o < static_cast<int>(cp.directions.size()); ++o) {
      ts.choice[j] = o;
      if (!promising(node_s * ts.gb * completion_bound(ts, j + 1))) continue;
      CurveCombination c;
      c.points = ts.set.points;
      c.tangents = ts.choice;
      const FitResult f = fit_of(c, false, false, &node_u);
      if (!f.ok) continue;
      const double sc = curve_stroke_score(f.curve, cam_, stroke_, p_);
      children.push_back({o, f.curve, f.u, sc, sc * ts.gb * completion_bound(ts, j + 1)});
    }
    ts.choice[j] = -1;
    children.push_back({-1, node_curve, node_u, node_s, node_s * ts.gb * completion_bound(ts, j + 1)});
    std::stable_sort(children.begin(), children.end(), [](const Child& a, const Child& b) { return a.bound > b.bound; });
    for (const Child& ch : children) {
      if (!promising(ch.bound)) continue;
      ts.choice[j] = ch.option;
      explore(ts, j + 1, ch.curve, ch.u, ch.s);
    }
    ts.choice[j] = -1;
  }

  const Camera& cam_;
  const Stroke2d& stroke_;
  const AnalyticParams& p_;
  CurveInference& out_;
  const std::vector<CurvePoint>& pts_;
  const double tol_;
  std::vector<int> starts_, ends_, interior_;
  std::vector<PointSet> sets_;
  std::vector<FitResult> free_fits_;
  double best_f_ = 0.0;
};

}  // namespace

CurveInference infer_curve(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                           const AnalyticParams& p) {
  CurveInference out;
  out.points = collect_curve_points(s, cam, stroke, p);
  if (out.points.size() < 2 || stroke.points.size() < 2) return out;
  CurveSearch(s, cam, stroke, p, out).run();
  if (out.best && out.runner_up && out.best->fitness > 0)
    out.confidence = out.runner_up->fitness / out.best->fitness;
  return out;
}

}  // namespace sketchlab::analytic
