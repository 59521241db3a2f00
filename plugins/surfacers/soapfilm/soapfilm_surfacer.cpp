#include "soapfilm_surfacer.hpp"

#include <algorithm>
#include <chrono>
#include <set>
#include <variant>

#include "boundary_polyline.hpp"
#include "curve_graph.hpp"
#include "manual_patch.hpp"
#include "patch_mesh.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/plugin/budget.hpp"

namespace sketchlab::soapfilm {

std::optional<Patch> make_patch(const Network& network, PatchId id,
                                const std::vector<OrientedSegment>& boundary, bool automatic,
                                const SoapfilmParams& params, PatchMeshTimings* timings) {
  try {
    const BoundaryPolyline poly =
        boundary_polyline(network, boundary, params.edge_length, params.max_boundary_points);
    Patch patch;
    patch.id = id;
    patch.boundary = boundary;
    patch.automatic = automatic;
    patch.mesh = patch_mesh(poly.points, poly.spacing, params.mesh, timings);
    return patch;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

SurfaceUpdate soapfilm_update(const Sketch& sketch, const Edit& last, const SoapfilmParams& params,
                              std::vector<PatchMeshTimings>* per_patch) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  SurfaceUpdate out;
  const UpkeepResult up = patch_upkeep(sketch, last, params.search);
  const auto t1 = clock::now();
  out.edit.patches_removed = up.patches_removed;
  PatchId next = sketch.network.next_patch_id();
  int failed = 0;
  PatchMeshTimings stages;  // summed over the patches (CPU ms)
  for (const auto& cycle : up.cycles_added) {
    check_budget();  // issue 17: the per-event time budget
    PatchMeshTimings t;
    auto patch = make_patch(sketch.network, next, cycle, true, params, &t);
    stages.fill_ms += t.fill_ms;
    stages.remesh_ms += t.remesh_ms;
    stages.smooth_ms += t.smooth_ms;
    if (per_patch) per_patch->push_back(t);
    if (patch) {
      out.edit.patches_added.push_back(std::move(*patch));
      ++next;
    } else {
      ++failed;
    }
  }
  const auto t2 = clock::now();
  const double search_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  const double mesh_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  out.stats["seeds"] = up.seeds;
  out.stats["walks"] = up.walks;
  out.stats["cycles_found"] = up.cycles_found;
  out.stats["rejected_duplicate"] = up.rejected_duplicate;
  out.stats["rejected_manifold"] = up.rejected_manifold;
  out.stats["mesh_failures"] = failed;
  out.stats["search_ms"] = search_ms;
  out.stats["walk_ms"] = up.walk_ms;
  out.stats["mesh_ms"] = mesh_ms;
  out.stats["mesh_fill_cpu_ms"] = stages.fill_ms;
  out.stats["mesh_remesh_cpu_ms"] = stages.remesh_ms;
  out.stats["mesh_smooth_cpu_ms"] = stages.smooth_ms;
  if (!up.cycles_added.empty())
    out.stats["ms_per_patch"] = mesh_ms / static_cast<double>(up.cycles_added.size());
  return out;
}

SurfaceUpdate soapfilm_command(const Sketch& sketch, const SurfaceCommand& command,
                               const SoapfilmParams& params) {
  SurfaceUpdate out;
  const Network& net = sketch.network;
  if (const auto* add = std::get_if<AddPatchEvent>(&command)) {
    const auto cycle = manual_cycle(net, add->point, params.manual, params.search.closed_seam_nodes);
    if (!cycle) {
      out.error = "add_patch: no closed cycle of curves found around the point";
      return out;
    }
    CurveGraph graph(net, params.search.closed_seam_nodes);
    const std::vector<int> key = boundary_key(graph, *cycle);
    // A patch over the same cycle bounds the cycle's first curve.
    for (PatchId id : net.patches_on(cycle->front().curve))
      if (boundary_key(graph, net.patches().at(id).boundary) == key) {
        out.error = "add_patch: patch " + std::to_string(id) + " already bounds that cycle";
        return out;
      }
    auto patch = make_patch(net, net.next_patch_id(), *cycle, false, params);
    if (!patch) {
      out.error = "add_patch: the cycle could not be meshed";
      return out;
    }
    out.edit.patches_added.push_back(std::move(*patch));
    return out;
  }
  const auto& del = std::get<DeletePatchEvent>(command);
  const auto id = nearest_patch(net, del.point);
  if (!id) {
    out.error = "delete_patch: there is no patch";
    return out;
  }
  out.edit.patches_removed.push_back(*id);
  return out;
}

}  // namespace sketchlab::soapfilm
