#pragma once
// A random VR scaffold session for property tests: boxes drawn edge by edge,
// lines between shown keypoints, lines leaving a keypoint along an existing
// direction, free lines, redrawn lines and ticks. Every stroke is hand-drawn
// like a controller stroke: the user aims at what is shown (the corrected
// lines' keypoints), misses by 0.3–2 cm (now and then 4 cm), bows the line by
// a few millimetres and jitters by one.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <random>
#include <vector>

#include "sketchlab/network.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::scaffoldsketch::test {

class RandomScaffoldSession {
 public:
  explicit RandomScaffoldSession(unsigned seed) : rng_(seed) {}

  // The next stroke (layer scaffold, samples 10 ms apart) given the network
  // the user sees; aimed_a/aimed_b are then the points the user aimed at.
  Stroke next(StrokeId id, const Network& network) {
    collect_shown(network);
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    bool tick = false;
    if (!box_.empty()) {
      box_edge(a, b);
    } else if (shown_lines_.size() < 2 || chance(0.12)) {
      start_box();
      box_edge(a, b);
    } else {
      const double pick = uniform(0, 1);
      if (pick < 0.22) {  // between two shown keypoints
        const Vec3 p = any_keypoint(), q = any_keypoint();
        if ((p - q).norm() < 0.06 || (p - q).norm() > 0.9) return next(id, network);
        a = p;
        b = q;
      } else if (pick < 0.52) {  // from a keypoint along a direction
        a = any_keypoint();
        Vec3 d = random_direction();
        const double kind = uniform(0, 1);
        if (kind < 0.45) d = any_line_direction();
        else if (kind < 0.65) d = Vec3::UnitY();
        if (chance(0.5)) d = -d;
        // Short lines (6–12 cm) put the midpoint within 5 cm of the start.
        b = a + d * (chance(0.3) ? uniform(0.06, 0.12) : uniform(0.12, 0.5));
      } else if (pick < 0.72) {  // free line, often nearly level or vertical
        a = Vec3(uniform(-1, 1), uniform(0.5, 2), uniform(-1, 1));
        Vec3 d = random_direction();
        if (chance(0.3)) d = Vec3(d.x(), 0.05 * d.y(), d.z()).normalized();
        else if (chance(0.2)) d = (Vec3::UnitY() + 0.05 * random_direction()).normalized();
        b = a + d * uniform(0.05, 0.6);
      } else if (pick < 0.9) {  // over an existing line
        const auto& [p, q] = shown_lines_[index(shown_lines_.size())];
        a = p;
        b = q;
        if (chance(0.5)) std::swap(a, b);
      } else {  // a tick across a line
        const auto& [p, q] = shown_lines_[index(shown_lines_.size())];
        const Vec3 c = p + uniform(0.1, 0.9) * (q - p);
        const Vec3 side = (q - p).cross(random_direction()).normalized();
        a = c - 0.008 * side;
        b = c + 0.008 * side;
        tick = true;
      }
    }
    aimed_a = a;
    aimed_b = b;
    if (tick) return stroke(id, a, b, 0.002, 0.0005);
    return stroke(id, a + miss(), b + miss(), 0.004, 0.001);
  }

  Vec3 aimed_a = Vec3::Zero(), aimed_b = Vec3::Zero();

 private:
  std::mt19937 rng_;
  std::vector<std::pair<Vec3, Vec3>> shown_lines_;
  std::deque<std::pair<int, int>> box_;
  std::vector<Vec3> box_corner_;   // intended corners
  std::vector<int> box_drawn_;     // per corner: 1 once an edge ended there
  std::vector<Vec3> box_shown_;    // per corner: where the corrected edges put it

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0, 1) < p; }
  std::size_t index(std::size_t n) {
    return std::min(n - 1, static_cast<std::size_t>(uniform(0, static_cast<double>(n))));
  }
  Vec3 random_direction() {
    Vec3 v;
    do v = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    while (v.norm() > 1 || v.norm() < 0.1);
    return v.normalized();
  }
  Vec3 miss() {
    const double r = chance(0.1) ? uniform(0.02, 0.04) : uniform(0.003, 0.02);
    return r * random_direction();
  }
  Vec3 any_keypoint() {
    const auto& [p, q] = shown_lines_[index(shown_lines_.size())];
    const double which = uniform(0, 3);
    return which < 1 ? p : which < 2 ? q : Vec3(0.5 * (p + q));
  }
  Vec3 any_line_direction() {
    const auto& [p, q] = shown_lines_[index(shown_lines_.size())];
    return (q - p).normalized();
  }

  void collect_shown(const Network& network) {
    shown_lines_.clear();
    for (const auto& [id, c] : network.curves())
      if (c.layer == Layer::scaffold && c.curve.kind == CurveKind::line)
        shown_lines_.emplace_back(c.curve.control_points.front(), c.curve.control_points.back());
  }

  void start_box() {
    const double w = uniform(0.1, 0.45), h = uniform(0.1, 0.45), d = uniform(0.1, 0.45);
    const double yaw = uniform(0, std::numbers::pi);
    const Mat3 turn = Eigen::AngleAxisd(yaw, Vec3::UnitY()).toRotationMatrix();
    const Vec3 o(uniform(-1, 1), uniform(0.5, 1.8), uniform(-1, 1));
    box_corner_.clear();
    for (int i = 0; i < 8; ++i)
      box_corner_.push_back(o + turn * Vec3(w * (i == 1 || i == 2 || i == 5 || i == 6), h * (i >= 4),
                                            d * (i == 2 || i == 3 || i == 6 || i == 7)));
    box_drawn_.assign(8, 0);
    box_shown_ = box_corner_;
    box_ = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
            {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  }

  void box_edge(Vec3& a, Vec3& b) {
    const auto [i, j] = box_.front();
    box_.pop_front();
    const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
    a = box_shown_[ui];
    b = box_drawn_[uj] ? box_shown_[uj] : Vec3(a + box_corner_[uj] - box_corner_[ui]);
    box_drawn_[ui] = box_drawn_[uj] = 1;
    pending_ = {i, j};
  }

 public:
  // Tells the generator where the corrected box edge went (call after each
  // stroke with the corrected line's ends; ignored outside boxes).
  void corrected(const Vec3& a, const Vec3& b) {
    if (pending_.first < 0) return;
    box_shown_[static_cast<std::size_t>(pending_.first)] = a;
    box_shown_[static_cast<std::size_t>(pending_.second)] = b;
    pending_ = {-1, -1};
  }

 private:
  std::pair<int, int> pending_{-1, -1};  // the box edge being drawn (corners)

  static Stroke stroke(StrokeId id, const Vec3& a, const Vec3& b, double bow_size, double jitter) {
    Stroke s;
    s.id = id;
    s.layer = Layer::scaffold;
    std::mt19937 local(static_cast<unsigned>(id) * 7919u + 1u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Vec3 bow = bow_size * Vec3(unit(local), unit(local), unit(local));
    const int n = 30;
    for (int i = 0; i <= n; ++i) {
      const double u = static_cast<double>(i) / n;
      Sample smp;
      smp.position = a + (b - a) * u;
      if (i > 0 && i < n)
        smp.position += 4 * u * (1 - u) * bow + jitter * Vec3(unit(local), unit(local), unit(local));
      smp.time = 0.01 * i;
      s.samples.push_back(smp);
    }
    return s;
  }
};

}  // namespace sketchlab::scaffoldsketch::test
