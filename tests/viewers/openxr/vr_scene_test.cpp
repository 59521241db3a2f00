// The VR scene is updated incrementally (issue #25): the worker rebuilds the
// geometry of the chunks an edit touches, and the frame that shows a
// correction swaps in only those; counts, not times (bench_vr_scene has the
// times). The incremental geometry equals a fresh build of the same sketch.
#include <catch2/catch.hpp>

// Only when the VR viewer is built (its internals are on the include path).
#if __has_include("vr_scene.hpp")

#include <vtkNew.h>
#include <vtkRenderer.h>

#include "sketch_geometry.hpp"
#include "vr_scene.hpp"

using namespace sketchlab;
using viewer::ChunkKey;
using viewer::DrawClass;
using viewer::SketchGeometryBuilder;

namespace {

NetworkCurve line_curve(CurveId id, Layer layer, const Vec3& from, const Vec3& step) {
  NetworkCurve c;
  c.id = id;
  c.layer = layer;
  c.source_stroke = id;
  for (int k = 0; k <= 3; ++k) c.curve.control_points.push_back(from + step * k);
  c.curve.sharp.assign(2, false);
  return c;
}

// `curves` 30 cm curves (every third a scaffold) in a 1 m box, `patches`
// 5x5-vertex patches bounded by the first curves, one node on each of the
// first 50 curves.
Sketch large_sketch(int curves, int patches) {
  Edit edit;
  for (int i = 0; i < curves; ++i) {
    const double a = 0.1 * i;
    edit.curves_added.push_back(line_curve(static_cast<CurveId>(i + 1), i % 3 == 0 ? Layer::scaffold : Layer::shape,
                                           Vec3(0.5 * std::cos(a), 1.0 + 0.4 * std::sin(1.7 * a), -0.5 + 0.001 * i),
                                           Vec3(0.1 * std::sin(a), 0.1 * std::cos(a), 0.0)));
  }
  for (int i = 0; i < patches; ++i) {
    Patch p;
    p.id = static_cast<PatchId>(i + 1);
    const Curve& rim = edit.curves_added[static_cast<std::size_t>(i)].curve;
    p.boundary.push_back({static_cast<CurveId>(i + 1), 0.0, rim.t_max(), 0, 0});
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b) {
        p.mesh.vertices.push_back(rim.control_points[0] + Vec3(0.02 * a, 0.02 * b, 0.0));
        p.mesh.normals.push_back(Vec3(0, 0, 1));
      }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int v = a * 5 + b;
        p.mesh.faces.push_back({v, v + 5, v + 1});
        p.mesh.faces.push_back({v + 1, v + 5, v + 6});
      }
    edit.patches_added.push_back(std::move(p));
  }
  for (int i = 0; i < 50; ++i) {
    Node n;
    n.id = static_cast<NodeId>(i + 1);
    n.position = edit.curves_added[static_cast<std::size_t>(i)].curve.control_points.front();
    n.incidences.push_back({static_cast<CurveId>(i + 1), 0.0});
    edit.nodes_added.push_back(std::move(n));
  }
  Sketch sketch;
  sketch.network.apply(edit);
  return sketch;
}

// Chunks whose data object is not the one in `before` (new ones included).
std::size_t changed(const viewer::SketchGeometry& before, const viewer::SketchGeometry& after) {
  std::size_t n = 0;
  for (const auto& [key, data] : after.chunks) {
    const auto it = before.chunks.find(key);
    if (it == before.chunks.end() || it->second != data) ++n;
  }
  return n;
}

void require_same_as_fresh(const viewer::SketchGeometry& incremental, const Sketch& sketch) {
  SketchGeometryBuilder fresh(vr::vr_style());
  const auto expected = fresh.update(sketch);
  REQUIRE(incremental.spacing == expected->spacing);
  REQUIRE(incremental.chunks.size() == expected->chunks.size());
  for (const auto& [key, data] : expected->chunks) {
    INFO("chunk class " << static_cast<int>(key.cls) << " index " << key.index);
    REQUIRE(incremental.chunks.count(key));
    CHECK(*incremental.chunks.at(key) == *data);
  }
}

}  // namespace

TEST_CASE("an edit to a 2,000-curve sketch rebuilds only the chunks holding what it added, changed or removed",
          "[openxr]") {
  Sketch sketch = large_sketch(2000, 200);
  SketchGeometryBuilder builder(vr::vr_style());
  const auto first = builder.update(sketch);
  CHECK(first->work.curves_sampled == 2000);
  CHECK(first->work.patches == 200);
  // 16 id ranges of 128 curves, each with scaffolds and shapes; 2 of patches; 1 of nodes.
  CHECK(first->chunks.size() == 16 * 2 + 2 + 1);
  CHECK(first->work.chunks_built == first->chunks.size());

  SECTION("nothing changed: nothing rebuilt, every chunk shared") {
    const auto again = builder.update(sketch);
    CHECK(again->work.curves_sampled == 0);
    CHECK(again->work.chunks_built == 0);
    CHECK(changed(*first, *again) == 0);
  }
  SECTION("a correction adds one curve: one curve sampled, one chunk rebuilt") {
    Edit add;
    add.curves_added.push_back(line_curve(2001, Layer::shape, Vec3(0.0, 1.0, -0.4), Vec3(0.05, 0.0, 0.0)));
    sketch.network.apply(add);
    const auto after = builder.update(sketch);
    CHECK(after->spacing == first->spacing);
    CHECK(after->work.curves_sampled == 1);
    CHECK(after->work.chunks_built == 1);
    CHECK(changed(*first, *after) == 1);
    CHECK(after->chunks.at(ChunkKey{DrawClass::shape, 2001 / SketchGeometryBuilder::default_chunk_size}) !=
          first->chunks.at(ChunkKey{DrawClass::shape, 2001 / SketchGeometryBuilder::default_chunk_size}));
    require_same_as_fresh(*after, sketch);
  }
  SECTION("a curve replaced on another layer: its old and new chunks; a curve removed: its chunk") {
    const NetworkCurve old = *sketch.network.find_curve(301);
    REQUIRE(old.layer == Layer::scaffold);
    Edit replace;
    replace.curves_replaced.push_back(line_curve(301, Layer::shape, old.curve.control_points[0], Vec3(0.0, 0.05, 0.0)));
    sketch.network.apply(replace);
    const auto replaced = builder.update(sketch);
    CHECK(replaced->work.curves_sampled == 1);
    CHECK(replaced->work.chunks_built == 2);
    CHECK(changed(*first, *replaced) == 2);
    require_same_as_fresh(*replaced, sketch);

    Edit remove;
    remove.curves_removed.push_back(1500);  // no node, no patch on it
    sketch.network.apply(remove);
    const auto removed = builder.update(sketch);
    CHECK(removed->work.curves_sampled == 0);
    CHECK(removed->work.chunks_built == 1);
    CHECK(changed(*replaced, *removed) == 1);
    require_same_as_fresh(*removed, sketch);
  }
  SECTION("removing a curve a node and a patch lie on rebuilds the nodes and that patch's chunk too") {
    Edit remove;
    remove.curves_removed.push_back(10);
    sketch.network.apply(remove);
    const auto after = builder.update(sketch);
    CHECK(after->work.chunks_built == 3);  // the curve's, the nodes', the patches'
    require_same_as_fresh(*after, sketch);
  }
  SECTION("the sketch doubling in size re-samples every curve at the new spacing") {
    Edit far;
    far.curves_added.push_back(line_curve(2001, Layer::shape, Vec3(8.0, 1.0, -0.5), Vec3(0.1, 0.0, 0.0)));
    sketch.network.apply(far);
    const auto after = builder.update(sketch);
    CHECK(after->spacing > first->spacing);
    CHECK(after->work.curves_sampled == 2001);
    require_same_as_fresh(*after, sketch);
  }
}

TEST_CASE("the frame showing a correction in a 2,000-curve scene swaps one chunk actor's geometry", "[openxr]") {
  vtkNew<vtkRenderer> renderer;
  vr::VrScene scene(renderer, vr::vr_style(), {"a", "b"});
  const vr::CorrectionWorker::Prepare prepare = vr::geometry_preparer(vr::vr_style());
  vr::SketchSnapshot snap;
  snap.stacks.resize(2);
  snap.stacks[0].sketch = snap.stacks[1].sketch = large_sketch(2000, 200);
  snap.version = 1;
  prepare(snap);
  ControllerView view;
  scene.show(snap, view, 0.0);
  CHECK(scene.chunks_swapped() == 16 * 2 + 2 + 1);

  // A correction in stack 0: one curve more.
  Edit add;
  add.curves_added.push_back(line_curve(2001, Layer::scaffold, Vec3(0.0, 1.0, -0.4), Vec3(0.05, 0.0, 0.0)));
  snap.stacks[0].sketch.network.apply(add);
  snap.version = 2;
  prepare(snap);
  scene.show(snap, view, 0.1);
  CHECK(scene.chunks_swapped() == 1);

  // Hiding the raw strokes or comparing changes what is drawn, not the shown stack's geometry.
  view.raw_strokes = false;
  scene.show(snap, view, 0.2);
  CHECK(scene.chunks_swapped() == 0);
  view.compare = true;
  scene.show(snap, view, 0.3);
  CHECK(scene.chunks_swapped() == 16 * 2);  // the other stack's curves only (no nodes, patches)
  snap.version = 3;
  prepare(snap);
  scene.show(snap, view, 0.4);
  CHECK(scene.chunks_swapped() == 0);

  vr::SketchSnapshot bare;
  bare.stacks.resize(1);
  bare.version = 4;
  CHECK_THROWS_AS(scene.show(bare, view, 0.5), std::logic_error);
}

#endif
