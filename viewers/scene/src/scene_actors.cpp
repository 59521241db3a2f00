// Builds the VTK actors of a sketch (DESIGN.md "Viewers": raw strokes faint,
// corrected curves dark, nodes as small dots, patches translucent).
#include "scene_actors.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkTextProperty.h>

#include "sketchlab/geometry/arclength.hpp"

namespace sketchlab::viewer {
namespace {

// Polylines as one vtkPolyData (points in metres).
class PolylineBuilder {
 public:
  void add(const std::vector<Vec3>& points) {
    if (points.size() < 2) return;
    const vtkIdType first = points_->GetNumberOfPoints();
    lines_->InsertNextCell(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
      points_->InsertNextPoint(points[i].x(), points[i].y(), points[i].z());
      lines_->InsertCellPoint(first + static_cast<vtkIdType>(i));
    }
    ++count_;
  }
  bool empty() const { return count_ == 0; }
  vtkSmartPointer<vtkPolyData> build() const {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points_);
    poly->SetLines(lines_);
    return poly;
  }

 private:
  vtkNew<vtkPoints> points_;
  vtkNew<vtkCellArray> lines_;
  int count_ = 0;
};

vtkSmartPointer<vtkActor> make_actor(vtkPolyData* poly, const Rgb& colour) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  return actor;
}

// Lines and dots are drawn flat: their colour is the style's colour exactly,
// whatever their orientation to the light.
vtkSmartPointer<vtkActor> make_line_actor(const PolylineBuilder& lines, const Rgb& colour,
                                          double width) {
  auto actor = make_actor(lines.build(), colour);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->LightingOff();
  return actor;
}

bool finite(const Vec3& p) { return p.allFinite(); }

std::vector<Vec3> stroke_points(const Stroke& stroke) {
  std::vector<Vec3> out;
  out.reserve(stroke.samples.size());
  for (const Sample& s : stroke.samples)
    if (finite(s.position)) out.push_back(s.position);
  return out;
}

vtkSmartPointer<vtkActor> make_patch_actor(const Sketch& sketch, const SceneStyle& style) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkDoubleArray> normals;
  normals->SetNumberOfComponents(3);
  bool all_normals = true;
  for (const auto& [id, patch] : sketch.network.patches()) {
    const Mesh& mesh = patch.mesh;
    const vtkIdType first = points->GetNumberOfPoints();
    for (const Vec3& v : mesh.vertices) points->InsertNextPoint(v.x(), v.y(), v.z());
    const bool has_normals = mesh.normals.size() == mesh.vertices.size();
    all_normals = all_normals && has_normals;
    for (std::size_t i = 0; has_normals && i < mesh.normals.size(); ++i)
      normals->InsertNextTuple3(mesh.normals[i].x(), mesh.normals[i].y(), mesh.normals[i].z());
    const auto n = static_cast<int>(mesh.vertices.size());
    for (const auto& f : mesh.faces) {
      if (std::min({f[0], f[1], f[2]}) < 0 || std::max({f[0], f[1], f[2]}) >= n) continue;
      const vtkIdType ids[3] = {first + f[0], first + f[1], first + f[2]};
      triangles->InsertNextCell(3, ids);
    }
  }
  if (triangles->GetNumberOfCells() == 0) return nullptr;
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  if (all_normals) poly->GetPointData()->SetNormals(normals);
  auto actor = make_actor(poly, style.patch_colour);
  // Mostly ambient so a patch reads as a tint of its colour from any side,
  // with a little diffuse to show its shape.
  actor->GetProperty()->SetOpacity(style.patch_opacity);
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.4);
  actor->GetProperty()->SetSpecular(0.0);
  actor->GetProperty()->BackfaceCullingOff();
  return actor;
}

}  // namespace

double curve_spacing(const Box3& bounds, const SceneStyle& style) {
  const double diagonal = bounds.isEmpty() ? 0.0 : bounds.diagonal().norm();
  const double spacing = style.curve_spacing_fraction * diagonal;
  return std::isfinite(spacing) && spacing > 1e-5 ? spacing : 1e-3;
}

SceneActors add_sketch_actors(vtkRenderer* renderer, const Sketch& sketch,
                              const std::vector<Stroke>* raw_strokes, const SceneStyle& style,
                              double spacing) {
  SceneActors actors;
  // Curves lie on patch boundaries and nodes on curves: offset depths so
  // polygons go behind lines and lines behind points (a process-wide VTK
  // setting; every sketch viewer wants it).
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();

  if (style.show_raw_strokes) {
    PolylineBuilder raw;
    auto add_stroke = [&](const Stroke& s) {
      if (!s.samples_are_pixels) raw.add(stroke_points(s));
    };
    if (raw_strokes) {
      for (const Stroke& s : *raw_strokes) add_stroke(s);
    } else {
      for (const auto& [id, s] : sketch.strokes) add_stroke(s);
    }
    if (!raw.empty())
      actors.raw_strokes = make_line_actor(raw, style.raw_stroke_colour, style.raw_stroke_width);
  }

  PolylineBuilder scaffold, shape, other;
  for (const auto& [id, nc] : sketch.network.curves()) {
    if (nc.curve.segment_count() < 1 || !nc.curve.control_points.front().allFinite()) continue;
    const auto points = sample_with_spacing(nc.curve, spacing);
    if (!std::all_of(points.begin(), points.end(), finite)) continue;
    (nc.layer == Layer::scaffold ? scaffold : nc.layer == Layer::shape ? shape : other).add(points);
  }
  if (!scaffold.empty())
    actors.scaffold_curves = make_line_actor(scaffold, style.scaffold_colour, style.scaffold_width);
  if (!other.empty())
    actors.other_curves = make_line_actor(other, style.curve_colour, style.curve_width);
  if (!shape.empty())
    actors.shape_curves = make_line_actor(shape, style.shape_colour, style.shape_width);

  if (style.show_nodes && !sketch.network.nodes().empty()) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> vertices;
    for (const auto& [id, node] : sketch.network.nodes()) {
      if (!finite(node.position)) continue;
      const vtkIdType i =
          points->InsertNextPoint(node.position.x(), node.position.y(), node.position.z());
      vertices->InsertNextCell(1, &i);
    }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetVerts(vertices);
    actors.nodes = make_actor(poly, style.node_colour);
    // Dots sit on the curves they join: pull them towards the camera so the
    // (wider) curve lines do not hide them.
    actors.nodes->GetMapper()->SetRelativeCoincidentTopologyPointOffsetParameter(-1000.0);
    actors.nodes->GetProperty()->SetPointSize(static_cast<float>(style.node_size));
    actors.nodes->GetProperty()->LightingOff();
  }

  if (style.show_patches) actors.patches = make_patch_actor(sketch, style);

  // Faint first, translucent last (VTK renders translucent props after the
  // opaque ones anyway; the order keeps the scene deterministic).
  for (const auto& actor : {actors.raw_strokes, actors.scaffold_curves, actors.other_curves,
                            actors.shape_curves, actors.nodes, actors.patches})
    if (actor) renderer->AddActor(actor);
  return actors;
}

void apply_camera(vtkRenderer* renderer, const Camera& camera) {
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetPosition(camera.position.x(), camera.position.y(), camera.position.z());
  cam->SetFocalPoint(camera.focal_point.x(), camera.focal_point.y(), camera.focal_point.z());
  cam->SetViewUp(camera.view_up.x(), camera.view_up.y(), camera.view_up.z());
  cam->SetViewAngle(camera.view_angle_deg);
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkTextActor> make_text(const std::string& text, double x, double y, bool top,
                                        int font_size, const Rgb& colour, bool monospace) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->SetTextScaleModeToNone();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* p = actor->GetTextProperty();
  p->SetFontSize(std::max(font_size, 6));
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetJustificationToLeft();
  if (top)
    p->SetVerticalJustificationToTop();
  else
    p->SetVerticalJustificationToBottom();
  if (monospace) p->SetFontFamilyToCourier();
  return actor;
}

vtkSmartPointer<vtkActor2D> make_left_separator(const Rgb& colour) {
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(0.0, 1.0, 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[2] = {0, 1};
  lines->InsertNextCell(2, ids);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkCoordinate> normalized;
  normalized->SetCoordinateSystemToNormalizedViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  mapper->SetTransformCoordinate(normalized);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(2.0f);
  return actor;
}

}  // namespace sketchlab::viewer
