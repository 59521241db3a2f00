// Hermite RBF surfacer: solve and meshing time against the number of curve
// samples (JustDrawIt §6 sampling) and the grid resolution. Prints
// `name value unit` lines. Built by plugins/surfacers/hermite_rbf/CMakeLists.txt
// (it needs the plugin's code), hence not named bench_*.cpp.
//
// Sketch: 3 principal ellipses + 4 more meridians + 2 parallels of an
// ellipsoid (semi-axes 0.3, 0.2, 0.25 m), 9 curves, sampled to a given total
// count; normals from JustDrawIt's default rules (every curve is planar).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

#include "hermite_rbf_surfacer.hpp"
#include "sketchlab/geometry/arclength.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;

namespace {

Curve ellipse(const Vec3& c, const Vec3& u, const Vec3& v) {
  // A closed interpolating poly-Bézier through 64 points (Catmull-Rom handles).
  const int K = 64;
  std::vector<Vec3> p;
  for (int k = 0; k < K; ++k) {
    const double a = 2.0 * std::numbers::pi * k / K;
    p.push_back(c + std::cos(a) * u + std::sin(a) * v);
  }
  Curve curve;
  for (int k = 0; k < K; ++k) {
    const Vec3& a = p[static_cast<std::size_t>(k)];
    const Vec3& b = p[static_cast<std::size_t>((k + 1) % K)];
    const Vec3 ta = (b - p[static_cast<std::size_t>((k + K - 1) % K)]) / 6.0;
    const Vec3 tb = (p[static_cast<std::size_t>((k + 2) % K)] - a) / 6.0;
    if (k == 0) curve.control_points.push_back(a);
    curve.control_points.push_back(a + ta);
    curve.control_points.push_back(b - tb);
    curve.control_points.push_back(k + 1 == K ? curve.control_points.front() : b);
  }
  curve.sharp.assign(K + 1, false);
  curve.closed = true;
  return curve;
}

Network ellipsoid_sketch() {
  const Vec3 r(0.3, 0.2, 0.25);
  std::vector<Curve> curves;
  curves.push_back(ellipse(Vec3::Zero(), Vec3(r.x(), 0, 0), Vec3(0, r.y(), 0)));
  curves.push_back(ellipse(Vec3::Zero(), Vec3(0, r.y(), 0), Vec3(0, 0, r.z())));
  curves.push_back(ellipse(Vec3::Zero(), Vec3(0, 0, r.z()), Vec3(r.x(), 0, 0)));
  for (int m = 1; m <= 6; ++m) {
    if (m == 3 || m == 6) continue;  // the x-y and y-z planes are already there
    const double a = std::numbers::pi * m / 6.0;
    curves.push_back(ellipse(Vec3::Zero(), Vec3(r.x() * std::cos(a), 0, r.z() * std::sin(a)), Vec3(0, r.y(), 0)));
  }
  for (double h : {-0.6, 0.6}) {
    const double s = std::sqrt(1.0 - h * h);
    curves.push_back(ellipse(Vec3(0, h * r.y(), 0), Vec3(s * r.x(), 0, 0), Vec3(0, 0, s * r.z())));
  }
  Network net;
  Edit e;
  CurveId id = 1;
  for (Curve& c : curves) {
    NetworkCurve nc;
    nc.id = id++;
    nc.curve = std::move(c);
    nc.keypoints = default_keypoints(nc.curve);
    e.curves_added.push_back(std::move(nc));
  }
  net.apply(e);
  return net;
}

double total_length(const Network& net) {
  double l = 0.0;
  for (const auto& [id, nc] : net.curves()) l += arclength(nc.curve);
  return l;
}

void run(const std::string& name, const Network& net, const HermiteRbfParams& params) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const SurfaceResult r = surface_from_network(net, params);
  const double total = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double cpu = 1000.0 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const auto& s = r.stats;
  std::printf("%s.samples %.0f count\n", name.c_str(), s.at("samples"));
  std::printf("%s.constraints %zu count\n", name.c_str(), r.constraints.size());
  std::printf("%s.rows %.0f count\n", name.c_str(), s.at("unknowns"));
  std::printf("%s.solve %.1f ms\n", name.c_str(), s.at("solve_ms"));
  std::printf("%s.evaluate %.1f ms\n", name.c_str(), s.at("eval_ms"));
  std::printf("%s.evaluated_nodes %.1f %%\n", name.c_str(), 100.0 * s.at("grid_evaluated_fraction"));
  std::printf("%s.mesh %.1f ms\n", name.c_str(), s.at("mesh_ms"));
  std::printf("%s.total %.1f ms\n", name.c_str(), total);
  // CPU time of all threads: on a shared machine the wall time above includes waiting.
  std::printf("%s.cpu %.1f ms\n", name.c_str(), cpu);
  std::printf("%s.faces %.0f count\n", name.c_str(), s.at("mesh_faces"));
  std::printf("%s.watertight %.0f bool\n", name.c_str(), s.at("watertight"));
  std::printf("%s.residual_point %.2e m\n", name.c_str(), s.at("residual_point_max"));
  std::printf("%s.residual_normal %.2e 1\n", name.c_str(), s.at("residual_normal_max"));
  std::fflush(stdout);
}

}  // namespace

int main() {
  const Network net = ellipsoid_sketch();
  const double length = total_length(net);
  for (int samples : {200, 1000, 2000}) {
    for (int res : {64, 128}) {
      HermiteRbfParams p;
      p.sampling.sample_spacing = length / samples;
      p.sampling.max_samples = samples;
      p.mesh.resolution = res;
      run("hermite_rbf.s" + std::to_string(samples) + ".r" + std::to_string(res), net, p);
    }
  }
  // 2,000 samples, each a point constraint and every third a normal: ~2,000
  // point + ~670 normal constraints (~4,000 rows), far denser than §6.
  for (int res : {64, 128}) {
    HermiteRbfParams p;
    p.sampling.sample_spacing = length / 2000;
    p.sampling.max_samples = 2000;
    p.sampling.point_stride = 1;
    p.sampling.normal_stride = 3;
    p.sampling.tangent_stride = 3;
    p.mesh.resolution = res;
    run("hermite_rbf.dense2000.r" + std::to_string(res), net, p);
  }
  return 0;
}
