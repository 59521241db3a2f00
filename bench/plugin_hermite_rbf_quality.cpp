// Hermite RBF surfacer: quality on real sketches, one line of figures per
// session. Replays each recording through a stack's corrector (default
// configs/stacks/cassie-hermite_rbf.yaml: CASSIE's network), builds the
// surface of the final network with the stack's surfacer parameters, and
// prints `name value unit` lines per session:
//   curves, constraints, rows, total time (wall, CPU), faces, watertight,
//   boundary edges, area, curve distance (area-weighted mean, p95, max; also
//   relative to the network's bounding-box diagonal), the share of the area
//   outside the network's bounding region (its box grown by 2 % of its
//   diagonal), the share trimmed away, and with --dense the Hausdorff
//   distance to the dense solve's surface (both sides, vertex to nearest
//   vertex, relative to the diagonal).
// Built by plugins/surfacers/hermite_rbf/CMakeLists.txt (it needs the
// plugin's code), hence not named bench_*.cpp.
//
//   hermite_rbf_quality [--stack FILE] [--out DIR] [--dense] [--measure] [name=value ...] [RECORDING|SKETCH.json ...]
//
// Recordings default to data/recordings/*.jsonl of the source tree; a
// sketch.json (as `sketchlab run` writes) is surfaced as it is, without
// replaying. name=value sets a surfacer parameter. --out writes
// DIR/<session>/sketch.json with the surface as its patch (for `sketchlab
// render`). --measure measures the patches already in each sketch.json
// instead of building a surface (the figures of another version's run).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "curve_samples.hpp"
#include "hermite_rbf_params.hpp"
#include "hermite_rbf_surfacer.hpp"
#include "mesh_topology.hpp"
#include "point_tree.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "stage_timer.hpp"
#include "surface_quality.hpp"

using namespace sketchlab;
using namespace sketchlab::hermite_rbf;
namespace fs = std::filesystem;

namespace {

void print(const std::string& name, double value, const char* unit) { std::printf("%s %.6g %s\n", name.c_str(), value, unit); }

// Largest distance from a vertex of `a` to the nearest vertex of `b` (m).
double one_sided(const Mesh& a, const Mesh& b) {
  const PointTree tree(b.vertices);
  double d = 0.0;
  for (const Vec3& v : a.vertices) d = std::max(d, tree.nearest(v).second);
  return d;
}

struct Options {
  fs::path stack = fs::path(SKETCHLAB_SOURCE_DIR) / "configs/stacks/cassie-hermite_rbf.yaml";
  fs::path out;
  bool dense = false;
  bool measure = false;
  std::vector<std::string> overrides;  // surfacer parameters, name=value
  std::vector<fs::path> inputs;
};

Sketch final_sketch(const fs::path& input, const StackConfig& stack, const PluginHost& host) {
  if (input.extension() == ".json") return read_sketch_json(input);
  StackConfig corrector_only = stack;
  corrector_only.surfacer.reset();
  const StackInstance instance = instantiate_stack(corrector_only, host);
  RecordingInput recording(read_recording(input));
  return replay(recording, instance).session.sketch();
}

// The figures of `mesh` against the network's curves (sampled as the
// surfacer samples them).
void measure(const std::string& name, const Mesh& mesh, const Network& network, const HermiteRbfParams& params) {
  std::vector<Vec3> samples;
  for (const CurveSamples& c : sample_curves(network, params.sampling)) samples.insert(samples.end(), c.points.begin(), c.points.end());
  Box3 box;
  for (const Vec3& p : samples) box.extend(p);
  const double diagonal = box.diagonal().norm();
  const SurfaceQuality q = surface_quality(mesh, PointTree(samples), quality_margin * diagonal);
  const MeshTopology t = mesh_topology(mesh);
  print(name + ".faces", double(mesh.faces.size()), "count");
  print(name + ".components", t.components, "count");
  print(name + ".watertight", t.watertight_manifold(), "bool");
  print(name + ".boundary_edges", t.boundary_edges, "count");
  print(name + ".area", q.area, "m2");
  print(name + ".curve_distance_mean", q.distance_mean, "m");
  print(name + ".curve_distance_p95", q.distance_p95, "m");
  print(name + ".curve_distance_max", q.distance_max, "m");
  print(name + ".curve_distance_p95_rel", q.distance_p95 / diagonal, "diagonal");
  print(name + ".curve_distance_max_rel", q.distance_max / diagonal, "diagonal");
  print(name + ".outside_area", 100.0 * q.outside_fraction, "%");
}

void run(const fs::path& input, const Options& o, const StackConfig& stack, const PluginHost& host, const HermiteRbfParams& params) {
  std::string name = input.stem().string();
  if (input.extension() == ".json") name = input.parent_path().parent_path().filename().string();  // runs/<recording>/<stack>/sketch.json
  Sketch sketch = final_sketch(input, stack, host);
  if (o.measure) {
    Mesh all;
    for (const auto& [id, patch] : sketch.network.patches()) {
      const int offset = static_cast<int>(all.vertices.size());
      all.vertices.insert(all.vertices.end(), patch.mesh.vertices.begin(), patch.mesh.vertices.end());
      for (auto f : patch.mesh.faces) all.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    }
    print(name + ".curves", double(sketch.network.curves().size()), "count");
    measure(name, all, sketch.network, params);
    std::fflush(stdout);
    return;
  }
  const StageTimer timer;
  const SurfaceResult r = surface_from_network(sketch.network, params);
  const double wall = timer.wall_ms(), cpu = timer.cpu_ms();
  const auto& s = r.stats;
  print(name + ".curves", s.at("curves"), "count");
  print(name + ".constraints", double(r.constraints.size()), "count");
  print(name + ".rows", double(r.constraints.rows()), "count");
  print(name + ".total.wall", wall, "ms");
  print(name + ".total.cpu", cpu, "ms");
  measure(name, r.mesh, sketch.network, params);
  print(name + ".trimmed_area", 100.0 * s.at("trimmed_area_fraction"), "%");
  print(name + ".residual_point", s.at("residual_point_max"), "m");
  print(name + ".residual_normal", s.at("residual_normal_max"), "1");
  if (o.dense) {
    HermiteRbfParams d = params;
    d.solver = Solver::dense;
    const SurfaceResult reference = surface_from_network(sketch.network, d);
    Box3 box;
    for (const Vec3& p : r.constraints.points) box.extend(p);
    const double h = std::max(one_sided(r.mesh, reference.mesh), one_sided(reference.mesh, r.mesh));
    print(name + ".hausdorff_dense", h, "m");
    print(name + ".hausdorff_dense_rel", h / box.diagonal().norm(), "diagonal");
  }
  std::fflush(stdout);
  if (!o.out.empty()) {
    Edit e;
    for (const auto& [id, patch] : sketch.network.patches()) e.patches_removed.push_back(id);
    Patch p;
    p.id = sketch.network.next_patch_id();
    p.automatic = true;
    for (const auto& [id, nc] : sketch.network.curves()) p.boundary.push_back({id, 0.0, 0.0, 0, 0});
    p.mesh = r.mesh;
    e.patches_added.push_back(std::move(p));
    sketch.network.apply(e);
    fs::create_directories(o.out / name);
    std::ofstream(o.out / name / "sketch.json") << sketch_to_json(sketch);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--stack" || a == "--out") && i + 1 < argc) {
      (a == "--stack" ? o.stack : o.out) = argv[++i];
    } else if (a == "--dense") {
      o.dense = true;
    } else if (a == "--measure") {
      o.measure = true;
    } else if (a.find('=') != std::string::npos) {
      o.overrides.push_back(a);
    } else if (a.starts_with("-")) {
      std::fprintf(stderr, "usage: hermite_rbf_quality [--stack FILE] [--out DIR] [--dense] [--measure] [name=value ...] [RECORDING|SKETCH.json ...]\n");
      return 2;
    } else {
      o.inputs.push_back(a);
    }
  }
  if (o.inputs.empty()) {
    for (const auto& e : fs::directory_iterator(fs::path(SKETCHLAB_SOURCE_DIR) / "data/recordings"))
      if (e.path().extension() == ".jsonl") o.inputs.push_back(e.path());
    std::sort(o.inputs.begin(), o.inputs.end());
  }
  try {
    PluginHost host;
    host.load_directories(PluginHost::default_search_paths());
    std::vector<Override> overrides;
    for (const std::string& kv : o.overrides) overrides.push_back(parse_override("surfacer.params." + kv));
    const StackConfig stack = load_stack(o.stack, overrides);
    if (!stack.surfacer || stack.surfacer->plugin != "hermite_rbf")
      throw ConfigError(o.stack.string() + ": the stack's surfacer must be hermite_rbf");
    std::map<std::string, ParamValue> given = stack.surfacer->params;
    const HermiteRbfParams params = hermite_rbf_params(validate_params(hermite_rbf_param_specs(), given));
    int failed = 0;
    for (const fs::path& input : o.inputs) {
      try {
        run(input, o, stack, host, params);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "hermite_rbf_quality: %s: %s\n", input.string().c_str(), e.what());
        ++failed;
      }
    }
    return failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hermite_rbf_quality: %s\n", e.what());
    return 2;
  }
}
