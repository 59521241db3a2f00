#include "sketchlab/io/mesh_export.hpp"

#include <array>
#include <sstream>

#include "sketchlab/geometry/arclength.hpp"

namespace sketchlab {
namespace {

struct Polylines {
  std::vector<Vec3> vertices;
  std::vector<std::pair<CurveId, std::vector<int>>> lines;  // vertex indices per curve
};

Polylines sample_curves(const Network& network, double spacing) {
  Polylines p;
  for (const auto& [id, c] : network.curves()) {
    std::vector<int> line;
    for (const Vec3& v : sample_with_spacing(c.curve, spacing)) {
      line.push_back(static_cast<int>(p.vertices.size()));
      p.vertices.push_back(v);
    }
    p.lines.emplace_back(id, std::move(line));
  }
  return p;
}

std::ostringstream precise_stream() {
  std::ostringstream out;
  out.precision(9);  // 1 nm at metre scale
  return out;
}

}  // namespace

std::string network_to_obj(const Network& network, double spacing) {
  const Polylines p = sample_curves(network, spacing);
  auto out = precise_stream();
  out << "# sketchlab network: " << network.curves().size() << " curves, "
      << network.patches().size() << " patches\n";
  for (const Vec3& v : p.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& [id, line] : p.lines) {
    out << "o curve_" << id << "\nl";
    for (int i : line) out << " " << i + 1;
    out << "\n";
  }
  int base = static_cast<int>(p.vertices.size());
  for (const auto& [id, patch] : network.patches()) {
    out << "o patch_" << id << "\n";
    for (const Vec3& v : patch.mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
    for (const auto& f : patch.mesh.faces)
      out << "f " << base + f[0] + 1 << " " << base + f[1] + 1 << " " << base + f[2] + 1 << "\n";
    base += static_cast<int>(patch.mesh.vertices.size());
  }
  return out.str();
}

std::string network_to_ply(const Network& network, double spacing) {
  const Polylines p = sample_curves(network, spacing);
  std::vector<Vec3> vertices = p.vertices;
  std::vector<std::array<int, 2>> edges;
  for (const auto& [id, line] : p.lines)
    for (std::size_t i = 1; i < line.size(); ++i) edges.push_back({line[i - 1], line[i]});
  std::vector<std::array<int, 3>> faces;
  for (const auto& [id, patch] : network.patches()) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), patch.mesh.vertices.begin(), patch.mesh.vertices.end());
    for (const auto& f : patch.mesh.faces) faces.push_back({base + f[0], base + f[1], base + f[2]});
  }
  auto out = precise_stream();
  out << "ply\nformat ascii 1.0\ncomment sketchlab network\n"
      << "element vertex " << vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << faces.size() << "\nproperty list uchar int vertex_indices\n"
      << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\n"
      << "end_header\n";
  for (const Vec3& v : vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& f : faces) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  for (const auto& e : edges) out << e[0] << " " << e[1] << "\n";
  return out.str();
}

}  // namespace sketchlab
