#include "mesh_features.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace sketchlab::synthetic {
namespace {

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

Vec3 to_vec(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

double turn_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - b;
  if (u.norm() == 0.0 || v.norm() == 0.0) return 0.0;
  return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0));
}

}  // namespace

std::vector<std::vector<Vec3>> mesh_feature_polylines(const std::filesystem::path& path,
                                                      const MeshFeatureParams& params) {
  Mesh mesh;
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + ": mesh file not found");
  OpenMesh::IO::Options opt;
  if (!OpenMesh::IO::read_mesh(mesh, path.string(), opt))
    throw std::runtime_error(path.string() + ": cannot read the mesh (OFF or PLY expected)");
  if (mesh.n_faces() == 0) throw std::runtime_error(path.string() + ": the mesh has no faces");
  mesh.request_face_normals();
  mesh.update_face_normals();

  // Feature edges and, per vertex, its feature edges in halfedge order.
  std::vector<bool> feature(mesh.n_edges(), false);
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) {
      feature[static_cast<std::size_t>(e.idx())] = true;
      continue;
    }
    const Vec3 n0 = to_vec(mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 0))));
    const Vec3 n1 = to_vec(mesh.normal(mesh.face_handle(mesh.halfedge_handle(e, 1))));
    if (n0.norm() < 0.5 || n1.norm() < 0.5) continue;  // degenerate face: no reliable angle
    const double angle = std::acos(std::clamp(n0.dot(n1), -1.0, 1.0));
    feature[static_cast<std::size_t>(e.idx())] = angle > params.feature_angle;
  }
  const std::size_t nv = mesh.n_vertices();
  std::vector<std::vector<int>> incident(nv);  // outgoing feature halfedges
  for (auto v : mesh.vertices()) {
    for (auto h : mesh.voh_range(v)) {
      if (feature[static_cast<std::size_t>(mesh.edge_handle(h).idx())])
        incident[static_cast<std::size_t>(v.idx())].push_back(h.idx());
    }
    std::sort(incident[static_cast<std::size_t>(v.idx())].begin(),
              incident[static_cast<std::size_t>(v.idx())].end());
  }
  auto point = [&](int v) { return to_vec(mesh.point(Mesh::VertexHandle(v))); };
  auto target = [&](int h) { return mesh.to_vertex_handle(Mesh::HalfedgeHandle(h)).idx(); };
  auto edge_of = [&](int h) { return static_cast<std::size_t>(mesh.edge_handle(Mesh::HalfedgeHandle(h)).idx()); };

  std::vector<bool> used(mesh.n_edges(), false);
  std::vector<std::vector<int>> chains;  // vertex indices
  auto walk = [&](int v0, int h0) {
    std::vector<int> chain{v0};
    int h = h0;
    while (true) {
      used[edge_of(h)] = true;
      const int v = target(h);
      chain.push_back(v);
      const auto& inc = incident[static_cast<std::size_t>(v)];
      if (inc.size() != 2 || v == v0) break;
      int next = -1;
      for (int g : inc)
        if (!used[edge_of(g)]) next = g;
      if (next < 0) break;
      h = next;
    }
    return chain;
  };
  for (std::size_t v = 0; v < nv; ++v) {
    if (incident[v].size() == 2) continue;
    for (int h : incident[v])
      if (!used[edge_of(h)]) chains.push_back(walk(static_cast<int>(v), h));
  }
  for (std::size_t v = 0; v < nv; ++v)
    for (int h : incident[v])
      if (!used[edge_of(h)]) chains.push_back(walk(static_cast<int>(v), h));

  // Split at corners; a closed loop is rotated to start at its first corner.
  std::vector<std::vector<Vec3>> out;
  for (auto chain : chains) {
    const bool closed = chain.size() > 2 && chain.front() == chain.back();
    auto is_corner = [&](std::size_t i) {
      const std::size_t n = chain.size();
      if (closed) {
        const std::size_t prev = i == 0 ? n - 2 : i - 1;
        return turn_angle(point(chain[prev]), point(chain[i]), point(chain[i + 1])) > params.corner_angle;
      }
      return i > 0 && i + 1 < n &&
             turn_angle(point(chain[i - 1]), point(chain[i]), point(chain[i + 1])) > params.corner_angle;
    };
    if (closed) {
      std::size_t first = chain.size();
      for (std::size_t i = 0; i + 1 < chain.size() && first == chain.size(); ++i)
        if (is_corner(i)) first = i;
      if (first == chain.size()) {  // a smooth loop
        std::vector<Vec3> pts;
        for (int v : chain) pts.push_back(point(v));
        out.push_back(std::move(pts));
        continue;
      }
      std::vector<int> rotated(chain.begin() + static_cast<std::ptrdiff_t>(first), chain.end() - 1);
      rotated.insert(rotated.end(), chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(first) + 1);
      chain = rotated;
    }
    std::vector<Vec3> piece{point(chain.front())};
    for (std::size_t i = 1; i < chain.size(); ++i) {
      piece.push_back(point(chain[i]));
      const bool corner = i + 1 < chain.size() &&
                          turn_angle(point(chain[i - 1]), point(chain[i]), point(chain[i + 1])) >
                              params.corner_angle;
      if (corner) {
        out.push_back(piece);
        piece = {point(chain[i])};
      }
    }
    if (piece.size() >= 2) out.push_back(piece);
  }
  return out;
}

GroundTruthNetwork feature_network(const std::vector<std::vector<Vec3>>& polylines,
                                   const Vec3& center, double size, const std::string& name) {
  GroundTruthNetwork net{name, {}};
  Box3 box;
  for (const auto& pl : polylines)
    for (const Vec3& p : pl) box.extend(p);
  if (box.isEmpty()) throw std::runtime_error(name + ": the mesh has no feature edges");
  const double extent = box.sizes().maxCoeff();
  if (!(extent > 0.0)) throw std::runtime_error(name + ": the feature edges have zero extent");
  const double scale = size / extent;
  const Vec3 mid = box.center();
  for (const auto& pl : polylines) {
    std::vector<Vec3> pts;
    for (const Vec3& p : pl) pts.push_back(center + scale * (p - mid));
    // Drop repeated points (zero-length edges) but keep the closing point.
    std::vector<Vec3> clean{pts.front()};
    for (std::size_t i = 1; i < pts.size(); ++i)
      if (pts[i] != clean.back()) clean.push_back(pts[i]);
    if (clean.size() < 2) continue;
    const bool closed = clean.size() > 3 && clean.front() == clean.back();
    const Vec3 chord = clean.back() - clean.front();
    bool straight = !closed && chord.norm() > 0.0;
    for (const Vec3& p : clean) {
      if (!straight) break;
      const Vec3 d = p - clean.front();
      straight = (d - d.dot(chord.normalized()) * chord.normalized()).norm() <= 1e-9 * size;
    }
    GroundTruthCurve gc;
    gc.layer = Layer::shape;
    if (straight) {
      gc.curve = make_line(clean.front(), clean.back());
    } else {
      Curve& c = gc.curve;
      c.control_points.push_back(clean.front());
      for (std::size_t i = 1; i < clean.size(); ++i) {
        const Vec3 a = clean[i - 1], b = clean[i];
        c.control_points.push_back(a + (b - a) / 3.0);
        c.control_points.push_back(a + 2.0 * (b - a) / 3.0);
        c.control_points.push_back(b);
      }
      c.closed = closed;
      if (closed) c.control_points.back() = c.control_points.front();
      c.sharp.assign(clean.size(), false);
      for (std::size_t i = 1; i + 1 < clean.size(); ++i)
        c.sharp[i] = turn_angle(clean[i - 1], clean[i], clean[i + 1]) > std::numbers::pi / 4;
    }
    net.curves.push_back(std::move(gc));
  }
  return net;
}

}  // namespace sketchlab::synthetic
