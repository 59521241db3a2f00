// The modelled errors have the configured statistics.
#include <catch2/catch.hpp>
#include <cmath>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "stroke_synthesis.hpp"
#include "synthetic_test_support.hpp"

using namespace sketchlab;
using namespace sketchlab::synthetic;
using namespace sketchlab::synthetic::support;

namespace {

// RMS distance of the samples to their ground-truth curves, over seeds.
double rms_distance(const SynthesisParams& base, int seeds) {
  double sum = 0.0;
  std::size_t n = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    SynthesisParams p = base;
    p.seed = static_cast<std::uint64_t>(seed);
    for (const auto& d : drawn(synthesize_session(p))) {
      for (const Sample& s : d.stroke.samples) {
        const double dist = closest_point(d.truth, s.position).distance;
        sum += dist * dist;
        ++n;
      }
    }
  }
  return std::sqrt(sum / static_cast<double>(n));
}

}  // namespace

TEST_CASE("VR jitter: RMS distance to the curve is jitter·√2", "[synthetic][noise]") {
  NoiseModel m;
  m.jitter = 0.002;
  // Gaussian noise of std σ per axis: its two components across a line give
  // an RMS distance of σ√2 (the component along the line does not count).
  const double rms = rms_distance(vr_only("cube", m), 3);
  CHECK(rms == Approx(0.002 * std::sqrt(2.0)).epsilon(0.2));
  CHECK(rms == Approx(0.002 * std::sqrt(2.0)).epsilon(0.05));  // tighter, with ~3000 samples
}

TEST_CASE("VR wobble: RMS lateral deviation is the configured wobble", "[synthetic][noise]") {
  NoiseModel m;
  m.wobble = 0.004;
  m.wobble_wavelength = 0.15;
  m.depth_factor = 0.0;  // only the component across the view ray
  CHECK(rms_distance(vr_only("cube", m), 4) == Approx(0.004).epsilon(0.2));
}

TEST_CASE("VR wobble is larger along the view ray by the depth factor", "[synthetic][noise]") {
  NoiseModel m;
  m.wobble = 0.003;
  m.depth_factor = 3.0;
  double across = 0.0, along = 0.0;
  for (int seed = 1; seed <= 4; ++seed) {
    for (const auto& d : drawn(synthesize_session(vr_only("cube", m, static_cast<std::uint64_t>(seed))))) {
      for (const Sample& s : d.stroke.samples) {
        const ClosestPoint cp = closest_point(d.truth, s.position);
        const Vec3 e = s.position - cp.point;
        const Vec3 t = tangent(d.truth, cp.t);
        const Vec3 ray = (cp.point - vr_head_position).normalized();
        const Vec3 u = t.cross(ray).normalized();
        across += std::pow(e.dot(u), 2);
        along += std::pow(e.dot(t.cross(u)), 2);
      }
    }
  }
  // The ray is not always perpendicular to the stroke, so the ratio is at
  // most the factor; it must be clearly above 1.
  const double ratio = std::sqrt(along / across);
  CHECK(ratio > 2.0);
  CHECK(ratio < 3.3);
}

TEST_CASE("VR overshoot: end extensions along the tangent have the configured std", "[synthetic][noise]") {
  NoiseModel m;
  m.overshoot = 0.01;
  double sum = 0.0;
  int n = 0;
  for (int seed = 1; seed <= 10; ++seed) {
    for (const auto& d : drawn(synthesize_session(vr_only("cube", m, static_cast<std::uint64_t>(seed))))) {
      const Vec3 a = d.truth.control_points.front(), b = d.truth.control_points.back();
      const Vec3 dir = (b - a).normalized();
      const double o0 = -(d.stroke.samples.front().position - a).dot(dir);
      const double o1 = (d.stroke.samples.back().position - b).dot(dir);
      sum += o0 * o0 + o1 * o1;
      n += 2;
      // Over/undershoot stays on the line.
      CHECK(closest_point(d.truth, d.stroke.samples[d.stroke.samples.size() / 2].position).distance < 1e-9);
    }
  }
  CHECK(std::sqrt(sum / n) == Approx(0.01).epsilon(0.2));
}

TEST_CASE("tablet jitter: RMS pixel distance to the projected line is the jitter", "[synthetic][noise]") {
  SynthesisParams p;
  p.model = "cube";
  p.modality = Modality::tablet;
  p.tablet_noise = NoiseModel{};
  p.tablet_noise.jitter = 1.5;
  double sum = 0.0;
  std::size_t n = 0;
  for (int seed = 1; seed <= 3; ++seed) {
    p.seed = static_cast<std::uint64_t>(seed);
    for (const auto& d : drawn(synthesize_session(p))) {
      const Vec3 a = world_to_pixel(*d.stroke.view, d.truth.control_points.front());
      const Vec3 b = world_to_pixel(*d.stroke.view, d.truth.control_points.back());
      const Vec2 dir = (b - a).head<2>().normalized();
      for (const Sample& s : d.stroke.samples) {
        const Vec2 e = (s.position - a).head<2>();
        const double across = e.x() * dir.y() - e.y() * dir.x();
        sum += across * across;
        ++n;
      }
    }
  }
  // One component in 2D is across the (projected, straight) line.
  CHECK(std::sqrt(sum / static_cast<double>(n)) == Approx(1.5).epsilon(0.2));
}

TEST_CASE("hooks: a flick of hook_length at each end, turning back past 90°", "[synthetic][noise]") {
  NoiseModel m;
  m.hook_probability = 1.0;
  m.hook_length = 0.02;
  for (const auto& d : drawn(synthesize_session(vr_only("cube", m)))) {
    const auto& s = d.stroke.samples;
    const Vec3 a = d.truth.control_points.front(), b = d.truth.control_points.back();
    CHECK((s.front().position - a).norm() == Approx(0.02).epsilon(1e-9));
    CHECK((s.back().position - b).norm() == Approx(0.02).epsilon(1e-9));
    const Vec3 dir = (b - a).normalized();
    // Arriving at the start from the hook, the pen turns by more than 90°.
    CHECK((a - s.front().position).normalized().dot(dir) < 0.0);
    CHECK((s.back().position - b).normalized().dot(dir) < 0.0);
  }
}

TEST_CASE("the global noise scale multiplies every magnitude, 0 gives perfect strokes", "[synthetic][noise]") {
  NoiseModel m{0.001, 0.003, 0.15, 2.0, 0.006, 0.2, 0.015};
  const NoiseModel half = scaled(m, 0.5);
  CHECK(half.jitter == 0.0005);
  CHECK(half.wobble == 0.0015);
  CHECK(half.overshoot == 0.003);
  CHECK(half.hook_length == 0.0075);
  CHECK(half.hook_probability == 0.2);
  CHECK(half.wobble_wavelength == 0.15);
  SynthesisParams p;  // default noise values
  p.model = "mug";
  const double at1 = rms_distance(p, 2);
  p.noise = 2.0;
  const double at2 = rms_distance(p, 2);
  CHECK(at2 > 1.5 * at1);
  p.noise = 0.0;
  CHECK(rms_distance(p, 1) < 1e-9);
}

TEST_CASE("minimum-jerk timing: 90 Hz, bell-shaped speed peaking at 1.875× the mean", "[synthetic][motion]") {
  const Curve line = make_line(Vec3(0, 1, 0), Vec3(0.4, 1, 0));
  Rng rng(1);
  MotionModel motion{0.4, 90.0, 0.25};
  const auto s = synthesize_vr_stroke(line, Vec3(0, 1.5, 0.6), NoiseModel{}, motion, 2.0, rng);
  const double duration = s.back().time - s.front().time;
  CHECK(s.front().time == 2.0);
  CHECK(duration == Approx(1.0).epsilon(0.01));  // 0.4 m at 0.4 m/s
  CHECK(s.size() == 91);
  double peak = 0.0;
  std::size_t peak_at = 0;
  for (std::size_t i = 1; i < s.size(); ++i) {
    CHECK(s[i].time > s[i - 1].time);
    CHECK(s[i].time - s[i - 1].time == Approx(1.0 / 90.0).epsilon(1e-6));
    const double v = (s[i].position - s[i - 1].position).norm() / (s[i].time - s[i - 1].time);
    if (v > peak) peak = v, peak_at = i;
  }
  CHECK(peak / 0.4 == Approx(1.875).epsilon(0.01));
  CHECK(std::abs(static_cast<double>(peak_at) - 45.5) <= 1.0);  // mid-stroke
}
