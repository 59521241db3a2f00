// Hermite RBF surfacer: wall and CPU time per stage, and peak memory, against
// the number of constraints (partition of unity against the dense solve), and
// the per-stroke incremental update at 100 and 2,000 curves. Prints
// `name value unit` lines. Built by plugins/surfacers/hermite_rbf/CMakeLists.txt
// (it needs the plugin's code), hence not named bench_*.cpp.
//
// Every case runs in its own process (fork), so `rss` is that case's peak
// resident memory. `threads` is 1 unless given: "on one core".
//
//   hermite_rbf_bench [case ...] [name=value ...]
//     cases: c2000 c20000 dense2000 stroke100 stroke2000 (default: all);
//     name=value: a plugin parameter (`sketchlab plugins hermite_rbf`) for
//     every case, e.g. pu_min_rows=120 or threads=2 (sampling and resolution
//     are the cases' own).
//
// Sketches: curves on an ellipsoid (semi-axes 0.3, 0.2, 0.25 m) carrying its
// exact normals (as JustDrawIt exports them), so the figures measure the
// solver, not the default normal rules.
//  * lattice(m, p): m meridians and p parallels, each edge between two
//    crossings one curve, crossings as nodes: about 2·m·p curves.
//  * cK: lattice(6, 5) (≈ 60 curves), sampled so that §6's rules give ≈ K
//    constraints; 128³ grid.
//  * dense2000: the 9-curve sketch of the first version of this bench, every
//    sample a point constraint and every third a normal (≈ 2,000 points +
//    670 normals, 4,000 rows): the "2,000 dense curve samples".
//  * strokeN: lattice with ≈ N curves at the default sampling, 64³ grid, then
//    one more stroke (a short arc across a few lattice cells); the update with
//    the previous surface's state against a rebuild from scratch, and whether
//    both meshes are identical.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "hermite_rbf_params.hpp"
#include "hermite_rbf_surfacer.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "stage_timer.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;

namespace {

const Vec3 semi_axes(0.3, 0.2, 0.25);

// Point and outward unit normal of the ellipsoid at (longitude u, latitude v).
Vec3 ellipsoid_point(double u, double v) {
  return Vec3(semi_axes.x() * std::cos(v) * std::cos(u), semi_axes.y() * std::sin(v), semi_axes.z() * std::cos(v) * std::sin(u));
}
Vec3 ellipsoid_normal(const Vec3& p) { return p.cwiseQuotient(semi_axes.cwiseProduct(semi_axes)).normalized(); }

// An interpolating poly-Bézier (Catmull-Rom handles) through K + 1 points of
// path(s), s in [0, 1], with the ellipsoid's normal at every joint.
NetworkCurve path_curve(CurveId id, const std::function<Vec3(double)>& path, int K, bool closed) {
  std::vector<Vec3> p;
  const int count = closed ? K : K + 1;
  for (int k = 0; k < count; ++k) p.push_back(path(double(k) / K));
  auto at = [&](int k) -> const Vec3& {
    if (closed) return p[static_cast<std::size_t>(((k % K) + K) % K)];
    return p[static_cast<std::size_t>(std::clamp(k, 0, K))];
  };
  NetworkCurve nc;
  nc.id = id;
  for (int k = 0; k < K; ++k) {
    if (k == 0) nc.curve.control_points.push_back(at(0));
    nc.curve.control_points.push_back(at(k) + (at(k + 1) - at(k - 1)) / 6.0);
    nc.curve.control_points.push_back(at(k + 1) - (at(k + 2) - at(k)) / 6.0);
    nc.curve.control_points.push_back(closed && k + 1 == K ? nc.curve.control_points.front() : at(k + 1));
  }
  nc.curve.sharp.assign(static_cast<std::size_t>(K + 1), false);
  nc.curve.closed = closed;
  nc.keypoints = default_keypoints(nc.curve);
  for (int k = 0; k <= K; ++k) nc.normals.push_back({double(k), ellipsoid_normal(at(k))});
  return nc;
}

Network lattice(int meridians, int parallels) {
  Edit e;
  CurveId id = 1;
  NodeId node_id = 1;
  // Crossings at longitudes 2π i / m and latitudes ±(π/2)(j + 1)/(p + 1).
  auto lon = [&](int i) { return 2.0 * std::numbers::pi * i / meridians; };
  auto lat = [&](int j) { return std::numbers::pi * ((j + 1.0) / (parallels + 1.0) - 0.5); };
  std::vector<std::vector<std::vector<NodeIncidence>>> at(static_cast<std::size_t>(meridians),
                                                           std::vector<std::vector<NodeIncidence>>(static_cast<std::size_t>(parallels)));
  auto incident = [&](int i, int j, CurveId c, double t) {
    at[static_cast<std::size_t>((i % meridians + meridians) % meridians)][static_cast<std::size_t>(j)].push_back({c, t});
  };
  for (int i = 0; i < meridians; ++i)
    for (int j = 0; j < parallels; ++j) {
      // Along the parallel to the next meridian, and along the meridian to the next parallel.
      e.curves_added.push_back(path_curve(id, [&](double s) { return ellipsoid_point(lon(i) + s * (lon(i + 1) - lon(i)), lat(j)); }, 4, false));
      incident(i, j, id, 0.0), incident(i + 1, j, id, 4.0);
      ++id;
      if (j + 1 < parallels) {
        e.curves_added.push_back(path_curve(id, [&](double s) { return ellipsoid_point(lon(i), lat(j) + s * (lat(j + 1) - lat(j))); }, 4, false));
        incident(i, j, id, 0.0), incident(i, j + 1, id, 4.0);
        ++id;
      }
    }
  for (int i = 0; i < meridians; ++i)
    for (int j = 0; j < parallels; ++j) {
      Node n;
      n.id = node_id++;
      n.position = ellipsoid_point(lon(i), lat(j));
      n.incidences = at[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      e.nodes_added.push_back(n);
    }
  Network net;
  net.apply(e);
  return net;
}

// The 9 closed curves of the first version of this bench: 3 principal
// ellipses, 4 more meridians, 2 parallels.
Network nine_curves() {
  Edit e;
  CurveId id = 1;
  auto ring = [&](const std::function<Vec3(double)>& f) { e.curves_added.push_back(path_curve(id++, f, 64, true)); };
  const double tau = 2.0 * std::numbers::pi;
  ring([&](double s) { return ellipsoid_point(0.0, tau * s); });
  ring([&](double s) { return ellipsoid_point(0.5 * std::numbers::pi, tau * s); });
  ring([&](double s) { return ellipsoid_point(tau * s, 0.0); });
  for (int m : {1, 2, 4, 5}) ring([&, m](double s) { return ellipsoid_point(std::numbers::pi * m / 6.0, tau * s); });
  for (double h : {-0.6, 0.6}) ring([&, h](double s) { return ellipsoid_point(tau * s, std::asin(h)); });
  Network net;
  net.apply(e);
  return net;
}

double total_length(const Network& net) {
  double l = 0.0;
  for (const auto& [id, nc] : net.curves()) l += arclength(nc.curve);
  return l;
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;
}

void print(const std::string& name, double value, const char* unit) { std::printf("%s %.6g %s\n", name.c_str(), value, unit); }

void report(const std::string& name, const SurfaceResult& r, const StageTimer& total) {
  const auto& s = r.stats;
  print(name + ".curves", s.at("curves"), "count");
  print(name + ".constraints", double(r.constraints.size()), "count");
  print(name + ".rows", double(r.constraints.rows()), "count");
  if (s.count("pu_cells")) {
    print(name + ".cells", s.at("pu_cells"), "count");
    print(name + ".cells_fitted", s.at("pu_cells_fitted"), "count");
    print(name + ".cell_rows_max", s.at("pu_max_rows"), "count");
  }
  for (const char* stage : {"constraints", "solve", "eval", "mesh"}) {
    print(name + "." + stage + ".wall", s.at(std::string(stage) + "_ms"), "ms");
    print(name + "." + stage + ".cpu", s.at(std::string(stage) + "_cpu_ms"), "ms");
  }
  print(name + ".total.wall", total.wall_ms(), "ms");
  print(name + ".total.cpu", total.cpu_ms(), "ms");
  print(name + ".grid_nodes", s.at("grid_nodes"), "count");
  print(name + ".evaluated_nodes", 100.0 * s.at("grid_evaluated_fraction"), "%");
  print(name + ".computed_nodes", 100.0 * s.at("grid_computed_fraction"), "%");
  print(name + ".faces", s.at("mesh_faces"), "count");
  print(name + ".residual_point", s.at("residual_point_max"), "m");
  print(name + ".residual_normal", s.at("residual_normal_max"), "1");
  print(name + ".residual_tangent", s.at("residual_tangent_max"), "1");
  print(name + ".regularizer", s.at("regularizer"), "1");
  print(name + ".rss", peak_rss_mb(), "MB");
  std::fflush(stdout);
}

// The plugin's defaults with the command line's name=value overrides; one thread unless given.
std::map<std::string, ParamValue> overrides = {{"threads", std::int64_t{1}}};

HermiteRbfParams base_params(int resolution) {
  HermiteRbfParams p = hermite_rbf_params(validate_params(hermite_rbf_param_specs(), overrides));
  p.mesh.resolution = resolution;
  return p;
}

// Spacing so that §6's rules (a point every 6 samples, a normal every 12)
// give about `constraints` constraints.
HermiteRbfParams sampled_for(const Network& net, int constraints, int resolution) {
  HermiteRbfParams p = base_params(resolution);
  const double samples = 4.0 * constraints;
  p.sampling.sample_spacing = total_length(net) / samples;
  p.sampling.max_samples = static_cast<int>(samples * 1.1);
  return p;
}

void run_case(const std::string& name, const Network& net, const HermiteRbfParams& params) {
  const StageTimer t;
  const SurfaceResult r = surface_from_network(net, params);
  report(name, r, t);
}

void stroke_case(const std::string& name, int meridians, int parallels) {
  Network net = lattice(meridians, parallels);
  HermiteRbfParams p = base_params(64);
  p.sampling.max_samples = 1000000;  // keep the default 5 mm spacing
  SurfaceState state;
  {
    const StageTimer t;
    report(name + ".first", surface_from_network(net, p, &state), t);
  }
  // One stroke: a short arc across a few lattice cells, off the lattice lines.
  Edit e;
  const double u0 = 0.37 * std::numbers::pi, v0 = 0.11;
  e.curves_added.push_back(path_curve(net.next_curve_id(), [&](double s) { return ellipsoid_point(u0 + 0.25 * s, v0 + 0.15 * s); }, 4, false));
  net.apply(e);
  const StageTimer tu;
  const SurfaceResult update = surface_from_network(net, p, &state);
  report(name + ".update", update, tu);
  const StageTimer tf;
  const SurfaceResult fresh = surface_from_network(net, p);
  report(name + ".rebuild", fresh, tf);
  print(name + ".identical", update.mesh.vertices == fresh.mesh.vertices && update.mesh.faces == fresh.mesh.faces, "bool");
  std::fflush(stdout);
}

void run(const std::string& which) {
  if (which == "c2000" || which == "c20000") {
    const int target = which == "c2000" ? 2000 : 20000;
    const Network net = lattice(6, 5);
    run_case(which + ".partition", net, sampled_for(net, target, 128));
    if (target == 2000) {
      HermiteRbfParams d = sampled_for(net, target, 128);
      d.solver = Solver::dense;
      run_case(which + ".dense", net, d);
    }
  } else if (which == "dense2000") {
    const Network net = nine_curves();
    HermiteRbfParams p = base_params(128);
    p.sampling.sample_spacing = total_length(net) / 2000;
    p.sampling.max_samples = 2000;
    p.sampling.point_stride = 1;
    p.sampling.normal_stride = 3;
    p.sampling.tangent_stride = 3;
    run_case(which + ".partition", net, p);
    p.solver = Solver::dense;
    run_case(which + ".dense", net, p);
  } else if (which == "stroke100") {
    stroke_case(which, 8, 6);  // 8·6 + 8·5 = 88 curves, +1 stroke
  } else if (which == "stroke2000") {
    stroke_case(which, 36, 28);  // 36·28 + 36·27 = 1980 curves
  } else {
    std::fprintf(stderr, "hermite_rbf_bench: unknown case '%s' (c2000 c20000 dense2000 stroke100 stroke2000)\n", which.c_str());
    std::exit(2);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> cases;
  try {
    const std::vector<ParamSpec> specs = hermite_rbf_param_specs();
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      const auto eq = arg.find('=');
      if (eq == std::string::npos) {
        cases.push_back(arg);
        continue;
      }
      const std::string name = arg.substr(0, eq);
      const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == name; });
      if (spec == specs.end()) throw ParamError(name, "unknown parameter '" + name + "' (see `sketchlab plugins hermite_rbf`)");
      overrides[name] = parse_param_value(*spec, arg.substr(eq + 1));
    }
    base_params(64);  // checks the combination once
  } catch (const ParamError& e) {
    std::fprintf(stderr, "hermite_rbf_bench: %s\n", e.what());
    return 2;
  }
  if (cases.empty()) cases = {"c2000", "c20000", "dense2000", "stroke100", "stroke2000"};
  int failed = 0;
  for (const std::string& c : cases) {
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
      try {
        run(c);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "hermite_rbf_bench: %s: %s\n", c.c_str(), e.what());
        _exit(1);
      }
      std::fflush(stdout);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::fprintf(stderr, "hermite_rbf_bench: case %s failed\n", c.c_str());
      ++failed;
    }
  }
  return failed ? 1 : 0;
}
