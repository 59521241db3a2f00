#include "hermite_rbf_surfacer.hpp"

#include <chrono>
#include <limits>
#include <optional>
#include <stdexcept>

#include "curve_normals.hpp"
#include "curve_samples.hpp"
#include "grid_evaluation.hpp"
#include "mesh_topology.hpp"
#include "parallel_for.hpp"
#include "point_tree.hpp"
#include "sketchlab/plugin/budget.hpp"
#include "stage_timer.hpp"
#include "surface_quality.hpp"
#include "surface_trim.hpp"
#include "zero_set_mesh.hpp"

namespace sketchlab::hermite_rbf {
SurfaceResult surface_from_constraints(const HermiteConstraints& input, const std::vector<Vec3>& curve_points,
                                       const HermiteRbfParams& params, SurfaceState* state) {
  SurfaceResult out;
  check_constraints(input);
  out.constraints = canonical_order(input);
  const HermiteConstraints& constraints = out.constraints;
  auto& s = out.stats;

  Box3 box;
  for (const Vec3& p : constraints.points) box.extend(p);
  for (const Vec3& p : constraints.normal_points) box.extend(p);
  for (const Vec3& p : constraints.tangent_points) box.extend(p);
  const double diagonal = box.diagonal().norm();
  const GridSpec spec = grid_around(box, params.mesh.padding * diagonal, params.mesh.resolution);

  StageTimer solve_timer;
  std::optional<HermiteInterpolant> dense;
  std::shared_ptr<const PartitionOfUnity> pu;
  std::vector<Sphere> changed;
  if (params.solver == Solver::dense) {
    dense = fit_hermite_rbf(constraints, params.solve, out.solve);
    out.solve.polynomial_rank = 4;
  } else {
    PartitionReport report;
    pu = std::make_shared<const PartitionOfUnity>(fit_partition_of_unity(
        constraints, grid_box(spec), params.partition, params.solve, params.mesh.threads, report,
        state ? state->model.get() : nullptr));
    changed = std::move(report.changed);
    out.solve.unknowns = constraints.rows();
    out.solve.regularizer = report.regularizer;
    s["pu_cells"] = double(report.cells);
    s["pu_cells_fitted"] = double(report.cells_fitted);
    s["pu_max_rows"] = report.max_rows;
    s["pu_mean_rows"] = report.mean_rows;
  }
  const ImplicitFunction& f = dense ? static_cast<const ImplicitFunction&>(*dense) : *pu;
  out.solve.solve_ms = solve_timer.wall_ms();
  s["solve_cpu_ms"] = solve_timer.cpu_ms();
  measure_residuals(f, constraints, out.solve);

  StageTimer eval_timer;
  GridCache* cache = nullptr;
  if (state && pu) {
    if (state->model) state->grid.invalidate(changed);
    else state->grid = GridCache{};
    cache = &state->grid;
  }
  const ScalarGrid grid = evaluate_grid(f, spec, params.mesh.threads, cache);
  if (state) {
    state->model = pu;
    if (!pu) state->grid = GridCache{};
  }
  const double eval_ms = eval_timer.wall_ms();
  s["eval_cpu_ms"] = eval_timer.cpu_ms();
  StageTimer mesh_timer;
  Mesh mesh = extract_zero_set(grid);
  if (mesh.faces.empty()) throw std::invalid_argument("hermite_rbf: the interpolant has no zero set inside the grid box");

  // Components far from every curve (§6 warns the surface may "bulge" away).
  const double far = params.mesh.far_distance * diagonal;
  const PointTree curves(curve_points);
  const double area_closed = surface_area(mesh);
  int trimmed = 0;
  if (params.mesh.trim != Trim::none) {
    int count = 0;
    const std::vector<int> component = vertex_components(mesh, count);
    std::vector<bool> keep(static_cast<std::size_t>(count), false);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      if (component[v] >= 0 && !keep[static_cast<std::size_t>(component[v])] && curves.nearest(mesh.vertices[v]).second <= far)
        keep[static_cast<std::size_t>(component[v])] = true;
    for (bool k : keep) trimmed += !k;
    mesh = keep_components(mesh, component, keep);
    if (mesh.faces.empty()) throw std::invalid_argument("hermite_rbf: every component of the zero set is far from the curves");
  }
  if (params.mesh.trim == Trim::enclosed) {
    const double reach = params.mesh.trim_reach * diagonal;
    const PointTree thinned(thin_points(curve_points, reach / 50.0));
    mesh = trim_unenclosed(mesh, f, thinned, {reach, params.mesh.trim_elevation, params.mesh.trim_gap}, 4.0 * spec.h,
                           params.mesh.threads);
    if (mesh.faces.empty()) throw std::invalid_argument("hermite_rbf: no part of the surface is enclosed by curves");
  }
  const double mesh_ms = mesh_timer.wall_ms();
  s["mesh_cpu_ms"] = mesh_timer.cpu_ms();
  const SurfaceQuality quality = surface_quality(mesh, curves, quality_margin * diagonal);
  // The old figure: the share of the surface farther than far_distance from every curve.
  double far_area = 0.0;
  {
    std::vector<char> near(mesh.vertices.size(), 0);
    parallel_for(mesh.vertices.size(), params.mesh.threads, [&](std::size_t v) { near[v] = curves.nearest(mesh.vertices[v]).second <= far; });
    for (const auto& face : mesh.faces)
      if (!near[static_cast<std::size_t>(face[0])] && !near[static_cast<std::size_t>(face[1])] && !near[static_cast<std::size_t>(face[2])])
        far_area += 0.5 * (mesh.vertices[static_cast<std::size_t>(face[1])] - mesh.vertices[static_cast<std::size_t>(face[0])])
                              .cross(mesh.vertices[static_cast<std::size_t>(face[2])] - mesh.vertices[static_cast<std::size_t>(face[0])])
                              .norm();
  }
  const MeshTopology topo = mesh_topology(mesh);

  s["solver_dense"] = dense ? 1.0 : 0.0;
  s["constraints_point"] = double(constraints.points.size());
  s["constraints_tangent"] = double(constraints.tangents.size());
  s["constraints_normal"] = double(constraints.normals.size());
  s["unknowns"] = double(constraints.rows() + 4);
  s["regularizer"] = out.solve.regularizer;
  s["solve_ms"] = out.solve.solve_ms;
  s["eval_ms"] = eval_ms;
  s["mesh_ms"] = mesh_ms;
  s["grid_nodes"] = double(spec.size());
  s["grid_nx"] = spec.n[0];
  s["grid_ny"] = spec.n[1];
  s["grid_nz"] = spec.n[2];
  s["grid_cell"] = spec.h;
  s["grid_evaluated_fraction"] = double(grid.evaluated) / double(spec.size());
  s["grid_computed_fraction"] = double(grid.computed) / double(spec.size());
  s["residual_point_max"] = out.solve.residual_point;
  s["residual_normal_max"] = out.solve.residual_normal;
  s["residual_tangent_max"] = out.solve.residual_tangent;
  s["mesh_vertices"] = double(mesh.vertices.size());
  s["mesh_faces"] = double(mesh.faces.size());
  s["components"] = topo.components;
  s["components_trimmed"] = trimmed;
  s["watertight"] = topo.watertight_manifold() ? 1.0 : 0.0;
  s["far_area_fraction"] = quality.area > 0.0 ? far_area / quality.area : 0.0;
  s["trimmed_area_fraction"] = area_closed > 0.0 ? std::max(0.0, 1.0 - quality.area / area_closed) : 0.0;
  s["diagonal"] = diagonal;
  s["area"] = quality.area;
  s["curve_distance_mean"] = quality.distance_mean;
  s["curve_distance_p95"] = quality.distance_p95;
  s["curve_distance_max"] = quality.distance_max;
  s["outside_area_fraction"] = quality.outside_fraction;
  s["boundary_edges"] = topo.boundary_edges;
  s["volume"] = signed_volume(mesh);
  out.mesh = std::move(mesh);
  return out;
}

SurfaceResult surface_from_network(const Network& network, const HermiteRbfParams& params, SurfaceState* state) {
  StageTimer timer;
  std::vector<CurveSamples> curves = sample_curves(network, params.sampling);
  if (curves.empty()) throw std::invalid_argument("hermite_rbf: no curve of non-zero length to surface");
  assign_normals(curves, network, params.normals);
  HermiteConstraints picked;
  std::vector<Vec3> samples;
  std::size_t sample_count = 0;
  double spacing = std::numeric_limits<double>::infinity();
  for (const CurveSamples& c : curves) {
    pick_constraints(c, params.sampling, picked);
    samples.insert(samples.end(), c.points.begin(), c.points.end());
    sample_count += c.points.size();
    spacing = std::min(spacing, c.spacing);
  }
  const HermiteConstraints merged = merge_duplicates(picked, 0.5 * spacing);
  check_budget();  // issue 17: the per-event time budget
  const double constraints_ms = timer.wall_ms(), constraints_cpu_ms = timer.cpu_ms();
  SurfaceResult r = surface_from_constraints(merged, samples, params, state);
  r.stats["curves"] = double(curves.size());
  r.stats["samples"] = double(sample_count);
  r.stats["sample_spacing"] = spacing;
  r.stats["constraints_merged"] = double(picked.size() - merged.size());
  r.stats["constraints_ms"] = constraints_ms;
  r.stats["constraints_cpu_ms"] = constraints_cpu_ms;
  return r;
}

SurfaceUpdate recompute_surface(const Sketch& sketch, const HermiteRbfParams& params, SurfaceState* state) {
  SurfaceUpdate u;
  try {
    StageTimer timer;
    SurfaceResult r = surface_from_network(sketch.network, params, state);
    for (const auto& [id, patch] : sketch.network.patches()) u.edit.patches_removed.push_back(id);
    Patch p;
    p.id = sketch.network.next_patch_id();
    p.automatic = true;
    // The patch names the curves it was built from with zero-length pieces at
    // t = 0: always valid whatever later edits do to the curves' length, and
    // removing one of those curves removes the (stale) surface with it.
    for (const auto& [id, nc] : sketch.network.curves()) p.boundary.push_back({id, 0.0, 0.0, 0, 0});
    p.mesh = std::move(r.mesh);
    u.edit.patches_added.push_back(std::move(p));
    u.stats = std::move(r.stats);
    u.stats["total_ms"] = timer.wall_ms();
    u.stats["total_cpu_ms"] = timer.cpu_ms();
  } catch (const std::exception& e) {
    // Degenerate input (invalid_argument) or a singular local system
    // (runtime_error): the sketch keeps its previous surface.
    u = SurfaceUpdate{};
    u.error = e.what();
    if (state) *state = SurfaceState{};
  }
  return u;
}

SurfaceUpdate surface_command(const Sketch& sketch, const SurfaceCommand& command, const HermiteRbfParams& params,
                              SurfaceState* state) {
  if (std::holds_alternative<AddPatchEvent>(command)) return recompute_surface(sketch, params, state);
  const Vec3 point = std::get<DeletePatchEvent>(command).point;
  SurfaceUpdate u;
  double best = std::numeric_limits<double>::infinity();
  PatchId nearest = 0;
  for (const auto& [id, patch] : sketch.network.patches())
    for (const Vec3& v : patch.mesh.vertices)
      if ((v - point).squaredNorm() < best) {
        best = (v - point).squaredNorm();
        nearest = id;
      }
  if (nearest == 0) {
    u.error = "delete_patch: there is no surface to delete";
    return u;
  }
  u.edit.patches_removed.push_back(nearest);
  return u;
}

}  // namespace sketchlab::hermite_rbf
