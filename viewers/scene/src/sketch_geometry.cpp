#include "sketch_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "scene_actors.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/viewer/camera.hpp"

namespace sketchlab::viewer {

DrawClass draw_class(Layer layer) {
  return layer == Layer::scaffold ? DrawClass::scaffold : layer == Layer::shape ? DrawClass::shape : DrawClass::other;
}

namespace {

void add_point(DrawData& d, const Vec3& p) {
  d.points.insert(d.points.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
}

}  // namespace

DrawData polylines_data(const std::vector<const std::vector<Vec3>*>& polylines) {
  DrawData d;
  d.cells = DrawData::Cells::lines;
  for (const std::vector<Vec3>* line : polylines) {
    if (line->size() < 2) continue;
    for (const Vec3& p : *line) {
      d.connectivity.push_back(static_cast<std::int64_t>(d.points.size() / 3));
      add_point(d, p);
    }
    d.offsets.push_back(static_cast<std::int64_t>(d.connectivity.size()));
  }
  return d;
}

DrawData meshes_data(const std::vector<const Mesh*>& meshes) {
  DrawData d;
  d.cells = DrawData::Cells::triangles;
  bool all_normals = true;
  for (const Mesh* mesh : meshes) {
    const auto first = static_cast<std::int64_t>(d.points.size() / 3);
    for (const Vec3& v : mesh->vertices) add_point(d, v);
    const bool has_normals = mesh->normals.size() == mesh->vertices.size();
    all_normals = all_normals && has_normals;
    if (all_normals)
      for (const Vec3& n : mesh->normals)
        d.normals.insert(d.normals.end(), {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())});
    const auto n = static_cast<int>(mesh->vertices.size());
    for (const auto& f : mesh->faces) {
      if (std::min({f[0], f[1], f[2]}) < 0 || std::max({f[0], f[1], f[2]}) >= n) continue;
      d.connectivity.insert(d.connectivity.end(), {first + f[0], first + f[1], first + f[2]});
      d.offsets.push_back(static_cast<std::int64_t>(d.connectivity.size()));
    }
  }
  if (!all_normals) d.normals.clear();
  return d;
}

DrawData nodes_data(const std::map<NodeId, Node>& nodes) {
  DrawData d;
  d.cells = DrawData::Cells::vertices;
  for (const auto& [id, node] : nodes) {
    if (!node.position.allFinite()) continue;
    d.connectivity.push_back(static_cast<std::int64_t>(d.points.size() / 3));
    add_point(d, node.position);
    d.offsets.push_back(static_cast<std::int64_t>(d.connectivity.size()));
  }
  return d;
}

std::vector<Vec3> stroke_points(const Stroke& stroke) {
  std::vector<Vec3> out;
  if (stroke.samples_are_pixels) return out;
  out.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples)
    if (s.position.allFinite()) out.push_back(s.position);
  return out;
}

std::vector<Vec3> curve_points(const Curve& curve, double spacing) {
  if (curve.segment_count() < 1 || !curve.control_points.front().allFinite()) return {};
  std::vector<Vec3> points = sample_with_spacing(curve, spacing);
  if (!std::all_of(points.begin(), points.end(), [](const Vec3& p) { return p.allFinite(); })) return {};
  return points;
}

double stable_curve_spacing(const Box3& bounds, const SceneStyle& style) {
  return std::exp2(std::round(std::log2(curve_spacing(bounds, style))));
}

SketchGeometryBuilder::SketchGeometryBuilder(const SceneStyle& style, std::size_t chunk_size)
    : style_(style), chunk_size_(chunk_size) {
  if (chunk_size_ < 1) throw std::invalid_argument("SketchGeometryBuilder: chunk_size must be >= 1, got 0");
}

void SketchGeometryBuilder::update_curves(const Sketch& sketch, double spacing, GeometryWork& work) {
  const auto& curves = sketch.network.curves();
  if (spacing != spacing_) {
    for (const auto& [id, item] : curves_) dirty_.push_back(key(draw_class(item.layer), id));
    curves_.clear();
    spacing_ = spacing;
  }
  for (auto it = curves_.begin(); it != curves_.end();) {
    if (curves.count(it->first)) {
      ++it;
      continue;
    }
    dirty_.push_back(key(draw_class(it->second.layer), it->first));
    it = curves_.erase(it);
  }
  for (const auto& [id, nc] : curves) {
    auto it = curves_.find(id);
    if (it != curves_.end()) {
      if (it->second.layer == nc.layer && it->second.curve == nc.curve) continue;
      dirty_.push_back(key(draw_class(it->second.layer), id));
    }
    curves_.insert_or_assign(id, CurveItem{nc.layer, nc.curve, curve_points(nc.curve, spacing)});
    dirty_.push_back(key(draw_class(nc.layer), id));
    ++work.curves_sampled;
  }
}

void SketchGeometryBuilder::update_strokes(const Sketch& sketch, GeometryWork& work) {
  for (auto it = strokes_.begin(); it != strokes_.end();) {
    if (sketch.strokes.count(it->first)) {
      ++it;
      continue;
    }
    dirty_.push_back(key(DrawClass::raw_strokes, it->first));
    it = strokes_.erase(it);
  }
  for (const auto& [id, stroke] : sketch.strokes) {
    auto it = strokes_.find(id);
    if (it != strokes_.end() && it->second.stroke == stroke) continue;
    strokes_.insert_or_assign(id, StrokeItem{stroke, stroke_points(stroke)});
    dirty_.push_back(key(DrawClass::raw_strokes, id));
    ++work.strokes;
  }
}

void SketchGeometryBuilder::update_patches(const Sketch& sketch, GeometryWork& work) {
  const auto& patches = sketch.network.patches();
  for (auto it = patches_.begin(); it != patches_.end();) {
    if (patches.count(it->first)) {
      ++it;
      continue;
    }
    dirty_.push_back(key(DrawClass::patches, it->first));
    it = patches_.erase(it);
  }
  for (const auto& [id, patch] : patches) {
    auto it = patches_.find(id);
    if (it != patches_.end() && it->second == patch.mesh) continue;
    patches_.insert_or_assign(id, patch.mesh);
    dirty_.push_back(key(DrawClass::patches, id));
    ++work.patches;
  }
}

DrawData SketchGeometryBuilder::build_chunk(const ChunkKey& k) const {
  const std::uint64_t first = k.index * chunk_size_, end = first + chunk_size_;
  std::vector<const std::vector<Vec3>*> lines;
  switch (k.cls) {
    case DrawClass::raw_strokes:
      for (auto it = strokes_.lower_bound(first); it != strokes_.end() && it->first < end; ++it)
        lines.push_back(&it->second.points);
      return polylines_data(lines);
    case DrawClass::scaffold:
    case DrawClass::shape:
    case DrawClass::other:
      for (auto it = curves_.lower_bound(first); it != curves_.end() && it->first < end; ++it)
        if (draw_class(it->second.layer) == k.cls) lines.push_back(&it->second.points);
      return polylines_data(lines);
    case DrawClass::nodes:
      return nodes_data(nodes_);
    case DrawClass::patches: {
      std::vector<const Mesh*> meshes;
      for (auto it = patches_.lower_bound(first); it != patches_.end() && it->first < end; ++it)
        meshes.push_back(&it->second);
      return meshes_data(meshes);
    }
  }
  return {};
}

std::shared_ptr<const SketchGeometry> SketchGeometryBuilder::update(const Sketch& sketch) {
  auto out = std::make_shared<SketchGeometry>();
  GeometryWork& work = out->work;
  out->spacing = stable_curve_spacing(scene_bounds({&sketch}), style_);
  dirty_.clear();
  update_curves(sketch, out->spacing, work);
  update_strokes(sketch, work);
  update_patches(sketch, work);
  if (nodes_ != sketch.network.nodes()) {
    nodes_ = sketch.network.nodes();
    dirty_.push_back({DrawClass::nodes, 0});
  }
  std::sort(dirty_.begin(), dirty_.end());
  dirty_.erase(std::unique(dirty_.begin(), dirty_.end()), dirty_.end());
  for (const ChunkKey& k : dirty_) {
    DrawData data = build_chunk(k);
    if (data.cell_count() > 0) {
      chunks_[k] = std::make_shared<const DrawData>(std::move(data));
      ++work.chunks_built;
    } else if (chunks_.erase(k)) {
      ++work.chunks_removed;
    }
  }
  out->chunks = chunks_;
  return out;
}

}  // namespace sketchlab::viewer
