#pragma once
// Shapes for the Hermite RBF tests: curves added straight to a network.
#include <cmath>
#include <numbers>
#include <vector>

#include "sketchlab/network.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::hermite_rbf_test {

// A closed poly-Bézier circle (K quarter-or-smaller arcs; radial error
// ~1e-6 R for K = 8) of radius r around c in the plane spanned by unit u, v.
inline Curve circle(const Vec3& c, double r, const Vec3& u, const Vec3& v, int K = 8) {
  Curve curve;
  const double step = 2.0 * std::numbers::pi / K;
  const double handle = 4.0 / 3.0 * std::tan(step / 4.0) * r;
  auto at = [&](double a) -> Vec3 { return c + r * (std::cos(a) * u + std::sin(a) * v); };
  auto dir = [&](double a) { return (-std::sin(a) * u + std::cos(a) * v).eval(); };
  for (int k = 0; k < K; ++k) {
    const double a0 = k * step, a1 = (k + 1) * step;
    if (k == 0) curve.control_points.push_back(at(a0));
    curve.control_points.push_back(at(a0) + handle * dir(a0));
    curve.control_points.push_back(at(a1) - handle * dir(a1));
    curve.control_points.push_back(k + 1 == K ? curve.control_points.front() : at(a1));
  }
  curve.sharp.assign(static_cast<std::size_t>(K + 1), false);
  curve.closed = true;
  return curve;
}

// The first `arcs` of the K arcs of circle(c, r, u, v, K): an open arc from
// c + r·u turning towards v.
inline Curve arc(const Vec3& c, double r, const Vec3& u, const Vec3& v, int arcs, int K = 8) {
  Curve curve = circle(c, r, u, v, K);
  curve.control_points.resize(static_cast<std::size_t>(3 * arcs + 1));
  curve.sharp.assign(static_cast<std::size_t>(arcs + 1), false);
  curve.closed = false;
  return curve;
}

inline NetworkCurve network_curve(CurveId id, Curve c, std::vector<CurveNormal> normals = {}) {
  NetworkCurve nc = make_network_curve(id, std::move(c), Layer::free);
  nc.normals = std::move(normals);
  return nc;
}

inline Network network_of(std::vector<NetworkCurve> curves, std::vector<Node> nodes = {}) {
  Network net;
  Edit e;
  e.curves_added = std::move(curves);
  e.nodes_added = std::move(nodes);
  net.apply(e);
  return net;
}

// Three great circles of a sphere (xy, yz, zx planes), no exported normals.
inline Network sphere_circles(const Vec3& c, double r) {
  return network_of({network_curve(1, circle(c, r, Vec3::UnitX(), Vec3::UnitY())),
                     network_curve(2, circle(c, r, Vec3::UnitY(), Vec3::UnitZ())),
                     network_curve(3, circle(c, r, Vec3::UnitZ(), Vec3::UnitX()))});
}

// The 12 edges of the cube c ± a, each with the normal of its two faces
// (their bisector, the one normal a point of a smooth surface can have).
inline Network cube_edges(const Vec3& c, double a) {
  std::vector<NetworkCurve> curves;
  CurveId id = 1;
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {-1, 1})
      for (int s2 : {-1, 1}) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        Vec3 p = c, n = Vec3::Zero();
        p[u] += s1 * a;
        p[v] += s2 * a;
        n[u] = s1;
        n[v] = s2;
        n.normalize();
        Vec3 q0 = p, q1 = p;
        q0[axis] -= a;
        q1[axis] += a;
        curves.push_back(network_curve(id++, make_line(q0, q1), {{0.0, n}, {1.0, n}}));
      }
  return network_of(std::move(curves));
}

// Square loops around the cube c ± a, perpendicular to each axis at the given
// heights (× a), with the normal of the face each side lies on.
inline std::vector<NetworkCurve> cube_face_loops(const Vec3& c, double a, const std::vector<double>& levels, CurveId first_id) {
  std::vector<NetworkCurve> out;
  for (int axis = 0; axis < 3; ++axis)
    for (double level : levels) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int su[4] = {1, -1, -1, 1}, sv[4] = {1, 1, -1, -1};
      Vec3 corners[4];
      for (int k = 0; k < 4; ++k) {
        corners[k] = c;
        corners[k][axis] += level * a;
        corners[k][u] += su[k] * a;
        corners[k][v] += sv[k] * a;
      }
      Curve loop;
      std::vector<CurveNormal> normals;
      for (int k = 0; k < 4; ++k) {
        const Vec3 p = corners[k], q = corners[(k + 1) % 4];
        if (k == 0) loop.control_points.push_back(p);
        loop.control_points.push_back(p + (q - p) / 3.0);
        loop.control_points.push_back(p + 2.0 * (q - p) / 3.0);
        loop.control_points.push_back(k == 3 ? loop.control_points.front() : q);
        // Side k runs along u or v at the face where the other coordinate is fixed.
        const int fixed = su[k] == su[(k + 1) % 4] ? u : v;
        Vec3 n = Vec3::Zero();
        n[fixed] = (p[fixed] - c[fixed]) > 0.0 ? 1.0 : -1.0;
        for (double f : {0.05, 0.5, 0.95}) normals.push_back({k + f, n});
      }
      loop.sharp.assign(5, true);
      loop.closed = true;
      out.push_back(network_curve(first_id++, loop, normals));
    }
  return out;
}

// A smooth closed poly-Bézier through points (Catmull-Rom handles).
inline Curve smooth_closed(const std::vector<Vec3>& p) {
  const int K = static_cast<int>(p.size());
  auto at = [&](int k) -> const Vec3& { return p[static_cast<std::size_t>(((k % K) + K) % K)]; };
  Curve curve;
  for (int k = 0; k < K; ++k) {
    if (k == 0) curve.control_points.push_back(at(0));
    curve.control_points.push_back(at(k) + (at(k + 1) - at(k - 1)) / 6.0);
    curve.control_points.push_back(at(k + 1) - (at(k + 2) - at(k)) / 6.0);
    curve.control_points.push_back(k + 1 == K ? curve.control_points.front() : at(k + 1));
  }
  curve.sharp.assign(static_cast<std::size_t>(K + 1), false);
  curve.closed = true;
  return curve;
}

}  // namespace sketchlab::hermite_rbf_test
