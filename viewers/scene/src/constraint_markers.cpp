#include "constraint_markers.hpp"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab::viewer {
namespace {

bool point_valued(ConstraintKind k) {
  return k == ConstraintKind::coincident_point || k == ConstraintKind::grid_point ||
         k == ConstraintKind::intersection;
}

struct Builder {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts, lines, polys;
  bool empty = true;
  vtkIdType add(const Vec3& p) {
    empty = false;
    return points->InsertNextPoint(p.x(), p.y(), p.z());
  }
  vtkSmartPointer<vtkActor> actor(double r, double g, double b, double opacity, double width) {
    if (empty) return nullptr;
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetVerts(verts);
    poly->SetLines(lines);
    poly->SetPolys(polys);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    mapper->ScalarVisibilityOff();
    auto a = vtkSmartPointer<vtkActor>::New();
    a->SetMapper(mapper);
    a->GetProperty()->SetColor(r, g, b);
    a->GetProperty()->SetOpacity(opacity);
    a->GetProperty()->SetLineWidth(static_cast<float>(width));
    a->GetProperty()->SetPointSize(static_cast<float>(5 * width));  // larger than node dots
    a->GetProperty()->SetRenderPointsAsSpheres(true);
    a->GetProperty()->LightingOff();
    return a;
  }
};

// Two unit vectors orthogonal to n (and to each other).
std::pair<Vec3, Vec3> basis(const Vec3& n) {
  const Vec3 u = n.unitOrthogonal();
  return {u, n.cross(u).normalized()};
}

}  // namespace

std::vector<Vec3> constraint_anchors(const Constraint& c, const Sketch& sketch) {
  std::vector<Vec3> out;
  for (const ConstraintRef& r : c.references) {
    if (r.kind == ConstraintRef::Kind::curve) {
      if (const NetworkCurve* curve = sketch.network.find_curve(r.id)) {
        const Vec3 p = evaluate(curve->curve, r.parameter);
        if (p.allFinite()) out.push_back(p);
      }
    } else if (r.kind == ConstraintRef::Kind::node) {
      const auto& nodes = sketch.network.nodes();
      if (auto it = nodes.find(r.id); it != nodes.end() && it->second.position.allFinite())
        out.push_back(it->second.position);
    }
  }
  if (out.empty() && point_valued(c.kind) && c.target.allFinite() && c.target != Vec3::Zero())
    out.push_back(c.target);
  return out;
}

ConstraintMarkers make_constraint_markers(const std::vector<Constraint>& constraints,
                                          const Sketch& sketch, double size, bool rejected) {
  Builder dots, corners, tangents, planes;
  for (const Constraint& c : constraints) {
    if (c.enforced == rejected) continue;
    const std::vector<Vec3> anchors = constraint_anchors(c, sketch);
    if (anchors.empty()) continue;
    switch (c.kind) {
      case ConstraintKind::coincident_point:
      case ConstraintKind::point_on_curve:
      case ConstraintKind::intersection:
      case ConstraintKind::grid_point:
      case ConstraintKind::closure:
        for (const Vec3& p : anchors) {
          const vtkIdType id = dots.add(p);
          dots.verts->InsertNextCell(1, &id);
        }
        break;
      case ConstraintKind::perpendicular: {
        // An L-shaped tick at the first anchor, in the plane facing the target.
        const Vec3 n = c.target.norm() > 0 ? c.target.normalized() : Vec3::UnitZ();
        const auto [u, v] = basis(n);
        const Vec3 p = anchors.front();
        const vtkIdType ids[3] = {corners.add(p + size * u), corners.add(p + size * (u + v)),
                                  corners.add(p + size * v)};
        corners.lines->InsertNextCell(3, ids);
        break;
      }
      case ConstraintKind::tangent:
      case ConstraintKind::parallel:
        for (const ConstraintRef& r : c.references) {
          if (r.kind != ConstraintRef::Kind::curve) continue;
          const NetworkCurve* curve = sketch.network.find_curve(r.id);
          if (!curve) continue;
          const Vec3 p = evaluate(curve->curve, r.parameter), t = tangent(curve->curve, r.parameter);
          if (!p.allFinite() || !t.allFinite()) continue;
          const vtkIdType ids[2] = {tangents.add(p - 1.5 * size * t), tangents.add(p + 1.5 * size * t)};
          tangents.lines->InsertNextCell(2, ids);
        }
        break;
      case ConstraintKind::planar:
      case ConstraintKind::axis_plane:
      case ConstraintKind::mirror_plane:
      case ConstraintKind::symmetry: {
        const Vec3 n = c.target.norm() > 0 ? c.target.normalized() : sketch.workspace.up;
        const auto [u, v] = basis(n);
        const Vec3 p = anchors.front();
        const double s = 2.0 * size;
        const vtkIdType ids[4] = {planes.add(p - s * u - s * v), planes.add(p + s * u - s * v),
                                  planes.add(p + s * u + s * v), planes.add(p - s * u + s * v)};
        planes.polys->InsertNextCell(4, ids);
        break;
      }
      default: break;
    }
  }
  if (rejected)
    return {dots.actor(0.85, 0.15, 0.15, 0.8, 2.0), corners.actor(0.85, 0.15, 0.15, 0.8, 2.0),
            tangents.actor(0.85, 0.15, 0.15, 0.8, 2.0), planes.actor(0.85, 0.15, 0.15, 0.25, 1.0)};
  return {dots.actor(0.10, 0.65, 0.25, 1.0, 3.0), corners.actor(0.80, 0.15, 0.70, 1.0, 2.5),
          tangents.actor(0.05, 0.65, 0.80, 1.0, 2.5), planes.actor(0.95, 0.75, 0.20, 0.35, 1.0)};
}

}  // namespace sketchlab::viewer
