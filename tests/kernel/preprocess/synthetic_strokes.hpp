#pragma once
// Seeded synthetic VR strokes for the preprocessing tests: a path sampled
// every ~2 mm with Gaussian jitter, at a given drawing speed.
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::test {

struct SyntheticStroke {
  std::vector<Vec3> points;
  std::vector<double> times;
};

// Samples `path` (s in [0,1]) at n points equally spaced in s, adds jitter
// of standard deviation `noise` (m) and times for a constant speed (m/s).
inline SyntheticStroke sample_path(const std::function<Vec3(double)>& path, int n, double noise,
                                   double speed, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, noise);
  SyntheticStroke s;
  for (int i = 0; i < n; ++i) {
    const Vec3 p = path(static_cast<double>(i) / (n - 1));
    s.points.push_back(noise > 0.0 ? Vec3(p + Vec3(g(rng), g(rng), g(rng))) : p);
  }
  std::vector<Vec3> clean;
  for (int i = 0; i < n; ++i) clean.push_back(path(static_cast<double>(i) / (n - 1)));
  const auto cum = cumulative_length(clean);
  for (double c : cum) s.times.push_back(c / speed);
  return s;
}

inline std::function<Vec3(double)> straight(const Vec3& a, const Vec3& b) {
  return [a, b](double s) { return Vec3(a + s * (b - a)); };
}

// Circular arc of radius r turning `angle` radians in the xy plane.
inline std::function<Vec3(double)> arc(double r, double angle) {
  return [r, angle](double s) {
    return Vec3(r * std::cos(s * angle), r * std::sin(s * angle), 0.0);
  };
}

// S-curve: x from 0 to len, y a full sine period of amplitude amp.
inline std::function<Vec3(double)> s_curve(double len, double amp) {
  return [len, amp](double s) {
    return Vec3(s * len, amp * std::sin(2.0 * std::numbers::pi * s), 0.1 * s * len);
  };
}

// L shape: a leg along +x then a leg along +y, each `leg` long.
inline std::function<Vec3(double)> l_shape(double leg) {
  return [leg](double s) {
    return s < 0.5 ? Vec3(2.0 * s * leg, 0.0, 0.0) : Vec3(leg, (2.0 * s - 1.0) * leg, 0.0);
  };
}

}  // namespace sketchlab::test
