#include "picture_annotations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include "scene_actors.hpp"
#include "sketch_geometry.hpp"

namespace sketchlab::viewer {
namespace {

double distance_to_polyline(const Vec3& p, const std::vector<Vec3>& line) {
  if (line.size() == 1) return (p - line[0]).norm();
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3 ab = line[i + 1] - line[i];
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - line[i]).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (line[i] + t * ab)).norm());
  }
  return best;
}

// Viridis (matplotlib's default map, van der Walt & Smith 2015) at 9 stops.
const double viridis[9][3] = {{0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530},
                              {0.207, 0.372, 0.553}, {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551},
                              {0.135, 0.659, 0.518}, {0.267, 0.749, 0.441}, {0.993, 0.906, 0.144}};

vtkSmartPointer<vtkLookupTable> viridis_table(double max_mm, const Rgb& nan_colour) {
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  const int n = 256;
  lut->SetNumberOfTableValues(n);
  for (int i = 0; i < n; ++i) {
    const double x = 8.0 * i / (n - 1);
    const int k = std::min(static_cast<int>(x), 7);
    const double f = x - k;
    double c[3];
    for (int j = 0; j < 3; ++j) c[j] = viridis[k][j] * (1 - f) + viridis[k + 1][j] * f;
    lut->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  lut->SetTableRange(0.0, max_mm);
  lut->SetUseAboveRangeColor(false);
  lut->SetNanColor(nan_colour[0], nan_colour[1], nan_colour[2], 1.0);
  lut->Build();
  return lut;
}

}  // namespace

DeviationLines curve_deviations(const Sketch& sketch, const std::vector<Stroke>* raw_strokes, double spacing) {
  std::map<StrokeId, std::vector<Vec3>> strokes;
  if (raw_strokes)
    for (const Stroke& s : *raw_strokes) strokes[s.id] = stroke_points(s);
  else
    for (const auto& [id, s] : sketch.strokes) strokes[id] = stroke_points(s);
  DeviationLines out;
  for (const auto& [id, nc] : sketch.network.curves()) {
    const auto it = strokes.find(nc.source_stroke);
    const bool known = it != strokes.end() && !it->second.empty();
    std::vector<Vec3> points = curve_points(nc.curve, spacing);
    if (points.size() < 2) continue;
    std::vector<double> d;
    for (const Vec3& p : points) d.push_back(known ? distance_to_polyline(p, it->second) : std::nan(""));
    out.polylines.push_back(std::move(points));
    out.distances.push_back(std::move(d));
  }
  return out;
}

vtkSmartPointer<vtkActor> deviation_actor(const DeviationLines& lines, double max_m, const SceneStyle& style) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkDoubleArray> mm;
  mm->SetName("deviation_mm");
  for (std::size_t i = 0; i < lines.polylines.size(); ++i) {
    cells->InsertNextCell(static_cast<vtkIdType>(lines.polylines[i].size()));
    for (std::size_t k = 0; k < lines.polylines[i].size(); ++k) {
      const Vec3& p = lines.polylines[i][k];
      cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
      mm->InsertNextValue(1000.0 * lines.distances[i][k]);
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(cells);
  poly->GetPointData()->SetScalars(mm);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetLookupTable(viridis_table(1000.0 * max_m, style.curve_colour));
  mapper->SetScalarRange(0.0, 1000.0 * max_m);
  mapper->SetColorModeToMapScalars();
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(static_cast<float>(style.shape_width));
  actor->GetProperty()->LightingOff();
  return actor;
}

vtkSmartPointer<vtkProp> deviation_colour_bar(double max_m, int font_size, const SceneStyle& style) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(viridis_table(1000.0 * max_m, style.curve_colour));
  bar->SetTitle("deviation (mm)");  // short: a longer title is clipped at the panel edge
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.3g");
  bar->UnconstrainedFontSizeOn();
  bar->SetOrientationToVertical();
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.86, 0.25);
  bar->SetWidth(0.12);
  bar->SetHeight(0.55);
  bar->SetBarRatio(0.3);
  for (vtkTextProperty* t : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
    t->SetColor(style.text_colour[0], style.text_colour[1], style.text_colour[2]);
    t->SetFontSize(std::max(font_size, 6));
    t->BoldOff();
    t->ItalicOff();
    t->ShadowOff();
  }
  return bar;
}

std::vector<vtkSmartPointer<vtkProp>> scale_bar(double metres_per_pixel, int viewport_width, int font_size,
                                                const SceneStyle& style) {
  if (!(metres_per_pixel > 0) || !std::isfinite(metres_per_pixel)) return {};
  const double target = 0.2 * viewport_width * metres_per_pixel;
  const double mag = std::pow(10.0, std::floor(std::log10(target)));
  double length = mag;
  for (double m : {1.0, 2.0, 5.0})
    if (m * mag <= target) length = m * mag;
  const double pixels = length / metres_per_pixel;
  const double x1 = viewport_width - 24.0, x0 = x1 - pixels, y = 24.0;
  vtkNew<vtkPoints> points;
  for (const auto& [x, yy] : std::vector<std::pair<double, double>>{{x0, y + 6}, {x0, y}, {x1, y}, {x1, y + 6}})
    points->InsertNextPoint(x, yy, 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  lines->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkCoordinate> viewport;
  viewport->SetCoordinateSystemToViewport();
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  mapper->SetTransformCoordinate(viewport);
  auto bar = vtkSmartPointer<vtkActor2D>::New();
  bar->SetMapper(mapper);
  bar->GetProperty()->SetColor(style.text_colour[0], style.text_colour[1], style.text_colour[2]);
  bar->GetProperty()->SetLineWidth(2.0f);
  char label[32];
  if (length >= 1.0) std::snprintf(label, sizeof label, "%g m", length);
  else if (length >= 0.01) std::snprintf(label, sizeof label, "%g cm", length * 100.0);
  else std::snprintf(label, sizeof label, "%g mm", length * 1000.0);
  auto text = make_text(label, 0.0, 0.0, false, font_size, style.text_colour, false);
  text->GetPositionCoordinate()->SetCoordinateSystemToViewport();
  text->GetPositionCoordinate()->SetValue(x0, y + 8);
  return {bar, text};
}

}  // namespace sketchlab::viewer
