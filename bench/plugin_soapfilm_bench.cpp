// Soapfilm surfacer benchmark (built from plugins/surfacers/soapfilm as
// soapfilm_bench). Sketches of 100 and 2,000 curves made of 5x5 curve grids
// ("tiles") on a wavy surface, every cycle already a patch. Measures the time
// to mesh one patch (p50, p95, and per stage) and the upkeep per edit (adding
// a curve across one tile, then deleting it), split into meshing and the
// graph/cycle part (searches, crossed patches, bookkeeping), which should not
// depend on the sketch size. Prints "name value unit" lines.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "boundary_polyline.hpp"
#include "patch_mesh.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/lab/distribution.hpp"
#include "sketchlab/network_curve.hpp"
#include "soapfilm_surfacer.hpp"

namespace {

using namespace sketchlab;
using clock_type = std::chrono::steady_clock;

// CPU time of this thread (ms): the build machine is shared, so wall times
// swing with its load; CPU time does not.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double height(double x, double y) { return 0.03 * std::sin(6.0 * x) * std::cos(5.0 * y); }

// A curve along x (dir 0) or y (dir 1) at the given offset, K cubic pieces
// whose parameter is linear in the running coordinate.
Curve grid_curve(int dir, double offset, double from, double to, int K) {
  Curve c;
  for (int i = 0; i <= 3 * K; ++i) {
    const double s = from + (to - from) * i / (3.0 * K);
    const double x = dir == 0 ? s : offset, y = dir == 0 ? offset : s;
    c.control_points.emplace_back(x, y, height(x, y));
  }
  c.sharp.assign(static_cast<std::size_t>(K + 1), false);
  return c;
}

struct Tile {
  double x0, y0;
};
constexpr int lines = 5;
constexpr double size = 0.4, step = size / (lines - 1);

// Curves and nodes of one tile (ids from the counters of `edit`-to-be).
void add_tile(Edit& e, const Tile& tile, CurveId& next_curve, NodeId& next_node) {
  std::vector<CurveId> xs, ys;
  for (int dir = 0; dir < 2; ++dir)
    for (int i = 0; i < lines; ++i) {
      const double off = (dir == 0 ? tile.y0 : tile.x0) + i * step;
      const double from = dir == 0 ? tile.x0 : tile.y0;
      NetworkCurve nc =
          make_network_curve(next_curve++, grid_curve(dir, off, from, from + size, lines - 1), Layer::free);
      (dir == 0 ? xs : ys).push_back(nc.id);
      e.curves_added.push_back(std::move(nc));
    }
  for (int i = 0; i < lines; ++i)
    for (int j = 0; j < lines; ++j) {
      Node n;
      n.id = next_node++;
      const double x = tile.x0 + j * step, y = tile.y0 + i * step;
      n.position = Vec3(x, y, height(x, y));
      n.incidences = {{xs[static_cast<std::size_t>(i)], static_cast<double>(j)},
                      {ys[static_cast<std::size_t>(j)], static_cast<double>(i)}};
      e.nodes_added.push_back(n);
    }
}

void run(int curves, const soapfilm::SoapfilmParams& params) {
  const int tiles = curves / (2 * lines);
  const int per_row = static_cast<int>(std::ceil(std::sqrt(tiles)));
  Sketch sketch;
  Edit e;
  CurveId nc = 1;
  NodeId nn = 1;
  std::vector<Tile> placed;
  for (int t = 0; t < tiles; ++t) {
    placed.push_back({(t % per_row) * (size + 0.2), (t / per_row) * (size + 0.2)});
    add_tile(e, placed.back(), nc, nn);
  }
  sketch.network.apply(e);
  // Every cycle is a patch (boundaries only: the upkeep reads boundaries).
  Edit patches;
  PatchId pid = 1;
  for (auto& cycle : soapfilm::detect_all_cycles(sketch.network, params.search)) {
    Patch p;
    p.id = pid++;
    p.boundary = std::move(cycle);
    patches.patches_added.push_back(std::move(p));
  }
  const std::size_t patch_count = patches.patches_added.size();
  sketch.network.apply(patches);

  // Time per patch: mesh the patches of the first tiles, by stage.
  std::vector<double> per_patch, per_patch_cpu, fill, remesh, smooth, output, border_points;
  for (const auto& [id, p] : sketch.network.patches()) {
    if (per_patch.size() >= 64) break;
    const auto t0 = clock_type::now();
    const double c0 = cpu_ms();
    auto made = soapfilm::make_patch(sketch.network, id, p.boundary, true, params);
    per_patch_cpu.push_back(cpu_ms() - c0);
    per_patch.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t0).count());
    if (!made) std::cerr << "mesh failed for patch " << id << "\n";
    // The same patch again, stage by stage.
    const auto poly = soapfilm::boundary_polyline(sketch.network, p.boundary, params.edge_length,
                                                  params.max_boundary_points);
    soapfilm::PatchMeshTimings t;
    soapfilm::patch_mesh(poly.points, poly.spacing, params.mesh, &t);
    fill.push_back(t.fill_ms);
    remesh.push_back(t.remesh_ms);
    smooth.push_back(t.smooth_ms);
    output.push_back(t.output_ms);
    border_points.push_back(static_cast<double>(poly.points.size()));
  }

  // Upkeep per edit: a y-curve through the middle of a tile's first column
  // of cells, crossing the 5 x-curves (splits 4 patches into 8); then the
  // same curve deleted (its 8 patches go with it, the 4 come back). The edits
  // are recorded in the history as a session would, so the deletion reads it.
  std::vector<double> upkeep, search, mesh, walk, del_upkeep, del_search;
  std::vector<double> upkeep_cpu, graph_cpu, del_graph_cpu;
  const int edits = std::min(tiles, 20);
  for (int k = 0; k < edits; ++k) {
    const Tile& tile = placed[static_cast<std::size_t>(k * tiles / edits)];
    Edit add;
    const double x = tile.x0 + 0.5 * step;
    const NetworkCurve c = make_network_curve(sketch.network.next_curve_id(),
                                              grid_curve(1, x, tile.y0, tile.y0 + size, lines - 1), Layer::free);
    add.curves_added.push_back(c);
    NodeId id = sketch.network.next_node_id();
    // The x-curves of this tile: ids in order of creation.
    const CurveId first = 1 + static_cast<CurveId>(k * tiles / edits) * 2 * lines;
    for (int i = 0; i < lines; ++i) {
      Node n;
      n.id = id++;
      const double y = tile.y0 + i * step;
      n.position = Vec3(x, y, height(x, y));
      n.incidences = {{c.id, static_cast<double>(i)}, {first + static_cast<CurveId>(i), 0.5}};
      add.nodes_added.push_back(n);
    }
    const Edit undo = sketch.network.apply(add);
    double c0 = cpu_ms();
    soapfilm::patch_upkeep(sketch, add, params.search);  // the graph/cycle part alone
    graph_cpu.push_back(cpu_ms() - c0);
    auto t0 = clock_type::now();
    c0 = cpu_ms();
    const SurfaceUpdate up = soapfilm::soapfilm_update(sketch, add, params);
    upkeep_cpu.push_back(cpu_ms() - c0);
    upkeep.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t0).count());
    search.push_back(up.stats.at("search_ms"));
    mesh.push_back(up.stats.at("mesh_ms"));
    walk.push_back(up.stats.at("walk_ms"));
    if (k == 0)
      std::cout << "soapfilm." << curves << ".edit_patches_added " << up.edit.patches_added.size()
                << " patches\nsoapfilm." << curves << ".edit_patches_removed "
                << up.edit.patches_removed.size() << " patches\n";
    const Edit undo_patches = sketch.network.apply(up.edit);
    sketch.history.done.push_back({"stroke", std::nullopt, {{add, undo}, {up.edit, undo_patches}}});

    Edit del;
    del.curves_removed = {c.id};
    const Edit undo_del = sketch.network.apply(del);
    c0 = cpu_ms();
    soapfilm::patch_upkeep(sketch, del, params.search);
    del_graph_cpu.push_back(cpu_ms() - c0);
    t0 = clock_type::now();
    const SurfaceUpdate dup = soapfilm::soapfilm_update(sketch, del, params);
    del_upkeep.push_back(std::chrono::duration<double, std::milli>(clock_type::now() - t0).count());
    del_search.push_back(dup.stats.at("search_ms"));
    if (k == 0)
      std::cout << "soapfilm." << curves << ".delete_patches_added " << dup.edit.patches_added.size()
                << " patches\n";
    sketch.network.apply(undo_del);
    sketch.network.apply(undo_patches);
    sketch.network.apply(undo);
    sketch.history.done.pop_back();
  }
  const std::string p = "soapfilm." + std::to_string(curves);
  auto print = [&](const std::string& name, const std::vector<double>& v, const char* unit) {
    const Distribution d = distribution(v);
    std::cout << p << "." << name << "_p50 " << d.median << " " << unit << "\n"
              << p << "." << name << "_p95 " << d.p95 << " " << unit << "\n";
  };
  std::cout << p << ".curves " << sketch.network.curves().size() << " curves\n"
            << p << ".patches " << patch_count << " patches\n"
            << p << ".mesh_border_points " << distribution(border_points).median << " points\n";
  print("mesh_per_patch", per_patch, "ms");
  print("mesh_per_patch_cpu", per_patch_cpu, "ms");
  print("mesh_fill", fill, "ms");
  print("mesh_remesh", remesh, "ms");
  print("mesh_smooth", smooth, "ms");
  print("mesh_output", output, "ms");
  print("upkeep_per_edit", upkeep, "ms");
  print("upkeep_meshing_per_edit", mesh, "ms");
  print("upkeep_graph_cycles_per_edit", search, "ms");
  print("upkeep_walks_per_edit", walk, "ms");
  print("upkeep_per_edit_cpu", upkeep_cpu, "ms");
  print("upkeep_graph_cycles_per_edit_cpu", graph_cpu, "ms");
  print("delete_upkeep_per_edit", del_upkeep, "ms");
  print("delete_graph_cycles_per_edit", del_search, "ms");
  print("delete_graph_cycles_per_edit_cpu", del_graph_cpu, "ms");
}

}  // namespace

int main() {
  const soapfilm::SoapfilmParams params;
  run(100, params);
  run(2000, params);
  return 0;
}
