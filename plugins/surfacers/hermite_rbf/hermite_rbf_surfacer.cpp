#include "hermite_rbf_surfacer.hpp"

#include <chrono>
#include <limits>
#include <stdexcept>

#include "curve_normals.hpp"
#include "curve_samples.hpp"
#include "grid_evaluation.hpp"
#include "mesh_topology.hpp"
#include "parallel_for.hpp"
#include "point_buckets.hpp"
#include "sketchlab/plugin/budget.hpp"
#include "zero_set_mesh.hpp"

namespace sketchlab::hermite_rbf {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SurfaceResult surface_from_constraints(const HermiteConstraints& constraints, const std::vector<Vec3>& curve_points,
                                       const HermiteRbfParams& params) {
  SurfaceResult out;
  out.constraints = constraints;
  const HermiteInterpolant f = fit_hermite_rbf(constraints, params.solve, out.solve);

  Box3 box;
  for (const Vec3& p : constraints.points) box.extend(p);
  for (const Vec3& p : constraints.normal_points) box.extend(p);
  for (const Vec3& p : constraints.tangent_points) box.extend(p);
  const double diagonal = box.diagonal().norm();
  const GridSpec spec = grid_around(box, params.mesh.padding * diagonal, params.mesh.resolution);
  auto start = std::chrono::steady_clock::now();
  const ScalarGrid grid = evaluate_grid(f, spec, params.mesh.threads);
  const double eval_ms = ms_since(start);
  start = std::chrono::steady_clock::now();
  Mesh mesh = extract_zero_set(grid);
  if (mesh.faces.empty()) throw std::invalid_argument("hermite_rbf: the interpolant has no zero set inside the grid box");

  // Near / far from the curves (§6 warns the surface may "bulge" away).
  const double far = params.mesh.far_distance * diagonal;
  PointBuckets buckets(std::max(far, 1e-12));
  for (std::size_t i = 0; i < curve_points.size(); ++i) buckets.add(curve_points[i], static_cast<int>(i));
  auto near_flags = [&](const Mesh& m) {
    std::vector<char> near(m.vertices.size(), 0);
    parallel_for(m.vertices.size(), params.mesh.threads, [&](std::size_t v) {
      near[v] = buckets.any_near(m.vertices[v], [&](int id) {
        return (curve_points[static_cast<std::size_t>(id)] - m.vertices[v]).squaredNorm() <= far * far;
      });
    });
    return near;
  };
  int count = 0;
  std::vector<int> component = vertex_components(mesh, count);
  std::vector<char> near = near_flags(mesh);
  std::vector<bool> keep(static_cast<std::size_t>(count), !params.mesh.trim_far_components);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (near[v] && component[v] >= 0) keep[static_cast<std::size_t>(component[v])] = true;
  int trimmed = 0;
  for (bool k : keep) trimmed += !k;
  if (trimmed > 0) {
    mesh = keep_components(mesh, component, keep);
    near = near_flags(mesh);
  } else {
    mesh = keep_components(mesh, component, keep);  // drops unused vertices
    near = near_flags(mesh);
  }
  if (mesh.faces.empty()) throw std::invalid_argument("hermite_rbf: every component of the zero set is far from the curves");
  double far_area = 0.0;
  for (const auto& face : mesh.faces)
    if (!near[static_cast<std::size_t>(face[0])] && !near[static_cast<std::size_t>(face[1])] && !near[static_cast<std::size_t>(face[2])])
      far_area += 0.5 * (mesh.vertices[static_cast<std::size_t>(face[1])] - mesh.vertices[static_cast<std::size_t>(face[0])])
                            .cross(mesh.vertices[static_cast<std::size_t>(face[2])] - mesh.vertices[static_cast<std::size_t>(face[0])])
                            .norm();
  const double area = surface_area(mesh);
  const double mesh_ms = ms_since(start);
  const MeshTopology topo = mesh_topology(mesh);

  auto& s = out.stats;
  s["constraints_point"] = double(constraints.points.size());
  s["constraints_tangent"] = double(constraints.tangents.size());
  s["constraints_normal"] = double(constraints.normals.size());
  s["unknowns"] = double(out.solve.unknowns + 4);
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
  s["residual_point_max"] = out.solve.residual_point;
  s["residual_normal_max"] = out.solve.residual_normal;
  s["residual_tangent_max"] = out.solve.residual_tangent;
  s["mesh_vertices"] = double(mesh.vertices.size());
  s["mesh_faces"] = double(mesh.faces.size());
  s["components"] = topo.components;
  s["components_trimmed"] = trimmed;
  s["watertight"] = topo.watertight_manifold() ? 1.0 : 0.0;
  s["far_area_fraction"] = area > 0.0 ? far_area / area : 0.0;
  s["volume"] = signed_volume(mesh);
  out.mesh = std::move(mesh);
  return out;
}

SurfaceResult surface_from_network(const Network& network, const HermiteRbfParams& params) {
  const auto start = std::chrono::steady_clock::now();
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
  const double constraints_ms = ms_since(start);
  SurfaceResult r = surface_from_constraints(merged, samples, params);
  r.stats["curves"] = double(curves.size());
  r.stats["samples"] = double(sample_count);
  r.stats["sample_spacing"] = spacing;
  r.stats["constraints_merged"] = double(picked.size() - merged.size());
  r.stats["constraints_ms"] = constraints_ms;
  return r;
}

SurfaceUpdate recompute_surface(const Sketch& sketch, const HermiteRbfParams& params) {
  SurfaceUpdate u;
  try {
    const auto start = std::chrono::steady_clock::now();
    SurfaceResult r = surface_from_network(sketch.network, params);
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
    u.stats["total_ms"] = ms_since(start);
  } catch (const std::invalid_argument& e) {
    u = SurfaceUpdate{};
    u.error = e.what();
  }
  return u;
}

SurfaceUpdate surface_command(const Sketch& sketch, const SurfaceCommand& command, const HermiteRbfParams& params) {
  if (std::holds_alternative<AddPatchEvent>(command)) return recompute_surface(sketch, params);
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
