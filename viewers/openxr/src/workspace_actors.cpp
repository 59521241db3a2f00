#include "workspace_actors.hpp"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkMapper.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>

#include "vr_actor_utils.hpp"

namespace sketchlab::vr {
namespace {

constexpr int grid_reach = 2;  // workspace grid points within ±2 spacings of the hand

vtkSmartPointer<vtkPolyData> floor_lines() {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const int n = static_cast<int>(std::lround(floor_grid_extent / floor_grid_spacing));
  for (int i = -n; i <= n; ++i) {
    const double u = i * floor_grid_spacing, e = floor_grid_extent;
    // Just above the ground so depth testing keeps the lines on top of it.
    const vtkIdType a[2] = {points->InsertNextPoint(u, 0.001, -e), points->InsertNextPoint(u, 0.001, e)};
    const vtkIdType b[2] = {points->InsertNextPoint(-e, 0.001, u), points->InsertNextPoint(e, 0.001, u)};
    lines->InsertNextCell(2, a);
    lines->InsertNextCell(2, b);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

}  // namespace

WorkspaceActors::WorkspaceActors(vtkRenderer* renderer, const viewer::SceneStyle& style) {
  renderer->SetBackground(sky_colour[0], sky_colour[1], sky_colour[2]);
  vtkNew<vtkRegularPolygonSource> disc;
  disc->SetNumberOfSides(96);
  disc->SetRadius(ground_radius);
  disc->SetNormal(0, 1, 0);
  disc->SetCenter(0, 0, 0);
  ground_ = actor_for(disc);
  // Flat colours: the stage reads the same from everywhere (and the tests
  // can name its pixels).
  set_colour(ground_, ground_colour);
  ground_->GetProperty()->LightingOff();
  renderer->AddActor(ground_);
  floor_grid_ = actor_for(floor_lines());
  set_colour(floor_grid_, floor_line_colour);
  floor_grid_->GetProperty()->LightingOff();
  floor_grid_->GetProperty()->SetLineWidth(1.5f);
  renderer->AddActor(floor_grid_);

  grid_points_ = actor_for(vtkNew<vtkPolyData>().GetPointer());
  set_colour(grid_points_, style.scaffold_colour);
  grid_points_->GetProperty()->SetPointSize(4.0f);
  grid_points_->GetProperty()->SetOpacity(0.6);
  renderer->AddActor(grid_points_);
  vtkNew<vtkPlaneSource> plane;
  mirror_ = actor_for(plane);
  set_colour(mirror_, style.patch_colour);
  mirror_->GetProperty()->SetOpacity(0.15);
  mirror_->VisibilityOff();
  renderer->AddActor(mirror_);
}

void WorkspaceActors::update(const ControllerState& input) {
  const auto placement = placement_matrix(input.placement);
  grid_points_->SetUserMatrix(placement);
  mirror_->SetUserMatrix(placement);
  const Workspace& ws = input.workspace;
  const ControllerHand& hand = input.pen;

  // Grid points around the dominant hand when the workspace grid is on (a
  // local grid, so the whole lattice does not clutter the view).
  vtkNew<vtkPolyData> grid;
  const double spacing = ws.grid_spacing;
  if (ws.grid_enabled && hand.tracked && spacing > 0.0 && std::isfinite(spacing)) {
    const Vec3 w = input.placement.to_workspace(hand.aim.position);
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
  set_data(grid_points_, grid);

  mirror_->SetVisibility(ws.mirror_enabled);
  if (ws.mirror_enabled && ws.mirror_normal.norm() > 0.0) {
    const Vec3 n = ws.mirror_normal.normalized();
    const Vec3 a = n.unitOrthogonal(), b = n.cross(a);
    // A 1 m square of the plane around the dominant hand's foot point (the
    // plane is infinite; this is the part the user works near).
    const double offset = ws.mirror_offset / ws.mirror_normal.norm();
    Vec3 near = Vec3::Zero();
    if (hand.tracked) near = input.placement.to_workspace(hand.aim.position);
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
