#pragma once
// Internal to viewers/: the drawable geometry of a sketch, one way for every
// viewer, and its incremental form for viewers that redraw while the sketch
// changes (VR, #25). Plain arrays, no VTK objects: VTK's reference counting
// goes through its garbage collector, which is not thread-safe, so only the
// render thread makes and drops VTK objects (to_polydata).
//
// SketchGeometryBuilder keeps each curve's sampled polyline, each patch's
// mesh and each raw stroke's points, and groups them in chunks of
// consecutive ids per drawing class. An update compares the sketch with
// what it built last time, item by item (the drawn fields: layer and curve,
// mesh, samples, nodes), and rebuilds only the chunks holding an item that
// was added, changed or removed: after a correction that adds one curve to a
// 2,000-curve sketch, one curve is sampled and one chunk of at most
// `chunk_size` curves is assembled. The result is immutable: build it on any
// thread (the VR viewer builds it on the correction worker) and hand it to
// the render thread, which draws it with SketchChunkActors and converts and
// re-uploads only the chunks that changed.
#include <compare>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::viewer {

// What a sketch is drawn as (DESIGN.md "Viewers"); one actor style each.
enum class DrawClass : std::uint8_t { raw_strokes, scaffold, shape, other, nodes, patches };

// Class of a curve of `layer`: free, guide and automatic curves are `other`.
DrawClass draw_class(Layer layer);

// Cells of one kind over shared points, as VTK's cell arrays store them:
// cell i uses connectivity[offsets[i] .. offsets[i + 1]).
struct DrawData {
  enum class Cells : std::uint8_t { vertices, lines, triangles };
  Cells cells = Cells::lines;
  std::vector<float> points;             // x, y, z per point (m)
  std::vector<float> normals;            // x, y, z per point, or empty
  std::vector<std::int64_t> offsets{0};  // cell count + 1
  std::vector<std::int64_t> connectivity;
  std::size_t cell_count() const { return offsets.size() - 1; }
  bool operator==(const DrawData&) const = default;
};

// Builders shared by every viewer.
// One polyline cell per point list with at least two points.
DrawData polylines_data(const std::vector<const std::vector<Vec3>*>& polylines);
// The meshes' triangles (faces indexing outside their mesh are skipped), with
// point normals when every mesh has one per vertex.
DrawData meshes_data(const std::vector<const Mesh*>& meshes);
// One vertex cell per node with a finite position.
DrawData nodes_data(const std::map<NodeId, Node>& nodes);

// A stroke's finite 3D sample positions (empty for pixel samples: 2D input
// has no place in a 3D scene).
std::vector<Vec3> stroke_points(const Stroke& stroke);
// A curve's polyline every `spacing` metres (empty when the curve has no
// segment or a non-finite point).
std::vector<Vec3> curve_points(const Curve& curve, double spacing);

struct ChunkKey {
  DrawClass cls = DrawClass::other;
  std::uint64_t index = 0;  // item id / chunk size (0 for nodes)
  auto operator<=>(const ChunkKey&) const = default;
};

// What one update rebuilt (for tests and benchmarks: counts, not times).
struct GeometryWork {
  std::size_t curves_sampled = 0;
  std::size_t strokes = 0;
  std::size_t patches = 0;
  std::size_t chunks_built = 0;
  std::size_t chunks_removed = 0;
};

struct SketchGeometry {
  double spacing = 0.0;  // curve polyline spacing (m)
  // Per chunk with at least one cell; never modified once published (an
  // update makes new data for the chunks it rebuilds and shares the others).
  std::map<ChunkKey, std::shared_ptr<const DrawData>> chunks;
  GeometryWork work;  // what the update that produced this rebuilt
};

// Curve spacing that stays put while a sketch grows: the style's fraction
// of the bounds' diagonal (curve_spacing), rounded to a power of two, so the
// curves are re-sampled only when the sketch's size doubles or halves.
double stable_curve_spacing(const Box3& bounds, const SceneStyle& style);

class SketchGeometryBuilder {
 public:
  static constexpr std::size_t default_chunk_size = 128;
  // `chunk_size` (>= 1) items of consecutive ids share a chunk: bigger means
  // fewer draw calls per frame, smaller means less to re-upload per edit.
  explicit SketchGeometryBuilder(const SceneStyle& style, std::size_t chunk_size = default_chunk_size);

  // The geometry of `sketch` (curves at stable_curve_spacing of its bounds;
  // a change of spacing rebuilds every curve). Not thread-safe: one thread
  // updates a builder; the results may go to any thread.
  std::shared_ptr<const SketchGeometry> update(const Sketch& sketch);

 private:
  struct CurveItem {
    Layer layer;
    Curve curve;
    std::vector<Vec3> points;
  };
  struct StrokeItem {
    Stroke stroke;
    std::vector<Vec3> points;
  };
  ChunkKey key(DrawClass cls, std::uint64_t id) const { return {cls, id / chunk_size_}; }
  void update_curves(const Sketch& sketch, double spacing, GeometryWork& work);
  void update_strokes(const Sketch& sketch, GeometryWork& work);
  void update_patches(const Sketch& sketch, GeometryWork& work);
  DrawData build_chunk(const ChunkKey& key) const;

  SceneStyle style_;
  std::size_t chunk_size_;
  double spacing_ = 0.0;
  std::map<CurveId, CurveItem> curves_;
  std::map<StrokeId, StrokeItem> strokes_;
  std::map<PatchId, Mesh> patches_;
  std::map<NodeId, Node> nodes_;
  std::vector<ChunkKey> dirty_;
  std::map<ChunkKey, std::shared_ptr<const DrawData>> chunks_;
};

}  // namespace sketchlab::viewer
