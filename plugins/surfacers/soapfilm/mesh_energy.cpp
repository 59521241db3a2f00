#include "mesh_energy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace sketchlab::soapfilm {

double mean_curvature_energy(const Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  std::vector<Vec3> lap(n, Vec3::Zero());
  std::vector<double> area(n, 0.0);
  std::map<std::pair<int, int>, int> edge_faces;
  for (const auto& f : mesh.faces) {
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3], c = f[(i + 2) % 3];
      const Vec3 &pa = mesh.vertices[a], &pb = mesh.vertices[b], &pc = mesh.vertices[c];
      // Cotangent of the angle at c, opposite edge (a, b).
      const Vec3 u = pa - pc, v = pb - pc;
      const double cot = u.dot(v) / std::max(u.cross(v).norm(), 1e-300);
      lap[a] += 0.5 * cot * (pb - pa);
      lap[b] += 0.5 * cot * (pa - pb);
      ++edge_faces[std::minmax(a, b)];
    }
    const double A = 0.5 * (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                               .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                               .norm();
    for (int v : f) area[v] += A / 3.0;
  }
  std::vector<bool> border(n, false);
  for (const auto& [e, count] : edge_faces)
    if (count == 1) border[e.first] = border[e.second] = true;
  double energy = 0.0;
  for (std::size_t v = 0; v < n; ++v)
    if (!border[v] && area[v] > 0.0) energy += lap[v].squaredNorm() / (4.0 * area[v]);
  return energy;
}

bool is_manifold_disk(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> edge_faces;
  std::set<std::pair<int, int>> directed;
  for (const auto& f : mesh.faces) {
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) return false;
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3];
      if (a < 0 || b < 0 || a >= static_cast<int>(mesh.vertices.size())) return false;
      if (!directed.insert({a, b}).second) return false;  // inconsistent orientation
      ++edge_faces[std::minmax(a, b)];
    }
  }
  std::map<int, std::vector<int>> border_next;
  for (const auto& [e, count] : edge_faces) {
    if (count > 2) return false;
    if (count == 1) {
      border_next[e.first].push_back(e.second);
      border_next[e.second].push_back(e.first);
    }
  }
  if (border_next.empty()) return false;
  for (const auto& [v, nb] : border_next)
    if (nb.size() != 2) return false;
  // One loop through every border vertex.
  const int start = border_next.begin()->first;
  int prev = -1, cur = start;
  std::size_t steps = 0;
  do {
    const auto& nb = border_next.at(cur);
    const int next = nb[0] != prev ? nb[0] : nb[1];
    prev = cur;
    cur = next;
    ++steps;
  } while (cur != start && steps <= border_next.size());
  return cur == start && steps == border_next.size();
}

}  // namespace sketchlab::soapfilm
