#include "vr_scene.hpp"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "sketchlab/viewer/camera.hpp"

namespace sketchlab::vr {
namespace {

vtkSmartPointer<vtkActor> actor_for(vtkPolyDataAlgorithm* source) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> actor_for(vtkPolyData* data) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

void set_data(vtkActor* actor, vtkPolyData* data) {
  vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->SetInputData(data);
}

constexpr double controller_radius = 0.015;  // m, stage
constexpr int grid_reach = 2;                // grid points within ±2 spacings of the hand

}  // namespace

viewer::Rgb mode_colour(Layer mode, bool correction) {
  viewer::Rgb c;
  switch (mode) {
    case Layer::scaffold: c = {0.20, 0.45, 0.85}; break;
    case Layer::shape: c = {0.85, 0.25, 0.20}; break;
    case Layer::free: c = {0.20, 0.65, 0.30}; break;
    default: c = {0.40, 0.40, 0.45}; break;
  }
  if (!correction)
    for (double& x : c) x = 0.5 * x + 0.5;
  return c;
}

VrScene::VrScene(vtkRenderer* renderer, const viewer::SceneStyle& style) : renderer_(renderer), style_(style) {
  renderer_->SetBackground(style.background[0], style.background[1], style.background[2]);
  stroke_ = actor_for(vtkNew<vtkPolyData>().GetPointer());
  stroke_->GetProperty()->SetColor(style.curve_colour[0], style.curve_colour[1], style.curve_colour[2]);
  stroke_->GetProperty()->SetLineWidth(static_cast<float>(style.curve_width));
  renderer_->AddActor(stroke_);
  grid_ = actor_for(vtkNew<vtkPolyData>().GetPointer());
  grid_->GetProperty()->SetColor(style.scaffold_colour[0], style.scaffold_colour[1], style.scaffold_colour[2]);
  grid_->GetProperty()->SetPointSize(4.0f);
  grid_->GetProperty()->SetOpacity(0.6);
  renderer_->AddActor(grid_);
  vtkNew<vtkPlaneSource> plane;
  mirror_ = actor_for(plane);
  mirror_->GetProperty()->SetColor(style.patch_colour[0], style.patch_colour[1], style.patch_colour[2]);
  mirror_->GetProperty()->SetOpacity(0.15);
  mirror_->VisibilityOff();
  renderer_->AddActor(mirror_);
  for (auto& hand : hands_) {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(controller_radius);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    hand = actor_for(sphere);
    hand->VisibilityOff();
    renderer_->AddActor(hand);
  }
}

void VrScene::set_sketch(const Sketch& sketch) {
  for (vtkActor* a : {sketch_.raw_strokes.Get(), sketch_.scaffold_curves.Get(), sketch_.shape_curves.Get(),
                      sketch_.other_curves.Get(), sketch_.nodes.Get(), sketch_.patches.Get()})
    if (a) renderer_->RemoveActor(a);
  const double spacing = viewer::curve_spacing(viewer::scene_bounds({&sketch}), style_);
  sketch_ = viewer::add_sketch_actors(renderer_, sketch, nullptr, style_, spacing);
}

void VrScene::apply_placement(const openxr::Placement& p) {
  vtkNew<vtkMatrix4x4> m;
  const Mat3 r = p.scale * p.rotation.toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m->SetElement(i, j, r(i, j));
    m->SetElement(i, 3, p.translation(i));
  }
  for (vtkActor* a : {sketch_.raw_strokes.Get(), sketch_.scaffold_curves.Get(), sketch_.shape_curves.Get(),
                      sketch_.other_curves.Get(), sketch_.nodes.Get(), sketch_.patches.Get(), stroke_.Get(),
                      grid_.Get(), mirror_.Get()})
    if (a) a->SetUserMatrix(m);
}

void VrScene::update(const openxr::GestureInterpreter& input, const openxr::ControllerFrame& frame,
                     openxr::Hand dominant) {
  apply_placement(input.placement());
  const Workspace& ws = input.workspace();

  // The stroke being drawn, as raw samples.
  const auto& samples = input.stroke_in_progress();
  vtkNew<vtkPolyData> stroke;
  if (samples.size() >= 2) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    lines->InsertNextCell(static_cast<vtkIdType>(samples.size()));
    for (const Sample& s : samples) lines->InsertCellPoint(points->InsertNextPoint(s.position.data()));
    stroke->SetPoints(points);
    stroke->SetLines(lines);
  }
  set_data(stroke_, stroke);

  for (int h = 0; h < 2; ++h) {
    const auto& hand = frame.hands[static_cast<std::size_t>(h)];
    hands_[h]->SetVisibility(hand.tracked);
    if (!hand.tracked) continue;
    hands_[h]->SetPosition(hand.aim.position.x(), hand.aim.position.y(), hand.aim.position.z());
    const viewer::Rgb c = h == static_cast<int>(dominant) ? mode_colour(input.mode(), input.correction_enabled())
                                                          : viewer::Rgb{0.75, 0.75, 0.78};
    hands_[h]->GetProperty()->SetColor(c[0], c[1], c[2]);
  }

  // Grid points around the dominant hand when the workspace grid is on (a
  // local grid, so the whole lattice does not clutter the view).
  vtkNew<vtkPolyData> grid;
  const auto& hand = frame.hands[static_cast<std::size_t>(dominant)];
  const double spacing = ws.grid_spacing;
  if (ws.grid_enabled && hand.tracked && spacing > 0.0 && std::isfinite(spacing)) {
    const Vec3 w = input.placement().to_workspace(hand.aim.position);
    const Vec3 cell = ((w - ws.grid_origin) / spacing).array().round();
    if (cell.allFinite() && cell.cwiseAbs().maxCoeff() < 1e6) {
      vtkNew<vtkPoints> points;
      vtkNew<vtkCellArray> verts;
      for (int i = -grid_reach; i <= grid_reach; ++i)
        for (int j = -grid_reach; j <= grid_reach; ++j)
          for (int k = -grid_reach; k <= grid_reach; ++k) {
            const Vec3 p = ws.grid_origin + spacing * (cell + Vec3(i, j, k));
            verts->InsertNextCell(1);
            verts->InsertCellPoint(points->InsertNextPoint(p.data()));
          }
      grid->SetPoints(points);
      grid->SetVerts(verts);
    }
  }
  set_data(grid_, grid);

  mirror_->SetVisibility(ws.mirror_enabled);
  if (ws.mirror_enabled && ws.mirror_normal.norm() > 0.0) {
    const Vec3 n = ws.mirror_normal.normalized();
    const Vec3 a = n.unitOrthogonal(), b = n.cross(a);
    // A 1 m square of the plane around the dominant hand's foot point (the
    // plane is infinite; this is the part the user works near).
    const double offset = ws.mirror_offset / ws.mirror_normal.norm();
    Vec3 near = Vec3::Zero();
    if (hand.tracked) near = input.placement().to_workspace(hand.aim.position);
    if (!near.allFinite()) near = Vec3::Zero();
    const Vec3 centre = near - n * (n.dot(near) - offset);
    const Vec3 o = centre - 0.5 * a - 0.5 * b, p1 = o + a, p2 = o + b;
    auto* plane = vtkPlaneSource::SafeDownCast(mirror_->GetMapper()->GetInputAlgorithm());
    plane->SetOrigin(o.x(), o.y(), o.z());
    plane->SetPoint1(p1.x(), p1.y(), p1.z());
    plane->SetPoint2(p2.x(), p2.y(), p2.z());
  }
}

}  // namespace sketchlab::vr
