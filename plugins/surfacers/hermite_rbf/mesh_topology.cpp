#include "mesh_topology.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace sketchlab::hermite_rbf {
namespace {

int find(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
  return x;
}

const Vec3& vertex(const Mesh& m, int i) { return m.vertices[static_cast<std::size_t>(i)]; }

}  // namespace

MeshTopology mesh_topology(const Mesh& mesh) {
  MeshTopology t;
  // Directed edge counts per undirected edge.
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // (min, max) -> (forward, backward)
  for (const auto& f : mesh.faces)
    for (int e = 0; e < 3; ++e) {
      const int a = f[static_cast<std::size_t>(e)], b = f[static_cast<std::size_t>((e + 1) % 3)];
      auto& c = edges[{std::min(a, b), std::max(a, b)}];
      (a < b ? c.first : c.second)++;
    }
  for (const auto& [e, c] : edges) {
    const int n = c.first + c.second;
    if (n == 1) ++t.boundary_edges;
    else if (n > 2) ++t.nonmanifold_edges;
    else if (c.first != 1) ++t.inconsistent_edges;
  }
  // Fans: faces around a vertex connected through edges at that vertex.
  std::vector<std::vector<int>> faces_of(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f]) faces_of[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
  for (std::size_t v = 0; v < faces_of.size(); ++v) {
    const auto& around = faces_of[v];
    if (around.size() < 2) continue;
    std::vector<int> parent(around.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::map<int, int> first_with;  // other vertex -> local face index
    for (std::size_t i = 0; i < around.size(); ++i)
      for (int w : mesh.faces[static_cast<std::size_t>(around[i])]) {
        if (w == static_cast<int>(v)) continue;
        auto [it, added] = first_with.try_emplace(w, static_cast<int>(i));
        if (!added) parent[static_cast<std::size_t>(find(parent, static_cast<int>(i)))] = find(parent, it->second);
      }
    int fans = 0;
    for (std::size_t i = 0; i < around.size(); ++i) fans += find(parent, static_cast<int>(i)) == static_cast<int>(i);
    if (fans > 1) ++t.nonmanifold_vertices;
  }
  vertex_components(mesh, t.components);
  return t;
}

std::vector<int> vertex_components(const Mesh& mesh, int& count) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& f : mesh.faces) {
    parent[static_cast<std::size_t>(find(parent, f[1]))] = find(parent, f[0]);
    parent[static_cast<std::size_t>(find(parent, f[2]))] = find(parent, f[0]);
  }
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& f : mesh.faces)
    for (int v : f) used[static_cast<std::size_t>(v)] = true;
  std::map<int, int> label;
  std::vector<int> out(mesh.vertices.size(), -1);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v]) continue;
    const auto [it, added] = label.try_emplace(find(parent, static_cast<int>(v)), static_cast<int>(label.size()));
    out[v] = it->second;
  }
  count = static_cast<int>(label.size());
  return out;
}

Mesh keep_components(const Mesh& mesh, const std::vector<int>& component, const std::vector<bool>& keep) {
  Mesh out;
  std::vector<int> remap(mesh.vertices.size(), -1);
  for (const auto& f : mesh.faces) {
    const int c = component[static_cast<std::size_t>(f[0])];
    if (c < 0 || !keep[static_cast<std::size_t>(c)]) continue;
    std::array<int, 3> g{};
    for (int e = 0; e < 3; ++e) {
      int& r = remap[static_cast<std::size_t>(f[static_cast<std::size_t>(e)])];
      if (r < 0) {
        r = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[static_cast<std::size_t>(f[static_cast<std::size_t>(e)])]);
        if (!mesh.normals.empty()) out.normals.push_back(mesh.normals[static_cast<std::size_t>(f[static_cast<std::size_t>(e)])]);
      }
      g[static_cast<std::size_t>(e)] = r;
    }
    out.faces.push_back(g);
  }
  return out;
}

double signed_volume(const Mesh& mesh) {
  double v = 0.0;
  for (const auto& f : mesh.faces) v += vertex(mesh, f[0]).dot(vertex(mesh, f[1]).cross(vertex(mesh, f[2])));
  return v / 6.0;
}

double surface_area(const Mesh& mesh) {
  double a = 0.0;
  for (const auto& f : mesh.faces)
    a += 0.5 * (vertex(mesh, f[1]) - vertex(mesh, f[0])).cross(vertex(mesh, f[2]) - vertex(mesh, f[0])).norm();
  return a;
}

}  // namespace sketchlab::hermite_rbf
