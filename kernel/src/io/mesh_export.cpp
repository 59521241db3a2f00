#include "sketchlab/io/mesh_export.hpp"

#include <array>
#include <sstream>

#include "sketchlab/geometry/arclength.hpp"

namespace sketchlab {
namespace {

std::ostringstream precise_stream() {
  std::ostringstream out;
  out.precision(9);  // 1 nm at metre scale
  return out;
}

// One PLY writer for every layer kind; empty element lists are omitted.
std::string write_ply(const std::vector<Vec3>& vertices, const std::vector<std::array<int, 3>>& faces,
                      const std::vector<std::array<int, 2>>& edges) {
  auto out = precise_stream();
  out << "ply\nformat ascii 1.0\ncomment sketchlab\n"
      << "element vertex " << vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (!faces.empty()) out << "element face " << faces.size() << "\nproperty list uchar int vertex_indices\n";
  if (!edges.empty())
    out << "element edge " << edges.size() << "\nproperty int vertex1\nproperty int vertex2\n";
  out << "end_header\n";
  for (const Vec3& v : vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& f : faces) out << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  for (const auto& e : edges) out << e[0] << " " << e[1] << "\n";
  return out.str();
}

void append_polylines(const std::vector<std::vector<Vec3>>& lines, std::vector<Vec3>& vertices,
                      std::vector<std::array<int, 2>>& edges) {
  for (const auto& line : lines) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), line.begin(), line.end());
    for (int i = 1; i < static_cast<int>(line.size()); ++i) edges.push_back({base + i - 1, base + i});
  }
}

void append_meshes(const std::vector<const Mesh*>& meshes, std::vector<Vec3>& vertices,
                   std::vector<std::array<int, 3>>& faces) {
  for (const Mesh* m : meshes) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), m->vertices.begin(), m->vertices.end());
    for (const auto& f : m->faces) faces.push_back({base + f[0], base + f[1], base + f[2]});
  }
}

std::vector<const Mesh*> patch_meshes(const Network& network) {
  std::vector<const Mesh*> meshes;
  for (const auto& [id, p] : network.patches()) meshes.push_back(&p.mesh);
  return meshes;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::vector<std::vector<Vec3>> curve_polylines(const Network& network, double spacing) {
  std::vector<std::vector<Vec3>> lines;
  for (const auto& [id, c] : network.curves())
    lines.push_back(sample_with_spacing(c.curve, spacing, kMaxPointsPerExportedCurve));
  return lines;
}

std::string polylines_to_ply(const std::vector<std::vector<Vec3>>& polylines) {
  std::vector<Vec3> v;
  std::vector<std::array<int, 2>> e;
  append_polylines(polylines, v, e);
  return write_ply(v, {}, e);
}

std::string points_to_ply(const std::vector<Vec3>& points) { return write_ply(points, {}, {}); }

std::string meshes_to_ply(const std::vector<const Mesh*>& meshes) {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> f;
  append_meshes(meshes, v, f);
  return write_ply(v, f, {});
}

std::string network_to_ply(const Network& network, double spacing) {
  std::vector<Vec3> v;
  std::vector<std::array<int, 2>> e;
  std::vector<std::array<int, 3>> f;
  append_polylines(curve_polylines(network, spacing), v, e);
  append_meshes(patch_meshes(network), v, f);
  return write_ply(v, f, e);
}

std::string network_to_obj(const Network& network, double spacing) {
  auto out = precise_stream();
  out << "# sketchlab network: " << network.curves().size() << " curves, "
      << network.patches().size() << " patches\n";
  int next = 1;  // OBJ indices are 1-based and global
  auto it = network.curves().begin();
  for (const auto& line : curve_polylines(network, spacing)) {
    out << "o curve_" << (it++)->first << "\n";
    for (const Vec3& v : line) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
    out << "l";
    for (std::size_t i = 0; i < line.size(); ++i) out << " " << next + static_cast<int>(i);
    out << "\n";
    next += static_cast<int>(line.size());
  }
  for (const auto& [id, patch] : network.patches()) {
    out << "o patch_" << id << "\n";
    for (const Vec3& v : patch.mesh.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
    for (const auto& f : patch.mesh.faces)
      out << "f " << next + f[0] << " " << next + f[1] << " " << next + f[2] << "\n";
    next += static_cast<int>(patch.mesh.vertices.size());
  }
  return out.str();
}

std::string meshlab_project(const std::vector<MeshLabLayer>& layers) {
  std::ostringstream out;
  out << "<!DOCTYPE MeshLabDocument>\n<MeshLabProject>\n <MeshGroup>\n";
  for (const auto& l : layers) {
    out << "  <MLMesh label=\"" << xml_escape(l.label) << "\" filename=\"" << xml_escape(l.filename) << "\" visible=\"1\">\n"
        << "   <MLMatrix44>\n1 0 0 0 \n0 1 0 0 \n0 0 1 0 \n0 0 0 1 \n</MLMatrix44>\n  </MLMesh>\n";
  }
  out << " </MeshGroup>\n <RasterGroup/>\n</MeshLabProject>\n";
  return out.str();
}

}  // namespace sketchlab
