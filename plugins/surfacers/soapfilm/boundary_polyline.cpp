#include "boundary_polyline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "curve_graph.hpp"
#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::soapfilm {

std::vector<double> piece_parameters(const Network& network, const OrientedSegment& piece, int n) {
  const NetworkCurve* nc = network.find_curve(piece.curve);
  if (!nc) throw std::invalid_argument("boundary: curve " + std::to_string(piece.curve) + " does not exist");
  const Curve& c = nc->curve;
  n = std::max(n, 2);
  double a = piece.t_from, b = piece.t_to;
  if (c.closed) {
    const double T = c.t_max();
    if (a == b) {
      b = a + T;  // a single node closing the whole loop
    } else {
      CurveGraph graph(network);
      bool wraps = false;
      graph.covered_by(piece, &wraps);
      if (wraps) b = a < b ? b - T : b + T;
    }
  }
  std::vector<double> t(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    t[static_cast<std::size_t>(i)] = wrap_parameter(c, a + (b - a) * i / (n - 1));
  t.front() = piece.t_from;
  t.back() = piece.t_to;
  return t;
}

BoundaryPolyline boundary_polyline(const Network& network, const std::vector<OrientedSegment>& boundary,
                                   double spacing, int max_points) {
  if (boundary.empty()) throw std::invalid_argument("boundary: empty cycle");
  // Dense samples per piece give arclength tables.
  std::vector<std::vector<double>> params;
  std::vector<std::vector<double>> lengths;
  double total = 0.0;
  for (const OrientedSegment& piece : boundary) {
    const Curve& c = network.find_curve(piece.curve) ? network.find_curve(piece.curve)->curve : Curve{};
    const std::vector<double> t = piece_parameters(network, piece, 64 + 1);
    std::vector<double> s{0.0};
    for (std::size_t i = 1; i < t.size(); ++i)
      s.push_back(s.back() + (evaluate(c, t[i]) - evaluate(c, t[i - 1])).norm());
    total += s.back();
    params.push_back(t);
    lengths.push_back(std::move(s));
  }
  if (!(total > 0.0) || !std::isfinite(total)) throw std::invalid_argument("boundary: zero length cycle");
  BoundaryPolyline out;
  auto points_of = [](double length, double step) {
    return std::max(1, static_cast<int>(std::ceil(length / step - 1e-9)));
  };
  auto count = [&](double step) {
    int n = 0;
    for (const auto& s : lengths) n += points_of(s.back(), step);
    return n;
  };
  out.spacing = std::max(spacing, total / std::max(3, max_points));
  // Rounding up per piece can exceed the cap by up to one point per piece:
  // widen the spacing until it holds (a cycle with more pieces than the cap
  // keeps one point per piece).
  for (int i = 0; i < 200 && count(out.spacing) > std::max(max_points, static_cast<int>(boundary.size())); ++i)
    out.spacing *= 1.02;
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Curve& c = network.find_curve(boundary[k].curve)->curve;
    const auto& t = params[k];
    const auto& s = lengths[k];
    const int n = points_of(s.back(), out.spacing);
    // Points 0..n-1 of this piece (its end is the next piece's start).
    std::size_t j = 0;
    for (int i = 0; i < n; ++i) {
      const double target = s.back() * i / n;
      while (j + 2 < s.size() && s[j + 1] < target) ++j;
      const double ds = s[j + 1] - s[j];
      const double u = ds > 0.0 ? std::clamp((target - s[j]) / ds, 0.0, 1.0) : 0.0;
      double tj = t[j], tk = t[j + 1];
      // Interpolate across the seam the short way.
      if (c.closed && std::abs(tk - tj) > 0.5 * c.t_max()) tk += tk < tj ? c.t_max() : -c.t_max();
      out.points.push_back(evaluate(c, wrap_parameter(c, tj + u * (tk - tj))));
    }
  }
  // Sampling at chord length: the arc between samples can exceed the chord
  // spacing slightly; report the longest border edge.
  double longest = 0.0;
  for (std::size_t i = 0; i < out.points.size(); ++i)
    longest = std::max(longest, (out.points[(i + 1) % out.points.size()] - out.points[i]).norm());
  out.spacing = std::max(out.spacing, longest);
  return out;
}

}  // namespace sketchlab::soapfilm
