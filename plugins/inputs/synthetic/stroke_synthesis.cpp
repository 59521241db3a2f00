#include "stroke_synthesis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::synthetic {
namespace {

constexpr int table_per_segment = 64;
constexpr double hook_duration = 0.1;  // s

// Minimum-jerk position profile (Flash & Hogan 1985, eq. for a
// point-to-point movement with zero end velocity and acceleration).
double minimum_jerk(double tau) { return tau * tau * tau * (10.0 + tau * (-15.0 + 6.0 * tau)); }

// The curve mapped to drawing space (metres or pixels), tabulated densely:
// parameter, point and cumulative length. Points between table entries are
// mapped exactly from the curve, so a noise-free sample lies on the curve.
template <class Map>
struct Path {
  const Curve& curve;
  Map map;
  std::vector<double> t, s;
  std::vector<Vec3> p;

  Path(const Curve& c, Map m) : curve(c), map(m) {
    const int n = c.segment_count() * table_per_segment + 1;
    for (int i = 0; i < n; ++i) {
      const double ti = (i == n - 1) ? c.t_max() : static_cast<double>(i) / table_per_segment;
      t.push_back(ti);
      p.push_back(map(evaluate(c, ti)));
      s.push_back(i == 0 ? 0.0 : s.back() + (p[static_cast<std::size_t>(i)] - p[static_cast<std::size_t>(i) - 1]).norm());
    }
  }
  double length() const { return s.back(); }

  // Unit direction of the table near index k (skipping zero-length steps).
  Vec3 direction_near(std::size_t k) const {
    for (std::size_t d = 0; d < p.size(); ++d) {
      for (std::size_t a : {k + d, k >= d ? k - d : p.size()}) {
        if (a + 1 < p.size()) {
          const Vec3 v = p[a + 1] - p[a];
          if (v.norm() > 0.0) return v.normalized();
        }
      }
    }
    return (p.back() - p.front()).normalized();
  }

  // Point and unit tangent at arclength s; beyond the ends the path goes on
  // straight along the end tangent.
  std::pair<Vec3, Vec3> at(double sv) const {
    if (sv <= 0.0) {
      const Vec3 d = direction_near(0);
      return {p.front() + sv * d, d};
    }
    if (sv >= length()) {
      const Vec3 d = direction_near(p.size() - 2);
      return {p.back() + (sv - length()) * d, d};
    }
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), sv) - s.begin()) - 1;
    const double w = s[k + 1] > s[k] ? (sv - s[k]) / (s[k + 1] - s[k]) : 0.0;
    const double tv = t[k] + w * (t[k + 1] - t[k]);
    return {map(evaluate(curve, tv)), direction_near(k)};
  }
};

// Offset directions for the wobble at a point with tangent `tangent`.
struct Frame {
  Vec3 e1, e2;  // e2 may be zero (tablet)
};

Vec3 any_perpendicular(const Vec3& d) {
  const Vec3 a = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return d.cross(a).normalized();
}

template <class Map, class FrameFn, class PerpFn>
std::vector<Sample> synthesize(const Curve& curve, Map map, FrameFn frame_at, PerpFn random_perp,
                               int dims, const NoiseModel& noise, const MotionModel& motion,
                               double start, Rng& rng) {
  if (!validate(curve).empty()) throw std::invalid_argument("synthesize: " + validate(curve));
  if (!(motion.speed > 0.0) || !(motion.rate > 0.0))
    throw std::invalid_argument("synthesize: speed and rate must be > 0");
  const Path<Map> path(curve, map);
  const double length = path.length();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("synthesize: the curve has zero or non-finite drawn length");

  // Every random value is drawn whatever the magnitudes, so the stream does
  // not depend on them.
  const double o0 = std::max(rng.normal(noise.overshoot), -0.25 * length);
  const double o1 = std::max(rng.normal(noise.overshoot), -0.25 * length);
  std::array<double, 6> phase{};
  for (double& ph : phase) ph = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const bool hook0 = rng.bernoulli(noise.hook_probability) && noise.hook_length > 0.0;
  const bool hook1 = rng.bernoulli(noise.hook_probability) && noise.hook_length > 0.0;
  const Vec3 perp0 = random_perp(path.at(0.0).second, rng);
  const Vec3 perp1 = random_perp(path.at(length).second, rng);

  const double s0 = -o0, s1 = length + o1;
  const double amplitude = noise.wobble * std::sqrt(2.0 / 3.0);  // RMS `wobble` for 3 sinusoids
  const std::array<double, 3> wavelengths{1.0, 0.62, 0.38};
  auto wobble = [&](double sv, int component) {
    double w = 0.0;
    for (int k = 0; k < 3; ++k) {
      w += std::sin(2.0 * std::numbers::pi * sv / (noise.wobble_wavelength * wavelengths[static_cast<std::size_t>(k)]) +
                    phase[static_cast<std::size_t>(3 * component + k)]);
    }
    return amplitude * w;
  };

  const double duration = std::max(motion.min_duration, (s1 - s0) / motion.speed);
  const int n = std::max(2, static_cast<int>(std::lround(duration * motion.rate)) + 1);
  const int hook_n = std::max(2, static_cast<int>(std::lround(hook_duration * motion.rate)));
  const double dt = 1.0 / motion.rate;

  std::vector<Vec3> points;
  std::vector<double> times;
  std::vector<Vec3> body;
  Vec3 first_tangent = Vec3::UnitX(), last_tangent = Vec3::UnitX();
  for (int i = 0; i < n; ++i) {
    const double tau = static_cast<double>(i) / (n - 1);
    const double sv = s0 + (s1 - s0) * minimum_jerk(tau);
    const auto [base, tangent] = path.at(sv);
    const Frame f = frame_at(base, tangent);
    body.push_back(base + wobble(sv, 0) * f.e1 + wobble(sv, 1) * f.e2);
    if (i == 0) first_tangent = tangent;
    last_tangent = tangent;
  }
  double time = start;
  if (hook0) {
    // The pen arrives from a flick turning back by more than 90°.
    const Vec3 h = (perp0 + 0.5 * first_tangent).normalized();
    const Vec3 from = body.front() + noise.hook_length * h;
    for (int i = 0; i < hook_n; ++i) {
      points.push_back(from + (body.front() - from) * minimum_jerk(static_cast<double>(i) / hook_n));
      times.push_back(time);
      time += dt;
    }
  }
  for (int i = 0; i < n; ++i) {
    points.push_back(body[static_cast<std::size_t>(i)]);
    times.push_back(time + duration * static_cast<double>(i) / (n - 1));
  }
  time = times.back();
  if (hook1) {
    const Vec3 h = (perp1 - 0.5 * last_tangent).normalized();
    const Vec3 to = body.back() + noise.hook_length * h;
    for (int i = 1; i <= hook_n; ++i) {
      points.push_back(body.back() + (to - body.back()) * minimum_jerk(static_cast<double>(i) / hook_n));
      times.push_back(time + dt * i);
    }
  }

  std::vector<Sample> samples(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    Vec3 q = points[i];
    for (int a = 0; a < dims; ++a) q[a] += rng.normal(noise.jitter);
    samples[i].position = q;
    samples[i].time = times[i];
  }
  return samples;
}

}  // namespace

NoiseModel scaled(const NoiseModel& m, double noise) {
  NoiseModel r = m;
  r.jitter *= noise;
  r.wobble *= noise;
  r.overshoot *= noise;
  r.hook_length *= noise;
  return r;
}

std::vector<Sample> synthesize_vr_stroke(const Curve& curve, const Vec3& head,
                                         const NoiseModel& noise, const MotionModel& motion,
                                         double start, Rng& rng) {
  auto identity = [](const Vec3& p) { return p; };
  auto frame = [&](const Vec3& p, const Vec3& tangent) {
    Vec3 ray = p - head;
    ray = ray.norm() > 0.0 ? ray.normalized() : any_perpendicular(tangent);
    Vec3 across = tangent.cross(ray);
    across = across.norm() > 1e-9 ? across.normalized() : any_perpendicular(tangent);
    return Frame{across, noise.depth_factor * ray};
  };
  auto perp = [](const Vec3& tangent, Rng& r) {
    Vec3 v(r.normal(), r.normal(), r.normal());
    v -= v.dot(tangent) * tangent;
    return v.norm() > 1e-9 ? Vec3(v.normalized()) : any_perpendicular(tangent);
  };
  return synthesize(curve, identity, frame, perp, 3, noise, motion, start, rng);
}

std::vector<Sample> synthesize_tablet_stroke(const Curve& curve, const View& view,
                                             const NoiseModel& noise, const MotionModel& motion,
                                             double start, Rng& rng) {
  auto project = [&view](const Vec3& p) {
    const Vec3 px = world_to_pixel(view, p);
    if (px.z() < 0.0) throw std::invalid_argument("synthesize: the curve passes behind the camera");
    return Vec3(px.x(), px.y(), 0.0);
  };
  auto frame = [](const Vec3&, const Vec3& tangent) {
    return Frame{Vec3(-tangent.y(), tangent.x(), 0.0), Vec3::Zero()};
  };
  auto perp = [](const Vec3& tangent, Rng& r) {
    const double side = r.uniform() < 0.5 ? -1.0 : 1.0;
    return Vec3(-side * tangent.y(), side * tangent.x(), 0.0);
  };
  return synthesize(curve, project, frame, perp, 2, noise, motion, start, rng);
}

}  // namespace sketchlab::synthetic
