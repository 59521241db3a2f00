#include "vr_actor_utils.hpp"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkVectorText.h>

namespace sketchlab::vr {

vtkSmartPointer<vtkActor> actor_for(vtkPolyData* data) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> actor_for(vtkPolyDataAlgorithm* source) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

void set_data(vtkActor* actor, vtkPolyData* data) {
  vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(data);
}

void set_colour(vtkActor* actor, const viewer::Rgb& c) { actor->GetProperty()->SetColor(c[0], c[1], c[2]); }

vtkSmartPointer<vtkMatrix4x4> placement_matrix(const StagePlacement& p) {
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  const Mat3 r = p.scale * p.rotation.toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m->SetElement(i, j, r(i, j));
    m->SetElement(i, 3, p.translation(i));
  }
  return m;
}

vtkSmartPointer<vtkMatrix4x4> pose_matrix(const Pose& pose) {
  StagePlacement p;
  p.rotation = pose.orientation.normalized();
  p.translation = pose.position;
  return placement_matrix(p);
}

vtkSmartPointer<vtkPolyData> polyline_data(const std::vector<Vec3>& points) {
  auto data = vtkSmartPointer<vtkPolyData>::New();
  if (points.size() < 2) return data;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<vtkIdType>(points.size()));
  for (const Vec3& p : points) lines->InsertCellPoint(pts->InsertNextPoint(p.data()));
  data->SetPoints(pts);
  data->SetLines(lines);
  return data;
}

vtkSmartPointer<vtkPolyData> text_data(const std::string& text, double height, const Vec3& origin, bool centred) {
  vtkNew<vtkVectorText> glyphs;
  glyphs->SetText(text.c_str());
  glyphs->Update();
  double bounds[6];
  glyphs->GetOutput()->GetBounds(bounds);
  // vtkVectorText's capitals are about one unit tall.
  vtkNew<vtkTransform> t;
  t->Translate(origin.x(), origin.y(), origin.z());
  t->Scale(height, height, height);
  if (centred && bounds[1] > bounds[0]) t->Translate(-0.5 * (bounds[0] + bounds[1]), 0.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetTransform(t);
  place->SetInputConnection(glyphs->GetOutputPort());
  place->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(place->GetOutput());
  return out;
}

}  // namespace sketchlab::vr
