// Proximity queries of the Network (spatial index) against a brute-force scan
// of every curve with closest_point, on random networks of 100 / 1,000 /
// 10,000 curves in a 1 m cube, r = 0.04 m. Prints one "name value unit" line
// per figure (medians over queries, microseconds per query).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/network.hpp"

using namespace sketchlab;

namespace {

double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

Vec3 random_point(std::mt19937_64& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}

// Sketch-like curves: 1-4 cubic pieces of 2-12 cm, a quarter of them lines
// of up to 36 cm.
NetworkCurve random_curve(std::mt19937_64& rng, CurveId id) {
  NetworkCurve nc;
  nc.id = id;
  const Vec3 start = random_point(rng, 0.0, 1.0);
  const double size = uniform(rng, 0.02, 0.12);
  if (uniform(rng, 0.0, 1.0) < 0.25) {
    nc.curve = make_line(start, start + size * uniform(rng, 0.5, 3.0) * random_point(rng, -1.0, 1.0).normalized());
  } else {
    const int k = 1 + static_cast<int>(uniform(rng, 0.0, 4.0));
    Vec3 p = start;
    nc.curve.control_points.push_back(p);
    for (int i = 0; i < 3 * k; ++i) {
      p += random_point(rng, -1.0, 1.0) * (size / 2.0);
      nc.curve.control_points.push_back(p);
    }
    nc.curve.sharp.assign(static_cast<std::size_t>(k) + 1, false);
  }
  nc.keypoints = default_keypoints(nc.curve);
  return nc;
}

std::vector<Vec3> random_stroke(std::mt19937_64& rng) {
  std::vector<Vec3> s{random_point(rng, 0.0, 1.0)};
  const Vec3 dir = random_point(rng, -1.0, 1.0).normalized();
  for (int i = 1; i < 20; ++i) s.push_back(s.back() + 0.01 * dir + random_point(rng, -0.002, 0.002));
  return s;
}

template <class F>
double median_us(int count, F&& f) {
  std::vector<double> times;
  for (int i = 0; i < count; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f(i);
    const auto t1 = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
  }
  std::nth_element(times.begin(), times.begin() + count / 2, times.end());
  return times[static_cast<std::size_t>(count / 2)];
}

}  // namespace

int main() {
  const double r = 0.04;
  std::size_t sink = 0;
  for (const int n : {100, 1000, 10000}) {
    std::mt19937_64 rng(1234 + n);
    Network net;
    Edit e;
    for (int i = 0; i < n; ++i) e.curves_added.push_back(random_curve(rng, static_cast<CurveId>(i + 1)));
    const auto b0 = std::chrono::steady_clock::now();
    net.apply(e);
    const auto b1 = std::chrono::steady_clock::now();
    std::printf("build_n%d_ms %.3f ms\n", n, std::chrono::duration<double, std::milli>(b1 - b0).count());

    const int point_queries = 500;
    std::vector<Vec3> points;
    for (int i = 0; i < point_queries; ++i) points.push_back(random_point(rng, 0.0, 1.0));
    std::vector<std::vector<Vec3>> strokes;
    for (int i = 0; i < 50; ++i) strokes.push_back(random_stroke(rng));

    std::size_t hits = 0;
    const double near = median_us(point_queries, [&](int i) { hits += net.curves_near(points[i], r).size(); });
    std::printf("curves_near_n%d_us %.2f us\n", n, near);
    std::printf("curves_near_n%d_mean_hits %.2f hits\n", n, double(hits) / point_queries);

    int mismatches = 0;
    const int brute_points = n >= 10000 ? 50 : 200;
    const double brute = median_us(brute_points, [&](int i) {
      std::size_t count = 0;
      for (const auto& [id, c] : net.curves()) count += closest_point(c.curve, points[i]).distance <= r;
      mismatches += count != net.curves_near(points[i], r).size();  // (untimed share is small)
      sink += count;
    });
    std::printf("curves_near_brute_n%d_us %.2f us\n", n, brute);

    const double poly = median_us(static_cast<int>(strokes.size()),
                                  [&](int i) { sink += net.curves_near_polyline(strokes[i], r).size(); });
    std::printf("curves_near_polyline_n%d_us %.2f us\n", n, poly);
    const int brute_strokes = n >= 10000 ? 5 : 20;
    const double brute_poly = median_us(brute_strokes, [&](int i) {
      std::size_t count = 0;
      for (const auto& [id, c] : net.curves())
        count += closest_point_to_polyline(c.curve, strokes[i]).distance <= r;
      mismatches += count != net.curves_near_polyline(strokes[i], r).size();
      sink += count;
    });
    std::printf("curves_near_polyline_brute_n%d_us %.2f us\n", n, brute_poly);
    std::printf("index_vs_brute_mismatches_n%d %d count\n", n, mismatches);
  }
  return sink == 0 ? 1 : 0;
}
