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

CurveInference infer_curve(const Scaffold& s, const Camera& cam, const Stroke2d& stroke,
                           const AnalyticParams& p) {
  CurveInference out;
  out.points = collect_curve_points(s, cam, stroke, p);
  const auto& pts = out.points;
  if (pts.size() < 2 || stroke.points.size() < 2) return out;
  const double tol = 1e-6 * s.extent;
  std::vector<int> starts, ends, interior;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto q = cam.project(pts[i].p);
    const bool at_start = (*q - stroke.points.front()).norm() <= p.k_r * stroke.delta.front();
    const bool at_end = (*q - stroke.points.back()).norm() <= p.k_r * stroke.delta.back();
    if (at_start && !at_end) starts.push_back(static_cast<int>(i));
    else if (at_end && !at_start) ends.push_back(static_cast<int>(i));
    else if (!at_start && !at_end) interior.push_back(static_cast<int>(i));
  }
  if (starts.empty() || ends.empty()) return out;
  const int m = std::min<int>(static_cast<int>(interior.size()), 20);

  struct Subset {
    std::vector<int> points;
    double bound = 0.0;  // C with every option at its best (S, G <= 1)
    bool coplanar = false, symmetric = false;
    double s_free = -1.0;  // S of the fit with free tangents (-1: not fitted)
    double g_free = 0.0;   // G of that fit
  };
  std::vector<Subset> subsets;
  for (int a : starts)
    for (int b : ends)
      for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << m); ++mask) {
        Subset sub;
        sub.points.push_back(a);
        for (int i = 0; i < m; ++i)
          if (mask >> i & 1) sub.points.push_back(interior[static_cast<std::size_t>(i)]);
        sub.points.push_back(b);
        std::vector<Vec3> xs;
        for (int i : sub.points) xs.push_back(pts[static_cast<std::size_t>(i)].p);
        if ((xs.back() - xs.front()).norm() <= tol) continue;
        const std::vector<std::optional<Vec3>> none(xs.size());
        sub.coplanar = xs.size() <= 3 || plane_of(xs, none, tol).planar;
        sub.symmetric = points_symmetric(xs, tol);
        CurveCombination cmax;
        cmax.points = sub.points;
        for (int i : sub.points) cmax.tangents.push_back(pts[static_cast<std::size_t>(i)].directions.empty() ? -1 : 0);
        cmax.planar = sub.coplanar;
        cmax.symmetric = sub.symmetric;
        sub.bound = combination_weight(cmax, p);
        subsets.push_back(std::move(sub));
      }

  auto make_problem = [&](const CurveCombination& c, FitProblem& pr) {
    const std::size_t n = c.points.size();
    std::vector<double> arc;
    for (std::size_t j = 0; j < n; ++j) {
      const CurvePoint& cp = pts[static_cast<std::size_t>(c.points[j])];
      pr.joints.push_back(cp.p);
      pr.tangent_dir.push_back(c.tangents[j] >= 0 ? std::optional<Vec3>(cp.directions[static_cast<std::size_t>(c.tangents[j])])
                                                  : std::nullopt);
      arc.push_back(cp.arclength);
    }
    // The curve runs from the first to the last constraint: the stroke's ends
    // beyond them are within the uncertainty radius.
    arc.front() = 0.0;
    arc.back() = stroke.length;
    const int per = std::max(2, p.samples_per_segment);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      if (!(arc[k + 1] > arc[k])) return false;
      std::vector<Ray> rays;
      std::vector<double> us;
      for (int i = 0; i < per; ++i) {
        const double u = (i + 0.5) / per;
        rays.push_back(cam.ray(point_at(stroke.points, arc[k] + u * (arc[k + 1] - arc[k]))));
        us.push_back(u);
      }
      pr.rays.push_back(std::move(rays));
      pr.u0.push_back(std::move(us));
    }
    return true;
  };

  double best_f = 0.0;
  // §3.2: discard a family whose upper bound is below the best fitness.
  auto promising = [&](double bound) { return p.curve_exhaustive || bound > best_f; };
  auto consider = [&](const CurveCombination& c, const Curve& curve, double sc, double g) {
    const double f = sc * g * c.weight;
    CurveChoice ch{c, curve, f, sc, g};
    if (!out.best || f > out.best->fitness) {
      if (out.best) out.runner_up = out.best;
      out.best = ch;
      best_f = f;
    } else if (!out.runner_up || f > out.runner_up->fitness) {
      out.runner_up = ch;
    }
  };

  // The fit with free tangents bounds S for every tangent assignment of a
  // point set (§3.2), so fit those first and visit point sets by S_free·C_max:
  // good candidates come early and the bound prunes the rest.
  std::vector<FitResult> free_fits(subsets.size());
  for (std::size_t i = 0; i < subsets.size(); ++i) {
    check_budget();  // issue 17: the per-event time budget
    Subset& sub = subsets[i];
    CurveCombination c;
    c.points = sub.points;
    c.tangents.assign(sub.points.size(), -1);
    FitProblem pr;
    if (!make_problem(c, pr)) continue;
    free_fits[i] = fit_spline(pr, p.fit_iterations);
    ++out.fitted;
    if (!free_fits[i].ok) continue;
    sub.s_free = curve_stroke_score(free_fits[i].curve, cam, stroke, p);
    sub.g_free = curvature_prior(free_fits[i].curve, p);
  }
  std::vector<std::size_t> order(subsets.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return subsets[a].s_free * subsets[a].bound > subsets[b].s_free * subsets[b].bound;
  });
  // Within a point set, a branch-and-bound over tangent assignments, point by
  // point: constraining more tangents can only lower S, so the S of a partial
  // assignment (the rest free) times the best C of its completions bounds
  // every completion (§3.2's bound, applied at each level).
  // A child's fit starts from its parent's sample parameters (same points):
  // half the foot-point rounds suffice.
  auto fit_of = [&](const CurveCombination& c, bool planar, bool symmetric,
                    const std::vector<std::vector<double>>* warm = nullptr) {
    FitProblem q;
    FitResult r;
    if (!make_problem(c, q)) return r;
    if (warm && warm->size() == q.u0.size()) q.u0 = *warm;
    const int rounds = warm ? std::max(1, p.fit_iterations / 2) : p.fit_iterations;
    if (planar) q.plane_normal = plane_of(q.joints, q.tangent_dir, tol).normal;
    q.symmetric = symmetric;
    r = fit_spline(q, rounds);
    ++out.fitted;
    return r;
  };
  for (std::size_t oi : order) {
    check_budget();  // issue 17: the per-event time budget
    const Subset& sub = subsets[oi];
    const std::size_t n = sub.points.size();
    long long family = sub.symmetric ? 2 : 1;
    for (int i : sub.points) family *= 1 + static_cast<long long>(pts[static_cast<std::size_t>(i)].directions.size());
    out.combinations += family;
    if (!free_fits[oi].ok || !promising(sub.s_free * sub.bound)) continue;  // §3.2, G <= 1
    std::vector<Vec3> xs;
    for (int i : sub.points) xs.push_back(pts[static_cast<std::size_t>(i)].p);
    // G bound of the family (README: a choice, not strictly admissible):
    // free tangents let the fit wiggle in depth (G near 0), while the
    // scaffold's tangents give the intended shape, so the larger G of the
    // free fit and of the probe fit with every point's first tangent option,
    // times curve_g_slack, stands in for the paper's G <= 1. The probe is
    // only a bound: its combination is scored when the tree reaches it.
    double gb = 1.0;
    if (p.curve_g_slack > 0 && !p.curve_exhaustive) {
      double g_probe = sub.g_free;
      CurveCombination probe;
      probe.points = sub.points;
      for (int i : sub.points) probe.tangents.push_back(pts[static_cast<std::size_t>(i)].directions.empty() ? -1 : 0);
      if (std::any_of(probe.tangents.begin(), probe.tangents.end(), [](int t) { return t >= 0; })) {
        FitProblem q;
        if (make_problem(probe, q)) {
          const FitResult f = fit_spline(q, p.fit_iterations);
          ++out.fitted;
          if (f.ok) g_probe = std::max(g_probe, curvature_prior(f.curve, p));
        }
      }
      gb = std::min(1.0, p.curve_g_slack * g_probe);
      if (!promising(sub.s_free * gb * sub.bound)) continue;
    }
    auto consider_in = [&](const CurveCombination& c, const Curve& curve, double sc) {
      const double g = curvature_prior(curve, p);
      if (g > gb) ++out.g_bound_exceeded;
      consider(c, curve, sc, g);
    };
    std::vector<int> choice(n, -1);
    // Best C of any completion of choice[0..j).
    auto completion_bound = [&](std::size_t j) {
      CurveCombination c;
      c.points = sub.points;
      c.tangents = choice;
      for (std::size_t k = j; k < n; ++k)
        c.tangents[k] = pts[static_cast<std::size_t>(sub.points[k])].directions.empty() ? -1 : 0;
      c.planar = sub.coplanar;
      c.symmetric = sub.symmetric;
      return combination_weight(c, p);
    };
    auto leaf = [&](const Curve& node_curve, const std::vector<std::vector<double>>& node_u, double node_s) {
      CurveCombination c;
      c.points = sub.points;
      c.tangents = choice;
      std::vector<std::optional<Vec3>> dirs(n);
      for (std::size_t j = 0; j < n; ++j)
        if (choice[j] >= 0) dirs[j] = pts[static_cast<std::size_t>(sub.points[j])].directions[static_cast<std::size_t>(choice[j])];
      c.planar = sub.coplanar && plane_of(xs, dirs, tol).planar;
      c.weight = combination_weight(c, p);
      if (!c.planar) {
        consider_in(c, node_curve, node_s);
      } else if (promising(node_s * gb * c.weight)) {
        const FitResult f = fit_of(c, true, false, &node_u);
        if (f.ok) consider_in(c, f.curve, curve_stroke_score(f.curve, cam, stroke, p));
      }
      if (sub.symmetric && tangents_symmetric(xs, dirs)) {
        CurveCombination sym = c;
        sym.symmetric = true;
        sym.weight = combination_weight(sym, p);
        if (promising(node_s * gb * sym.weight)) {
          const FitResult f = fit_of(sym, sym.planar, true, &node_u);
          if (f.ok) consider_in(sym, f.curve, curve_stroke_score(f.curve, cam, stroke, p));
        }
      }
    };
    auto explore = [&](auto&& self, std::size_t j, const Curve& node_curve,
                       const std::vector<std::vector<double>>& node_u, double node_s) -> void {
      if (j == n) {
        leaf(node_curve, node_u, node_s);
        return;
      }
      const CurvePoint& cp = pts[static_cast<std::size_t>(sub.points[j])];
      struct Child {
        int option;
        Curve curve;
        std::vector<std::vector<double>> u;
        double s, bound;
      };
      std::vector<Child> children;
      for (int o = 0; o < static_cast<int>(cp.directions.size()); ++o) {
        choice[j] = o;
        if (!promising(node_s * gb * completion_bound(j + 1))) continue;
        CurveCombination c;
        c.points = sub.points;
        c.tangents = choice;
        const FitResult f = fit_of(c, false, false, &node_u);
        if (!f.ok) continue;
        const double sc = curve_stroke_score(f.curve, cam, stroke, p);
        children.push_back({o, f.curve, f.u, sc, sc * gb * completion_bound(j + 1)});
      }
      choice[j] = -1;
      children.push_back({-1, node_curve, node_u, node_s, node_s * gb * completion_bound(j + 1)});
      std::stable_sort(children.begin(), children.end(),
                       [](const Child& a, const Child& b) { return a.bound > b.bound; });
      for (const Child& ch : children) {
        if (!promising(ch.bound)) continue;
        choice[j] = ch.option;
        self(self, j + 1, ch.curve, ch.u, ch.s);
      }
      choice[j] = -1;
    };
    explore(explore, 0, free_fits[oi].curve, free_fits[oi].u, sub.s_free);
  }
  if (out.best && out.runner_up && out.best->fitness > 0)
    out.confidence = out.runner_up->fitness / out.best->fitness;
  return out;
}

}  // namespace sketchlab::analytic
