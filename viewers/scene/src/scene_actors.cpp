// Builds the VTK actors of a sketch (DESIGN.md "Viewers": raw strokes faint,
// corrected curves dark, nodes as small dots, patches translucent).
#include "scene_actors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkTextProperty.h>

namespace sketchlab::viewer {
namespace {

vtkSmartPointer<vtkActor> actor_of(vtkPolyData* poly) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// Lines and dots are drawn flat: their colour is the style's colour exactly,
// whatever their orientation to the light.
void style_lines(vtkProperty* p, const Rgb& colour, double width) {
  p->SetColor(colour[0], colour[1], colour[2]);
  p->SetLineWidth(static_cast<float>(width));
  p->LightingOff();
}

}  // namespace

vtkSmartPointer<vtkPolyData> to_polydata(const DrawData& data) {
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(data.points.size() / 3));
  std::copy(data.points.begin(), data.points.end(), xyz->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(data.offsets.size()));
  std::copy(data.offsets.begin(), data.offsets.end(), offsets->GetPointer(0));
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(data.connectivity.size()));
  std::copy(data.connectivity.begin(), data.connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  switch (data.cells) {
    case DrawData::Cells::vertices: poly->SetVerts(cells); break;
    case DrawData::Cells::lines: poly->SetLines(cells); break;
    case DrawData::Cells::triangles: poly->SetPolys(cells); break;
  }
  if (!data.normals.empty() && data.normals.size() == data.points.size()) {
    vtkNew<vtkFloatArray> normals;
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(xyz->GetNumberOfTuples());
    std::copy(data.normals.begin(), data.normals.end(), normals->GetPointer(0));
    poly->GetPointData()->SetNormals(normals);
  }
  return poly;
}

vtkSmartPointer<vtkActor> make_sketch_actor(DrawClass cls, vtkPolyData* poly, const SceneStyle& style) {
  auto actor = actor_of(poly);
  vtkProperty* p = actor->GetProperty();
  switch (cls) {
    case DrawClass::raw_strokes:
      style_lines(p, style.raw_stroke_colour, style.raw_stroke_width);
      break;
    case DrawClass::scaffold:
      style_lines(p, style.scaffold_colour, style.scaffold_width);
      break;
    case DrawClass::shape:
      style_lines(p, style.shape_colour, style.shape_width);
      break;
    case DrawClass::other:
      style_lines(p, style.curve_colour, style.curve_width);
      break;
    case DrawClass::nodes:
      p->SetColor(style.node_colour[0], style.node_colour[1], style.node_colour[2]);
      // Dots sit on the curves they join: pull them towards the camera so the
      // (wider) curve lines do not hide them.
      actor->GetMapper()->SetRelativeCoincidentTopologyPointOffsetParameter(-1000.0);
      p->SetPointSize(static_cast<float>(style.node_size));
      p->LightingOff();
      break;
    case DrawClass::patches:
      p->SetColor(style.patch_colour[0], style.patch_colour[1], style.patch_colour[2]);
      // Mostly ambient so a patch reads as a tint of its colour from any side,
      // with a little diffuse to show its shape.
      p->SetOpacity(style.patch_opacity);
      p->SetAmbient(0.6);
      p->SetDiffuse(0.4);
      p->SetSpecular(0.0);
      p->BackfaceCullingOff();
      break;
  }
  return actor;
}

bool drawn(DrawClass cls, const SceneStyle& style) {
  switch (cls) {
    case DrawClass::raw_strokes: return style.show_raw_strokes;
    case DrawClass::nodes: return style.show_nodes;
    case DrawClass::patches: return style.show_patches;
    default: return true;
  }
}

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
  const auto actor = [&](DrawClass cls, const DrawData& data) -> vtkSmartPointer<vtkActor> {
    if (!drawn(cls, style) || data.cell_count() == 0) return nullptr;
    return make_sketch_actor(cls, to_polydata(data), style);
  };

  std::vector<std::vector<Vec3>> raw;
  if (raw_strokes) {
    for (const Stroke& s : *raw_strokes) raw.push_back(stroke_points(s));
  } else {
    for (const auto& [id, s] : sketch.strokes) raw.push_back(stroke_points(s));
  }
  std::vector<const std::vector<Vec3>*> raw_lines;
  for (const auto& r : raw) raw_lines.push_back(&r);
  actors.raw_strokes = actor(DrawClass::raw_strokes, polylines_data(raw_lines));

  std::vector<std::vector<Vec3>> curves;
  curves.reserve(sketch.network.curves().size());
  std::map<DrawClass, std::vector<const std::vector<Vec3>*>> lines;
  for (const auto& [id, nc] : sketch.network.curves()) {
    curves.push_back(curve_points(nc.curve, spacing));
    lines[draw_class(nc.layer)].push_back(&curves.back());
  }
  actors.scaffold_curves = actor(DrawClass::scaffold, polylines_data(lines[DrawClass::scaffold]));
  actors.other_curves = actor(DrawClass::other, polylines_data(lines[DrawClass::other]));
  actors.shape_curves = actor(DrawClass::shape, polylines_data(lines[DrawClass::shape]));
  actors.nodes = actor(DrawClass::nodes, nodes_data(sketch.network.nodes()));
  std::vector<const Mesh*> meshes;
  for (const auto& [id, patch] : sketch.network.patches()) meshes.push_back(&patch.mesh);
  actors.patches = actor(DrawClass::patches, meshes_data(meshes));

  // Faint first, translucent last (VTK renders translucent props after the
  // opaque ones anyway; the order keeps the scene deterministic).
  for (const auto& a : {actors.raw_strokes, actors.scaffold_curves, actors.other_curves,
                        actors.shape_curves, actors.nodes, actors.patches})
    if (a) renderer->AddActor(a);
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
